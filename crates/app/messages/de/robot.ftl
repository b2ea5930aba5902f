# Der Abschnitt Roboter: die Glieder einer Roboterbeschreibung und ihre Befunde (crates/app/src/gui/panels/robot.rs).

robot-header = Roboter
robot-summary = { $name } ({ $format }): { $links } Glieder, { $flagged } mit Befunden zu ihrer angegebenen Trägheit. Berechnet: gleichmäßige Dichte über die Kollisionsgeometrie. Ganzer Roboter: das Ersatzellipsoid jedes Glieds, grün aus seiner Geometrie, orange wie angegeben.
robot-whole = Ganzer Roboter (Nullstellung)
robot-no-inertial = ohne Inertial
robot-link = Glied { $name }
robot-stated-moments = angegebene Momente { $moments } kg·m²
robot-computed-moments = berechnete Momente { $moments } kg·m²
