//! A map over a slice on every logical CPU (std's scoped threads taking the next unmapped item
//! from a shared counter; no thread pool crate), the results in the order of the items: for the
//! independent MPFR integrals of one solve (the loading law's residual and Jacobian rows per
//! collocation node, its fields per point). Each result is what the closure returns for its item
//! alone, so the output does not depend on the number of threads (test below). A map inside a
//! map's worker runs serially (the outer map already holds the CPUs). [`join`] runs two unequal
//! closures at once, each on a CPU of its own.

use std::cell::Cell;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

thread_local! {
    /// Whether this thread is a worker of [`map`].
    static WORKER: Cell<bool> = const { Cell::new(false) };
}

/// `f(i, &items[i])` for every i, on min(CPUs, items) threads (one: in the calling thread),
/// returned in the order of `items`.
pub fn map<T: Sync, R: Send>(items: &[T], f: impl Fn(usize, &T) -> R + Sync) -> Vec<R> {
    let cpus = std::thread::available_parallelism().map_or(1, |n| n.get());
    map_on(items, cpus, f)
}

/// [`map`] on at most `threads` threads.
pub fn map_on<T: Sync, R: Send>(items: &[T], threads: usize, f: impl Fn(usize, &T) -> R + Sync) -> Vec<R> {
    let threads = threads.clamp(1, items.len().max(1));
    if threads == 1 || WORKER.with(Cell::get) {
        return items.iter().enumerate().map(|(i, t)| f(i, t)).collect();
    }
    let next = AtomicUsize::new(0);
    let results: Mutex<Vec<Option<R>>> = Mutex::new((0..items.len()).map(|_| None).collect());
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| {
                WORKER.with(|w| w.set(true));
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(item) = items.get(i) else { break };
                    let r = f(i, item);
                    results.lock().unwrap_or_else(std::sync::PoisonError::into_inner)[i] = Some(r);
                }
            });
        }
    });
    // Every index below the length was taken by one thread, which stored its result.
    results.into_inner().unwrap_or_else(std::sync::PoisonError::into_inner).into_iter().flatten().collect()
}

/// `a()` and `b()` at once: `b` on a new thread, `a` in the calling one, both as workers (a
/// [`map`] inside either runs serially, so the two hold the two CPUs); in turn, `a` first, on one
/// CPU or inside another map's worker. For two unequal jobs whose longer one should have a CPU
/// to itself (the f64 loading law's check run beside its nominal run and the mode check).
pub fn join<A: Send, B: Send>(a: impl FnOnce() -> A + Send, b: impl FnOnce() -> B + Send) -> (A, B) {
    let cpus = std::thread::available_parallelism().map_or(1, |n| n.get());
    if cpus < 2 || WORKER.with(Cell::get) {
        return (a(), b());
    }
    std::thread::scope(|scope| {
        let other = scope.spawn(|| {
            WORKER.with(|w| w.set(true));
            b()
        });
        /// Resets the calling thread's flag, also when `a` panics.
        struct Reset;
        impl Drop for Reset {
            fn drop(&mut self) {
                WORKER.with(|w| w.set(false));
            }
        }
        WORKER.with(|w| w.set(true));
        let reset = Reset;
        let ra = a();
        drop(reset);
        (ra, other.join().unwrap_or_else(|e| std::panic::resume_unwind(e)))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The order of the items is kept and the results equal the serial map's, on 1, 2 and 5
    /// threads, with a nested map (serial inside a worker) and an empty slice.
    #[test]
    fn results_in_order_on_any_number_of_threads() {
        let items: Vec<u64> = (0..37).collect();
        let f = |i: usize, x: &u64| {
            let inner: u64 = map(&[1u64, 2, 3], |_, y| y * x).into_iter().sum();
            (i, x * x + inner)
        };
        let serial: Vec<(usize, u64)> = items.iter().enumerate().map(|(i, x)| (i, x * x + 6 * x)).collect();
        for threads in [1, 2, 5] {
            assert_eq!(map_on(&items, threads, f), serial, "{threads} threads");
        }
        assert!(map(&Vec::<u64>::new(), f).is_empty());
    }

    /// join gives each closure's own result; a map inside either side runs serially (in the
    /// side's thread), and the calling thread is no worker afterwards.
    #[test]
    fn join_gives_both_results_and_maps_inside_run_serially() {
        let side = |k: u64| {
            let here = std::thread::current().id();
            let threads: Vec<_> = map(&[1u64, 2, 3], |_, _| std::thread::current().id());
            let inner: u64 = map(&[1u64, 2, 3], |_, y| y * k).into_iter().sum();
            (inner, threads.iter().all(|t| *t == here))
        };
        let (a, b) = join(|| side(2), || side(5));
        assert_eq!(a, (12, true));
        assert_eq!(b, (30, true));
        assert!(!WORKER.with(Cell::get));
        // Inside a map's worker: in turn, a first.
        let order = map(&[0u8], |_, _| {
            let seq = Mutex::new(Vec::new());
            join(|| seq.lock().unwrap().push('a'), || seq.lock().unwrap().push('b'));
            seq.into_inner().unwrap()
        });
        assert_eq!(order, vec![vec!['a', 'b']]);
    }
}
