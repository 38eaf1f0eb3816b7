#![allow(clippy::needless_range_loop)] // index loops over coefficient tables read best here
use super::*;
use std::sync::OnceLock;

fn q(n: i64, d: i64) -> Q {
    Q::new(BigInt::from(n), BigInt::from(d))
}

/// The order-12 expansion, computed once per test binary (about a minute in the test profile).
fn order12() -> &'static AdhesionExpansion {
    static E: OnceLock<AdhesionExpansion> = OnceLock::new();
    E.get_or_init(|| adhesion_expansion(12).unwrap())
}

fn nu(n: i64, d: i64) -> Q {
    q(n, d)
}

fn sym(name: &str) -> Symbol {
    Symbol::new(name).unwrap()
}

/// The coefficient of `lambda^n` in `ln sec(lambda)/(lambda^2/2)` (Kuznetsov [2.15], docs/theory.md
/// section 6), computed by the engine over Q from -log(cos), independently of the adhesion code.
fn kuznetsov_load(order: usize) -> Series<Q> {
    let x = Series::<Q>::var(order + 3);
    let lnsec = x.cos().unwrap().log().unwrap().neg();
    Series::from_fn(order + 1, |n| lnsec.coeff(n + 2).unwrap().scale(&q(2, 1)))
}

/// nu = 1/2 (eps = 0): the adhesive problem is the frictionless one: c_n of ln sec, psi = 0,
/// h_N real.
#[test]
fn nu_half_reduces_to_kuznetsov() {
    let order = 12;
    let e = order12();
    let kz = kuznetsov_load(order);
    assert_eq!(kz.coeff(2).unwrap(), &q(1, 6)); // docs/theory.md section 5 check value c2 = 1/6
    let zero = Q::from_integer(0.into());
    for n in 0..=order {
        let c = e.load.coeff(n).unwrap().subs(sym(EPS), &zero).unwrap();
        let c = c.subs(sym(S), &zero).unwrap(); // S(0) = 0
        assert_eq!(c.as_q().as_ref(), Some(kz.coeff(n).unwrap()), "c_{n}: {}", c.text());
    }
    for n in 0..=order + 1 {
        let a = e.slope.coeff(n).unwrap().subs(sym(EPS), &zero).unwrap();
        assert!(a.is_zero(), "A_{n} at eps = 0: {}", a.text());
    }
    for n in 0..=order / 2 {
        let h = e.stress.coeff(2 * n).unwrap();
        assert!(h.im.subs(sym(EPS), &zero).unwrap().is_zero());
    }
    // h_0 = tau at eps = 0: Hertz, int_xi^1 tau/sqrt(tau^2 - xi^2) = sqrt(1 - xi^2).
    let h0 = e.stress.coeff(0).unwrap().re.subs(sym(EPS), &zero).unwrap().subs(sym(S), &zero).unwrap();
    assert_eq!(h0.text(), "tau");
}

/// Single-punch check values of docs/theory.md section 5: C_P = pi/(2 (1 - 2 eps S)); A_1 (the
/// single-punch slope) = -2 eps B k/(1 - 2 eps S); A_2 = 0.
#[test]
fn single_punch_constants_exact() {
    let e = adhesion_expansion(4).unwrap();
    let eps = Poly::symbol(sym(EPS));
    let b = Poly::symbol(sym(B));
    let s = Poly::symbol(sym(S));
    let d = Poly::one().sub(&eps.mul(&s).mul_int(2));
    assert_eq!(e.load_constant, Frac::new(Poly::one(), d.mul_int(2)).unwrap());
    assert_eq!(e.slope.coeff(1).unwrap(), &Frac::new(eps.mul(&b).mul_int(-2), d).unwrap());
    for n in [0, 2, 4] {
        assert!(e.slope.coeff(n).unwrap().is_zero());
    }
    for n in [1, 3] {
        assert!(e.load.coeff(n).unwrap().is_zero());
    }
}

/// Independent route for the single punch (Muskhelishvili, fixed a; docs/theory.md section 4 and the
/// Problem 1 reduction with theta = i eps): a bounded solution of (H + i beta) sigma = f on
/// (-a, a) exists iff int_{-1}^{1} f(a y) dy/omega(y) = 0, omega(y) = (1+y)^{1/2+i eps}
/// (1-y)^{1/2-i eps}. With f = (E*/2)(2 k a y - i A_1 a |y|) (self-similar psi = A_1 |x|) this
/// must vanish for the A_1 of the incremental route. Evaluated by MPFR tanh-sinh (no moments, no
/// recurrence, no S): the residual is at the quadrature accuracy.
#[test]
fn single_punch_slope_satisfies_fixed_a_solvability() {
    let e = adhesion_expansion(2).unwrap();
    for nu_v in [nu(0, 1), nu(3, 10), nu(9, 20)] {
        for prec in [128u32, 200] {
            let vals = adhesion_values(&e, &nu_v, prec).unwrap();
            let w = prec + 32;
            let a1 = Float::with_val(w, &vals.slope[1]);
            let eps = Float::with_val(w, &vals.eps);
            let rule = TanhSinh::new(prec, 1.0, w);
            // y = s: weight (1+s)^(-1/2-i eps) (1-s)^(-1/2+i eps); y = -s: the conjugate.
            let mut acc = Complex::with_val(w, 0);
            for k in 0..rule.len() {
                let (sv, cv) = (&rule.s[k], &rule.c[k]);
                let lp = Float::with_val(w, (Float::with_val(w, sv + 1u32)).ln_ref());
                let lm = Float::with_val(w, cv.ln_ref());
                let re = Float::with_val(w, &lp + &lm) / -2i32;
                let im = Float::with_val(w, &lm - &lp) * &eps;
                let wt = Complex::with_val(w, (re, im)).exp();
                let wt_conj = Complex::with_val(w, wt.conj_ref());
                // f(s) = 2 s - i A1 s; f(-s) = -2 s - i A1 s
                let two_s = Float::with_val(w, sv * 2u32);
                let a1s = Float::with_val(w, &a1 * sv);
                let fp = Complex::with_val(w, (two_s.clone(), -a1s.clone()));
                let fm = Complex::with_val(w, (-two_s, -a1s));
                acc += (wt * fp + wt_conj * fm) * &rule.w[k];
            }
            let r = Float::with_val(w, acc.abs_ref()).to_f64();
            let tol = 2f64.powi(-(prec as i32) + 16); // rule accurate to ~prec bits, 16 bits slack
            assert!(r < tol, "nu = {nu_v}: solvability residual {r:e} (prec {prec})");
        }
    }
}

/// The paper's text on (3.17)-(3.18): delta_{1,3} > 0 for nu in [0, 1/2] (A_1 = -k delta_1,
/// A_3 = -k (pi/L)^2 delta_3: the slope points inward), and the positive c_2 term (the mutual
/// influence reduces the contact). Strictly for nu < 1/2; zero at nu = 1/2.
#[test]
fn paper_signs_of_a1_a3_c2() {
    let e = adhesion_expansion(4).unwrap();
    for (n, d) in [(0, 1), (1, 10), (1, 5), (3, 10), (2, 5), (9, 20), (49, 100)] {
        let v = adhesion_values(&e, &nu(n, d), 64).unwrap();
        assert!(v.slope[1] < 0 && v.slope[3] < 0, "nu = {n}/{d}: A1 {} A3 {}", v.slope[1], v.slope[3]);
        assert!(v.load[2] > 0, "nu = {n}/{d}: c2 = {}", v.load[2]);
    }
}

/// The stress coefficient N = 0 at nu = 1/2 is Hertz's sqrt(1 - xi^2) (B = pi), by quadrature.
#[test]
fn stress_leading_term_is_hertz_at_nu_half() {
    let e = adhesion_expansion(2).unwrap();
    for prec in [96u32, 160] {
        let constants = series_constants(&nu(1, 2), prec).unwrap();
        for (n, d) in [(0, 1), (1, 2), (9, 10)] {
            let xi = crate::numerics::exact::to_float(&q(n, d), prec);
            let c = stress_coefficient_mpfr(&e, 0, &xi, &constants, prec, prec).unwrap().unwrap();
            let hertz = Float::with_val(prec, 1 - Float::with_val(prec, &xi * &xi)).sqrt();
            let err = Float::with_val(prec, c.real() - &hertz).abs().to_f64() + c.imag().clone().abs().to_f64();
            assert!(err < 2f64.powi(-(prec as i32) + 20), "xi {n}/{d} prec {prec}: {err:e}");
        }
    }
}

/// Without stresses the same A_n, c_n, p_j.
#[test]
fn without_stress_same_coefficients() {
    let a = adhesion_expansion_with(6, false).unwrap();
    let b = adhesion_expansion(6).unwrap();
    assert_eq!(a.load, b.load);
    assert_eq!(a.slope, b.slope);
    assert_eq!(a.volterra, b.volterra);
    assert_eq!(a.stress.prec(), 0);
    assert_eq!(b.stress.prec(), 7);
}

/// The MPFR values are correct to the requested precision (30+ digits): the order-12 values at
/// 128 bits agree with those at 256 bits to 2^-120 relative, at nu = 0 (largest eps) and 0.3.
#[test]
fn values_stable_across_precisions() {
    let e = order12();
    for nu_v in [nu(0, 1), nu(3, 10)] {
        let lo = adhesion_values(e, &nu_v, 128).unwrap();
        let hi = adhesion_values(e, &nu_v, 256).unwrap();
        let pairs = lo.load.iter().zip(&hi.load).chain(lo.slope.iter().zip(&hi.slope));
        for (x, y) in pairs {
            let d = Float::with_val(256, x - y).abs().to_f64();
            assert!(d <= 2f64.powi(-120) * y.clone().abs().to_f64().max(1e-300), "{x} vs {y}");
        }
        // 30 digits printed for the CLI: e.g. c_2 at nu = 0.
        eprintln!("nu {nu_v}: C_P = {:.32}, c_2 = {:.32}, A_1/k = {:.32}", hi.load_constant, hi.load[2], hi.slope[1]);
    }
}

/// The B-structure of the module doc: c_n and p_j free of B, A_{2J+1}/B free of B, h_N free of B.
#[test]
fn b_enters_only_as_factor_of_the_slope() {
    let e = adhesion_expansion(8).unwrap();
    let b = sym(B);
    let free = |f: &Frac| f.numer().degree_in(b) == 0 && f.denom().degree_in(b) == 0;
    assert!(e.load.coeffs().iter().all(free));
    assert!(e.volterra.iter().all(free));
    assert!(e.stress.coeffs().iter().all(|h| free(&h.re) && free(&h.im)));
    for n in (1..=9).step_by(2) {
        let a = e.slope.coeff(n).unwrap();
        assert!(a.numer().degree_in(b) == 1 && a.denom().degree_in(b) == 0, "A_{n}");
        let over_b = a.numer().div_exact(&Poly::symbol(b)).unwrap();
        assert_eq!(over_b.degree_in(b), 0);
    }
}
