//! The fast path for OBJ: one pass over the bytes for the records nearly every mesh file is made
//! of, welding as it goes. It reads `v` (exactly three numbers), `vt` (two or three), `vn`
//! (three), `f` (three or more corners `v`, `v/vt`, `v//vn` or `v/vt/vn`, positive or negative),
//! `o`, `g`, `s`, `usemtl`, `mtllib` and comments, and declines everything else — a `w` on a
//! `v` (or colours on only some), `l` and `p`, a face of fewer than three corners, a reference to an element
//! not yet defined, a trailing comment, a lone carriage return, a byte-order mark, whitespace
//! other than spaces and tabs between words, any other keyword — so that the caller hands the
//! same bytes to `tobj`: every file either path accepts gives the same mesh bit for bit, and every
//! error message stays `tobj`'s (tested on every OBJ in the test data and the real-mesh survey).
//!
//! Numbers go through the standard library's parser (correctly rounded, and whole words only, so
//! `0x10` is declined rather than read as 0). Vertices are numbered as `tobj` followed by
//! [`weld_exact`] number them: in order of first use over all corners, identical coordinates one
//! vertex, the first one's coordinates kept.

use nalgebra::Point3;

use super::obj_parsed::{Parsed, PartRun, Records, extend_runs};
use crate::mesh::weld_exact;

/// The fast path met a line it does not read; the general reader takes the file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Declined {
    /// The line (one-based) that made it decline.
    pub line: usize,
}

/// The state of one pass: fed whole lines, block by block.
pub(super) struct FastObj {
    /// The file's `v` records, in order.
    vertices: Vec<Point3<f64>>,
    /// For each file vertex, its rank in order of first use once a face has used it.
    first_use: Vec<u32>,
    /// How many vertices faces have used.
    used: u32,
    texcoords: usize,
    normals: usize,
    /// Whether the vertices carry colours, once the first is read.
    coloured: Option<bool>,
    indices: Vec<u32>,
    arities: Vec<usize>,
    face_lines: Vec<u32>,
    records: Records,
    runs: Vec<PartRun>,
    object: u32,
    group: u32,
    /// Lines read so far.
    line: usize,
}

const UNUSED: u32 = u32::MAX;

impl FastObj {
    /// A pass over a file of about `bytes` bytes (the size sets the first capacities).
    pub fn new(bytes: usize) -> Self {
        // A typical mesh line is 25–40 bytes, with about two faces per vertex.
        let vertices = bytes / 80;
        Self {
            vertices: Vec::with_capacity(vertices),
            first_use: Vec::with_capacity(vertices),
            used: 0,
            texcoords: 0,
            normals: 0,
            coloured: None,
            indices: Vec::with_capacity(6 * vertices),
            arities: Vec::with_capacity(2 * vertices),
            face_lines: Vec::with_capacity(2 * vertices),
            records: Records::new(),
            runs: Vec::new(),
            object: 0,
            group: 0,
            line: 0,
        }
    }

    /// Reads whole lines: `text` ends just after a `\n`, or is the file's last line. The first
    /// block must be the start of the file.
    pub fn feed(&mut self, text: &str) -> Result<(), Declined> {
        if self.line == 0 && text.starts_with('\u{FEFF}') {
            return Err(Declined { line: 1 });
        }
        let bytes = text.as_bytes();
        let mut start = 0;
        while start < bytes.len() {
            let end = memchr::memchr(b'\n', &bytes[start..]).map_or(bytes.len(), |k| start + k);
            self.line += 1;
            let line = &text[start..end];
            // `tobj` reads lines as `BufRead::lines` does: one `\r` before the `\n` goes too.
            let line = line.strip_suffix('\r').unwrap_or(line);
            self.line_record(line)
                .map_err(|()| Declined { line: self.line })?;
            start = end + 1;
        }
        Ok(())
    }

    /// The mesh: welded positions, faces and their lines, and the parts.
    pub fn finish(self) -> Parsed {
        // The used vertices in order of first use: scattered once here (writes in any order
        // are cheap) rather than gathered at each first use (a cache miss per vertex).
        let mut used = vec![Point3::origin(); self.used as usize];
        for (p, &rank) in self.vertices.iter().zip(&self.first_use) {
            if rank != UNUSED {
                used[rank as usize] = *p;
            }
        }
        let (positions, remap) = weld_exact(&used);
        let mut indices = self.indices;
        // Most files have no two vertices at the same place: nothing to renumber.
        if positions.len() < used.len() {
            for i in &mut indices {
                *i = remap[*i as usize];
            }
        }
        Parsed {
            positions,
            indices,
            arities: self.arities,
            face_lines: self.face_lines,
            records: self.records,
            runs: self.runs,
            two_corner: Vec::new(),
        }
    }

    fn line_record(&mut self, line: &str) -> Result<(), ()> {
        let mut words = Words::new(line);
        let Some(keyword) = words.next() else {
            return Ok(());
        };
        match keyword {
            "v" => {
                let p = [words.number()?, words.number()?, words.number()?];
                // Vertex colours (`v x y z r g b`, ignored here) only when every vertex has
                // them: `tobj` refuses a face on a vertex without colours once any has some.
                let coloured = words.peek().is_some();
                if coloured {
                    for _ in 0..3 {
                        words.number()?;
                    }
                }
                words.end()?;
                if *self.coloured.get_or_insert(coloured) != coloured {
                    return Err(());
                }
                self.vertices.push(Point3::from(p));
                self.first_use.push(UNUSED);
            }
            "vt" => {
                words.number()?;
                words.number()?;
                if words.peek().is_some() {
                    words.number()?;
                }
                words.end()?;
                self.texcoords += 1;
            }
            "vn" => {
                for _ in 0..3 {
                    words.number()?;
                }
                words.end()?;
                self.normals += 1;
            }
            "f" => self.face(words.rest)?,
            "o" | "g" => {
                plain(line)?;
                // As the records scan names them: the rest of the line, trimmed.
                let name = line.trim_ascii_start()[1..].trim_ascii().to_owned();
                if keyword == "o" {
                    self.records.objects.push(name);
                    self.object = (self.records.objects.len() - 1) as u32;
                } else {
                    self.records.groups.push(name);
                    self.group = (self.records.groups.len() - 1) as u32;
                }
            }
            "s" | "mtllib" => plain(line)?,
            "usemtl" => {
                plain(line)?;
                // `tobj` takes the name after the line's first space and refuses an empty one.
                let name = line.split_once(' ').map_or("", |(_, n)| n.trim());
                if name.is_empty() {
                    return Err(());
                }
            }
            comment if comment.starts_with('#') => plain(line)?,
            _ => return Err(()),
        }
        Ok(())
    }

    /// An `f` record; `rest` is the line after its keyword.
    fn face(&mut self, rest: &str) -> Result<(), ()> {
        let bytes = rest.as_bytes();
        let first = self.indices.len();
        let mut at = 0;
        loop {
            while at < bytes.len() && (bytes[at] == b' ' || bytes[at] == b'\t') {
                at += 1;
            }
            if at == bytes.len() {
                break;
            }
            let (v, next) = index(bytes, at, self.vertices.len())?;
            at = next;
            // Then `/vt`, `/vt/vn` or `//vn`, each pointing at an element already defined.
            for (part, count) in [self.texcoords, self.normals].into_iter().enumerate() {
                if bytes.get(at) != Some(&b'/') {
                    break;
                }
                at += 1;
                if part == 0 && bytes.get(at) == Some(&b'/') {
                    continue;
                }
                at = index(bytes, at, count)?.1;
            }
            if at < bytes.len() && bytes[at] != b' ' && bytes[at] != b'\t' {
                return Err(());
            }
            let id = match self.first_use[v] {
                UNUSED => {
                    let id = self.used;
                    self.used += 1;
                    self.first_use[v] = id;
                    id
                }
                id => id,
            };
            self.indices.push(id);
        }
        let corners = self.indices.len() - first;
        if corners < 3 {
            return Err(());
        }
        extend_runs(&mut self.runs, self.arities.len(), self.object, self.group);
        self.arities.push(corners);
        self.face_lines.push(self.line as u32);
        Ok(())
    }
}

/// A line whose words are not read: a carriage return inside it would end it for some readers
/// and not for others.
fn plain(line: &str) -> Result<(), ()> {
    if line.contains('\r') { Err(()) } else { Ok(()) }
}

/// The OBJ index (one-based, or negative from the end) at `bytes[at..]` into the `count` elements
/// defined so far, as a zero-based index, and where it ends; `Err` when there is none there or
/// it points at nothing yet.
fn index(bytes: &[u8], mut at: usize, count: usize) -> Result<(usize, usize), ()> {
    let negative = sign(bytes, &mut at);
    let start = at;
    let mut n: usize = 0;
    while let Some(&b) = bytes.get(at) {
        if !b.is_ascii_digit() {
            break;
        }
        // Beyond ten digits no file has that many elements (and `tobj` would fail to parse).
        if at - start == 10 {
            return Err(());
        }
        n = n * 10 + usize::from(b - b'0');
        at += 1;
    }
    if at == start || n == 0 || n > count {
        return Err(());
    }
    Ok((if negative { count - n } else { n - 1 }, at))
}

/// A whole word as an `f64`, correctly rounded: what `str::parse` gives, bit for bit, and `None`
/// where it fails.
///
/// The numbers a mesh file holds (`-0.0503644`, `1.25e-3`) take Clinger's fast path: a decimal
/// of at most 19 digits whose integer mantissa m ≤ 2⁵³ and whose power of ten |k| ≤ 22 is m·10ᵏ
/// or m/10⁻ᵏ, both operands exact in f64, so one IEEE operation rounds it correctly (W. D.
/// Clinger, "How to Read Floating Point Numbers Accurately", PLDI 1990). Every other word goes to
/// the standard library's parser (Eisel–Lemire with a big-number fallback).
pub(super) fn number(word: &str) -> Option<f64> {
    fast_decimal(word.as_bytes()).or_else(|| word.parse().ok())
}

/// The fast path of [`number`]; `None` sends the word to the full parser.
fn fast_decimal(bytes: &[u8]) -> Option<f64> {
    const POWERS: [f64; 23] = [
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
        1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
    ];
    let mut at = 0;
    let negative = sign(bytes, &mut at);
    let mut mantissa: u64 = 0;
    // Significant digits (leading zeros add none); wrapping is harmless past 19, declined below.
    let mut digits = 0;
    let mut run = |at: &mut usize| {
        let start = *at;
        while let Some(&b) = bytes.get(*at).filter(|b| b.is_ascii_digit()) {
            if mantissa != 0 || b != b'0' {
                digits += 1;
            }
            mantissa = mantissa.wrapping_mul(10).wrapping_add(u64::from(b - b'0'));
            *at += 1;
        }
        *at - start
    };
    let whole = run(&mut at);
    let mut fraction = 0;
    if bytes.get(at) == Some(&b'.') {
        at += 1;
        fraction = run(&mut at);
    }
    let mut exponent = -(fraction as i32);
    if whole + fraction == 0 || digits > 19 {
        return None;
    }
    if matches!(bytes.get(at), Some(b'e' | b'E')) {
        at += 1;
        let negative_exponent = sign(bytes, &mut at);
        let start = at;
        let mut e: i32 = 0;
        while let Some(&b) = bytes.get(at) {
            if !b.is_ascii_digit() || at - start >= 4 {
                break;
            }
            e = e * 10 + i32::from(b - b'0');
            at += 1;
        }
        if at == start {
            return None;
        }
        exponent += if negative_exponent { -e } else { e };
    }
    if at != bytes.len() || mantissa > 1 << 53 {
        return None;
    }
    let m = mantissa as f64;
    let value = match exponent {
        0..=22 => m * POWERS[exponent as usize],
        -22..=-1 => m / POWERS[(-exponent) as usize],
        _ => return None,
    };
    Some(if negative { -value } else { value })
}

/// Whether a `-` is at `bytes[*at]`; a sign, `+` or `-`, is stepped over.
fn sign(bytes: &[u8], at: &mut usize) -> bool {
    match bytes.get(*at) {
        Some(b'-') => {
            *at += 1;
            true
        }
        Some(b'+') => {
            *at += 1;
            false
        }
        _ => false,
    }
}

/// The words of a line, split at spaces and tabs only.
struct Words<'a> {
    rest: &'a str,
}

impl<'a> Words<'a> {
    fn new(line: &'a str) -> Self {
        Self { rest: line }
    }

    fn peek(&self) -> Option<&'a str> {
        let mut copy = Words { rest: self.rest };
        copy.next()
    }

    /// The next word as a number.
    fn number(&mut self) -> Result<f64, ()> {
        number(self.next().ok_or(())?).ok_or(())
    }

    /// No word is left.
    fn end(&mut self) -> Result<(), ()> {
        if self.next().is_some() {
            Err(())
        } else {
            Ok(())
        }
    }
}

impl<'a> Iterator for Words<'a> {
    type Item = &'a str;

    fn next(&mut self) -> Option<&'a str> {
        let bytes = self.rest.as_bytes();
        let start = bytes.iter().position(|&b| b != b' ' && b != b'\t')?;
        let end = bytes[start..]
            .iter()
            .position(|&b| b == b' ' || b == b'\t')
            .map_or(bytes.len(), |k| start + k);
        let word = &self.rest[start..end];
        self.rest = &self.rest[end..];
        Some(word)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn numbers_are_the_standard_parsers_bit_for_bit() {
        for word in [
            "0",
            "-0",
            "+0",
            "-0.0503644",
            "0.032027",
            "1.",
            ".5",
            "-.5",
            "1e5",
            "1E-5",
            "1e+22",
            "1e23",
            "9007199254740993",
            "12345678901234567890",
            "0.1",
            "3.4028235e38",
            "1e-400",
            "inf",
            "-infinity",
            "NaN",
            "0x10",
            "1e",
            "e5",
            ".",
            "-",
            "1.2.3",
            "1e99999",
            "00000001",
            "0.000000000000000000000000001",
            "123456789012345678",
            "4.9e-324",
            "1_0",
        ] {
            let ours = number(word).map(f64::to_bits);
            let std = word.parse::<f64>().ok().map(f64::to_bits);
            assert_eq!(ours, std, "{word}");
        }
    }

    proptest! {
        /// Decimal words of every shape the fast path takes or hands on.
        #[test]
        fn any_decimal_word_parses_as_the_standard_parser_does(
            sign in "[-+]?",
            whole in "[0-9]{0,12}",
            fraction in proptest::option::of("[0-9]{0,12}"),
            exponent in proptest::option::of((prop::sample::select(vec!["e", "E"]), "[-+]?", "[0-9]{1,3}")),
        ) {
            let mut word = format!("{sign}{whole}");
            if let Some(f) = &fraction {
                word.push('.');
                word.push_str(f);
            }
            if let Some((e, s, d)) = &exponent {
                word.push_str(e);
                word.push_str(s);
                word.push_str(d);
            }
            let ours = number(&word).map(f64::to_bits);
            let std = word.parse::<f64>().ok().map(f64::to_bits);
            prop_assert_eq!(ours, std, "{}", word);
        }

        /// Any f64 written the shortest way, or with a fixed number of digits, reads back.
        #[test]
        fn written_numbers_read_back(x in proptest::num::f64::NORMAL | proptest::num::f64::SUBNORMAL | proptest::num::f64::ZERO, digits in 0usize..18) {
            for word in [format!("{x}"), format!("{x:e}"), format!("{x:.digits$}"), format!("{x:.digits$e}")] {
                let ours = number(&word).map(f64::to_bits);
                let std = word.parse::<f64>().ok().map(f64::to_bits);
                prop_assert_eq!(ours, std, "{}", word);
            }
        }
    }
}
