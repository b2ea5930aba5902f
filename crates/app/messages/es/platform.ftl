# Lo que difiere entre la ventana y la página.

drop-hint-window = o suelte una malla, un cuerpo .toml o un robot .urdf/.sdf/.xml en la ventana
drop-hint-page = o suelte una malla, o un cuerpo .toml con sus mallas, en la página
no-file-chosen-window = no se eligió ningún archivo (si no apareció ningún diálogo, este escritorio no tiene portal de diálogos de archivo: escriba una ruta o suelte el archivo en la ventana)
no-file-chosen-page = no se eligió ningún archivo
record-hint-window = la ventana como imágenes PNG numeradas, 10 por segundo
record-hint-page = la página como imágenes PNG numeradas, 10 por segundo, en una sola descarga .zip
share-hint-window = póngalo tras la dirección de la página del laboratorio
share-hint-page = abre esta escena en la página
dialog-body-files = Archivos de cuerpo
dialog-gltf-binary = glTF binario
