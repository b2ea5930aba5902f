# La sección Diagnóstico de la malla: de qué está hecha la malla y sus avisos (crates/app/src/gui/panels/diagnostics.rs).

diagnostics-header = Diagnóstico de la malla
diagnostics-header-warnings = { $count ->
    [one] Diagnóstico de la malla (1 aviso)
   *[other] Diagnóstico de la malla ({ $count } avisos)
}
diagnostics-counts = { $vertices } vértices, { $faces } caras ({ $triangles } triángulos), { $edges } aristas
diagnostics-volume-area = volumen { $volume } m³ (sin escalar), área { $area } m²
diagnostics-no-defects = No se encontraron defectos: los números son exactos para esta malla.
diagnostics-click-hint = Haga clic en un aviso para resaltar sus caras.
diagnostics-shells = { $count ->
    [one] 1 carcasa
   *[other] { $count } carcasas
}: { $parts }
diagnostics-shells-closed = { $count ->
    [one] 1 cerrada
   *[other] { $count } cerradas
}
diagnostics-shells-cavities = { $count ->
    [one] 1 de ellas es una cavidad
   *[other] { $count } de ellas son cavidades
}
diagnostics-shells-capped = { $count ->
    [one] 1 abierta (tapada)
   *[other] { $count } abiertas (tapadas)
}
diagnostics-shells-uneven = { $count ->
    [one] 1 unida de forma irregular a otras
   *[other] { $count } unidas de forma irregular a otras
}
