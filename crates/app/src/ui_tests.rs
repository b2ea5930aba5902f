//! UI tests with egui_kittest: the panels drive the model through the real widgets (found by
//! their labels, as a screen reader would). No GL context here, so the 3D view shows its
//! placeholder; the app repaints continuously while running, so the tests step frames explicitly.

use std::time::Duration;

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

use crate::gui::LabApp;
use crate::settings::{AppSettings, InertiaSource};

fn harness() -> Harness<'static, LabApp> {
    let app = LabApp::new(AppSettings::default(), None, &egui::Context::default()).expect("app");
    Harness::builder()
        .with_size([1280.0, 800.0])
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
    assert!(h.state().lab().sim().steps() > 0, "runs from the start");
    h.get_all_by_label("Pause").next().expect("button").click();
    frames(&mut h, 2);
    assert!(h.state().lab().sim().is_paused());
    let steps = h.state().lab().sim().steps();
    frames(&mut h, 5);
    assert_eq!(
        h.state().lab().sim().steps(),
        steps,
        "no steps while paused"
    );
    h.get_by_label("Step").click();
    frames(&mut h, 1);
    assert_eq!(h.state().lab().sim().steps(), steps + 1);
    h.key_press(egui::Key::Space);
    frames(&mut h, 5);
    assert!(!h.state().lab().sim().is_paused());
    assert!(h.state().lab().sim().steps() > steps + 1);
}

#[test]
fn switching_the_inertia_source_mid_run_keeps_angular_momentum() {
    let mut h = harness();
    frames(&mut h, 5);
    h.get_all_by_label("Pause").next().expect("button").click();
    frames(&mut h, 1);
    let l = h.state().lab().sim().body().angular_momentum();
    h.get_by_label("bounding box").click();
    frames(&mut h, 2);
    let lab = h.state().lab();
    assert_eq!(lab.settings.body.source, InertiaSource::BoundingBox);
    let bbox = lab.properties(InertiaSource::BoundingBox).principal.moments;
    let used = lab.sim().body().moments();
    assert!(
        (used - bbox).norm() <= 1e-12 * bbox.norm(),
        "{used} vs {bbox}"
    );
    assert!((lab.sim().body().angular_momentum() - l).norm() <= 1e-12 * l.norm());
    // "exact" also heads the table column: the radio button is the last one.
    h.get_all_by_label("exact").last().expect("radio").click();
    frames(&mut h, 2);
    let lab = h.state().lab();
    let exact = lab.properties(InertiaSource::Exact).principal.moments;
    assert!((lab.sim().body().moments() - exact).norm() <= 1e-12 * exact.norm());
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
    assert_eq!(lab.body().name, "T-handle");
    assert!(!lab.sim().is_paused(), "the old body keeps running");
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
    assert_eq!(h.state().lab().body().name, "Book");
    h.key_press(egui::Key::F1);
    frames(&mut h, 2);
    assert!(h.query_by_label_contains("Dzhanibekov").is_some());
}
