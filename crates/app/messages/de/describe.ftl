# Die Live-Beschreibung, die ein Bildschirmleser vorliest (crates/app/src/lab/describe.rs).

describe-at-rest = Der Körper „{ $name }“ ruht.
describe-spins = Der Körper „{ $name }“ dreht sich mit { $rate } rad/s um seinen Drehimpuls, überwiegend um Achse { $axis }.
describe-reversed = Achse 2 überschlägt sich: ω₂ kehrte sich bei t = { $last } s um; die nächste Umkehr wird bei t = { $next } s erwartet.
describe-will-turn-over = Achse 2 wird sich alle { $half } s überschlagen, während L Achse { $axis } umkreist.
describe-wobbles = Er taumelt um Achse { $axis }, seine Drehachse bleibt höchstens { $angle }° von ihr entfernt, und er überschlägt sich nie.
describe-steady = Er dreht sich gleichmäßig um Achse { $axis }.
describe-separatrix = Er ist auf der Separatrix: genau zwischen den beiden Bewegungsarten.
describe-textbook = Das Lehrbuchmodell ist aktiv: ohne den Term ω × Iω überschlägt sich nichts.
describe-paused = Angehalten bei t = { $time } s.
describe-copies = { $copies ->
    [one] Eine verglichene Kopie läuft daneben.
   *[other] { $copies } verglichene Kopien laufen daneben.
}
describe-lesson = Lektion: { $title }. Schritt { $step } von { $steps }: { $text }
describe-predict = Vorhersage: { $question } Auswahl: { $choices }.
describe-predicted = Ihre Vorhersage: { $choice }.
describe-checks-held = { $held } von { $checks } Prüfungen erfüllt.
describe-done = Erledigt. { $explain }
