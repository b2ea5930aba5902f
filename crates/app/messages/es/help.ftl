# La ventana de ayuda de F1 (crates/app/src/gui/panels/help.rs).

help-title = Ayuda (F1)
help-on-the-body = Sobre el cuerpo
help-click-body = Clic en el cuerpo
help-click-body-does = toque: impulso J a lo largo del rayo de vista; ΔL = r × J destella
help-drag-body = Arrastrar el cuerpo
help-drag-body-does = cuerda: tira del punto agarrado hacia el puntero
help-drag-background = Arrastrar el fondo
help-drag-background-does = orbitar la cámara
help-pan-drag = Arrastrar con botón derecho o central
help-pan-drag-does = desplazar
help-wheel = Rueda
help-wheel-does = zoom
help-frame-gesture = F o doble clic
help-frame-does = encuadrar el cuerpo
help-keys = Teclas
help-key-space = Espacio
help-key-space-does = pausar / continuar
help-key-s-does = un paso (pausa)
help-key-r-does = volver al estado inicial
help-key-axes-does = girar sobre el eje principal 1, 2, 3
help-key-arrows = Flechas
help-key-arrows-does = mover la mira (un anillo) sobre la vista 3D
help-key-p-does = dar un toque al cuerpo en la mira, a lo largo del rayo de vista
help-key-l-does = mostrar u ocultar las lecciones
help-key-enter = Intro
help-key-enter-does = pulsar el botón enfocado, elegir la opción enfocada
help-key-f1-does = esta ayuda
help-key-escape = Esc
help-key-escape-does = devuelve las teclas a la vista desde un botón o campo (las teclas de arriba actúan tenga el foco el botón que tenga; un campo en edición se las queda)
help-key-tab = Tab
help-key-tab-does = pasa de un botón o campo a otro
help-what-you-see = Lo que ve
help-principal-axes = Ejes principales
help-arrows-in-world = (momentos en orden creciente). Las flechas naranja de ω y morada de L están en el sistema fijo al espacio: sin par de torsión L queda fijo mientras ω deambula — el mango en T se voltea alrededor de L.
help-axis-2-unstable = Girar sobre el eje 2 (momento intermedio) es inestable: una perturbación mínima crece y el cuerpo se voltea periódicamente (efecto Dzhanibekov). Los ejes 1 y 3 son estables. Cambie «La simulación usa» a la caja envolvente para ver cómo la aproximación habitual cambia el movimiento; el modelo de libro de texto omite el término giroscópico y nunca se voltea.
help-sphere-poinsot-compare = La esfera del momento angular (a la derecha) muestra L visto desde el cuerpo: recorre su polhodia violeta; la separatriz naranja que pasa por el eje 2 separa las curvas alrededor de los ejes 1 y 3. Poinsot (barra de herramientas) hace rodar el elipsoide de inercia sobre el plano perpendicular a L. Comparar (panel lateral) ejecuta copias que difieren en una elección como fantasmas; Grabar (barra de gráficas) guarda la ventana como imágenes.
