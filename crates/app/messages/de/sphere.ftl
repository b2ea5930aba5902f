# Die Drehimpulskugel (crates/app/src/gui/panels/sphere.rs).

sphere-heading = Drehimpulskugel (Hauptachsensystem)
sphere-textbook-note = Lehrbuchmodell: ohne ω × Iω dreht sich ω im Körper nie, also steht der Punkt still, während sich L im Raum dreht (es sollte fest sein).
sphere-leaves-curve = Der Punkt verlässt seine Kurve: E oder |L| ändert sich durch { $reasons }.
sphere-reasons-and = { $first } und { $second }
sphere-reason-damping = die Dämpfung
sphere-reason-string = den Faden
sphere-reason-integrator = diesen Integrator
sphere-axis = Achse { $axis }: I{ $axis } = { $moment } kg·m², { $stability }
sphere-stable = stabil
sphere-unstable = instabil
sphere-neutral = neutral (gleiche Momente)
sphere-legend = orange: die Separatrix; violett: die Polhodie von L; weiß: L und seine Spur
