//! Formatting shared by every front end's words (the command line's report, the app's panels):
//! how a face and its file line, and a list of indices, are written. What each front end says
//! around them stays its own.

/// One face as "12" or "12 (line 40)": zero-based, with its one-based file line where the file
/// has lines (`lines[f]` is face f's).
pub fn face_line(f: usize, lines: &[u32]) -> String {
    match lines.get(f) {
        Some(line) => format!("{f} (line {line})"),
        None => f.to_string(),
    }
}

/// Indices as "1, 4, 9".
pub fn list(indices: &[usize]) -> String {
    indices
        .iter()
        .map(usize::to_string)
        .collect::<Vec<_>>()
        .join(", ")
}

/// Words joined as alternatives: "a", "a or b", "a, b or c".
pub fn alternatives<S: AsRef<str>>(words: &[S]) -> String {
    match words {
        [] => String::new(),
        [one] => one.as_ref().to_owned(),
        [rest @ .., last] => {
            let rest: Vec<&str> = rest.iter().map(AsRef::as_ref).collect();
            format!("{} or {}", rest.join(", "), last.as_ref())
        }
    }
}

/// `v` rounded to `digits` significant digits, trailing zeros dropped (`0.2`, `7e-11`).
pub fn significant(v: f64, digits: usize) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let exponent = v.abs().log10().floor();
    if (-4.0..15.0).contains(&exponent) {
        let decimals = digits as f64 - 1.0 - exponent;
        let text = if decimals >= 0.0 {
            format!("{v:.prec$}", prec = decimals as usize)
        } else {
            // More integer digits than significant ones: round the extra ones away.
            let unit = 10f64.powf(-decimals);
            format!("{:.0}", (v / unit).round() * unit)
        };
        if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.').to_owned()
        } else {
            text
        }
    } else {
        let text = format!("{v:.prec$e}", prec = digits - 1);
        let (mantissa, exp) = text.split_once('e').unwrap_or((&text, "0"));
        let mantissa = if mantissa.contains('.') {
            mantissa.trim_end_matches('0').trim_end_matches('.')
        } else {
            mantissa
        };
        format!("{mantissa}e{exp}")
    }
}

/// A count as "5.23 M", "871 k" or "950".
pub fn millions(n: usize) -> String {
    match n {
        0..1_000 => n.to_string(),
        1_000..1_000_000 => format!("{} k", significant(n as f64 / 1e3, 3)),
        _ => format!("{} M", significant(n as f64 / 1e6, 3)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn faces_name_their_line_when_the_file_has_lines() {
        assert_eq!(face_line(2, &[10, 11, 40]), "2 (line 40)");
        assert_eq!(face_line(3, &[10, 11, 40]), "3");
        assert_eq!(face_line(0, &[]), "0");
        assert_eq!(list(&[1, 4, 9]), "1, 4, 9");
        assert_eq!(list(&[]), "");
    }

    #[test]
    fn counts_read_in_thousands_and_millions() {
        assert_eq!(millions(950), "950");
        assert_eq!(millions(871_414), "871 k");
        assert_eq!(millions(5_227_836), "5.23 M");
    }
}
