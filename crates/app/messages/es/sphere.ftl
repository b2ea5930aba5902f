# La esfera del momento angular (crates/app/src/gui/panels/sphere.rs).

sphere-heading = Esfera del momento angular (sistema principal)
sphere-textbook-note = Modelo de libro de texto: sin ω × Iω, ω nunca gira en el cuerpo, así que el punto se queda quieto mientras L gira en el espacio (debería estar fijo).
sphere-leaves-curve = El punto deja su curva: E o |L| cambia por { $reasons }.
sphere-reasons-and = { $first } y { $second }
sphere-reason-damping = el amortiguamiento
sphere-reason-string = la cuerda
sphere-reason-integrator = este integrador
sphere-axis = eje { $axis }: I{ $axis } = { $moment } kg·m², { $stability }
sphere-stable = estable
sphere-unstable = inestable
sphere-neutral = neutro (momentos iguales)
sphere-legend = naranja: la separatriz; violeta: la polhodia de L; blanco: L y su estela
