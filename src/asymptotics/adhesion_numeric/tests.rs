use super::*;
use crate::asymptotics::adhesion::{adhesion_expansion_with, adhesion_values};
use exact_series::{Ring, Series};

fn q(n: i64, d: i64) -> Q {
    Q::new(n.into(), d.into())
}

fn material(nu: &Q) -> Material {
    Material::from_contact_modulus(nu.clone(), q(1, 1)).unwrap()
}

/// |a - b|/|b| (|a - b| when b = 0).
fn rel(a: &Float, b: &Float) -> f64 {
    let d = Float::with_val(a.prec(), a - b).abs();
    if b.is_zero() {
        d.to_f64()
    } else {
        (d / b.clone().abs()).to_f64()
    }
}

/// Through order 12, the numerical route equals the exact coefficients of
/// `asymptotics::adhesion` substituted at nu (`series adhesion --order 12 --nu R`'s values) at
/// nu = 0, 3/10, 9/20: C_P/pi, every c_n, every A_n and p_j to 1e-40 relative.
#[test]
fn first_terms_equal_the_exact_coefficients() {
    let order = 12;
    let exact = adhesion_expansion_with(order, false).unwrap();
    for nu in [q(0, 1), q(3, 10), q(9, 20)] {
        let prec = 200;
        let values = adhesion_values(&exact, &nu, prec).unwrap();
        let run = adhesion_run(&material(&nu), order / 2, prec);
        let pi = Float::with_val(prec, Constant::Pi);
        let cp = Float::with_val(prec, &values.load_constant / &pi);
        assert!(rel(&run.load_constant_over_pi(), &cp) < 1e-40, "nu = {nu}: C_P/pi");
        for (j, c) in run.load().iter().enumerate() {
            assert!(rel(c, &values.load[2 * j]) < 1e-40, "nu = {nu}: c_{} = {c} vs {}", 2 * j, values.load[2 * j]);
        }
        for (jj, a) in run.psi.iter().enumerate() {
            let want = &values.slope[2 * jj + 1];
            assert!(rel(a, want) < 1e-40, "nu = {nu}: A_{} = {a} vs {want}", 2 * jj + 1);
        }
        for (j, p) in run.p.iter().enumerate() {
            assert!(rel(p, &values.volterra[j]) < 1e-40, "nu = {nu}: p_{j}");
        }
    }
}

/// nu = 1/2 (eps = 0) is Kuznetsov's frictionless problem: c_n are the coefficients of
/// ln sec(lambda)/(lambda^2/2), computed over Q by the exact engine from -log(cos) (independent
/// of the tangent-variable recurrence), through lambda^200, to the digits asked; psi = 0.
#[test]
fn nu_half_is_kuznetsov_through_order_200() {
    let order = 200;
    let s = adhesion_numeric(&q(1, 2), order, 30).unwrap();
    let x = Series::<exact_series::Q>::var(order + 3);
    let lnsec = x.cos().unwrap().log().unwrap().neg();
    assert!(s.pole.is_none());
    assert_eq!(s.load.len(), order / 2 + 1);
    for (k, c, d) in &s.load {
        let want = lnsec.coeff(k + 2).unwrap().scale(&exact_series::Q::from_integer(2.into()));
        let want = crate::numerics::exact::to_float(&want, 300);
        assert!(rel(c, &want) < 1e-30, "c_{k} = {c} vs {want}");
        assert!(*d >= 30.0, "c_{k}: {d} digits");
    }
    assert!(s.slope.iter().all(|(_, a, _)| a.is_zero() || a.to_f64().abs() < 1e-100));
}

/// The two runs agree to the digits asked at every printed coefficient (nu = 3/10, order 200,
/// 30 digits) and a run at 64 more bits confirms the first run's digits (the verification is not
/// fooled by a cancellation common to both runs).
#[test]
fn two_precisions_agree_at_order_200() {
    let nu = q(3, 10);
    let s = adhesion_numeric(&nu, 200, 30).unwrap();
    assert!(s.pole.is_none(), "{}", s.pole_text());
    assert_eq!(s.printed_order(), 200);
    assert!(s.min_digits() >= 30.0, "{}", s.min_digits());
    assert!(s.short().is_empty());
    let third = adhesion_run(&material(&nu), 100, s.bits[1] + 64);
    for (j, (_, c, _)) in s.load.iter().enumerate() {
        assert!(rel(c, &third.load()[j]) < 1e-30, "c_{}", 2 * j);
    }
    for (j, (_, a, _)) in s.slope.iter().enumerate() {
        assert!(rel(a, &third.psi[j]) < 1e-30, "A_{}", 2 * j + 1);
    }
}

/// nu = 0: D_N = Re M_(2N+1) changes sign once below N = 400, at N = 303 (module doc: near
/// N ~ 300); the printed coefficients stop just before (lambda^604), the text and the JSON say so;
/// at nu = 1/10 D_N stays positive through N = 500 (order 1000).
#[test]
#[ignore = "long tier: 13 s alone in the test profile (opt-level 2) on a loaded 2-core machine (scripts/test --long)"]
fn sign_change_at_nu_zero() {
    let run = adhesion_run(&material(&q(0, 1)), 400, 128);
    let n = run.sign_change().expect("D_N changes sign below N = 400 at nu = 0");
    assert!(run.d[..n].iter().all(|d| d.is_sign_positive()));
    assert!(run.d[n..].iter().all(|d| d.is_sign_negative()));
    assert_eq!(n, SIGN_CHANGE_NU_ZERO);
    let s = adhesion_numeric(&q(0, 1), 2 * n + 20, 20).unwrap();
    let pole = s.pole.as_ref().unwrap();
    assert_eq!(pole.n, n);
    assert_eq!(s.printed_order(), 2 * (n - 1));
    assert!(s.text().contains(&format!("changes sign at N = {n}")), "{}", s.pole_text());
    assert_eq!(s.json()["pole"]["power"], 2 * n);
    let run = adhesion_run(&material(&q(1, 10)), 500, 128);
    assert!(run.sign_change().is_none());
}

/// The measured first N with Re M_(2N+1) <= 0 at nu = 0 (`sign_change_at_nu_zero`).
const SIGN_CHANGE_NU_ZERO: usize = 303;

/// Bad input: a clear error naming the parameter, never a panic.
#[test]
fn bad_input() {
    let e = adhesion_numeric(&q(3, 5), 10, 30).unwrap_err().to_string();
    assert!(e.contains("nu") && e.contains("[0, 1/2]"), "{e}");
    let e = adhesion_numeric(&q(1, 4), MAX_ORDER + 2, 30).unwrap_err().to_string();
    assert!(e.contains("order") && e.contains("1000"), "{e}");
    let e = adhesion_numeric(&q(1, 4), 10, 0).unwrap_err().to_string();
    assert!(e.contains("digits"), "{e}");
}
