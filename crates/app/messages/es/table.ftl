# La sección Propiedades de masa: la tabla de cada fuente de inercia y la que usa la simulación (crates/app/src/gui/panels/table.rs).

table-header = Propiedades de masa
table-column-bbox = caja
table-column-points = puntos
table-mass = masa (kg)
table-same = igual
table-moment-hover = Momento principal de inercia alrededor del eje principal { $axis }, momentos en orden ascendente (el eje 1, el menor)
table-error = error I{ $axis }
table-error-hover = Cuánto se aleja el momento I{ $axis } de la aproximación del exacto, en porcentaje (rojo por encima del 5 %)
table-axis-angle = ángulo eje { $axis }
table-axis-angle-hover = El ángulo entre el eje principal { $axis } de la aproximación y el exacto (rojo por encima de 5°)
table-not-applicable = n/d
table-com-offset = desvío del CM (m)
table-com-offset-hover = Cuánto se aleja el centro de masa de la aproximación del exacto
table-center-of-mass = centro de masa exacto ({ $x }; { $y }; { $z }) m
table-simulation-uses = La simulación usa
table-meaning-exact = Exacta: el sólido que encierra la malla, integrado sobre su volumen (método de Mirtich)
table-meaning-bounding-box = Caja envolvente (caja): una caja sólida alrededor de la malla, alineada con los ejes, con la misma masa, la estimación habitual de los motores de juego
table-meaning-point-masses = Puntos: la masa repartida por igual entre los vértices de la malla, como si cada uno fuera una masa puntual
table-meaning-stated = Declarada: lo que dice la descripción del robot
