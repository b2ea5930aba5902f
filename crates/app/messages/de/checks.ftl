# Was die Prüfungen einer Lektion gemessen haben.

check-reversals = { $measured } von { $wanted } Umkehrungen von ω₂ gemessen
check-no-reversal = { $passed } von { $seconds } s ohne Umkehrung
check-half-period = gemessen { $measured } s zwischen Umkehrungen, vorhergesagt { $predicted } s ({ $apart } % Abweichung)
check-flip-period = vorhergesagte Überschlagsperiode { $period } s (Ziel { $target } s ± { $tolerance } %)
check-no-flip = er klappt jetzt nicht um
check-moments-apart = die zwei nächstliegenden Momente liegen { $apart } % auseinander
check-conserved = { $passed } von { $seconds } s; Energie gehalten auf { $drift }
check-elapsed = { $passed } von { $seconds } s
check-parts = { $parts ->
    [one] { $parts } Teil
   *[other] { $parts } Teile
}
check-part-moved = ein Teil von { $mass } kg um { $distance } m verschoben; der Tensor um den Ursprung änderte sich um höchstens { $measured } kg·m², der Satz von Steiner sagt { $predicted }
