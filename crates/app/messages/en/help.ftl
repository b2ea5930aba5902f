# The F1 help window (crates/app/src/gui/panels/help.rs).

help-title = Help (F1)
help-on-the-body = On the body
help-click-body = Click the body
help-click-body-does = poke: impulse J along the view ray; ΔL = r × J flashes
help-drag-body = Drag the body
help-drag-body-does = string: pulls the grabbed point towards the pointer
help-drag-background = Drag the background
help-drag-background-does = orbit the camera
help-pan-drag = Right or middle drag
help-pan-drag-does = pan
help-wheel = Wheel
help-wheel-does = zoom
help-frame-gesture = F or double-click
help-frame-does = frame the body
help-keys = Keys
help-key-space = Space
help-key-space-does = pause / run
help-key-s-does = one step (pauses)
help-key-r-does = reset to the start state
help-key-axes-does = spin about principal axis 1, 2, 3
help-key-arrows = Arrows
help-key-arrows-does = move the aim (a ring) over the 3D view
help-key-p-does = poke the body at the aim, along the view ray
help-key-l-does = show or hide the lessons
help-key-enter = Enter
help-key-enter-does = press the focused button, choose the focused option
help-key-f1-does = this help
help-key-escape = Escape
help-key-escape-does = gives the keys back to the view from a button or field (the keys above act whatever button has focus; a field being edited takes them)
help-key-tab = Tab
help-key-tab-does = moves between the buttons and fields
help-what-you-see = What you see
help-principal-axes = Principal axes
help-arrows-in-world = (moments ascending). Orange ω and purple L arrows are in world space: with no torque L stays fixed while ω wanders — the T-handle flips about it.
help-axis-2-unstable = Spinning about axis 2 (intermediate moment) is unstable: a tiny perturbation grows and the body flips periodically (Dzhanibekov effect). Axes 1 and 3 are stable. Switch "Simulation uses" to the bounding box to see how the usual approximation changes the motion; the Textbook model drops the gyroscopic term and never flips.
help-sphere-poinsot-compare = The momentum sphere (right) shows L as seen from the body: it runs along its violet polhode; the orange separatrix through axis 2 parts the curves around axes 1 and 3. Poinsot (toolbar) rolls the inertia ellipsoid on the plane perpendicular to L. Compare (side panel) runs copies that differ in one choice as ghosts; Record (plot bar) saves the window as pictures.
