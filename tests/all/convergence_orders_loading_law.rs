//! The loading-law expansion (`asymptotics::loading_law`, issue 12 "Asymptotics beyond the
//! paper") against the full MPFR solution of the loading-law problem
//! (`loading_law::collocation`, an independent method: Chebyshev collocation of the
//! Volterra system in the contact size, chord Newton): at several small Lambda the remainder
//! after the terms through lambda^(2J) of P(Lambda), c/l and psi_hat at chi = +-Lambda/2 (one
//! point on each side) decays like Lambda^(2J+2), J = 0..4: least-squares slopes over
//! Lambda = pi/96, pi/64, pi/32 within 0.05 of 2J + 2, for nu = 3/10 and 0, n = 1/5 and 1/2
//! (measured: within 0.002 at nu = 3/10, n = 1/5; `cargo test --test
//! convergence_orders_loading_law -- --nocapture` prints every slope). An odd power of lambda in the expansion would
//! give slope 2J + 1 (the parity claim of the module doc).

use periodic_contact::asymptotics::loading_law::{law_coefficients, LawExpansion};
use periodic_contact::loading_law::collocation::{solve, LawCollocation, LawSetting};
use periodic_contact::model::{Convention, Exact, Material};
use periodic_contact::numerics::exact::to_float;
use periodic_contact::numerics::tanh_sinh::TanhSinh;
use periodic_contact::params::adhesion::AdhesionParamsMpfr;
use rug::float::Constant;
use rug::Float;

fn q(n: i64, d: i64) -> Exact {
    Exact::new(n.into(), d.into())
}

/// Collocation nodes, bits and precision of the full solution: 30 digits at Lambda <= pi/32
/// (the smallest remainder, J = 4 at pi/96, is ~1e-20 of the value: 30 digits leave it 10).
const NODES: usize = 14;
const BITS: u32 = 90;
const PREC: u32 = 128;

/// J = 0..=4 (terms through lambda^8).
const TERMS: usize = 5;

/// The full solution's P, c/l and psi_hat at chi = +-Lambda/2.
struct Full {
    lambda: Float,
    values: [Float; 4],
}

fn full(material: &Material, n: &Exact, over: Exact) -> Full {
    let setting = LawSetting::linear(material.clone(), n.clone(), over, Convention::Paper);
    let sol: LawCollocation = solve(&setting, NODES, BITS, PREC).unwrap();
    let rule = TanhSinh::new(BITS + 8, 1.0, PREC);
    let half = Float::with_val(PREC, &sol.lambda_max / 2u32);
    let minus = Float::with_val(PREC, -&half);
    Full {
        lambda: sol.lambda_max.clone(),
        values: [sol.load(), sol.centre_ratio(), sol.psi_hat(&half, &rule), sol.psi_hat(&minus, &rule)],
    }
}

/// The series' P, c/l, psi_hat(+-Lambda/2) with the terms through lambda^(2J).
fn partial(e: &LawExpansion, lambda: &Float, big_j: usize) -> [Float; 4] {
    let p = PREC;
    let t = Float::with_val(p, lambda.square_ref());
    let pi = Float::with_val(p, Constant::Pi);
    let (mut load, mut centre, mut pw) = (Float::with_val(p, 0), Float::with_val(p, 0), Float::with_val(p, 1));
    let c = e.load();
    for (cj, gj) in c.iter().zip(&e.g).take(big_j + 1) {
        load += Float::with_val(p, cj * &pw);
        centre += Float::with_val(p, gj * &pw);
        pw *= &t;
    }
    load *= &t;
    // psi_hat = sum_m (-pi/2) A_m chi^m, m odd <= 2J + 1.
    let psi = |sigma: i32| {
        let a = e.slope(sigma);
        let chi = Float::with_val(p, lambda * sigma) / 2u32;
        let mut acc = Float::with_val(p, 0);
        for m in (1..=2 * big_j + 1).step_by(2) {
            acc += Float::with_val(p, &a[m] * Float::with_val(p, rug::ops::Pow::pow(&chi, m as u32)));
        }
        acc * &pi / -2i32
    };
    [load, centre, psi(1), psi(-1)]
}

/// Least-squares slope of ln y against ln x.
fn slope(x: &[f64], y: &[f64]) -> f64 {
    let lx: Vec<f64> = x.iter().map(|v| v.ln()).collect();
    let ly: Vec<f64> = y.iter().map(|v| v.ln()).collect();
    let n = lx.len() as f64;
    let (mx, my) = (lx.iter().sum::<f64>() / n, ly.iter().sum::<f64>() / n);
    let num: f64 = lx.iter().zip(&ly).map(|(a, b)| (a - mx) * (b - my)).sum();
    let den: f64 = lx.iter().map(|a| (a - mx).powi(2)).sum();
    num / den
}

fn check(nu: Exact, n: Exact) {
    let material = Material::from_contact_modulus(nu.clone(), q(1, 1)).unwrap();
    let params = AdhesionParamsMpfr::new(&material, PREC);
    let rule = TanhSinh::new(BITS + 16, 1.0, PREC);
    let e = law_coefficients(&params, &to_float(&n, PREC), TERMS, &rule, PREC).unwrap();
    // Lambda = pi l/L, l/L = 1/64, 1/48, 1/32.
    let t = std::time::Instant::now();
    let fulls: Vec<Full> = [64, 48, 32].iter().map(|d| full(&material, &n, q(1, *d))).collect();
    eprintln!("nu = {nu}, n = {n}: 3 full solutions in {:.1}s", t.elapsed().as_secs_f64());
    let names = ["P", "c/l", "psi(+L/2)", "psi(-L/2)"];
    let lambdas: Vec<f64> = fulls.iter().map(|f| f.lambda.to_f64()).collect();
    for big_j in 0..TERMS {
        for (i, name) in names.iter().enumerate() {
            let rem: Vec<f64> = fulls
                .iter()
                .map(|f| {
                    let s = partial(&e, &f.lambda, big_j);
                    Float::with_val(PREC, &f.values[i] - &s[i]).to_f64().abs() / f.values[i].to_f64().abs()
                })
                .collect();
            let observed = slope(&lambdas, &rem);
            let want = (2 * big_j + 2) as f64;
            eprintln!(
                "  J = {big_j} {name}: slope {observed:.4} (want {want}), remainder {:.1e}..{:.1e}",
                rem[0], rem[2]
            );
            assert!(
                (observed - want).abs() < 0.05,
                "nu = {nu}, n = {n}, {name}, J = {big_j}: slope {observed} vs {want} (remainders {rem:?})"
            );
        }
    }
}

#[test]
fn remainders_nu_3_10_n_1_5() {
    check(q(3, 10), q(1, 5));
}

#[test]
fn remainders_nu_3_10_n_1_2() {
    check(q(3, 10), q(1, 2));
}

#[test]
fn remainders_nu_0_n_1_5() {
    check(q(0, 1), q(1, 5));
}

#[test]
fn remainders_nu_0_n_1_2() {
    check(q(0, 1), q(1, 2));
}
