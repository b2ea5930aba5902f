# Der Fensterrahmen: Titel, obere Leiste, Meldungszeile und Hinweis beim Ablegen.

window-title = Inertia Lab — { $body }
top-help = Hilfe
top-help-hover = Was Sie sehen, die Bedienelemente und die Tasten (F1)
top-lessons = Lektionen
top-lessons-hover = Angeleitete Aktivitäten: vorhersagen, ausprobieren, messen, erklären (L)
top-share = Teilen
top-share-hover = Einen Link kopieren, der diese Szene öffnet: das Beispiel, seine Größe, Masse und Drehung, Trägheit und Modell, den Vergleich und den Schritt der Lektion
top-share-copied = kopiert: { $address } ({ $hint })
message-dismiss = schließen
message-none = Inertia Lab — exakte Trägheit gegen die Schätzung aus dem Begrenzungsquader.
drop-adds-part = Ein Netz ablegen, um es als Teil hinzuzufügen (eine Körperdatei, um sie zu öffnen)
drop-loads = Zum Laden ablegen
