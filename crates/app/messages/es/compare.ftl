# La sección Comparar: copias del cuerpo, cada una distinta en una elección (crates/app/src/gui/panels/compare.rs).

compare-header = Comparar
compare-intro = Copias del cuerpo desde el mismo inicio, cada una distinta en una sola elección:
compare-model-textbook = modelo de libro de texto (sin ω × Iω)
compare-model-full = modelo completo (con ω × Iω)
compare-integrator = integrador
compare-start = Comparar { $count } desde el inicio
compare-stop = Dejar de comparar
compare-too-many = Como máximo { $max } copias a la vez.
compare-ghosts = Fantasmas
compare-overlaid = superpuestos
compare-in-a-row = en fila
compare-drift-note = Deriva desde el inicio o el último toque, tirón o cambio. El toque y la cuerda actúan sobre el propio cuerpo, no sobre sus copias.
compare-turns-over = se voltea cada
compare-turns-over-hover = T/2 predicho a partir de E y |L| de la copia (— cuando solo bambolea o gira de forma estable)
compare-measured = medido
compare-measured-hover = el tiempo entre las dos últimas inversiones de ω₂ vistas en la ejecución
compare-max-energy = máx. ΔE/E
compare-max-momentum = máx. Δ|L|/|L|
compare-body = cuerpo
