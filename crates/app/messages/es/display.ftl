# El menú de idioma y el menú Pantalla en la barra superior.

display-language = Idioma
display-language-system = Sistema ({ $language })
display-menu = Pantalla
display-larger-text = Texto más grande
display-larger-text-hover = Todo una cuarta parte más grande: texto, botones y gráficas
display-reduced-motion = Menos movimiento
display-reduced-motion-hover = Nada se mueve hasta que pulse «Ejecutar»: un cuerpo que abra espera en pausa y los paneles se abren sin deslizarse
display-read-aloud = Leer en voz alta
display-read-aloud-hover = La página dice con la voz del navegador lo que recibe el foco del teclado
