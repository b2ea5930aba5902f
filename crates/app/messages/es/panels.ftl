# El marco del panel lateral y lo que comparten sus secciones (crates/app/src/gui/panels/mod.rs, side.rs).

panels-run = Ejecutar
panels-pause = Pausar
panels-restart-on-switch = Cambiar reinicia
panels-restart-on-switch-hover = Una nueva inercia o un nuevo modelo de rotación reinicia el movimiento con el mismo giro, para que las ejecuciones se comparen de forma justa. Desactivado: el movimiento sigue desde donde está.
side-reset-settings = Restablecer ajustes
