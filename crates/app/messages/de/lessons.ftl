# Die eigenen Worte der Lektionsleiste; die Texte der Lektionen stehen in ihren Dateien (crates/app/src/gui/panels/lessons.rs).

lessons-heading = Lektionen
lessons-done-mark = (erledigt)
lessons-own-file = Eine eigene Lektionsdatei (….lesson.toml) öffnet sich mit „Netz öffnen…“ oder durch Ablegen auf dem Fenster.
lessons-step = Schritt { $step } von { $steps }
lessons-look-body = Sehen Sie sich die 3D-Ansicht an.
lessons-look-table = Sehen Sie sich die Tabelle „Masseneigenschaften“ an.
lessons-look-plots = Sehen Sie sich die Diagramme an.
lessons-look-sphere = Sehen Sie sich die Drehimpulskugel an.
lessons-look-parts = Sehen Sie sich den Abschnitt „Teile“ an.
lessons-look-motion = Sehen Sie sich den Abschnitt „Bewegung“ an.
lessons-predict = Vorhersage: { $question }
lessons-commit = Vorhersage festlegen
lessons-waits-for-commit = Das Labor wartet angehalten, bis Sie sich festlegen.
lessons-predicted = Ihre Vorhersage: { $choice }
lessons-check-done = Erledigt: { $what }
lessons-check-done-found = Erledigt: { $what }: { $found }
lessons-check-waiting = Ausstehend: { $what }
lessons-check-waiting-found = Ausstehend: { $what }: { $found }
lessons-prediction-right = Ihre Vorhersage war richtig. Die Antwort: { $answer }.
lessons-prediction-wrong = Ihre Vorhersage traf nicht ein. Die Antwort: { $answer }.
lessons-back = Zurück
lessons-next-step = Nächster Schritt
lessons-close = Lektion schließen
lessons-finished = Lektion abgeschlossen.
lessons-check-sample = „{ $sample }“ ist geladen
lessons-check-own-mesh = ein eigenes Netz ist geöffnet
lessons-check-source-exact = die Simulation verwendet die exakte Trägheit
lessons-check-source-bounding-box = die Simulation verwendet die Trägheit des Begrenzungsquaders
lessons-check-source-point-masses = die Simulation verwendet die Trägheit der Punktmassen
lessons-check-model-full = die volle Euler-Gleichung ist aktiv
lessons-check-model-textbook = das Lehrbuchmodell ist aktiv
lessons-check-spin-axis = der Körper dreht sich um Achse { $axis }
lessons-check-reversals = Umkehrungen von ω₂
lessons-check-steady = gleichmäßig
lessons-check-half-period = gemessen wie vorhergesagt, auf { $tolerance } % genau
lessons-check-flip-period = die Überschlagsperiode
lessons-check-moments-equal = zwei Momente auf { $tolerance } % gleich
lessons-check-poked = ein Stoß änderte L um r × J
lessons-check-conserved = E und |L| blieben erhalten
lessons-check-elapsed = Zeit
lessons-check-parts = { $count ->
    [one] mindestens ein Teil
   *[other] mindestens { $count } Teile
}
lessons-check-part-moved = ein Teil wurde um { $distance } m verschoben
