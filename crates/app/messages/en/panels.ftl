# The side panel's frame and what its sections share (crates/app/src/gui/panels/mod.rs, side.rs).

panels-run = Run
panels-pause = Pause
panels-restart-on-switch = Switching starts again
panels-restart-on-switch-hover = A new inertia or rotation model starts the motion again from the same spin, so that the runs compare fairly. Off: the motion goes on from where it is.
side-reset-settings = Reset settings
