# Lo que han medido las comprobaciones de una lección.

check-reversals = { $measured } de { $wanted } inversiones de ω₂ medidas
check-no-reversal = { $passed } de { $seconds } s sin inversión
check-half-period = medido { $measured } s entre inversiones, predicho { $predicted } s ({ $apart } % de diferencia)
check-flip-period = periodo de volteo predicho { $period } s (objetivo { $target } s ± { $tolerance } %)
check-no-flip = ahora no se voltea
check-moments-apart = los dos momentos más cercanos difieren un { $apart } %
check-conserved = { $passed } de { $seconds } s; energía conservada con { $drift }
check-elapsed = { $passed } de { $seconds } s
check-parts = { $parts ->
    [one] { $parts } pieza
   *[other] { $parts } piezas
}
check-part-moved = una pieza de { $mass } kg se movió { $distance } m; el tensor respecto al origen cambió como mucho { $measured } kg·m², el teorema de Steiner dice { $predicted }
