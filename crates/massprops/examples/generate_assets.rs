//! Writes the sample bodies of `massprops::shapes::samples`, and the parts the body files use, to
//! `assets/*.obj` at the workspace root.

use std::path::Path;

fn main() -> std::io::Result<()> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets");
    std::fs::create_dir_all(&dir)?;
    for (name, comment, mesh) in massprops::shapes::samples() {
        let path = dir.join(format!("{name}.obj"));
        std::fs::write(&path, massprops::shapes::to_obj(name, comment, &mesh))?;
        println!("wrote {}", path.display());
    }
    // Parts for the body files (assets/*.toml), not a sample body by itself.
    let path = dir.join("hollow_box.obj");
    let parts = massprops::shapes::hollow_box_parts();
    let comment = "a 0.3 m box and its 0.26 m cavity, for hollow_box.toml; metres";
    std::fs::write(
        &path,
        massprops::shapes::to_obj("hollow_box", comment, &parts),
    )?;
    println!("wrote {}", path.display());
    Ok(())
}
