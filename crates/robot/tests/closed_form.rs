//! Synthetic robots whose inertials are derived by hand: boxes and cylinders under rotated
//! origins, a scaled mesh found through a package path, MJCF defaults and a `fromto` capsule;
//! the impossibility bound just above and just below m·r²; the hull test; placeholders.

use std::f64::consts::PI;
use std::path::{Path, PathBuf};

use nalgebra::{Matrix3, Vector3};
use robot::{AuditOptions, Finding, ReadOptions, Region, UnitSlip, audit, read, read_str};

/// `a` equals `b` to `tol` relative to the larger entry of `b`.
fn close(a: &Matrix3<f64>, b: &Matrix3<f64>, tol: f64) {
    let scale = b.amax();
    assert!((a - b).amax() <= tol * scale, "\n{a}\nvs\n{b}");
}

fn steiner(m: f64, d: Vector3<f64>) -> Matrix3<f64> {
    (Matrix3::identity() * d.norm_squared() - d * d.transpose()) * m
}

fn codes(f: &[Finding]) -> Vec<&'static str> {
    f.iter().map(Finding::code).collect()
}

/// A fresh folder under the target directory's tmp.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("present");
    dir
}

#[test]
fn a_box_and_a_cylinder_under_rotated_origins_sum_to_their_hand_derived_tensor() {
    let urdf = format!(
        r#"<robot name="t">
  <link name="arm">
    <inertial><origin xyz="0 0 0"/><mass value="3"/>
      <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>
    <collision><origin xyz="0.1 0 0" rpy="0 0 {half_pi}"/>
      <geometry><box size="0.2 0.4 0.6"/></geometry></collision>
    <collision><origin xyz="0 0.2 0" rpy="{half_pi} 0 0"/>
      <geometry><cylinder radius="0.05" length="0.3"/></geometry></collision>
  </link>
</robot>"#,
        half_pi = PI / 2.0
    );
    let robot = read_str(&urdf, Path::new("t.urdf"), &ReadOptions::default()).expect("present");
    let report = audit(&robot, &AuditOptions::default());
    let c = report.links[0].computed.as_ref().expect("present");

    // By hand: the stated 3 kg spread over both volumes.
    let (vb, vc) = (0.2 * 0.4 * 0.6, PI * 0.05 * 0.05 * 0.3);
    let rho = 3.0 / (vb + vc);
    let (mb, mc) = (rho * vb, rho * vc);
    // The box turned a quarter about z: its 0.4 side along x, 0.2 along y.
    let ib = Matrix3::from_diagonal(&Vector3::new(
        mb * (0.2f64.powi(2) + 0.6f64.powi(2)) / 12.0,
        mb * (0.4f64.powi(2) + 0.6f64.powi(2)) / 12.0,
        mb * (0.4f64.powi(2) + 0.2f64.powi(2)) / 12.0,
    ));
    // The cylinder turned a quarter about x: its axis along y.
    let (r, l) = (0.05f64, 0.3f64);
    let side = mc * (3.0 * r * r + l * l) / 12.0;
    let ic = Matrix3::from_diagonal(&Vector3::new(side, mc * r * r / 2.0, side));
    let (cb, cc) = (Vector3::new(0.1, 0.0, 0.0), Vector3::new(0.0, 0.2, 0.0));
    let com = (cb * mb + cc * mc) / 3.0;
    let expected = ib + steiner(mb, cb - com) + ic + steiner(mc, cc - com);

    assert!((c.properties.mass - 3.0).abs() < 1e-15);
    assert!((c.properties.center_of_mass.coords - com).amax() < 1e-15);
    close(&c.properties.inertia_com, &expected, 1e-12);
    assert!((c.density - rho).abs() < 1e-9 * rho);
}

/// A unit cube centred on the origin, as OBJ text.
fn cube_obj() -> String {
    let mut s = String::new();
    for z in [-0.5, 0.5] {
        for y in [-0.5, 0.5] {
            for x in [-0.5, 0.5] {
                s += &format!("v {x} {y} {z}\n");
            }
        }
    }
    // Vertices numbered 1 + x + 2y + 4z; faces wound outward.
    s + "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n"
}

#[test]
fn a_scaled_mesh_is_found_through_its_package_and_weighed_exactly() {
    let root = scratch("package_search");
    std::fs::create_dir_all(root.join("mypkg/urdf")).expect("present");
    std::fs::create_dir_all(root.join("mypkg/meshes")).expect("present");
    std::fs::write(root.join("mypkg/meshes/cube.obj"), cube_obj()).expect("present");
    let urdf = r#"<robot name="s"><link name="block">
  <collision><origin xyz="0 0 0.5" rpy="0 0 0"/><geometry>
    <mesh filename="package://mypkg/meshes/cube.obj" scale="0.1 0.2 0.3"/></geometry></collision>
</link></robot>"#;
    let path = root.join("mypkg/urdf/s.urdf");
    std::fs::write(&path, urdf).expect("present");
    let robot = read(&path, &ReadOptions::default()).expect("present");
    let report = audit(&robot, &AuditOptions::default());
    let l = &report.links[0];
    // No mass stated: the assumed 1000 kg/m³ over 0.1 × 0.2 × 0.3 m.
    let c = l.computed.as_ref().expect("present");
    let m = 1000.0 * 0.006;
    assert!((c.properties.mass - m).abs() < 1e-12);
    assert!((c.properties.center_of_mass.z - 0.5).abs() < 1e-15);
    let expected = Matrix3::from_diagonal(&Vector3::new(
        m * (0.04 + 0.09) / 12.0,
        m * (0.01 + 0.09) / 12.0,
        m * (0.01 + 0.04) / 12.0,
    ));
    close(&c.properties.inertia_com, &expected, 1e-12);
    assert_eq!(codes(&l.findings), ["missing_inertial"]);

    // Elsewhere, found through --package; not found, every path tried is named.
    let other = scratch("package_option");
    std::fs::create_dir_all(other.join("store/meshes")).expect("present");
    std::fs::create_dir_all(other.join("robot")).expect("present");
    std::fs::write(other.join("store/meshes/cube.obj"), cube_obj()).expect("present");
    let lone = other.join("robot/s.urdf");
    std::fs::write(&lone, urdf.replace("mypkg", "elsewhere")).expect("present");
    let missing = read(&lone, &ReadOptions::default()).expect("present");
    let report = audit(&missing, &AuditOptions::default());
    let tried = report.links[0]
        .findings
        .iter()
        .find_map(|f| match f {
            Finding::MeshMissing { tried, .. } => Some(tried),
            _ => None,
        })
        .expect("the missing mesh is a finding");
    assert!(tried.len() >= 3, "{tried:?}");
    assert!(tried.iter().all(|p| p.ends_with("meshes/cube.obj")));
    let options = ReadOptions {
        packages: vec![("elsewhere".into(), other.join("store"))],
        ..ReadOptions::default()
    };
    let found = read(&lone, &options).expect("present");
    let c = audit(&found, &AuditOptions::default()).links[0]
        .computed
        .clone()
        .expect("present");
    assert!((c.properties.mass - m).abs() < 1e-12);
}

#[test]
fn mjcf_defaults_childclass_and_a_fromto_capsule_give_the_closed_forms() {
    let xml = r#"<mujoco model="m">
  <compiler angle="radian"/>
  <default>
    <geom density="500"/>
    <default class="limb"><geom type="capsule" size="0.05"/></default>
  </default>
  <worldbody>
    <body name="upper" pos="0 0 1" childclass="limb">
      <joint type="hinge"/>
      <geom fromto="0 0 0 0.4 0 0"/>
      <body name="lower" pos="0.4 0 0" euler="0 0 1.5707963267948966">
        <joint/>
        <geom class="main" type="box" size="0.1 0.05 0.02" pos="0.1 0 0"/>
      </body>
    </body>
  </worldbody>
</mujoco>"#;
    let robot = read_str(xml, Path::new("m.xml"), &ReadOptions::default()).expect("present");
    assert_eq!(robot.links.len(), 2);
    assert!(robot.links.iter().all(|l| l.moving));
    let report = audit(&robot, &AuditOptions::default());

    // The capsule: radius 0.05 (class limb), half-length 0.2 along x, density 500 (main).
    let (r, h, rho) = (0.05f64, 0.2f64, 500.0);
    let (vc, vs) = (PI * r * r * 2.0 * h, 4.0 / 3.0 * PI * r.powi(3));
    let axial = rho * (vc * r * r / 2.0 + vs * 0.4 * r * r);
    let side = rho * (vc * (r * r / 4.0 + h * h / 3.0) + vs * (0.4 * r * r + h * h + 0.75 * h * r));
    let upper = report.links[0].computed.as_ref().expect("present");
    assert!((upper.properties.mass - rho * (vc + vs)).abs() < 1e-14);
    assert!((upper.properties.center_of_mass.x - 0.2).abs() < 1e-15);
    close(
        &upper.properties.inertia_com,
        &Matrix3::from_diagonal(&Vector3::new(axial, side, side)),
        1e-12,
    );

    // The box in class main: 0.2 × 0.1 × 0.04 at density 500, 0.1 along the body's x.
    let lower = report.links[1].computed.as_ref().expect("present");
    let m = 500.0 * 0.2 * 0.1 * 0.04;
    assert!((lower.properties.mass - m).abs() < 1e-15);
    let expected = Matrix3::from_diagonal(&Vector3::new(
        m * (0.01 + 0.0016) / 12.0,
        m * (0.04 + 0.0016) / 12.0,
        m * (0.04 + 0.01) / 12.0,
    ));
    close(&lower.properties.inertia_com, &expected, 1e-12);
    // Its zero pose: at (0.4, 0, 1), turned a quarter about z (MJCF euler, radians here).
    let pose = robot.links[1].pose;
    assert!((pose.translation.vector - Vector3::new(0.4, 0.0, 1.0)).amax() < 1e-15);
    assert!((pose.rotation * Vector3::x() - Vector3::y()).amax() < 1e-15);
}

/// A 0.2 × 0.4 × 0.6 box of 2 kg centred at the origin stating diag(ixx, 0.18, 0.09): about x
/// the corners lie √(0.2² + 0.3²) from the axis, so ixx ≤ 2 · 0.13 = 0.26.
fn box_stating(ixx: f64, com_x: f64) -> Vec<Finding> {
    let urdf = format!(
        r#"<robot name="b"><link name="box">
  <inertial><origin xyz="{com_x} 0 0"/><mass value="2"/>
    <inertia ixx="{ixx}" ixy="0" ixz="0" iyy="0.18" iyz="0" izz="0.09"/></inertial>
  <collision><geometry><box size="0.2 0.4 0.6"/></geometry></collision>
</link></robot>"#
    );
    let robot = read_str(&urdf, Path::new("b.urdf"), &ReadOptions::default()).expect("present");
    audit(&robot, &AuditOptions::default()).links[0]
        .findings
        .clone()
}

#[test]
fn the_impossibility_bound_is_m_r_squared_exactly() {
    let bound = 2.0 * (0.2f64.powi(2) + 0.3f64.powi(2));
    assert!(!codes(&box_stating(bound * (1.0 - 1e-6), 0.0)).contains(&"impossible_moment"));
    let above = box_stating(bound * (1.0 + 1e-6), 0.0);
    match above.iter().find(|f| f.code() == "impossible_moment") {
        Some(Finding::ImpossibleMoment { region, mass, axes }) => {
            assert_eq!(*region, Region::Only(robot::GeometryKind::Collision));
            assert_eq!(*mass, 2.0);
            assert_eq!(axes.len(), 1);
            assert_eq!(axes[0].rank, 2, "the largest moment, about x");
            assert!((axes[0].bound - bound).abs() < 1e-15);
            assert!((axes[0].radius - 0.13f64.sqrt()).abs() < 1e-15);
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_centre_of_mass_outside_the_hull_is_found_with_its_distance() {
    // 0.4 m beyond the box's face at x = 0.1 (the axis direction of the polytope).
    let findings = box_stating(0.2, 0.5);
    let outside = findings.iter().find_map(|f| match f {
        Finding::ComOutsideGeometry { distance, .. } => Some(*distance),
        _ => None,
    });
    assert!((outside.expect("outside") - 0.4).abs() < 1e-12);
    assert!(!codes(&box_stating(0.2, 0.09)).contains(&"com_outside_geometry"));
}

#[test]
fn placeholders_are_equal_moments_round_numbers_or_one_tensor_on_different_links() {
    let urdf = r#"<robot name="p">
  <link name="a"><inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    <collision><geometry><box size="0.5 0.5 2"/></geometry></collision></link>
  <link name="b"><inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    <collision><geometry><box size="1 0.5 0.5"/></geometry></collision></link>
  <link name="ball"><inertial><mass value="1"/><inertia ixx="0.016" ixy="0" ixz="0" iyy="0.016" iyz="0" izz="0.016"/></inertial>
    <collision><geometry><sphere radius="0.2"/></geometry></collision></link>
  <joint name="j" type="revolute"><parent link="a"/><child link="b"/></joint>
</robot>"#;
    let robot = read_str(urdf, Path::new("p.urdf"), &ReadOptions::default()).expect("present");
    let report = audit(&robot, &AuditOptions::default());
    let reasons = |name: &str| {
        let i = report
            .links
            .iter()
            .position(|l| robot.links[l.link].name == name)
            .expect("present");
        match report.links[i]
            .findings
            .iter()
            .find(|f| f.code() == "placeholder")
        {
            Some(Finding::Placeholder { reasons }) => reasons.len(),
            _ => 0,
        }
    };
    // Equal moments on a long box, powers of ten, and the same tensor as the other box.
    assert_eq!(reasons("a"), 3);
    assert_eq!(reasons("b"), 3);
    // A ball may have equal moments: 2/5 · 1 · 0.2² = 0.016.
    assert_eq!(reasons("ball"), 0);
}

#[test]
fn unreadable_descriptions_name_the_place() {
    let bad = read_str(
        "<robot>\n  <link name=\"a\">\n</robot>",
        Path::new("x.urdf"),
        &ReadOptions::default(),
    );
    let text = bad.expect_err("refused").to_string();
    assert!(text.starts_with("x.urdf:3:"), "{text}");

    let xacro =
        "<robot xmlns:xacro=\"http://ros.org/wiki/xacro\">\n<xacro:macro name=\"m\"/>\n</robot>";
    let text = read_str(xacro, Path::new("r.urdf.xacro"), &ReadOptions::default())
        .expect_err("refused")
        .to_string();
    assert!(
        text.contains("run xacro first") && text.contains("r.urdf.xacro:2:"),
        "{text}"
    );

    let mjcf = "<mujoco>\n<worldbody>\n<body><geom class=\"nope\" size=\"1\"/></body>\n</worldbody>\n</mujoco>";
    let text = read_str(mjcf, Path::new("m.xml"), &ReadOptions::default())
        .expect_err("refused")
        .to_string();
    assert!(
        text.starts_with("m.xml:3:") && text.contains("nope"),
        "{text}"
    );

    let number = "<robot name=\"r\"><link name=\"a\"><inertial><mass value=\"0.07,\"/>\
        <inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial></link></robot>";
    let text = read_str(number, Path::new("n.urdf"), &ReadOptions::default())
        .expect_err("refused")
        .to_string();
    assert!(
        text.contains("<mass value=\"0.07,\">") && text.contains("not a number"),
        "{text}"
    );
}

#[test]
fn xacro_markup_in_comments_is_not_xacro_but_a_substitution_is() {
    // As xArm's and TALOS's URDFs: xacro left in comments.
    let commented = r#"<robot name="c"><!-- <xacro:arm prefix="${p}"/> -->
  <link name="a"><visual><geometry><box size="1 1 1"/></geometry></visual></link></robot>"#;
    assert!(read_str(commented, Path::new("c.urdf"), &ReadOptions::default()).is_ok());
    // As Husky's: a roslaunch substitution in an attribute, on line 2, refuses the file.
    let husky = "<robot name=\"h\">\n<link name=\"a\"><visual><origin \
        rpy=\"$(optenv HUSKY_IMU_RPY 0 -1.5708 3.1416)\"/><geometry><box size=\"1 1 1\"/>\
        </geometry></visual></link></robot>";
    let text = read_str(husky, Path::new("h.urdf"), &ReadOptions::default())
        .expect_err("refused")
        .to_string();
    assert!(
        text.starts_with("h.urdf:2:") && text.contains("substitution rpy"),
        "{text}"
    );
    // In a mesh's file name it makes that mesh missing, named, and the rest is audited.
    let leftover = r#"<robot name="l">
  <link name="leg"><collision><geometry>
    <mesh filename="package://l/meshes/${direction}_leg.stl"/></geometry></collision></link>
  <link name="body"><collision><geometry><box size="1 1 1"/></geometry></collision></link>
</robot>"#;
    let robot = read_str(leftover, Path::new("l.urdf"), &ReadOptions::default()).expect("read");
    let report = audit(&robot, &AuditOptions::default());
    let missing = report.links[0]
        .findings
        .iter()
        .find_map(|f| match f {
            Finding::MeshMissing { written, .. } => Some(written.clone()),
            _ => None,
        })
        .expect("mesh_missing");
    assert_eq!(
        robot::unexpanded_substitution(&missing),
        Some("${direction}")
    );
    assert!(report.links[1].computed.is_ok());
    assert_eq!(
        robot::unexpanded_substitution("a$(find x)/b"),
        Some("$(find x)")
    );
    assert_eq!(robot::unexpanded_substitution("plain.stl"), None);
}

#[test]
fn a_bad_primitive_is_its_link_finding_not_the_files_error() {
    // As laikago_toes.urdf: one visual sphere of radius 0.
    let urdf = r#"<robot name="t"><link name="toe">
  <inertial><mass value="0.1"/><inertia ixx="1e-5" ixy="0" ixz="0" iyy="1e-5" iyz="0" izz="1e-5"/></inertial>
  <collision><geometry><sphere radius="0.0"/></geometry></collision></link></robot>"#;
    let robot = read_str(urdf, Path::new("t.urdf"), &ReadOptions::default()).expect("read");
    let report = audit(&robot, &AuditOptions::default());
    let what = report.links[0].findings.iter().find_map(|f| match f {
        Finding::GeometryUnsupported { what } => Some(what.clone()),
        _ => None,
    });
    let what = what.expect("a finding");
    assert!(
        what.contains("t.urdf:3:") && what.contains("must be positive"),
        "{what}"
    );
}

#[test]
fn a_point_mass_is_a_body_unless_it_moves() {
    let urdf = |joint: &str| {
        format!(
            r#"<robot name="p"><link name="base"/><link name="frame">
  <inertial><mass value="1e-9"/><inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial></link>
  <joint name="j" type="{joint}"><parent link="base"/><child link="frame"/></joint></robot>"#
        )
    };
    let codes_of = |joint: &str| {
        let robot =
            read_str(&urdf(joint), Path::new("p.urdf"), &ReadOptions::default()).expect("read");
        let report = audit(&robot, &AuditOptions::default());
        codes(&report.links[1].findings)
            .iter()
            .map(|c| c.to_string())
            .collect::<Vec<_>>()
    };
    assert!(!codes_of("fixed").contains(&"not_positive_definite".to_owned()));
    assert!(codes_of("revolute").contains(&"not_positive_definite".to_owned()));
}

#[test]
fn an_mjcf_body_without_inertial_weighs_every_geom_and_includes_mujocoinclude() {
    let dir = scratch("mujocoinclude");
    std::fs::write(
        dir.join("parts.xml"),
        r#"<mujocoinclude><body name="b"><freejoint/>
  <geom type="box" size="0.1 0.1 0.1"/>
  <geom type="sphere" size="0.05" pos="0 0 0.3" contype="0" conaffinity="0"/>
</body></mujocoinclude>"#,
    )
    .expect("write");
    let main = dir.join("model.xml");
    std::fs::write(
        &main,
        r#"<mujoco><worldbody><include file="parts.xml"/></worldbody></mujoco>"#,
    )
    .expect("write");
    let robot = read(&main, &ReadOptions::default()).expect("read");
    let report = audit(&robot, &AuditOptions::default());
    let c = report.links[0].computed.as_ref().expect("weighed");
    // MuJoCo's default density over both geoms, the visual sphere too.
    let m = 1000.0 * (0.008 + 4.0 / 3.0 * PI * 0.05f64.powi(3));
    assert!(
        (c.properties.mass - m).abs() < 1e-12 * m,
        "{} vs {m}",
        c.properties.mass
    );
}

/// A relative `file://meshes/…` is beside the description, whatever the working folder (as
/// gym-ignition-models' panda writes it); `file:///…` is absolute.
#[test]
fn a_relative_file_uri_is_beside_the_description() {
    let root = scratch("file_uri");
    std::fs::create_dir_all(root.join("meshes")).expect("present");
    std::fs::write(root.join("meshes/cube.obj"), cube_obj()).expect("present");
    let absolute = root.join("meshes/cube.obj");
    for written in [
        "file://meshes/cube.obj".to_owned(),
        format!("file://{}", absolute.display()),
    ] {
        let urdf = format!(
            r#"<robot name="f"><link name="block"><collision><geometry>
  <mesh filename="{written}" scale="0.1 0.2 0.3"/></geometry></collision></link></robot>"#
        );
        let path = root.join("f.urdf");
        std::fs::write(&path, urdf).expect("present");
        let robot = read(&path, &ReadOptions::default()).expect("present");
        let report = audit(&robot, &AuditOptions::default());
        let c = report.links[0].computed.as_ref();
        let mass = c
            .map(|c| c.properties.mass)
            .map_err(|_| codes(&report.links[0].findings));
        assert!(
            matches!(mass, Ok(m) if (m - 6.0).abs() < 1e-12),
            "{written}: {mass:?}"
        );
    }
}

/// Mesh and include paths written in included files are found where MuJoCo 4.0.0 finds them
/// (measured with MuJoCo's own loader on these layouts): a mesh beside the model (in meshdir)
/// first, else beside the included file that writes it (without meshdir), never beside the
/// model file's own meshes otherwise; a nested include beside the model, else beside the file
/// that includes it. Each tetrahedron has its own size, so its volume says which was read.
#[test]
fn included_files_find_their_meshes_and_includes_as_mujoco_does() {
    let dir = scratch("mjcf-include-paths");
    let tetra = |side: f64| {
        format!(
            "v 0 0 0\nv {side} 0 0\nv 0 {side} 0\nv 0 0 {side}\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
        )
    };
    for (path, side) in [
        ("sub/meshes/m.obj", 1.0),
        ("meshes/m.obj", 2.0),
        ("sub/m.obj", 3.0),
        ("sub/deeper/m.obj", 5.0),
    ] {
        let file = dir.join(path);
        std::fs::create_dir_all(file.parent().expect("a folder")).expect("folders");
        std::fs::write(file, tetra(side)).expect("write");
    }
    let body =
        r#"<worldbody><body name="b"><freejoint/><geom type="mesh" mesh="m"/></body></worldbody>"#;
    let write = |name: &str, text: &str| std::fs::write(dir.join(name), text).expect("write");
    let side_read = |main: &str| -> Result<f64, String> {
        let robot = read(&dir.join(main), &ReadOptions::default()).map_err(|e| e.to_string())?;
        let report = audit(&robot, &AuditOptions::default());
        let b = robot
            .links
            .iter()
            .position(|l| l.name == "b")
            .ok_or("no link b")?;
        let link = report
            .links
            .iter()
            .find(|l| l.link == b)
            .ok_or("no audit of b")?;
        let c = link
            .computed
            .as_ref()
            .map_err(|why| format!("not weighed ({why:?}): {:?}", codes(&link.findings)))?;
        Ok((c.properties.mass / 1000.0 * 6.0).cbrt())
    };
    write(
        "sub/inc.xml",
        r#"<mujocoinclude><asset><mesh name="m" file="meshes/m.obj"/></asset></mujocoinclude>"#,
    );
    write(
        "main.xml",
        &format!(r#"<mujoco><include file="sub/inc.xml"/>{body}</mujoco>"#),
    );
    write(
        "sub/inc2.xml",
        r#"<mujocoinclude><asset><mesh name="m" file="m.obj"/></asset></mujocoinclude>"#,
    );
    write(
        "main2.xml",
        &format!(
            r#"<mujoco><compiler meshdir="meshes"/><include file="sub/inc2.xml"/>{body}</mujoco>"#
        ),
    );
    write(
        "sub/inc3.xml",
        r#"<mujocoinclude><include file="deeper/inc4.xml"/></mujocoinclude>"#,
    );
    write(
        "sub/deeper/inc4.xml",
        r#"<mujocoinclude><asset><mesh name="m" file="m.obj"/></asset></mujocoinclude>"#,
    );
    write(
        "main3.xml",
        &format!(r#"<mujoco><include file="sub/inc3.xml"/>{body}</mujoco>"#),
    );
    write(
        "main6.xml",
        &format!(
            r#"<mujoco><compiler meshdir="meshes"/><asset><mesh name="m" file="m.obj"/></asset>{body}</mujoco>"#
        ),
    );
    let near = |found: Result<f64, String>, side: f64, what: &str| {
        assert!(
            matches!(found, Ok(s) if (s - side).abs() < 1e-9),
            "{what}: {found:?}, expected the tetrahedron of side {side}"
        );
    };
    // Beside the model first: meshes/m.obj (side 2) over sub/meshes/m.obj (side 1).
    near(
        side_read("main.xml"),
        2.0,
        "an included file's mesh, both there",
    );
    // meshdir's meshes/m.obj is there: side 2.
    near(side_read("main2.xml"), 2.0, "meshdir, both there");
    std::fs::remove_file(dir.join("meshes/m.obj")).expect("remove");
    near(side_read("main.xml"), 1.0, "beside the included file");
    near(
        side_read("main2.xml"),
        3.0,
        "beside the included file, without meshdir",
    );
    // The nested include beside the file that includes it; its mesh beside itself.
    near(side_read("main3.xml"), 5.0, "a nested include");
    // The model file's own mesh has no second place to look.
    let own = side_read("main6.xml");
    assert!(
        matches!(&own, Err(e) if e.contains("mesh_missing")),
        "{own:?}"
    );
}

/// XML that strict parsers refuse and urdfdom and MuJoCo's TinyXML2 read (airo-models' UR5e
/// carries Drake's attributes without declaring their prefix; `--` in comments; a declaration
/// after blank lines): read, each fault named with its line, and the fix still splices the
/// file's own bytes, the undeclared attributes kept as written.
#[test]
fn xml_the_engines_accept_is_read_with_its_faults_named() {
    let urdf = "\n\n<?xml version=\"1.0\"?>\n<robot name=\"r\">\n\
        <!-- a -- comment --->\n\
        <link name=\"a\" drake:accel=\"1\"><inertial><mass value=\"6\"/>\
        <inertia ixx=\"0.1\" ixy=\"0\" ixz=\"0\" iyy=\"0.1\" iyz=\"0\" izz=\"0.1\"/></inertial>\
        <collision><geometry><box size=\"1 2 3\"/></geometry></collision></link>\n\
        <drake:collision_filter_group name=\"g\"></drake:collision_filter_group>\n</robot>\n";
    let robot = read_str(urdf, Path::new("r.urdf"), &ReadOptions::default()).expect("read");
    let faults: Vec<(u32, &str)> = robot.sources[0]
        .read_leniently
        .iter()
        .map(|l| (l.at.line, l.what.as_str()))
        .collect();
    assert_eq!(faults.len(), 3, "{faults:?}");
    assert_eq!(faults[0].0, 3, "the declaration: {faults:?}");
    assert!(
        faults
            .iter()
            .any(|(line, what)| *line == 5 && what.contains("\"--\"")),
        "{faults:?}"
    );
    assert!(
        faults.iter().any(|(_, what)| what.contains("drake:")),
        "{faults:?}"
    );
    // The box of 6 kg: the audit weighs the link.
    let report = audit(&robot, &AuditOptions::default());
    let c = report.links[0].computed.as_ref().expect("weighed");
    assert!((c.properties.mass - 6.0).abs() < 1e-12);
    let fixed = robot::fix::splice(
        &robot,
        &[robot::fix::Replacement {
            link: 0,
            text: "<inertial><mass value=\"6\"/></inertial>".to_owned(),
        }],
    )
    .expect("spliced");
    assert!(
        fixed.contains(
            "<link name=\"a\" drake:accel=\"1\"><inertial><mass value=\"6\"/></inertial><collision>"
        ),
        "{fixed}"
    );
    assert!(
        fixed.starts_with("\n\n<?xml") && fixed.contains("<!-- a -- comment --->"),
        "{fixed}"
    );
    // A NUL after the root element (pybullet's humanoid.urdf) is read past too.
    let nul = format!("{urdf}\0");
    let with_nul = read_str(&nul, Path::new("r.urdf"), &ReadOptions::default()).expect("read");
    assert!(
        with_nul.sources[0]
            .read_leniently
            .iter()
            .any(|l| l.what.contains("NUL")),
        "{:?}",
        with_nul.sources[0].read_leniently
    );
    // Two attributes run together, twice on one line (the second `name="b"type=…` after the
    // first space is put in): read, every element at its place in the file as written, and the
    // fix splices the file's own bytes.
    let joined = urdf.replace("name=\"a\" drake", "name=\"a\"drake").replace(
        "<box size=\"1 2 3\"/>",
        "<box size=\"1 2 3\"name=\"b\"x=\"1\"/>",
    );
    let robot = read_str(&joined, Path::new("r.urdf"), &ReadOptions::default()).expect("read");
    let spaces = robot.sources[0]
        .read_leniently
        .iter()
        .filter(|l| l.what.contains("no space between two attributes"))
        .count();
    assert_eq!(spaces, 3, "{:?}", robot.sources[0].read_leniently);
    let link = &robot.links[0];
    assert!(joined[link.element.range.clone()].starts_with("<link name=\"a\"drake"));
    assert!(joined[link.element.range.clone()].ends_with("</link>"));
    let inertial = link.stated.as_ref().expect("stated");
    assert!(joined[inertial.span.range.clone()].starts_with("<inertial><mass value=\"6\"/>"));
    assert_eq!(
        (inertial.span.at.line, inertial.span.at.column),
        (6, 31),
        "the inertial's place in the file as written"
    );
    let fixed = robot::fix::splice(
        &robot,
        &[robot::fix::Replacement {
            link: 0,
            text: "<inertial><mass value=\"7\"/></inertial>".to_owned(),
        }],
    )
    .expect("spliced");
    assert_eq!(
        fixed,
        joined.replace(
            &joined[inertial.span.range.clone()],
            "<inertial><mass value=\"7\"/></inertial>"
        )
    );
}

/// Unit and typing slips named with the value they would have: a 0.1 × 0.2 × 0.3 m aluminium
/// block (16.2 kg, 2700 kg/m³) stated in grams, with its decimal point one place off, its mesh
/// in millimetres, its moments in kg·mm²; nothing named when the link is right, light (a
/// density too low is as often a hollow part) or only its shape witnesses the slip.
#[test]
fn unit_slips_are_named_with_the_value_they_would_have() {
    let root = scratch("unit_slips");
    std::fs::write(root.join("cube.obj"), cube_obj()).expect("present");
    let (a, b, c) = (0.1f64, 0.2f64, 0.3f64);
    let m = 2700.0 * a * b * c;
    let moments = [
        m * (b * b + c * c) / 12.0,
        m * (a * a + c * c) / 12.0,
        m * (a * a + b * b) / 12.0,
    ];
    let link = |mass: f64, scale: &str, factor: f64| {
        let [ixx, iyy, izz] = moments.map(|i| i * factor);
        let urdf = format!(
            r#"<robot name="u"><link name="block"><inertial><mass value="{mass}"/>
  <inertia ixx="{ixx}" ixy="0" ixz="0" iyy="{iyy}" iyz="0" izz="{izz}"/></inertial>
  <collision><geometry><mesh filename="cube.obj" scale="{scale}"/></geometry></collision></link></robot>"#
        );
        let path = root.join("u.urdf");
        std::fs::write(&path, urdf).expect("present");
        let robot = read(&path, &ReadOptions::default()).expect("read");
        let report = audit(&robot, &AuditOptions::default());
        report.links[0]
            .findings
            .iter()
            .filter_map(|f| match f {
                Finding::LikelyUnitError {
                    slip,
                    stated,
                    would_be,
                } => Some((*slip, *stated, *would_be)),
                _ => None,
            })
            .collect::<Vec<_>>()
    };
    let metres = "0.1 0.2 0.3";
    let near = |x: f64, y: f64| (x - y).abs() <= 1e-9 * y.abs();
    assert_eq!(link(m, metres, 1.0), [], "a right link");
    assert_eq!(link(0.03 * m, metres, 0.03), [], "a light (hollow) link");
    // The whole inertial in grams, and the mass alone.
    for moments_factor in [1000.0, 1.0] {
        let grams = link(1000.0 * m, metres, moments_factor);
        assert!(
            matches!(grams.as_slice(), [(UnitSlip::MassInGrams, s, w)] if near(*s, 1000.0 * m) && near(*w, m)),
            "{grams:?}"
        );
    }
    // Ten times too dense with a tensor of the same shape: an undersized geometry as well as a
    // slip, so nothing is named.
    assert_eq!(link(10.0 * m, metres, 10.0), [], "shape alone");
    // The mass typed ten times too large beside a tensor worked out right.
    let decimal = link(10.0 * m, metres, 1.0);
    assert!(
        matches!(decimal.as_slice(), [(UnitSlip::MassDecimalPoint { power: 1 }, _, w)] if near(*w, m)),
        "{decimal:?}"
    );
    let mm = link(m, "100 200 300", 1.0);
    assert!(
        mm.iter()
            .any(|(slip, _, w)| *slip == UnitSlip::MeshInMillimetres && near(*w, 2700.0)),
        "{mm:?}"
    );
    let kg_mm2 = link(m, metres, 1e6);
    assert!(
        matches!(kg_mm2.as_slice(), [(UnitSlip::MomentsInKgMm2, s, w)] if near(*s, 1e6 * moments[0]) && near(*w, moments[0])),
        "{kg_mm2:?}"
    );
}

/// What the fuzz target does with an input (`fuzz/fuzz_targets/robot.rs`), shared with it.
#[path = "../../../fuzz/fuzz_targets/robot_common.rs"]
mod fuzz_target;

#[test]
fn the_fuzz_seeds_read_audit_and_fix_again() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fuzz/seeds/robot");
    let mut n = 0;
    for entry in std::fs::read_dir(&dir).expect("the seeds") {
        let text = std::fs::read_to_string(entry.expect("entry").path()).expect("text");
        fuzz_target::audit_and_fix(&text);
        n += 1;
    }
    assert!(n >= 2);
}

#[test]
fn a_shared_tensor_is_a_placeholder_only_between_links_that_have_geometry() {
    // As jvrc1's hip links: one tensor on links without any geometry says nothing of shapes.
    let urdf = r#"<robot name="j">
  <link name="a"><inertial><mass value="1"/><inertia ixx="0.0123" ixy="0" ixz="0" iyy="0.0234" iyz="0" izz="0.0345"/></inertial></link>
  <link name="b"><inertial><mass value="1"/><inertia ixx="0.0123" ixy="0" ixz="0" iyy="0.0234" iyz="0" izz="0.0345"/></inertial></link>
  <joint name="j" type="revolute"><parent link="a"/><child link="b"/></joint>
</robot>"#;
    let robot = read_str(urdf, Path::new("j.urdf"), &ReadOptions::default()).expect("read");
    let report = audit(&robot, &AuditOptions::default());
    for l in &report.links {
        assert!(
            !codes(&l.findings).contains(&"placeholder"),
            "{:?}",
            l.findings
        );
    }
}

/// The nearest valid inertial, written back and audited again, is found valid: here for a
/// 1 mm cube with a larger visual box, stated as go1's camera links are (1e-5 kg, 1e-6 kg·m²
/// each way), whose nearest
/// tensor has two equal moments, so the audit may take any axis of their plane as principal
/// (the bound about every axis of that plane must hold, not only the solver's own axes).
#[test]
fn the_nearest_inertial_written_back_is_valid() {
    let urdf = |mass: f64, com: [f64; 3], i: [f64; 6]| {
        format!(
            r#"<robot name="r"><link name="camera"><inertial>
  <origin xyz="{} {} {}" rpy="0 0 0"/><mass value="{mass}"/>
  <inertia ixx="{}" ixy="{}" ixz="{}" iyy="{}" iyz="{}" izz="{}"/></inertial>
  <collision><geometry><box size="0.001 0.001 0.001"/></geometry></collision>
  <visual><origin xyz="0.012 0.003 -0.002" rpy="0.3 0.2 0.1"/>
    <geometry><box size="0.03 0.01 0.02"/></geometry></visual></link></robot>"#,
            com[0], com[1], com[2], i[0], i[1], i[2], i[3], i[4], i[5]
        )
    };
    let options = AuditOptions {
        nearest: true,
        ..AuditOptions::default()
    };
    let stated = urdf(1e-5, [0.0; 3], [1e-6, 0.0, 0.0, 1e-6, 0.0, 1e-6]);
    let robot = read_str(&stated, Path::new("r.urdf"), &ReadOptions::default()).expect("read");
    let report = audit(&robot, &options);
    assert!(codes(&report.links[0].findings).contains(&"impossible_moment"));
    let n = report.links[0]
        .nearest
        .clone()
        .expect("asked for")
        .expect("a nearest inertial");
    let (c, t) = (n.properties.center_of_mass, n.properties.inertia_com);
    let fixed = urdf(
        n.properties.mass,
        [c.x, c.y, c.z],
        // URDF's ixy is the tensor's own entry (−∑m·x·y).
        [
            t[(0, 0)],
            t[(0, 1)],
            t[(0, 2)],
            t[(1, 1)],
            t[(1, 2)],
            t[(2, 2)],
        ],
    );
    let again = audit(
        &read_str(&fixed, Path::new("r.urdf"), &ReadOptions::default()).expect("read"),
        &options,
    );
    let found = codes(&again.links[0].findings);
    assert!(
        !found.iter().any(|c| [
            "impossible_moment",
            "triangle_inequality",
            "not_positive_definite"
        ]
        .contains(c)),
        "{found:?}: moments {:?}",
        n.properties.principal.moments
    );
    let own = again.links[0].nearest.clone().expect("asked").expect("one");
    assert!(own.held_by.is_empty() && own.moved == 0.0, "{own:?}");
}

/// A stated centre written in a mesh's own frame (its origin left out) is named with the centre
/// it would be; the centre written in the link's frame, a centre at the link's origin (the
/// default a primitive's own centre always matches) and one simply elsewhere are not.
#[test]
fn a_centre_in_the_meshs_frame_is_named() {
    let dir = scratch("frame_slip");
    // A box mesh with a corner at its origin, as CAD exports often are: 0.3 x 0.05 x 0.05 m,
    // its centre (0.15, 0.025, 0.025) in its own frame. Turned 90 degrees about y and raised
    // 0.2 m, its centre is (0.025, 0.025, 0.05) in the link's.
    let corner_cube: String = cube_obj()
        .lines()
        .map(|l| match l.strip_prefix("v ") {
            Some(v) => {
                let c: Vec<f64> = v
                    .split(' ')
                    .map(|x| x.parse::<f64>().expect("a number") + 0.5)
                    .collect();
                format!("v {} {} {}\n", c[0], c[1], c[2])
            }
            None => format!("{l}\n"),
        })
        .collect();
    std::fs::write(dir.join("bar.obj"), corner_cube).expect("written");
    let findings = |com: &str| {
        let path = dir.join("arm.urdf");
        std::fs::write(
            &path,
            format!(
                r#"<robot name="r"><link name="arm"><inertial>
  <origin xyz="{com}" rpy="0 0 0"/><mass value="2.7"/>
  <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.02"/></inertial>
  <collision><origin xyz="0 0 0.2" rpy="0 1.5707963267948966 0"/>
    <geometry><mesh filename="bar.obj" scale="0.3 0.05 0.05"/></geometry></collision>
</link></robot>"#
            ),
        )
        .expect("written");
        let robot = read(&path, &ReadOptions::default()).expect("read");
        audit(&robot, &AuditOptions::default()).links[0]
            .findings
            .clone()
    };
    let named = findings("0.15 0.025 0.025")
        .iter()
        .find_map(|f| match f {
            Finding::CenterInGeometryFrame { would_be, .. } => Some(*would_be),
            _ => None,
        })
        .expect("named");
    assert!(
        (named - nalgebra::Point3::new(0.025, 0.025, 0.05)).norm() < 1e-12,
        "{named}"
    );
    for not_a_slip in ["0.025 0.025 0.05", "0 0 0", "0 0.3 0"] {
        assert!(
            !codes(&findings(not_a_slip)).contains(&"center_in_geometry_frame"),
            "{not_a_slip}"
        );
    }
}

/// What yourdfpy loads and urdfdom refuses is read, and what the audit cannot use is named: an
/// `<inertial>` without its `<mass>` or its `<inertia>` (mani-skill's trifinger cubes,
/// airo-models' d435), a joint to a link the file lacks (the trifinger stage), an `rpy` of four
/// numbers (pybullet's microtaur), a file with no link at all (pybullet's `torus_deform.urdf`). The fix replaces an incomplete inertial.
#[test]
fn descriptions_yourdfpy_loads_are_read_with_what_is_missing_named() {
    let urdf = r#"<robot name="r">
  <link name="cube"><inertial><origin xyz="0 0 0"/>
    <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>
    <collision><origin rpy="0 0 0.5 0"/><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>
  <link name="camera"><inertial><mass value="0.07"/></inertial></link>
  <joint name="mount" type="fixed"><parent link="base_link"/><child link="cube"/></joint>
  <joint name="cam" type="fixed"><parent link="cube"/><child link="camera"/></joint>
</robot>"#;
    let robot = read_str(urdf, Path::new("r.urdf"), &ReadOptions::default()).expect("read");
    assert_eq!(robot.links.len(), 2);
    assert_eq!(
        robot.links[1].parent,
        Some(0),
        "the joint between two links is kept"
    );
    assert_eq!(robot.unsupported.len(), 2, "{:?}", robot.unsupported);
    // An rpy of four numbers (pybullet's microtaur): the first three, as yourdfpy reads it.
    assert!(robot.unsupported[0].what.contains("rpy has 4 numbers"));
    let turn = robot.links[0].collision[0].pose.rotation;
    assert!(
        (turn.angle() - 0.5).abs() < 1e-15 && (turn.axis().expect("turned").z - 1.0).abs() < 1e-15
    );
    assert!(robot.unsupported[1].what.contains("\"base_link\""));
    let report = audit(&robot, &AuditOptions::default());
    let missing: Vec<Option<&str>> = report
        .links
        .iter()
        .map(|l| {
            l.findings.iter().find_map(|f| match f {
                Finding::MissingInertial { incomplete, .. } => Some(*incomplete),
                _ => None,
            })
        })
        .map(Option::flatten)
        .collect();
    assert_eq!(missing, [Some("mass"), Some("inertia")]);
    let fixed = robot::fix::splice(
        &robot,
        &[robot::fix::Replacement {
            link: 0,
            text: "<inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial>".to_owned(),
        }],
    )
    .expect("spliced");
    assert_eq!(
        fixed.matches("<inertial>").count(),
        2,
        "replaced, not added: {fixed}"
    );
    let again = read_str(&fixed, Path::new("r.urdf"), &ReadOptions::default()).expect("read");
    assert_eq!(again.links[0].stated.as_ref().expect("stated").mass, 1.0);

    let soft = r#"<robot name="torus"><deformable name="torus"><inertial><mass value="3"/>
      </inertial></deformable></robot>"#;
    let robot = read_str(soft, Path::new("t.urdf"), &ReadOptions::default()).expect("read");
    assert!(robot.links.is_empty());
    let notes: Vec<&str> = robot
        .unsupported
        .iter()
        .map(|u| u.element.as_str())
        .collect();
    assert_eq!(notes, ["robot", "deformable"]);
}
