//! UI tests with egui_kittest: the panels drive the model through the real widgets (found by
//! their labels, as a screen reader would). No GL context here, so the 3D view shows its
//! placeholder; the app repaints continuously while running, so the tests step frames explicitly.

use std::time::Duration;

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

use inertia_lab::gui::LabApp;
use inertia_lab::gui::view3d::overlay::{Overlay, Selection};
use inertia_lab::i18n::Language;
use inertia_lab::lab::Variant;
use inertia_lab::lab::settings::{AppSettings, InertiaSource, MassGiven};
use rbcore::RotationModel;

/// The default settings in English, whatever the machine's locale: the tests find widgets by
/// their English names.
fn english() -> AppSettings {
    let mut s = AppSettings::default();
    s.display.language = Some(Language::English);
    s
}

fn harness() -> Harness<'static, LabApp> {
    harness_of_size([1280.0, 800.0])
}

fn harness_of_size(size: [f32; 2]) -> Harness<'static, LabApp> {
    let app = LabApp::new(english(), None, &egui::Context::default()).expect("app");
    Harness::builder()
        .with_size(size)
        .build_ui_state(|ui, app: &mut LabApp| app.show(ui), app)
}

/// Steps frames with real time passing (the frame clock reads the wall clock).
fn frames(h: &mut Harness<'static, LabApp>, n: usize) {
    for _ in 0..n {
        std::thread::sleep(Duration::from_millis(10));
        h.step();
    }
}

#[test]
fn pause_button_and_space_stop_and_restart_the_simulation() {
    let mut h = harness();
    frames(&mut h, 5);
    assert!(
        h.state().lab().primary().sim().steps() > 0,
        "runs from the start"
    );
    h.get_all_by_label("Pause").next().expect("button").click();
    frames(&mut h, 2);
    assert!(h.state().lab().is_paused());
    let steps = h.state().lab().primary().sim().steps();
    frames(&mut h, 5);
    assert_eq!(
        h.state().lab().primary().sim().steps(),
        steps,
        "no steps while paused"
    );
    h.get_by_label("Step").click();
    frames(&mut h, 1);
    assert_eq!(h.state().lab().primary().sim().steps(), steps + 1);
    h.key_press(egui::Key::Space);
    frames(&mut h, 5);
    assert!(!h.state().lab().is_paused());
    assert!(h.state().lab().primary().sim().steps() > steps + 1);
}

/// By default a new inertia source starts the motion again from the same spin, and says so.
#[test]
fn switching_the_inertia_source_starts_again_from_the_same_spin() {
    let mut h = harness();
    frames(&mut h, 30);
    let ran = h.state().lab().primary().sim().time();
    h.get_by_label("bounding box").click();
    frames(&mut h, 1);
    let lab = h.state().lab();
    assert!(lab.primary().sim().time() < ran, "did not start again");
    let w = lab.primary().history().samples()[0].omega_principal;
    assert_eq!(
        w[1],
        lab.settings().body.spin_rate,
        "the default spin, axis 2"
    );
    let said = lab.message().expect("a message");
    assert!(
        said.text.contains("started again") && said.text.contains("bounding box"),
        "{}",
        said.text
    );
}

#[test]
fn switching_the_inertia_source_mid_run_keeps_angular_momentum() {
    let mut h = harness();
    frames(&mut h, 5);
    h.get_all_by_label("Switching starts again")
        .next()
        .expect("checkbox")
        .click();
    h.get_all_by_label("Pause").next().expect("button").click();
    frames(&mut h, 1);
    assert!(!h.state().lab().settings().physics.restart_on_switch);
    let l = h.state().lab().primary().sim().body().angular_momentum();
    h.get_by_label("bounding box").click();
    frames(&mut h, 2);
    let lab = h.state().lab();
    assert_eq!(lab.settings().body.source, InertiaSource::BoundingBox);
    let bbox = lab
        .primary()
        .properties(InertiaSource::BoundingBox)
        .principal
        .moments;
    let used = lab.primary().sim().body().moments();
    assert!(
        (used - bbox).norm() <= 1e-12 * bbox.norm(),
        "{used} vs {bbox}"
    );
    assert!((lab.primary().sim().body().angular_momentum() - l).norm() <= 1e-12 * l.norm());
    // "exact" also heads the table column: the radio button is the last one.
    h.get_all_by_label("exact").last().expect("radio").click();
    frames(&mut h, 2);
    let lab = h.state().lab();
    let exact = lab
        .primary()
        .properties(InertiaSource::Exact)
        .principal
        .moments;
    assert!((lab.primary().sim().body().moments() - exact).norm() <= 1e-12 * exact.norm());
}

#[test]
fn a_bad_file_shows_the_error_and_keeps_the_body() {
    let dir = std::env::temp_dir().join(format!("inertia-lab-ui-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let bad = dir.join("not-a-mesh.obj");
    std::fs::write(&bad, "this is not an OBJ file\nf 1 2 9\n").expect("write");
    let mut h = harness();
    frames(&mut h, 2);
    h.get_by_label("Path").focus();
    h.get_by_label("Path").type_text(&bad.display().to_string());
    frames(&mut h, 1);
    h.get_by_label("Load").click();
    frames(&mut h, 2);
    for _ in 0..500 {
        if h.state().lab().loading().is_none() {
            break;
        }
        frames(&mut h, 1);
    }
    let lab = h.state().lab();
    let message = lab.message().expect("a message");
    assert!(message.error);
    assert!(message.text.contains("not-a-mesh.obj"), "{}", message.text);
    assert!(message.text.contains("kept"), "{}", message.text);
    assert_eq!(lab.primary().body().name, "T-handle");
    assert!(!lab.is_paused(), "the old body keeps running");
    // The message is on screen.
    frames(&mut h, 1);
    assert!(h.query_by_label_contains("not-a-mesh.obj").is_some());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn samples_load_and_help_opens_with_f1() {
    let mut h = harness();
    frames(&mut h, 1);
    h.get_by_label("Book").click();
    frames(&mut h, 2);
    assert_eq!(h.state().lab().primary().body().name, "Book");
    h.key_press(egui::Key::F1);
    frames(&mut h, 2);
    assert!(h.query_by_label_contains("Dzhanibekov").is_some());
    // The Help button on the message line closes it and opens it again.
    h.get_by_label("Help").click();
    frames(&mut h, 2);
    assert!(h.query_by_label_contains("Dzhanibekov").is_none());
    h.get_by_label("Help").click();
    frames(&mut h, 2);
    assert!(h.query_by_label_contains("Dzhanibekov").is_some());
}

/// Edits in two panels in the same frame both survive (the panels share one settings draft).
#[test]
fn reset_settings_spin_presets_and_reset_from_the_panel() {
    // Tall enough that "Reset settings", at the bottom of the side panel, is on screen.
    let mut h = harness_of_size([1280.0, 1400.0]);
    frames(&mut h, 2);
    h.get_by_label("Spin axis 3").click();
    frames(&mut h, 2);
    let lab = h.state().lab();
    let w = lab.primary().history().samples()[0].omega_principal;
    let rate = lab.settings().body.spin_rate;
    assert_eq!(w[2], rate, "axis 3 spins at the rate");
    assert!((w[0] - 0.02 * rate).abs() < 1e-12);
    // Bounding box (the toolbar) and the Mass radio (the side panel) in the same frame.
    h.get_by_label("Bounding box").click();
    h.get_by_label("Mass").click();
    frames(&mut h, 2);
    let s = h.state().lab().settings().clone();
    assert!(s.view.bounding_box, "toolbar edit kept");
    assert!(matches!(s.body.mass, MassGiven::Mass(_)), "panel edit kept");
    h.get_by_label("Reset").click();
    frames(&mut h, 1);
    assert!(h.state().lab().primary().sim().time() < 0.1);
    h.get_by_label("Reset settings").click();
    frames(&mut h, 2);
    assert_eq!(
        h.state().lab().settings(),
        &english(),
        "the defaults, the language kept"
    );
}

/// An open mesh under a long path: while it loads and after, the side panel keeps its width (a
/// row that cannot wrap used to widen it for good), the 3D toolbar stays one row, and the
/// warning is shown in the app's words.
#[test]
fn a_long_named_open_mesh_keeps_the_layout() {
    long_named_open_mesh_keeps_the_layout(harness(), "1280x800");
}

/// README: "The window fits at 1280×800, 1366×768 and 1920×1080 (1.5 pixels per point)". The
/// same open mesh with the long name at 1366×768.
#[test]
fn the_layout_fits_at_1366x768() {
    long_named_open_mesh_keeps_the_layout(harness_of_size([1366.0, 768.0]), "1366x768");
}

/// 1920×1080 pixels at 1.5 pixels per point: a 1280×720-point screen.
#[test]
fn the_layout_fits_at_1920x1080_with_1_5_pixels_per_point() {
    let app = LabApp::new(english(), None, &egui::Context::default()).expect("app");
    let h = Harness::builder()
        .with_size([1920.0 / 1.5, 1080.0 / 1.5])
        .with_pixels_per_point(1.5)
        .build_ui_state(|ui, app: &mut LabApp| app.show(ui), app);
    assert_eq!(h.ctx.pixels_per_point(), 1.5);
    long_named_open_mesh_keeps_the_layout(h, "1920x1080 at 1.5 px/pt");
}

/// A narrow page (1024 × 768 CSS pixels at 1.5 device pixels each, as the student's, less the
/// browser's frame): the 3D toolbar wraps and every control stays whole; with the momentum
/// sphere open the view's row is narrower still.
#[test]
fn the_toolbar_wraps_in_a_narrow_window() {
    let app = LabApp::new(english(), None, &egui::Context::default()).expect("app");
    let mut h = Harness::builder()
        .with_size([900.0, 700.0])
        .with_pixels_per_point(1.5)
        .build_ui_state(|ui, app: &mut LabApp| app.show(ui), app);
    frames(&mut h, 2);
    let row = |h: &Harness<'static, LabApp>, label: &str| h.get_by_label(label).rect().center().y;
    assert!(
        row(&h, "Equivalent") > row(&h, "Frame") + 5.0,
        "the toolbar did not wrap"
    );
    assert_fits(&h, "900x700 at 1.5 px/pt");
}

/// Loads an open mesh under a long path into `h` and checks the layout while it loads and after:
/// the side panel keeps its default width (the one it has at 1280×800), the 3D toolbar stays one
/// row, and no control of the toolbar, the plot bar or the side panel's Body section is cut off
/// by the window's edges or by the side panel's.
fn long_named_open_mesh_keeps_the_layout(mut h: Harness<'static, LabApp>, size: &str) {
    let dir = std::env::temp_dir().join(format!(
        "inertia-lab-ui-{}-{}-a-folder-whose-name-is-much-longer-than-the-side-panel-is-wide",
        std::process::id(),
        size.replace([' ', '/'], "-")
    ));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let torus = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/torus.obj"),
    )
    .expect("asset");
    // Every 50th face left out: an open surface with holes.
    let mut face = 0;
    let open: String = torus
        .lines()
        .filter(|l| {
            let is_face = l.starts_with("f ");
            face += usize::from(is_face);
            !(is_face && face % 50 == 0)
        })
        .map(|l| format!("{l}\n"))
        .collect();
    let path = dir.join("scanned_turbine_blade_with_holes_export_v2_final.obj");
    std::fs::write(&path, open).expect("write");

    // The side panel's width at 1280×800, where the default was chosen.
    let default_edge = {
        let mut reference = harness();
        frames(&mut reference, 2);
        reference.get_by_label("Frame").rect().min.x
    };
    frames(&mut h, 2);
    let frame_button = |h: &Harness<'static, LabApp>| h.get_by_label("Frame").rect();
    let before = frame_button(&h);
    // Panel edges are rounded to whole pixels: within one pixel of it at 1.5 pixels per point.
    let pixel = 1.0 / h.ctx.pixels_per_point();
    assert!(
        (before.min.x - default_edge).abs() <= pixel,
        "{size}: the side panel opens at its default width ({} vs {default_edge})",
        before.min.x
    );
    assert_fits(&h, size);
    h.get_by_label("Path").focus();
    h.get_by_label("Path")
        .type_text(&path.display().to_string());
    frames(&mut h, 1);
    h.get_by_label("Load").click();
    for _ in 0..500 {
        h.step();
        assert_eq!(
            frame_button(&h).min.x,
            before.min.x,
            "{size}: the side panel kept its width while loading"
        );
        if h.state().lab().loading().is_none() {
            break;
        }
    }
    frames(&mut h, 3);
    let lab = h.state().lab();
    assert!(
        lab.primary().body().name.starts_with("scanned_turbine"),
        "{:?}",
        lab.message()
    );
    assert!(!lab.primary().body().analysis.warnings.is_empty());
    assert!(h.query_by_label_contains("The mesh has holes").is_some());
    let after = frame_button(&h);
    assert_eq!(
        after.min.x, before.min.x,
        "{size}: the side panel kept its width"
    );
    let axes = h.get_by_label("Principal axes").rect();
    assert!(
        (axes.center().y - after.center().y).abs() < 2.0,
        "{size}: the toolbar is one row"
    );
    assert_fits(&h, size);
    std::fs::remove_dir_all(&dir).ok();
}

/// No control is cut off: the 3D toolbar's first and last controls, the plot bar's last ones and
/// the side panel's Path row lie wholly inside the window, the toolbar's right of the side panel
/// and the side panel's left of the toolbar.
fn assert_fits(h: &Harness<'static, LabApp>, size: &str) {
    let screen = h.ctx.content_rect();
    let side_edge = h.get_by_label("Frame").rect().min.x;
    let rect_of = |label: &str| {
        h.query_all_by_label(label)
            .map(|n| n.rect())
            .reduce(|a, b| a.union(b))
            .unwrap_or_else(|| panic!("{size}: no widget labelled {label:?}"))
    };
    for label in ["Frame", "Principal axes", "Sphere", "Equivalent"] {
        let r = rect_of(label);
        assert!(
            screen.contains_rect(r) && r.min.x >= side_edge,
            "{size}: toolbar's {label:?} at {r:?} is cut off (window {screen:?})"
        );
    }
    for label in ["Export CSV", "Record"] {
        let r = rect_of(label);
        assert!(
            screen.contains_rect(r),
            "{size}: plot bar's {label:?} at {r:?} is cut off (window {screen:?})"
        );
    }
    for label in ["Path", "Load", "Open mesh…"] {
        let r = rect_of(label);
        assert!(
            screen.contains_rect(r) && r.max.x <= side_edge,
            "{size}: side panel's {label:?} at {r:?} is cut off (panel edge {side_edge})"
        );
    }
}

/// A mesh with a face listed twice: the diagnostics say so with the effect on the mass, and
/// clicking the warning outlines that face in the 3D view (and clicking again clears it).
#[test]
fn clicking_a_mesh_warning_highlights_its_faces() {
    let dir = std::env::temp_dir().join(format!("inertia-lab-ui-warning-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join("doubled-top.obj");
    let cube = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
f 1 4 3 2\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\nf 5 6 7 8\nf 6 7 8 5\n";
    std::fs::write(&path, cube).expect("write");
    let mut h = harness_of_size([1280.0, 1400.0]);
    frames(&mut h, 2);
    h.get_by_label("Path").focus();
    h.get_by_label("Path")
        .type_text(&path.display().to_string());
    frames(&mut h, 1);
    h.get_by_label("Load").click();
    for _ in 0..500 {
        h.step();
        if h.state().lab().loading().is_none() {
            break;
        }
    }
    frames(&mut h, 3);
    let title = "Duplicate faces (1): +17 % mass";
    assert!(
        h.query_by_label(title).is_some(),
        "{:?}",
        h.state().lab().message()
    );
    assert!(h.query_by_label_contains("face 6 (line 15)").is_some());
    assert_eq!(h.state().selected_warning(), None);
    h.get_by_label(title).click();
    frames(&mut h, 1);
    assert_eq!(h.state().selected_warning(), Some(0));
    let overlay = Overlay::build(
        h.state().lab(),
        std::time::Instant::now(),
        Selection {
            warning: Some(0),
            part: None,
        },
    );
    let labels: Vec<&str> = overlay.labels.iter().map(|l| l.text.as_str()).collect();
    assert!(labels.contains(&"face 6"), "{labels:?}");
    // The top face's four sides, at z = 1 of the unit cube (placed about its centre of mass).
    let none = Overlay::build(
        h.state().lab(),
        std::time::Instant::now(),
        Selection::default(),
    );
    assert_eq!(overlay.segments.len(), none.segments.len() + 4);
    h.get_by_label(title).click();
    frames(&mut h, 1);
    assert_eq!(h.state().selected_warning(), None);
    std::fs::remove_dir_all(&dir).ok();
}

/// A body made of parts from the samples: selecting a part opens its editor, and making the
/// steel head a 2 mm wall lightens the body mid-run with the angular momentum kept.
#[test]
fn editing_a_part_from_the_panel_keeps_the_motion() {
    let mut h = harness_of_size([1280.0, 1600.0]);
    frames(&mut h, 2);
    h.get_by_label("Hammer: steel & wood").click();
    frames(&mut h, 5);
    let lab = h.state().lab();
    let parts = lab.primary().body().composition.as_ref().expect("parts");
    assert_eq!(parts.parts.len(), 2);
    let before = lab.primary().properties(InertiaSource::Exact).mass;
    h.get_by_label("head").click();
    frames(&mut h, 1);
    assert!(h.query_by_label("Part “head”").is_some());
    h.get_all_by_label("Pause").next().expect("button").click();
    frames(&mut h, 1);
    let l = h.state().lab().primary().sim().body().angular_momentum();
    h.get_by_label("Thin wall").click();
    frames(&mut h, 2);
    let lab = h.state().lab();
    assert!(
        lab.message().is_none_or(|m| !m.error),
        "{:?}",
        lab.message()
    );
    let parts = lab.primary().body().composition.as_ref().expect("parts");
    assert_eq!(parts.parts[0].entry.thin_wall, Some(0.002));
    let after = lab.primary().properties(InertiaSource::Exact).mass;
    // The head: 0.12 × 0.03 × 0.03 m of steel, now 2 mm walls on its 0.0162 m² of surface.
    let head_solid = 7850.0 * 0.12 * 0.03 * 0.03;
    let head_wall = 7850.0 * 0.002 * 2.0 * (0.12 * 0.03 * 2.0 + 0.03 * 0.03);
    assert!(
        ((before - after) - (head_solid - head_wall)).abs() < 1e-12,
        "{before} → {after}"
    );
    let b = lab.primary().sim().body();
    assert!((b.angular_momentum() - l).norm() <= 1e-12 * l.norm());
}

/// The Compare section starts copies from the same start, shows their drift, and stops them.
#[test]
fn compare_from_the_panel() {
    let mut h = harness_of_size([1280.0, 1400.0]);
    frames(&mut h, 2);
    h.get_by_label("Compare").click();
    frames(&mut h, 2);
    h.get_by_label("textbook model (no ω × Iω)").click();
    frames(&mut h, 1);
    h.get_by_label("Compare 2 from the start").click();
    frames(&mut h, 5);
    let lab = h.state().lab();
    let variants: Vec<_> = lab.specimens().iter().map(|s| s.variant()).collect();
    assert_eq!(
        variants,
        [
            Variant::Same,
            Variant::Source(InertiaSource::BoundingBox),
            Variant::Model(RotationModel::Textbook)
        ]
    );
    assert!(h.query_by_label_contains("max ΔE/E").is_some());
    // The body's predicted turn-over interval is in its row (the default spin, axis 2).
    let turns = lab
        .primary()
        .turn_over_interval()
        .expect("axis 2 turns over");
    assert!(h.query_by_label(&format!("{turns:.3} s")).is_some());
    // The table names each copy by what it changes (the checkbox says "textbook model" too).
    assert_eq!(h.query_all_by_label_contains("textbook model").count(), 2);
    // The checkbox and the table's row.
    assert_eq!(h.query_all_by_label("bounding box inertia").count(), 2);
    h.get_by_label("Stop comparing").click();
    frames(&mut h, 2);
    assert_eq!(h.state().lab().specimens().len(), 1);
}

/// Every non-ASCII character the app's code writes (outside comments) has a glyph in the app's
/// fonts, egui's defaults: one without shows as an empty box (a regression: "⚠" and "⟂" did).
#[test]
fn every_symbol_the_gui_writes_has_a_glyph() {
    let ctx = egui::Context::default();
    // One pass loads the fonts; its texture upload is not needed here.
    ctx.run_ui(egui::RawInput::default(), |_| {})
        .textures_delta
        .clear();
    let src = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    // The built-in lessons' text, in every language, and the message files are drawn by the
    // same fonts.
    let lessons = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../lessons");
    let messages = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("messages");
    let mut dirs = vec![src.join("gui"), src.join("lab"), lessons, messages];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).expect("source folder") {
            let path = entry.expect("entry").path();
            if path.is_dir() {
                dirs.push(path);
            } else if path
                .extension()
                .is_some_and(|e| e == "rs" || e == "toml" || e == "ftl")
            {
                files.push(path);
            }
        }
    }
    assert!(files.len() > 10, "{files:?}");
    let mut missing = std::collections::BTreeSet::new();
    for file in &files {
        let text = std::fs::read_to_string(file).expect("source");
        for line in text.lines().filter(|l| !l.trim_start().starts_with("//")) {
            for c in line.chars().filter(|c| !c.is_ascii()) {
                let font = egui::FontId::proportional(14.0);
                if !ctx.fonts_mut(|f| f.has_glyph(&font, c)) {
                    missing.insert((c, file.file_name().map(|n| n.to_owned())));
                }
            }
        }
    }
    assert!(missing.is_empty(), "no glyph for {missing:?}");
}

#[test]
fn a_robot_opens_from_the_path_field_and_a_link_chosen_in_its_section_spins_beside_its_stated_copy()
{
    let panda = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../tests/data/robots/franka_panda/panda.urdf");
    let mut h = harness();
    frames(&mut h, 2);
    h.get_by_label("Path").focus();
    h.get_by_label("Path")
        .type_text(&panda.display().to_string());
    frames(&mut h, 1);
    h.get_by_label("Load").click();
    for _ in 0..1000 {
        frames(&mut h, 1);
        if h.state().lab().robot().is_some() {
            break;
        }
    }
    assert!(
        h.state().lab().robot().is_some(),
        "{:?}",
        h.state().lab().message()
    );
    frames(&mut h, 2);
    assert!(
        h.query_by_label_contains("13 links, 13 with findings on their stated inertia")
            .is_some()
    );
    // The finger's row names its findings; clicking it makes it the body.
    h.get_by_label_contains("panda_leftfinger  0.1 kg").click();
    frames(&mut h, 3);
    let lab = h.state().lab();
    assert_eq!(
        lab.robot()
            .and_then(|r| r.shown)
            .map(|i| lab.robot().map(|r| r.robot.links[i].name.clone())),
        Some(Some("panda_leftfinger".to_owned()))
    );
    assert_eq!(lab.specimens().len(), 2, "the stated copy beside it");
    assert_eq!(
        lab.specimens()[1].variant(),
        Variant::Source(InertiaSource::Stated)
    );
    // The table shows the stated column, and the finding's words are on screen.
    // The table's column and the "Simulation uses" choice.
    assert_eq!(h.get_all_by_label("stated").count(), 2);
    assert!(
        h.query_by_label_contains("A proof, not an estimate")
            .is_some()
    );
}

/// The keys are the lab's whatever button has focus (Space once clicked the focused button, and
/// 1/2/3 did nothing), a number field being edited keeps them, and Escape gives them back.
#[test]
fn shortcuts_act_with_a_button_focused_and_escape_returns_the_keys() {
    let mut h = harness_of_size([1280.0, 1400.0]);
    frames(&mut h, 2);
    let spun_about = |h: &Harness<'static, LabApp>| {
        let lab = h.state().lab();
        let w = lab.primary().history().samples()[0].omega_principal;
        let rate = lab.settings().body.spin_rate;
        (0..3).find(|&k| (w[k] - rate).abs() < 1e-9 * rate)
    };
    h.get_by_label("Spin axis 3").focus();
    frames(&mut h, 2);
    assert!(
        h.ctx.memory(|m| m.focused()).is_some(),
        "the button has focus"
    );
    h.key_press(egui::Key::Num1);
    frames(&mut h, 2);
    assert_eq!(spun_about(&h), Some(0), "1 spins about axis 1");
    h.key_press(egui::Key::Space);
    frames(&mut h, 2);
    assert!(h.state().lab().is_paused(), "Space pauses");
    assert_eq!(spun_about(&h), Some(0), "Space did not click Spin axis 3");
    h.key_press(egui::Key::Escape);
    frames(&mut h, 1);
    assert!(
        h.ctx.memory(|m| m.focused()).is_none(),
        "Escape frees the keys"
    );
    h.key_press(egui::Key::Space);
    frames(&mut h, 2);
    assert!(!h.state().lab().is_paused(), "Space runs again");
    // A field being edited keeps the keys.
    h.get_by_label("Size ×").focus();
    frames(&mut h, 2);
    assert!(h.ctx.text_edit_focused(), "the size field is being edited");
    h.key_press(egui::Key::Num3);
    frames(&mut h, 2);
    assert_eq!(
        spun_about(&h),
        Some(0),
        "3 went to the field, not to the spin"
    );
}

/// A widget that gets the focus (Tab) is scrolled into view: the side panel's last button, far
/// below the bottom of a 1280 × 600 window.
#[test]
fn the_focused_widget_is_scrolled_into_view() {
    let mut h = harness_of_size([1280.0, 600.0]);
    frames(&mut h, 2);
    let screen = h.ctx.content_rect();
    let before = h.get_by_label("Reset settings").rect();
    assert!(
        !screen.contains_rect(before),
        "already in view at {before:?}"
    );
    h.get_by_label("Reset settings").focus();
    frames(&mut h, 30);
    let after = h.get_by_label("Reset settings").rect();
    assert!(screen.contains_rect(after), "out of view at {after:?}");
}

/// The 3D view is named, for a screen reader, by what it shows in words (the lab's
/// description): the T-handle spinning about axis 2, and after Spin axis 3 its wobble; the name
/// changes when the motion does.
#[test]
fn the_3d_view_is_described_in_words() {
    let mut h = harness();
    h.get_by_label("Spin axis 2").click();
    frames(&mut h, 3);
    for words in [
        "The T-handle spins at",
        "mostly about axis 2",
        "Axis 2 will turn over",
    ] {
        assert!(h.query_by_label_contains(words).is_some(), "{words}");
    }
    h.get_by_label("Spin axis 3").click();
    frames(&mut h, 3);
    assert!(h.query_by_label_contains("wobbles about axis 3").is_some());
    assert!(h.query_by_label_contains("mostly about axis 2").is_none());
}

/// Export motion is reached by its name: its file field (named by the button), the seconds and
/// the keyframes a second; the button writes the file with that many keyframes.
#[test]
fn export_motion_is_named_and_writes_the_file() {
    let mut h = harness();
    let path = std::env::temp_dir().join(format!("inertia-lab-ui-{}.usda", std::process::id()));
    h.get_by_role_and_label(egui::accesskit::Role::TextInput, "Export motion")
        .focus();
    frames(&mut h, 1);
    // The field holds motion.glb: selected whole, then typed over.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    frames(&mut h, 1);
    h.get_by_role_and_label(egui::accesskit::Role::TextInput, "Export motion")
        .type_text(&path.display().to_string());
    frames(&mut h, 1);
    assert!(h.query_by_label("Seconds baked").is_some());
    assert!(h.query_by_label("Keyframes a second").is_some());
    h.get_by_role_and_label(egui::accesskit::Role::Button, "Export motion")
        .click();
    frames(&mut h, 2);
    let text = std::fs::read_to_string(&path).expect("written");
    std::fs::remove_file(&path).ok();
    // 10 s at 30 fps, the defaults beside the button.
    assert!(
        text.contains("endTimeCode = 300"),
        "{}",
        &text[..400.min(text.len())]
    );
}

/// Lesson 1 by the panel's widgets, found by role and name as a screen reader finds them: the
/// Lessons button, the lesson, the prediction's choice and its commit, the inertia source, Next.
#[test]
fn lesson_1_is_completed_from_the_lessons_panel() {
    use egui::accesskit::Role;
    let mut h = harness();
    frames(&mut h, 1);
    h.get_by_role_and_label(Role::Button, "Lessons").click();
    frames(&mut h, 2);
    h.get_by_label_contains("1. What the inertia tensor is")
        .click();
    frames(&mut h, 2);
    assert_eq!(h.state().lab().primary().body().name, "L-bracket");
    assert!(h.query_by_label_contains("Step 1 of 2").is_some());
    h.get_by_role_and_label(Role::RadioButton, "larger than the exact ones")
        .click();
    frames(&mut h, 1);
    h.get_by_role_and_label(Role::Button, "Commit to my prediction")
        .click();
    frames(&mut h, 2);
    h.get_by_role_and_label(Role::RadioButton, "bounding box")
        .click();
    frames(&mut h, 2);
    assert!(
        h.query_by_label_contains("Your prediction was right")
            .is_some()
    );
    h.get_by_role_and_label(Role::Button, "Next step").click();
    frames(&mut h, 2);
    h.get_by_role_and_label(Role::RadioButton, "exact").click();
    frames(&mut h, 2);
    assert!(h.query_by_label_contains("Lesson done").is_some());
    let run = h.state().lab().lesson().expect("open");
    assert_eq!(run.progress(), "done");
}

/// The Language menu turns the whole window German at once: the top bar, the side panel, the
/// live description of the 3D view (with a decimal comma), and back to English.
#[test]
fn the_language_menu_changes_every_word_and_the_decimal_separator() {
    use egui::accesskit::Role;
    use egui_kittest::kittest::NodeT;
    let mut h = harness();
    frames(&mut h, 2);
    h.get_by_role_and_label(Role::ComboBox, "Language").click();
    frames(&mut h, 2);
    h.get_by_label("Deutsch").click();
    frames(&mut h, 3);
    assert_eq!(
        h.state().lab().settings().display.language,
        Some(Language::German)
    );
    h.get_by_role_and_label(Role::Button, "Hilfe");
    h.get_by_role_and_label(Role::Button, "Lektionen");
    assert!(
        h.query_by_label("Help").is_none(),
        "English left in the top bar"
    );
    let described = h
        .query_by_label_contains("dreht sich mit")
        .expect("the 3D view described in German");
    let text = described.accesskit_node().label().unwrap_or_default();
    // The rate, to two significant digits, in the word before its unit: "8,0 rad/s".
    let rate = text
        .split_whitespace()
        .take_while(|w| *w != "rad/s")
        .last()
        .unwrap_or_default();
    assert!(
        rate.contains(',')
            && rate
                .trim_matches(|c: char| c.is_ascii_digit() || c == ',')
                .is_empty(),
        "the rate {rate:?} is not written with a decimal comma: {text}"
    );
    h.get_by_role_and_label(Role::ComboBox, "Sprache").click();
    frames(&mut h, 2);
    h.get_by_label("English").click();
    frames(&mut h, 3);
    h.get_by_role_and_label(Role::Button, "Help");
}

/// Every control of every panel has a name a screen reader says (its own text, or the label it
/// is tied to): each side-panel section opened, on a body of parts, with the lessons and the F1
/// help shown beside the toolbar, the plots and the sphere.
#[test]
fn every_control_in_every_panel_has_a_name() {
    use egui::accesskit::Role;
    use egui_kittest::kittest::{By, NodeT};
    const CONTROLS: [Role; 8] = [
        Role::Button,
        Role::CheckBox,
        Role::RadioButton,
        Role::ComboBox,
        Role::SpinButton,
        Role::Slider,
        Role::TextInput,
        Role::Link,
    ];
    let mut h = harness();
    frames(&mut h, 2);
    h.get_by_label("Hammer: steel & wood").click();
    frames(&mut h, 3);
    h.get_by_role_and_label(Role::Button, "Lessons").click();
    h.key_press(egui::Key::F1);
    frames(&mut h, 2);
    // Open every closed section, until none is left (a section may hold another).
    for _ in 0..5 {
        let closed: Vec<String> = h
            .query_all(By::new().predicate(|n| n.data().is_expanded() == Some(false)))
            .filter_map(|n| n.accesskit_node().label())
            .collect();
        if closed.is_empty() {
            break;
        }
        for label in closed {
            if let Some(node) = h.query_by_label(&label) {
                node.click();
            }
            frames(&mut h, 1);
        }
        frames(&mut h, 2);
    }
    let mut named = 0;
    let mut unnamed = Vec::new();
    for node in h.query_all(By::new().predicate(|n| CONTROLS.contains(&n.role()))) {
        let n = node.accesskit_node();
        match n.label() {
            Some(label) if !label.trim().is_empty() => named += 1,
            _ => unnamed.push(format!("{:?} (value {:?})", n.role(), n.value())),
        }
    }
    assert!(
        named > 80,
        "only {named} named controls: the panels were not all shown"
    );
    assert!(unnamed.is_empty(), "controls without a name: {unnamed:?}");
}
