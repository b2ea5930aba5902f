# Las palabras propias del panel de lecciones; los textos de las lecciones son de sus archivos (crates/app/src/gui/panels/lessons.rs).

lessons-heading = Lecciones
lessons-done-mark = (hecha)
lessons-own-file = Un archivo de lección propio (….lesson.toml) se abre con «Abrir malla…» o soltándolo sobre la ventana.
lessons-step = Paso { $step } de { $steps }
lessons-look-body = Observe la vista 3D.
lessons-look-table = Observe la tabla «Propiedades de masa».
lessons-look-plots = Observe las gráficas.
lessons-look-sphere = Observe la esfera del momento angular.
lessons-look-parts = Observe la sección «Piezas».
lessons-look-motion = Observe la sección «Movimiento».
lessons-predict = Prediga: { $question }
lessons-commit = Fijar mi predicción
lessons-waits-for-commit = El laboratorio espera, en pausa, hasta que usted fije su predicción.
lessons-predicted = Usted predijo: { $choice }
lessons-check-done = Hecho: { $what }
lessons-check-done-found = Hecho: { $what }: { $found }
lessons-check-waiting = Pendiente: { $what }
lessons-check-waiting-found = Pendiente: { $what }: { $found }
lessons-prediction-right = Su predicción fue correcta. La respuesta: { $answer }.
lessons-prediction-wrong = Su predicción no fue lo que ocurrió. La respuesta: { $answer }.
lessons-back = Atrás
lessons-next-step = Siguiente paso
lessons-close = Cerrar lección
lessons-finished = Lección terminada.
lessons-check-sample = «{ $sample }» está cargado
lessons-check-own-mesh = hay abierta una malla propia
lessons-check-source-exact = la simulación usa la inercia exacta
lessons-check-source-bounding-box = la simulación usa la inercia de la caja envolvente
lessons-check-source-point-masses = la simulación usa la inercia de masas puntuales
lessons-check-model-full = la ecuación de Euler completa está activa
lessons-check-model-textbook = el modelo de libro de texto está activo
lessons-check-spin-axis = el cuerpo gira sobre el eje { $axis }
lessons-check-reversals = inversiones de ω₂
lessons-check-steady = giro estable
lessons-check-half-period = medido como se predijo, con un margen del { $tolerance } %
lessons-check-flip-period = el período de volteo
lessons-check-moments-equal = dos momentos iguales con un margen del { $tolerance } %
lessons-check-poked = un toque cambió L en r × J
lessons-check-conserved = E y |L| se conservaron
lessons-check-elapsed = tiempo
lessons-check-parts = { $count ->
    [one] al menos una pieza
   *[other] al menos { $count } piezas
}
lessons-check-part-moved = una pieza se movió { $distance } m
