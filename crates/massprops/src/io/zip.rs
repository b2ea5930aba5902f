//! The files of a ZIP archive (PKWARE's APPNOTE, sections 4.3–4.4), as 3MF packages them: the
//! central directory is read from the end-of-central-directory record, and each file is stored
//! or deflated (RFC 1951, through `miniz_oxide`), its CRC-32 checked. ZIP64 archives (4 GiB and
//! more) and encrypted files are refused by name.

use std::collections::HashMap;

/// An archive's files by name, read when asked for.
pub(super) struct Archive<'a> {
    bytes: &'a [u8],
    entries: HashMap<String, Entry>,
}

/// Where one file's data is and how it is stored.
struct Entry {
    method: u16,
    crc: u32,
    compressed: usize,
    size: usize,
    local_header: usize,
}

fn u16_at(bytes: &[u8], at: usize) -> Option<u16> {
    bytes
        .get(at..at + 2)
        .map(|b| u16::from_le_bytes([b[0], b[1]]))
}

fn u32_at(bytes: &[u8], at: usize) -> Option<u32> {
    bytes
        .get(at..at + 4)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
}

impl<'a> Archive<'a> {
    /// Reads an archive's central directory.
    pub(super) fn new(bytes: &'a [u8]) -> Result<Self, String> {
        const END: u32 = 0x0605_4b50;
        const CENTRAL: u32 = 0x0201_4b50;
        // The end record is 22 bytes plus a comment of at most 65 535.
        let earliest = bytes.len().saturating_sub(22 + 0xFFFF);
        let end = (earliest..=bytes.len().saturating_sub(22))
            .rev()
            .find(|&at| u32_at(bytes, at) == Some(END))
            .ok_or("not a ZIP archive: no end-of-central-directory record")?;
        let count = u16_at(bytes, end + 10).unwrap_or(0);
        let directory = u32_at(bytes, end + 16).unwrap_or(0);
        if count == 0xFFFF || directory == 0xFFFF_FFFF {
            return Err("a ZIP64 archive (4 GiB or more), which is not read".to_owned());
        }
        let mut entries = HashMap::new();
        let mut at = directory as usize;
        for k in 0..count {
            let cut = || format!("the central directory is cut short at entry {k}");
            if u32_at(bytes, at) != Some(CENTRAL) {
                return Err(cut());
            }
            let field = |offset: usize| u16_at(bytes, at + offset).ok_or_else(cut);
            let word = |offset: usize| u32_at(bytes, at + offset).ok_or_else(cut);
            let (flags, method) = (field(8)?, field(10)?);
            let (crc, compressed, size) = (word(16)?, word(20)?, word(24)?);
            let (name_length, extra, comment) = (field(28)?, field(30)?, field(32)?);
            let local_header = word(42)?;
            let name = bytes
                .get(at + 46..at + 46 + name_length as usize)
                .ok_or_else(cut)?;
            let name = String::from_utf8_lossy(name).into_owned();
            if flags & 1 != 0 {
                return Err(format!("{name} is encrypted"));
            }
            if [compressed, size, local_header].contains(&0xFFFF_FFFF) {
                return Err(format!("{name} is stored as ZIP64, which is not read"));
            }
            entries.insert(
                name,
                Entry {
                    method,
                    crc,
                    compressed: compressed as usize,
                    size: size as usize,
                    local_header: local_header as usize,
                },
            );
            at += 46 + name_length as usize + extra as usize + comment as usize;
        }
        Ok(Self { bytes, entries })
    }

    /// A file's bytes; `None` when the archive has no file of that name (a leading `/` and the
    /// case of letters do not count, as the Open Packaging Conventions say).
    pub(super) fn read(&self, name: &str) -> Option<Result<Vec<u8>, String>> {
        let name = name.trim_start_matches('/');
        let (name, entry) = self
            .entries
            .iter()
            .find(|(n, _)| n.eq_ignore_ascii_case(name))?;
        Some(self.inflate(name, entry))
    }

    fn inflate(&self, name: &str, entry: &Entry) -> Result<Vec<u8>, String> {
        const LOCAL: u32 = 0x0403_4b50;
        let at = entry.local_header;
        let cut = || format!("{name}: its data is past the end of the archive");
        if u32_at(self.bytes, at) != Some(LOCAL) {
            return Err(format!("{name}: no local header where the directory says"));
        }
        let name_length = u16_at(self.bytes, at + 26).ok_or_else(cut)? as usize;
        let extra = u16_at(self.bytes, at + 28).ok_or_else(cut)? as usize;
        let start = at + 30 + name_length + extra;
        let data = start
            .checked_add(entry.compressed)
            .and_then(|end| self.bytes.get(start..end))
            .ok_or_else(cut)?;
        let bytes = match entry.method {
            0 => data.to_vec(),
            8 => {
                // The directory's size (at most 4 GiB) bounds what a hostile archive can make us hold.
                miniz_oxide::inflate::decompress_to_vec_with_limit(data, entry.size)
                    .map_err(|e| format!("{name}: its deflated data is broken ({:?})", e.status))?
            }
            m => {
                return Err(format!(
                    "{name}: compression method {m} is not read (only stored and deflated)"
                ));
            }
        };
        if bytes.len() != entry.size {
            return Err(format!(
                "{name}: {} bytes where the directory says {}",
                bytes.len(),
                entry.size
            ));
        }
        if crc32(&bytes) != entry.crc {
            return Err(format!(
                "{name}: its CRC-32 does not match: the archive is damaged"
            ));
        }
        Ok(bytes)
    }
}

/// CRC-32 (ISO-HDLC, the polynomial 0xEDB88320 reflected), as ZIP checks its files with.
pub(super) fn crc32(bytes: &[u8]) -> u32 {
    static TABLE: std::sync::OnceLock<[u32; 256]> = std::sync::OnceLock::new();
    let table = TABLE.get_or_init(|| {
        let mut table = [0u32; 256];
        for (n, entry) in table.iter_mut().enumerate() {
            let mut c = n as u32;
            for _ in 0..8 {
                c = if c & 1 != 0 {
                    0xEDB8_8320 ^ (c >> 1)
                } else {
                    c >> 1
                };
            }
            *entry = c;
        }
        table
    });
    !bytes.iter().fold(!0u32, |c, &b| {
        table[((c ^ u32::from(b)) & 0xFF) as usize] ^ (c >> 8)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The check value of CRC-32/ISO-HDLC.
    #[test]
    fn crc32_of_the_check_string() {
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
    }
}
