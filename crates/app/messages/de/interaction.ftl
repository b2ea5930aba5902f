# Der Abschnitt Stoß und Faden: die Stärken der Eingriffe (crates/app/src/gui/panels/interaction.rs).

interaction-header = Stoß und Faden
interaction-poke = Stoß
interaction-poke-unit = % von |L|
interaction-poke-hover = Wie stark ein Klick den Drehimpuls L höchstens ändert: ein Klick quer zum Punkt, der am weitesten vom Schwerpunkt entfernt ist. Klein, damit eine stabile Drehung stabil bleibt; groß genug, um eine instabile ins Überschlagen zu bringen.
interaction-impulse = J = { $impulse } N·s; |ΔL| bis { $delta } kg m²/s
interaction-string-frequency = Fadenfrequenz
interaction-string-damping = Dämpfungsgrad des Fadens
interaction-force-cap = Kraftgrenze F/m
interaction-max-force = F max. = { $force } N
