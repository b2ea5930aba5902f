//! Body files: a hammer in millimetres against its closed form, the round trip through
//! `to_toml`, and every error naming the file, the line and the key.

use crate::common;

use std::path::{Path, PathBuf};

use common::{assert_mat, assert_rel, box_tensor};
use massprops::{BodyFile, Repairs, composite, shapes};
use nalgebra::{Matrix3, Point3, Vector3};

/// A folder with two box meshes: `head.obj` (two objects, `head` and `spare`) and `bar.stl`.
fn folder(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("massprops-body-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    // 100 × 30 × 30 mm head centred at the origin; a spare 10 mm cube far away.
    let mut head = shapes::cuboid(Vector3::new(100.0, 30.0, 30.0), Point3::origin());
    let obj_head = shapes::to_obj("head", "a hammer head in mm", &head);
    let spare = shapes::cuboid(Vector3::repeat(10.0), Point3::new(500.0, 0.0, 0.0));
    let obj_spare = shapes::to_obj("spare", "", &spare);
    head.append(&spare);
    // One file, two objects: the spare's indices follow the head's eight vertices.
    let spare_part: String = obj_spare
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| {
            if let Some(rest) = l.strip_prefix("f ") {
                let shifted: Vec<String> = rest
                    .split_whitespace()
                    .map(|i| (i.parse::<usize>().expect("index") + 8).to_string())
                    .collect();
                format!("f {}\n", shifted.join(" "))
            } else {
                format!("{l}\n")
            }
        })
        .collect();
    std::fs::write(dir.join("head.obj"), format!("{obj_head}{spare_part}")).expect("write");
    std::fs::write(
        dir.join("bar.obj"),
        shapes::to_obj(
            "bar",
            "a handle in mm",
            &shapes::cuboid(Vector3::new(30.0, 300.0, 30.0), Point3::origin()),
        ),
    )
    .expect("write");
    dir
}

fn steiner(m: f64, d: Vector3<f64>) -> Matrix3<f64> {
    (Matrix3::identity() * d.norm_squared() - d * d.transpose()) * m
}

const HAMMER: &str = r#"units = "mm"

[[part]]
name = "head"
mesh = "head.obj"
object = "head"
material = "steel"
translation = [0, 315, 0]

[[part]]
name = "handle"
mesh = "bar.obj"
density = 600
rotation = { axis = [0, 1, 0], degrees = 90 }
translation = [0, 150, 0]
"#;

#[test]
fn a_hammer_in_millimetres_matches_its_closed_form_and_reads_back() {
    let dir = folder("hammer");
    let path = dir.join("hammer.toml");
    std::fs::write(&path, HAMMER).expect("write");
    let body = BodyFile::read(&path).expect("valid");
    assert_eq!(body.units, massprops::LengthUnit::Mm);
    let c = composite(&body.load().expect("meshes"), &Repairs::default()).expect("two parts");
    let (mh, ms) = (7850.0 * 0.1 * 0.03 * 0.03, 600.0 * 0.03 * 0.3 * 0.03);
    let m = mh + ms;
    let y = (mh * 0.315 + ms * 0.15) / m;
    assert_rel(c.properties.mass, m, 1e-13, "mass in kg");
    assert_rel(c.properties.center_of_mass.y, y, 1e-13, "centre in metres");
    // The square handle turned about its own long axis is the same box.
    let want = box_tensor(mh, 0.1, 0.03, 0.03)
        + steiner(mh, Vector3::new(0.0, 0.315 - y, 0.0))
        + box_tensor(ms, 0.03, 0.3, 0.03)
        + steiner(ms, Vector3::new(0.0, 0.15 - y, 0.0));
    assert_mat(&c.properties.inertia_com, &want, 1e-12, "hammer");
    // The centre of mass lies in the steel head's half.
    assert!(c.properties.center_of_mass.y > 0.15);

    assert!(body.to_toml().starts_with("version = 1\n"));
    let again = BodyFile::parse(&body.to_toml(), &path).expect("round trip");
    assert_eq!(again.parts.len(), 2);
    for (a, b) in again.parts.iter().zip(&body.parts) {
        assert_eq!(
            (
                &a.name,
                &a.mesh,
                &a.object,
                &a.material,
                a.rotation,
                a.translation
            ),
            (
                &b.name,
                &b.mesh,
                &b.object,
                &b.material,
                b.rotation,
                b.translation
            )
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// The error for `text` as a body file in `dir`, reading the meshes too.
fn error(dir: &Path, text: &str) -> String {
    let path = dir.join("bad.toml");
    std::fs::write(&path, text).expect("write");
    match BodyFile::read(&path).and_then(|b| b.load().map(|_| ())) {
        Ok(()) => panic!("accepted: {text}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn every_mistake_names_the_file_the_line_and_the_key() {
    let dir = folder("errors");
    let part = "[[part]]\nname = \"head\"\nmesh = \"head.obj\"\n";
    let cases: [(String, &[&str]); 10] = [
        (
            format!("{part}densty = 3\n"),
            &["bad.toml, line 4", "unknown field `densty`"],
        ),
        (
            format!("{part}material = \"unobtainium\"\n"),
            &["line 4", "material", "unknown material", "steel", "wood"],
        ),
        (
            "[[part]]\nname = \"head\"\ndensity = 1\n".to_owned(),
            &["line 1", "part \"head\": mesh: missing"],
        ),
        (
            "[[part]]\nname = \"x\"\nmesh = \"nowhere.obj\"\ndensity = 1\n".to_owned(),
            &["line 1", "mesh:", "nowhere.obj does not exist"],
        ),
        (
            format!("{part}object = \"handle\"\ndensity = 1\n"),
            &["line 1", "has no object \"handle\"", "it has: head, spare"],
        ),
        (
            format!("units = \"furlong\"\n{part}density = 1\n"),
            &["line 1", "units", "furlong", "mm, in, ft"],
        ),
        (
            format!("{part}density = 1\nmass = 2\n"),
            &["part \"head\"", "one of density, material and mass"],
        ),
        (
            format!("{part}density = -5\n"),
            &["line 4", "density", "-5 is not a positive number"],
        ),
        (format!("{part}\n"), &["part \"head\"", "density: missing"]),
        (
            format!("version = 2\n{part}density = 1\n"),
            &["line 1", "version", "version 1, not 2"],
        ),
    ];
    for (text, wanted) in &cases {
        let e = error(&dir, text);
        for w in *wanted {
            assert!(e.contains(w), "{e:?} lacks {w:?}");
        }
    }
    // A void larger than the solid: the composite says so.
    let voids = format!(
        "{part}object = \"spare\"\ndensity = 1\n[[part]]\nname = \"hole\"\nmesh = \"bar.obj\"\ndensity = 1\nvoid = true\n"
    );
    let path = dir.join("void.toml");
    std::fs::write(&path, voids).expect("write");
    let parts = BodyFile::read(&path)
        .expect("valid")
        .load()
        .expect("meshes");
    let e = composite(&parts, &Repairs::default()).expect_err("negative mass");
    assert!(e.to_string().contains("remove more than there is"), "{e}");
    std::fs::remove_dir_all(&dir).ok();
}

/// A folder holding `brick.obj`: a 1 × 2 × 3 m box centred at `centre` (mesh coordinates).
fn brick_folder(tag: &str, centre: Point3<f64>) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("massprops-brick-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let brick = shapes::cuboid(Vector3::new(1.0, 2.0, 3.0), centre);
    std::fs::write(dir.join("brick.obj"), shapes::to_obj("brick", "", &brick)).expect("write");
    dir
}

/// The body file's composite for one part `brick.obj` with the given `rotation` (a TOML inline
/// table) and translation [1, 2, 3].
fn turned_brick(dir: &Path, rotation: &str) -> massprops::Composite {
    let path = dir.join("turned.toml");
    let text = format!(
        "[[part]]\nname = \"brick\"\nmesh = \"brick.obj\"\ndensity = 2\n\
         rotation = {rotation}\ntranslation = [1, 2, 3]\n"
    );
    std::fs::write(&path, text).expect("write");
    let body = BodyFile::read(&path).expect("valid");
    composite(&body.load().expect("mesh"), &Repairs::default()).expect("one part")
}

/// A 1 × 2 × 3 box turned 30° about [1, 1, 0]: its tensor about the centre of mass is R·I·Rᵀ
/// with R from nalgebra (not the crate's placement), and its centre R·c + t. The box is not a
/// cube and the axis is no edge, so reading degrees as radians, dropping the rotation or
/// turning the other way all change the tensor.
#[test]
fn a_rotated_box_has_the_rotated_tensor_about_its_centre() {
    let centre = Point3::new(0.2, -0.1, 0.4);
    let dir = brick_folder("rotated", centre);
    let m = 2.0 * 6.0;
    let local = box_tensor(m, 1.0, 2.0, 3.0);
    let turn = |axis: Vector3<f64>, degrees: f64| {
        nalgebra::Rotation3::from_axis_angle(
            &nalgebra::Unit::new_normalize(axis),
            degrees.to_radians(),
        )
        .into_inner()
    };
    let t = Vector3::new(1.0, 2.0, 3.0);
    let cases = [
        (
            "{ axis = [1, 1, 0], degrees = 30 }",
            Vector3::new(1.0, 1.0, 0.0),
        ),
        // The norm of [1e200, 0, 0] overflows; it must still mean the x axis.
        ("{ axis = [1e200, 0, 0], degrees = 30 }", Vector3::x()),
        ("{ axis = [1, 0, 0], degrees = 30 }", Vector3::x()),
    ];
    for (rotation, axis) in cases {
        let c = turned_brick(&dir, rotation);
        let r = turn(axis, 30.0);
        let want = r * local * r.transpose();
        assert_rel(c.properties.mass, m, 1e-14, rotation);
        assert_mat(&c.properties.inertia_com, &want, 1e-13, rotation);
        common::assert_point(
            &c.properties.center_of_mass,
            &Point3::from(r * centre.coords + t),
            1.0,
            1e-14,
            rotation,
        );
        // Not the unturned box: the case can tell a lost rotation.
        assert!(common::mat_rel(&c.properties.inertia_com, &local) > 0.05);
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `to_toml` and `parse` keep every setting of every part: units, each way of giving the
/// material (density, preset, mass), the object, a void, a thin wall, the rotation and the
/// translation, checked key by key.
#[test]
fn to_toml_keeps_every_setting_of_every_part() {
    use massprops::{MaterialEntry, PartEntry};
    let entry = |name: &str, material: MaterialEntry| PartEntry {
        name: name.to_owned(),
        mesh: PathBuf::from("meshes/head.obj"),
        object: None,
        material,
        rotation: None,
        translation: [0.0; 3],
        void: false,
        thin_wall: None,
        line: 0,
    };
    let body = BodyFile {
        path: PathBuf::from("/nowhere/body.toml"),
        units: massprops::LengthUnit::Cm,
        parts: vec![
            PartEntry {
                object: Some("head".to_owned()),
                rotation: Some(([1e200, 0.0, -0.5], 12.25)),
                translation: [0.1, -2.0, 3e-7],
                ..entry("dense", MaterialEntry::Density(7850.5))
            },
            PartEntry {
                void: true,
                ..entry("cavity", MaterialEntry::Preset("steel".to_owned()))
            },
            entry("weighed", MaterialEntry::Mass(0.125)),
            PartEntry {
                thin_wall: Some(1.5),
                mesh: PathBuf::from("shade \"1\".stl"),
                ..entry("wall", MaterialEntry::Preset("aluminium".to_owned()))
            },
        ],
    };
    let text = body.to_toml();
    let again = BodyFile::parse(&text, &body.path).expect("reads back");
    assert_eq!(again.units, massprops::LengthUnit::Cm, "units\n{text}");
    assert_eq!(again.parts.len(), 4, "{text}");
    for (a, b) in again.parts.iter().zip(&body.parts) {
        let what = format!("part {:?} in\n{text}", b.name);
        assert_eq!(a.name, b.name, "name: {what}");
        assert_eq!(a.mesh, b.mesh, "mesh: {what}");
        assert_eq!(a.object, b.object, "object: {what}");
        assert_eq!(a.material, b.material, "material: {what}");
        assert_eq!(a.void, b.void, "void: {what}");
        assert_eq!(a.thin_wall, b.thin_wall, "thin_wall: {what}");
        assert_eq!(a.rotation, b.rotation, "rotation: {what}");
        assert_eq!(a.translation, b.translation, "translation: {what}");
    }
    // The values themselves, so that a writer and reader that both lose a key still fail.
    assert_eq!(again.parts[0].object.as_deref(), Some("head"));
    assert_eq!(again.parts[0].material, MaterialEntry::Density(7850.5));
    assert!(again.parts[1].void);
    assert_eq!(
        again.parts[1].material,
        MaterialEntry::Preset("steel".to_owned())
    );
    assert_eq!(again.parts[2].material, MaterialEntry::Mass(0.125));
    assert_eq!(again.parts[3].thin_wall, Some(1.5));
    assert_eq!(again.unit(), 0.01);
    // And written again, the same text.
    assert_eq!(again.to_toml(), text);
}
