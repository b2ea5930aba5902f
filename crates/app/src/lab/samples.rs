//! The built-in bodies, embedded so the binary needs no files: the sample meshes of `assets/`
//! (written by massprops' `generate_assets` example) and the sample bodies made of parts.

/// The sample bodies, embedded so the binary needs no files: (label, file name, OBJ text).
pub const SAMPLES: [(&str, &str, &str); 7] = [
    (
        "T-handle",
        "t_handle.obj",
        include_str!("../../../../assets/t_handle.obj"),
    ),
    (
        "Tennis racket",
        "tennis_racket.obj",
        include_str!("../../../../assets/tennis_racket.obj"),
    ),
    (
        "Book",
        "book.obj",
        include_str!("../../../../assets/book.obj"),
    ),
    (
        "Hammer",
        "hammer.obj",
        include_str!("../../../../assets/hammer.obj"),
    ),
    (
        "L-bracket",
        "l_bracket.obj",
        include_str!("../../../../assets/l_bracket.obj"),
    ),
    (
        "Cube",
        "cube.obj",
        include_str!("../../../../assets/cube.obj"),
    ),
    (
        "Torus",
        "torus.obj",
        include_str!("../../../../assets/torus.obj"),
    ),
];

/// Sample bodies made of parts, embedded with their meshes: (label, body file name, body file
/// text). Their meshes are among [`SAMPLES`].
pub const SAMPLE_BODIES: [(&str, &str, &str); 3] = [
    (
        "Hammer: steel & wood",
        "hammer.toml",
        include_str!("../../../../assets/hammer.toml"),
    ),
    (
        "Racket: frame, strings, handle",
        "tennis_racket.toml",
        include_str!("../../../../assets/tennis_racket.toml"),
    ),
    (
        "Hollow box & solid box",
        "hollow_box.toml",
        include_str!("../../../../assets/hollow_box.toml"),
    ),
];

/// The mesh files the sample bodies use, besides [`SAMPLES`].
pub const SAMPLE_PART_MESHES: [(&str, &str); 1] = [(
    "hollow_box.obj",
    include_str!("../../../../assets/hollow_box.obj"),
)];

/// Every sample's label: the meshes, then the bodies of parts.
pub fn labels() -> Vec<&'static str> {
    SAMPLES
        .iter()
        .map(|(label, ..)| *label)
        .chain(SAMPLE_BODIES.iter().map(|(label, ..)| *label))
        .collect()
}
