//! Block sums on the rayon pool, with the calling thread working too.
//!
//! The blocks are handed out by guided self-scheduling (C. Polychronopoulos and D. Kuck,
//! "Guided Self-Scheduling: A Practical Scheduling Scheme for Parallel Supercomputers", IEEE
//! Trans. Computers 36(12), 1987): each claim takes a share of the blocks still unclaimed, so
//! early claims are large, the last ones a single block, and a thread that starts late or is
//! preempted only leaves less work for itself.
//!
//! Why the caller works rather than waits, measured on a 2-core KVM guest: a fixed split run
//! from outside the pool puts the caller to sleep and wakes it at the end, about 16 µs per call,
//! as long as the whole job on one thread for 10k triangles. A task spawned while the pool's
//! threads are awake starts 0.4–1.6 µs later, so the caller starts at once, a block at a time,
//! and the helper joins.
//! When the pool sleeps, the guest scheduler wakes the helper on the caller's own core (it avoids
//! the halted vCPU) and the two share it until the load balancer moves one, milliseconds later;
//! so when no helper has started within [`HELPER_START_WAIT`] and much work is left, a caller
//! from outside the pool hands its share to the pool too and sleeps, which frees its core.
//!
//! Every block is still computed by the same function and stored in its own slot, so the result
//! does not depend on which thread took which block.

use std::ops::Range;
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// How long the caller waits for a helper to start before it steps aside (see the module doc).
const HELPER_START_WAIT: Duration = Duration::from_micros(10);

/// The least work left, timed at the caller's pace, for which the caller steps aside: that costs
/// it a sleep and a wake-up, 50–70 µs here.
const STEP_ASIDE_MIN_WORK: Duration = Duration::from_micros(100);

/// How long the caller spins without yielding: a helper on another core is usually done by then.
const YIELD_AFTER: Duration = Duration::from_micros(5);

/// How long the caller spins, once every block is claimed, for a helper still finishing one,
/// before it falls back to rayon's blocking wait (which costs a thread wake-up).
const SPIN_LIMIT: Duration = Duration::from_micros(200);

/// `[block(0), block(1), …, block(count − 1)]`, computed on the caller and the rayon pool.
///
/// Like any rayon scope entered from outside the pool, the call returns only once a pool thread
/// has run each helper task, even one that finds no block left: while the pool is busy with
/// other work, that can take long, and it never comes if that work waits for the caller.
pub(crate) fn map_blocks<const N: usize>(
    count: usize,
    block: impl Fn(usize) -> [f64; N] + Sync,
) -> Vec<[f64; N]> {
    let schedule = match Schedule::new(count, rayon::current_num_threads()) {
        Some(schedule) if schedule.threads > 1 && count > 1 => schedule,
        _ => return (0..count).map(block).collect(),
    };
    // f64 bits in relaxed atomics: each slot is written once by whichever thread claims it, and
    // the end of the rayon scope orders those writes before the reads.
    let slots: Vec<[AtomicU64; N]> = (0..count)
        .map(|_| std::array::from_fn(|_| AtomicU64::new(0)))
        .collect();
    run(&schedule, &slots, block, HELPER_START_WAIT);
    // Same size and alignment: the collect reuses the allocation.
    slots
        .into_iter()
        .map(|slot| slot.map(|bits| f64::from_bits(bits.into_inner())))
        .collect()
}

/// What the calling thread did in [`run`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Caller {
    /// Claimed blocks alongside the helpers.
    Worked,
    /// Handed its share to the pool and waited.
    SteppedAside,
}

/// Fills `slots` with the blocks: one rayon task per other thread claims from the back of
/// `schedule`; the caller takes single blocks from the front until a helper starts, then
/// claims like the helpers, or, outside the pool, steps aside if none has started within
/// `helper_start_wait` and enough work is left.
fn run<const N: usize>(
    schedule: &Schedule,
    slots: &[[AtomicU64; N]],
    block: impl Fn(usize) -> [f64; N] + Sync,
    helper_start_wait: Duration,
) -> Caller {
    let (started, finished) = (AtomicUsize::new(0), AtomicUsize::new(0));
    let fill = |run: Range<usize>| {
        for b in run {
            for (slot, value) in slots[b].iter().zip(block(b)) {
                slot.store(value.to_bits(), Ordering::Relaxed);
            }
        }
    };
    let work = |end| {
        while let Some(run) = schedule.claim(end) {
            fill(run);
        }
    };
    // A pool thread that stepped aside would only queue its share on its own deque.
    let may_step_aside = rayon::current_thread_index().is_none();
    rayon::in_place_scope(|scope| {
        for _ in 1..schedule.threads {
            scope.spawn(|_| {
                started.fetch_add(1, Ordering::AcqRel);
                work(End::Back);
                finished.fetch_add(1, Ordering::AcqRel);
            });
        }
        let start = Instant::now();
        let mut done = 0;
        loop {
            if started.load(Ordering::Acquire) > 0 {
                work(End::Front);
                break;
            }
            // The work left, at the pace of the blocks done so far.
            let waited = start.elapsed();
            let work_left = waited.as_secs_f64() * schedule.left() as f64 / done.max(1) as f64;
            if may_step_aside
                && waited >= helper_start_wait
                && work_left >= STEP_ASIDE_MIN_WORK.as_secs_f64()
            {
                scope.spawn(|_| work(End::Front));
                return Caller::SteppedAside;
            }
            match schedule.claim_at_most(End::Front, 1) {
                Some(run) => fill(run),
                None => break,
            }
            done += 1;
        }
        // A helper that has started holds at most one claim, soon done: spinning for it is
        // cheaper than being woken. One that never started finds nothing left, and the scope
        // waits for it either way.
        spin_until(SPIN_LIMIT, || {
            finished.load(Ordering::Acquire) == started.load(Ordering::Acquire)
        });
        Caller::Worked
    })
}

/// Spins until `done()` or `limit` has passed, yielding the core after [`YIELD_AFTER`] in case
/// the thread waited for shares it.
fn spin_until(limit: Duration, done: impl Fn() -> bool) {
    let start = Instant::now();
    while !done() {
        let spun = start.elapsed();
        if spun >= limit {
            return;
        }
        if spun >= YIELD_AFTER {
            std::thread::yield_now();
        } else {
            std::hint::spin_loop();
        }
    }
}

/// Which end of the unclaimed blocks a thread takes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum End {
    Front,
    Back,
}

/// Guided self-scheduling of `0..count` among `threads` threads, the caller taking from the
/// front and the helpers from the back: with two threads working, repeated calls on one mesh
/// tend to give each thread the blocks it had last time, still in its own cache.
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
            threads: threads.max(1) as u64,
            unclaimed: AtomicU64::new(u64::from(count) << 32),
        })
    }

    /// The number of blocks not yet claimed.
    fn left(&self) -> usize {
        let unclaimed = self.unclaimed.load(Ordering::Relaxed);
        ((unclaimed >> 32) - (unclaimed & u64::from(u32::MAX))) as usize
    }

    /// The next run of unclaimed blocks at `end`: a `1/(2·threads)` share of those left, at
    /// least one.
    fn claim(&self, end: End) -> Option<Range<usize>> {
        self.claim_at_most(end, usize::MAX)
    }

    /// [`Self::claim`], of at most `most` (≥ 1) blocks.
    fn claim_at_most(&self, end: End, most: usize) -> Option<Range<usize>> {
        debug_assert!(most >= 1, "a claim of no block would never end `work`");
        let most = most as u64;
        let mut unclaimed = self.unclaimed.load(Ordering::Relaxed);
        loop {
            let (front, back) = (unclaimed & u64::from(u32::MAX), unclaimed >> 32);
            let left = back.checked_sub(front).filter(|&left| left > 0)?;
            let size = left.div_ceil(2 * self.threads).min(most);
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
        let schedule = Schedule::new(100, 2).expect("small count");
        assert_eq!(schedule.left(), 100);
        assert_eq!(schedule.claim_at_most(End::Front, 1), Some(0..1));
        assert_eq!(schedule.claim_at_most(End::Back, 3), Some(97..100));
        assert_eq!(schedule.claim(End::Front), Some(1..25));
        assert_eq!(schedule.left(), 72);
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
            let inside = pool.install(|| map_blocks(count, block));
            assert_eq!(inside, expected, "{count} blocks");
            let outside = map_blocks(count, block);
            assert_eq!(outside, expected, "{count} blocks");
        }
    }

    #[test]
    fn working_or_stepping_aside_the_caller_gets_every_block_computed_once() {
        let count = 300;
        let calls: Vec<AtomicUsize> = (0..count).map(|_| AtomicUsize::new(0)).collect();
        // A few µs a block, so that 300 of them are worth stepping aside for.
        let block = |b: usize| {
            calls[b].fetch_add(1, Ordering::Relaxed);
            let x = (0..2000).fold(b as f64, |x, _| (x + 1.0).sqrt() + b as f64);
            [x, -(b as f64)]
        };
        let mut roles = Vec::new();
        // No wait: the caller steps aside unless a helper is already running; a long one: it
        // always works.
        for wait in [Duration::ZERO; 20]
            .into_iter()
            .chain([Duration::from_secs(5)])
        {
            let expected: Vec<[f64; 2]> = (0..count).map(block).collect();
            calls.iter().for_each(|c| c.store(0, Ordering::Relaxed));
            let schedule = Schedule::new(count, 2).expect("small count");
            let slots: Vec<[AtomicU64; 2]> = (0..count)
                .map(|_| std::array::from_fn(|_| AtomicU64::new(0)))
                .collect();
            roles.push(run(&schedule, &slots, block, wait));
            let filled: Vec<[f64; 2]> = slots
                .iter()
                .map(|slot| {
                    slot.each_ref()
                        .map(|b| f64::from_bits(b.load(Ordering::Relaxed)))
                })
                .collect();
            assert_eq!(filled, expected, "wait {wait:?}");
            assert!(calls.iter().all(|c| c.load(Ordering::Relaxed) == 1));
        }
        assert_eq!(roles.last(), Some(&Caller::Worked));
        assert!(roles.contains(&Caller::SteppedAside), "{roles:?}");
    }
}
