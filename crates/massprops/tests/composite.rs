//! Bodies made of parts, against closed forms: two boxes of different densities, a hollow box
//! (a box void), a thin-walled box against its six plates, rotated and moved parts, and equal
//! densities against the single mesh.

use crate::common;

use common::{assert_mat, assert_rel, box_tensor};
use massprops::defects::shell_faces;
use massprops::shapes;
use massprops::{Fill, MassSpec, MeshError, Method, Part, Repairs, analyze, composite};
use nalgebra::{Isometry3, Matrix3, Point3, Translation3, UnitQuaternion, Vector3};

fn cuboid(size: [f64; 3], center: [f64; 3]) -> massprops::PolyMesh {
    shapes::cuboid(Vector3::from(size), Point3::from(center)).build()
}

fn part(name: &str, mesh: massprops::PolyMesh, fill: Fill) -> Part {
    Part {
        name: name.to_owned(),
        mesh,
        fill,
        placement: Isometry3::identity(),
    }
}

/// m(|d|²E − d dᵀ).
fn steiner(m: f64, d: Vector3<f64>) -> Matrix3<f64> {
    (Matrix3::identity() * d.norm_squared() - d * d.transpose()) * m
}

#[test]
fn two_boxes_of_different_densities() {
    // A steel head (0.1 × 0.03 × 0.03 at y = 0.3) on a wooden handle (0.03 × 0.3 × 0.03).
    let head = cuboid([0.1, 0.03, 0.03], [0.0, 0.315, 0.0]);
    let handle = cuboid([0.03, 0.3, 0.03], [0.0, 0.15, 0.0]);
    let c = composite(
        &[
            part("head", head, Fill::Solid { density: 7850.0 }),
            part("handle", handle, Fill::Solid { density: 600.0 }),
        ],
        &Repairs::default(),
    )
    .expect("two solids");
    let (mh, ms) = (7850.0 * 0.1 * 0.03 * 0.03, 600.0 * 0.03 * 0.3 * 0.03);
    let m = mh + ms;
    let y = (mh * 0.315 + ms * 0.15) / m;
    assert_rel(c.properties.mass, m, 1e-14, "mass");
    assert_rel(
        c.properties.center_of_mass.y,
        y,
        1e-14,
        "centre in the head's direction",
    );
    let want = box_tensor(mh, 0.1, 0.03, 0.03)
        + steiner(mh, Vector3::new(0.0, 0.315 - y, 0.0))
        + box_tensor(ms, 0.03, 0.3, 0.03)
        + steiner(ms, Vector3::new(0.0, 0.15 - y, 0.0));
    assert_mat(&c.properties.inertia_com, &want, 1e-13, "composite tensor");
    assert_eq!(c.parts[0].name, "head");
    assert_rel(c.parts[0].mass, mh, 1e-14, "head mass");
    assert_rel(c.parts[1].volume, 0.03 * 0.3 * 0.03, 1e-14, "handle volume");
    for k in 0..3 {
        assert_rel(
            c.parts[0].share[k] + c.parts[1].share[k],
            1.0,
            1e-13,
            "shares add up",
        );
    }
}

#[test]
fn a_box_void_makes_a_hollow_box() {
    let outer = cuboid([2.0, 3.0, 4.0], [0.0; 3]);
    let inner = cuboid([1.0, 2.0, 3.0], [0.2, -0.1, 0.3]);
    let c = composite(
        &[
            part("shell", outer, Fill::Solid { density: 2.0 }),
            part("hollow", inner, Fill::Void { density: 2.0 }),
        ],
        &Repairs::default(),
    )
    .expect("a hollow box");
    let (mo, mi) = (2.0 * 24.0, 2.0 * 6.0);
    let m = mo - mi;
    let ci = Vector3::new(0.2, -0.1, 0.3);
    let com = -ci * mi / m;
    let want = box_tensor(mo, 2.0, 3.0, 4.0) + steiner(mo, -com)
        - box_tensor(mi, 1.0, 2.0, 3.0)
        - steiner(mi, ci - com);
    assert_rel(c.properties.mass, m, 1e-14, "mass");
    assert!((c.properties.center_of_mass.coords - com).norm() < 1e-14);
    assert_mat(&c.properties.inertia_com, &want, 1e-13, "hollow box");
    assert_rel(c.parts[1].mass, -mi, 1e-14, "a void's mass is negative");

    // A void as large as the solid leaves nothing: refused, naming the total.
    let e = composite(
        &[
            part(
                "shell",
                cuboid([1.0; 3], [0.0; 3]),
                Fill::Solid { density: 1.0 },
            ),
            part(
                "hollow",
                cuboid([1.0; 3], [0.0; 3]),
                Fill::Void { density: 1.0 },
            ),
        ],
        &Repairs::default(),
    )
    .expect_err("nothing left");
    assert!(matches!(e, MeshError::VoidTooLarge { .. }), "{e}");
    assert!(e.to_string().contains("remove more than there is"), "{e}");
}

#[test]
fn a_thin_walled_box_is_its_six_plates() {
    let (a, b, c) = (0.4, 0.3, 0.2);
    let (rho, t) = (7850.0, 0.002);
    let body = composite(
        &[part(
            "crate",
            cuboid([a, b, c], [0.0; 3]),
            Fill::ThinWall {
                density: rho,
                thickness: t,
            },
        )],
        &Repairs::default(),
    )
    .expect("a wall");
    // Each plate: mass ρ t u v; about its centre I = m/12 (v², u², u² + v²) in its own (u, v, n)
    // axes; moved out along its normal by half the box.
    let mut want = Matrix3::zeros();
    let mut mass = 0.0;
    for (axis, (u, v), half) in [
        (0, (b, c), a / 2.0),
        (1, (a, c), b / 2.0),
        (2, (a, b), c / 2.0),
    ] {
        let m = rho * t * u * v;
        let mut own = Vector3::zeros();
        // The in-plane axes are the other two coordinates, in order.
        let (p, q) = ((axis + 1) % 3, (axis + 2) % 3);
        let (len_p, len_q) = if p < q { (u, v) } else { (v, u) };
        own[axis] = m * (u * u + v * v) / 12.0;
        own[p] = m * len_q * len_q / 12.0;
        own[q] = m * len_p * len_p / 12.0;
        for side in [-1.0, 1.0] {
            want += Matrix3::from_diagonal(&own) + steiner(m, Vector3::ith(axis, side * half));
            mass += m;
        }
    }
    assert_rel(body.properties.mass, mass, 1e-14, "six plates");
    assert_mat(
        &body.properties.inertia_com,
        &want,
        1e-13,
        "thin-walled box",
    );
    assert_rel(
        body.parts[0].volume,
        2.0 * (a * b + b * c + c * a) * t,
        1e-14,
        "wall volume",
    );
}

#[test]
fn rotated_and_moved_parts() {
    // A 1 × 2 × 3 box turned 90° about z (its 2 along x) and moved to (5, 0, 0), beside a unit
    // cube at the origin.
    let turned = Part {
        placement: Isometry3::from_parts(
            Translation3::new(5.0, 0.0, 0.0),
            UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_2),
        ),
        ..part(
            "bar",
            cuboid([1.0, 2.0, 3.0], [0.0; 3]),
            Fill::Solid { density: 1.0 },
        )
    };
    let cube = part("cube", cuboid([1.0; 3], [0.0; 3]), Fill::Mass { mass: 6.0 });
    let c = composite(&[turned, cube], &Repairs::default()).expect("two");
    let com = Vector3::new(2.5, 0.0, 0.0);
    let want = box_tensor(6.0, 2.0, 1.0, 3.0)
        + steiner(6.0, Vector3::new(5.0, 0.0, 0.0) - com)
        + box_tensor(6.0, 1.0, 1.0, 1.0)
        + steiner(6.0, -com);
    assert_rel(c.properties.mass, 12.0, 1e-14, "mass");
    assert!((c.properties.center_of_mass.coords - com).norm() < 1e-13);
    assert_mat(
        &c.properties.inertia_com,
        &want,
        1e-13,
        "turned bar and cube",
    );
}

#[test]
fn equal_densities_give_the_single_mesh_result() {
    for (name, _, body) in shapes::samples() {
        let mesh = body.build();
        let whole = analyze(&mesh, Method::Volume, MassSpec::Density(1234.0)).expect("closed");
        let parts: Vec<Part> = shell_faces(&mesh)
            .iter()
            .enumerate()
            .map(|(i, faces)| {
                part(
                    &format!("shell {}", i + 1),
                    mesh.subset(faces).expect("faces of the mesh"),
                    Fill::Solid { density: 1234.0 },
                )
            })
            .collect();
        let c = composite(&parts, &Repairs::default()).expect("parts");
        let p = &whole.properties;
        assert_rel(c.properties.mass, p.mass, 1e-13, name);
        let size = p.inertia_com.amax();
        assert!(
            (c.properties.inertia_com - p.inertia_com).amax() <= 1e-13 * size,
            "{name}"
        );
        assert!(
            (c.properties.center_of_mass - p.center_of_mass).norm()
                <= 1e-13 * (1.0 + p.center_of_mass.coords.norm()),
            "{name}"
        );
    }
}

#[test]
fn a_bad_part_is_named() {
    let mut open = shapes::cube();
    open.faces.pop();
    let refuse = Repairs {
        holes: massprops::defects::Holes::Refuse,
        ..Repairs::default()
    };
    let e = composite(
        &[part("lid", open.build(), Fill::Solid { density: 1.0 })],
        &refuse,
    )
    .expect_err("open");
    assert!(
        e.to_string().starts_with("part \"lid\": the mesh is open"),
        "{e}"
    );
    let e = composite(
        &[part(
            "wall",
            cuboid([1.0; 3], [0.0; 3]),
            Fill::ThinWall {
                density: 1.0,
                thickness: -1.0,
            },
        )],
        &Repairs::default(),
    )
    .expect_err("negative thickness");
    assert!(e.to_string().contains("thickness"), "{e}");
}

/// Each part's `share` against its closed form: the part's tensor moved to the composite's
/// centre of mass (parallel axes), projected on the whole's principal axes (nalgebra's own
/// eigensolver on the closed-form tensor) and divided by that principal moment. Two boxes of
/// different densities, one turned, so that the whole's axes are none of the mesh axes and
/// neither share is a mass fraction or a diagonal ratio.
#[test]
fn each_parts_share_is_its_tensor_on_the_wholes_principal_axes() {
    let (sa, ca, rho_a) = ([0.1, 0.03, 0.05], Vector3::new(0.02, 0.3, -0.01), 7850.0);
    let (sb, cb, rho_b) = ([0.03, 0.3, 0.04], Vector3::new(-0.01, 0.12, 0.02), 600.0);
    let turn = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 0.35)
        * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), 0.2);
    let move_b = Vector3::new(0.03, 0.0, -0.02);
    let c = composite(
        &[
            part(
                "head",
                cuboid(sa, [ca.x, ca.y, ca.z]),
                Fill::Solid { density: rho_a },
            ),
            Part {
                placement: Isometry3::from_parts(Translation3::from(move_b), turn),
                ..part(
                    "handle",
                    cuboid(sb, [cb.x, cb.y, cb.z]),
                    Fill::Solid { density: rho_b },
                )
            },
        ],
        &Repairs::default(),
    )
    .expect("two solids");

    let (ma, mb) = (rho_a * sa[0] * sa[1] * sa[2], rho_b * sb[0] * sb[1] * sb[2]);
    let r = *turn.to_rotation_matrix().matrix();
    let (com_a, com_b) = (ca, r * cb + move_b);
    let com = (com_a * ma + com_b * mb) / (ma + mb);
    let about = [
        box_tensor(ma, sa[0], sa[1], sa[2]) + steiner(ma, com_a - com),
        r * box_tensor(mb, sb[0], sb[1], sb[2]) * r.transpose() + steiner(mb, com_b - com),
    ];
    let whole = about[0] + about[1];
    assert_mat(&c.properties.inertia_com, &whole, 1e-12, "the whole");
    let eigen = whole.symmetric_eigen();
    let mut order = [0, 1, 2];
    order.sort_by(|&i, &j| eigen.eigenvalues[i].total_cmp(&eigen.eigenvalues[j]));
    for (k, &e) in order.iter().enumerate() {
        let (moment, axis) = (eigen.eigenvalues[e], eigen.eigenvectors.column(e));
        assert_rel(c.properties.principal.moments[k], moment, 1e-12, "moment");
        let mut sum = 0.0;
        for (p, tensor) in c.parts.iter().zip(&about) {
            let want = (axis.transpose() * tensor * axis)[(0, 0)] / moment;
            assert_rel(
                p.share[k],
                want,
                1e-10,
                &format!("{} share of I{}", p.name, k + 1),
            );
            sum += want;
        }
        assert_rel(sum, 1.0, 1e-13, "closed-form shares add up");
    }
    // The case tells a projection from a mass fraction.
    assert!((c.parts[0].share - Vector3::repeat(ma / (ma + mb))).amax() > 0.01);
}
