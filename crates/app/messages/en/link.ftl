# What a link's parameters and the Share button tell the user (crates/app/src/gui/link.rs).

link-spin-invalid = spin={ $value }: the principal axis is 1, 2 or 3 (smallest to largest moment)
link-source-invalid = source={ $value }: exact, bbox or points
link-model-invalid = model={ $value }: full or textbook
link-size-invalid = size={ $value }: give a positive number
link-density-invalid = density={ $value }: give a positive number of kg/m³
link-mass-invalid = mass={ $value }: give a positive number of kg
link-rate-invalid = rate={ $value }: give a positive number of rad/s
link-step-invalid = step={ $value }: the lesson's step, from 1
link-bench-invalid = bench={ $value }: give the number of frames to measure
link-unknown-key = unknown link parameter { $key } (known: { $known })
link-step-needs-lesson = step= needs lesson=
link-own-file = { $name } came from a file of yours, which a link cannot carry: a link opens only the built-in samples (send the file with the link)
link-sample-unknown = sample={ $value }: no such sample (there are { $samples })
link-compare-unknown = compare={ $value }: { $name } is none of bbox, points, textbook
link-compare-too-many = compare={ $value }: at most { $most } copies
link-lang-invalid = lang={ $value }: the lab speaks en, de and es
link-problems = the link: { $problems }
link-lesson-not-fetched = lesson={ $address }: not fetched ({ $why })
