# Der Abschnitt Bewegung: Starten und Schritt, Drehungen, Bewegungstext, Export, Modell und Zeitschritt (crates/app/src/gui/panels/motion.rs).

motion-terms-period = T: die Periode der Bewegung, vom Körper aus gesehen (ω kehrt dorthin zurück, wo es war), vorhergesagt aus der Energie E und |L|.
motion-terms-turns-over = Überschlägt sich: Achse 2 schwingt herum, bis sie in die Gegenrichtung zeigt, und zurück, alle T/2: der Überschlag um die mittlere Achse (Tennisschläger-Effekt).
motion-terms-wobbles = Taumelt: Die Drehachse umkreist eine stabile Achse in kleinem Winkel und überschlägt sich nie.
motion-terms-separatrix = Separatrix: die Grenze zwischen den Bewegungen um Achse 1 und um Achse 3, durch Achse 2; je näher eine Drehung ihr ist, desto länger zwischen den Überschlägen.
motion-equal-moments = Die Achsen { $p } und { $q } haben gleiche Momente: Der Körper präzediert um Achse { $axis }, seine Drehachse { $cone }° davon entfernt, einmal alle T = { $period } s, und überschlägt sich nie.
motion-turns-over-measured = Überschlägt sich alle T/2 = { $half } s (vorhergesagt aus E und |L|; gemessen { $measured } s): Achse 2 schwingt herum und zurück, während L um Achse { $axis } kreist.
motion-turns-over = Überschlägt sich alle T/2 = { $half } s (vorhergesagt aus E und |L|; gemessen nach zwei Überschlägen): Achse 2 schwingt herum und zurück, während L um Achse { $axis } kreist.
motion-near-separatrix = Nahe der Separatrix: Je näher die Drehung ihr ist, desto länger das Intervall, ohne Grenze.
motion-wobbles = Taumelt mit ±{ $cone }° um Achse { $axis } und überschlägt sich nie (einmal alle T = { $period } s).
motion-separatrix = Auf der Separatrix durch Achse 2: Das Intervall zwischen den Überschlägen wächst ohne Grenze.
motion-steady-unstable = Gleichmäßige Drehung um Achse { $axis }: instabil, die kleinste Störung (ein Stoß) startet die Überschläge.
motion-steady-stable = Gleichmäßige Drehung um Achse { $axis }: stabil, nichts schlägt um (ein Stoß bringt sie nur ins Taumeln).
motion-steady-neutral = Gleichmäßige Drehung um Achse { $axis }: Ihr Moment gleicht einem anderen, daher ist jede Achse in deren Ebene eine Hauptachse, und nichts schlägt um.
motion-spherical = Alle drei Momente sind gleich: Jede Achse ist eine Hauptachse, daher bewegt sich die Drehachse im Körper nie, und nichts schlägt um.
motion-at-rest = In Ruhe: Nichts dreht sich.
motion-textbook-note = Das Lehrbuchmodell lässt ω × Iω weg, daher schlägt dieser Körper nie um: Die Vorhersage ist die des echten Körpers.
motion-torque-note = Dämpfung oder der Faden ändern E und |L|: Die Vorhersage folgt ihnen.
motion-header = Bewegung
motion-step = Schritt
motion-reset = Zurücksetzen
motion-spin-axis = Um Achse { $axis }
motion-spin-axis-hover = Drehung um diese Hauptachse, plus eine Störung von 2 %
motion-spin-rate = Drehrate
motion-unit-rad-per-second = rad/s
motion-integrator = Integrator
motion-rotation-model = Rotationsmodell
motion-gravity = Schwerkraft (−y)
motion-linear-damping = Lineare Dämpfung
motion-angular-damping = Drehdämpfung
motion-time-scale = Zeitfaktor
motion-time-step = Zeitschritt
motion-export = Bewegung exportieren
motion-export-hover = Die Bewegung ab jetzt mit dem Netz in eine glTF-Datei (.glb) oder USD-Datei (.usda) schreiben: Keyframes dieser Simulation, für Blender, Viewer und Engines.
motion-export-file-hover = die Datei: .glb oder .usda
motion-export-choose-hover = Speicherort wählen
motion-seconds-baked = Exportierte Sekunden
motion-keyframes = Keyframes pro Sekunde
motion-unit-fps = fps
