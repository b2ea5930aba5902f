# La sección Cuerpo: abrir un archivo, los ejemplos, la carga, el tamaño y la masa (crates/app/src/gui/panels/body.rs).

body-header = Cuerpo
body-open-mesh = Abrir malla…
body-mesh-formats = Mallas: { $formats }
body-path = Ruta
body-load = Cargar
body-samples = Ejemplos:
body-made-of-parts = De piezas:
body-stage-starting = iniciando…
body-stage-reading = leyendo…
body-stage-checking = comprobando la malla y sus propiedades de masa…
body-stage-picking-index = creando el índice de selección…
body-stage-robot = leyendo y auditando el robot…
body-size = Tamaño ×
body-mass-from-parts = Masa { $mass } kg, según los materiales de las piezas (abajo)
body-volume = Volumen { $volume } m³
body-volume-hover = Las piezas sólidas y las paredes delgadas, menos los huecos.
body-density = Densidad
body-mass = Masa
body-volume-mass = Volumen { $volume } m³, masa { $mass } kg
