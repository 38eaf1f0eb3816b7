//! Charts of Problem 2 (explorations that print; the numbers quoted from them in the module docs of
//! `adhesion::volterra_mpfr` and `adhesion::series_f64` say which chart they come from).
//!
//! ```text
//! cargo run --release --example adhesion_charts -- conditioning      verified digits, nodes, pivot
//!     ratio, time and the first tension zone over nu and a/L (20 digits requested);
//!     ADHESION_CHART_SMALL=1 for three sizes only
//! cargo run --release --example adhesion_charts -- singularity       Chebyshev decay rate of F
//!     (200-bit runs) and the real singularity t_s it implies, nu = 0 and 0.3
//! cargo run --release --example adhesion_charts -- series-ratios     ratios f_{n-1}/f_n of the
//!     universal coefficients of the lambda^2 series and their signs
//! cargo run --release --example adhesion_charts -- timing            time of the parts of one solve
//! cargo run --release --example adhesion_charts -- digits-cost       verified digits and time
//!     against the requested digits (nu = 0.3, a/L = 3/20, 11 points)
//! cargo run --release --example adhesion_charts -- series-timing     time of the order-12 exact
//!     series without stresses and of its values at 100 bits, and the values at nu = 0
//! cargo run --release --example adhesion_charts -- homogeneous       the homogeneous solution
//!     (asymptotics::adhesion_mode): loads of collocations with 60-120 nodes at 300 bits, their
//!     residual between the nodes, and log10 |F_a - F_b| over tau, at nu = 0, 0.3, 1/2
//! ```

use periodic_contact::adhesion::series_f64::{self, SeriesParams, UniversalSeries};
use periodic_contact::adhesion::volterra_mpfr::{self, VolterraParams};
use periodic_contact::adhesion::{solve_mpfr_with, solve_verified, TensionZones};
use periodic_contact::asymptotics::adhesion::{adhesion_expansion_with, adhesion_values};
use periodic_contact::model::{AdhesionProblem, AdhesionSize, Exact, Material, Period, PunchShape};
use periodic_contact::params::adhesion::{AdhesionParamsF64, AdhesionParamsMpfr};
use rug::Float;
use std::time::Instant;

fn q(n: i64, d: i64) -> Exact {
    Exact::new(n.into(), d.into())
}

fn material(nu: &Exact) -> Material {
    Material::from_contact_modulus(nu.clone(), q(2, 1)).unwrap()
}

fn problem(nu: Exact, period: Option<Exact>, size: AdhesionSize) -> AdhesionProblem {
    let p = match period {
        Some(l) => Period::finite(l).unwrap(),
        None => Period::Infinite,
    };
    AdhesionProblem::new(material(&nu), p, PunchShape::parabolic(q(3, 1)).unwrap(), size).unwrap()
}

fn conditioning() {
    let points = vec![q(0, 1), q(1, 2), q(9, 10), q(99, 100), q(999, 1000)];
    let sizes = match std::env::var("ADHESION_CHART_SMALL") {
        Ok(_) => vec![q(1, 20), q(1, 10), q(3, 20)],
        Err(_) => {
            vec![q(1, 20), q(1, 10), q(3, 20), q(1, 5), q(1, 4), q(3, 10), q(7, 20), q(2, 5), q(9, 20), q(19, 40)]
        }
    };
    for nu in [q(0, 1), q(3, 10), q(9, 20), q(1, 2)] {
        for a_over_l in &sizes {
            let pr = problem(nu.clone(), Some(q(1, 1)), AdhesionSize::HalfWidth(a_over_l.clone()));
            match solve_verified(&pr, &points, 20) {
                Ok(v) => {
                    let d = v.digits_verified;
                    let s = &v.solution;
                    let z = s
                        .tension
                        .zones
                        .first()
                        .map(|z| format!("({:.6e}, {:.6e})", z.delta_inner.to_f64(), z.delta_outer.to_f64()))
                        .unwrap_or("-".into());
                    println!(
                        "nu {nu} a/L {a_over_l} lambda {:.4}: P2~ {:.20e} digits size {:.1} psi {:.1} phi {:.1} \
                         q1 {:.1} q2 {:.1} | n {} piv {:.1e} | {:.3}s | tension 1-x/a in {z}",
                        s.lambda.to_f64(),
                        s.normal_load.to_f64(),
                        d.size,
                        d.psi,
                        d.phi,
                        d.q1,
                        d.q2,
                        s.nodes,
                        s.pivot_ratio,
                        v.elapsed_seconds
                    );
                }
                Err(e) => println!("nu {nu} a/L {a_over_l}: error {e}"),
            }
        }
    }
}

fn singularity() {
    for nu in [q(0, 1), q(3, 10)] {
        let p = VolterraParams { prec: 260, target_bits: 200, refine: 1.2 };
        let constants = AdhesionParamsMpfr::new(&material(&nu), p.prec);
        for lam in [0.4f64, 0.5, 0.6, 0.7, 0.75, 0.8] {
            match volterra_mpfr::solve(&constants, &Float::with_val(p.prec, lam), p) {
                Ok(s) => {
                    let c: Vec<f64> = s.f_coeffs.iter().map(|x| x.clone().abs().to_f64().max(1e-300).ln()).collect();
                    let n = c.len();
                    let (i0, i1) = (n / 4, 3 * n / 4);
                    let rho = ((c[i0] - c[i1]) / (i1 - i0) as f64).exp();
                    let z = 0.5 * (rho + 1.0 / rho);
                    let ts = (z + 1.0) / 2.0 * lam * lam;
                    println!("nu {nu} lambda {lam}: n {n} rho {rho:.3} -> t_s {ts:.4} (eta_s {:.4})", ts.sqrt());
                }
                Err(e) => println!("nu {nu} lambda {lam}: {e}"),
            }
        }
    }
}

fn series_ratios() {
    for nu in [q(0, 1), q(1, 10), q(3, 10), q(9, 20), q(49, 100)] {
        let constants = AdhesionParamsF64::new(&material(&nu));
        let u = UniversalSeries::new(&constants, SeriesParams::NOMINAL).unwrap();
        let f = &u.f;
        let n = f.len();
        let r: Vec<String> =
            (n - 8..n - 1).chain([20usize, 40, 60]).map(|k| format!("{:.4}", f[k] / f[k + 1])).collect();
        println!("nu {nu} eps {:.4} ratios {r:?}", constants.eps);
        let signs: String = f.iter().map(|x| if *x > 0.0 { '+' } else { '-' }).collect();
        println!("   signs {signs}");
    }
}

fn timing() {
    let m = material(&q(0, 1));
    let p = VolterraParams::for_digits(20);
    for params in [p, p.refined()] {
        let constants = AdhesionParamsMpfr::new(&m, params.prec);
        let lam = Float::with_val(params.prec, 0.4712);
        let n0 = volterra_mpfr::chebyshev_size(0.4712, params.target_bits, params.refine).unwrap();
        let t = Instant::now();
        let s = volterra_mpfr::solve(&constants, &lam, params).unwrap();
        let t1 = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let _ = s.psi_ratio(&Float::with_val(params.prec, 0.5));
        let t2 = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let _ = s.stress_ratio(&q(1, 2));
        let t3 = t.elapsed().as_secs_f64();
        println!(
            "prec {} target {} n0 {n0} n {} solve {t1:.3}s psi {t2:.4}s stress {t3:.4}s",
            params.prec,
            params.target_bits,
            s.f_coeffs.len()
        );
    }
    let pr = problem(q(0, 1), Some(q(1, 1)), AdhesionSize::HalfWidth(q(3, 20)));
    let points = vec![q(0, 1), q(1, 2), q(9, 10), q(99, 100), q(999, 1000)];
    for tz in [TensionZones::Skip, TensionZones::Locate] {
        let t = Instant::now();
        let _ = solve_mpfr_with(&pr, &points, p, tz).unwrap();
        println!("solve_mpfr_with tension {tz:?}: {:.3}s", t.elapsed().as_secs_f64());
    }
    let t = Instant::now();
    let v = solve_verified(&pr, &points, 20).unwrap();
    println!("solve_verified: {:.3}s (own {:.3}s)", t.elapsed().as_secs_f64(), v.elapsed_seconds);
    let t = Instant::now();
    let f = series_f64::solve_nominal(&m, 0.4712).unwrap();
    println!("f64 series at lambda 0.4712: {:.4}s ({} terms)", t.elapsed().as_secs_f64(), f.f.len());
}

fn digits_cost() {
    let ten: Vec<Exact> = (0..=10).map(|i| q(i, 10)).collect();
    let pr = problem(q(3, 10), Some(q(1, 1)), AdhesionSize::HalfWidth(q(3, 20)));
    for d in [10u32, 20, 30, 50, 80] {
        let v = solve_verified(&pr, &ten, d).unwrap();
        let g = v.digits_verified;
        println!(
            "digits {d}: verified size {:.1} psi {:.1} phi {:.1} q1 {:.1} q2 {:.1} nodes {} time {:.3}s",
            g.size, g.psi, g.phi, g.q1, g.q2, v.solution.nodes, v.elapsed_seconds
        );
    }
}

fn series_timing() {
    let t0 = Instant::now();
    let e = adhesion_expansion_with(12, false).unwrap();
    println!("order 12 without stress: {:?}", t0.elapsed());
    let t0 = Instant::now();
    let v = adhesion_values(&e, &q(0, 1), 100).unwrap();
    println!("values at 100 bits: {:?}", t0.elapsed());
    for n in (1..=13).step_by(2) {
        println!("A_{n}/k(pi/L)^{} at nu = 0: {:.30}", n - 1, v.slope[n]);
    }
    for n in (0..=12).step_by(2) {
        println!("c_{n} at nu = 0: {:.30}", v.load[n]);
    }
}

fn homogeneous() {
    let prec = 300;
    let p = VolterraParams { prec, target_bits: prec - 40, refine: 1.3 };
    let pi = Float::with_val(prec, rug::float::Constant::Pi);
    for (nu, lams) in [(q(0, 1), vec![0.8, 0.9, 1.0]), (q(3, 10), vec![1.2, 1.35, 1.45]), (q(1, 2), vec![1.0, 1.45])] {
        let c = AdhesionParamsMpfr::new(&material(&nu), prec);
        let f = AdhesionParamsF64::new(&material(&nu));
        let mode = periodic_contact::asymptotics::adhesion_mode::symmetric_mode_exponent(f.eps, f.b, f.s, 2_000_000);
        println!("nu {nu}: m* = {mode:?}");
        for lam in lams {
            let l = Float::with_val(prec, lam);
            let runs: Vec<_> = [60usize, 80, 100, 120]
                .iter()
                .filter_map(|&n| volterra_mpfr::solve_with_nodes(&c, &l, p, n).ok().map(|s| (n, s)))
                .collect();
            for (n, s) in &runs {
                let res = (1..24)
                    .map(|k| {
                        let sigma = Float::with_val(prec, k as f64 / 24.0 + 0.007);
                        Float::with_val(prec, s.integral_i(&sigma).0 - &pi).abs().to_f64()
                    })
                    .fold(0f64, f64::max);
                println!(
                    "  lambda {lam}: n {n}: load {} residual {res:.1e}",
                    s.load_ratio().to_string_radix(10, Some(32))
                );
            }
            if let [(_, a), .., (_, b)] = runs.as_slice() {
                let d: Vec<String> = (1..=10)
                    .map(|k| {
                        let t = Float::with_val(prec, k as f64 / 10.0);
                        let v = Float::with_val(prec, a.f_at(&t) - b.f_at(&t)).abs().to_f64();
                        format!("{:.1}", v.max(1e-300).log10())
                    })
                    .collect();
                println!("  lambda {lam}: log10|F_60 - F_120| at tau = 0.1..1: {}", d.join(" "));
            }
        }
    }
}

fn main() {
    match std::env::args().nth(1).as_deref() {
        Some("conditioning") => conditioning(),
        Some("singularity") => singularity(),
        Some("series-ratios") => series_ratios(),
        Some("timing") => timing(),
        Some("digits-cost") => digits_cost(),
        Some("series-timing") => series_timing(),
        Some("homogeneous") => homogeneous(),
        _ => eprintln!(
            "usage: adhesion_charts conditioning | singularity | series-ratios | timing | digits-cost | series-timing | homogeneous"
        ),
    }
}
