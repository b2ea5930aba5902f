//! The app's words in the user's language: every text the window, the page and the live
//! description show comes from the Fluent message files in `crates/app/messages/<code>/`
//! (Project Fluent's syntax, <https://projectfluent.org/fluent/guide/>), through the crate's own
//! macro `tr!`.
//!
//! One file a panel in each language, the same ids in each (`tests` checks it); English is the
//! reference. The language is the one the user chose (the settings), else the system's or the
//! browser's (`sys-locale`), else English. It is a thread's own: the app sets it once a frame
//! from its settings, so that tests running side by side in one process cannot change each
//! other's words.
//!
//! Numbers shown as words use the language's decimal separator ([`fixed`], [`sci`]); a float is
//! never handed to a message as such ([`Arg`] has no `f64`), so none slips through in the C
//! locale. The files the lab writes (CSV, JSON) and the command line stay in the C locale and in
//! English: they are read by programs.

use std::cell::{Cell, OnceCell};

use fluent_bundle::{FluentArgs, FluentBundle, FluentResource, FluentValue};
use serde::{Deserialize, Serialize};

#[cfg(test)]
mod tests;

/// A language the app speaks completely.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
pub enum Language {
    /// English, the reference.
    #[default]
    #[serde(rename = "en")]
    English,
    /// German.
    #[serde(rename = "de")]
    German,
    /// Spanish.
    #[serde(rename = "es")]
    Spanish,
}

impl Language {
    /// Every language, in the order the menu lists them.
    pub const ALL: [Language; 3] = [Language::English, Language::German, Language::Spanish];

    /// The language's BCP 47 code (`?lang=`, `--lang`, `data-lang`, the message folder).
    pub fn code(self) -> &'static str {
        match self {
            Language::English => "en",
            Language::German => "de",
            Language::Spanish => "es",
        }
    }

    /// The language's name in itself, as a menu of languages lists it.
    pub fn endonym(self) -> &'static str {
        match self {
            Language::English => "English",
            Language::German => "Deutsch",
            Language::Spanish => "Español",
        }
    }

    /// The language of a BCP 47 tag or a POSIX locale (`de`, `de-AT`, `es_MX.UTF-8`), if the app
    /// speaks it.
    pub fn from_tag(tag: &str) -> Option<Language> {
        let primary = tag
            .split(['-', '_', '.', '@'])
            .next()
            .unwrap_or("")
            .to_ascii_lowercase();
        Language::ALL.into_iter().find(|l| l.code() == primary)
    }

    /// The system's language (the desktop's locale, the browser's `navigator.language`), or
    /// English when the app does not speak it.
    pub fn of_system() -> Language {
        sys_locale::get_locales()
            .find_map(|tag| Language::from_tag(&tag))
            .unwrap_or_default()
    }

    /// Whether the language writes a decimal comma (3,14) rather than a point.
    fn decimal_comma(self) -> bool {
        matches!(self, Language::German | Language::Spanish)
    }

    fn index(self) -> usize {
        self as usize
    }
}

/// Every message file, by name: one a panel or subject, the same names in every language.
macro_rules! message_files {
    ($($name:literal),+ $(,)?) => {
        /// Each message file's name and its text in each language of [`Language::ALL`].
        pub(crate) const MESSAGE_FILES: &[(&str, [&str; 3])] = &[$((
            $name,
            [
                include_str!(concat!("../../messages/en/", $name, ".ftl")),
                include_str!(concat!("../../messages/de/", $name, ".ftl")),
                include_str!(concat!("../../messages/es/", $name, ".ftl")),
            ],
        )),+];
    };
}

message_files![
    "app",
    "lab",
    "checks",
    "display",
    "platform",
    "panels",
    "body",
    "compare",
    "diagnostics",
    "interaction",
    "motion",
    "parts",
    "robot",
    "table",
    "plots",
    "sphere",
    "lessons",
    "help",
    "toolbar",
    "describe",
    "warnings",
    "view3d",
    "capture",
    "link",
];

thread_local! {
    static LANGUAGE: Cell<Language> = const { Cell::new(Language::English) };
    static BUNDLES: OnceCell<Vec<FluentBundle<FluentResource>>> = const { OnceCell::new() };
}

/// Makes `language` the one this thread's words are in.
pub fn set_language(language: Language) {
    LANGUAGE.with(|l| l.set(language));
}

/// The language this thread's words are in.
pub fn language() -> Language {
    LANGUAGE.with(Cell::get)
}

/// A value given to a message: words, or a whole number (which a message may select a plural
/// form by). A float is formatted first, with [`fixed`] or [`sci`].
#[derive(Debug, Clone, PartialEq)]
pub enum Arg {
    /// Words or a number already formatted.
    Text(String),
    /// A count.
    Count(i64),
}

impl From<String> for Arg {
    fn from(s: String) -> Self {
        Arg::Text(s)
    }
}

impl From<&str> for Arg {
    fn from(s: &str) -> Self {
        Arg::Text(s.to_owned())
    }
}

impl From<&String> for Arg {
    fn from(s: &String) -> Self {
        Arg::Text(s.clone())
    }
}

impl From<usize> for Arg {
    fn from(n: usize) -> Self {
        Arg::Count(i64::try_from(n).unwrap_or(i64::MAX))
    }
}

impl From<i64> for Arg {
    fn from(n: i64) -> Self {
        Arg::Count(n)
    }
}

impl From<u32> for Arg {
    fn from(n: u32) -> Self {
        Arg::Count(n.into())
    }
}

impl From<i32> for Arg {
    fn from(n: i32) -> Self {
        Arg::Count(n.into())
    }
}

/// The message `id` in this thread's language with `args` filled in; the English one where the
/// language lacks it (the tests make sure none does), the id itself where English lacks it too.
pub fn text(id: &str, args: &[(&str, Arg)]) -> String {
    text_in(language(), id, args)
}

/// The message `id` in `language`.
pub fn text_in(language: Language, id: &str, args: &[(&str, Arg)]) -> String {
    BUNDLES.with(|cell| {
        let bundles = cell.get_or_init(bundles);
        let mut fluent_args = FluentArgs::new();
        for (name, value) in args {
            match value {
                Arg::Text(s) => fluent_args.set(*name, FluentValue::from(s.as_str())),
                Arg::Count(n) => fluent_args.set(*name, FluentValue::from(*n)),
            }
        }
        for bundle in [&bundles[language.index()], &bundles[0]] {
            if let Some(pattern) = bundle.get_message(id).and_then(|m| m.value()) {
                let mut errors = Vec::new();
                return bundle
                    .format_pattern(pattern, Some(&fluent_args), &mut errors)
                    .into_owned();
            }
        }
        id.to_owned()
    })
}

/// Every language's bundle of every message file, in [`Language::ALL`]'s order.
fn bundles() -> Vec<FluentBundle<FluentResource>> {
    Language::ALL
        .into_iter()
        .map(|language| {
            let tag = language
                .code()
                .parse()
                .unwrap_or_else(|_| unic_langid::LanguageIdentifier::default());
            let mut bundle = FluentBundle::new(vec![tag]);
            // Unicode isolation marks around each value: egui's fonts draw them as boxes, and
            // none of these languages is written right to left.
            bundle.set_use_isolating(false);
            for (_, texts) in MESSAGE_FILES {
                // A file that does not parse keeps what did; the tests refuse any error.
                let resource = FluentResource::try_new(texts[language.index()].to_owned())
                    .unwrap_or_else(|(partial, _)| partial);
                // Ids are unique across the files (tested), so nothing is overridden.
                bundle.add_resource_overriding(resource);
            }
            bundle
        })
        .collect()
}

/// `x` with `decimals` digits after the separator of this thread's language ("3,14" in German).
pub fn fixed(x: f64, decimals: usize) -> String {
    localize(format!("{x:.decimals$}"))
}

/// `x` in scientific notation with `decimals` digits after the separator ("1,2346e3").
pub fn sci(x: f64, decimals: usize) -> String {
    localize(format!("{x:.decimals$e}"))
}

/// A number written in the C locale, with this thread's language's decimal separator.
pub fn localize(c_locale: String) -> String {
    if language().decimal_comma() {
        c_locale.replace('.', ",")
    } else {
        c_locale
    }
}

/// A number typed in this thread's language (a decimal comma or a point), if it is one.
pub fn parse_number(typed: &str) -> Option<f64> {
    typed.trim().replace(',', ".").parse().ok()
}

/// The message `id` in this thread's language, with named values: `tr!("id")`,
/// `tr!("id", mass = sci(m, 4), count = n)`.
macro_rules! tr {
    ($id:literal) => {
        $crate::i18n::text($id, &[])
    };
    ($id:literal, $($name:ident = $value:expr),+ $(,)?) => {
        $crate::i18n::text(
            $id,
            &[$((stringify!($name), $crate::i18n::Arg::from($value))),+],
        )
    };
}
pub(crate) use tr;
