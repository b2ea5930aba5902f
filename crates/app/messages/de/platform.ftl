# Was sich zwischen Fenster und Seite unterscheidet.

drop-hint-window = oder ein Netz, eine Körperdatei .toml oder einen Roboter .urdf/.sdf/.xml auf dem Fenster ablegen
drop-hint-page = oder ein Netz oder eine Körperdatei .toml mit ihren Netzen auf der Seite ablegen
no-file-chosen-window = keine Datei gewählt (erschien kein Dialog, fehlt diesem Desktop das Dateidialog-Portal: einen Pfad eingeben oder die Datei auf dem Fenster ablegen)
no-file-chosen-page = keine Datei gewählt
record-hint-window = das Fenster als nummerierte PNG-Bilder, 10 pro Sekunde
record-hint-page = die Seite als nummerierte PNG-Bilder, 10 pro Sekunde, in einem .zip-Download
share-hint-window = hinter die Adresse der Seite des Labors setzen
share-hint-page = er öffnet diese Szene auf der Seite
dialog-body-files = Körperdateien
dialog-gltf-binary = glTF binär
