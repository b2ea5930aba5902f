//! Writes the sample bodies of `massprops::shapes::samples`, and the parts the body files use, to
//! `assets/*.obj` at the workspace root.

use std::path::Path;

fn main() -> std::io::Result<()> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets");
    std::fs::create_dir_all(&dir)?;
    let shapes = massprops::shapes::samples()
        .into_iter()
        .chain(massprops::shapes::part_samples());
    for (name, comment, mesh) in shapes {
        let path = dir.join(format!("{name}.obj"));
        std::fs::write(&path, massprops::shapes::to_obj(name, comment, &mesh))?;
        println!("wrote {}", path.display());
    }
    Ok(())
}
