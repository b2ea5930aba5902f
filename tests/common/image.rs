//! Screenshots for the tests that look at the app's pixels (the Xvfb window, the page in a
//! browser): read as RGB, and the pixels of a box that pass a test counted.

// Each test binary that includes this module uses a different part of it.
#![allow(dead_code)]

use std::path::Path;

/// A screenshot as RGB bytes, row by row.
pub struct Image {
    /// Pixels per row.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// Red, green, blue of each pixel.
    pub rgb: Vec<u8>,
}

impl Image {
    /// A PNG file (8 bits per channel, with or without alpha).
    pub fn read_png(path: &Path) -> Image {
        let file = std::fs::File::open(path).expect("the screenshot was written");
        let mut reader = png::Decoder::new(std::io::BufReader::new(file))
            .read_info()
            .expect("a PNG");
        let mut bytes = vec![0; reader.output_buffer_size().expect("size")];
        let info = reader.next_frame(&mut bytes).expect("pixels");
        let channels = info.color_type.samples();
        Image {
            width: info.width as usize,
            height: info.height as usize,
            rgb: bytes
                .chunks(channels)
                .flat_map(|p| [p[0], p[1], p[2]])
                .collect(),
        }
    }

    /// A binary PPM (P6) file, as ImageMagick's `import` writes it.
    pub fn read_ppm(path: &Path) -> Option<Image> {
        let bytes = std::fs::read(path).ok()?;
        // Header: "P6", width, height, max value, each separated by whitespace, then one byte.
        let mut fields = Vec::new();
        let mut i = 0;
        while fields.len() < 4 && i < bytes.len() {
            while i < bytes.len() && bytes[i].is_ascii_whitespace() {
                i += 1;
            }
            let start = i;
            while i < bytes.len() && !bytes[i].is_ascii_whitespace() {
                i += 1;
            }
            fields.push(String::from_utf8_lossy(&bytes[start..i]).into_owned());
        }
        if fields.first().map(String::as_str) != Some("P6") || fields.get(3)? != "255" {
            return None;
        }
        let width = fields[1].parse().ok()?;
        let height = fields[2].parse().ok()?;
        let rgb = bytes.get(i + 1..i + 1 + width * height * 3)?.to_vec();
        Some(Image { width, height, rgb })
    }

    /// Pixels in the box `[x0, x1) × [y0, y1)` for which `f(r, g, b)` holds.
    pub fn count(
        &self,
        (x0, x1): (usize, usize),
        (y0, y1): (usize, usize),
        f: impl Fn(u8, u8, u8) -> bool,
    ) -> usize {
        let mut n = 0;
        for y in y0..y1.min(self.height) {
            for x in x0..x1.min(self.width) {
                let k = 3 * (y * self.width + x);
                if f(self.rgb[k], self.rgb[k + 1], self.rgb[k + 2]) {
                    n += 1;
                }
            }
        }
        n
    }
}

/// The shaded body's tan (albedo 200, 160, 90, lit).
pub fn body_pixel(r: u8, g: u8, b: u8) -> bool {
    r > 90 && i32::from(r) > i32::from(g) + 10 && i32::from(g) > i32::from(b) + 20
}

/// The green of the ω₂ / Ly plot lines (90, 200, 90).
pub fn green_line(r: u8, g: u8, b: u8) -> bool {
    g > 150 && r < 150 && b < 150
}
