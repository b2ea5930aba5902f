# What the lab says in the message line, and the words for its choices (src/lab/).

lab-split = { $parts } parts
lab-saved = saved { $path } ({ $what })
lab-parts = { $parts } parts
lab-parts-meshes = { $parts } parts; meshes { $meshes }
lab-wrote-samples = wrote { $samples } samples to { $path }
lab-wrote-keyframes = wrote { $frames } keyframes ({ $seconds } s at { $fps } fps) to { $path }
lab-started-again = started again from the spin about axis { $axis } with the { $source } inertia and the { $model } model
lab-loaded = loaded { $body } ({ $triangles } triangles){ $warnings ->
    [0] {""}
    [one] ; 1 mesh warning, under Mesh diagnostics
   *[other] ; { $warnings } mesh warnings, under Mesh diagnostics
}
lab-added = added { $parts }
lab-loaded-robot = loaded robot { $robot } ({ $links } links, { $flagged } with findings on their inertial): choose a link under Robot
lab-load-failed = { $error } (the current body is kept)
lab-whole-robot = the whole robot at its zero pose, with each link's ellipsoids
lab-link-stated = link { $link }: its collision geometry, spinning beside a copy with the inertia its file states
lab-link-unstated = link { $link }: its collision geometry (no inertia stated)
lab-link-not-simulated = link { $link }: its collision geometry; its stated inertia cannot be simulated: { $error }
variant-same = same settings
variant-source = { $source } inertia
variant-model = { $model } model
source-exact = exact
source-bounding-box = bounding box
source-point-masses = point masses
source-stated = stated
model-full = full
model-textbook = textbook
