//! Runs the real `inertia-lab simulate` binary and checks its CSV against the physics of the
//! canonical tennis-racket case (I = 1, 2, 3; ω₀ = 0.001, 10, 0.001).

use std::path::PathBuf;
use std::process::{Command, Output};

const BIN: &str = env!("CARGO_BIN_EXE_inertia-lab");
const HEADER: &str = "t,w1,w2,w3,wx,wy,wz,Lx,Ly,Lz,qw,qx,qy,qz,T,U,E";

fn simulate(args: &[&str]) -> Output {
    Command::new(BIN)
        .arg("simulate")
        .args(args)
        .output()
        .expect("the binary runs")
}

fn temp_csv(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("inertia-lab-{}-{name}.csv", std::process::id()))
}

fn asset(name: &str) -> String {
    format!("{}/../../assets/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// Parses the CSV body into rows of 17 numbers, checking the header.
fn rows(csv: &str) -> Vec<[f64; 17]> {
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some(HEADER));
    lines
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().expect("a number")).collect();
            v.try_into().expect("17 columns")
        })
        .collect()
}

#[test]
fn canonical_case_writes_a_csv_meeting_the_figures() {
    let path = temp_csv("flip");
    let out = simulate(&[
        "--inertia",
        "1,2,3",
        "--omega",
        "0.001,10,0.001",
        "--dt",
        "0.004166666666666667",
        "--duration",
        "60",
        "--csv",
        path.to_str().expect("utf-8 path"),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let csv = std::fs::read_to_string(&path).expect("CSV written");
    std::fs::remove_file(&path).ok();
    let r = rows(&csv);
    assert_eq!(r.len(), 14_401);
    // t = 0: ω as given in both frames, L = Iω, identity quaternion, E = ½ Σ Iω².
    let first = r[0];
    assert_eq!(&first[..4], &[0.0, 0.001, 10.0, 0.001]);
    assert_eq!(&first[7..14], &[0.001, 20.0, 0.003, 1.0, 0.0, 0.0, 0.0]);
    assert!((first[16] - 100.000_002).abs() < 1e-12);
    assert!((r[14_400][0] - 60.0).abs() < 1e-9);
    let (l0, e0) = ([first[7], first[8], first[9]], first[16]);
    let l0n = l0.iter().map(|x| x * x).sum::<f64>().sqrt();
    let mut flips = 0;
    for w in r.windows(2) {
        let row = w[1];
        let dl = (0..3)
            .map(|i| (row[7 + i] - l0[i]).powi(2))
            .sum::<f64>()
            .sqrt();
        assert!(dl < 1e-10 * l0n, "world L moved at t = {}", row[0]);
        assert!(((row[16] - e0) / e0).abs() < 1e-9, "E at t = {}", row[0]);
        let qn = (10..14).map(|i| row[i] * row[i]).sum::<f64>();
        assert!((qn - 1.0).abs() < 1e-12);
        // E = T + U and T = ½ ω·L (world frame).
        assert!((row[14] + row[15] - row[16]).abs() < 1e-12 * e0);
        let t = 0.5 * (row[4] * row[7] + row[5] * row[8] + row[6] * row[9]);
        assert!((t - row[14]).abs() < 1e-9 * e0);
        if (w[0][2] > 0.0) != (row[2] > 0.0) {
            flips += 1;
        }
    }
    assert_eq!(flips, 17);
    let stderr = String::from_utf8_lossy(&out.stderr);
    let flip_line = stderr
        .lines()
        .find(|l| l.starts_with("flips"))
        .expect("flip count printed");
    assert!(flip_line.trim_end().ends_with(" 17"), "{flip_line}");
    for what in ["|L|", "world L", "of E"] {
        assert!(stderr.contains(what), "{stderr}");
    }
}

#[test]
fn stdout_every_and_textbook_model() {
    let out = simulate(&["--duration", "10", "--every", "240", "--model", "textbook"]);
    assert!(out.status.success());
    let r = rows(&String::from_utf8_lossy(&out.stdout));
    assert_eq!(r.len(), 11);
    assert!((r[10][0] - 10.0).abs() < 1e-12);
    // The textbook model keeps body ω fixed: no flip, ω₂ stays 10.
    assert!(r.iter().all(|row| (row[2] - 10.0).abs() < 1e-9));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr
            .lines()
            .any(|l| l.starts_with("flips") && l.trim_end().ends_with(" 0"))
    );
}

#[test]
fn mesh_input_runs_and_conserves_energy() {
    let out = simulate(&[
        "--mesh",
        &asset("t_handle.obj"),
        "--mass",
        "2",
        "--duration",
        "2",
        "--every",
        "48",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let r = rows(&String::from_utf8_lossy(&out.stdout));
    assert_eq!(r.len(), 11);
    assert!(
        r.iter()
            .all(|row| ((row[16] - r[0][16]) / r[0][16]).abs() < 1e-9)
    );
}

#[test]
fn compare_prints_every_integrator() {
    let out = simulate(&["--compare", "--duration", "8"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    for name in [
        "midpoint-cayley",
        "splitting",
        "rk4",
        "euler",
        "midpoint",
        "exact",
        "engine-style",
        "implicit-euler",
    ] {
        assert!(
            text.lines().any(|l| l.starts_with(name)),
            "{name} missing:\n{text}"
        );
    }
    assert!(text.contains("4K(k)/lambda"));
}

#[test]
fn bad_input_gets_the_documented_exit_codes() {
    for (args, code) in [
        (vec!["--dt", "0"], 2),
        (vec!["--dt", "-1"], 2),
        (vec!["--dt", "nan"], 2),
        (vec!["--duration", "inf"], 2),
        (vec!["--inertia", "1,1,3"], 2),
        (vec!["--inertia", "3,2,1"], 2),
        (vec!["--inertia", "0,2,3"], 2),
        (vec!["--inertia", "1,2"], 2),
        (vec!["--omega", "1,nan,0"], 2),
        (vec!["--mass", "-1"], 2),
        (vec!["--every", "0"], 2),
        (vec!["--integrator", "verlet"], 2),
        (vec!["--model", "newtonian"], 2),
        (vec!["--mesh", "/nonexistent/shape.obj"], 3),
    ] {
        let out = simulate(&args);
        assert_eq!(
            out.status.code(),
            Some(code),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(out.stdout.is_empty(), "{args:?}");
    }
}
