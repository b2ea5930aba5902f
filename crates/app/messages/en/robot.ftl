# The Robot section: a robot description's links and their findings (crates/app/src/gui/panels/robot.rs).

robot-header = Robot
robot-summary = { $name } ({ $format }): { $links } links, { $flagged } with findings on their stated inertia. Computed: uniform density over the collision geometry. Whole robot: each link's equivalent ellipsoid, green from its geometry, orange as stated.
robot-whole = Whole robot (zero pose)
robot-no-inertial = no inertial
robot-link = Link { $name }
robot-stated-moments = stated moments   { $moments } kg·m²
robot-computed-moments = computed moments { $moments } kg·m²
