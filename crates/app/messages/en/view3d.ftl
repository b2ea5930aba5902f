# The 3D view's hint line and the labels over the body (crates/app/src/gui/view3d/).

view3d-hint = Click body: poke · Drag body: string · Drag background: orbit · Right/middle drag: pan · Wheel: zoom · F: frame · Space: pause · S: step · R: reset · Arrows and P: aim and poke · L: lessons · F1: help
view3d-unavailable = 3D view unavailable (no OpenGL context)
view3d-drawn-simplified = Drawn simplified: { $drawn } of { $total } triangles (the drawing budget of a software renderer); every number and pick uses them all · { $hint }
view3d-wireframe-off = Wireframe off above { $edges } edges · { $hint }
view3d-gl-context = cannot use the GL context: { $error }
view3d-ellipsoids-too-large = { $count } ellipsoid(s) larger than the robot, not drawn (up to { $across } m across)
view3d-face = face { $face }
view3d-faces = faces { $faces }
view3d-bounding-box = bounding box
view3d-equivalent-ellipsoid = equivalent ellipsoid
view3d-invariable-plane = invariable plane (perpendicular to L)
view3d-exact-com = exact CoM
view3d-l-fixed = L (fixed: no torque)
