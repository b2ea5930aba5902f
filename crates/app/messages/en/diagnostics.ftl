# The Mesh diagnostics section: what the mesh is made of and its warnings (crates/app/src/gui/panels/diagnostics.rs).

diagnostics-header = Mesh diagnostics
diagnostics-header-warnings = { $count ->
    [one] Mesh diagnostics (1 warning)
   *[other] Mesh diagnostics ({ $count } warnings)
}
diagnostics-counts = { $vertices } vertices, { $faces } faces ({ $triangles } triangles), { $edges } edges
diagnostics-volume-area = volume { $volume } m³ (unscaled), area { $area } m²
diagnostics-no-defects = No defects found: the numbers are exact for this mesh.
diagnostics-click-hint = Click a warning to highlight its faces.
diagnostics-shells = { $count } shell(s): { $parts }
diagnostics-shells-closed = { $count } closed
diagnostics-shells-cavities = { $count } of them cavities
diagnostics-shells-capped = { $count } open (capped)
diagnostics-shells-uneven = { $count } joined unevenly to others
