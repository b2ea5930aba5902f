//! The `props` report: the human table ([`table`]), the JSON object ([`json`]) and the words for
//! massprops' warnings ([`words`]), which both use and `export` and `simulate` print.

pub mod json;
pub mod table;
pub mod words;

pub use json::SCHEMA_VERSION;
pub use words::warning_text;

pub(crate) use crate::wording::significant;
