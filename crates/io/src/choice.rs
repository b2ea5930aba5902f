//! Options with a fixed list of values (an export format, a frame, an up axis): each value's
//! name, as the command line, the app and the Python package spell it, and a line saying what it
//! is. Every front end reads the one list, so adding a value is one entry in it; the command
//! line builds its flags from it without this crate knowing any command line.

use std::fmt;

/// An option whose values are listed once, with their names and a line of help each.
pub trait Choice: Copy + 'static {
    /// What the option is called in messages ("format", "up").
    const OPTION: &'static str;
    /// Every value, in the order the help lists them.
    const ALL: &'static [Self];
    /// The value's name (`urdf`, `com-principal`).
    fn name(self) -> &'static str;
    /// One line saying what the value is.
    fn help(self) -> &'static str;
}

/// The value of `T` named `name`, or an error listing the names there are.
pub fn parse<T: Choice>(name: &str) -> Result<T, UnknownChoice> {
    T::ALL
        .iter()
        .copied()
        .find(|v| v.name() == name)
        .ok_or_else(|| UnknownChoice {
            option: T::OPTION,
            given: name.to_owned(),
            names: T::ALL.iter().map(|v| v.name()).collect(),
        })
}

/// A name that is none of an option's values.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub struct UnknownChoice {
    /// The option ("format").
    pub option: &'static str,
    /// The name given.
    pub given: String,
    /// The names there are.
    pub names: Vec<&'static str>,
}

impl fmt::Display for UnknownChoice {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} must be one of {}; not {:?}",
            self.option,
            self.names.join(", "),
            self.given
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::export::{Format, Frame, UpAxis};

    /// Every value reads back from its own name, and the names are distinct.
    fn round_trips<T: Choice + PartialEq + fmt::Debug>() {
        for &v in T::ALL {
            assert_eq!(parse::<T>(v.name()), Ok(v));
            assert!(!v.help().is_empty(), "{v:?} has no help");
        }
        let mut names: Vec<_> = T::ALL.iter().map(|v| v.name()).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), T::ALL.len(), "{} names repeat", T::OPTION);
    }

    #[test]
    fn every_value_is_read_back_from_its_name() {
        round_trips::<Format>();
        round_trips::<Frame>();
        round_trips::<UpAxis>();
        assert_eq!(Format::ALL.len(), 15);
    }

    #[test]
    fn an_unknown_name_lists_the_names_there_are() {
        let e = parse::<UpAxis>("w").err().map(|e| e.to_string());
        assert_eq!(e.as_deref(), Some("up must be one of y, z; not \"w\""));
    }
}
