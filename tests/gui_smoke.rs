//! Smoke test of the real `inertia-lab` window under Xvfb: it starts with a mesh argument that
//! cannot be loaded, keeps the default T-handle, keeps running, and a screenshot of the screen
//! shows the shaded body in the 3D view and the plot lines (saved as
//! `target/gui-smoke.png` for a human to look at).
//!
//! Needs `Xvfb`, ImageMagick's `import` and the X11/GL runtime libraries (`.ci/run` installs
//! them); without Xvfb or `import` it prints a SKIPPED line (a failure under `CI`).

mod common;

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use common::{on_path, skip};

/// Kills a child process when dropped, so a failing assertion leaves nothing behind.
struct Guard(Child);

impl Drop for Guard {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// A binary PPM (P6) screenshot: width, height, RGB bytes.
struct Image {
    width: usize,
    height: usize,
    rgb: Vec<u8>,
}

impl Image {
    fn read(path: &Path) -> Option<Image> {
        let bytes = std::fs::read(path).ok()?;
        // Header: "P6", width, height, max value, each separated by whitespace, then one byte.
        let mut fields = Vec::new();
        let mut i = 0;
        while fields.len() < 4 && i < bytes.len() {
            while i < bytes.len() && bytes[i].is_ascii_whitespace() {
                i += 1;
            }
            let start = i;
            while i < bytes.len() && !bytes[i].is_ascii_whitespace() {
                i += 1;
            }
            fields.push(String::from_utf8_lossy(&bytes[start..i]).into_owned());
        }
        if fields.first().map(String::as_str) != Some("P6") || fields.get(3)? != "255" {
            return None;
        }
        let width = fields[1].parse().ok()?;
        let height = fields[2].parse().ok()?;
        let rgb = bytes.get(i + 1..i + 1 + width * height * 3)?.to_vec();
        Some(Image { width, height, rgb })
    }

    /// Pixels in the box `[x0, x1) × [y0, y1)` for which `f(r, g, b)` holds.
    fn count(
        &self,
        (x0, x1): (usize, usize),
        (y0, y1): (usize, usize),
        f: impl Fn(u8, u8, u8) -> bool,
    ) -> usize {
        let mut n = 0;
        for y in y0..y1.min(self.height) {
            for x in x0..x1.min(self.width) {
                let k = 3 * (y * self.width + x);
                if f(self.rgb[k], self.rgb[k + 1], self.rgb[k + 2]) {
                    n += 1;
                }
            }
        }
        n
    }
}

/// The shaded body's tan (albedo 200, 160, 90, lit).
fn body_pixel(r: u8, g: u8, b: u8) -> bool {
    r > 90 && i32::from(r) > i32::from(g) + 10 && i32::from(g) > i32::from(b) + 20
}

/// The green of the ω₂ / Ly plot lines (90, 200, 90).
fn green_line(r: u8, g: u8, b: u8) -> bool {
    g > 150 && r < 150 && b < 150
}

/// Starts Xvfb at 1280 × 800 on a display of its own (`offset` tells this file's tests apart)
/// and waits for its socket.
fn start_xvfb(offset: u32) -> (Guard, String) {
    let display = format!(":{}", 90 + offset + 2 * (std::process::id() % 500));
    let mut xvfb = Command::new("Xvfb");
    xvfb.args([
        display.as_str(),
        "-screen",
        "0",
        "1280x800x24",
        "-nolisten",
        "tcp",
    ])
    .stdout(Stdio::null())
    .stderr(Stdio::null());
    let guard = Guard(xvfb.spawn().expect("start Xvfb"));
    let socket = PathBuf::from(format!("/tmp/.X11-unix/X{}", &display[1..]));
    let start = Instant::now();
    while !socket.exists() {
        assert!(
            start.elapsed() < Duration::from_secs(20),
            "Xvfb did not start"
        );
        std::thread::sleep(Duration::from_millis(50));
    }
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
    let (_xvfb, display) = start_xvfb(1);
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
    let decoder = png::Decoder::new(std::io::BufReader::new(
        std::fs::File::open(&png).expect("the PNG was written"),
    ));
    let mut reader = decoder.read_info().expect("a PNG");
    let mut bytes = vec![0; reader.output_buffer_size().expect("size")];
    let info = reader.next_frame(&mut bytes).expect("pixels");
    assert_eq!((info.width, info.height), (1280, 800));
    let rgba = Image {
        width: 1280,
        height: 800,
        rgb: bytes.chunks(4).flat_map(|p| [p[0], p[1], p[2]]).collect(),
    };
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
    let (_xvfb, display) = start_xvfb(0);

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
        let Some(img) = Image::read(&ppm) else {
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
