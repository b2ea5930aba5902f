# Ergebnis und Fehler von Bildschirmfoto und Aufnahme (crates/app/src/gui/capture.rs, archive.rs).

capture-no-pixels = die Pixel des Fensters kamen nie an
capture-cannot-create = { $path } kann nicht angelegt werden: { $error }
capture-cannot-write = { $path } kann nicht geschrieben werden: { $error }
capture-recording-stopped = Aufnahme abgebrochen: { $error }
capture-recording-not-saved = Aufnahme nicht gespeichert: { $path }: { $error }
capture-recorded = { $written } von { $requested } Bildern ({ $rate } pro Sekunde) in { $path } aufgenommen
capture-archive-too-big = { $name }: Das Archiv würde 4 GiB oder 65 535 Dateien überschreiten
