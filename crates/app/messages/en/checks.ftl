# What a lesson's live checks have measured (src/lab/lessons/checks.rs).

check-reversals = { $measured } of { $wanted } reversals of ω₂ measured
check-no-reversal = { $passed } of { $seconds } s without a reversal
check-half-period = measured { $measured } s between reversals, predicted { $predicted } s ({ $apart } % apart)
check-flip-period = predicted flip period { $period } s (target { $target } s ± { $tolerance } %)
check-no-flip = it does not flip now
check-moments-apart = the two closest moments are { $apart } % apart
check-conserved = { $passed } of { $seconds } s; energy held to { $drift }
check-elapsed = { $passed } of { $seconds } s
check-parts = { $parts ->
    [one] { $parts } part
   *[other] { $parts } parts
}
check-part-moved = a part of { $mass } kg moved { $distance } m; the tensor about the origin changed by { $measured } kg·m² at most, the parallel-axis theorem says { $predicted }
