//! The desktop's side of [`platform`](super): work and jobs run on threads of their own, and the process's
//! memory is read from Linux's `/proc/self/status` (`None` elsewhere; the benchmarks print it).

use super::{Job, JobEvent, Memory};

/// Runs `job` on a thread of its own (a load, while the UI goes on drawing).
pub fn spawn(job: impl FnOnce() + Send + 'static) {
    std::thread::spawn(job);
}

/// Runs job `J` on a thread of its own, telling `on_event` its progress and then its output
/// (as they are: nothing crosses as bytes on the desktop).
pub fn start_job<J: Job>(input: J::Input, on_event: impl Fn(JobEvent<J>) + Send + 'static) {
    std::thread::spawn(move || {
        let output = J::run(input, &|p| on_event(JobEvent::Progress(p)));
        on_event(JobEvent::Done(output));
    });
}

/// Nothing to prepare on the desktop: a job's thread starts with the job. (The web starts its
/// worker here.)
pub fn prepare_jobs() {}

/// Nothing to do on the desktop: [`spawn`]ed work runs by itself. (The web runs it here.)
pub fn run_spawned() {}

/// Writes `bytes` to the file at `path`.
///
/// # Errors
/// The system's, as it says it.
pub fn write_file(path: &std::path::Path, bytes: &[u8]) -> std::io::Result<()> {
    std::fs::write(path, bytes)
}

/// A line on standard output (a benchmark's table).
pub fn print(line: &str) {
    println!("{line}");
}

/// A line on standard error.
pub fn print_error(line: &str) {
    eprintln!("{line}");
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
