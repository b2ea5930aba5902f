# The Body section: opening a file, the samples, loading, size and mass (crates/app/src/gui/panels/body.rs).

body-header = Body
body-open-mesh = Open mesh…
body-mesh-formats = Meshes: { $formats }
body-path = Path
body-load = Load
body-samples = Samples:
body-made-of-parts = Made of parts:
body-stage-starting = starting…
body-stage-reading = reading…
body-stage-checking = checking the mesh and its mass properties…
body-stage-picking-index = picking index…
body-stage-robot = reading and auditing the robot…
body-size = Size ×
body-mass-from-parts = Mass { $mass } kg, from the parts' materials (below)
body-volume = Volume { $volume } m³
body-volume-hover = The solid parts and thin walls, less the voids.
body-density = Density
body-mass = Mass
body-volume-mass = Volume { $volume } m³, mass { $mass } kg
