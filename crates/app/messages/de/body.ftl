# Der Abschnitt Körper: Datei öffnen, Beispiele, Laden, Größe und Masse (crates/app/src/gui/panels/body.rs).

body-header = Körper
body-open-mesh = Netz öffnen…
body-mesh-formats = Netze: { $formats }
body-path = Pfad
body-load = Laden
body-samples = Beispiele:
body-made-of-parts = Aus Teilen:
body-stage-starting = wird gestartet…
body-stage-reading = wird gelesen…
body-stage-checking = Netz und Masseneigenschaften werden geprüft…
body-stage-picking-index = Auswahlindex wird erstellt…
body-stage-robot = Roboter wird gelesen und geprüft…
body-size = Größe ×
body-mass-from-parts = Masse { $mass } kg, aus den Materialien der Teile (unten)
body-volume = Volumen { $volume } m³
body-volume-hover = Die festen Teile und dünnen Wände, abzüglich der Hohlräume.
body-density = Dichte
body-mass = Masse
body-volume-mass = Volumen { $volume } m³, Masse { $mass } kg
