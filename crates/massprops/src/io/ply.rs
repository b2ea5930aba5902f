//! Stanford PLY (Greg Turk's polygon file format, 1994, as Paul Bourke's description of it and
//! the RPly and tinyply readers take it): a header of elements, each with a count and typed
//! properties, then their records in ASCII or binary, little- or big-endian.
//!
//! The `vertex` element's `x`, `y` and `z` (any numeric type; doubles stay doubles) and the
//! `face` element's index list (`vertex_indices` or `vertex_index`, any count and index type)
//! make the mesh; every other property and element (normals, colours, edges, materials) is read
//! past. Polygons stay polygons; positions are welded exactly, as OBJ and STL are. A file with
//! vertices and no faces is a point cloud, which encloses nothing, and is refused as one.

use std::path::Path;

use nalgebra::Point3;

use super::MeshFile;
use crate::diagnostics::EXAMPLES;
use crate::mesh::weld_exact;
use crate::{Defect, MeshError, PolyMesh, Warning};

/// Reads a PLY file already in memory; `path` names it in messages.
///
/// # Errors
/// The header or a record does not follow the format (the message names the line, or for a
/// binary file the byte offset, and the element), an index names no vertex, a coordinate is not
/// finite, or the file has no faces.
pub fn parse_ply(bytes: &[u8], path: &Path) -> Result<MeshFile, MeshError> {
    let bad = |line: Option<usize>, message: String| MeshError::Malformed {
        path: path.to_path_buf(),
        line,
        message,
    };
    let header = header(bytes).map_err(|(line, message)| bad(Some(line), message))?;
    let mut body = match header.encoding {
        Encoding::Ascii => {
            let text = std::str::from_utf8(&bytes[header.body..])
                .map_err(|e| bad(None, format!("the ASCII data is not text: {e}")))?;
            Body::Ascii(Tokens::new(text, header.lines + 1))
        }
        Encoding::Binary { little } => Body::Binary {
            bytes,
            at: header.body,
            little,
        },
    };
    let mut mesh = Read::default();
    for element in &header.elements {
        read_element(element, &mut body, &mut mesh)
            .map_err(|(line, message)| bad(line, message))?;
    }
    finish(mesh, path)
}

/// How the records are written.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Encoding {
    Ascii,
    Binary { little: bool },
}

/// A property's number type.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Scalar {
    /// The type a header names, in either spelling (`uchar` or `uint8`).
    fn named(name: &str) -> Option<Scalar> {
        Some(match name {
            "char" | "int8" => Scalar::I8,
            "uchar" | "uint8" => Scalar::U8,
            "short" | "int16" => Scalar::I16,
            "ushort" | "uint16" => Scalar::U16,
            "int" | "int32" => Scalar::I32,
            "uint" | "uint32" => Scalar::U32,
            "float" | "float32" => Scalar::F32,
            "double" | "float64" => Scalar::F64,
            _ => return None,
        })
    }

    fn size(self) -> usize {
        match self {
            Scalar::I8 | Scalar::U8 => 1,
            Scalar::I16 | Scalar::U16 => 2,
            Scalar::I32 | Scalar::U32 | Scalar::F32 => 4,
            Scalar::F64 => 8,
        }
    }
}

/// One property of an element.
#[derive(Debug, Clone, PartialEq)]
enum Property {
    /// One number.
    Scalar { name: String, ty: Scalar },
    /// A count, then that many numbers.
    List {
        name: String,
        count: Scalar,
        item: Scalar,
    },
}

/// An element of the header: its records' count and layout.
#[derive(Debug, Clone, PartialEq)]
struct Element {
    name: String,
    count: usize,
    properties: Vec<Property>,
}

/// What the header says, and where the data begins.
#[derive(Debug)]
struct Header {
    encoding: Encoding,
    elements: Vec<Element>,
    /// The byte offset of the first record.
    body: usize,
    /// The header's lines (the data's first line is the next).
    lines: usize,
}

/// A problem at a line (the header's).
type LineError = (usize, String);

/// Reads the header, up to and including `end_header`.
fn header(bytes: &[u8]) -> Result<Header, LineError> {
    let (mut at, mut lines) = (0, 0);
    // The next line (without its end), counting lines and bytes.
    let next_line = |at: &mut usize, lines: &mut usize| -> Option<&str> {
        let rest = bytes.get(*at..)?;
        let end = rest.iter().position(|&b| b == b'\n')?;
        *at += end + 1;
        *lines += 1;
        let line = std::str::from_utf8(&rest[..end]).unwrap_or("\u{FFFD}");
        Some(line.trim_end_matches('\r'))
    };
    if next_line(&mut at, &mut lines) != Some("ply") {
        return Err((
            1,
            "not a PLY file: it does not start with the line \"ply\"".to_owned(),
        ));
    }
    let mut encoding = None;
    let mut elements: Vec<Element> = Vec::new();
    loop {
        let line_number = lines + 1;
        let Some(line) = next_line(&mut at, &mut lines) else {
            return Err((line_number, "the header has no end_header line".to_owned()));
        };
        let bad = |what: &str| Err((line_number, format!("{what}: {line:?}")));
        let words: Vec<&str> = line.split_ascii_whitespace().collect();
        match words.as_slice() {
            ["end_header"] => break,
            [] | ["comment" | "obj_info", ..] => {}
            ["format", kind, "1.0"] => {
                encoding = Some(match *kind {
                    "ascii" => Encoding::Ascii,
                    "binary_little_endian" => Encoding::Binary { little: true },
                    "binary_big_endian" => Encoding::Binary { little: false },
                    _ => return bad("an unknown format"),
                });
            }
            ["element", name, count] => match count.parse() {
                Ok(count) => elements.push(Element {
                    name: (*name).to_owned(),
                    count,
                    properties: Vec::new(),
                }),
                Err(_) => return bad("an element count that is not a whole number"),
            },
            ["property", "list", count, item, name] => {
                let (Some(count), Some(item)) = (Scalar::named(count), Scalar::named(item)) else {
                    return bad("a list property of an unknown type");
                };
                if matches!(count, Scalar::F32 | Scalar::F64) {
                    return bad("a list whose count is not an integer type");
                }
                let Some(element) = elements.last_mut() else {
                    return bad("a property before any element");
                };
                element.properties.push(Property::List {
                    name: (*name).to_owned(),
                    count,
                    item,
                });
            }
            ["property", ty, name] => {
                let Some(ty) = Scalar::named(ty) else {
                    return bad("a property of an unknown type");
                };
                let Some(element) = elements.last_mut() else {
                    return bad("a property before any element");
                };
                element.properties.push(Property::Scalar {
                    name: (*name).to_owned(),
                    ty,
                });
            }
            _ => return bad("a header line that is not PLY"),
        }
    }
    let encoding = encoding.ok_or((lines, "the header names no format".to_owned()))?;
    Ok(Header {
        encoding,
        elements,
        body: at,
        lines,
    })
}

/// The records: whitespace-separated numbers, or bytes.
enum Body<'a> {
    Ascii(Tokens<'a>),
    Binary {
        bytes: &'a [u8],
        at: usize,
        little: bool,
    },
}

/// The ASCII data's numbers, one at a time, with their lines.
struct Tokens<'a> {
    /// The data's length in bytes.
    left: usize,
    lines: std::str::Lines<'a>,
    words: std::str::SplitAsciiWhitespace<'a>,
    /// The line of the last number read.
    line: usize,
}

impl<'a> Tokens<'a> {
    fn new(text: &'a str, first_line: usize) -> Self {
        Self {
            left: text.len(),
            lines: text.lines(),
            words: "".split_ascii_whitespace(),
            line: first_line - 1,
        }
    }

    fn next(&mut self) -> Option<&'a str> {
        loop {
            if let Some(word) = self.words.next() {
                return Some(word);
            }
            self.words = self.lines.next()?.split_ascii_whitespace();
            self.line += 1;
        }
    }
}

/// A problem in the data: its line (ASCII) or none (binary: the message gives the offset).
type DataError = (Option<usize>, String);

impl Body<'_> {
    /// The next number, of type `ty`.
    fn value(&mut self, ty: Scalar, what: &dyn Fn() -> String) -> Result<f64, DataError> {
        match self {
            Body::Ascii(tokens) => {
                let Some(word) = tokens.next() else {
                    return Err((None, format!("the data ends inside {}", what())));
                };
                let value: f64 = word.parse().map_err(|_| {
                    (
                        Some(tokens.line),
                        format!("{word:?} is not a number, in {}", what()),
                    )
                })?;
                let integral = !matches!(ty, Scalar::F32 | Scalar::F64);
                if integral && value.fract() != 0.0 {
                    return Err((
                        Some(tokens.line),
                        format!("{word:?} is not a whole number, in {}", what()),
                    ));
                }
                Ok(value)
            }
            Body::Binary { bytes, at, little } => {
                let n = ty.size();
                let Some(b) = bytes.get(*at..*at + n) else {
                    return Err((
                        None,
                        format!("the file ends at byte {} inside {}", bytes.len(), what()),
                    ));
                };
                *at += n;
                Ok(binary_value(b, ty, *little))
            }
        }
    }

    /// How many bytes are left: a bound on the records still to come.
    fn left(&self) -> usize {
        match self {
            Body::Ascii(tokens) => tokens.left,
            Body::Binary { bytes, at, .. } => bytes.len().saturating_sub(*at),
        }
    }

    /// The line of the number read last (ASCII), for a face's line.
    fn line(&self) -> Option<u32> {
        match self {
            Body::Ascii(tokens) => Some(tokens.line as u32),
            Body::Binary { .. } => None,
        }
    }
}

/// A binary number of type `ty` from its bytes (exactly `ty.size()` of them).
fn binary_value(b: &[u8], ty: Scalar, little: bool) -> f64 {
    macro_rules! read {
        ($t:ty) => {{
            let mut a = [0u8; std::mem::size_of::<$t>()];
            a.copy_from_slice(b);
            if little {
                <$t>::from_le_bytes(a)
            } else {
                <$t>::from_be_bytes(a)
            }
        }};
    }
    match ty {
        Scalar::I8 => f64::from(b[0] as i8),
        Scalar::U8 => f64::from(b[0]),
        Scalar::I16 => f64::from(read!(i16)),
        Scalar::U16 => f64::from(read!(u16)),
        Scalar::I32 => f64::from(read!(i32)),
        Scalar::U32 => f64::from(read!(u32)),
        Scalar::F32 => f64::from(read!(f32)),
        Scalar::F64 => read!(f64),
    }
}

/// What the records give.
#[derive(Default)]
struct Read {
    positions: Vec<Point3<f64>>,
    /// Whether a vertex element was read (a file may have one of zero vertices).
    has_vertices: bool,
    indices: Vec<i64>,
    arities: Vec<usize>,
    /// The line of each face (ASCII only).
    face_lines: Vec<u32>,
    /// Faces of fewer than three corners, skipped: their lines (ASCII) or face numbers.
    two_corner: Vec<usize>,
}

/// Reads the records of `element`: vertices and faces into `mesh`, anything else read past.
fn read_element(element: &Element, body: &mut Body<'_>, mesh: &mut Read) -> Result<(), DataError> {
    let name = element.name.as_str();
    let scalar = |wanted: &str| {
        element
            .properties
            .iter()
            .position(|p| matches!(p, Property::Scalar { name, .. } if name == wanted))
    };
    let (xyz, index_list) = match name {
        "vertex" => {
            let (Some(x), Some(y), Some(z)) = (scalar("x"), scalar("y"), scalar("z")) else {
                return Err((
                    None,
                    "the vertex element has no x, y and z properties".to_owned(),
                ));
            };
            mesh.has_vertices = true;
            // The count is the file's word: room for what the bytes can hold, no more.
            mesh.positions.reserve(element.count.min(body.left()));
            (Some([x, y, z]), None)
        }
        "face" => {
            let list = element.properties.iter().position(|p| {
                matches!(p, Property::List { name, .. } if name == "vertex_indices" || name == "vertex_index")
            });
            if list.is_none() {
                return Err((
                    None,
                    "the face element has no vertex_indices (or vertex_index) list".to_owned(),
                ));
            }
            (None, list)
        }
        _ => (None, None),
    };
    // Records of no properties take no bytes: there is nothing to read, however many.
    if element.properties.is_empty() {
        return Ok(());
    }
    // Which coordinate each property is, worked out once for all the records.
    let axis_of: Vec<Option<usize>> = (0..element.properties.len())
        .map(|k| xyz.and_then(|xyz| xyz.iter().position(|&p| p == k)))
        .collect();
    for record in 0..element.count {
        let what = || format!("{name} {record} (counting from 0)");
        let mut point = [0.0; 3];
        for (k, property) in element.properties.iter().enumerate() {
            match property {
                Property::Scalar { ty, .. } => {
                    let v = body.value(*ty, &what)?;
                    if let Some(axis) = axis_of[k] {
                        point[axis] = v;
                    }
                }
                Property::List { count, item, .. } => {
                    let n = body.value(*count, &what)?;
                    if n < 0.0 {
                        return Err((
                            body.line().map(|l| l as usize),
                            format!("a negative count in {}", what()),
                        ));
                    }
                    let n = n as usize;
                    if index_list == Some(k) {
                        if n < 3 {
                            mesh.two_corner
                                .push(body.line().map_or(record, |l| l as usize));
                        } else {
                            mesh.face_lines.extend(body.line());
                            mesh.arities.push(n);
                        }
                    }
                    for _ in 0..n {
                        let v = body.value(*item, &what)?;
                        if index_list == Some(k) && n >= 3 {
                            mesh.indices.push(v as i64);
                        }
                    }
                }
            }
        }
        if xyz.is_some() {
            if let Some(axis) = point.iter().position(|c| !c.is_finite()) {
                return Err((
                    body.line().map(|l| l as usize),
                    format!(
                        "vertex {record} has a coordinate that is not finite ({})",
                        point[axis]
                    ),
                ));
            }
            mesh.positions.push(Point3::from(point));
        }
    }
    Ok(())
}

/// The mesh file: indices checked against the vertices, positions welded.
fn finish(read: Read, path: &Path) -> Result<MeshFile, MeshError> {
    let bad = |message: String| MeshError::Malformed {
        path: path.to_path_buf(),
        line: None,
        message,
    };
    if read.arities.is_empty() {
        return Err(bad(if read.has_vertices {
            format!(
                "a point cloud of {} points: it has no faces, so it encloses no volume",
                read.positions.len()
            )
        } else {
            "no vertices and no faces".to_owned()
        }));
    }
    let vertices = read.positions.len();
    let mut corner = 0;
    for (face, &arity) in read.arities.iter().enumerate() {
        for &i in &read.indices[corner..corner + arity] {
            if i < 0 || i as usize >= vertices {
                let line = read.face_lines.get(face).map(|&l| l as usize);
                return Err(MeshError::Malformed {
                    path: path.to_path_buf(),
                    line,
                    message: format!(
                        "face {face} (counting from 0) names vertex {i}, but there are {vertices} \
                         vertices"
                    ),
                });
            }
        }
        corner += arity;
    }
    let (welded, remap) = weld_exact(&read.positions);
    let indices = read.indices.iter().map(|&i| remap[i as usize]).collect();
    let mesh =
        PolyMesh::from_flat(welded, indices, &read.arities).map_err(|e| MeshError::InFile {
            path: path.to_path_buf(),
            line: None,
            source: Box::new(e),
        })?;
    let mut warnings = Vec::new();
    if !read.two_corner.is_empty() {
        warnings.push(Warning {
            count: read.two_corner.len(),
            defect: Defect::TwoCornerFaces {
                lines: read.two_corner.iter().copied().take(EXAMPLES).collect(),
            },
            faces: Vec::new(),
            effect_on_mass: Some(0.0),
        });
    }
    Ok(MeshFile {
        mesh,
        face_lines: read.face_lines,
        warnings,
        part_names: Vec::new(),
        face_parts: Vec::new(),
    })
}

#[cfg(test)]
mod tests {
    use super::super::tests::face_points;
    use super::*;

    /// The unit cube as eight corners and six outward quads.
    const CORNERS: [[f64; 3]; 8] = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 1.0],
        [1.0, 1.0, 1.0],
        [0.0, 1.0, 1.0],
    ];
    const QUADS: [[u32; 4]; 6] = [
        [0, 3, 2, 1],
        [4, 5, 6, 7],
        [0, 1, 5, 4],
        [1, 2, 6, 5],
        [2, 3, 7, 6],
        [3, 0, 4, 7],
    ];

    /// The cube as an OBJ, read by the OBJ reader: what every PLY spelling must give.
    fn cube_from_obj() -> MeshFile {
        let mut text = String::new();
        for [x, y, z] in CORNERS {
            text += &format!("v {x} {y} {z}\n");
        }
        for q in QUADS {
            text += &format!("f {} {} {} {}\n", q[0] + 1, q[1] + 1, q[2] + 1, q[3] + 1);
        }
        super::super::parse_obj(text.as_bytes(), Path::new("cube.obj")).expect("the OBJ")
    }

    /// The cube in binary PLY: float or double coordinates, a normal and a colour per vertex, the
    /// index list with a `uchar` count and `int` indices, and an extra face property.
    fn binary_cube(little: bool, double: bool) -> Vec<u8> {
        let coordinate = if double { "double" } else { "float" };
        let order = if little { "little" } else { "big" };
        let mut bytes = format!(
            "ply\nformat binary_{order}_endian 1.0\ncomment made by a test\nelement vertex 8\n\
             property {coordinate} x\nproperty {coordinate} y\nproperty {coordinate} z\n\
             property float nx\nproperty uchar red\nelement face 6\n\
             property list uchar int vertex_indices\nproperty ushort flags\nend_header\n"
        )
        .into_bytes();
        let put = |bytes: &mut Vec<u8>, le: &[u8], be: &[u8]| {
            bytes.extend_from_slice(if little { le } else { be });
        };
        for c in CORNERS {
            for x in c {
                if double {
                    put(&mut bytes, &x.to_le_bytes(), &x.to_be_bytes());
                } else {
                    let x = x as f32;
                    put(&mut bytes, &x.to_le_bytes(), &x.to_be_bytes());
                }
            }
            put(&mut bytes, &1.5f32.to_le_bytes(), &1.5f32.to_be_bytes());
            bytes.push(200);
        }
        for q in QUADS {
            bytes.push(4);
            for i in q {
                let i = i as i32;
                put(&mut bytes, &i.to_le_bytes(), &i.to_be_bytes());
            }
            put(&mut bytes, &7u16.to_le_bytes(), &7u16.to_be_bytes());
        }
        bytes
    }

    /// The cube in ASCII PLY with `vertex_index`, CRLF lines, and an edge element.
    fn ascii_cube() -> String {
        let mut text = "ply\r\nformat ascii 1.0\r\nelement vertex 8\r\nproperty double x\r\n\
                        property double y\r\nproperty double z\r\nelement face 6\r\n\
                        property list uint8 int32 vertex_index\r\nelement edge 1\r\n\
                        property int vertex1\r\nproperty int vertex2\r\nend_header\r\n"
            .to_owned();
        for [x, y, z] in CORNERS {
            text += &format!("{x} {y} {z}\r\n");
        }
        for q in QUADS {
            text += &format!("4 {} {} {} {}\r\n", q[0], q[1], q[2], q[3]);
        }
        text + "0 1\r\n"
    }

    /// Every spelling of the cube has the OBJ's faces, corner for corner, and its mass
    /// properties bit for bit (volume 1); ASCII faces know their lines.
    #[test]
    fn every_spelling_of_the_cube_is_the_objs_mesh() {
        let expected = cube_from_obj();
        let exact = crate::mass_properties(&expected.mesh, 1.0).expect("the OBJ's");
        assert!((exact.mass - 1.0).abs() < 1e-15);
        let path = Path::new("cube.ply");
        let mut spellings = vec![("ascii", ascii_cube().into_bytes())];
        for (little, double) in [(true, false), (false, false), (true, true), (false, true)] {
            spellings.push(("binary", binary_cube(little, double)));
        }
        for (what, bytes) in spellings {
            let file = parse_ply(&bytes, path).expect(what);
            assert_eq!(
                face_points(&file.mesh),
                face_points(&expected.mesh),
                "{what}"
            );
            let props = crate::mass_properties(&file.mesh, 1.0).expect(what);
            assert_eq!(props, exact, "{what}");
            if what == "ascii" {
                assert_eq!(file.face_lines, [21, 22, 23, 24, 25, 26]);
            }
        }
    }

    /// Doubles stay doubles: 0.1 is not rounded to the nearest f32.
    #[test]
    fn double_coordinates_are_kept() {
        let text = ascii_cube().replacen("1 1 1\r\n", "1 1 1.1\r\n", 1);
        let file = parse_ply(text.as_bytes(), Path::new("c.ply")).expect("reads");
        assert!(file.mesh.positions().iter().any(|p| p.z == 1.1));
    }

    /// Bad files are refused with what is wrong and where: a point cloud with its point count, a
    /// truncated binary file with its length and the element, an index past the vertices with its
    /// face and line, a header line that is not PLY with its line.
    #[test]
    fn bad_files_are_refused_by_name() {
        let path = Path::new("bad.ply");
        let said = |bytes: &[u8]| {
            parse_ply(bytes, path)
                .map(|_| ())
                .map_err(|e| e.to_string())
        };
        let cloud = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
                     property float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
        assert_eq!(
            said(cloud.as_bytes()),
            Err(
                "bad.ply: a point cloud of 3 points: it has no faces, so it encloses no volume"
                    .to_owned()
            )
        );
        let full = binary_cube(true, false);
        assert_eq!(
            said(&full[..full.len() - 3]),
            Err(format!(
                "bad.ply: the file ends at byte {} inside face 5 (counting from 0)",
                full.len() - 3
            ))
        );
        let past = ascii_cube().replacen("4 0 3 2 1", "4 0 3 2 8", 1);
        assert_eq!(
            said(past.as_bytes()),
            Err(
                "bad.ply, line 21: face 0 (counting from 0) names vertex 8, but there are 8 \
                 vertices"
                    .to_owned()
            )
        );
        let header = ascii_cube().replacen("element edge 1", "elephant edge 1", 1);
        assert_eq!(
            said(header.as_bytes()),
            Err("bad.ply, line 9: a header line that is not PLY: \"elephant edge 1\"".to_owned())
        );
        assert_eq!(
            said(b"solid cube\n"),
            Err(
                "bad.ply, line 1: not a PLY file: it does not start with the line \"ply\""
                    .to_owned()
            )
        );
        let nan = ascii_cube().replacen("1 1 1\r\n", "1 nan 1\r\n", 1);
        assert_eq!(
            said(nan.as_bytes()),
            Err("bad.ply, line 19: vertex 6 has a coordinate that is not finite (NaN)".to_owned())
        );
    }

    /// Counts no file could hold are refused quickly, without reserving memory for them: a
    /// billion vertices in a few bytes, and a trillion records of an element with no properties
    /// (which take no bytes at all) before a cube.
    #[test]
    fn counts_no_file_could_hold_are_harmless() {
        let path = Path::new("big.ply");
        let huge = "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000000\n\
                    property float x\nproperty float y\nproperty float z\nend_header\n\0\0\0\0";
        let said = parse_ply(huge.as_bytes(), path)
            .map(|_| ())
            .map_err(|e| e.to_string());
        assert_eq!(
            said,
            Err("big.ply: the file ends at byte 134 inside vertex 0 (counting from 0)".to_owned())
        );
        let empty = ascii_cube().replacen(
            "element vertex 8",
            "element nothing 1000000000000\r\nelement vertex 8",
            1,
        );
        let file = parse_ply(empty.as_bytes(), path).expect("reads");
        assert_eq!(file.mesh.face_count(), 6);
    }

    /// A face of two corners is skipped and reported, as OBJ's are.
    #[test]
    fn a_two_corner_face_is_skipped_and_reported() {
        let text = ascii_cube()
            .replacen("element face 6", "element face 7", 1)
            .replacen("4 3 0 4 7\r\n", "4 3 0 4 7\r\n2 0 1\r\n", 1);
        let file = parse_ply(text.as_bytes(), Path::new("c.ply")).expect("reads");
        assert_eq!(file.mesh.face_count(), 6);
        assert_eq!(file.warnings.len(), 1);
        assert_eq!(
            file.warnings[0].defect,
            Defect::TwoCornerFaces { lines: vec![27] }
        );
    }
}
