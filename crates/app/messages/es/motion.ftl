# La sección Movimiento: ejecutar y avanzar, los giros, el texto del movimiento, la exportación, el modelo y el paso de tiempo (crates/app/src/gui/panels/motion.rs).

motion-terms-period = T: el período del movimiento visto desde el cuerpo (ω vuelve a donde estaba), predicho a partir de la energía E y |L|.
motion-terms-turns-over = Se voltea: el eje 2 gira hasta apuntar en sentido contrario, y vuelve, cada T/2: el volteo del eje intermedio (efecto de la raqueta de tenis).
motion-terms-wobbles = Bambolea: el eje de giro rodea un eje estable con un ángulo pequeño y nunca se voltea.
motion-terms-separatrix = Separatriz: el límite entre los movimientos alrededor del eje 1 y alrededor del eje 3, a través del eje 2; cuanto más cerca está un giro de ella, más tiempo entre volteos.
motion-equal-moments = Los ejes { $p } y { $q } tienen momentos iguales: el cuerpo precesa alrededor del eje { $axis }, con su eje de giro a { $cone }° de él, una vez cada T = { $period } s, y nunca se voltea.
motion-turns-over-measured = Se voltea cada T/2 = { $half } s (predicho a partir de E y |L|; medido { $measured } s): el eje 2 gira y vuelve mientras L rodea el eje { $axis }.
motion-turns-over = Se voltea cada T/2 = { $half } s (predicho a partir de E y |L|; se mide tras dos vueltas): el eje 2 gira y vuelve mientras L rodea el eje { $axis }.
motion-near-separatrix = Cerca de la separatriz: cuanto más cerca está el giro de ella, más largo es el intervalo, sin límite.
motion-wobbles = Bambolea ±{ $cone }° alrededor del eje { $axis } y nunca se voltea (un bamboleo cada T = { $period } s).
motion-separatrix = Sobre la separatriz a través del eje 2: el intervalo entre volteos crece sin límite.
motion-steady-unstable = Giro estacionario alrededor del eje { $axis }: inestable, la menor perturbación (un toque) inicia los volteos.
motion-steady-stable = Giro estacionario alrededor del eje { $axis }: estable, nada se voltea (un toque solo lo hace bambolear).
motion-steady-neutral = Giro estacionario alrededor del eje { $axis }: su momento es igual a otro, así que todo eje de su plano es principal y nada se voltea.
motion-spherical = Los tres momentos son iguales: todo eje es principal, así que el giro nunca se mueve dentro del cuerpo y nada se voltea.
motion-at-rest = En reposo: nada gira.
motion-textbook-note = El modelo de libro de texto omite ω × Iω, así que este cuerpo nunca se voltea: la predicción es la del cuerpo real.
motion-torque-note = El amortiguamiento o la cuerda cambian E y |L|: la predicción los sigue.
motion-header = Movimiento
motion-step = Paso
motion-reset = Reiniciar
motion-spin-axis = Girar eje { $axis }
motion-spin-axis-hover = alrededor de este eje principal, más una perturbación del 2 %
motion-spin-rate = Velocidad de giro
motion-unit-rad-per-second = rad/s
motion-integrator = Integrador
motion-rotation-model = Modelo de rotación
motion-gravity = Gravedad (−y)
motion-linear-damping = Amortiguamiento lineal
motion-angular-damping = Amortiguamiento angular
motion-time-scale = Escala de tiempo
motion-time-step = Paso de tiempo
motion-export = Exportar movimiento
motion-export-hover = Grabar el movimiento desde ahora en un archivo glTF (.glb) o USD (.usda) con la malla: fotogramas clave de esta simulación, para Blender, visores y motores.
motion-export-file-hover = el archivo: .glb o .usda
motion-export-choose-hover = elegir dónde guardar
motion-seconds-baked = Segundos grabados
motion-keyframes = Fotogramas por segundo
motion-unit-fps = fps
