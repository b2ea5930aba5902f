//! The message files are complete and the code speaks only through them.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use super::*;

/// Each message's id and the variables (`{ $name }`) its text uses, in the order of the file.
fn messages(ftl: &str) -> Vec<(String, BTreeSet<String>)> {
    let mut out: Vec<(String, BTreeSet<String>)> = Vec::new();
    for line in ftl.lines() {
        let starts_entry = line.starts_with(|c: char| c.is_ascii_lowercase());
        if starts_entry && let Some((id, _)) = line.split_once('=') {
            out.push((id.trim().to_owned(), BTreeSet::new()));
        }
        if let Some((_, vars)) = out.last_mut()
            && !line.starts_with('#')
        {
            let mut rest = line;
            while let Some(at) = rest.find('$') {
                rest = &rest[at + 1..];
                let name: String = rest
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric() || *c == '_' || *c == '-')
                    .collect();
                vars.insert(name);
            }
        }
    }
    out
}

#[test]
fn every_file_parses_in_every_language() {
    for (name, texts) in MESSAGE_FILES {
        for (language, text) in Language::ALL.iter().zip(texts) {
            if let Err((_, errors)) = FluentResource::try_new((*text).to_owned()) {
                panic!("{}/{name}.ftl: {errors:?}", language.code());
            }
        }
    }
}

#[test]
fn every_message_is_in_every_language_with_the_same_variables() {
    let mut owner = BTreeMap::new();
    for (name, texts) in MESSAGE_FILES {
        let english = messages(texts[0]);
        assert!(!english.is_empty(), "en/{name}.ftl has no message");
        for (id, _) in &english {
            if let Some(other) = owner.insert(id.clone(), *name) {
                panic!("{id} is in both {other}.ftl and {name}.ftl");
            }
        }
        let english: BTreeMap<_, _> = english.into_iter().collect();
        for (language, text) in Language::ALL.iter().zip(texts).skip(1) {
            let code = language.code();
            let translated: BTreeMap<_, _> = messages(text).into_iter().collect();
            for (id, vars) in &english {
                let Some(theirs) = translated.get(id) else {
                    panic!("{code}/{name}.ftl lacks {id}");
                };
                assert_eq!(theirs, vars, "{code}/{name}.ftl: {id} uses other variables");
            }
            for id in translated.keys() {
                assert!(
                    english.contains_key(id),
                    "{code}/{name}.ftl has {id}, which English lacks"
                );
            }
        }
    }
}

/// Every Rust file under `dir`.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("source folder") {
        let path = entry.expect("entry").path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

fn source_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// The ids the code asks for: the literal first argument of each `tr!(` (not `include_str!(`).
fn ids_in(source: &str) -> Vec<String> {
    source
        .match_indices("tr!(")
        .filter(|(at, _)| !source[..*at].ends_with(|c: char| c.is_alphanumeric() || c == '_'))
        .filter_map(|(at, _)| {
            let rest = source[at + 4..].trim_start().strip_prefix('"')?;
            Some(rest[..rest.find('"')?].to_owned())
        })
        .collect()
}

#[test]
fn every_id_the_code_asks_for_exists_and_every_message_is_used() {
    let english: BTreeSet<String> = MESSAGE_FILES
        .iter()
        .flat_map(|(_, texts)| messages(texts[0]))
        .map(|(id, _)| id)
        .collect();
    let mut files = Vec::new();
    rust_files(&source_dir(), &mut files);
    let mut used = BTreeSet::new();
    // This folder's own tests write `tr!(` in their strings.
    let here = source_dir().join("i18n");
    for file in files.iter().filter(|f| !f.starts_with(&here)) {
        let source = std::fs::read_to_string(file).expect("source");
        for id in ids_in(&source) {
            assert!(
                english.contains(&id),
                "{}: no message {id} in messages/en",
                file.display()
            );
            used.insert(id);
        }
    }
    let unused: Vec<_> = english.difference(&used).collect();
    assert!(unused.is_empty(), "messages no code asks for: {unused:?}");
}

/// The folders and files whose every text reaches the user: the panels, the 3D view's overlays,
/// the mesh warnings' words, the recording's messages, the live description and the lessons'
/// findings. (The rest of `gui/` also speaks to scripts, the terminal and the browser: the
/// link's keys, `--bench-frames`' table, the canvas's `data-*` names; its words to the user go
/// through `tr!` too, checked by review, not by this lint.)
const UI_SOURCES: &[&str] = &[
    "gui/panels",
    "gui/view3d",
    "gui/warnings.rs",
    "gui/capture.rs",
    "gui/archive.rs",
    "lab/describe.rs",
    "lab/lessons/checks.rs",
];

/// Calls whose string is a name egui keeps a widget's state under, never shown.
const ID_CALLS: &[&str] = &[
    "Id::new(",
    "::left(",
    "::right(",
    "::top(",
    "::bottom(",
    "Grid::new(",
    "id_salt(",
    "Plot::new(",
    "Area::new(",
    "Id::unique(",
    "ComboBox::new(",
    "debug_struct(",
    ".field(",
];

/// Literals with words that are never shown: file names offered to save as, and the plots' ids
/// (given in a list, not in `Plot::new(`).
const NOT_SHOWN: &[&str] = &[
    "inertia-lab.csv",
    "frame-{:04}.png",
    "body.toml",
    "motion.glb",
    "plot-omega",
    "plot-l",
    "plot-energy",
];

/// The string literals of a line of Rust outside its comment, each with what precedes it.
fn literals(line: &str) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut chars = line.char_indices().peekable();
    while let Some((at, c)) = chars.next() {
        match c {
            '/' if line[at..].starts_with("//") => break,
            '\'' => {
                // A char literal ('"') or a lifetime: skip the char literal whole.
                let rest = &line[at + 1..];
                if let Some(end) = rest.char_indices().nth(2).map(|(i, _)| i)
                    && rest[..end].ends_with('\'')
                {
                    while chars.peek().is_some_and(|(i, _)| *i <= at + end) {
                        chars.next();
                    }
                }
            }
            '"' => {
                let mut text = String::new();
                while let Some((_, c)) = chars.next() {
                    match c {
                        '\\' => {
                            chars.next();
                        }
                        '"' => break,
                        c => text.push(c),
                    }
                }
                out.push((line[..at].to_owned(), text));
            }
            _ => {}
        }
    }
    out
}

/// Whether a literal reads as words: a run of three letters or more outside `{…}` (units such as
/// "kg", symbols such as "ω₁" and format strings such as "{name}: {:.3}" do not).
fn has_words(text: &str) -> bool {
    let mut run = 0;
    let mut placeholder = false;
    for c in text.chars() {
        match c {
            '{' => placeholder = true,
            '}' => placeholder = false,
            _ => {}
        }
        run = if c.is_alphabetic() && !placeholder {
            run + 1
        } else {
            0
        };
        if run >= 3 {
            return true;
        }
    }
    false
}

#[test]
fn no_ui_text_bypasses_the_message_files() {
    let mut files = Vec::new();
    for place in UI_SOURCES {
        let path = source_dir().join(place);
        if path.is_dir() {
            rust_files(&path, &mut files);
        } else {
            files.push(path);
        }
    }
    let mut found = Vec::new();
    for file in &files {
        let source = std::fs::read_to_string(file).expect("source");
        // Tests assert on words: everything after the file's test module is theirs.
        let code = source
            .split("\n#[cfg(test)]\nmod ")
            .next()
            .unwrap_or(&source);
        // rustfmt puts a long `tr!(`'s id on the next line.
        let mut after_tr = false;
        for (n, line) in code.lines().enumerate() {
            let trimmed = line.trim_start();
            if trimmed.starts_with("//") || trimmed.starts_with("#[") {
                continue;
            }
            let id_first = std::mem::replace(&mut after_tr, trimmed.ends_with("tr!("));
            for (k, (before, text)) in literals(line).into_iter().enumerate() {
                let asks_for_message = before.trim_end().ends_with("tr!(")
                    || (id_first && k == 0 && before.trim().is_empty());
                let names_a_widget = ID_CALLS.iter().any(|call| before.contains(call))
                    || NOT_SHOWN.contains(&text.as_str());
                if has_words(&text) && !asks_for_message && !names_a_widget {
                    found.push(format!("{}:{}: \"{text}\"", file.display(), n + 1));
                }
            }
        }
    }
    assert!(
        found.is_empty(),
        "text shown to the user must come from messages/ through tr!:\n{}",
        found.join("\n")
    );
}

#[test]
fn the_lint_finds_words_and_passes_ids_units_and_messages() {
    let line = r#"ui.label("Mass"); ui.label(tr!("body-mass")); Grid::new("help-keys"); x(" kg"); format!("{head}…{tail}") // "not this""#;
    let found: Vec<_> = literals(line)
        .into_iter()
        .filter(|(before, text)| {
            has_words(text)
                && !before.trim_end().ends_with("tr!(")
                && !ID_CALLS.iter().any(|c| before.contains(c))
        })
        .map(|(_, text)| text)
        .collect();
    assert_eq!(found, ["Mass"]);
    assert_eq!(
        ids_in(r#"tr!("a-b"), tr!( "c", x = 1), include_str!("x.toml")"#),
        ["a-b", "c"]
    );
}

#[test]
fn numbers_take_the_language_s_decimal_separator() {
    set_language(Language::German);
    assert_eq!(fixed(1.23456, 2), "1,23");
    assert_eq!(sci(1234.5, 2), "1,23e3");
    set_language(Language::Spanish);
    assert_eq!(fixed(0.5, 1), "0,5");
    set_language(Language::English);
    assert_eq!(fixed(1.23456, 2), "1.23");
    assert_eq!(parse_number("2,5"), Some(2.5));
    assert_eq!(parse_number(" 2.5 "), Some(2.5));
}

#[test]
fn messages_come_in_the_thread_s_language_with_their_values() {
    set_language(Language::German);
    assert_eq!(tr!("top-help"), "Hilfe");
    assert_eq!(
        tr!("window-title", body = "T-Griff"),
        "Inertia Lab — T-Griff"
    );
    set_language(Language::English);
    assert_eq!(tr!("top-help"), "Help");
    assert_eq!(text_in(Language::Spanish, "top-help", &[]), "Ayuda");
    // Another thread keeps its own language (tests run side by side).
    set_language(Language::Spanish);
    let other = std::thread::spawn(|| tr!("top-help"))
        .join()
        .expect("thread");
    assert_eq!(other, "Help");
    set_language(Language::English);
}

#[test]
fn tags_and_locales_name_a_language() {
    assert_eq!(Language::from_tag("de-AT"), Some(Language::German));
    assert_eq!(Language::from_tag("es_MX.UTF-8"), Some(Language::Spanish));
    assert_eq!(Language::from_tag("EN"), Some(Language::English));
    assert_eq!(Language::from_tag("fr-FR"), None);
    assert_eq!(Language::from_tag(""), None);
}
