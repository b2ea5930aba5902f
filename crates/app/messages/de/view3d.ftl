# Die Hinweiszeile der 3D-Ansicht und die Beschriftungen über dem Körper (crates/app/src/gui/view3d/).

view3d-hint = Klick auf Körper: Stoß · Körper ziehen: Faden · Hintergrund ziehen: drehen · Rechts/Mitte ziehen: verschieben · Mausrad: zoomen · F: einpassen · Leertaste: Pause · S: Schritt · R: zurücksetzen · Pfeile und P: zielen und stoßen · L: Lektionen · F1: Hilfe
view3d-unavailable = 3D-Ansicht nicht verfügbar (kein OpenGL-Kontext)
view3d-drawn-simplified = Vereinfacht gezeichnet: { $drawn } von { $total } Dreiecken (das Zeichenbudget eines Software-Renderers); alle Zahlen und jedes Anklicken verwenden sie alle · { $hint }
view3d-wireframe-off = Drahtgitter aus über { $edges } Kanten · { $hint }
view3d-gl-context = der GL-Kontext ist nicht nutzbar: { $error }
view3d-ellipsoids-too-large = { $count } Ellipsoid(e) größer als der Roboter, nicht gezeichnet (bis zu { $across } m groß)
view3d-face = Fläche { $face }
view3d-faces = Flächen { $faces }
view3d-bounding-box = Begrenzungsquader
view3d-equivalent-ellipsoid = Ersatzellipsoid
view3d-invariable-plane = invariable Ebene (senkrecht zu L)
view3d-exact-com = exakter Schwerpunkt
view3d-l-fixed = L (fest: kein Drehmoment)
