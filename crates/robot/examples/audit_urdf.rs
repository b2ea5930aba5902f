//! Audits a robot description given on the command line and prints, worst link first, each
//! link's stated mass, the density that mass gives its geometry, how far the stated inertia
//! tensor is from the geometry's, and the codes of its findings:
//!
//! ```text
//! cargo run -p robot --example audit_urdf -- tests/data/robots/franka_panda/panda.urdf
//! ```
//!
//! (`inertia-lab audit` prints the same audit with every finding in words, and `--json`.)

use std::path::PathBuf;
use std::process::ExitCode;

use robot::{AuditOptions, ReadOptions};

fn main() -> ExitCode {
    let Some(path) = std::env::args_os().nth(1).map(PathBuf::from) else {
        eprintln!("usage: audit_urdf ROBOT.urdf|ROBOT.xml");
        return ExitCode::from(2);
    };
    // Meshes named `package://NAME/…` are looked for beside the description unless
    // `ReadOptions::packages` says where NAME is.
    let description = match robot::read(&path, &ReadOptions::default()) {
        Ok(d) => d,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::FAILURE;
        }
    };
    let audit = robot::audit(&description, &AuditOptions::default());
    println!(
        "{} \"{}\": {} links, {} with findings",
        description.format.name(),
        description.name,
        description.links.len(),
        audit.links.iter().filter(|l| l.flagged()).count()
    );
    for link in audit.worst_first() {
        let stated = link
            .stated
            .as_ref()
            .map_or("none".to_owned(), |p| format!("{:.4} kg", p.mass));
        let density = link
            .computed
            .as_ref()
            .map_or("not weighed".to_owned(), |c| {
                format!("{:.0} kg/m^3", c.density)
            });
        let error = link.comparison.as_ref().map_or("-".to_owned(), |c| {
            format!("{:.1} %", c.tensor_error * 100.0)
        });
        let codes: Vec<&str> = link.findings.iter().map(|f| f.code()).collect();
        println!(
            "  {:<24} {stated:>10}  {density:>12}  tensor error {error:>9}  {}",
            description.links[link.link].name,
            if codes.is_empty() {
                "-".to_owned()
            } else {
                codes.join(", ")
            }
        );
    }
    ExitCode::SUCCESS
}
