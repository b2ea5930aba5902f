# Was das Labor in der Meldungszeile sagt, und die Wörter für seine Auswahlen.

lab-split = { $parts } Teile
lab-saved = gespeichert: { $path } ({ $what })
lab-parts = { $parts } Teile
lab-parts-meshes = { $parts } Teile; Netze { $meshes }
lab-wrote-samples = { $samples } Messwerte nach { $path } geschrieben
lab-wrote-keyframes = { $frames } Schlüsselbilder ({ $seconds } s bei { $fps } fps) nach { $path } geschrieben
lab-started-again = neu gestartet mit der Drehung um Achse { $axis }, Trägheit: { $source }, Modell: { $model }
lab-loaded = { $body } geladen ({ $triangles } Dreiecke){ $warnings ->
    [0] {""}
    [one] ; 1 Warnung zum Netz, unter Netzdiagnose
   *[other] ; { $warnings } Warnungen zum Netz, unter Netzdiagnose
}
lab-added = hinzugefügt: { $parts }
lab-loaded-robot = Roboter { $robot } geladen ({ $links } Glieder, { $flagged } mit Befunden zu ihrer Trägheit): unter Roboter ein Glied wählen
lab-load-failed = { $error } (der bisherige Körper bleibt)
lab-whole-robot = der ganze Roboter in seiner Nullstellung, mit den Ellipsoiden jedes Glieds
lab-link-stated = Glied { $link }: seine Kollisionsgeometrie, die sich neben einer Kopie mit der in seiner Datei angegebenen Trägheit dreht
lab-link-unstated = Glied { $link }: seine Kollisionsgeometrie (keine Trägheit angegeben)
lab-link-not-simulated = Glied { $link }: seine Kollisionsgeometrie; seine angegebene Trägheit lässt sich nicht simulieren: { $error }
variant-same = gleiche Einstellungen
variant-source = Trägheit: { $source }
variant-model = Modell: { $model }
source-exact = exakt
source-bounding-box = Begrenzungsquader
source-point-masses = Punktmassen
source-stated = angegeben
model-full = vollständig
model-textbook = Lehrbuch
