# The plot panel and its controls row (crates/app/src/gui/panels/plots.rs).

plots-follow = Follow
plots-window = Window
plots-history = History
plots-skipped = skipped { $seconds } s
plots-skipped-hover = The frames came too slowly for the time step: simulated time beyond the catch-up limit was skipped (a larger step or a smaller time scale keeps up).
plots-csv = CSV
plots-export-csv = Export CSV
plots-choose-file-hover = choose where to save
plots-recording = recording… { $seconds } s
plots-stop = Stop
plots-record = Record
plots-record-seconds-hover = how long to record
plots-omega-title = ω, principal frame (rad/s)
plots-l-title = L, world (kg·m²/s)
plots-energy-title = energy (J)
plots-drift = ΔE/E₀ { $now } (max { $max })
plots-drift-none = ΔE/E₀: n/a (E₀ = 0)
plots-drift-string = ΔE/E: n/a while the string pulls
