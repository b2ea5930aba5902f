# The screenshot's and the recording's outcomes and failures (crates/app/src/gui/capture.rs, archive.rs).

capture-no-pixels = the window's pixels never arrived
capture-cannot-create = cannot create { $path }: { $error }
capture-cannot-write = cannot write { $path }: { $error }
capture-recording-stopped = recording stopped: { $error }
capture-recording-not-saved = recording not saved: { $path }: { $error }
capture-recorded = recorded { $written } of { $requested } pictures ({ $rate } per second) to { $path }
capture-archive-too-big = { $name }: the archive would pass 4 GiB or 65 535 files
