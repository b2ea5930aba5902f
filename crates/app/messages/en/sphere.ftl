# The momentum sphere panel (crates/app/src/gui/panels/sphere.rs).

sphere-heading = Momentum sphere (principal frame)
sphere-textbook-note = Textbook model: without ω × Iω, ω never turns in the body, so the dot stands still while L turns in space (it should be fixed).
sphere-leaves-curve = The dot leaves its curve: { $reasons } changes E or |L|.
sphere-reasons-and = { $first } and { $second }
sphere-reason-damping = damping
sphere-reason-string = the string
sphere-reason-integrator = this integrator
sphere-axis = axis { $axis }: I{ $axis } = { $moment } kg·m², { $stability }
sphere-stable = stable
sphere-unstable = unstable
sphere-neutral = neutral (equal moments)
sphere-legend = orange: the separatrix; violet: L's polhode; white: L and its trail
