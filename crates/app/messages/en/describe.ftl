# The live description a screen reader hears (crates/app/src/lab/describe.rs).

describe-at-rest = The { $name } is at rest.
describe-spins = The { $name } spins at { $rate } rad/s about its angular momentum, mostly about axis { $axis }.
describe-reversed = Axis 2 turns over: ω₂ reversed at t = { $last } s; the next reversal is predicted at t = { $next } s.
describe-will-turn-over = Axis 2 will turn over, every { $half } s, while L circles axis { $axis }.
describe-wobbles = It wobbles about axis { $axis }, its spin axis within { $angle }° of it, and never turns over.
describe-steady = It turns steadily about axis { $axis }.
describe-separatrix = It is on the separatrix: exactly between the two kinds of motion.
describe-textbook = The textbook model is on: without the term ω × Iω nothing turns over.
describe-paused = Paused at t = { $time } s.
describe-copies = { $copies ->
    [one] { $copies } compared copy runs beside it.
   *[other] { $copies } compared copies run beside it.
}
describe-lesson = Lesson: { $title }. Step { $step } of { $steps }: { $text }
describe-predict = Predict: { $question } Choices: { $choices }.
describe-predicted = You predicted: { $choice }.
describe-checks-held = { $held } of { $checks } checks held.
describe-done = Done. { $explain }
