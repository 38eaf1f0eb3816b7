//! In-process timing of one f64 solve of Problem 1 and its parts (issue 14):
//! `cargo run --release --example solve_timing [-- REPEATS [params|prepared|mpfr|dense]]` (default:
//! the f64 solve of `scenes/sliding_friction.toml`, its parameters and its candidate search apart;
//! `prepared`: only the solve with the parameters derived once;
//! `mpfr`: the verified MPFR solve of `scenes/sinusoid_friction.toml` at 30 digits; `dense`: the
//! machine's flop rate and the LU steps at the f64 solve's sizes, its lower bound). For `perf
//! record`.
use nalgebra::{DMatrix, DVector};
use periodic_contact::params::sliding::SlidingParamsF64;
use periodic_contact::scene::parse::parse_scene;
use periodic_contact::scene::SceneProblem;
use periodic_contact::sliding::collocation_f64::{
    candidate_roots, solve_sliding_f64, solve_sliding_f64_with, SolverOptions,
};
use std::hint::black_box;
use std::time::Instant;

/// Times `reps` calls in 100 batches and prints the fastest batch's and the median batch's time
/// per call (on a shared machine the fastest batch is the least disturbed one).
fn time(name: &str, reps: usize, mut f: impl FnMut()) {
    f();
    let per = (reps / 100).max(1);
    let mut batches: Vec<f64> = (0..100)
        .map(|_| {
            let t = Instant::now();
            for _ in 0..per {
                f();
            }
            t.elapsed().as_secs_f64() * 1e6 / per as f64
        })
        .collect();
    batches.sort_by(f64::total_cmp);
    println!("{name}: {:.2} us (fastest of 100 batches of {per}; median {:.2} us)", batches[0], batches[50]);
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
    if only == "dense" {
        // The machine's dense flop rate (a 512 x 512 product, 2 n^3 flops) and the time of one
        // LU back-substitution at the f64 solve's sizes (17 x 17 at n = 16 nodes, 25 x 25 at the
        // check run's 24), the factorisations cached as in the solver.
        let m = 512;
        let a = DMatrix::<f64>::from_fn(m, m, |i, j| ((i * 7 + j * 13) % 17) as f64 / 17.0 - 0.5);
        let b = DMatrix::<f64>::from_fn(m, m, |i, j| ((i * 5 + j * 3) % 11) as f64 / 11.0 - 0.5);
        let t = Instant::now();
        let r = 5;
        for _ in 0..r {
            black_box(&a * &b);
        }
        let s = t.elapsed().as_secs_f64() / r as f64;
        println!("dense 512 x 512 product: {:.2} GFLOP/s", 2.0 * (m as f64).powi(3) / s / 1e9);
        for size in [17usize, 25] {
            let mat = DMatrix::<f64>::from_fn(size, size, |i, j| {
                1.0 / (1.0 + i as f64 + j as f64) + if i == j { 2.0 } else { 0.0 }
            });
            let lu = mat.clone().lu();
            let rhs = DVector::<f64>::from_fn(size, |i, _| i as f64);
            time(&format!("LU back-substitution {size} x {size} ({} flops)", 2 * size * size), reps * 10, || {
                black_box(lu.solve(black_box(&rhs)));
            });
            time(&format!("LU factorisation {size} x {size} ({} flops)", 2 * size.pow(3) / 3), reps, || {
                black_box(black_box(&mat).clone().lu());
            });
        }
        return;
    }
    if only == "prepared" {
        // Only the solve with the parameters derived once (for `perf record`).
        let prm = SlidingParamsF64::new(&p).expect("parameters");
        time("solve_sliding_f64_with (parameters derived once)", reps, || {
            black_box(solve_sliding_f64_with(black_box(&p), &prm, &[], &opts).unwrap());
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
