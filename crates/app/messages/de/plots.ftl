# Die Diagramme und ihre Bedienzeile (crates/app/src/gui/panels/plots.rs).

plots-follow = Folgen
plots-window = Fenster
plots-history = Verlauf
plots-skipped = { $seconds } s übersprungen
plots-skipped-hover = Die Bilder kamen zu langsam für den Zeitschritt: simulierte Zeit jenseits der Aufholgrenze wurde übersprungen (ein größerer Schritt oder ein kleinerer Zeitmaßstab hält mit).
plots-csv = CSV
plots-export-csv = CSV exportieren
plots-choose-file-hover = Speicherort wählen
plots-recording = Aufnahme… { $seconds } s
plots-stop = Stopp
plots-record = Aufnehmen
plots-record-seconds-hover = wie lange aufgenommen wird
plots-omega-title = ω, Hauptachsensystem (rad/s)
plots-l-title = L, raumfest (kg·m²/s)
plots-energy-title = Energie (J)
plots-drift = ΔE/E₀ { $now } (max. { $max })
plots-drift-none = ΔE/E₀: k. A. (E₀ = 0)
plots-drift-string = ΔE/E: k. A., solange der Faden zieht
