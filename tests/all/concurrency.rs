//! Solves from several threads give the answers of serial solves (issue 34): 4 threads x 50 mixed
//! solves (Problem 1 by f64 and MPFR on the parabola, sinusoid and circle; Problem 2 by f64 and
//! MPFR) through the library, each thread starting at another place of the list so that the
//! process caches (the MPFR Gauss-Jacobi rules, the admissible-range memo) and the per-thread
//! ones (the f64 collocation operators) are filled and read concurrently; every JSON answer
//! (or refusal text) must equal the serial one byte for byte. (The bound of the rule cache: `numerics::gauss_jacobi_mpfr`'s test `the_cache_is_bounded`.)

use periodic_contact::scene::parse::parse_scene;
use periodic_contact::scene::{Method, Scene};
use periodic_contact::solve::{solve_scene, SolveRequest};

fn scene(name: &str) -> Scene {
    let path = format!("{}/scenes/{name}.toml", env!("CARGO_MANIFEST_DIR"));
    parse_scene(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// A sliding scene refused by both methods (no contact carries the load), so that refusals and
/// their memoised admissible scan run concurrently too.
fn refused_scene() -> Scene {
    parse_scene(
        "[problem]\nkind = \"sliding\"\n[material]\npoisson_ratio = \"0.3\"\ncontact_modulus = \"1\"\n\
         [punch]\nshape = \"sinusoidal\"\namplitude = \"0.01\"\nperiod = \"1\"\n[sliding]\nnormal_load = \"0.05\"\n",
    )
    .unwrap()
}

/// The job list: (scene, method, digits).
fn jobs() -> Vec<(Scene, Method, u32)> {
    vec![
        (scene("sliding_friction"), Method::F64, 30),
        (scene("sliding_friction"), Method::Mpfr, 24),
        (scene("sinusoid_friction"), Method::Mpfr, 20),
        (scene("sinusoid_friction"), Method::F64, 30),
        (scene("circle"), Method::Mpfr, 20),
        (scene("sliding_wear_periodic"), Method::F64, 30),
        (scene("adhesion_nu03"), Method::F64, 30),
        (scene("quartic_friction_periodic"), Method::Mpfr, 16),
        (scene("adhesion_nu045"), Method::Mpfr, 12),
        (refused_scene(), Method::Mpfr, 20),
        (refused_scene(), Method::F64, 30),
        (scene("kuznetsov_parabola"), Method::Mpfr, 40),
    ]
}

fn run(job: &(Scene, Method, u32)) -> String {
    let (scene, method, digits) = job;
    match solve_scene(scene, SolveRequest { method: *method, digits: *digits, series_order: 12 }) {
        Ok(v) => serde_json::to_string(&v).unwrap(),
        Err(e) => format!("refused: {e}"),
    }
}

#[test]
fn four_threads_give_the_serial_answers() {
    let jobs = jobs();
    // Serial answers, after emptying the rule cache so that the threads below fill it again.
    let serial: Vec<String> = jobs.iter().map(run).collect();
    assert!(serial.iter().filter(|s| s.starts_with("refused")).count() == 2, "{serial:?}");
    periodic_contact::numerics::gauss_jacobi_mpfr::clear_cache();
    let start = std::time::Instant::now();
    std::thread::scope(|scope| {
        let handles: Vec<_> = (0..4)
            .map(|t| {
                let (jobs, serial) = (&jobs, &serial);
                scope.spawn(move || {
                    for k in 0..50 {
                        let i = (7 * t + k) % jobs.len();
                        let got = run(&jobs[i]);
                        assert_eq!(got, serial[i], "thread {t}, solve {k}: job {i} differs from its serial answer");
                    }
                })
            })
            .collect();
        for h in handles {
            h.join().expect("a solving thread panicked");
        }
    });
    eprintln!("4 x 50 solves: {:.1} s", start.elapsed().as_secs_f64());
}
