# El marco de la ventana: título, barra superior, línea de mensajes y aviso al soltar.

window-title = Inertia Lab — { $body }
top-help = Ayuda
top-help-hover = Lo que ve, los controles y las teclas (F1)
top-lessons = Lecciones
top-lessons-hover = Actividades guiadas: predecir, probar, medir, explicar (L)
top-share = Compartir
top-share-hover = Copiar un enlace que abre esta escena: el ejemplo, su tamaño, masa y giro, la inercia y el modelo, la comparación y el paso de la lección
top-share-copied = copiado: { $address } ({ $hint })
message-dismiss = cerrar
message-none = Inertia Lab — inercia exacta frente a la estimación de la caja envolvente.
drop-adds-part = Suelte una malla para añadirla como pieza (un archivo de cuerpo para abrirlo)
drop-loads = Suelte para cargar
