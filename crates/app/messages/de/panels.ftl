# Der Rahmen der Seitenleiste und was ihre Abschnitte teilen (crates/app/src/gui/panels/mod.rs, side.rs).

panels-run = Starten
panels-pause = Anhalten
panels-restart-on-switch = Wechsel startet neu
panels-restart-on-switch-hover = Eine andere Trägheit oder ein anderes Rotationsmodell startet die Bewegung neu mit derselben Drehung, damit sich die Läufe fair vergleichen lassen. Aus: Die Bewegung läuft weiter, wo sie ist.
side-reset-settings = Einstellungen zurücksetzen
