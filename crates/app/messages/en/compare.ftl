# The Compare section: copies of the body, each differing in one choice (crates/app/src/gui/panels/compare.rs).

compare-header = Compare
compare-intro = Copies of the body from the same start, each differing in one choice:
compare-model-textbook = textbook model (no ω × Iω)
compare-model-full = full model (with ω × Iω)
compare-integrator = integrator
compare-start = Compare { $count } from the start
compare-stop = Stop comparing
compare-too-many = At most { $max } copies at a time.
compare-ghosts = Ghosts
compare-overlaid = overlaid
compare-in-a-row = in a row
compare-drift-note = Drift since the start or the last poke, pull or change. Poke and string act on the body itself, not on its copies.
compare-turns-over = turns over every
compare-turns-over-hover = T/2 predicted from the copy's E and |L| (— when it only wobbles or spins steadily)
compare-measured = measured
compare-measured-hover = the time between the last two reversals of ω₂ seen in the run
compare-max-energy = max ΔE/E
compare-max-momentum = max Δ|L|/|L|
compare-body = body
