# Lo que el laboratorio dice en la línea de mensajes, y las palabras de sus opciones.

lab-split = { $parts } piezas
lab-saved = guardado { $path } ({ $what })
lab-parts = { $parts } piezas
lab-parts-meshes = { $parts } piezas; mallas { $meshes }
lab-wrote-samples = { $samples } muestras escritas en { $path }
lab-wrote-keyframes = { $frames } fotogramas clave ({ $seconds } s a { $fps } fps) escritos en { $path }
lab-started-again = reiniciado desde el giro alrededor del eje { $axis }, inercia: { $source }, modelo: { $model }
lab-loaded = { $body } cargado ({ $triangles } triángulos){ $warnings ->
    [0] {""}
    [one] ; 1 aviso de la malla, en Diagnóstico de la malla
   *[other] ; { $warnings } avisos de la malla, en Diagnóstico de la malla
}
lab-added = añadido: { $parts }
lab-loaded-robot = robot { $robot } cargado ({ $links } eslabones, { $flagged } con hallazgos en su inercia): elija un eslabón en Robot
lab-load-failed = { $error } (se conserva el cuerpo actual)
lab-whole-robot = el robot entero en su posición cero, con los elipsoides de cada eslabón
lab-link-stated = eslabón { $link }: su geometría de colisión, girando junto a una copia con la inercia que declara su archivo
lab-link-unstated = eslabón { $link }: su geometría de colisión (sin inercia declarada)
lab-link-not-simulated = eslabón { $link }: su geometría de colisión; su inercia declarada no se puede simular: { $error }
variant-same = mismos ajustes
variant-source = inercia: { $source }
variant-model = modelo: { $model }
source-exact = exacta
source-bounding-box = caja envolvente
source-point-masses = masas puntuales
source-stated = declarada
model-full = completo
model-textbook = de libro de texto
