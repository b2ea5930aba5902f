# Das Sprachmenü und das Menü Anzeige in der oberen Leiste.

display-language = Sprache
display-language-system = System ({ $language })
display-menu = Anzeige
display-larger-text = Größere Schrift
display-larger-text-hover = Alles um ein Viertel größer: Text, Schaltflächen und Diagramme
display-reduced-motion = Weniger Bewegung
display-reduced-motion-hover = Nichts bewegt sich, bis Sie „Starten“ drücken: ein geöffneter Körper wartet angehalten, und Bereiche öffnen sich ohne Gleiten
display-read-aloud = Vorlesen
display-read-aloud-hover = Die Seite spricht mit der Stimme des Browsers aus, was den Tastaturfokus erhält
