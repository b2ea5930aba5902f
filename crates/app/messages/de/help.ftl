# Das Hilfefenster zu F1 (crates/app/src/gui/panels/help.rs).

help-title = Hilfe (F1)
help-on-the-body = Am Körper
help-click-body = Körper anklicken
help-click-body-does = Stoß: Kraftstoß J entlang des Sichtstrahls; ΔL = r × J leuchtet auf
help-drag-body = Körper ziehen
help-drag-body-does = Faden: zieht den gegriffenen Punkt zum Zeiger
help-drag-background = Hintergrund ziehen
help-drag-background-does = Kamera umkreisen lassen
help-pan-drag = Rechts oder mittig ziehen
help-pan-drag-does = verschieben
help-wheel = Mausrad
help-wheel-does = zoomen
help-frame-gesture = F oder Doppelklick
help-frame-does = den Körper einpassen
help-keys = Tasten
help-key-space = Leertaste
help-key-space-does = anhalten / laufen lassen
help-key-s-does = ein Schritt (hält an)
help-key-r-does = auf den Anfangszustand zurücksetzen
help-key-axes-does = um Hauptachse 1, 2, 3 drehen
help-key-arrows = Pfeiltasten
help-key-arrows-does = das Ziel (einen Ring) über die 3D-Ansicht bewegen
help-key-p-does = den Körper am Ziel anstoßen, entlang des Sichtstrahls
help-key-l-does = die Lektionen ein- oder ausblenden
help-key-enter = Eingabe
help-key-enter-does = die fokussierte Schaltfläche drücken, die fokussierte Option wählen
help-key-f1-does = diese Hilfe
help-key-escape = Esc
help-key-escape-does = gibt die Tasten von einer Schaltfläche oder einem Feld an die Ansicht zurück (die Tasten oben wirken, welche Schaltfläche auch den Fokus hat; ein Feld, das gerade bearbeitet wird, nimmt sie selbst)
help-key-tab = Tab
help-key-tab-does = wechselt zwischen den Schaltflächen und Feldern
help-what-you-see = Was Sie sehen
help-principal-axes = Hauptachsen
help-arrows-in-world = (Momente aufsteigend). Der orange ω-Pfeil und der violette L-Pfeil liegen im raumfesten System: ohne Drehmoment bleibt L fest, während ω wandert — der T-Griff überschlägt sich um L.
help-axis-2-unstable = Die Drehung um Achse 2 (mittleres Moment) ist instabil: eine winzige Störung wächst, und der Körper überschlägt sich periodisch (Dschanibekow-Effekt). Die Achsen 1 und 3 sind stabil. Stellen Sie „Simulation verwendet“ auf den Begrenzungsquader, um zu sehen, wie die übliche Näherung die Bewegung ändert; das Lehrbuchmodell lässt den Kreiselterm weg und überschlägt sich nie.
help-sphere-poinsot-compare = Die Drehimpulskugel (rechts) zeigt L vom Körper aus gesehen: es läuft entlang seiner violetten Polhodie; die orange Separatrix durch Achse 2 trennt die Kurven um die Achsen 1 und 3. Poinsot (Werkzeugleiste) rollt das Trägheitsellipsoid auf der Ebene senkrecht zu L ab. Vergleichen (Seitenleiste) lässt Kopien, die sich in einer Wahl unterscheiden, als Geister mitlaufen; Aufnehmen (Diagrammleiste) speichert das Fenster als Bilder.
