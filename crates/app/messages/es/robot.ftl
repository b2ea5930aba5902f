# La sección Robot: los eslabones de una descripción de robot y sus hallazgos (crates/app/src/gui/panels/robot.rs).

robot-header = Robot
robot-summary = { $name } ({ $format }): { $links } eslabones, { $flagged } con hallazgos sobre su inercia declarada. Calculado: densidad uniforme sobre la geometría de colisión. Robot completo: el elipsoide equivalente de cada eslabón, verde según su geometría, naranja según lo declarado.
robot-whole = Robot completo (pose cero)
robot-no-inertial = sin inertial
robot-link = Eslabón { $name }
robot-stated-moments = momentos declarados { $moments } kg·m²
robot-computed-moments = momentos calculados { $moments } kg·m²
