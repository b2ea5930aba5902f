//! What the robot target does with a description's text: read it as URDF, MJCF or SDFormat, audit every
//! link (primitives only: no mesh file exists beside it), and write a fix of every link. Any
//! panic is a bug; errors are the expected answer to bad input. A fix of a description that
//! reads must read again, with the new inertials.

use std::path::Path;

use robot::fix::{Replacement, splice};
use robot::{AuditOptions, ReadOptions, audit, read_str};

pub fn audit_and_fix(text: &str) {
    let Ok(robot) = read_str(text, Path::new("fuzz/robot.urdf"), &ReadOptions::default()) else {
        return;
    };
    let report = audit(&robot, &AuditOptions::default());
    for l in &report.links {
        for f in &l.findings {
            let _ = f.code();
        }
    }
    let element = match robot.format {
        robot::DescriptionFormat::Urdf => {
            "<inertial>\n  <mass value=\"1\"/>\n  <inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/>\n</inertial>"
        }
        robot::DescriptionFormat::Mjcf => {
            "<inertial pos=\"0 0 0\" mass=\"1\" diaginertia=\"1 1 1\"/>"
        }
        robot::DescriptionFormat::Sdf => {
            "<inertial>\n  <mass>1</mass>\n  <inertia><ixx>1</ixx><iyy>1</iyy><izz>1</izz></inertia>\n</inertial>"
        }
    };
    let replacements: Vec<Replacement> = (0..robot.links.len())
        .map(|link| Replacement {
            link,
            text: element.to_owned(),
        })
        .collect();
    if let Ok(fixed) = splice(&robot, &replacements) {
        let again = read_str(
            &fixed,
            Path::new("fuzz/robot.urdf"),
            &ReadOptions::default(),
        )
        .unwrap_or_else(|e| panic!("the fix does not read again: {e}\n{fixed}"));
        assert_eq!(again.links.len(), robot.links.len());
        for link in &again.links {
            let stated = link
                .stated
                .as_ref()
                .expect("every link has the new inertial");
            assert_eq!(stated.mass, 1.0);
        }
    }
}
