# Der Abschnitt Vergleichen: Kopien des Körpers, die sich in je einer Wahl unterscheiden (crates/app/src/gui/panels/compare.rs).

compare-header = Vergleichen
compare-intro = Kopien des Körpers vom selben Anfang, die sich jeweils in einer Wahl unterscheiden:
compare-model-textbook = Lehrbuchmodell (ohne ω × Iω)
compare-model-full = vollständiges Modell (mit ω × Iω)
compare-integrator = Integrator
compare-start = { $count } vom Anfang vergleichen
compare-stop = Vergleich beenden
compare-too-many = Höchstens { $max } Kopien gleichzeitig.
compare-ghosts = Geister
compare-overlaid = überlagert
compare-in-a-row = nebeneinander
compare-drift-note = Drift seit dem Anfang oder dem letzten Stoß, Zug oder der letzten Änderung. Stoß und Faden wirken auf den Körper selbst, nicht auf seine Kopien.
compare-turns-over = überschlägt sich alle
compare-turns-over-hover = T/2, vorhergesagt aus E und |L| der Kopie (—, wenn sie nur taumelt oder gleichmäßig dreht)
compare-measured = gemessen
compare-measured-hover = die Zeit zwischen den letzten beiden Umkehrungen von ω₂ in diesem Lauf
compare-max-energy = max. ΔE/E
compare-max-momentum = max. Δ|L|/|L|
compare-body = Körper
