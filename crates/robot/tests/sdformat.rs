//! SDFormat read as its specification places things, checked against poses and tensors derived
//! by hand: frames `relative_to` others, a nested model and a `model://` include, libsdformat's
//! default inertial, `<inertial auto="true">` with densities and a stated mass, and the errors a
//! user sees. (`tests/audit_cli.rs` reads the same arm with libsdformat itself.)

use std::f64::consts::FRAC_PI_2;
use std::path::{Path, PathBuf};

use nalgebra::{Matrix3, Rotation3, Vector3};
use robot::{
    AuditOptions, DescriptionFormat, MassBasis, ReadOptions, Robot, audit, read, read_str,
};

fn arm_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/data/robots/sdf_arm")
}

fn arm() -> Robot {
    let dir = arm_dir();
    let options = ReadOptions {
        resource_paths: vec![dir.join("models")],
        ..ReadOptions::default()
    };
    read(&dir.join("arm.sdf"), &options).expect("reads")
}

fn link<'a>(robot: &'a Robot, name: &str) -> (usize, &'a robot::Link) {
    robot
        .links
        .iter()
        .enumerate()
        .find(|(_, l)| l.name == name)
        .unwrap_or_else(|| panic!("no link {name}"))
}

fn close(a: &Matrix3<f64>, b: &Matrix3<f64>, tol: f64) {
    assert!((a - b).amax() <= tol * b.amax(), "\n{a}\nvs\n{b}");
}

#[test]
fn frames_nested_models_and_includes_place_every_link_as_the_spec_says() {
    let robot = arm();
    assert_eq!(robot.format, DescriptionFormat::Sdf);
    assert_eq!(robot.name, "arm");
    let names: Vec<&str> = robot.links.iter().map(|l| l.name.as_str()).collect();
    assert_eq!(
        names,
        ["base", "upper", "forearm_model::forearm", "hand::finger"],
        "parents first"
    );
    // base at z 0.05; the shoulder frame 0.05 above it, turned a quarter about z; upper 0.25
    // above that; the nested model 0.25 above upper and its link 0.15 above the model; the
    // included hand 0.15 above the forearm. The model's own pose (x = 5) places it in a world
    // and is not the robot's.
    let quarter = Rotation3::from_axis_angle(&Vector3::z_axis(), FRAC_PI_2);
    for (name, z, turned) in [
        ("base", 0.05, false),
        ("upper", 0.35, true),
        ("forearm_model::forearm", 0.75, true),
        ("hand::finger", 0.90, true),
    ] {
        let (_, l) = link(&robot, name);
        assert!(
            (l.pose.translation.vector - Vector3::new(0.0, 0.0, z)).amax() < 1e-15,
            "{name}: {}",
            l.pose.translation.vector
        );
        let want = if turned {
            quarter
        } else {
            Rotation3::identity()
        };
        assert!(
            (l.pose.rotation.to_rotation_matrix().matrix() - want.matrix()).amax() < 1e-15,
            "{name}"
        );
    }
    let (upper, u) = link(&robot, "upper");
    let (forearm, f) = link(&robot, "forearm_model::forearm");
    let (finger, h) = link(&robot, "hand::finger");
    assert_eq!((u.parent, u.moving), (Some(0), true));
    assert_eq!((f.parent, f.moving), (Some(upper), true));
    assert_eq!((h.parent, h.moving), (Some(forearm), false));
    assert!(finger > forearm);

    // The forearm's box tensor written in a frame turned 0.3 rad about x: R·D·Rᵀ in link axes.
    let r = Rotation3::from_axis_angle(&Vector3::x_axis(), 0.3);
    let d = Matrix3::from_diagonal(&Vector3::new(0.0039, 0.0039, 0.0003));
    let stated = f.stated.as_ref().expect("stated");
    close(
        &stated.inertia,
        &(r.matrix() * d * r.matrix().transpose()),
        1e-15,
    );
    // upper writes a mass and no tensor: libsdformat's default moments of 1 kg·m².
    let s = u.stated.as_ref().expect("stated");
    assert_eq!((s.mass, s.center_of_mass.z), (1.0, 0.01));
    assert_eq!(s.inertia, Matrix3::identity());
    assert_eq!(s.written, ["1", "0", "0", "1", "0", "1"]);
    // The included finger's mesh is found beside the included file, and it is weighed.
    assert!(matches!(
        &h.collision[0].shape,
        robot::Shape::Mesh { file, .. } if file.ends_with("models/gripper/meshes/finger.obj")
    ));
    assert_eq!(
        robot.sources.len(),
        2,
        "the arm and the gripper it includes"
    );

    let report = audit(&robot, &AuditOptions::default());
    let codes =
        |i: usize| -> Vec<&str> { report.links[i].findings.iter().map(|f| f.code()).collect() };
    assert!(
        codes(upper).contains(&"impossible_moment"),
        "{:?}",
        codes(upper)
    );
    assert!(
        codes(finger).contains(&"impossible_moment"),
        "{:?}",
        codes(finger)
    );
    assert!(!codes(0).contains(&"impossible_moment"), "{:?}", codes(0));
    // The base states its box's own tensor: the geometry agrees to round-off.
    let base = report.links[0].computed.as_ref().expect("weighed");
    close(
        &base.properties.inertia_com,
        &robot.links[0].stated.as_ref().expect("stated").inertia,
        1e-12,
    );
}

/// An SDFormat 1.11 link whose inertial Gazebo computes (`auto="true"`) from two boxes.
fn auto_link(mass: &str) -> String {
    format!(
        r#"<sdf version="1.11"><model name="m"><link name="l">
  <inertial auto="true">{mass}</inertial>
  <collision name="a"><density>500</density>
    <geometry><box><size>0.1 0.2 0.3</size></box></geometry></collision>
  <collision name="b"><pose>0 0 0.25 0 0 0</pose>
    <geometry><box><size>0.1 0.2 0.2</size></box></geometry></collision>
  <visual name="v"><geometry><sphere><radius>9</radius></sphere></geometry></visual>
</link></model></sdf>"#
    )
}

#[test]
fn an_auto_inertial_is_computed_as_gazebo_computes_it() {
    // Box a: 0.006 m³ at its own 500 kg/m³, at the origin; box b: 0.004 m³, 0.25 m up, at the
    // inertial's <density> when written, else 1000 kg/m³. The visual sphere does not count.
    let box_tensor = |m: f64, x: f64, y: f64, z: f64| {
        Matrix3::from_diagonal(&Vector3::new(y * y + z * z, x * x + z * z, x * x + y * y))
            * (m / 12.0)
    };
    let sideways = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 0.0));
    for (written, mb, total) in [
        ("", 4.0, None),
        ("<density>250</density>", 1.0, None),
        ("<mass>14</mass>", 4.0, Some(14.0)),
    ] {
        let ma = 3.0;
        let zc = mb * 0.25 / (ma + mb);
        let tensor = box_tensor(ma, 0.1, 0.2, 0.3)
            + sideways * ma * zc * zc
            + box_tensor(mb, 0.1, 0.2, 0.2)
            + sideways * mb * (0.25 - zc).powi(2);
        let robot = read_str(
            &auto_link(written),
            Path::new("auto.sdf"),
            &ReadOptions::default(),
        )
        .expect("reads");
        let l = &robot.links[0];
        assert!(l.stated.is_none());
        assert_eq!(l.auto_inertial.as_ref().expect("auto").mass, total);
        let report = audit(&robot, &AuditOptions::default());
        let c = report.links[0].computed.as_ref().expect("weighed");
        assert_eq!(c.basis, MassBasis::AutoInertial);
        let total = total.unwrap_or(ma + mb);
        assert!(
            (c.properties.mass - total).abs() < 1e-12 * total,
            "{written}: {}",
            c.properties.mass
        );
        assert!(
            (c.properties.center_of_mass.z - zc).abs() < 1e-12,
            "{written}"
        );
        // A stated mass scales every density alike: the tensor scales, the centre stays.
        close(
            &c.properties.inertia_com,
            &(tensor * (total / (ma + mb))),
            1e-12,
        );
        let codes: Vec<&str> = report.links[0].findings.iter().map(|f| f.code()).collect();
        assert!(!codes.contains(&"missing_inertial"), "{codes:?}");
    }
}

#[test]
fn sdformat_errors_name_the_file_line_and_frame() {
    let cases = [
        (
            r#"<sdf version="1.9"><model name="m"><link name="a">
<pose relative_to="nowhere">0 0 0 0 0 0</pose></link></model></sdf>"#,
            "no frame is named \"nowhere\"",
        ),
        (
            r#"<sdf version="1.9"><model name="m">
<link name="a"><pose relative_to="b"/></link>
<link name="b"><pose relative_to="a"/></link></model></sdf>"#,
            "loop of frames",
        ),
        (
            r#"<sdf version="1.9"><model name="m"><link name="a">
<pose>0 0 0 0 0</pose></link></model></sdf>"#,
            "expected x y z roll pitch yaw",
        ),
        (
            r#"<sdf version="1.9"><model name="m"><link name="a"><inertial>
<mass>heavy</mass></inertial></link></model></sdf>"#,
            "heavy",
        ),
        (
            r#"<sdf version="1.9"><model name="m"><link name="a"/>
<include><uri>model://nothing_here</uri></include></model></sdf>"#,
            "model://nothing_here",
        ),
        (
            r#"<sdf version="1.9"><model name="m"><link name="a"/>
<joint name="j" type="fixed"><parent>a</parent><child>b</child></joint></model></sdf>"#,
            "no link or frame is named \"b\"",
        ),
        (
            r#"<sdf version="1.6"><world name="w"><model name="a"><link name="l"/></model>
<model name="a"><link name="l"/></model></world></sdf>"#,
            "a second model (or frame) named \"a\"",
        ),
    ];
    for (text, words) in cases {
        let e = read_str(text, Path::new("bad.sdf"), &ReadOptions::default())
            .expect_err("refused")
            .to_string();
        assert!(e.starts_with("bad.sdf:"), "{e}");
        assert!(e.contains(words), "{e}");
    }
}

#[test]
fn a_world_places_each_model_and_scopes_its_links() {
    let text = r#"<sdf version="1.7"><world name="w">
<model name="cart"><pose>1 0 0 0 0 0</pose>
  <link name="body"><pose degrees="true">0 2 0 0 0 90</pose>
    <collision name="c"><geometry><sphere><radius>0.1</radius></sphere></geometry></collision>
  </link></model>
<model name="pole"><pose rotation_format="quat_xyzw">0 0 3 0 0 1 0</pose><link name="body"/></model>
</world></sdf>"#;
    let robot = read_str(text, Path::new("w.sdf"), &ReadOptions::default()).expect("reads");
    assert_eq!(robot.name, "w");
    let (_, cart) = link(&robot, "cart::body");
    assert!((cart.pose.translation.vector - Vector3::new(1.0, 2.0, 0.0)).amax() < 1e-15);
    assert!((cart.pose.rotation.angle() - FRAC_PI_2).abs() < 1e-15);
    let (_, pole) = link(&robot, "pole::body");
    assert!((pole.pose.translation.vector - Vector3::new(0.0, 0.0, 3.0)).amax() < 1e-15);
    // The quaternion (0, 0, 1, 0) is a half turn about z.
    assert!((pole.pose.rotation.angle() - std::f64::consts::PI).abs() < 1e-15);
}
