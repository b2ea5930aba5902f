# Las gráficas y su fila de controles (crates/app/src/gui/panels/plots.rs).

plots-follow = Seguir
plots-window = Ventana
plots-history = Historial
plots-skipped = { $seconds } s omitidos
plots-skipped-hover = Los fotogramas llegaron demasiado despacio para el paso de tiempo: se omitió el tiempo simulado más allá del límite de recuperación (un paso mayor o una escala de tiempo menor lo sigue).
plots-csv = CSV
plots-export-csv = Exportar CSV
plots-choose-file-hover = elegir dónde guardar
plots-recording = grabando… { $seconds } s
plots-stop = Detener
plots-record = Grabar
plots-record-seconds-hover = cuánto tiempo grabar
plots-omega-title = ω, sistema principal (rad/s)
plots-l-title = L, sistema fijo (kg·m²/s)
plots-energy-title = energía (J)
plots-drift = ΔE/E₀ { $now } (máx. { $max })
plots-drift-none = ΔE/E₀: n/d (E₀ = 0)
plots-drift-string = ΔE/E: n/d mientras tira la cuerda
