//! A batch of scenes solved on several threads (issue 33, sweeps): [`solve_many`] runs
//! [`super::solve_answer`] on every scene of a slice, each scene on one thread
//! ([`crate::numerics::parallel::map_on`]: std's scoped threads taking the next unsolved scene from
//! a shared counter; the parallel parts of one solve then run serially on its thread), and returns
//! the results in the order of the scenes. Each result is exactly what the serial solve returns
//! (the solvers' caches are per thread or locked; `tests/all/concurrency.rs` checks threaded solves
//! against serial ones); the throughput on this machine is in docs/performance.md
//! (`examples/throughput.rs`). Tests: below.

use super::{solve_answer, Answer, SolveRequest};
use crate::error::Error;
use crate::scene::Scene;

/// Solves every scene of `scenes` with `request` on `threads` threads (`None`: one per logical
/// CPU, `std::thread::available_parallelism`; never more threads than scenes) and returns each
/// scene's typed [`Answer`] (its `json` is what `periodic-contact solve --json` prints), or its
/// refusal, in the order of `scenes`.
///
/// ```
/// use periodic_contact::api::{parse_scene, solve_many, Method, SolveRequest};
/// let base = include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/sliding_friction.toml"));
/// let scenes: Vec<_> = ["0.001", "0.01", "0.1"]
///     .iter()
///     .map(|p| parse_scene(&base.replace("normal_load = \"0.01\"", &format!("normal_load = \"{p}\""))))
///     .collect::<Result<_, _>>()?;
/// let request = SolveRequest { method: Method::F64, digits: 12, series_order: 12 };
/// let answers = solve_many(&scenes, request, None);
/// assert_eq!(answers.len(), 3);
/// assert_eq!(answers[1].as_ref().unwrap().json["P2"], "1.000000000000e-2");
/// assert!(answers[2].as_ref().unwrap().get("l").is_some_and(|l| l.digits > 12.0));
/// # Ok::<(), periodic_contact::api::ModelError>(())
/// ```
pub fn solve_many(scenes: &[Scene], request: SolveRequest, threads: Option<usize>) -> Vec<Result<Answer, Error>> {
    let cpus = std::thread::available_parallelism().map_or(1, |n| n.get());
    crate::numerics::parallel::map_on(scenes, threads.unwrap_or(cpus), |_, scene| solve_answer(scene, request))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::parse::parse_scene;
    use crate::scene::Method;

    fn scenes() -> Vec<Scene> {
        let base = include_str!("../../scenes/sliding_friction.toml");
        ["0.001", "0.003", "0.01", "0.03", "0.1", "1e9"]
            .iter()
            .map(|p| parse_scene(&base.replace("normal_load = \"0.01\"", &format!("normal_load = \"{p}\""))).unwrap())
            .collect()
    }

    #[test]
    fn a_batch_on_three_threads_equals_the_serial_solves_in_order() {
        let scenes = scenes();
        let request = SolveRequest { method: Method::F64, digits: 12, series_order: 12 };
        let batch = solve_many(&scenes, request, Some(3));
        assert_eq!(batch.len(), scenes.len());
        for (scene, got) in scenes.iter().zip(&batch) {
            let serial = solve_answer(scene, request);
            match (got, &serial) {
                (Ok(a), Ok(b)) => assert_eq!(a, b),
                (Err(a), Err(b)) => assert_eq!(a.to_string(), b.to_string()),
                _ => panic!("batch {got:?} vs serial {serial:?}"),
            }
        }
        // The load 1e9 is beyond the parabola's reach on this scene: refused, in its place.
        assert!(batch[5].is_err(), "{:?}", batch[5]);
        assert!(batch[..5].iter().all(Result::is_ok));
    }

    #[test]
    fn an_empty_batch_is_empty() {
        let request = SolveRequest { method: Method::F64, digits: 12, series_order: 12 };
        assert!(solve_many(&[], request, None).is_empty());
    }
}
