# The language menu and the Display menu in the top bar (src/gui/panels/display.rs).

display-language = Language
display-language-system = System ({ $language })
display-menu = Display
display-larger-text = Larger text
display-larger-text-hover = Everything a quarter larger: text, buttons and plots
display-reduced-motion = Reduced motion
display-reduced-motion-hover = Nothing moves until you press Run: a body you open waits paused, and panels open without sliding
display-read-aloud = Read aloud
display-read-aloud-hover = The page speaks what takes the keyboard's focus, with the browser's voice
