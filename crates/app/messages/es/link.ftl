# Lo que los parámetros de un enlace y el botón Compartir dicen al usuario (crates/app/src/gui/link.rs).

link-spin-invalid = spin={ $value }: el eje principal es 1, 2 o 3 (del momento menor al mayor)
link-source-invalid = source={ $value }: exact, bbox o points
link-model-invalid = model={ $value }: full o textbook
link-size-invalid = size={ $value }: indique un número positivo
link-density-invalid = density={ $value }: indique un número positivo de kg/m³
link-mass-invalid = mass={ $value }: indique un número positivo de kg
link-rate-invalid = rate={ $value }: indique un número positivo de rad/s
link-step-invalid = step={ $value }: el paso de la lección, desde 1
link-bench-invalid = bench={ $value }: indique el número de fotogramas que medir
link-unknown-key = parámetro de enlace desconocido { $key } (conocidos: { $known })
link-step-needs-lesson = step= requiere lesson=
link-own-file = { $name } viene de un archivo suyo, que un enlace no puede llevar: un enlace solo abre los ejemplos incluidos (envíe el archivo junto con el enlace)
link-sample-unknown = sample={ $value }: no existe ese ejemplo (hay { $samples })
link-compare-unknown = compare={ $value }: { $name } no es ninguno de bbox, points, textbook
link-compare-too-many = compare={ $value }: como máximo { $most } copias
link-lang-invalid = lang={ $value }: el laboratorio habla en, de y es
link-problems = el enlace: { $problems }
link-lesson-not-fetched = lesson={ $address }: no se pudo obtener ({ $why })
