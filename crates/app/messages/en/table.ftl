# The Mass properties section: every inertia source's table and the one the simulation uses (crates/app/src/gui/panels/table.rs).

table-header = Mass properties
table-column-bbox = bbox
table-column-points = points
table-mass = mass (kg)
table-same = same
table-moment-hover = Principal moment of inertia about principal axis { $axis }, moments ascending (axis 1 the least)
table-error = error I{ $axis }
table-error-hover = How far the approximation's moment I{ $axis } is from the exact one, in percent (red beyond 5 %)
table-axis-angle = axis { $axis } angle
table-axis-angle-hover = The angle between the approximation's principal axis { $axis } and the exact one (red beyond 5°)
table-not-applicable = n/a
table-com-offset = CoM offset (m)
table-com-offset-hover = How far the approximation's centre of mass is from the exact one
table-center-of-mass = exact centre of mass ({ $x }, { $y }, { $z }) m
table-simulation-uses = Simulation uses
table-meaning-exact = Exact: the solid the mesh encloses, integrated over its volume (Mirtich's method)
table-meaning-bounding-box = Bounding box (bbox): a solid box around the mesh, axis-aligned, with the same mass, the usual guess of game engines
table-meaning-point-masses = Points: the mass shared equally among the mesh's vertices, as if each were a point mass
table-meaning-stated = Stated: what the robot description says
