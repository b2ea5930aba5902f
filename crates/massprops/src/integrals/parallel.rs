//! Block sums on the rayon pool, with the calling thread working too.
//!
//! The blocks are handed out by guided self-scheduling (C. Polychronopoulos and D. Kuck,
//! "Guided Self-Scheduling: A Practical Scheduling Scheme for Parallel Supercomputers", IEEE
//! Trans. Computers 36(12), 1987): each claim takes a share of the blocks still unclaimed, so
//! early claims are large, the last ones a single block, and a thread that starts late or is
//! preempted only leaves less work for itself. Measured on a 2-core VM, handing a job to a rayon
//! worker takes 10–20 µs when the worker is awake and 50–70 µs when it sleeps: with a fixed split,
//! that latency stalls the whole call; here the caller starts at once and the worker joins when it
//! can.
//!
//! Every block is still computed by the same function and stored in its own slot, so the result
//! does not depend on which thread took which block.

use std::ops::Range;
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// How long the caller spins, once every block is claimed, for a helper still finishing one,
/// before it falls back to rayon's blocking wait (which costs a thread wake-up).
const SPIN_LIMIT: Duration = Duration::from_micros(200);

/// `[block(0), block(1), …, block(count − 1)]`, computed on the caller and the rayon pool.
pub(crate) fn map_blocks<const N: usize>(
    count: usize,
    block: impl Fn(usize) -> [f64; N] + Sync,
) -> Vec<[f64; N]> {
    let helpers = rayon::current_num_threads().saturating_sub(1);
    let schedule = match Schedule::new(count, helpers + 1) {
        Some(schedule) if helpers > 0 && count > 1 => schedule,
        _ => return (0..count).map(block).collect(),
    };
    // f64 bits in relaxed atomics: each slot is written once by whichever thread claims it, and
    // the end of the rayon scope orders those writes before the reads below.
    let slots: Vec<[AtomicU64; N]> = (0..count)
        .map(|_| std::array::from_fn(|_| AtomicU64::new(0)))
        .collect();
    let active_helpers = AtomicUsize::new(0);
    let work = |end| {
        while let Some(claimed) = schedule.claim(end) {
            for b in claimed {
                for (slot, value) in slots[b].iter().zip(block(b)) {
                    slot.store(value.to_bits(), Ordering::Relaxed);
                }
            }
        }
    };
    rayon::in_place_scope(|scope| {
        for _ in 0..helpers {
            scope.spawn(|_| {
                active_helpers.fetch_add(1, Ordering::AcqRel);
                work(End::Back);
                active_helpers.fetch_sub(1, Ordering::AcqRel);
            });
        }
        work(End::Front);
        // A helper that has started holds at most one claim, soon done: spinning for it is
        // cheaper than being woken. A helper that never started finds nothing left, and the
        // scope waits for it either way.
        let start = Instant::now();
        while active_helpers.load(Ordering::Acquire) > 0 && start.elapsed() < SPIN_LIMIT {
            std::hint::spin_loop();
        }
    });
    slots
        .iter()
        .map(|slot| slot.each_ref().map(|bits| f64::from_bits(bits.load(Ordering::Relaxed))))
        .collect()
}

/// Which end of the unclaimed blocks a thread takes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum End {
    Front,
    Back,
}

/// Guided self-scheduling of `0..count` among `threads` threads, the caller taking from the
/// front and the helpers from the back, so that on repeated calls each thread tends to get the
/// blocks it had last time, still in its own cache.
struct Schedule {
    threads: u64,
    /// The unclaimed blocks `front..back`, as `back << 32 | front`: one atomic, so that a claim
    /// from either end sees the other's.
    unclaimed: AtomicU64,
}

impl Schedule {
    /// `None` when `count` does not fit the 32-bit halves (2³² blocks, far beyond any memory).
    fn new(count: usize, threads: usize) -> Option<Self> {
        let count = u32::try_from(count).ok()?;
        Some(Self {
            threads: threads as u64,
            unclaimed: AtomicU64::new(u64::from(count) << 32),
        })
    }

    /// The next run of unclaimed blocks at `end`: a `1/(2·threads)` share of those left, at
    /// least one.
    fn claim(&self, end: End) -> Option<Range<usize>> {
        let mut unclaimed = self.unclaimed.load(Ordering::Relaxed);
        loop {
            let (front, back) = (unclaimed & u64::from(u32::MAX), unclaimed >> 32);
            let left = back.checked_sub(front).filter(|&left| left > 0)?;
            let size = left.div_ceil(2 * self.threads);
            let (run, rest) = match end {
                End::Front => (front..front + size, (back << 32) | (front + size)),
                End::Back => (back - size..back, ((back - size) << 32) | front),
            };
            match self.unclaimed.compare_exchange_weak(
                unclaimed,
                rest,
                Ordering::Relaxed,
                Ordering::Relaxed,
            ) {
                Ok(_) => return Some(run.start as usize..run.end as usize),
                Err(now) => unclaimed = now,
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn claims_from_both_ends_cover_every_block_once_in_shrinking_runs() {
        for (count, threads) in [(1, 2), (7, 2), (20, 2), (2000, 2), (1000, 8)] {
            let schedule = Schedule::new(count, threads).expect("small count");
            let mut runs = Vec::new();
            // Uneven turns, as when one thread runs ahead of the other.
            for turn in 0.. {
                let end = if turn % 3 == 0 { End::Back } else { End::Front };
                match schedule.claim(end) {
                    Some(run) => runs.push((end, run)),
                    None => break,
                }
            }
            let mut covered: Vec<usize> = runs.iter().flat_map(|(_, run)| run.clone()).collect();
            covered.sort_unstable();
            assert_eq!(covered, (0..count).collect::<Vec<_>>());
            assert_eq!(runs[0].1, count - count.div_ceil(2 * threads)..count);
            assert_eq!(runs.last().map(|(_, run)| run.len()), Some(1));
            for end in [End::Front, End::Back] {
                let lengths: Vec<usize> = runs
                    .iter()
                    .filter(|(e, _)| *e == end)
                    .map(|(_, run)| run.len())
                    .collect();
                assert!(lengths.windows(2).all(|w| w[1] <= w[0]), "{lengths:?}");
            }
        }
        assert!(Schedule::new(1 << 32, 2).is_none());
    }

    #[test]
    fn every_block_lands_in_its_own_slot() {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .expect("pool");
        for count in [0, 1, 2, 3, 20, 777] {
            let block = |b: usize| [b as f64, (b * b) as f64 + 0.5];
            let expected: Vec<[f64; 2]> = (0..count).map(block).collect();
            // From inside the pool (the caller is a rayon worker) and from outside it.
            assert_eq!(pool.install(|| map_blocks(count, block)), expected);
            assert_eq!(map_blocks(count, block), expected, "{count} blocks");
        }
    }
}
