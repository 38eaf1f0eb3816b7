//! Print-only charts of the f64 collocation method of Problem 1
//! (`periodic_contact::sliding::collocation_f64`), whose numbers its module doc quotes:
//!
//! ```text
//! cargo run --release --example collocation_f64_charts -- convergence   errors vs n, automatic nodes, timing
//! cargo run --release --example collocation_f64_charts -- two-roots     the sinusoid's two roots near its maximum load
//! cargo run --release --example collocation_f64_charts -- build-cost    cost of the rules and of the LU
//! cargo run --release --example collocation_f64_charts -- hard-cases    lambda -> pi/2, theta -> +-1/2, small P2 with tau0
//! cargo run --release --example collocation_f64_charts -- load-curve    P2(lambda) of the sinusoid with theta != 0
//! cargo run --release --example collocation_f64_charts -- all
//! ```
//!
//! Closed forms: Kuznetsov P2 = (E* k L^2/pi) ln sec(pi a/L) [2.15], Westergaard
//! P2 = pi E* D sin^2(pi a/L) and its pressure [2.17]. Every problem has E* = 1.

use num_bigint::BigInt;
use periodic_contact::model::{Exact, Material, Period, PunchShape, SlidingLoad, SlidingProblem};
use periodic_contact::numerics::gauss_jacobi_f64::sliding_rules;
use periodic_contact::sliding::collocation_f64::{
    candidate_roots, clear_cache, collocation_nodes, solve_sliding_f64, Collocation, SolverOptions,
};
use std::f64::consts::PI;

fn r(n: i64, d: i64) -> Exact {
    Exact::new(BigInt::from(n), BigInt::from(d))
}

/// Problem with E* = 1, given (nu, L or None, shape, mu, tau0, cW, load).
fn problem(
    nu: Exact,
    period: Option<Exact>,
    shape: PunchShape,
    mu: Exact,
    tau0: Exact,
    cw: Exact,
    load: SlidingLoad,
) -> SlidingProblem {
    let mat = Material::from_contact_modulus(nu, r(1, 1)).unwrap();
    let per = match period {
        Some(l) => Period::finite(l).unwrap(),
        None => Period::Infinite,
    };
    SlidingProblem::builder()
        .material(mat)
        .period(per)
        .shape(shape)
        .friction(mu)
        .adhesive_friction(tau0)
        .wear(cw)
        .load(load)
        .build()
        .unwrap()
}

fn parabola(k: Exact) -> PunchShape {
    PunchShape::parabolic(k).unwrap()
}

fn rel(a: f64, b: f64, scale: f64) -> f64 {
    (a - b).abs() / scale
}

fn main() {
    let which = std::env::args().nth(1).unwrap_or_else(|| "all".into());
    let all = which == "all";
    let mut ran = false;
    for (name, chart) in [
        ("convergence", chart_convergence_and_timing as fn()),
        ("two-roots", chart_sinusoid_two_roots),
        ("build-cost", chart_build_cost),
        ("hard-cases", chart_hard_cases),
        ("load-curve", chart_sinusoid_load_curve),
    ] {
        if all || which == name {
            println!("== {name}");
            chart();
            ran = true;
        }
    }
    if !ran {
        eprintln!("unknown chart {which}: convergence, two-roots, build-cost, hard-cases, load-curve or all");
        std::process::exit(2);
    }
}

/// Cold (empty rule cache) and warm (minimum over 30 runs: the machine is shared; the minimum
/// is the least disturbed) times of one case, printed with its node counts and error estimate.
fn time_case(name: &str, pb: &SlidingProblem) {
    clear_cache();
    let t0 = std::time::Instant::now();
    let s = solve_sliding_f64(pb, &[0.0, 0.5], &SolverOptions::default()).unwrap();
    let cold = t0.elapsed();
    let mut warm = std::time::Duration::MAX;
    for _ in 0..30 {
        let t0 = std::time::Instant::now();
        solve_sliding_f64(pb, &[0.0, 0.5], &SolverOptions::default()).unwrap();
        warm = warm.min(t0.elapsed());
    }
    let s = s.primary();
    println!(
        "{name:24} lambda {:.4} n {} (check {}) est {:.1e}: cold {:?}, warm {:?}",
        s.lambda,
        s.nodes,
        s.accuracy.check_nodes,
        s.accuracy.max(),
        cold,
        warm
    );
}

fn chart_convergence_and_timing() {
    let (k, big_l) = (1.0, 1.0);
    println!("Kuznetsov: relative error of P2 at given l vs n");
    for lam in [0.3f64, 0.7, 1.0, 1.3, 1.45] {
        let a = lam * big_l / PI;
        let p2 = k * big_l * big_l / PI * (1.0 / f64::cos(lam)).ln();
        let mut line = format!("lambda {lam:5}: ");
        for n in [8, 16, 24, 32, 48, 64, 96, 128, 192] {
            let pb = problem(
                r(1, 2),
                Some(r(1, 1)),
                parabola(r(1, 1)),
                r(0, 1),
                r(0, 1),
                r(0, 1),
                SlidingLoad::HalfLength(Exact::from_float(a).unwrap()),
            );
            let opts = SolverOptions { nodes: Some(n), accept: 1.0, ..Default::default() };
            let s = solve_sliding_f64(&pb, &[], &opts).unwrap();
            line += &format!("{n}:{:.1e} ", rel(s.primary().p2, p2, p2));
        }
        println!("{line}  auto n = {}", collocation_nodes(lam, &SolverOptions::default()));
    }
    println!("Westergaard: relative error of p (scale max p) at xh in {{-0.9,0,0.5,0.99}} vs n");
    for lam in [0.3f64, 0.7, 1.0, 1.3, 1.45] {
        let p2 = PI * 0.1 * lam.sin().powi(2);
        let mut line = format!("lambda {lam:5}: ");
        for n in [8, 16, 24, 32, 48, 64, 96, 128, 192] {
            let pts = [-0.9, 0.0, 0.5, 0.99];
            let pb = problem(
                r(1, 2),
                Some(r(1, 1)),
                PunchShape::sinusoidal(r(1, 10)).unwrap(),
                r(0, 1),
                r(0, 1),
                r(0, 1),
                SlidingLoad::HalfLength(Exact::from_float(lam / PI).unwrap()),
            );
            let opts = SolverOptions { nodes: Some(n), accept: 1.0, ..Default::default() };
            let s = match solve_sliding_f64(&pb, &pts, &opts) {
                Ok(s) => s,
                Err(e) => {
                    line += &format!("{n}:ERR({e}) ");
                    continue;
                }
            };
            let s = s.primary();
            let pmax = 2.0 * PI * 0.1 * lam.sin();
            let e = s
                .pressure
                .iter()
                .map(|p| {
                    let chi = PI * p.x;
                    (p.p - 2.0 * PI * 0.1 * chi.cos() * (lam.sin().powi(2) - chi.sin().powi(2)).sqrt()).abs() / pmax
                })
                .fold(rel(s.p2, p2, p2), f64::max);
            line += &format!("{n}:{:.1e} ", e);
        }
        println!("{line}");
    }
    println!("Automatic nodes, P2 given: max relative error of a (scale l), p (scale max p) vs closed forms");
    for lam in [0.3f64, 0.7, 1.0, 1.3] {
        let p2 = k * big_l * big_l / PI * (1.0 / lam.cos()).ln();
        let pb = problem(
            r(1, 2),
            Some(r(1, 1)),
            parabola(r(1, 1)),
            r(0, 1),
            r(0, 1),
            r(0, 1),
            SlidingLoad::NormalLoad(Exact::from_float(p2).unwrap()),
        );
        let s = solve_sliding_f64(&pb, &[], &SolverOptions::default()).unwrap();
        let s = s.primary();
        let a = lam / PI;
        let pw = PI * 0.1 * lam.sin().powi(2);
        let pts = [-0.99, -0.9, -0.5, 0.0, 0.3, 0.77, 0.999];
        let pb = problem(
            r(1, 2),
            Some(r(1, 1)),
            PunchShape::sinusoidal(r(1, 10)).unwrap(),
            r(0, 1),
            r(0, 1),
            r(0, 1),
            SlidingLoad::NormalLoad(Exact::from_float(pw).unwrap()),
        );
        let w = solve_sliding_f64(&pb, &pts, &SolverOptions::default()).unwrap();
        let w = w.primary();
        let pmax = 2.0 * PI * 0.1 * lam.sin();
        let ep = w
            .pressure
            .iter()
            .map(|p| {
                let chi = PI * p.x;
                (p.p - 2.0 * PI * 0.1 * chi.cos() * (lam.sin().powi(2) - chi.sin().powi(2)).sqrt()).abs() / pmax
            })
            .fold(0.0, f64::max);
        println!(
            "lambda {lam}: Kuznetsov a {:.1e} (n {}, est {:.1e}); Westergaard a {:.1e}, p {:.1e} (n {}, est {:.1e})",
            rel(s.a, a, a),
            s.nodes,
            s.accuracy.max(),
            rel(w.a, a, a),
            ep,
            w.nodes,
            w.accuracy.max()
        );
    }
    println!("Timing per case (P2 given, automatic nodes, check run and physicality check included;");
    println!("cold = empty rule/LU cache, warm = cached, minimum of 30 runs):");
    for (name, lam, theta_case) in [
        ("kuznetsov", 0.5, false),
        ("kuznetsov", 1.3, false),
        ("parabola+wear+friction", 1.0, true),
        ("parabola+wear+friction", 1.3, true),
    ] {
        let p2 = k * big_l * big_l / PI * (1.0 / f64::cos(lam)).ln();
        let pb = if theta_case {
            problem(
                r(1, 4),
                Some(r(1, 1)),
                parabola(r(1, 1)),
                r(3, 10),
                r(1, 20),
                r(1, 2),
                SlidingLoad::NormalLoad(Exact::from_float(p2).unwrap()),
            )
        } else {
            problem(
                r(1, 2),
                Some(r(1, 1)),
                parabola(r(1, 1)),
                r(0, 1),
                r(0, 1),
                r(0, 1),
                SlidingLoad::NormalLoad(Exact::from_float(p2).unwrap()),
            )
        };
        time_case(name, &pb);
    }
    for lam in [0.5f64, 1.0, 1.3] {
        let p2 = PI * 0.1 * lam.sin().powi(2);
        let pb = problem(
            r(1, 2),
            Some(r(1, 1)),
            PunchShape::sinusoidal(r(1, 10)).unwrap(),
            r(0, 1),
            r(0, 1),
            r(0, 1),
            SlidingLoad::NormalLoad(Exact::from_float(p2).unwrap()),
        );
        time_case("westergaard", &pb);
    }
}

/// Roots of the sinusoid's scalar equation near the maximum load: two (either side of the
/// peak of P2(lambda)); which are physical.
fn chart_sinusoid_two_roots() {
    for (cw, frac) in [(r(1, 1), 0.40), (r(1, 1), 0.42), (r(4, 1), 0.2), (r(4, 1), 0.25)] {
        let shape = PunchShape::sinusoidal(r(1, 10)).unwrap();
        let pb = problem(
            r(1, 4),
            Some(r(1, 1)),
            shape,
            r(0, 1),
            r(0, 1),
            cw.clone(),
            SlidingLoad::NormalLoad(Exact::from_float(frac * PI * 0.1).unwrap()),
        );
        let roots = match candidate_roots(&pb, &SolverOptions::default()) {
            Ok(roots) => roots,
            Err(e) => {
                println!("cW {cw} P2/(pi D) {frac}: {e}");
                continue;
            }
        };
        for root in roots {
            println!(
                "cW {cw} P2/(pi D) {frac}: lambda {:.5} c/l {:.4} physical {:?}",
                root.lambda,
                root.c / root.l,
                root.physical
            );
        }
    }
}

fn chart_build_cost() {
    for n in [24usize, 48, 96, 134, 201] {
        // Minimum over 7 repetitions (the machine is shared).
        let mut t1 = std::time::Duration::MAX;
        let mut t2 = std::time::Duration::MAX;
        for _ in 0..7 {
            let t0 = std::time::Instant::now();
            let (_r, _c) = sliding_rules(n, 0.1).unwrap();
            t1 = t1.min(t0.elapsed());
            let t0 = std::time::Instant::now();
            let _ = Collocation::new(0.1, n).unwrap();
            t2 = t2.min(t0.elapsed());
        }
        println!("n {n}: rules {t1:?}, rules + matrix + LU {t2:?}");
    }
}

/// Probes of THEORY.md section 7: lambda -> pi/2, theta -> +-1/2, small P2 with tau0 > 0.
fn chart_hard_cases() {
    let show = |name: &str, pb: &SlidingProblem| {
        let t0 = std::time::Instant::now();
        match solve_sliding_f64(pb, &[0.0], &SolverOptions::default()) {
            Ok(s) => {
                let s = s.primary();
                println!("{name}: theta {:.4} lambda {:.6} l {:.6e} c {:.6e} P2 {:.6e} n {} est {:.1e} min_gap {:.1e} ({:?})", s.theta, s.lambda, s.l, s.c, s.p2, s.nodes, s.accuracy.max(), s.physicality.min_gap, t0.elapsed());
            }
            Err(e) => println!("{name}: ERROR {e} ({:?})", t0.elapsed()),
        }
    };
    for (p2n, p2d) in [(1, 1), (3, 1), (5, 1), (8, 1), (12, 1)] {
        // Kuznetsov, L = 1, k = 1: P2 = (1/pi) ln sec(lambda): P2 = 12 is lambda = pi/2 - 2e-16.
        let pb = problem(
            r(1, 2),
            Some(r(1, 1)),
            parabola(r(1, 1)),
            r(0, 1),
            r(0, 1),
            r(0, 1),
            SlidingLoad::NormalLoad(r(p2n, p2d)),
        );
        show(&format!("kuznetsov P2 {p2n}/{p2d}"), &pb);
    }
    for cw in [r(1, 1), r(10, 1), r(100, 1), r(10000, 1)] {
        let pb =
            problem(r(1, 4), None, parabola(r(1, 1)), r(0, 1), r(0, 1), cw.clone(), SlidingLoad::NormalLoad(r(1, 100)));
        show(&format!("single, wear cW {cw}"), &pb);
        let pb = problem(
            r(1, 4),
            Some(r(1, 1)),
            parabola(r(1, 1)),
            r(0, 1),
            r(0, 1),
            cw.clone(),
            SlidingLoad::NormalLoad(r(1, 100)),
        );
        show(&format!("periodic, wear cW {cw}"), &pb);
    }
    for mu in [r(1, 1), r(10, 1), r(1000, 1)] {
        let pb = problem(
            r(0, 1),
            Some(r(1, 1)),
            parabola(r(1, 1)),
            mu.clone(),
            r(0, 1),
            r(0, 1),
            SlidingLoad::NormalLoad(r(1, 100)),
        );
        show(&format!("periodic, friction mu {mu} nu 0"), &pb);
    }
    for p2 in [r(1, 100), r(1, 10000), r(1, 1000000), r(1, 100000000)] {
        let pb = problem(
            r(1, 4),
            Some(r(1, 1)),
            parabola(r(1, 1)),
            r(1, 2),
            r(1, 100),
            r(0, 1),
            SlidingLoad::NormalLoad(p2.clone()),
        );
        show(&format!("periodic, tau0 = 1/100, P2 {p2} (c -> -beta tau0/(E* k) = -1/300)"), &pb);
    }
}

/// P2(lambda) of the sinusoid with theta != 0 (direct problem), for the docs/report.
fn chart_sinusoid_load_curve() {
    for (mu, cw, tau0) in [
        (r(0, 1), r(1, 1), r(0, 1)),
        (r(0, 1), r(4, 1), r(0, 1)),
        (r(1, 1), r(0, 1), r(0, 1)),
        (r(1, 2), r(0, 1), r(1, 50)),
    ] {
        println!("mu {mu} cW {cw} tau0 {tau0}");
        for j in 1..=29 {
            let lam = 1.5 * j as f64 / 29.0;
            let pb = problem(
                r(1, 4),
                Some(r(1, 1)),
                PunchShape::sinusoidal(r(1, 10)).unwrap(),
                mu.clone(),
                tau0.clone(),
                cw.clone(),
                SlidingLoad::HalfLength(Exact::from_float(lam / PI).unwrap()),
            );
            let opts = SolverOptions { accept: 1.0, ..Default::default() };
            match solve_sliding_f64(&pb, &[], &opts) {
                Ok(s) => {
                    let v: Vec<String> = s
                        .solutions
                        .iter()
                        .map(|s| {
                            format!(
                                "P2/(pi D) {:.6} c/l {:.4} mingap {:.1e} closure {:?}",
                                s.p2 / (PI * 0.1),
                                s.c / s.l,
                                s.physicality.min_gap,
                                s.physicality.closure_defect
                            )
                        })
                        .collect();
                    println!("  lambda {lam:.4} theta {:.3}: {}", s.primary().theta, v.join(" | "));
                }
                Err(e) => println!("  lambda {lam:.4}: {e}"),
            }
        }
    }
}
