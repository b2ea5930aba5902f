# The window's frame: its title, the top bar, the message line and the drop overlay
# (crates/app/src/gui/mod.rs). Ids are the same in every language; see src/i18n/mod.rs.

window-title = Inertia Lab — { $body }
top-help = Help
top-help-hover = What you see, the controls and the keys (F1)
top-lessons = Lessons
top-lessons-hover = Guided activities: predict, try, measure, explain (L)
top-share = Share
top-share-hover = Copy a link that opens this scene: the sample, its size, mass and spin, the inertia and model, the comparison and the lesson's step
top-share-copied = copied { $address } ({ $hint })
message-dismiss = dismiss
message-none = Inertia Lab — exact inertia vs the bounding-box guess.
drop-adds-part = Drop a mesh to add it as a part (a body file to open it)
drop-loads = Drop to load
