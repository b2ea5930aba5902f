//! The defects of real meshes, each on a case with a closed form: duplicate faces, internal
//! walls, overlapping and nested shells, cavities, cracks, holes, separately flipped shells.

use crate::common;

use common::{assert_mat, assert_rel, box_tensor};
use massprops::defects::Holes;
use massprops::defects::Orientation;
use massprops::defects::Weld;
use massprops::shapes::{self, MeshBuilder};
use massprops::{Analysis, Defect, MassSpec, Method, PolyMesh, Repairs, analyze, analyze_with};
use nalgebra::{Point2, Point3, Vector3};

fn cuboid(size: f64, center: [f64; 3]) -> MeshBuilder {
    shapes::cuboid(Vector3::repeat(size), Point3::from(center))
}

/// Builds with identical positions welded, as the file readers do.
fn welded(b: &MeshBuilder) -> PolyMesh {
    let (positions, remap) = massprops::mesh::weld_exact(&b.positions);
    let faces: Vec<Vec<usize>> = b
        .faces
        .iter()
        .map(|f| f.iter().map(|&i| remap[i] as usize).collect())
        .collect();
    PolyMesh::new(positions, &faces).expect("valid")
}

fn volume(mesh: &PolyMesh) -> Analysis {
    analyze(mesh, Method::Volume, MassSpec::Density(1.0)).expect("volume")
}

fn codes(a: &Analysis) -> Vec<&'static str> {
    a.warnings.iter().map(|w| w.code()).collect()
}

fn warning<'a>(a: &'a Analysis, code: &str) -> &'a massprops::Warning {
    a.warnings
        .iter()
        .find(|w| w.code() == code)
        .unwrap_or_else(|| panic!("no {code} in {:?}", a.warnings))
}

#[test]
fn faces_listed_twice_count_once() {
    // Unit cube about the origin: about its centre, each face carries a sixth of the volume.
    for repeated in [1, 3, 6] {
        let mut b = cuboid(1.0, [0.0; 3]);
        let extra: Vec<Vec<usize>> = b.faces[..repeated].to_vec();
        b.faces.extend(extra);
        let a = volume(&b.build());
        assert_rel(a.properties.mass, 1.0, 1e-15, "counted once");
        assert_mat(
            &a.properties.inertia_com,
            &box_tensor(1.0, 1.0, 1.0, 1.0),
            1e-15,
            "cube",
        );
        assert_eq!(codes(&a), ["duplicate_faces"], "{repeated}");
        let w = &a.warnings[0];
        assert_eq!(w.count, repeated);
        assert_eq!(w.faces, (6..6 + repeated.min(5)).collect::<Vec<_>>());
        assert_rel(
            w.effect_on_mass.expect("known"),
            repeated as f64 / 6.0,
            1e-14,
            "what they would add",
        );
    }
    // A whole mesh doubled, rotated copies of each cycle: twice the mass, and no false flip.
    let mut b = cuboid(2.0, [5.0, 0.0, 0.0]);
    let again: Vec<Vec<usize>> = b
        .faces
        .iter()
        .map(|f| {
            let mut f = f.clone();
            f.rotate_left(1);
            f
        })
        .collect();
    b.faces.extend(again);
    let a = volume(&b.build());
    assert_rel(a.properties.mass, 8.0, 1e-15, "doubled cube");
    assert_eq!(codes(&a), ["duplicate_faces"]);
    assert_rel(
        a.warnings[0].effect_on_mass.expect("known"),
        1.0,
        1e-14,
        "2x",
    );
    assert!(!a.flipped);
}

/// Zero-area faces repeated on the same vertices (as scanner exports write them) are degenerate,
/// not duplicates: only the real copy is a duplicate face (racecar/hokuyo.obj had 166
/// "duplicates", 165 of them degenerate).
#[test]
fn degenerate_faces_are_not_counted_again_as_duplicates() {
    let mut b = cuboid(1.0, [0.0; 3]);
    let first = b.faces[0].clone();
    // A sliver on three corners of one edge (two of them the same point), three times over.
    for _ in 0..3 {
        b.faces.push(vec![first[0], first[1], first[1]]);
    }
    // And one real copy of a face.
    b.faces.push(first);
    let a = volume(&b.build());
    assert_rel(a.properties.mass, 1.0, 1e-15, "counted once");
    let duplicates = warning(&a, "duplicate_faces");
    assert_eq!(duplicates.count, 1, "{:?}", a.warnings);
    assert_eq!(duplicates.faces, [9]);
    assert_eq!(warning(&a, "degenerate_faces").count, 3);
}

#[test]
fn an_internal_wall_between_two_boxes_goes_and_joins_them() {
    // Two unit boxes sharing the face x = 1, each listing it (opposite windings).
    let mut b = cuboid(1.0, [0.5, 0.5, 0.5]);
    b.append(&cuboid(1.0, [1.5, 0.5, 0.5]));
    let a = volume(&welded(&b));
    assert_rel(a.properties.mass, 2.0, 1e-15, "two boxes");
    assert_eq!(codes(&a), ["opposite_duplicate_faces"]);
    assert_eq!(a.warnings[0].count, 2);
    assert_eq!(a.warnings[0].effect_on_mass, Some(0.0));
    assert_eq!(a.shells.len(), 1, "{:?}", a.shells);
    assert!(a.shells[0].closed);
    assert_eq!(a.shells[0].faces, 10);
    // A thin wall keeps one copy of the shared face: 11 unit faces.
    let s = analyze(&welded(&b), Method::Shell, MassSpec::Density(1.0)).expect("area");
    assert_rel(s.properties.mass, 11.0, 1e-15, "one wall");
    // Where the wall meets the outer faces, three faces share an edge (a T-joint).
    assert_eq!(codes(&s), ["opposite_duplicate_faces", "nonmanifold_edges"]);
    assert_rel(
        s.warnings[0].effect_on_mass.expect("known"),
        1.0 / 11.0,
        1e-15,
        "a face",
    );
}

#[test]
fn a_box_with_an_inward_box_inside_is_a_cavity() {
    let mut b = cuboid(3.0, [0.0; 3]);
    let mut inner = cuboid(1.0, [0.5, 0.2, -0.3]);
    inner.faces.iter_mut().for_each(|f| f.reverse());
    b.append(&inner);
    let a = volume(&b.build());
    assert!(a.warnings.is_empty(), "{:?}", a.warnings);
    assert_rel(a.properties.mass, 26.0, 1e-15, "27 - 1");
    // Closed form: the solid box minus the small one, each by the parallel-axis theorem.
    let c = Vector3::new(0.5, 0.2, -0.3);
    let com = -c / 26.0;
    let shift = |m: f64, d: Vector3<f64>| {
        (nalgebra::Matrix3::identity() * d.norm_squared() - d * d.transpose()) * m
    };
    let want = box_tensor(27.0, 3.0, 3.0, 3.0) + shift(27.0, -com)
        - (box_tensor(1.0, 1.0, 1.0, 1.0) + shift(1.0, c - com));
    assert_mat(&a.properties.inertia_com, &want, 1e-14, "hollow box");
    let shells: Vec<(Orientation, Option<usize>)> =
        a.shells.iter().map(|s| (s.orientation, s.depth)).collect();
    assert_eq!(
        shells,
        [
            (Orientation::Outward, Some(0)),
            (Orientation::Inward, Some(1))
        ]
    );
}

#[test]
fn an_outward_inner_wall_is_a_nested_shell_and_counts_twice() {
    let mut b = cuboid(3.0, [0.0; 3]);
    b.append(&cuboid(1.0, [0.5, 0.2, -0.3]));
    let a = volume(&b.build());
    assert_rel(a.properties.mass, 28.0, 1e-15, "sum as written");
    assert_eq!(codes(&a), ["nested_shell"]);
    let w = &a.warnings[0];
    assert_eq!(w.defect, Defect::NestedShell { shells: vec![1] });
    assert_eq!(w.faces, (6..11).collect::<Vec<_>>());
    assert_rel(
        w.effect_on_mass.expect("known"),
        1.0 / 28.0,
        1e-14,
        "inner box",
    );
    assert_eq!(a.shells[1].depth, Some(1));
}

#[test]
fn overlapping_boxes_report_the_volume_they_count_twice() {
    // A 2 × 2 × 2 box and a diamond prism (a square turned 45°, corners (1,1) (2,0) (3,1) (2,2))
    // of the same height: they share the triangle (1,1) (2,0) (2,2), area 1, so volume 2.
    let mut b = cuboid(2.0, [1.0, 1.0, 1.0]);
    let diamond = [(1.0, 1.0), (2.0, 0.0), (3.0, 1.0), (2.0, 2.0)];
    let diamond: Vec<Point2<f64>> = diamond.iter().map(|&(x, y)| Point2::new(x, y)).collect();
    // Counter-clockwise: (2,0) (3,1) (2,2) (1,1).
    let ccw = [diamond[1], diamond[2], diamond[3], diamond[0]];
    b.append(&shapes::prism(&ccw, 0.0, 2.0));
    let a = volume(&b.build());
    assert_rel(a.properties.mass, 8.0 + 4.0, 1e-14, "the sum");
    assert_eq!(codes(&a), ["overlapping_shells"]);
    let w = &a.warnings[0];
    let Defect::OverlappingShells {
        ref pairs,
        volume,
        uncertainty,
        compared,
        candidates,
        uncompared_bound,
    } = w.defect
    else {
        panic!("{w:?}")
    };
    assert_eq!(uncompared_bound, 0.0, "all compared");
    assert_eq!(
        (pairs.as_slice(), compared, candidates),
        ([(0, 1)].as_slice(), 1, 1)
    );
    assert!(uncertainty > 0.0 && uncertainty < 0.02, "{uncertainty}");
    assert!(
        (volume - 2.0).abs() < 4.0 * uncertainty,
        "{volume} ± {uncertainty}"
    );
    assert_rel(
        w.effect_on_mass.expect("known"),
        volume / 12.0,
        1e-15,
        "counted twice",
    );
    assert_eq!(
        a.shells.iter().map(|s| s.depth).collect::<Vec<_>>(),
        [Some(0), Some(0)]
    );
}

#[test]
fn a_zero_budget_says_the_comparison_was_cut_short() {
    let mut b = cuboid(2.0, [1.0, 1.0, 1.0]);
    b.append(&cuboid(2.0, [2.0, 1.0, 1.0]));
    let repairs = Repairs {
        overlap_budget: 0,
        ..Default::default()
    };
    let a =
        analyze_with(&b.build(), Method::Volume, MassSpec::Density(1.0), &repairs).expect("volume");
    let w = warning(&a, "overlapping_shells");
    // Not compared: the two 2 × 2 × 2 boxes may share at most the smaller one, 8.
    let Defect::OverlappingShells {
        compared: 0,
        candidates: 1,
        uncompared_bound,
        ..
    } = w.defect
    else {
        panic!("{w:?}")
    };
    assert_rel(uncompared_bound, 8.0, 1e-14, "the bound");
    assert!(a.shells.iter().all(|s| s.depth.is_none()));
}

/// A city block: `n × n` unit boxes of varying heights on a grid 0.8 apart, each overlapping
/// its neighbours (the kind of scene a game level is: thousands of closed shells through one
/// another), with the exact volume the pairs of boxes share.
fn city_block(n: usize) -> (PolyMesh, f64) {
    let mut b = MeshBuilder::default();
    let mut boxes = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let height = 1.0 + ((i * 7 + j * 3) % 5) as f64 * 0.5;
            let (x, y) = (i as f64 * 0.8, j as f64 * 0.8);
            let lo = [x, y, 0.0];
            let hi = [x + 1.0, y + 1.0, height];
            let center = Point3::new(x + 0.5, y + 0.5, height / 2.0);
            b.append(&shapes::cuboid(Vector3::new(1.0, 1.0, height), center));
            boxes.push((lo, hi));
        }
    }
    let mut shared = 0.0;
    for (k, (alo, ahi)) in boxes.iter().enumerate() {
        for (blo, bhi) in &boxes[k + 1..] {
            let overlap: f64 = (0..3)
                .map(|d| (ahi[d].min(bhi[d]) - alo[d].max(blo[d])).max(0.0))
                .product();
            shared += overlap;
        }
    }
    (b.build(), shared)
}

/// The overlap warning's (volume, uncertainty, compared, candidates).
fn overlap_of(a: &Analysis) -> (f64, f64, usize, usize) {
    match warning(a, "overlapping_shells").defect {
        Defect::OverlappingShells {
            volume,
            uncertainty,
            compared,
            candidates,
            ..
        } => (volume, uncertainty, compared, candidates),
        _ => unreachable!("an overlap warning"),
    }
}

#[test]
fn a_city_block_of_overlapping_shells_is_compared_in_full_and_its_overlap_is_exact() {
    let (mesh, shared) = city_block(12);
    let a = analyze_with(
        &mesh,
        Method::Volume,
        MassSpec::Density(1.0),
        &Repairs::default(),
    )
    .expect("volume");
    let (volume, uncertainty, compared, candidates) = overlap_of(&a);
    // Each box meets its 8 neighbours (4 by a side band, 4 by a corner): 2·11·12 + 2·11·11.
    assert_eq!(candidates, 2 * 11 * 12 + 2 * 11 * 11);
    assert_eq!(
        compared, candidates,
        "the default budget finishes the block"
    );
    assert!(
        (volume - shared).abs() <= 5.0 * uncertainty + 1e-9 * shared,
        "{volume} ± {uncertainty} vs {shared}"
    );
    assert!(uncertainty < 0.05 * shared, "{uncertainty}");
}

#[test]
fn a_work_budget_cuts_the_comparison_at_the_same_place_whatever_the_load() {
    let (mesh, _) = city_block(8);
    let repairs = Repairs {
        // Enough for about a third of the pairs (each costs 24 triangles and 4 096 lines).
        overlap_budget: 60 * 4120,
        ..Repairs::default()
    };
    let run = || analyze_with(&mesh, Method::Volume, MassSpec::Density(1.0), &repairs);
    let idle = run().expect("volume");
    let (_, _, compared, candidates) = overlap_of(&idle);
    assert_eq!(compared, 60);
    assert!(candidates > compared);
    // Busy cores (as when other programs run) change nothing: the budget counts work, not time.
    let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let burners: Vec<_> = (0..3)
        .map(|_| {
            let stop = stop.clone();
            std::thread::spawn(move || {
                let mut x = 0u64;
                while !stop.load(std::sync::atomic::Ordering::Relaxed) {
                    x = x.wrapping_mul(6364136223846793005).wrapping_add(1);
                }
                x
            })
        })
        .collect();
    let loaded = run().expect("volume");
    stop.store(true, std::sync::atomic::Ordering::Relaxed);
    for b in burners {
        let _ = b.join();
    }
    assert_eq!(loaded, idle);
}

/// A height field (a terrain), open along its border: capped by a fan from the border's centre,
/// the "solid" between the sheet and the cap is made of pieces of both signs, and its moments
/// are no body's (pybullet's terrain.obj had I1 + I2 < I3 and its centre of mass outside its own
/// box). It is refused, naming the law and the caps; the shell method measures it.
#[test]
fn a_capped_terrain_is_refused_with_the_law_it_breaks_and_the_caps_named() {
    let n = 20;
    let mut b = MeshBuilder::default();
    for j in 0..=n {
        for i in 0..=n {
            let (x, y) = (i as f64 / n as f64 * 10.0, j as f64 / n as f64 * 10.0);
            let z = 1.5 * (0.9 * x).sin() * (0.7 * y).cos() + 0.3 * x;
            b.positions.push(Point3::new(x, y, z));
        }
    }
    let at = |i: usize, j: usize| j * (n + 1) + i;
    for j in 0..n {
        for i in 0..n {
            b.faces
                .push(vec![at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    let mesh = b.build();
    let e = analyze(&mesh, Method::Volume, MassSpec::Density(1.0)).expect_err("no body");
    assert!(
        matches!(e, massprops::MeshError::Impossible { .. }),
        "{e:?}"
    );
    let text = e.to_string();
    assert!(
        text.contains("not all positive") || text.contains("I1 + I2"),
        "{text}"
    );
    assert!(
        text.contains("holes capped") && text.contains("shell method"),
        "{text}"
    );
    let sheet = analyze(&mesh, Method::Shell, MassSpec::Density(1.0)).expect("a sheet");
    assert!(sheet.properties.mass > 100.0, "{}", sheet.properties.mass);
}

/// A closed mesh with 5 % of its faces flipped (an exporter's slip, a bad merge) integrates as
/// the surface it is: the faces are turned to agree with their neighbours, the volume is the
/// unflipped mesh's to round-off, and the warning counts the faces turned and their effect.
#[test]
fn a_mesh_with_five_percent_of_its_faces_flipped_has_its_own_volume() {
    let good = shapes::torus(1.0, 0.35, 64, 32).triangulated();
    let mut bad = good.clone();
    let flipped: Vec<usize> = (0..bad.faces.len()).filter(|f| f % 20 == 7).collect();
    for &f in &flipped {
        bad.faces[f].reverse();
    }
    let reference = volume(&good.build());
    let a = volume(&bad.build());
    assert_rel(
        a.volume.expect("v"),
        reference.volume.expect("v"),
        1e-12,
        "volume",
    );
    assert_mat(
        &a.properties.inertia_com,
        &reference.properties.inertia_com,
        1e-12,
        "tensor",
    );
    let w = warning(&a, "inconsistent_winding");
    assert_eq!(w.count, flipped.len());
    assert_eq!(w.faces, flipped[..5]);
    // Taken literally, each flipped face takes its cone away twice: the effect is negative and
    // about twice their share (5 %) of the volume.
    let effect = w.effect_on_mass.expect("known");
    assert!((-0.12..-0.08).contains(&effect), "{effect}");
    assert_eq!(codes(&a), ["inconsistent_winding"]);
}

/// The volume of the prism of `height` on the inner pentagon of a pentagram {5/2} of radius 1:
/// (5/2) ρ² sin 72° with ρ = cos 72° / cos 36°.
fn pentagram_overlap(height: f64) -> f64 {
    let inner = 72f64.to_radians().cos() / 36f64.to_radians().cos();
    height * 2.5 * inner * inner * 72f64.to_radians().sin()
}

fn pentagram(radius: f64, center: (f64, f64)) -> Vec<Point2<f64>> {
    (0..5)
        .map(|k| {
            let angle = std::f64::consts::FRAC_PI_2 + (2 * k % 5) as f64 * 72f64.to_radians();
            Point2::new(
                center.0 + radius * angle.cos(),
                center.1 + radius * angle.sin(),
            )
        })
        .collect()
}

/// The a1 trunk of pybullet_data in miniature: a shell passing through itself (a pentagram
/// prism) beside two boxes that overlap. The self-overlap warning states the volume counted
/// twice in all, its own and the boxes' (closed forms: the inner pentagon's prism, and a
/// 1 × 1 × 1 corner shared by two 2-cubes).
#[test]
fn the_self_overlap_warning_states_the_total_counted_twice_with_the_overlaps_between_shells() {
    let height = 0.7;
    let mut b = shapes::prism(&pentagram(1.0, (0.0, 0.0)), 0.0, height);
    b.append(&cuboid(2.0, [5.0, 0.0, 0.0]));
    b.append(&cuboid(2.0, [6.0, 1.0, 1.0]));
    let a = volume(&b.build());
    assert_eq!(codes(&a), ["overlapping_shells", "self_overlapping_shell"]);
    let counted = a.volume.expect("v");
    let own = pentagram_overlap(height);
    let expected = (own + 1.0) / counted;
    let w = warning(&a, "self_overlapping_shell");
    let Defect::SelfOverlappingShell {
        total_effect,
        total_uncertainty,
        ..
    } = w.defect
    else {
        unreachable!("its code")
    };
    let between = warning(&a, "overlapping_shells")
        .effect_on_mass
        .expect("known");
    let within = w.effect_on_mass.expect("known");
    assert_rel(total_effect, between + within, 1e-15, "the sum of both");
    assert!(
        (total_effect - expected).abs() <= 4.0 * total_uncertainty
            && total_uncertainty < 0.01 * expected,
        "{total_effect} ± {total_uncertainty} vs {expected}"
    );
}

/// A prism on a pentagram {5/2} is one closed, consistently wound shell that passes through
/// itself: its outline winds twice around the central pentagon, so the volume method counts that
/// pentagonal prism twice (the integral is the winding number's). It is named, with the volume
/// counted twice: the height times the inner pentagon's area, (5/2) ρ² sin 72° with
/// ρ = cos 72° / cos 36° of the star's radius.
#[test]
fn a_shell_that_passes_through_itself_is_named_with_the_volume_counted_twice() {
    let height = 0.7;
    let mesh = shapes::prism(&pentagram(1.0, (0.0, 0.0)), 0.0, height).build();
    let a = volume(&mesh);
    let w = warning(&a, "self_overlapping_shell");
    let Defect::SelfOverlappingShell {
        ref shells,
        volume: doubled,
        uncertainty,
        crossing_faces,
        total_effect,
        ..
    } = w.defect
    else {
        unreachable!("its code")
    };
    assert_eq!((w.count, shells.as_slice()), (1, [0].as_slice()));
    let expected = pentagram_overlap(height);
    assert!(
        (doubled - expected).abs() <= 4.0 * uncertainty && uncertainty < 0.003 * expected,
        "{doubled} ± {uncertainty} vs {expected}"
    );
    // The vertical lines see the doubly counted prism through the star's top and bottom (the
    // walls are parallel to them); the five walls bound it too but no line crosses them.
    assert_eq!((crossing_faces, w.faces.as_slice()), (2, [0, 1].as_slice()));
    assert_eq!(
        total_effect,
        w.effect_on_mass.expect("known"),
        "nothing else"
    );
    // Counted as it is (the star's own area once, the pentagon again): the effect is the
    // pentagon's share of that.
    let counted = a.volume.expect("v");
    let effect = w.effect_on_mass.expect("known");
    assert!(
        (effect - expected / counted).abs() < 0.03 * expected / counted,
        "{effect}"
    );
    // A prism on a pentagon does not pass through itself.
    let pentagon: Vec<Point2<f64>> = (0..5)
        .map(|k| {
            let angle = std::f64::consts::FRAC_PI_2 + k as f64 * 72f64.to_radians();
            Point2::new(angle.cos(), angle.sin())
        })
        .collect();
    let plain = volume(&shapes::prism(&pentagon, 0.0, height).build());
    assert!(plain.warnings.is_empty(), "{:?}", plain.warnings);
}

#[test]
fn float32_cracks_are_closed_not_called_holes() {
    // The top face of a unit cube refers to copies of its corners moved by up to 1e-8.
    let mut b = cuboid(1.0, [0.0; 3]);
    let top = b.faces[1].clone();
    let mut moved = Vec::new();
    for (k, &i) in top.iter().enumerate() {
        let delta = Vector3::new(1e-8, -0.5e-8, 0.7e-8) * (k as f64 + 1.0) / 4.0;
        b.positions.push(b.positions[i] + delta);
        moved.push(b.positions.len() - 1);
    }
    b.faces[1] = moved;
    let mesh = b.build();
    assert_eq!(massprops::diagnostics::diagnose(&mesh).open_edges, 8);
    let a = volume(&mesh);
    assert_eq!(codes(&a), ["cracks_closed"]);
    let w = &a.warnings[0];
    assert_eq!(w.count, 8, "boundary edges closed");
    let Defect::CracksClosed { largest_gap } = w.defect else {
        panic!("{w:?}")
    };
    let biggest = Vector3::new(1e-8, -0.5e-8, 0.7e-8).norm();
    assert_rel(largest_gap, biggest, 1e-6, "largest move");
    assert!(w.effect_on_mass.expect("known").abs() < 1e-7);
    assert_rel(a.properties.mass, 1.0, 1e-7, "the cube");
    assert!(a.shells.len() == 1 && a.shells[0].closed);

    // Welding exactly leaves the seam open; the caps then close it (two loops: the top's own
    // rim and the hole's), again with the cube's volume.
    let exact = Repairs {
        weld: Weld::Exact,
        ..Default::default()
    };
    let a = analyze_with(&mesh, Method::Volume, MassSpec::Density(1.0), &exact).expect("capped");
    assert_eq!(codes(&a), ["holes_capped"]);
    assert_eq!(a.warnings[0].count, 2);
    assert_rel(a.properties.mass, 1.0, 1e-7, "capped");
    // A gap wider than the tolerance is a hole, not a crack.
    let coarse = Repairs {
        weld: Weld::Distance(1e-9),
        ..Default::default()
    };
    let a = analyze_with(&mesh, Method::Volume, MassSpec::Density(1.0), &coarse).expect("capped");
    assert_eq!(codes(&a), ["holes_capped"]);
}

#[test]
fn a_separate_inward_box_is_turned_outward() {
    let mut b = cuboid(1.0, [0.0; 3]);
    let mut other = cuboid(1.0, [3.0, 0.0, 0.0]);
    other.faces.iter_mut().for_each(|f| f.reverse());
    b.append(&other);
    let a = volume(&b.build());
    assert_rel(a.properties.mass, 2.0, 1e-15, "two boxes");
    assert_rel(a.properties.center_of_mass.x, 1.5, 1e-15, "between them");
    assert!(!a.flipped);
    assert_eq!(codes(&a), ["flipped"]);
    let w = &a.warnings[0];
    assert_eq!(
        w.defect,
        Defect::Flipped {
            shells: vec![1],
            whole: false
        }
    );
    // As wound, the two would cancel: the turn added the second box twice over.
    assert_rel(w.effect_on_mass.expect("known"), -1.0, 1e-14, "-2 x 1/2");
}

#[test]
fn the_sample_bodies_raise_no_false_alarm() {
    for (name, _, body) in shapes::samples() {
        let a = volume(&body.build());
        assert!(a.warnings.is_empty(), "{name}: {:?}", a.warnings);
        assert!(a.shells.iter().all(|s| s.closed), "{name}");
    }
}

#[test]
fn refusing_holes_or_a_bad_weld_distance_is_an_error() {
    let mut b = cuboid(1.0, [0.0; 3]);
    b.faces.pop();
    let refuse = Repairs {
        holes: Holes::Refuse,
        ..Default::default()
    };
    assert!(analyze_with(&b.build(), Method::Volume, MassSpec::Density(1.0), &refuse).is_err());
    let bad = Repairs {
        weld: Weld::Distance(-1.0),
        ..Default::default()
    };
    let e = analyze_with(&b.build(), Method::Volume, MassSpec::Density(1.0), &bad)
        .expect_err("negative");
    assert!(e.to_string().contains("weld distance"), "{e}");
}

#[test]
fn a_single_inner_wall_closes_one_half_and_the_other_is_capped() {
    // A 2 × 1 × 1 box whose long faces are split at x = 1, plus one wall at x = 1 wound towards
    // +x: every edge of the wall has three faces. Around each, the left half's face pairs with
    // the wall (they bound the left cube), so the left half is a closed shell; the right half
    // lacks its wall and is capped. Together: the box, volume 2.
    let p = |x: f64, y: f64, z: f64| Point3::new(x, y, z);
    let mut positions = Vec::new();
    for x in [0.0, 1.0, 2.0] {
        for (y, z) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            positions.push(p(x, y, z));
        }
    }
    // Vertex (k, c): x index k, corner c of the square (y, z) loop above.
    let v = |k: usize, c: usize| 4 * k + c;
    let mut faces = vec![
        vec![v(0, 0), v(0, 3), v(0, 2), v(0, 1)], // x = 0, facing -x
        vec![v(2, 0), v(2, 1), v(2, 2), v(2, 3)], // x = 2, facing +x
    ];
    for k in 0..2 {
        for c in 0..4 {
            let d = (c + 1) % 4;
            faces.push(vec![v(k, c), v(k, d), v(k + 1, d), v(k + 1, c)]);
        }
    }
    faces.push(vec![v(1, 0), v(1, 1), v(1, 2), v(1, 3)]); // the wall, facing +x
    let mesh = PolyMesh::new(positions, &faces).expect("valid");
    let a = volume(&mesh);
    assert_rel(a.properties.mass, 2.0, 1e-15, "the whole box");
    assert_mat(
        &a.properties.inertia_com,
        &box_tensor(2.0, 2.0, 1.0, 1.0),
        1e-14,
        "the whole box",
    );
    assert_eq!(a.shells.len(), 2, "{:?}", a.shells);
    assert_eq!(
        a.shells
            .iter()
            .map(|s| (s.faces, s.closed, s.capped))
            .collect::<Vec<_>>(),
        [(6, true, false), (5, false, true)]
    );
    assert!(codes(&a).contains(&"holes_capped"), "{:?}", a.warnings);
}

#[test]
fn a_cavity_stays_a_cavity_when_the_comparison_runs_out_of_time() {
    let mut b = cuboid(3.0, [0.0; 3]);
    let mut inner = cuboid(1.0, [0.5, 0.2, -0.3]);
    inner.faces.iter_mut().for_each(|f| f.reverse());
    b.append(&inner);
    let no_time = Repairs {
        overlap_budget: 0,
        ..Default::default()
    };
    let a =
        analyze_with(&b.build(), Method::Volume, MassSpec::Density(1.0), &no_time).expect("volume");
    assert_rel(a.properties.mass, 26.0, 1e-15, "27 - 1, as wound");
    assert!(!codes(&a).contains(&"flipped"), "{:?}", a.warnings);
    assert!(a.shells.iter().all(|s| s.depth.is_none()));
}

#[test]
fn an_inverted_mesh_keeps_the_signs_of_its_repairs_and_ignores_stray_faces() {
    // The cube without its top, wound inward, plus one stray triangle far away: the whole mesh
    // is inverted (the triangle encloses nothing), and the cap still adds a sixth.
    let mut b = cuboid(1.0, [0.0; 3]);
    b.faces.remove(1);
    b.faces.iter_mut().for_each(|f| f.reverse());
    let base = b.positions.len();
    b.positions.extend([
        Point3::new(5.0, 0.0, 0.0),
        Point3::new(6.0, 0.0, 0.0),
        Point3::new(5.0, 1.0, 0.0),
    ]);
    b.faces.push(vec![base, base + 1, base + 2]);
    let a = volume(&b.build());
    assert!(a.flipped);
    assert_rel(a.properties.mass, 1.0, 1e-14, "the capped cube");
    let holes = warning(&a, "holes_capped");
    assert_rel(
        holes.effect_on_mass.expect("known"),
        -1.0 / 6.0,
        1e-12,
        "caps add a sixth",
    );
    let flipped = warning(&a, "flipped");
    assert!(matches!(
        flipped.defect,
        Defect::Flipped { whole: true, .. }
    ));
    assert_eq!(flipped.effect_on_mass, Some(0.0));
}

/// A crack of known size: the top face of a unit cube refers to copies of its corners moved by
/// h along z (lifted or sunk), a parallel seam well inside the weld tolerance (1e-6 × √3). The
/// mesh taken literally has the top face at 0.5 ± h, and since the open band's area vectors
/// cancel, its divergence volume is 1 ± h/3 about any reference point; the welded mesh (the
/// copies merge into the original corners, the lower indices) is the unit cube. So the
/// effect is +h/3 for a lifted top and −h/3 for a sunk one, relative to a mass of 1.
#[test]
fn a_cracks_effect_on_mass_has_its_closed_form_value_and_sign() {
    let h = 1e-6;
    for (sign, what) in [(1.0, "lifted"), (-1.0, "sunk")] {
        let mut b = cuboid(1.0, [0.0; 3]);
        let top = b.faces[1].clone();
        let mut moved = Vec::new();
        for &i in &top {
            b.positions
                .push(b.positions[i] + Vector3::new(0.0, 0.0, sign * h));
            moved.push(b.positions.len() - 1);
        }
        b.faces[1] = moved;
        let a = volume(&b.build());
        assert_eq!(codes(&a), ["cracks_closed"], "{what}");
        let w = &a.warnings[0];
        assert_eq!(w.count, 8, "{what}: boundary edges closed");
        let Defect::CracksClosed { largest_gap } = w.defect else {
            panic!("{w:?}")
        };
        assert_rel(largest_gap, h, 1e-9, what);
        assert_rel(a.properties.mass, 1.0, 1e-14, what);
        let effect = w.effect_on_mass.expect("known");
        // Measured to agree to about 1e-10; the bound is far below the effect's own size.
        assert_rel(effect, sign * h / 3.0, 1e-6, what);
        assert_eq!(effect.signum(), sign, "{what}: the sign");
    }
}

/// The shell method integrates the surface, so an open mesh (a box without its top) has a
/// mass and an area but encloses no volume: `Analysis::volume` is `None` (JSON null), while a
/// closed mesh under the same method reports its volume.
#[test]
fn an_open_mesh_under_the_shell_method_has_no_volume() {
    let mut b = cuboid(1.0, [0.0; 3]);
    b.faces.remove(1);
    let open = b.build();
    let a = analyze(&open, Method::Shell, MassSpec::Density(1.0)).expect("a sheet");
    assert_eq!(a.volume, None, "{a:?}");
    // Five unit faces of surface density 1.
    assert_rel(a.properties.mass, 5.0, 1e-14, "five faces");
    let closed = analyze(
        &cuboid(1.0, [0.0; 3]).build(),
        Method::Shell,
        MassSpec::Density(1.0),
    )
    .expect("a box");
    assert_rel(closed.volume.expect("closed"), 1.0, 1e-14, "closed box");
    assert_rel(closed.properties.mass, 6.0, 1e-14, "six faces");
}

/// A unit cube with only the faces `kept` (of x−, x+, y−, y+, z−, z+), wound outward.
fn cube_with(kept: &[usize]) -> massprops::PolyMesh {
    let p: Vec<nalgebra::Point3<f64>> = (0..8)
        .map(|i| nalgebra::Point3::new((i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2 & 1) as f64))
        .collect();
    let faces: [[usize; 4]; 6] = [
        [0, 4, 6, 2],
        [1, 3, 7, 5],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 2, 3, 1],
        [4, 5, 7, 6],
    ];
    let chosen: Vec<[usize; 4]> = kept.iter().map(|&k| faces[k]).collect();
    massprops::PolyMesh::new(p, &chosen).expect("valid")
}

#[test]
fn caps_larger_than_the_surface_they_close_are_refused_unless_allowed() {
    use massprops::{MeshError, analyze_with};
    let spec = MassSpec::Density(1.0);
    // One face missing: its cap is 1/6 of the closed surface; the cube comes back whole.
    let a = analyze_with(
        &cube_with(&[0, 1, 2, 3, 4]),
        Method::Volume,
        spec,
        &Repairs::default(),
    )
    .expect("capped");
    assert!((a.volume.expect("volume") - 1.0).abs() < 1e-12);
    // A band: the four sides of a box 0.1 tall, top and bottom missing. Its caps (2 m²) are
    // 2 / 2.4 of the closed surface.
    let fold = cube_with(&[0, 1, 2, 3])
        .map_positions(|p| nalgebra::Point3::new(p.x, p.y, 0.1 * p.z))
        .expect("valid");
    let e = analyze_with(&fold, Method::Volume, spec, &Repairs::default()).expect_err("refused");
    match e {
        MeshError::CapsTooLarge {
            share,
            threshold,
            holes,
        } => {
            assert!((share - 2.0 / 2.4).abs() < 1e-12, "{share}");
            assert_eq!(threshold, 0.5);
            assert_eq!(holes, 2);
        }
        other => panic!("{other:?}"),
    }
    let allowed = Repairs {
        max_cap_share: 1.0,
        ..Default::default()
    };
    let capped = analyze_with(&fold, Method::Volume, spec, &allowed).expect("allowed");
    assert!((capped.volume.expect("volume") - 0.1).abs() < 1e-12);
    // The shell method needs no caps.
    assert!(analyze_with(&fold, Method::Shell, spec, &Repairs::default()).is_ok());
}
