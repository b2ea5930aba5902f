//! A scene named by a link: the query string of the page's address, as the lab's commands, so
//! that a teacher can send students straight to the racket spinning about its middle axis
//! beside its bounding-box copy (`?sample=tennis_racket&spin=2&compare=bbox`), or into a
//! lesson's third step (`?lesson=racket-flip&step=2`). [`share`] writes the link of the scene
//! shown. docs/web.md lists the keys.

use rbcore::RotationModel;

use crate::i18n::{Language, tr};
use crate::lab::lessons::LessonSource;
use crate::lab::samples::{SAMPLE_BODIES, SAMPLES};
use crate::lab::settings::{AppSettings, InertiaSource, MassGiven};
use crate::lab::{Command, Lab, MAX_COPIES, Variant};

/// The keys a link may give.
pub const KEYS: [&str; 14] = [
    "sample", "spin", "compare", "source", "model", "size", "density", "mass", "rate", "lesson",
    "step", "lang", "embed", "bench",
];

/// What a link asks for.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LinkScene {
    /// The lab's commands, in order: the body, its spin, the comparison, the lesson.
    pub commands: Vec<Command>,
    /// Settings the link changes (applied to the saved ones before the lab starts).
    pub settings: Tweaks,
    /// `embed=1`: the 3D view, the plots and the lesson only (for an iframe).
    pub embed: bool,
    /// `bench=N`: measure N frames and print the table to the console.
    pub bench_frames: Option<usize>,
    /// `lesson=ADDRESS`: a lesson file to fetch (a teacher's, beside the page or elsewhere), with
    /// the step to go to once it is open.
    pub lesson_address: Option<(String, Option<usize>)>,
    /// Each key or value that was not understood, in words; the rest still applies.
    pub problems: Vec<String>,
}

/// The settings a link changes; each left out keeps the user's own.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Tweaks {
    /// `source=`: the inertia the simulation uses.
    pub source: Option<InertiaSource>,
    /// `model=`: full or textbook.
    pub model: Option<RotationModel>,
    /// `size=`: the uniform scale.
    pub scale: Option<f64>,
    /// `density=` or `mass=`.
    pub mass: Option<MassGiven>,
    /// `rate=`: the presets' spin rate (rad/s).
    pub spin_rate: Option<f64>,
    /// `lang=`: the language.
    pub language: Option<Language>,
}

impl Tweaks {
    /// `settings` with the link's changes.
    pub fn apply(&self, mut settings: AppSettings) -> AppSettings {
        let b = &mut settings.body;
        b.source = self.source.unwrap_or(b.source);
        b.scale = self.scale.unwrap_or(b.scale);
        b.mass = self.mass.unwrap_or(b.mass);
        b.spin_rate = self.spin_rate.unwrap_or(b.spin_rate);
        if let Some(model) = self.model {
            settings.physics.model = model;
        }
        if self.language.is_some() {
            settings.display.language = self.language;
        }
        settings
    }
}

/// A positive finite number, if `value` is one.
fn positive(value: &str) -> Option<f64> {
    value
        .parse::<f64>()
        .ok()
        .filter(|v| v.is_finite() && *v > 0.0)
}

/// The scene of a query string (with or without its leading `?`).
pub fn parse(query: &str) -> LinkScene {
    let mut scene = LinkScene::default();
    let (mut body, mut spin, mut compare) = (None, None, None);
    let (mut lesson, mut step) = (None, None);
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
                _ => Err(tr!("link-spin-invalid", value = &value)),
            },
            "compare" => variants(&value).map(|v| compare = Some(v)),
            "source" => match value.as_str() {
                "exact" => Ok(InertiaSource::Exact),
                "bbox" => Ok(InertiaSource::BoundingBox),
                "points" => Ok(InertiaSource::PointMasses),
                _ => Err(tr!("link-source-invalid", value = &value)),
            }
            .map(|s| scene.settings.source = Some(s)),
            "model" => match value.as_str() {
                "full" => Ok(RotationModel::Full),
                "textbook" => Ok(RotationModel::Textbook),
                _ => Err(tr!("link-model-invalid", value = &value)),
            }
            .map(|m| scene.settings.model = Some(m)),
            "size" => positive(&value)
                .map(|v| scene.settings.scale = Some(v))
                .ok_or_else(|| tr!("link-size-invalid", value = &value)),
            "density" => positive(&value)
                .map(|v| scene.settings.mass = Some(MassGiven::Density(v)))
                .ok_or_else(|| tr!("link-density-invalid", value = &value)),
            "mass" => positive(&value)
                .map(|v| scene.settings.mass = Some(MassGiven::Mass(v)))
                .ok_or_else(|| tr!("link-mass-invalid", value = &value)),
            "rate" => positive(&value)
                .map(|v| scene.settings.spin_rate = Some(v))
                .ok_or_else(|| tr!("link-rate-invalid", value = &value)),
            "lesson" if is_address(&value) => {
                scene.lesson_address = Some((value.clone(), None));
                Ok(())
            }
            "lesson" => crate::lab::lessons::find(&value)
                .map(|l| lesson = Some(l.id.clone()))
                .map_err(|e| format!("lesson={value}: {e}")),
            "step" => match value.parse::<usize>() {
                Ok(k) if k >= 1 => {
                    step = Some(k - 1);
                    Ok(())
                }
                _ => Err(tr!("link-step-invalid", value = &value)),
            },
            "lang" => Language::from_tag(&value)
                .map(|l| scene.settings.language = Some(l))
                .ok_or_else(|| tr!("link-lang-invalid", value = &value)),
            "embed" => {
                scene.embed = value != "0";
                Ok(())
            }
            "bench" => match value.parse::<usize>() {
                Ok(n) if n > 0 => {
                    scene.bench_frames = Some(n);
                    Ok(())
                }
                _ => Err(tr!("link-bench-invalid", value = &value)),
            },
            _ => Err(tr!(
                "link-unknown-key",
                key = format!("{key:?}"),
                known = KEYS.join(", ")
            )),
        };
        if let Err(problem) = result {
            scene.problems.push(problem);
        }
    }
    // The lesson first: its step sets the lab up, and the link's own body and spin then win.
    if let Some(id) = lesson {
        scene
            .commands
            .push(Command::OpenLesson(LessonSource::BuiltIn(id)));
        scene.commands.extend(step.map(Command::GoToStep));
    } else if let Some((_, at)) = &mut scene.lesson_address {
        *at = step;
    } else if step.is_some() {
        scene.problems.push(tr!("link-step-needs-lesson"));
    }
    scene.commands.extend(body.map(Command::LoadSample));
    scene.commands.extend(spin.map(Command::Preset));
    scene.commands.extend(compare.map(Command::Compare));
    scene
}

/// Whether a `lesson=` value names a file to fetch (`class.lesson.toml`, `lessons/a.toml`, an
/// `https://` address) rather than a built-in lesson's number or id (which hold no `.` or `/`).
fn is_address(value: &str) -> bool {
    value.contains('/') || value.to_ascii_lowercase().ends_with(".toml")
}

/// The commands that open a fetched lesson's `text` (from `address`) at `step`.
pub fn fetched_lesson(address: &str, text: String, step: Option<usize>) -> Vec<Command> {
    let mut commands = vec![Command::OpenLesson(LessonSource::Text {
        file: address.to_owned(),
        text,
    })];
    commands.extend(step.map(Command::GoToStep));
    commands
}

/// The query (`?…`) of a link that opens the scene shown: the sample, its size and mass, the
/// inertia source, the model, the spin and its rate, the comparison, the lesson and its step.
///
/// # Errors
/// The body is not a sample (a file of the user's cannot travel in a link), in words.
pub fn share(lab: &Lab) -> Result<String, String> {
    let name = &lab.primary().body().name;
    let Some((_, file, _)) = SAMPLES
        .iter()
        .chain(SAMPLE_BODIES.iter())
        .find(|(label, ..)| label == name)
    else {
        return Err(tr!("link-own-file", name = name));
    };
    let s = lab.settings();
    let b = &s.body;
    let mut pairs = vec![
        ("sample", encode(file)),
        ("spin", (lab.preset_axis() + 1).to_string()),
        ("size", b.scale.to_string()),
        match b.mass {
            MassGiven::Density(d) => ("density", d.to_string()),
            MassGiven::Mass(m) => ("mass", m.to_string()),
        },
        ("rate", b.spin_rate.to_string()),
        (
            "source",
            match b.source {
                InertiaSource::BoundingBox => "bbox",
                InertiaSource::PointMasses => "points",
                InertiaSource::Exact | InertiaSource::Stated => "exact",
            }
            .to_owned(),
        ),
        (
            "model",
            match s.physics.model {
                RotationModel::Textbook => "textbook",
                _ => "full",
            }
            .to_owned(),
        ),
    ];
    let copies: Vec<&str> = lab.specimens()[1..]
        .iter()
        .filter_map(|c| match c.variant() {
            Variant::Source(InertiaSource::BoundingBox) => Some("bbox"),
            Variant::Source(InertiaSource::PointMasses) => Some("points"),
            Variant::Model(RotationModel::Textbook) => Some("textbook"),
            _ => None,
        })
        .collect();
    if !copies.is_empty() {
        pairs.push(("compare", copies.join(",")));
    }
    if let Some(run) = lab.lesson() {
        pairs.push(("lesson", run.lesson.id.clone()));
        pairs.push(("step", (run.step + 1).to_string()));
    }
    if let Some(language) = s.display.language {
        pairs.push(("lang", language.code().to_owned()));
    }
    let query: Vec<String> = pairs.into_iter().map(|(k, v)| format!("{k}={v}")).collect();
    Ok(format!("?{}", query.join("&")))
}

/// A query value: what [`decode`] reads back (letters, digits and `-_.~` as they are).
fn encode(text: &str) -> String {
    text.bytes()
        .map(|b| match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'_' | b'.' | b'~' => {
                char::from(b).to_string()
            }
            _ => format!("%{b:02X}"),
        })
        .collect()
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
            tr!(
                "link-sample-unknown",
                value = value,
                samples = names.join(", ")
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
            other => Err(tr!(
                "link-compare-unknown",
                value = value,
                name = format!("{other:?}")
            )),
        })
        .collect::<Result<_, _>>()?;
    if list.len() > MAX_COPIES {
        return Err(tr!(
            "link-compare-too-many",
            value = value,
            most = MAX_COPIES
        ));
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

    /// A shared link opens the same scene: settings, spin, copies, lesson and step.
    #[test]
    fn a_shared_link_reopens_the_scene() {
        let mut lab = Lab::new(AppSettings::default()).expect("the lab");
        lab.apply(Command::OpenLesson(LessonSource::BuiltIn(
            "stable-axes".to_owned(),
        )));
        lab.apply(Command::GoToStep(2));
        lab.apply(Command::LoadSample("Hammer: steel & wood".to_owned()));
        let mut s = lab.settings().clone();
        s.body.scale = 1.5;
        s.body.mass = MassGiven::Mass(2.25);
        s.body.spin_rate = 5.5;
        s.body.source = InertiaSource::BoundingBox;
        s.physics.model = RotationModel::Textbook;
        s.display.language = Some(Language::German);
        lab.apply(Command::Settings(Box::new(s)));
        lab.apply(Command::Preset(2));
        lab.apply(Command::Compare(vec![Variant::Source(
            InertiaSource::PointMasses,
        )]));
        let query = share(&lab).expect("a sample");
        let scene = parse(&query);
        assert!(scene.problems.is_empty(), "{query}: {:?}", scene.problems);
        // As the page starts (gui::start): the link's settings, its commands, the settings again.
        let mut again = Lab::new(scene.settings.apply(AppSettings::default())).expect("the lab");
        again.apply_all(scene.commands);
        let settings = scene.settings.apply(again.settings().clone());
        again.apply(Command::Settings(Box::new(settings)));
        assert_eq!(again.lesson().map(|r| r.step), Some(2));
        assert_eq!(again.primary().body().name, "Hammer: steel & wood");
        assert_eq!(again.preset_axis(), 2);
        assert_eq!(again.settings().body, lab.settings().body);
        assert_eq!(again.settings().physics.model, RotationModel::Textbook);
        assert_eq!(again.settings().display.language, Some(Language::German));
        assert_eq!(again.specimens().len(), 2);
        let bad = parse("?lang=fr");
        assert_eq!(bad.settings.language, None);
        assert_eq!(bad.problems, ["lang=fr: the lab speaks en, de and es"]);

        let mut own = Lab::new(AppSettings::default()).expect("the lab");
        let dir = std::env::temp_dir().join(format!("share-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("a folder");
        let file = dir.join("mine.obj");
        let cube = massprops::shapes::cuboid(
            nalgebra::Vector3::new(0.1, 0.2, 0.3),
            nalgebra::Point3::origin(),
        );
        std::fs::write(&file, massprops::shapes::to_obj("mine", "mine", &cube)).expect("written");
        own.apply(Command::LoadFile(file));
        own.wait_for_load();
        let e = share(&own).expect_err("a file of the user's");
        assert!(e.contains("mine.obj") && e.contains("cannot carry"), "{e}");
        let _ = std::fs::remove_dir_all(dir);
    }

    /// `lesson=` with an address names a file to fetch, its step kept for after; a number or an
    /// id is a built-in lesson; the fetched text opens as a lesson file of that name.
    #[test]
    fn a_lesson_by_its_address_is_fetched_then_opened_at_its_step() {
        for address in ["class.lesson.toml", "lessons/a.TOML", "https://x.org/l"] {
            let scene = parse(&format!("?lesson={}&step=2", encode(address)));
            assert!(scene.problems.is_empty(), "{address}: {:?}", scene.problems);
            assert_eq!(scene.lesson_address, Some((address.to_owned(), Some(1))));
            assert!(scene.commands.is_empty(), "{address}: {:?}", scene.commands);
        }
        assert_eq!(parse("?lesson=3").lesson_address, None);
        let text = include_str!("../../../../lessons/03-racket-flip.toml");
        let mut lab = Lab::new(AppSettings::default()).expect("the lab");
        lab.apply_all(fetched_lesson(
            "class.lesson.toml",
            text.to_owned(),
            Some(1),
        ));
        let run = lab.lesson().expect("opened");
        assert_eq!((run.lesson.id.as_str(), run.step), ("racket-flip", 1));
        let mut lab = Lab::new(AppSettings::default()).expect("the lab");
        lab.apply_all(fetched_lesson("bad.lesson.toml", "id = 3".to_owned(), None));
        let said = lab.message().expect("refused in words");
        assert!(
            said.error && said.text.contains("bad.lesson.toml"),
            "{}",
            said.text
        );
    }

    #[test]
    fn decoding_keeps_malformed_escapes() {
        assert_eq!(decode("a%20b+c"), "a b c");
        assert_eq!(decode("100%"), "100%");
        assert_eq!(decode("%zz%4"), "%zz%4");
        assert_eq!(
            decode(&encode("Hammer: steel & wood")),
            "Hammer: steel & wood"
        );
    }
}
