//! A ZIP archive of stored files, built in memory: how a page hands over a recording's pictures
//! as one download. Files are stored, not deflated (PNGs are compressed already). The layout is
//! PKWARE's APPNOTE.TXT 6.3.10 §4.3: a local header and the data for each file, then the central
//! directory and its end record; sizes and offsets are 32-bit (no ZIP64: an archive over 4 GiB
//! is refused).

use crate::i18n::tr;

/// A ZIP archive being written.
#[derive(Debug, Default)]
pub struct Archive {
    bytes: Vec<u8>,
    directory: Vec<u8>,
    files: u16,
}

/// Signatures of the records (APPNOTE §4.3.7, §4.3.12, §4.3.16).
const LOCAL: u32 = 0x0403_4b50;
const CENTRAL: u32 = 0x0201_4b50;
const END: u32 = 0x0605_4b50;
/// Version 2.0: stored files in folders, the least a reader must support.
const VERSION: u16 = 20;
/// General-purpose flag bit 11: the names are UTF-8.
const UTF8_NAMES: u16 = 1 << 11;
/// 1980-01-01 00:00 in MS-DOS date and time (the earliest a ZIP can say; the pictures' order is
/// in their names).
const DOS_DATE: u16 = (1 << 5) | 1;

impl Archive {
    /// Adds the file `name` with `data`, stored.
    ///
    /// # Errors
    /// The archive would pass 4 GiB or 65 535 files, or the name is over 65 535 bytes.
    pub fn add(&mut self, name: &str, data: &[u8]) -> Result<(), String> {
        let too_big = || tr!("capture-archive-too-big", name = name);
        let offset = u32::try_from(self.bytes.len()).map_err(|_| too_big())?;
        let size = u32::try_from(data.len()).map_err(|_| too_big())?;
        let name_len = u16::try_from(name.len()).map_err(|_| too_big())?;
        self.files = self.files.checked_add(1).ok_or_else(too_big)?;
        let crc = crc32fast::hash(data);
        // The fields both headers share, from "version needed" to "extra field length".
        let mut common = Vec::with_capacity(26);
        for half in [VERSION, UTF8_NAMES, 0, 0, DOS_DATE] {
            common.extend(half.to_le_bytes());
        }
        for word in [crc, size, size] {
            common.extend(word.to_le_bytes());
        }
        common.extend(name_len.to_le_bytes());
        common.extend(0u16.to_le_bytes());

        self.bytes.extend(LOCAL.to_le_bytes());
        self.bytes.extend(&common);
        self.bytes.extend(name.as_bytes());
        self.bytes.extend(data);

        self.directory.extend(CENTRAL.to_le_bytes());
        self.directory.extend(VERSION.to_le_bytes());
        self.directory.extend(&common);
        // Comment length, disk number, internal and external attributes.
        self.directory.extend([0; 2 + 2 + 2 + 4]);
        self.directory.extend(offset.to_le_bytes());
        self.directory.extend(name.as_bytes());
        if u32::try_from(self.bytes.len() + self.directory.len()).is_err() {
            return Err(too_big());
        }
        Ok(())
    }

    /// The archive's bytes.
    pub fn finish(mut self) -> Vec<u8> {
        // `add` kept both parts under 4 GiB together.
        let at = self.bytes.len() as u32;
        let directory_len = self.directory.len() as u32;
        self.bytes.append(&mut self.directory);
        self.bytes.extend(END.to_le_bytes());
        // This disk, the directory's disk, its entries here and in all.
        for half in [0, 0, self.files, self.files] {
            self.bytes.extend(half.to_le_bytes());
        }
        self.bytes.extend(directory_len.to_le_bytes());
        self.bytes.extend(at.to_le_bytes());
        self.bytes.extend(0u16.to_le_bytes());
        self.bytes
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Python's zipfile, an independent reader, lists the files in order and finds each one's
    /// bytes and CRC intact.
    #[test]
    fn pythons_zipfile_reads_the_archive_back() {
        const TEST: &str = "pythons_zipfile_reads_the_archive_back";
        let files: Vec<(String, Vec<u8>)> = (0..3)
            .map(|k| {
                let data = (0..1000 * k + 7).map(|i| (i * 31 + k) as u8).collect();
                (format!("frame-{:04}.png", k + 1), data)
            })
            .chain([("é/empty".to_owned(), Vec::new())])
            .collect();
        let mut archive = Archive::default();
        for (name, data) in &files {
            archive.add(name, data).expect("added");
        }
        let path =
            std::env::temp_dir().join(format!("inertia-lab-archive-{}.zip", std::process::id()));
        std::fs::write(&path, archive.finish()).expect("written");
        let script = "import sys, zipfile, hashlib\n\
            z = zipfile.ZipFile(sys.argv[1])\n\
            assert z.testzip() is None\n\
            for i in z.infolist():\n\
            \x20   print(i.filename, i.compress_type, hashlib.sha256(z.read(i)).hexdigest())\n";
        let Ok(out) = std::process::Command::new("python3")
            .args(["-c", script])
            .arg(&path)
            .output()
        else {
            std::fs::remove_file(&path).ok();
            assert!(
                std::env::var_os("CI").is_none(),
                "{TEST}: python3 is missing under CI"
            );
            println!("SKIPPED {TEST}: python3 is missing (apt-get install python3)");
            return;
        };
        std::fs::remove_file(&path).ok();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let expected: String = files
            .iter()
            .map(|(name, data)| {
                use sha2::Digest;
                let hash = sha2::Sha256::digest(data);
                let hex: String = hash.iter().map(|b| format!("{b:02x}")).collect();
                format!("{name} 0 {hex}\n")
            })
            .collect();
        assert_eq!(String::from_utf8_lossy(&out.stdout), expected);
    }
}
