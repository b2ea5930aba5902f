# El resultado y los fallos de la captura de pantalla y de la grabación (crates/app/src/gui/capture.rs, archive.rs).

capture-no-pixels = los píxeles de la ventana nunca llegaron
capture-cannot-create = no se puede crear { $path }: { $error }
capture-cannot-write = no se puede escribir { $path }: { $error }
capture-recording-stopped = grabación detenida: { $error }
capture-recording-not-saved = grabación no guardada: { $path }: { $error }
capture-recorded = grabadas { $written } de { $requested } imágenes ({ $rate } por segundo) en { $path }
capture-archive-too-big = { $name }: el archivo ZIP superaría 4 GiB o 65 535 archivos
