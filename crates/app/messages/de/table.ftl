# Der Abschnitt Masseneigenschaften: die Tabelle aller Trägheitsquellen und die, die die Simulation verwendet (crates/app/src/gui/panels/table.rs).

table-header = Masseneigenschaften
table-column-bbox = Quader
table-column-points = Punkte
table-mass = Masse (kg)
table-same = gleich
table-moment-hover = Hauptträgheitsmoment um Hauptachse { $axis }, Momente aufsteigend (Achse 1 das kleinste)
table-error = Fehler I{ $axis }
table-error-hover = Wie weit das Moment I{ $axis } der Näherung vom exakten abweicht, in Prozent (rot über 5 %)
table-axis-angle = Winkel Achse { $axis }
table-axis-angle-hover = Der Winkel zwischen der Hauptachse { $axis } der Näherung und der exakten (rot über 5°)
table-not-applicable = k. A.
table-com-offset = SP-Versatz (m)
table-com-offset-hover = Wie weit der Schwerpunkt der Näherung vom exakten abweicht
table-center-of-mass = exakter Schwerpunkt ({ $x }; { $y }; { $z }) m
table-simulation-uses = Simulation verwendet
table-meaning-exact = Exakt: der Festkörper, den das Netz umschließt, über sein Volumen integriert (Verfahren von Mirtich)
table-meaning-bounding-box = Begrenzungsquader (Quader): ein massiver, achsparalleler Quader um das Netz mit derselben Masse, die übliche Schätzung von Spiele-Engines
table-meaning-point-masses = Punkte: die Masse gleichmäßig auf die Eckpunkte des Netzes verteilt, als wäre jeder eine Punktmasse
table-meaning-stated = Angegeben: was die Roboterbeschreibung sagt
