# La sección Toque y cuerda: la intensidad de las interacciones (crates/app/src/gui/panels/interaction.rs).

interaction-header = Toque y cuerda
interaction-poke = Toque
interaction-poke-unit = % de |L|
interaction-poke-hover = Cuánto cambia un clic el momento angular L, como máximo: un clic en el punto más alejado del centro de masa, transversal a él. Pequeño, para que un giro estable siga estable; lo bastante grande para iniciar un vuelco desde uno inestable.
interaction-impulse = J = { $impulse } N·s; |ΔL| hasta { $delta } kg m²/s
interaction-string-frequency = Frecuencia de la cuerda
interaction-string-damping = Amortiguamiento de la cuerda
interaction-force-cap = Límite de fuerza F/m
interaction-max-force = F máx. = { $force } N
