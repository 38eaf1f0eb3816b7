//! The report's work in parallel (issue 14): an ordered map over the current rayon pool.
//!
//! Results come back in the items' order whatever thread ran them, so the report's text does not
//! depend on the number of threads (`periodic-contact report --jobs 1` runs everything on the
//! calling thread; the test `report_parallel` compares the two). Items are started in the order of
//! a priority the caller gives (the costliest first: the stability maps' large-lambda cells take
//! seconds where most take milliseconds), each thread taking the next item when it is done with
//! its last, so that a long item does not start last and leave one core idle at the end.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, PoisonError};

/// `f` of every item, in the items' order, computed on the current rayon pool; items are started
/// in decreasing `priority` (ties in the items' order). On a pool of one thread (`--jobs 1`), or
/// for one item, everything runs on the calling thread in the items' order.
pub fn map<T: Sync, R: Send>(items: &[T], priority: impl Fn(&T) -> f64, f: impl Fn(&T) -> R + Sync) -> Vec<R> {
    let n = items.len();
    let threads = rayon::current_num_threads().min(n);
    if threads <= 1 {
        return items.iter().map(f).collect();
    }
    let keys: Vec<f64> = items.iter().map(&priority).collect();
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&i, &j| keys[j].total_cmp(&keys[i]));
    let next = AtomicUsize::new(0);
    let slots: Vec<Mutex<Option<R>>> = (0..n).map(|_| Mutex::new(None)).collect();
    rayon::scope(|s| {
        for _ in 0..threads {
            s.spawn(|_| loop {
                let k = next.fetch_add(1, Ordering::Relaxed);
                let Some(&i) = order.get(k) else { break };
                let r = f(&items[i]);
                *slots[i].lock().unwrap_or_else(PoisonError::into_inner) = Some(r);
            });
        }
    });
    // rayon::scope returns when every spawned loop has finished, i.e. every item ran (a panic in
    // `f` is propagated by the scope before this point).
    slots.into_iter().filter_map(|m| m.into_inner().unwrap_or_else(PoisonError::into_inner)).collect()
}

/// Runs `f` on a pool of `jobs` threads (`None`: rayon's global pool, one thread per logical CPU
/// unless `RAYON_NUM_THREADS` says otherwise).
pub fn with_jobs<R: Send>(jobs: Option<usize>, f: impl FnOnce() -> R + Send) -> Result<R, String> {
    match jobs {
        None => Ok(f()),
        Some(n) => {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .map_err(|e| format!("cannot start {n} threads: {e}"))?;
            Ok(pool.install(f))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn results_keep_the_items_order_whatever_the_priority_and_threads() {
        let items: Vec<u64> = (0..40).collect();
        let f = |x: &u64| {
            // Uneven work so that threads finish out of order.
            let mut acc = *x;
            for k in 0..(x % 7) * 20_000 {
                acc = acc.wrapping_mul(6364136223846793005).wrapping_add(k);
            }
            (*x, acc)
        };
        let serial: Vec<(u64, u64)> = items.iter().map(f).collect();
        for jobs in [1, 2, 3] {
            let got = with_jobs(Some(jobs), || map(&items, |x| (*x % 5) as f64, f)).unwrap();
            assert_eq!(got, serial, "jobs = {jobs}");
        }
        assert!(with_jobs(Some(2), || map(&Vec::<u64>::new(), |_| 0.0, f)).unwrap().is_empty());
    }

    #[test]
    fn every_item_runs_once() {
        let count = AtomicUsize::new(0);
        let items: Vec<usize> = (0..25).collect();
        let got = with_jobs(Some(2), || {
            map(
                &items,
                |x| -(*x as f64),
                |x| {
                    count.fetch_add(1, Ordering::Relaxed);
                    x * 2
                },
            )
        })
        .unwrap();
        assert_eq!(count.load(Ordering::Relaxed), 25);
        assert_eq!(got, items.iter().map(|x| x * 2).collect::<Vec<_>>());
    }
}
