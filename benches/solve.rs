//! Criterion benchmarks of one solve and one series evaluation (issue 14):
//! - `f64_solve`: one verified f64 solve of Problem 1 (`solve_sliding_f64`: the scene
//!   `scenes/sliding_friction.toml`, periodic parabola, mu = 0.3, P2 = 1/100, lambda = 0.2497,
//!   automatic nodes (16) for >= 13 digits), which includes its check run with n + 8 nodes, the
//!   p >= 0 samples, the gap integration of the physicality criterion and p at the 86 fixed samples
//!   in u of max p and the pressure difference (both runs); collocation operators cached per thread as in `solve`; `_prepared`:
//!   the same with the f64 parameters derived once (`solve_sliding_f64_with`), and
//!   `parameters_only` what that leaves out (`SlidingParamsF64::new`: kappa and beta in exact
//!   rational arithmetic, in i128 parts for the scene's small decimals, every input rounded once);
//! - `series_eval`: one evaluation of the derived l/l_s of the same problem through Lambda^16 at
//!   Lambda (coefficients prepared once, `numerics::evaluate::PreparedSeries`), in f64 and in MPFR at
//!   30 digits (`precision_for(30)` = 132 bits);
//! - `mpfr_solve`: one verified MPFR solve of Problem 1 at 30 digits
//!   (`sliding::reduction_mpfr::solve_verified`, the two runs at 132 and 164 bits, the
//!   physicality criterion on the first): the scene `scenes/sinusoid_friction.toml` (sinusoid,
//!   mu = 0.5, theta != 0, P2 = 0.005, p at its three points), as `solve SCENE --method mpfr
//!   --digits 30` computes it without the process start, the scene parse and the printing. The
//!   Gauss–Jacobi rules are cached (per process, the scan's lifted f64 rules with the MPFR ones), so
//!   the repeated solve measures a warm one; `_cold` empties that cache before each solve
//!   (`gauss_jacobi_mpfr::clear_cache`, outside the timing), as one solve in a fresh process
//!   computes it; the README states the whole process beside both.
//! - `law_f64`: the loading law's f64 answer on the shipped scene `scenes/adhesion_loading_law.toml`
//!   (nu = 0.3, n = 1/5, l/L = 1/6, its five points): `solve_law_f64` (the march and its check run,
//!   on two CPUs where free, then psi, phi and the stresses at the points), and the problem's
//!   mode exponent at 12 digits (`mode_exponent`, printed with every loading-law answer; `solve`
//!   runs it on its own thread beside the march), each alone; issue 33 asks for the whole
//!   answer in 20 ms (docs/performance.md, "The loading law", Round four).
//!
//! Run: `cargo bench --bench solve`

use criterion::{black_box, criterion_group, criterion_main, BatchSize, Criterion};
use periodic_contact::asymptotics::loading_law_modes::{mode_exponent, MODE_DIGITS};
use periodic_contact::asymptotics::sliding::sliding_expansion_with;
use periodic_contact::loading_law::verified_f64::solve_law_f64;
use periodic_contact::model::{OnPunchRow, SlidingProblem};
use periodic_contact::numerics::evaluate::PreparedSeries;
use periodic_contact::numerics::gauss_jacobi_mpfr::clear_cache;
use periodic_contact::numerics::precision::precision_for;
use periodic_contact::params::sliding::SlidingParamsF64;
use periodic_contact::scene::parse::parse_scene;
use periodic_contact::scene::SceneProblem;
use periodic_contact::sliding::collocation_f64::{solve_sliding_f64, solve_sliding_f64_with, SolverOptions};
use periodic_contact::sliding::reduction_mpfr::solve_verified;
use periodic_contact::sliding::series::{expansion_shape, series_point};
use rug::Float;

fn problem() -> SlidingProblem {
    let text = include_str!("../scenes/sliding_friction.toml");
    match parse_scene(text).expect("the shipped scene parses").problem {
        SceneProblem::Sliding(p) => p,
        _ => unreachable!("sliding_friction.toml is a sliding scene"),
    }
}

fn f64_solve(c: &mut Criterion) {
    let p = problem();
    let opts = SolverOptions::default();
    let s = solve_sliding_f64(&p, &[], &opts).expect("the scene solves");
    let sol = &s.solutions[0];
    assert!(sol.digits().0.iter().all(|d| *d >= 13.0), "digits {:?}", sol.digits());
    c.bench_function("f64_solve/sliding_friction", |b| b.iter(|| solve_sliding_f64(black_box(&p), &[], &opts)));
    // The same with the f64 parameters derived once (kappa and beta in exact rationals).
    let prm = SlidingParamsF64::new(&p).expect("parameters");
    c.bench_function("f64_solve/sliding_friction_prepared", |b| {
        b.iter(|| solve_sliding_f64_with(black_box(&p), &prm, &[], &opts))
    });
    c.bench_function("f64_solve/parameters_only", |b| b.iter(|| SlidingParamsF64::new(black_box(&p))));
}

fn series_eval(c: &mut Criterion) {
    let p = problem();
    let order = 16;
    let e = sliding_expansion_with(expansion_shape(&p).expect("parabola"), order, p.convention()).expect("derives");
    let prec = precision_for(30);
    let sp = series_point(&p, prec).expect("parameters");
    let prepared = PreparedSeries::new(&e.l_over_ls, &sp.bindings(), prec).expect("bound symbols");
    let x = sp.big_lambda.clone();
    let xf = x.to_f64();
    let mut acc = Float::new(prec);
    c.bench_function("series_eval/l_over_ls_order16_f64", |b| b.iter(|| prepared.at_f64(black_box(xf))));
    c.bench_function("series_eval/l_over_ls_order16_mpfr30", |b| {
        b.iter(|| prepared.at_mpfr_into(black_box(&x), &mut acc))
    });
}

fn mpfr_solve(c: &mut Criterion) {
    let scene = parse_scene(include_str!("../scenes/sinusoid_friction.toml")).expect("the shipped scene parses");
    let SceneProblem::Sliding(p) = scene.problem else { unreachable!("sinusoid_friction.toml is a sliding scene") };
    let points = scene.output.points.clone();
    let s = solve_verified(&p, &points, 30).expect("the scene solves");
    assert!(s.iter().all(|v| v.accuracy.digits_verified >= 30.0), "digits {:?}", s[0].accuracy);
    let mut g = c.benchmark_group("mpfr_solve");
    g.sample_size(20);
    g.bench_function("sinusoid_friction_30", |b| b.iter(|| solve_verified(black_box(&p), &points, 30)));
    g.bench_function("sinusoid_friction_30_cold", |b| {
        b.iter_batched(clear_cache, |()| solve_verified(black_box(&p), &points, 30), BatchSize::PerIteration)
    });
    g.finish();
}

fn law_f64(c: &mut Criterion) {
    let scene = parse_scene(include_str!("../scenes/adhesion_loading_law.toml")).expect("the shipped scene parses");
    let SceneProblem::LoadingLaw(p) = scene.problem else { unreachable!("a loading-law scene") };
    let points = scene.output.points.clone();
    let s = solve_law_f64(&p, &points).expect("the scene solves");
    assert!(s.digits.headline >= 12.0, "digits {:?}", s.digits);
    let nu = p.material().poisson_ratio().clone();
    let n = p.law().initial_ratio();
    let mode = mode_exponent(&nu, &n, MODE_DIGITS).expect("the mode check runs");
    assert!(mode.mu.is_none(), "no zero below MU_MAX at nu = 0.3, n = 1/5");
    let mut g = c.benchmark_group("law_f64");
    g.sample_size(20);
    g.bench_function("adhesion_loading_law", |b| b.iter(|| solve_law_f64(black_box(&p), &points)));
    g.bench_function("mode_exponent_12", |b| b.iter(|| mode_exponent(black_box(&nu), &n, MODE_DIGITS)));
    g.finish();
}

criterion_group!(benches, f64_solve, series_eval, mpfr_solve, law_f64);
criterion_main!(benches);
