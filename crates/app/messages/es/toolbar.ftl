# La barra de herramientas sobre la vista 3D (crates/app/src/gui/panels/toolbar.rs).

toolbar-frame = Encuadrar
toolbar-frame-hover = centrar la cámara en el cuerpo (F)
toolbar-follow-body = Seguir cuerpo
toolbar-follow-body-hover = la cámara se mueve con el centro de masa, así un cuerpo tras un toque sigue a la vista
toolbar-wireframe = Alambre
toolbar-bounding-box = Caja envolvente
toolbar-bounding-box-hover = la caja alineada con los ejes alrededor de la malla: la estimación habitual de la inercia
toolbar-com = CM
toolbar-com-hover = el centro de masa
toolbar-principal-axes = Ejes principales
toolbar-principal-axes-hover = los ejes de los momentos principales, 1 el menor, 3 el mayor
toolbar-omega-hover = la velocidad angular ω (rad/s)
toolbar-l-hover = el momento angular L = Iω, fijo en el espacio sin par de torsión
toolbar-poinsot = Poinsot
toolbar-poinsot-hover = el elipsoide de inercia rodando sin deslizar sobre el plano perpendicular a L
toolbar-sphere = Esfera
toolbar-sphere-hover = la esfera del momento angular: L tal como lo ve el cuerpo, sobre una esfera de radio |L|; su trayectoria, la polhodia, rodea el eje 1 o el 3 y cambia en la separatriz que pasa por el eje 2
toolbar-equivalent = Equivalente
toolbar-equivalent-none = ninguno
toolbar-equivalent-box = caja
toolbar-equivalent-ellipsoid = elipsoide
