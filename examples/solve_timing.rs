//! In-process timing of one f64 solve of Problem 1 and its parts (issue 14):
//! `cargo run --release --example solve_timing [-- REPEATS [params|mpfr]]` (default: the f64
//! solve of `scenes/sliding_friction.toml`, its parameters and its candidate search apart; `mpfr`:
//! the verified MPFR solve of `scenes/sinusoid_friction.toml` at 30 digits). For `perf record`.
use periodic_contact::params::sliding::SlidingParamsF64;
use periodic_contact::scene::parse::parse_scene;
use periodic_contact::scene::SceneProblem;
use periodic_contact::sliding::collocation_f64::{
    candidate_roots, solve_sliding_f64, solve_sliding_f64_with, SolverOptions,
};
use std::hint::black_box;
use std::time::Instant;

fn time(name: &str, reps: usize, mut f: impl FnMut()) {
    f();
    let t = Instant::now();
    for _ in 0..reps {
        f();
    }
    println!("{name}: {:.2} us", t.elapsed().as_secs_f64() * 1e6 / reps as f64);
}

fn main() {
    let reps: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(5000);
    let only = std::env::args().nth(2).unwrap_or_default();
    let text = include_str!("../scenes/sliding_friction.toml");
    let SceneProblem::Sliding(p) = parse_scene(text).expect("parses").problem else { unreachable!() };
    let opts = SolverOptions::default();
    if only == "mpfr" {
        let scene = parse_scene(include_str!("../scenes/sinusoid_friction.toml")).expect("parses");
        let SceneProblem::Sliding(q) = scene.problem else { unreachable!() };
        let pts = scene.output.points.clone();
        time("mpfr solve_verified sinusoid_friction 30", reps, || {
            black_box(periodic_contact::sliding::reduction_mpfr::solve_verified(black_box(&q), &pts, 30).unwrap());
        });
        return;
    }
    if only == "params" {
        time("params", reps, || {
            black_box(SlidingParamsF64::new(black_box(&p)).unwrap());
        });
        return;
    }
    time("params", reps, || {
        black_box(SlidingParamsF64::new(black_box(&p)).unwrap());
    });
    time("candidate_roots (params, search, outputs, physicality)", reps, || {
        black_box(candidate_roots(black_box(&p), &opts).unwrap());
    });
    time("solve_sliding_f64", reps, || {
        black_box(solve_sliding_f64(black_box(&p), &[], &opts).unwrap());
    });
    let prm = SlidingParamsF64::new(&p).expect("parameters");
    time("solve_sliding_f64_with (parameters derived once)", reps, || {
        black_box(solve_sliding_f64_with(black_box(&p), &prm, &[], &opts).unwrap());
    });
}
