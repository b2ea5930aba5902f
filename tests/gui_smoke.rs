//! Smoke test of the real `inertia-lab` window under Xvfb: it starts with a mesh argument that
//! cannot be loaded, keeps the default T-handle, keeps running, and a screenshot of the screen
//! shows the shaded body in the 3D view and the plot lines (saved as
//! `target/gui-smoke.png` for a human to look at).
//!
//! Needs `Xvfb`, ImageMagick's `import` and the X11/GL runtime libraries (`.ci/run` installs
//! them); without Xvfb or `import` it prints a SKIPPED line (a failure under `CI`).

mod common;
#[path = "common/image.rs"]
mod image;

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use common::{on_path, skip};
use image::{Image, body_pixel, green_line};

/// Kills a child process when dropped, so a failing assertion leaves nothing behind.
struct Guard(Child);

impl Drop for Guard {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// Starts Xvfb on a display it picks itself and waits until it serves. With `-displayfd 1` the
/// server takes a free display under its own lock files (the five tests of this file start
/// servers at once) and writes the display's number to its standard output once it accepts
/// connections. Guessing a number and waiting for its socket file once waited 90 s in CI beside a
/// running server whose socket file never appeared.
fn start_xvfb(test: &str) -> (Guard, String) {
    let log = std::env::temp_dir().join(format!(
        "inertia-lab-xvfb-{test}-{}.log",
        std::process::id()
    ));
    let mut xvfb = Command::new("Xvfb")
        .args([
            "-displayfd",
            "1",
            "-screen",
            "0",
            "1280x800x24",
            "-nolisten",
            "tcp",
        ])
        .stdout(Stdio::piped())
        .stderr(std::fs::File::create(&log).expect("Xvfb's log file"))
        .spawn()
        .expect("start Xvfb");
    let stdout = xvfb.stdout.take().expect("Xvfb's standard output");
    let guard = Guard(xvfb);
    let (sender, receiver) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let mut line = String::new();
        let _ = BufReader::new(stdout).read_line(&mut line);
        let _ = sender.send(line);
    });
    // Generous: five servers and apps start at once on two cores shared with the rest of the run.
    let answer = receiver.recv_timeout(Duration::from_secs(90));
    let said = || std::fs::read_to_string(&log).unwrap_or_default();
    let display = match answer {
        Ok(line) => match line.trim().parse::<u32>() {
            Ok(number) => format!(":{number}"),
            Err(_) => panic!("Xvfb exited before serving a display; it said:\n{}", said()),
        },
        Err(_) => panic!(
            "Xvfb did not serve a display within 90 s; it said:\n{}",
            said()
        ),
    };
    std::fs::remove_file(&log).ok();
    (guard, display)
}

/// `--screenshot OUT.png --after S` writes the app's own pixels (the 3D view included) after S
/// simulated seconds and exits 0.
#[test]
fn screenshot_writes_the_apps_own_pixels_and_exits() {
    if !on_path("Xvfb") {
        skip(
            "screenshot_writes_the_apps_own_pixels_and_exits",
            "Xvfb is not installed",
            "apt-get install xvfb libx11-6 libxcursor1 libx11-xcb1 libxi6 libxkbcommon-x11-0 \
             libgl1",
        );
        return;
    }
    let (_xvfb, display) = start_xvfb("screenshot");
    let home = std::env::temp_dir().join(format!("inertia-lab-shot-{}", std::process::id()));
    std::fs::create_dir_all(&home).expect("temp home");
    let png = home.join("shot.png");
    let out = Command::new(env!("CARGO_BIN_EXE_inertia-lab"))
        .args(["--after", "3", "--screenshot"])
        .arg(&png)
        .env("DISPLAY", &display)
        .env("HOME", &home)
        .env("XDG_DATA_HOME", &home)
        .env_remove("WAYLAND_DISPLAY")
        .output()
        .expect("inertia-lab runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let rgba = Image::read_png(&png);
    assert_eq!((rgba.width, rgba.height), (1280, 800));
    let body = rgba.count((370, 1280), (30, 580), body_pixel);
    let plot = rgba.count((370, 1280), (630, 800), green_line);
    assert!(body > 2000, "the 3D view shows no body ({body} pixels)");
    assert!(
        plot > 100,
        "the plots show no lines after 3 s ({plot} pixels)"
    );
    std::fs::remove_dir_all(&home).ok();
}

#[test]
fn window_shows_the_body_and_the_plots_and_survives_a_bad_file() {
    for program in ["Xvfb", "import"] {
        if !on_path(program) {
            skip(
                "gui_smoke",
                &format!("{program} is not installed"),
                "apt-get install xvfb imagemagick libx11-6 libxcursor1 libx11-xcb1 libxi6 \
                 libxkbcommon-x11-0 libgl1",
            );
            return;
        }
    }
    let (_xvfb, display) = start_xvfb("window");

    let home = std::env::temp_dir().join(format!("inertia-lab-smoke-{}", std::process::id()));
    std::fs::create_dir_all(&home).expect("temp home");
    let missing = home.join("no-such-mesh.obj");
    let mut app = Command::new(env!("CARGO_BIN_EXE_inertia-lab"));
    app.arg(&missing)
        .env("DISPLAY", &display)
        .env("HOME", &home)
        .env("XDG_DATA_HOME", &home)
        .env_remove("WAYLAND_DISPLAY")
        .stdout(Stdio::null())
        .stderr(Stdio::piped());
    let mut app = Guard(app.spawn().expect("start inertia-lab"));

    let target = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../target");
    let ppm = home.join("shot.ppm");
    let start = Instant::now();
    let (mut body, mut plot) = (0, 0);
    // Debug builds under software GL need a few seconds for the first frames; then the plots
    // need simulated time to draw lines.
    while start.elapsed() < Duration::from_secs(60) {
        std::thread::sleep(Duration::from_millis(1000));
        if let Ok(Some(status)) = app.0.try_wait() {
            let mut err = String::new();
            if let Some(mut e) = app.0.stderr.take() {
                let _ = std::io::Read::read_to_string(&mut e, &mut err);
            }
            panic!("inertia-lab exited early with {status}: {err}");
        }
        // 8 bits per channel: ImageMagick's default PPM depth follows its 16-bit quantum.
        let shot = Command::new("import")
            .args([
                "-display",
                display.as_str(),
                "-window",
                "root",
                "-depth",
                "8",
            ])
            .arg(&ppm)
            .status()
            .expect("run import");
        if !shot.success() {
            continue;
        }
        let Some(img) = Image::read_ppm(&ppm) else {
            continue;
        };
        // Layout at 1280 × 800: side panel up to x ≈ 360, 3D view above y ≈ 590, plots below.
        body = img.count((370, 1280), (30, 580), body_pixel);
        plot = img.count((370, 1280), (630, 800), green_line);
        if body > 2000 && plot > 100 && start.elapsed() > Duration::from_secs(4) {
            break;
        }
    }
    let png = target.join("gui-smoke.png");
    let _ = Command::new("import")
        .args(["-display", display.as_str(), "-window", "root"])
        .arg(&png)
        .status();
    assert!(
        body > 2000,
        "the 3D view shows no body ({body} body-coloured pixels)"
    );
    assert!(plot > 100, "the plots show no lines ({plot} line pixels)");
    assert!(
        app.0.try_wait().expect("poll").is_none(),
        "the app must keep running after a failed load"
    );
    std::fs::remove_dir_all(&home).ok();
}

/// Skips `test` (see [`skip`]) unless every program in `programs` is on `PATH`.
fn have(test: &str, programs: &[&str]) -> bool {
    for program in programs {
        if !on_path(program) {
            skip(
                test,
                &format!("{program} is not installed"),
                "apt-get install xvfb xdotool imagemagick libx11-6 libxcursor1 libx11-xcb1 \
                 libxi6 libxkbcommon-x11-0 libgl1",
            );
            return false;
        }
    }
    true
}

/// A fresh, empty folder for one test's HOME and outputs.
fn temp_home(name: &str) -> PathBuf {
    let home = std::env::temp_dir().join(format!("inertia-lab-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&home);
    std::fs::create_dir_all(&home).expect("temp home");
    home
}

/// `inertia-lab` on `display` with `home` as HOME and working folder.
fn app_command(display: &str, home: &Path) -> Command {
    let mut app = Command::new(env!("CARGO_BIN_EXE_inertia-lab"));
    app.current_dir(home)
        .env("DISPLAY", display)
        .env("HOME", home)
        .env("XDG_DATA_HOME", home)
        .env_remove("WAYLAND_DISPLAY");
    app
}

/// README: `--screenshot` exits "1 and the reason when the file does not load": a file that is
/// not a mesh, and one that does not exist, give status 1, a message naming the file, and no
/// picture (not one of the default body).
#[test]
fn screenshot_of_a_file_that_does_not_load_exits_1() {
    if !have("screenshot_of_a_file_that_does_not_load_exits_1", &["Xvfb"]) {
        return;
    }
    let (_xvfb, display) = start_xvfb("bad-file");
    let home = temp_home("shot-bad-file");
    let bad = home.join("not-a-mesh.obj");
    std::fs::write(&bad, "this is not an OBJ file\nf 1 2 9\n").expect("write");
    for (file, name) in [
        (bad, "not-a-mesh.obj"),
        (home.join("no-such-mesh.stl"), "no-such-mesh.stl"),
    ] {
        let png = home.join("shot.png");
        let out = app_command(&display, &home)
            .arg(&file)
            .args(["--after", "0.5", "--screenshot"])
            .arg(&png)
            .output()
            .expect("inertia-lab runs");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{name}: {stderr}");
        assert!(stderr.contains(name), "{name}: {stderr}");
        assert!(!png.exists(), "{name}: a picture was written anyway");
    }
    std::fs::remove_dir_all(&home).ok();
}

/// README: `--screenshot` exits "1 and the reason when … the picture cannot be written": into
/// a folder that does not exist, and onto a path that is a folder (which even root cannot
/// overwrite with a file), with the path in the message.
#[test]
fn screenshot_that_cannot_be_written_exits_1() {
    if !have("screenshot_that_cannot_be_written_exits_1", &["Xvfb"]) {
        return;
    }
    let (_xvfb, display) = start_xvfb("unwritable");
    let home = temp_home("shot-unwritable");
    let folder = home.join("a-folder.png");
    std::fs::create_dir_all(&folder).expect("folder");
    for out_path in [home.join("no-such-folder").join("shot.png"), folder.clone()] {
        let out = app_command(&display, &home)
            .args(["--after", "0.5", "--screenshot"])
            .arg(&out_path)
            .output()
            .expect("inertia-lab runs");
        let stderr = String::from_utf8_lossy(&out.stderr);
        let shown = out_path.display().to_string();
        assert_eq!(out.status.code(), Some(1), "{shown}: {stderr}");
        assert!(stderr.contains("cannot write"), "{shown}: {stderr}");
        assert!(stderr.contains(&shown), "{shown}: {stderr}");
    }
    assert!(!home.join("no-such-folder").exists());
    assert!(folder.is_dir(), "the folder is still a folder");
    std::fs::remove_dir_all(&home).ok();
}

/// Width, height and RGBA pixels of a PNG file, or why it is not a valid one.
fn read_png(path: &Path) -> Result<(u32, u32, Vec<u8>), String> {
    let file = std::fs::File::open(path).map_err(|e| e.to_string())?;
    let decoder = png::Decoder::new(std::io::BufReader::new(file));
    let mut reader = decoder.read_info().map_err(|e| e.to_string())?;
    let mut bytes = vec![0; reader.output_buffer_size().ok_or("no size")?];
    let info = reader.next_frame(&mut bytes).map_err(|e| e.to_string())?;
    if (info.color_type, info.bit_depth) != (png::ColorType::Rgba, png::BitDepth::Eight) {
        return Err(format!("{:?} {:?}", info.color_type, info.bit_depth));
    }
    bytes.truncate(info.buffer_size());
    Ok((info.width, info.height, bytes))
}

/// The boxes of egui's button fill (gray 50 on the panel's gray 27) in the plot bar, the rows
/// between y = 560 and 700 right of the side panel, in reading order: the plot bar's buttons and
/// number fields (`Pause`, `Window`, `History`, `Export CSV`, `…`, `Record`, its seconds), found
/// on the screen because the row wraps differently as labels come and go ("skipped 0.21 s").
fn plot_bar_boxes(img: &Image) -> Vec<(usize, usize, usize, usize)> {
    let (x0, x1, y0, y1) = (345, img.width.min(1280), 560, img.height.min(700));
    let fill = |x: usize, y: usize| {
        let k = 3 * (y * img.width + x);
        img.rgb[k..k + 3] == [50, 50, 50]
    };
    let mut seen = vec![false; img.width * img.height];
    let mut boxes = Vec::new();
    for y in y0..y1 {
        for x in x0..x1 {
            if seen[y * img.width + x] || !fill(x, y) {
                continue;
            }
            // One 4-connected component of the fill: a widget's background around its text.
            let (mut lo_x, mut hi_x, mut lo_y, mut hi_y, mut n) = (x, x, y, y, 0);
            let mut stack = vec![(x, y)];
            seen[y * img.width + x] = true;
            while let Some((cx, cy)) = stack.pop() {
                n += 1;
                (lo_x, hi_x, lo_y, hi_y) = (lo_x.min(cx), hi_x.max(cx), lo_y.min(cy), hi_y.max(cy));
                for (nx, ny) in [
                    (cx + 1, cy),
                    (cx.wrapping_sub(1), cy),
                    (cx, cy + 1),
                    (cx, cy.wrapping_sub(1)),
                ] {
                    if (x0..x1).contains(&nx)
                        && (y0..y1).contains(&ny)
                        && !seen[ny * img.width + nx]
                        && fill(nx, ny)
                    {
                        seen[ny * img.width + nx] = true;
                        stack.push((nx, ny));
                    }
                }
            }
            let (w, h) = (hi_x - lo_x + 1, hi_y - lo_y + 1);
            if (14..=26).contains(&h) && (20..=200).contains(&w) && 2 * n >= w * h {
                boxes.push((lo_x, lo_y, w, h));
            }
        }
    }
    // Rows first (a row's boxes share their top within a few pixels), then left to right.
    boxes.sort_by_key(|&(x, y, ..)| (y / 12, x));
    boxes
}

/// README: "Record (plot bar) writes the window as numbered PNG pictures, 10 per second for the
/// seconds set beside it (5 s by default), into a new folder `inertia-lab-recording-<time>`".
/// Clicking the real button under Xvfb writes one folder with frame-0001.png … frame-N.png and
/// nothing else, N up to the 50 pictures of 5 s at 10 per second (one a frame at most), each a
/// valid 1280 × 800 RGBA PNG of the window with the body in it; the body turns between the
/// first and the last.
#[test]
fn record_writes_every_picture_it_asks_for() {
    if !have(
        "record_writes_every_picture_it_asks_for",
        &["Xvfb", "xdotool", "import"],
    ) {
        return;
    }
    let (_xvfb, display) = start_xvfb("record");
    let home = temp_home("record");
    let mut app = app_command(&display, &home);
    app.stdout(Stdio::null()).stderr(Stdio::null());
    let mut app = Guard(app.spawn().expect("start inertia-lab"));

    // Wait until the window shows the body (the first frames of a debug build take seconds).
    let ppm = home.join("screen.ppm");
    let start = Instant::now();
    loop {
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "the window never showed the body"
        );
        assert!(app.0.try_wait().expect("poll").is_none(), "the app exited");
        std::thread::sleep(Duration::from_millis(500));
        let shot = Command::new("import")
            .args(["-display", &display, "-window", "root", "-depth", "8"])
            .arg(&ppm)
            .status()
            .expect("run import");
        if shot.success()
            && Image::read_ppm(&ppm)
                .is_some_and(|img| img.count((370, 1280), (30, 580), body_pixel) > 2000)
        {
            break;
        }
    }
    let xdotool = |args: &[&str]| {
        let ok = Command::new("xdotool")
            .args(args)
            .env("DISPLAY", &display)
            .status()
            .expect("run xdotool")
            .success();
        assert!(ok, "xdotool {args:?}");
    };
    let folder = || {
        std::fs::read_dir(&home)
            .expect("home")
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| {
                p.is_dir()
                    && p.file_name()
                        .and_then(|n| n.to_str())
                        .is_some_and(|n| n.starts_with("inertia-lab-recording-"))
            })
            .collect::<Vec<_>>()
    };
    // Record is the plot bar's last button, before its seconds field. The row can rewrap between
    // the screenshot and the click: look again and retry until the recording has started.
    let mut boxes = Vec::new();
    for _ in 0..5 {
        let shot = Command::new("import")
            .args(["-display", &display, "-window", "root", "-depth", "8"])
            .arg(&ppm)
            .status()
            .expect("run import");
        boxes = Image::read_ppm(&ppm)
            .filter(|_| shot.success())
            .map_or_else(Vec::new, |img| plot_bar_boxes(&img));
        let Some(&(bx, by, bw, bh)) = boxes.len().checked_sub(2).and_then(|k| boxes.get(k)) else {
            continue;
        };
        let (x, y) = ((bx + bw / 2).to_string(), (by + bh / 2).to_string());
        // Press and release apart, so that egui sees the press over the button first.
        xdotool(&["mousemove", &x, &y]);
        std::thread::sleep(Duration::from_millis(300));
        xdotool(&["mousedown", "1"]);
        std::thread::sleep(Duration::from_millis(150));
        xdotool(&["mouseup", "1"]);
        xdotool(&["mousemove", "700", "300"]);
        std::thread::sleep(Duration::from_millis(1500));
        if !folder().is_empty() {
            break;
        }
    }
    std::fs::remove_file(&ppm).ok();
    assert!(
        !folder().is_empty(),
        "Record never started; plot bar boxes {boxes:?}"
    );

    // 5 s of recording, then the last pictures are encoded: wait until no file has appeared for
    // 3 s after those 5 s.
    let clicked = Instant::now();
    let (mut count, mut changed) = (0, Instant::now());
    loop {
        std::thread::sleep(Duration::from_millis(250));
        let n = folder()
            .first()
            .map_or(0, |d| std::fs::read_dir(d).map_or(0, Iterator::count));
        if n != count {
            (count, changed) = (n, Instant::now());
        }
        let waited = clicked.elapsed();
        if waited > Duration::from_secs(8) && changed.elapsed() > Duration::from_secs(3) {
            break;
        }
        assert!(
            waited < Duration::from_secs(60),
            "the recording never ended ({n} files)"
        );
    }
    assert!(app.0.try_wait().expect("poll").is_none(), "the app exited");

    let folders = folder();
    assert_eq!(folders.len(), 1, "one recording folder: {folders:?}");
    let dir = &folders[0];
    let stamp = dir.file_name().and_then(|n| n.to_str()).expect("a name")
        ["inertia-lab-recording-".len()..]
        .to_owned();
    assert!(
        !stamp.is_empty() && stamp.bytes().all(|b| b.is_ascii_digit()),
        "{dir:?}"
    );
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("folder")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    // One picture a frame at most: a frame rate under 10 per second (a debug build on software
    // GL) gives fewer, but every one asked for is written, numbered from 1 without a gap.
    let n = names.len();
    assert!(
        (25..=50).contains(&n),
        "5 s at 10 per second (at least 5 per second): {n} pictures"
    );
    let expected: Vec<String> = (1..=n).map(|k| format!("frame-{k:04}.png")).collect();
    assert_eq!(
        names, expected,
        "frame-0001.png … frame-{n:04}.png and nothing else"
    );
    let mut body_counts = Vec::new();
    let (mut first, mut last) = (Vec::new(), Vec::new());
    for name in &names {
        let (w, h, rgba) = read_png(&dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!((w, h), (1280, 800), "{name}");
        let img = Image {
            width: 1280,
            height: 800,
            rgb: rgba.chunks(4).flat_map(|p| [p[0], p[1], p[2]]).collect(),
        };
        body_counts.push(img.count((370, 1280), (30, 580), body_pixel));
        if first.is_empty() {
            first = img.rgb;
        } else {
            last = img.rgb;
        }
    }
    assert!(
        body_counts.iter().all(|&n| n > 2000),
        "every picture shows the body: {body_counts:?}"
    );
    assert_ne!(first, last, "the body moves during the recording");
    std::fs::remove_dir_all(&home).ok();
}
