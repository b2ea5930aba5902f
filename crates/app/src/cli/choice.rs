//! A flag whose values are one of `inertia_io`'s [`Choice`] lists: the names and their help
//! lines come from the list, so a value added there is a value of the flag.

use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
use inertia_io::choice::{self, Choice};

/// The value parser of a flag taking one value of `T`.
pub fn choice<T: Choice + Clone + Send + Sync>() -> impl TypedValueParser<Value = T> {
    PossibleValuesParser::new(
        T::ALL
            .iter()
            .map(|v| PossibleValue::new(v.name()).help(v.help())),
    )
    .try_map(|name| choice::parse::<T>(&name))
}
