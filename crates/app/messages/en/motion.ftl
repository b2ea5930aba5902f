# The Motion section: run and step, the spins, the motion text, export, model and time step (crates/app/src/gui/panels/motion.rs).

motion-terms-period = T: the period of the motion seen from the body (ω returns to where it was), predicted from the energy E and |L|.
motion-terms-turns-over = Turns over: axis 2 swings round to point the other way, and back, every T/2: the intermediate-axis (tennis-racket) flip.
motion-terms-wobbles = Wobbles: the spin axis circles a stable axis at a small angle and never turns over.
motion-terms-separatrix = Separatrix: the boundary between the motions about axis 1 and about axis 3, through axis 2; the closer a spin to it, the longer between flips.
motion-equal-moments = Axes { $p } and { $q } have equal moments: the body precesses about axis { $axis }, its spin axis at { $cone }° from it, once every T = { $period } s, and never turns over.
motion-turns-over-measured = Turns over every T/2 = { $half } s (predicted from E and |L|; measured { $measured } s): axis 2 swings round and back while L circles axis { $axis }.
motion-turns-over = Turns over every T/2 = { $half } s (predicted from E and |L|; measured after two turns): axis 2 swings round and back while L circles axis { $axis }.
motion-near-separatrix = Near the separatrix: the closer the spin to it, the longer the interval, without bound.
motion-wobbles = Wobbles by ±{ $cone }° about axis { $axis } and never turns over (one wobble every T = { $period } s).
motion-separatrix = On the separatrix through axis 2: the interval between flips grows without bound.
motion-steady-unstable = Steady spin about axis { $axis }: unstable, the slightest disturbance (a poke) starts the flips.
motion-steady-stable = Steady spin about axis { $axis }: stable, nothing flips (a poke only makes it wobble).
motion-steady-neutral = Steady spin about axis { $axis }: its moment equals another's, so every axis in their plane is principal and nothing flips.
motion-spherical = All three moments are equal: every axis is principal, so the spin never moves in the body and nothing flips.
motion-at-rest = At rest: nothing turns.
motion-textbook-note = The textbook model drops ω × Iω, so this body never flips: the prediction is the real body's.
motion-torque-note = Damping or the string changes E and |L|: the prediction follows them.
motion-header = Motion
motion-step = Step
motion-reset = Reset
motion-spin-axis = Spin axis { $axis }
motion-spin-axis-hover = about this principal axis, plus a 2 % perturbation
motion-spin-rate = Spin rate
motion-unit-rad-per-second = rad/s
motion-integrator = Integrator
motion-rotation-model = Rotation model
motion-gravity = Gravity (−y)
motion-linear-damping = Linear damping
motion-angular-damping = Angular damping
motion-time-scale = Time scale
motion-time-step = Time step
motion-export = Export motion
motion-export-hover = Bake the motion from now on into a glTF (.glb) or USD (.usda) file with the mesh: keyframes of this simulation, for Blender, viewers and engines.
motion-export-file-hover = the file: .glb or .usda
motion-export-choose-hover = choose where to save
motion-seconds-baked = Seconds baked
motion-keyframes = Keyframes a second
motion-unit-fps = fps
