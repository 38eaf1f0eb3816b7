//! Issue 11: the exact Problem 1 series of polynomial punches against the MPFR solver, term by
//! term. For g = x^2 + x^4/10 (even) and g = x^2 + x^3/10 (asymmetric), frictionless, `paper`
//! convention, fixed load P2: truncating l/l_s and rbar - rbar_s after Lambda^n leaves a
//! remainder that scales like Lambda^(n+2) (the series are even in Lambda), n = 2, 4, ..., 10;
//! fitted log-log slopes over Lambda in [0.03, 0.085] within 0.1 of n + 2 (measured: within
//! 0.005: `cargo test --test all convergence_orders_polynomial:: -- --nocapture`).
//!
//! Independent pieces: the series are derived with the profile ratio rho_j = c_j l_s^(j-2)/c_2
//! (and, for the cubic, rbar_s) as symbols and evaluated here at the single punch's values, which
//! come from the MPFR solver at period "inf"; that single punch is itself checked against the
//! series' own single-punch relations (T + rho_1/2 = Tb_s = 0 without friction, and
//! P2 = pi E* c_2 l_s^2 (1/4 - theta^2) m0s) to 30 digits.
//!
//! Problem 2 (nu = 3/10): the quartic's load series against the MPFR Volterra solution, relative
//! remainder after lambda^n ~ lambda^n, n = 4..10, slopes within 0.1 (measured: within 0.01).

use exact_series::{Frac, Q};
use periodic_contact::asymptotics::polynomial::{
    polynomial_sliding_expansion_at, FixedValues, PolynomialProfile, PolynomialSlidingExpansion,
};
use periodic_contact::model::{Convention, Exact, Material, Period, PunchShape, SlidingProblem};
use periodic_contact::numerics::evaluate::poly_mpfr;
use periodic_contact::numerics::exact::to_float;
use periodic_contact::sliding::solve_verified;
use periodic_contact::verification::convergence::slope;
use rug::float::Constant;
use rug::ops::Pow;
use rug::Float;

const DIGITS: u32 = 40;
const PREC: u32 = 180;
const ORDER: usize = 10;

fn q(s: &str) -> Exact {
    exact_series::parse_rational(s).unwrap()
}

fn problem(coefficients: &[&str], p2: &str, period: Period) -> SlidingProblem {
    SlidingProblem::builder()
        .material(Material::from_contact_modulus(q("1/2"), q("1")).unwrap())
        .period(period)
        .shape(PunchShape::polynomial(coefficients.iter().map(|s| q(s)).collect()).unwrap())
        .friction(q("0"))
        .adhesive_friction(q("0"))
        .wear(q("0"))
        .convention(Convention::Paper)
        .normal_load(q(p2))
        .build()
        .unwrap()
}

fn value(f: &Frac, bindings: &[(exact_series::Symbol, Float)]) -> Float {
    let n = poly_mpfr(f.numer(), bindings, PREC).unwrap();
    let d = poly_mpfr(f.denom(), bindings, PREC).unwrap();
    Float::with_val(PREC, n / d)
}

/// sum_{k <= n} c_k Lambda^k.
fn truncated(
    s: &exact_series::Series<Frac>,
    n: usize,
    big_lambda: &Float,
    b: &[(exact_series::Symbol, Float)],
) -> Float {
    let mut acc = Float::with_val(PREC, 0);
    let mut pow = Float::with_val(PREC, 1);
    for k in 0..=n {
        acc += Float::with_val(PREC, value(s.coeff(k).unwrap(), b) * &pow);
        pow *= big_lambda;
    }
    acc
}

/// Runs the study for g = x^2 + c_j x^j (j = 3 or 4) and returns the fitted slopes
/// (n, slope of l, slope of rbar) for n = 2, 4, ..., 10.
fn study(label: &str, coefficients: &[&str], j: usize, p2: &str) -> Vec<(usize, f64, Option<f64>)> {
    let symmetric = j % 2 == 0;
    // Single punch at the same load, by the MPFR solver.
    let single = solve_verified(&problem(coefficients, p2, Period::Infinite), &[], DIGITS).unwrap().remove(0);
    let l_s = single.solution.l.clone();
    let rbar_s = Float::with_val(PREC, &single.solution.c / &l_s);
    let cj = to_float(&q(coefficients[j]), PREC);
    let rho_j = Float::with_val(PREC, &cj * l_s.clone().pow(j as i32 - 2));
    let rho_sym = exact_series::Symbol::new(&format!("rho_{j}")).unwrap();
    let rbar_sym = exact_series::Symbol::new("rbar_s").unwrap();
    let b = vec![(rho_sym, rho_j), (rbar_sym, rbar_s.clone())];

    // The series: rho_j symbolic, theta = 0, rbar_s = 0 (even) or symbolic (cubic: an algebraic
    // root of Tb_s = 0).
    let mut c: Vec<Option<Q>> = vec![Some(q("0")), Some(q("0")), Some(q("1"))];
    c.resize(j + 1, Some(q("0")));
    c[j] = None;
    let profile = PolynomialProfile::new(c).unwrap();
    let fixed = FixedValues { theta: Some(q("0")), rbar_s: symmetric.then(|| q("0")) };
    let e: PolynomialSlidingExpansion =
        polynomial_sliding_expansion_at(&profile, ORDER, Convention::Paper, &fixed).unwrap();

    // The single punch against the series' single-punch relations (30 digits).
    let tb = poly_mpfr(&e.tbar_single, &b, PREC).unwrap();
    assert!(tb.clone().abs() < 1e-30, "{label}: Tb_s at the MPFR single punch = {tb}");
    let pi = Float::with_val(PREC, Constant::Pi);
    let load = Float::with_val(PREC, &pi * poly_mpfr(&e.load_single, &b, PREC).unwrap()) * l_s.clone().square() / 4;
    let p2f = to_float(&q(p2), PREC);
    let rel = Float::with_val(PREC, &load - &p2f).abs() / &p2f;
    assert!(rel < 1e-30, "{label}: single-punch load law, relative error {rel}");

    let targets = [0.03, 0.042, 0.06, 0.085];
    let ns = [2usize, 4, 6, 8, 10];
    let mut logx = Vec::new();
    let mut rem_l: Vec<Vec<f64>> = vec![Vec::new(); ns.len()];
    let mut rem_c: Vec<Vec<f64>> = vec![Vec::new(); ns.len()];
    for &target in &targets {
        // L = pi l_s / Lambda, rounded to an exact rational; Lambda recomputed from it.
        let l_period = std::f64::consts::PI * l_s.to_f64() / target;
        let big_l = Q::new(((l_period * 1e6).round() as i64).into(), 1_000_000.into());
        let big_lambda = Float::with_val(PREC, &pi * &l_s) / to_float(&big_l, PREC);
        let p = problem(coefficients, p2, Period::finite(big_l).unwrap());
        let sol = solve_verified(&p, &[], DIGITS).unwrap().remove(0).solution;
        let l_ratio = Float::with_val(PREC, &sol.l / &l_s);
        let rbar = Float::with_val(PREC, &sol.c / &sol.l);
        logx.push(big_lambda.to_f64().ln());
        for (i, &n) in ns.iter().enumerate() {
            let sl = truncated(&e.l_over_ls, n, &big_lambda, &b);
            let sc = truncated(&e.rbar_minus_rbar_s, n, &big_lambda, &b);
            rem_l[i].push(Float::with_val(PREC, &l_ratio - &sl).abs().to_f64());
            rem_c[i].push(Float::with_val(PREC, Float::with_val(PREC, &rbar - &rbar_s) - &sc).abs().to_f64());
        }
    }
    ns.iter()
        .enumerate()
        .map(|(i, &n)| {
            let sl = slope(&logx, &rem_l[i].iter().map(|x| x.ln()).collect::<Vec<_>>());
            let sc = (!symmetric).then(|| slope(&logx, &rem_c[i].iter().map(|x| x.ln()).collect::<Vec<_>>()));
            eprintln!(
                "{label}: n = {n}: slope l {sl:.4}, rbar {sc:?}; remainders l {:.2e}..{:.2e}, rbar {:.2e}..{:.2e}",
                rem_l[i][0], rem_l[i][3], rem_c[i][0], rem_c[i][3]
            );
            (n, sl, sc)
        })
        .collect()
}

fn check(label: &str, rows: &[(usize, f64, Option<f64>)]) {
    for &(n, sl, sc) in rows {
        let want = (n + 2) as f64;
        assert!((sl - want).abs() < 0.1, "{label}: l/l_s after Lambda^{n}: slope {sl}, want {want}");
        if let Some(sc) = sc {
            assert!((sc - want).abs() < 0.1, "{label}: rbar after Lambda^{n}: slope {sc}, want {want}");
        }
    }
}

#[test]
fn quartic_series_remainders_have_the_predicted_orders() {
    let rows = study("x^2 + x^4/10", &["0", "0", "1", "0", "1/10"], 4, "1/100");
    check("quartic", &rows);
}

#[test]
fn asymmetric_cubic_series_remainders_have_the_predicted_orders() {
    let rows = study("x^2 + x^3/10", &["0", "0", "1", "1/10"], 3, "1/100");
    check("cubic", &rows);
}

/// Problem 2 (complete adhesion, nu = 3/10) for g = x^2 + x^4/10, L = 1: the load series
/// P2 = E* c_2 (L/pi)^2 P(lambda), P/pi = sum_k p_k lambda^k (exact in eps, B, S, sigma_4 =
/// (c_4/c_2)(L/pi)^2, evaluated here in MPFR) truncated after lambda^n leaves a remainder
/// ~ lambda^(n+2) against the MPFR Volterra solution, n = 4, 6, 8, 10; slopes within 0.1.
#[test]
fn adhesion_quartic_load_series_remainders_have_the_predicted_orders() {
    use periodic_contact::adhesion::solve_mpfr;
    use periodic_contact::adhesion::volterra_mpfr::VolterraParams;
    use periodic_contact::asymptotics::adhesion::{series_constants, symbol_values};
    use periodic_contact::asymptotics::polynomial::polynomial_adhesion_expansion;
    use periodic_contact::model::{AdhesionProblem, AdhesionSize};
    let nu = q("3/10");
    let profile = PolynomialProfile::new(vec![Some(q("0")), Some(q("0")), Some(q("1")), Some(q("0")), None]).unwrap();
    let e = polynomial_adhesion_expansion(&profile, 12).unwrap();
    let pi = Float::with_val(PREC, Constant::Pi);
    let mut b = symbol_values(&series_constants(&nu, PREC).unwrap());
    let sigma_4 = Float::with_val(PREC, to_float(&q("1/10"), PREC) / Float::with_val(PREC, pi.square_ref()));
    b.push((exact_series::Symbol::new("sigma_4").unwrap(), sigma_4));
    let shape = PunchShape::polynomial(["0", "0", "1", "0", "1/10"].iter().map(|s| q(s)).collect()).unwrap();
    let material = Material::from_contact_modulus(nu.clone(), q("1")).unwrap();
    let ns = [4usize, 6, 8, 10];
    let mut logx = Vec::new();
    let mut rem: Vec<Vec<f64>> = vec![Vec::new(); ns.len()];
    for a in ["1/40", "1/28", "1/20", "1/14"] {
        let p = AdhesionProblem::new(
            material.clone(),
            Period::finite(q("1")).unwrap(),
            shape.clone(),
            AdhesionSize::HalfWidth(q(a)),
        )
        .unwrap();
        let s = solve_mpfr(&p, &[], VolterraParams::for_digits(30)).unwrap();
        let lam = Float::with_val(PREC, &pi * to_float(&q(a), PREC));
        logx.push(lam.to_f64().ln());
        // P2 = (1/pi)^2 pi (P/pi) = (P/pi)/pi for E* = c_2 = L = 1.
        let scale = Float::with_val(PREC, pi.recip_ref());
        for (i, &n) in ns.iter().enumerate() {
            let series = Float::with_val(PREC, truncated(&e.load, n, &lam, &b) * &scale);
            let r = Float::with_val(PREC, &s.normal_load - &series).abs() / &s.normal_load;
            rem[i].push(r.to_f64());
        }
    }
    for (i, &n) in ns.iter().enumerate() {
        let sl = slope(&logx, &rem[i].iter().map(|x| x.ln()).collect::<Vec<_>>());
        eprintln!(
            "Problem 2 quartic: n = {n}: slope {sl:.4}; relative remainders {:.2e}..{:.2e}",
            rem[i][0], rem[i][3]
        );
        // Relative to P2 ~ lambda^2: the remainder lambda^(n+2) is lambda^n relative.
        let want = n as f64;
        assert!((sl - want).abs() < 0.1, "Problem 2: P2 after lambda^{n}: slope {sl}, want {want}");
    }
}
