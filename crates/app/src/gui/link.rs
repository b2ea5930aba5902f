//! A scene named by a link: the query string of the page's address, as the lab's commands, so
//! that a teacher can send students straight to the racket spinning about its middle axis
//! beside its bounding-box copy (`?sample=tennis_racket&spin=2&compare=bbox`). docs/web.md lists
//! the keys.

use crate::lab::samples::{SAMPLE_BODIES, SAMPLES};
use crate::lab::settings::InertiaSource;
use crate::lab::{Command, MAX_COPIES, Variant};

/// The keys a link may give.
pub const KEYS: [&str; 4] = ["sample", "spin", "compare", "bench"];

/// What a link asks for.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LinkScene {
    /// The lab's commands, in order: the body, its spin, the comparison.
    pub commands: Vec<Command>,
    /// `bench=N`: measure N frames and print the table to the console.
    pub bench_frames: Option<usize>,
    /// Each key or value that was not understood, in words; the rest still applies.
    pub problems: Vec<String>,
}

/// The scene of a query string (with or without its leading `?`).
pub fn parse(query: &str) -> LinkScene {
    let mut scene = LinkScene::default();
    let (mut body, mut spin, mut compare) = (None, None, None);
    for pair in query.trim_start_matches('?').split('&') {
        if pair.is_empty() {
            continue;
        }
        let (key, value) = pair.split_once('=').unwrap_or((pair, ""));
        let (key, value) = (decode(key), decode(value));
        let result = match key.as_str() {
            "sample" => sample(&value).map(|label| body = Some(label)),
            "spin" => match value.as_str() {
                "1" | "2" | "3" => {
                    spin = value.parse::<usize>().ok().map(|axis| axis - 1);
                    Ok(())
                }
                _ => Err(format!(
                    "spin={value}: the principal axis is 1, 2 or 3 (smallest to largest moment)"
                )),
            },
            "compare" => variants(&value).map(|v| compare = Some(v)),
            "bench" => match value.parse::<usize>() {
                Ok(n) if n > 0 => {
                    scene.bench_frames = Some(n);
                    Ok(())
                }
                _ => Err(format!(
                    "bench={value}: give the number of frames to measure"
                )),
            },
            _ => Err(format!(
                "unknown link parameter {key:?} (known: {})",
                KEYS.join(", ")
            )),
        };
        if let Err(problem) = result {
            scene.problems.push(problem);
        }
    }
    scene.commands.extend(body.map(Command::LoadSample));
    scene.commands.extend(spin.map(Command::Preset));
    scene.commands.extend(compare.map(Command::Compare));
    scene
}

/// The label of the sample a link names: by the label itself, or its file name with or
/// without the extension (`tennis_racket` is the mesh, `tennis_racket.toml` its body of parts).
fn sample(value: &str) -> Result<String, String> {
    let all = || SAMPLES.iter().chain(SAMPLE_BODIES.iter());
    let stem = |file: &str| file.rsplit_once('.').map_or(file, |(s, _)| s).to_owned();
    all()
        .find(|(label, file, _)| *label == value || *file == value)
        .or_else(|| all().find(|(_, file, _)| stem(file) == value))
        .map(|(label, ..)| (*label).to_owned())
        .ok_or_else(|| {
            let names: Vec<&str> = all().map(|(_, file, _)| *file).collect();
            format!(
                "sample={value}: no such sample (there are {})",
                names.join(", ")
            )
        })
}

/// The copies `compare=` names, comma-separated: `bbox`, `points`, `textbook`.
fn variants(value: &str) -> Result<Vec<Variant>, String> {
    let list: Vec<Variant> = value
        .split(',')
        .map(|name| match name.trim() {
            "bbox" => Ok(Variant::Source(InertiaSource::BoundingBox)),
            "points" => Ok(Variant::Source(InertiaSource::PointMasses)),
            "textbook" => Ok(Variant::Model(rbcore::RotationModel::Textbook)),
            other => Err(format!(
                "compare={value}: {other:?} is none of bbox, points, textbook"
            )),
        })
        .collect::<Result<_, _>>()?;
    if list.len() > MAX_COPIES {
        return Err(format!("compare={value}: at most {MAX_COPIES} copies"));
    }
    Ok(list)
}

/// `application/x-www-form-urlencoded` decoding: `+` is a space, `%XX` a byte (a malformed
/// escape stays as it is).
fn decode(text: &str) -> String {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut k = 0;
    while k < bytes.len() {
        let hex = |b: u8| char::from(b).to_digit(16);
        match bytes[k] {
            b'+' => out.push(b' '),
            b'%' if k + 2 < bytes.len() => match (hex(bytes[k + 1]), hex(bytes[k + 2])) {
                (Some(h), Some(l)) => {
                    out.push((h * 16 + l) as u8);
                    k += 2;
                }
                _ => out.push(b'%'),
            },
            b => out.push(b),
        }
        k += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_documented_link_gives_sample_spin_and_comparison() {
        let scene = parse("?sample=tennis_racket&spin=2&compare=bbox");
        assert_eq!(
            scene.commands,
            vec![
                Command::LoadSample("Tennis racket".to_owned()),
                Command::Preset(1),
                Command::Compare(vec![Variant::Source(InertiaSource::BoundingBox)]),
            ]
        );
        assert!(scene.problems.is_empty(), "{:?}", scene.problems);
    }

    #[test]
    fn samples_by_file_name_label_and_body_file() {
        let label = |q: &str| match parse(q).commands.first() {
            Some(Command::LoadSample(l)) => l.clone(),
            other => panic!("{q}: {other:?}"),
        };
        assert_eq!(label("sample=hammer"), "Hammer");
        assert_eq!(label("sample=hammer.toml"), "Hammer: steel & wood");
        assert_eq!(label("sample=hollow_box"), "Hollow box & solid box");
        assert_eq!(label("sample=T-handle"), "T-handle");
        assert_eq!(label("sample=Tennis+racket"), "Tennis racket");
        assert_eq!(label("sample=L%2Dbracket"), "L-bracket");
    }

    #[test]
    fn every_problem_is_named_and_the_rest_still_applies() {
        let scene = parse("sample=anvil&spin=4&compare=bbox,mass&colour=red&bench=x&spin=3");
        assert_eq!(scene.commands, vec![Command::Preset(2)]);
        let problems = scene.problems.join("\n");
        for part in [
            "sample=anvil",
            "t_handle.obj",
            "spin=4",
            "\"mass\"",
            "\"colour\"",
            "bench=x",
        ] {
            assert!(problems.contains(part), "{part} in {problems}");
        }
        assert_eq!(scene.problems.len(), 5);
        assert_eq!(parse("compare=bbox,points,textbook,bbox").problems.len(), 1);
        assert_eq!(parse("bench=120").bench_frames, Some(120));
        assert_eq!(parse(""), LinkScene::default());
    }

    #[test]
    fn decoding_keeps_malformed_escapes() {
        assert_eq!(decode("a%20b+c"), "a b c");
        assert_eq!(decode("100%"), "100%");
        assert_eq!(decode("%zz%4"), "%zz%4");
    }
}
