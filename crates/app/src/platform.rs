//! What the system tells about the process, where it differs between systems: today, the
//! resident memory (Linux's `/proc/self/status`; `None` elsewhere). The benchmarks print it.

/// Resident memory of this process, in KiB: now and at its peak.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Memory {
    /// Resident now (`VmRSS`).
    pub resident_kib: u64,
    /// The most resident so far (`VmHWM`).
    pub peak_kib: u64,
}

/// This process's memory, where the system says.
pub fn memory() -> Option<Memory> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let field = |name: &str| -> Option<u64> {
        let line = status.lines().find(|l| l.starts_with(name))?;
        line.split_whitespace().nth(1)?.parse().ok()
    };
    Some(Memory {
        resident_kib: field("VmRSS:")?,
        peak_kib: field("VmHWM:")?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Holding 64 MiB more (written, so resident) shows in both figures. A lower bound only:
    /// other tests of the process allocate and free meanwhile.
    #[test]
    fn memory_counts_what_is_held() {
        let Some(before) = memory() else {
            println!("SKIPPED memory_counts_what_is_held: no /proc/self/status (not Linux)");
            return;
        };
        let mut held = vec![0u8; 64 << 20];
        for (k, b) in held.iter_mut().enumerate() {
            *b = k as u8;
        }
        std::hint::black_box(&held);
        let after = memory().expect("still there");
        let grown = after.resident_kib.saturating_sub(before.resident_kib);
        assert!(grown >= 48 << 10, "{grown} KiB");
        assert!(after.peak_kib >= after.resident_kib);
        drop(held);
    }
}
