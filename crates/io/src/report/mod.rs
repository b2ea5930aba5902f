//! The reports every front end prints: `props`' human table ([`table`]) and JSON object
//! ([`json`]), the words for massprops' warnings ([`words`]), which both use and `export` and
//! `simulate` print, and `audit`'s table and JSON ([`audit`]) with the words for its findings
//! ([`findings`]), which the app's Robot section shows too.

pub mod audit;
pub mod findings;
pub mod json;
pub mod table;
pub mod words;

pub use json::SCHEMA_VERSION;
pub use words::warning_text;

pub(crate) use crate::wording::significant;
