# Die Werkzeugleiste über der 3D-Ansicht (crates/app/src/gui/panels/toolbar.rs).

toolbar-frame = Einpassen
toolbar-frame-hover = die Kamera auf den Körper ausrichten (F)
toolbar-follow-body = Körper folgen
toolbar-follow-body-hover = die Kamera bewegt sich mit dem Schwerpunkt, sodass ein angestoßener Körper im Blick bleibt
toolbar-wireframe = Drahtgitter
toolbar-bounding-box = Begrenzungsquader
toolbar-bounding-box-hover = der achsparallele Quader um das Netz: die übliche Schätzung der Trägheit
toolbar-com = SP
toolbar-com-hover = der Schwerpunkt
toolbar-principal-axes = Hauptachsen
toolbar-principal-axes-hover = die Achsen der Hauptträgheitsmomente, 1 das kleinste, 3 das größte
toolbar-omega-hover = die Winkelgeschwindigkeit ω (rad/s)
toolbar-l-hover = der Drehimpuls L = Iω, ohne Drehmoment raumfest
toolbar-poinsot = Poinsot
toolbar-poinsot-hover = das Trägheitsellipsoid, das ohne Gleiten auf der Ebene senkrecht zu L abrollt
toolbar-sphere = Kugel
toolbar-sphere-hover = die Drehimpulskugel: L, wie der Körper es sieht, auf einer Kugel vom Radius |L|; seine Bahn, die Polhodie, umkreist Achse 1 oder 3 und wechselt an der Separatrix durch Achse 2
toolbar-equivalent = Ersatzkörper
toolbar-equivalent-none = keiner
toolbar-equivalent-box = Quader
toolbar-equivalent-ellipsoid = Ellipsoid
