# The toolbar over the 3D view (crates/app/src/gui/panels/toolbar.rs).

toolbar-frame = Frame
toolbar-frame-hover = centre the camera on the body (F)
toolbar-follow-body = Follow body
toolbar-follow-body-hover = the camera moves with the centre of mass, so a poked body stays in view
toolbar-wireframe = Wireframe
toolbar-bounding-box = Bounding box
toolbar-bounding-box-hover = the axis-aligned box around the mesh: the usual inertia guess
toolbar-com = CoM
toolbar-com-hover = the centre of mass
toolbar-principal-axes = Principal axes
toolbar-principal-axes-hover = the axes of the principal moments, 1 the least, 3 the greatest
toolbar-omega-hover = the angular velocity ω (rad/s)
toolbar-l-hover = the angular momentum L = Iω, fixed in space with no torque
toolbar-poinsot = Poinsot
toolbar-poinsot-hover = the inertia ellipsoid rolling without slipping on the plane perpendicular to L
toolbar-sphere = Sphere
toolbar-sphere-hover = the momentum sphere: L as the body sees it, on a sphere of radius |L|; its path, the polhode, circles axis 1 or 3 and crosses at the separatrix through axis 2
toolbar-equivalent = Equivalent
toolbar-equivalent-none = none
toolbar-equivalent-box = box
toolbar-equivalent-ellipsoid = ellipsoid
