//! The `props` report: the human table ([`table`]), the JSON object ([`json`]) and the words for
//! massprops' warnings ([`words`]), which both use and `export` and `simulate` print.

pub mod json;
pub mod table;
pub mod words;

pub use json::SCHEMA_VERSION;
pub use words::warning_text;

/// `v` rounded to `digits` significant digits, trailing zeros dropped (`0.2`, `7e-11`).
pub(crate) fn significant(v: f64, digits: usize) -> String {
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
