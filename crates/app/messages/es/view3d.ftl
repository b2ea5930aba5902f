# La línea de ayuda de la vista 3D y las etiquetas sobre el cuerpo (crates/app/src/gui/view3d/).

view3d-hint = Clic en el cuerpo: toque · Arrastrar el cuerpo: cuerda · Arrastrar el fondo: orbitar · Arrastre derecho/central: desplazar · Rueda: zoom · F: encuadrar · Espacio: pausa · S: paso · R: reiniciar · Flechas y P: apuntar y tocar · L: lecciones · F1: ayuda
view3d-unavailable = Vista 3D no disponible (sin contexto OpenGL)
view3d-drawn-simplified = Dibujo simplificado: { $drawn } de { $total } triángulos (el límite de dibujo de un renderizador por software); cada número y cada selección los usan todos · { $hint }
view3d-wireframe-off = Alambre desactivado por encima de { $edges } aristas · { $hint }
view3d-gl-context = no se puede usar el contexto GL: { $error }
view3d-ellipsoids-too-large = { $count } elipsoide(s) más grande(s) que el robot, sin dibujar (hasta { $across } m de ancho)
view3d-face = cara { $face }
view3d-faces = caras { $faces }
view3d-bounding-box = caja envolvente
view3d-equivalent-ellipsoid = elipsoide equivalente
view3d-invariable-plane = plano invariable (perpendicular a L)
view3d-exact-com = centro de masa exacto
view3d-l-fixed = L (fijo: sin torque)
