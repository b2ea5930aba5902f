# La descripción en vivo que oye un lector de pantalla (crates/app/src/lab/describe.rs).

describe-at-rest = El cuerpo «{ $name }» está en reposo.
describe-spins = El cuerpo «{ $name }» gira a { $rate } rad/s alrededor de su momento angular, sobre todo alrededor del eje { $axis }.
describe-reversed = El eje 2 se voltea: ω₂ se invirtió en t = { $last } s; la siguiente inversión se predice en t = { $next } s.
describe-will-turn-over = El eje 2 se volteará, cada { $half } s, mientras L rodea el eje { $axis }.
describe-wobbles = Se bambolea alrededor del eje { $axis }, con su eje de giro a menos de { $angle }° de él, y nunca se voltea.
describe-steady = Gira de forma estable alrededor del eje { $axis }.
describe-separatrix = Está en la separatriz: justo entre los dos tipos de movimiento.
describe-textbook = El modelo de libro de texto está activo: sin el término ω × Iω nada se voltea.
describe-paused = En pausa en t = { $time } s.
describe-copies = { $copies ->
    [one] Una copia comparada se ejecuta a su lado.
   *[other] { $copies } copias comparadas se ejecutan a su lado.
}
describe-lesson = Lección: { $title }. Paso { $step } de { $steps }: { $text }
describe-predict = Prediga: { $question } Opciones: { $choices }.
describe-predicted = Usted predijo: { $choice }.
describe-checks-held = { $held } de { $checks } comprobaciones cumplidas.
describe-done = Hecho. { $explain }
