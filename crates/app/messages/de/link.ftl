# Was die Parameter eines Links und die Schaltfläche Teilen dem Benutzer sagen (crates/app/src/gui/link.rs).

link-spin-invalid = spin={ $value }: Die Hauptachse ist 1, 2 oder 3 (vom kleinsten zum größten Moment)
link-source-invalid = source={ $value }: exact, bbox oder points
link-model-invalid = model={ $value }: full oder textbook
link-size-invalid = size={ $value }: Geben Sie eine positive Zahl an
link-density-invalid = density={ $value }: Geben Sie eine positive Zahl in kg/m³ an
link-mass-invalid = mass={ $value }: Geben Sie eine positive Zahl in kg an
link-rate-invalid = rate={ $value }: Geben Sie eine positive Zahl in rad/s an
link-step-invalid = step={ $value }: der Schritt der Lektion, ab 1
link-bench-invalid = bench={ $value }: Geben Sie die Anzahl der zu messenden Bilder an
link-unknown-key = unbekannter Link-Parameter { $key } (bekannt: { $known })
link-step-needs-lesson = step= braucht lesson=
link-own-file = { $name } stammt aus einer eigenen Datei, die ein Link nicht transportieren kann: Ein Link öffnet nur die eingebauten Beispiele (senden Sie die Datei mit dem Link)
link-sample-unknown = sample={ $value }: kein solches Beispiel (es gibt { $samples })
link-compare-unknown = compare={ $value }: { $name } ist keines von bbox, points, textbook
link-compare-too-many = compare={ $value }: höchstens { $most } Kopien
link-lang-invalid = lang={ $value }: das Labor spricht en, de und es
link-problems = der Link: { $problems }
link-lesson-not-fetched = lesson={ $address }: nicht abgerufen ({ $why })
