# Der Abschnitt Netzdiagnose: woraus das Netz besteht und seine Warnungen (crates/app/src/gui/panels/diagnostics.rs).

diagnostics-header = Netzdiagnose
diagnostics-header-warnings = { $count ->
    [one] Netzdiagnose (1 Warnung)
   *[other] Netzdiagnose ({ $count } Warnungen)
}
diagnostics-counts = { $vertices } Eckpunkte, { $faces } Flächen ({ $triangles } Dreiecke), { $edges } Kanten
diagnostics-volume-area = Volumen { $volume } m³ (unskaliert), Fläche { $area } m²
diagnostics-no-defects = Keine Defekte gefunden: Die Zahlen sind für dieses Netz exakt.
diagnostics-click-hint = Klicken Sie auf eine Warnung, um ihre Flächen hervorzuheben.
diagnostics-shells = { $count ->
    [one] 1 Schale
   *[other] { $count } Schalen
}: { $parts }
diagnostics-shells-closed = { $count } geschlossen
diagnostics-shells-cavities = { $count ->
    [one] davon 1 Hohlraum
   *[other] davon { $count } Hohlräume
}
diagnostics-shells-capped = { $count } offen (gedeckelt)
diagnostics-shells-uneven = { $count } ungleichmäßig mit anderen verbunden
