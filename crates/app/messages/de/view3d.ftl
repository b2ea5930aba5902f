# view3d: to be written (see crates/app/src/i18n/mod.rs)
