//! The lab in a browser: `web/build.sh` builds the site (Debian's wasm32 toolchain and
//! wasm-bindgen), this test serves it on 127.0.0.1 and drives headless Chromium through
//! puppeteer-core (`tests/web/drive.mjs`, which reports what it saw as JSON). It checks that the
//! page runs with no console error; draws the body and the plots (pixels of a screenshot, saved
//! as `target/web-test/page-*.png` for a person to look at); keeps |L| while nothing acts and
//! changes it with a click or a tap on the body; opens the scene a link names; loads a mesh
//! through the file picker and a body file with its meshes dropped on the page, each with the
//! mass `props` computes for the same files; loads a big mesh in the page's worker while the page
//! goes on drawing (frames recorded in the page, `tests/web/busy.mjs`); names the body in the
//! page's title; and says what the canvas shows in a live region that Chromium's accessibility
//! tree holds.
//!
//! Without Chromium, Node.js, the web toolchain or the npm registry it prints a SKIPPED line (a
//! failure under `CI`; `.ci/run` installs them all).

mod common;
#[path = "common/image.rs"]
mod image;

use std::io::{BufRead, BufReader, Write};
use std::net::{TcpListener, TcpStream};
use std::path::{Path, PathBuf};
use std::process::Command;

use common::{PUPPETEER, on_path, root, skip};
use image::{Image, body_pixel, green_line};

const TEST: &str = "web_page_runs_the_lab";

#[test]
fn web_page_runs_the_lab() {
    let chromium = Path::new("/usr/bin/chromium");
    if !chromium.is_file() {
        skip(
            TEST,
            "Chromium is not installed",
            "apt-get install chromium",
        );
        return;
    }
    if !on_path("node") || !on_path("npm") {
        skip(
            TEST,
            "Node.js is not installed",
            "apt-get install nodejs npm",
        );
        return;
    }
    let build = root().join("web/build.sh");
    let check = Command::new(&build)
        .arg("--check")
        .output()
        .expect("web/build.sh runs");
    if check.status.code() == Some(3) {
        let said = String::from_utf8_lossy(&check.stderr);
        let mut lines = said.lines().map(|l| l.trim_start_matches("web/build.sh: "));
        let missing = lines.next().unwrap_or("the web toolchain");
        let install = lines.next().unwrap_or("see README");
        skip(TEST, missing, install);
        return;
    }
    let work = root().join("target/web-test");
    let site = work.join("site");
    std::fs::create_dir_all(&work).expect("target/web-test");
    // A recording downloaded by an earlier run must not pass for this run's.
    for old in std::fs::read_dir(&work).expect("target/web-test").flatten() {
        let name = old.file_name().to_string_lossy().into_owned();
        if name.starts_with("inertia-lab-recording-") {
            std::fs::remove_file(old.path()).expect("old recording removed");
        }
    }
    let built = Command::new(&build)
        .arg(&site)
        // The test process's library path (the test toolchain's) is not the web compiler's.
        .env_remove("LD_LIBRARY_PATH")
        .output()
        .expect("web/build.sh runs");
    assert!(
        built.status.success(),
        "web/build.sh failed:\n{}",
        String::from_utf8_lossy(&built.stderr)
    );
    let driver = work.join("driver");
    if !driver.join("node_modules/puppeteer-core").is_dir() {
        let npm = Command::new("npm")
            .args(["install", "--no-audit", "--no-fund", "--prefix"])
            .arg(&driver)
            .arg(PUPPETEER)
            .output()
            .expect("npm runs");
        if !npm.status.success() {
            skip(
                TEST,
                &format!(
                    "npm could not install {PUPPETEER}: {}",
                    String::from_utf8_lossy(&npm.stderr).trim()
                ),
                "network access to the npm registry",
            );
            return;
        }
    }
    // Beside its node_modules: an ES module finds its imports from its own folder.
    for file in ["drive.mjs", "busy.mjs"] {
        std::fs::copy(root().join("tests/web").join(file), driver.join(file))
            .unwrap_or_else(|e| panic!("tests/web/{file} copied: {e}"));
    }
    let script = driver.join("drive.mjs");
    let base = serve(site.clone());
    let picked = root().join("assets/l_bracket.obj");
    let dropped = [
        root().join("assets/hammer.toml"),
        root().join("assets/hammer.obj"),
    ];
    let gltf = write_box_gltf(&work);
    // A teacher's lesson file beside the page, which a link names by its address.
    std::fs::write(site.join("class.lesson.toml"), CLASS_LESSON).expect("class.lesson.toml");
    // The site as one HTML file that runs from the disk (web/build.sh --single-file's last step).
    let single = work.join("inertia-lab.html");
    let made = Command::new("python3")
        .arg(root().join("web/single_file.py"))
        .arg(&site)
        .arg(&single)
        .output()
        .expect("python3 runs");
    assert!(
        made.status.success(),
        "web/single_file.py failed:\n{}",
        String::from_utf8_lossy(&made.stderr)
    );
    let driven = Command::new("node")
        .env("SINGLE_FILE", &single)
        .env(
            "DROP_GLTF",
            format!("{}:{}", work.join("box.bin").display(), gltf.display()),
        )
        .arg(&script)
        .arg(&base)
        .arg(&work)
        .arg(&picked)
        .args(&dropped)
        .current_dir(&driver)
        .output()
        .expect("node runs");
    assert!(
        driven.status.success(),
        "the browser driver failed:\n{}",
        String::from_utf8_lossy(&driven.stderr)
    );
    // Kept for a person to read when an assertion below fails.
    std::fs::write(work.join("seen.json"), &driven.stdout).expect("seen.json");
    let seen: serde_json::Value =
        serde_json::from_slice(&driven.stdout).expect("the driver prints JSON");
    let s = &seen["scenarios"];

    assert_eq!(
        seen["failures"],
        serde_json::json!([]),
        "scenarios that failed"
    );
    assert_eq!(seen["errors"], serde_json::json!([]), "console errors");

    // Opened: the T-handle, named in the title, moving.
    let default = &s["default"];
    assert_eq!(default["first"]["title"], "Inertia Lab — T-handle");
    assert!(number(&default["later"]["frames"]) > number(&default["first"]["frames"]) + 10.0);
    let shot = Image::read_png(&work.join("page-1280x800.png"));
    let [left, top, width, height] = view(&default["later"]["view"]);
    let body = shot.count((left, left + width), (top, top + height), body_pixel);
    let plot = shot.count((left, shot.width), (top + height, shot.height), green_line);
    assert!(body > 2000, "the 3D view shows no body ({body} pixels)");
    assert!(plot > 100, "the plots show no lines ({plot} pixels)");
    // The live region says what the canvas shows, and the accessibility tree holds it.
    let live = default["live"].as_str().unwrap_or_default();
    assert!(
        live.starts_with("The T-handle spins at") && live.contains("mostly about axis"),
        "the live region: {live:?}"
    );
    assert!(
        default["described"].as_u64().unwrap_or(0) >= 1,
        "the accessibility tree lacks the description {live:?}"
    );

    // Torque-free, |L| is constant; a click (a tap on a touch screen) on the body pokes it.
    for name in ["poke", "tap"] {
        let p = &s[name];
        let (before, still, after) = (
            number(&p["before"]["momentum"]),
            number(&p["still"]["momentum"]),
            number(&p["after"]["momentum"]),
        );
        assert!(
            (still - before).abs() <= 1e-9 * before,
            "{name}: |L| drifted from {before} to {still} with nothing acting"
        );
        // A poke changes |L| by ΔL·L̂ + |ΔL⊥|²/2|L| (ΔL = r × J, about 0.2 % of |L| here): at
        // least second order, some 1e-6, even with ΔL across L; nothing else changes it.
        assert!(
            (after - still).abs() > 1e-7 * still,
            "{name}: |L| {still} → {after}: the {name} at {} did not poke the body",
            p["at"]
        );
    }

    // A link names the scene; a bad one is said in the page, and the rest runs.
    assert_eq!(s["link"]["title"], "Inertia Lab — Tennis racket");
    assert_eq!(s["link"]["specimens"], "2");
    assert_eq!(s["bad_link"]["title"], "Inertia Lab — T-handle");

    // No dead link: every address the page names answers (the project's home is linked only
    // when the build is given one).
    let links = s["links"].as_array().expect("the page's links");
    assert!(!links.is_empty(), "the page names no address at all");
    let dead: Vec<_> = links.iter().filter(|l| l["ok"] != true).collect();
    assert!(dead.is_empty(), "dead links in the page: {dead:?}");

    // Files in: the same mass as props at the app's default density (water, 1000 kg/m³).
    for (name, file) in [("picker", &picked), ("drop", &dropped[0])] {
        let shown = number(&s[name]["mass"]);
        let props = props_mass(file);
        assert!(
            (shown - props).abs() <= 1e-12 * props,
            "{name}: the page shows {shown} kg, props {props} kg"
        );
    }
    // A .gltf dropped with its .bin (the .bin first): the 2 × 3 × 4 box its node scales the
    // unit cube to, of water, as props reads it from the disk.
    let shown = number(&s["drop_gltf"]["mass"]);
    assert!(
        (shown - 24_000.0).abs() <= 1e-9 * 24_000.0 && (shown - props_mass(&gltf)).abs() <= 1e-9,
        "drop_gltf: the page shows {shown} kg, props {} kg, the box 24000 kg",
        props_mass(&gltf)
    );
    check_busy_page(&s["busy"], 0.0);
    // Dropped on a body of parts it joins it: the hammer's volume and the sphere's.
    check_busy_page(&s["busy_part"], number(&s["busy_part"]["before"]["volume"]));
    check_recording(&s["record"]);
    check_restarts(&s["restarts"]);
    check_keyboard_lesson(&s["keyboard_lesson"]);
    // ?lesson=ADDRESS&step=2: the file fetched and opened at its second step.
    let fetched = &s["fetched_lesson"];
    assert_eq!(fetched["lesson"], "class", "the fetched lesson: {fetched}");
    assert!(
        fetched["lessonStep"] == "2/2" || fetched["lessonStep"] == "done",
        "the fetched lesson's step: {fetched}"
    );
    // The single file runs from the disk, and a file dropped on it loads in its worker with the
    // mass props computes.
    let single = &s["single_file"];
    assert_eq!(
        single["first"]["title"], "Inertia Lab — T-handle",
        "single file: {single}"
    );
    let shown = number(&single["dropped"]["mass"]);
    let props = props_mass(&picked);
    assert!(
        (shown - props).abs() <= 1e-12 * props,
        "single file: the dropped mesh shows {shown} kg, props {props} kg"
    );
    for (lang, spins) in [("de", "dreht sich"), ("es", "gira")] {
        let page = &s[format!("lang_{lang}")];
        assert_eq!(page["figures"]["lang"], lang, "?lang={lang}: data-lang");
        assert_eq!(page["documentLang"], lang, "?lang={lang}: <html lang>");
        let live = page["live"].as_str().unwrap_or_default();
        assert!(
            live.contains(spins) && live.contains("rad/s") && !live.contains("spins at"),
            "?lang={lang}: the live description is not in that language: {live:?}"
        );
        // Rates to two significant digits, with the language's decimal comma ("6,2 rad/s").
        let rate = live
            .split_whitespace()
            .take_while(|w| *w != "rad/s")
            .last()
            .unwrap_or_default();
        assert!(
            rate.contains(',') && !rate.contains('.'),
            "?lang={lang}: the rate {rate:?} has no decimal comma: {live:?}"
        );
    }
}

/// A lesson of a teacher's own, put beside the page.
const CLASS_LESSON: &str = r#"
id = "class"
title = "A class's own lesson"
goal = "Open a lesson from the page's address."

[[step]]
text = "Spin the body about axis 3."
check = [{ kind = "spin_axis", axis = 3 }]
explain = "It spins about axis 3."

[[step]]
text = "Watch it for a second."
check = [{ kind = "elapsed", seconds = 1.0 }]
explain = "A second passed."
"#;

/// Lesson 1 done by the keyboard alone: each widget reached by Tab and pressed by Enter, the
/// lesson open from the first, and its last step done.
fn check_keyboard_lesson(run: &serde_json::Value) {
    let steps = run["steps"]
        .as_array()
        .expect("the keyboard lesson's steps");
    assert_eq!(steps.len(), 6, "keyboard lesson: {run}");
    assert_eq!(
        steps[0]["lesson"], "tensor",
        "Enter on lesson 1 opened it: {run}"
    );
    assert_eq!(steps[0]["title"], "Inertia Lab — L-bracket", "{run}");
    assert_eq!(steps[2]["step"], "1/2", "{run}");
    assert_eq!(steps[4]["step"], "2/2", "Next step went on: {run}");
    assert_eq!(run["end"]["lessonStep"], "done", "lesson 1 not done: {run}");
    let live = run["live"].as_str().unwrap_or_default();
    assert!(
        live.contains("Lesson: What the inertia tensor is"),
        "{live:?}"
    );
}

/// Fifty restarts, by keys and buttons, with the view or a widget holding the keys: each starts
/// the clock again, which then runs past half a second with no further input, and the body turns
/// in the model and on the screen.
fn check_restarts(runs: &serde_json::Value) {
    let runs = runs.as_array().expect("the restarts");
    assert_eq!(runs.len(), 50, "restarts");
    for run in runs {
        assert!(run["restarted"] == true, "did not restart: {run}");
        let end = run["end"].as_f64().expect("end");
        let turned = run["turned"].as_f64().expect("turned");
        assert!(
            end >= 0.5 && turned > 1e-3 && run["redrawn"] == true,
            "the clock, the body or the picture stood still after the restart: {run}"
        );
    }
}

/// Record in the page downloads one ZIP archive that Python's zipfile reads intact: five seconds
/// of pictures, numbered in order, each a PNG of the page (1280 × 800), the body on the first.
fn check_recording(record: &serde_json::Value) {
    let archive = record["archive"].as_str().expect("the archive's path");
    let first = Path::new(archive).with_extension("png");
    let script = "import sys, zipfile\n\
        z = zipfile.ZipFile(sys.argv[1])\n\
        assert z.testzip() is None\n\
        names = z.namelist()\n\
        open(sys.argv[2], 'wb').write(z.read(names[0]))\n\
        print(len(names), names[0], names[-1])\n";
    let out = Command::new("python3")
        .args(["-c", script, archive])
        .arg(&first)
        .output()
        .expect("python3 runs");
    assert!(
        out.status.success(),
        "{archive}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let listing = String::from_utf8_lossy(&out.stdout);
    let words: Vec<&str> = listing.split_whitespace().collect();
    let count: usize = words[0].parse().expect("a count");
    // As many as the frames allowed (a picture is taken with a frame): some 35 of the 50 asked
    // for under SwiftShader here.
    assert!(
        count >= 10 && words[1] == "frame-0001.png" && words[2] == format!("frame-{count:04}.png"),
        "{archive}: {listing}"
    );
    let picture = Image::read_png(&first);
    assert_eq!((picture.width, picture.height), (1280, 800), "{archive}");
    let body = picture.count((0, 1280), (0, 800), body_pixel);
    assert!(
        body > 500,
        "{archive}: the body is not in the first picture"
    );
}

/// A big mesh loads in the page's worker: the page draws on while the worker checks the mesh and
/// builds its picking index, says the stage, and then shows the volume the divergence theorem
/// gives the same file.
///
/// What is asserted holds however busy the machine is: frames drawn while the page says the
/// worker is at work. A load on the page's own thread draws no frame until it is over, so none
/// of its frames can show those stages. How long the page paused, and how many frames it drew,
/// depend on the machine: `bench/web.mjs` measures them.
///
/// `base`: the volume of the body the sphere joins as a part (0 when it opens as the body).
fn check_busy_page(busy: &serde_json::Value, base: f64) {
    let worker_frames = busy["worker_frames"].as_u64().expect("worker_frames");
    assert!(
        worker_frames >= 2,
        "the page drew {worker_frames} frames while the worker checked the mesh and built its \
         picking index (a load on the page's thread draws none); seen: {busy}"
    );
    let stages = busy["stages"].as_array().expect("stages");
    assert!(
        stages
            .iter()
            .any(|s| s == "checking the mesh and its mass properties"),
        "stages seen: {stages:?}"
    );
    let (shown, exact) = (
        number(&busy["shown"]["volume"]),
        base + busy["volume"].as_f64().expect("volume"),
    );
    assert!(
        (shown - exact).abs() <= 1e-9 * exact,
        "sphere.stl on a body of volume {base}: the page shows a volume of {shown}, expected \
         {exact}"
    );
}

/// A figure the page published (a number in a data-* attribute).
fn number(v: &serde_json::Value) -> f64 {
    v.as_str()
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| panic!("a number, got {v}"))
}

/// The 3D view's rectangle in CSS pixels, as the page publishes it.
fn view(v: &serde_json::Value) -> [usize; 4] {
    let numbers: Vec<usize> = v
        .as_str()
        .expect("data-view")
        .split(' ')
        .map(|t| t.parse::<f64>().expect("a number").round() as usize)
        .collect();
    [numbers[0], numbers[1], numbers[2], numbers[3]]
}

/// `props --json FILE`'s mass, at the app's density for a mesh (a body file gives its own).
/// Writes `box.gltf` and the `box.bin` it names into `dir`: the unit cube centred on the origin,
/// scaled 2 × 3 × 4 by its node. Returns the `.gltf`'s path.
fn write_box_gltf(dir: &Path) -> PathBuf {
    let corners: Vec<u8> = (0..8)
        .flat_map(|i| [0, 1, 2].map(|a| ((i >> a) & 1) as f32 - 0.5))
        .flat_map(f32::to_le_bytes)
        .collect();
    let triangles: [u16; 36] = [
        0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2,
        1, 3, 7, 1, 7, 5,
    ];
    let mut bin = corners;
    bin.extend(triangles.iter().flat_map(|i| i.to_le_bytes()));
    std::fs::write(dir.join("box.bin"), &bin).expect("box.bin");
    let json = serde_json::json!({
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "scale": [2.0, 3.0, 4.0]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3",
             "min": [-0.5, -0.5, -0.5], "max": [0.5, 0.5, 0.5]},
            {"bufferView": 1, "componentType": 5123, "count": 36, "type": "SCALAR"}],
        "bufferViews": [{"buffer": 0, "byteLength": 96},
                        {"buffer": 0, "byteOffset": 96, "byteLength": 72}],
        "buffers": [{"byteLength": 168, "uri": "box.bin"}]
    });
    let path = dir.join("box.gltf");
    std::fs::write(&path, json.to_string()).expect("box.gltf");
    path
}

fn props_mass(file: &Path) -> f64 {
    let mut args = vec!["props", "--json", file.to_str().expect("utf-8")];
    if file.extension().is_some_and(|e| e != "toml") {
        args.extend(["--density", "1000"]);
    }
    let out = common::run(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    json["mass"].as_f64().expect("mass")
}

/// Serves the files of `site` on 127.0.0.1 (a port of its own) until the test process ends;
/// returns the base address.
fn serve(site: PathBuf) -> String {
    let listener = TcpListener::bind("127.0.0.1:0").expect("a port on 127.0.0.1");
    let base = format!("http://{}", listener.local_addr().expect("address"));
    std::thread::spawn(move || {
        for stream in listener.incoming().flatten() {
            let site = site.clone();
            std::thread::spawn(move || answer(stream, &site));
        }
    });
    base
}

/// Answers one GET request with a file of `site` (404 for anything else).
fn answer(mut stream: TcpStream, site: &Path) {
    let mut request = String::new();
    let mut reader = BufReader::new(&stream);
    if reader.read_line(&mut request).is_err() {
        return;
    }
    // The headers, up to the empty line.
    let mut line = String::new();
    while reader.read_line(&mut line).is_ok_and(|n| n > 2) {
        line.clear();
    }
    let target = request.split_whitespace().nth(1).unwrap_or("/");
    let path = target.split('?').next().unwrap_or("/");
    let name = if path == "/" {
        "index.html"
    } else {
        path.trim_start_matches('/')
    };
    let file = (!name.contains("..")).then(|| site.join(name));
    let (status, kind, body) = match file.and_then(|f| std::fs::read(&f).ok().map(|b| (f, b))) {
        Some((f, bytes)) => {
            let kind = match f.extension().and_then(|e| e.to_str()) {
                Some("html") => "text/html; charset=utf-8",
                Some("js") => "text/javascript",
                Some("wasm") => "application/wasm",
                _ => "application/octet-stream",
            };
            ("200 OK", kind, bytes)
        }
        None => ("404 Not Found", "text/plain", b"not found".to_vec()),
    };
    let head = format!(
        "HTTP/1.1 {status}\r\nContent-Type: {kind}\r\nContent-Length: {}\r\nConnection: close\r\n\r\n",
        body.len()
    );
    let _ = stream.write_all(head.as_bytes());
    let _ = stream.write_all(&body);
}
