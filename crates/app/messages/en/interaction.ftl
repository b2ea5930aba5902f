# The Poke and string section: the interaction strengths (crates/app/src/gui/panels/interaction.rs).

interaction-header = Poke and string
interaction-poke = Poke
interaction-poke-unit = % of |L|
interaction-poke-hover = How much a click changes the angular momentum L, at most: a click at the point farthest from the centre of mass, across it. Small, so that a stable spin stays stable; large enough to start a tumble from an unstable one.
interaction-impulse = J = { $impulse } N·s, |ΔL| up to { $delta } kg m²/s
interaction-string-frequency = String frequency
interaction-string-damping = String damping ratio
interaction-force-cap = Force cap F/m
interaction-max-force = F max = { $force } N
