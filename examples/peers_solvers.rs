//! Our side of `bench/peers/solvers` (side-by-side benchmark against mpmath and Tamaas).
//! Prints one JSON line per call; times are in-process wall times of the solver call only
//! (no process start-up, no scene parsing), the best of `repeat` calls. The MPFR Gauss–Jacobi
//! rule cache is cleared before every call, so each call builds its rules from scratch.
//!
//! ```text
//! peers_solvers sliding NU ESTAR K L P2 MU TAU0 CW DIGITS REPEAT   Problem 1, periodic parabola,
//!     one MPFR run of the exact reduction (`solve_at`, no verification run, no physicality checks)
//!     at precision_for(DIGITS) bits; p at xh = -0.6, 0, 0.7. Inputs are exact rationals ("3/10").
//! peers_solvers westergaard-f64 A_OVER_L NODES REPEAT    sinusoid, frictionless, E* = D = L = 1,
//!     P2 = pi sin^2(pi a/L) rounded to f64, f64 collocation with NODES nodes (plus its built-in
//!     check run with NODES + max(8, NODES/4) nodes, which cannot be switched off)
//! peers_solvers westergaard-mpfr A_OVER_L DIGITS REPEAT   the same load, one MPFR run (`solve_at`)
//! ```
//! The Westergaard error is |a - a_ref|/a_ref with a_ref = (L/pi) asin(sqrt(P2/(pi E* D))) for the
//! exact f64 load, evaluated at 8192 bits. Values are printed with 80 significant digits..

use num_rational::BigRational;
use periodic_contact::model::{Exact, Material, Period, PunchShape, SlidingProblem};
use periodic_contact::numerics::gauss_jacobi_mpfr::clear_cache;
use periodic_contact::sliding::collocation_f64::{solve_sliding_f64, SolverOptions};
use periodic_contact::sliding::{precision_for, solve_at, Checks, NodeRule, SlidingSolution};
use rug::{float::Constant, Float};
use std::str::FromStr;
use std::time::Instant;

fn q(s: &str) -> Exact {
    BigRational::from_str(s).unwrap_or_else(|_| panic!("not a rational: {s}"))
}

fn s(x: &Float) -> String {
    format!("{:.80e}", x)
}

fn best<T>(repeat: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut best_t = f64::INFINITY;
    let mut out = None;
    for _ in 0..repeat.max(1) {
        clear_cache();
        let t0 = Instant::now();
        let r = f();
        let dt = t0.elapsed().as_secs_f64();
        if dt < best_t {
            best_t = dt;
        }
        out = Some(r);
    }
    (best_t, out.expect("at least one run"))
}

#[allow(clippy::too_many_arguments)]
fn sliding_problem(
    nu: &str,
    es: &str,
    k: &str,
    l: &str,
    p2: Exact,
    mu: &str,
    tau0: &str,
    cw: &str,
    sinus: bool,
) -> SlidingProblem {
    let material = Material::from_contact_modulus(q(nu), q(es)).expect("material");
    let shape = if sinus { PunchShape::sinusoidal(q(k)) } else { PunchShape::parabolic(q(k)) }.expect("shape");
    SlidingProblem::builder()
        .material(material)
        .period(Period::finite(q(l)).expect("period"))
        .shape(shape)
        .friction(q(mu))
        .adhesive_friction(q(tau0))
        .wear(q(cw))
        .normal_load(p2)
        .build()
        .expect("problem")
}

fn westergaard(a_over_l: f64) -> (SlidingProblem, Float) {
    let p2 = std::f64::consts::PI * (std::f64::consts::PI * a_over_l).sin().powi(2);
    let exact = BigRational::from_float(p2).expect("finite");
    let prob = sliding_problem("0", "1", "1", "1", exact.clone(), "0", "0", "0", true);
    let prec = 8192;
    let pi = Float::with_val(prec, Constant::Pi);
    let p = Float::with_val(prec, periodic_contact::numerics::exact::to_rational(&exact));
    let a_ref = (p / &pi).sqrt().asin() / &pi;
    (prob, a_ref)
}

fn log10_rel(x: &Float, r: &Float) -> f64 {
    let d = Float::with_val(r.prec(), x - r).abs() / r;
    if d.is_zero() {
        f64::NEG_INFINITY
    } else {
        d.log10().to_f64()
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let points = [q("-3/5"), q("0"), q("7/10")];
    match args.first().map(String::as_str) {
        Some("sliding") if args.len() == 11 => {
            let a = &args[1..];
            let prob = sliding_problem(&a[0], &a[1], &a[2], &a[3], q(&a[4]), &a[5], &a[6], &a[7], false);
            let digits: u32 = a[8].parse().expect("digits");
            let repeat: usize = a[9].parse().expect("repeat");
            let prec = precision_for(digits);
            let rule = NodeRule { digits: digits as f64, factor: 1.0 };
            let (t, sol) = best(repeat, || solve_at(&prob, &points, rule, Checks::Skip, prec).expect("solve"));
            let x: &SlidingSolution = &sol[0];
            let lam = x.lambda.as_ref().expect("periodic");
            let p: Vec<String> = x.pressure.iter().map(|pp| s(&pp.p)).collect();
            println!(
                "{}",
                serde_json::json!({"time_s": t, "nodes": x.nodes, "prec": x.prec, "lambda": s(lam), "a": s(&x.a),
                    "b": s(&x.b), "c": s(&x.c), "P1": s(&x.p1), "P2": s(&x.p2), "F_def": s(&x.f_def), "p": p})
            );
        }
        Some("westergaard-f64") if args.len() == 4 => {
            let a_over_l: f64 = args[1].parse().expect("a/L");
            let n: usize = args[2].parse().expect("nodes");
            let repeat: usize = args[3].parse().expect("repeat");
            let (prob, a_ref) = westergaard(a_over_l);
            let opts = SolverOptions { nodes: Some(n), accept: 1.0, max_nodes: 4000, ..Default::default() };
            let (t, sol) = best(repeat, || solve_sliding_f64(&prob, &[], &opts));
            match sol {
                Ok(sol) => {
                    let a = Float::with_val(a_ref.prec(), sol.primary().a);
                    println!(
                        "{}",
                        serde_json::json!({"method": "f64", "aL": a_over_l, "n": n, "nodes": sol.primary().nodes,
                            "time_s": t, "log10_err": log10_rel(&a, &a_ref)})
                    );
                }
                Err(e) => {
                    println!("{}", serde_json::json!({"method": "f64", "aL": a_over_l, "n": n, "error": e.to_string()}))
                }
            }
        }
        Some("westergaard-mpfr") if args.len() == 4 => {
            let a_over_l: f64 = args[1].parse().expect("a/L");
            let digits: u32 = args[2].parse().expect("digits");
            let repeat: usize = args[3].parse().expect("repeat");
            let (prob, a_ref) = westergaard(a_over_l);
            let prec = precision_for(digits);
            let rule = NodeRule { digits: digits as f64, factor: 1.0 };
            let (t, sol) = best(repeat, || solve_at(&prob, &[], rule, Checks::Skip, prec).expect("solve"));
            let x = &sol[0];
            println!(
                "{}",
                serde_json::json!({"method": "mpfr", "aL": a_over_l, "digits": digits, "nodes": x.nodes, "prec": x.prec,
                    "time_s": t, "log10_err": log10_rel(&x.a, &a_ref)})
            );
        }
        _ => {
            eprintln!("usage: see the header of examples/peers_solvers.rs");
            std::process::exit(2);
        }
    }
}
