//! Property tests of the engine's identities (proptest with a fixed seed, so every run checks the
//! same cases): log(exp f) = f, exp(log f) = f, revert(revert f) = f, (f g)/g = f, associativity of
//! composition, the product rule, sin^2 + cos^2 = 1, sqrt(f)^2 = f, f^a f^b = f^(a+b).

use exact_series::{Poly, Ring, Series, Q};
use num_bigint::BigInt;
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

const PREC: usize = 9;

fn runner(seed: u8) -> TestRunner {
    let config = Config { cases: 48, failure_persistence: None, ..Config::default() };
    TestRunner::new_with_rng(config, TestRng::from_seed(RngAlgorithm::ChaCha, &[seed; 32]))
}

fn rational() -> impl Strategy<Value = Q> {
    (-9i64..=9, 1i64..=6).prop_map(|(n, d)| Q::new(BigInt::from(n), BigInt::from(d)))
}

/// A series over Q with the given constant term policy.
fn series_q(c0: Option<Q>) -> impl Strategy<Value = Series<Q>> {
    proptest::collection::vec(rational(), PREC).prop_map(move |mut v| {
        if let Some(c) = &c0 {
            v[0] = c.clone();
        }
        Series::from_coeffs(v)
    })
}

/// A series over Q[theta] (coefficients a + b theta).
fn series_poly(c0: Option<Q>) -> impl Strategy<Value = Series<Poly>> {
    proptest::collection::vec((rational(), rational()), PREC).prop_map(move |v| {
        let theta = Poly::var("theta").unwrap();
        let mut coeffs: Vec<Poly> = v.iter().map(|(a, b)| Poly::from_q(a).add(&theta.scale(b))).collect();
        if let Some(c) = &c0 {
            coeffs[0] = Poly::from_q(c);
        }
        Series::from_coeffs(coeffs)
    })
}

fn q(n: i64) -> Q {
    Q::from_integer(BigInt::from(n))
}

#[test]
fn log_of_exp_is_identity() {
    runner(1)
        .run(&series_q(Some(q(0))), |f| {
            prop_assert_eq!(f.exp().unwrap().log().unwrap(), f.clone());
            Ok(())
        })
        .unwrap();
    runner(2)
        .run(&series_poly(Some(q(0))), |f| {
            prop_assert_eq!(f.exp().unwrap().log().unwrap(), f.clone());
            Ok(())
        })
        .unwrap();
}

#[test]
fn exp_of_log_is_identity() {
    runner(3)
        .run(&series_poly(Some(q(1))), |f| {
            prop_assert_eq!(f.log().unwrap().exp().unwrap(), f.clone());
            Ok(())
        })
        .unwrap();
}

#[test]
fn reversion_of_reversion_is_identity() {
    let strat = series_q(Some(q(0))).prop_filter("f'(0) != 0", |f| f.coeff(1).unwrap() != &q(0));
    runner(4)
        .run(&strat, |f| {
            let g = f.revert().unwrap();
            prop_assert_eq!(g.revert().unwrap(), f.clone());
            // and f(g(y)) = y
            prop_assert_eq!(f.compose(&g).unwrap(), Series::var(PREC));
            Ok(())
        })
        .unwrap();
    let strat = series_poly(Some(q(0)))
        .prop_filter("f'(0) rational non-zero", |f| f.coeff(1).unwrap().as_q().is_some_and(|c| c != q(0)));
    runner(5)
        .run(&strat, |f| {
            prop_assert_eq!(f.revert().unwrap().revert().unwrap(), f.clone());
            Ok(())
        })
        .unwrap();
}

#[test]
fn product_divided_by_factor_is_identity() {
    let strat = (series_poly(None), series_poly(Some(q(3))));
    runner(6)
        .run(&strat, |(f, g)| {
            prop_assert_eq!(f.mul(&g).div(&g).unwrap(), f.clone());
            Ok(())
        })
        .unwrap();
    // A divisor with a leading zero: x^2 g, dividend x^2 f g.
    let strat = (series_q(None), series_q(Some(q(-2))));
    runner(7)
        .run(&strat, |(f, g)| {
            let g2 = g.shift(2);
            let h = f.mul(&g2).div(&g2).unwrap();
            prop_assert!(h.eq_trunc(&f, h.prec()));
            prop_assert_eq!(h.prec(), PREC);
            Ok(())
        })
        .unwrap();
}

#[test]
fn composition_is_associative() {
    let strat = (series_q(None), series_q(Some(q(0))), series_q(Some(q(0))));
    runner(8)
        .run(&strat, |(f, g, h)| {
            let left = f.compose(&g.compose(&h).unwrap()).unwrap();
            let right = f.compose(&g).unwrap().compose(&h).unwrap();
            prop_assert_eq!(left, right);
            Ok(())
        })
        .unwrap();
}

#[test]
fn derivative_of_product() {
    let strat = (series_poly(None), series_poly(None));
    runner(9)
        .run(&strat, |(f, g)| {
            let lhs = f.mul(&g).derivative();
            let rhs = f.derivative().mul(&g).add(&f.mul(&g.derivative()));
            prop_assert_eq!(lhs, rhs);
            Ok(())
        })
        .unwrap();
}

#[test]
fn trigonometric_identities() {
    runner(10)
        .run(&series_poly(Some(q(0))), |f| {
            let (s, c) = f.sin_cos().unwrap();
            prop_assert_eq!(s.mul(&s).add(&c.mul(&c)), Series::one(PREC));
            // tan' = f' (1 + tan^2)
            let t = f.tan().unwrap();
            let lhs = t.derivative();
            let rhs = f.derivative().mul(&Series::one(PREC).add(&t.mul(&t)));
            prop_assert_eq!(lhs, rhs);
            Ok(())
        })
        .unwrap();
}

#[test]
fn square_root_squared() {
    runner(11)
        .run(&series_poly(Some(Q::new(BigInt::from(9), BigInt::from(4)))), |f| {
            let r = f.sqrt().unwrap();
            prop_assert_eq!(r.coeff(0).unwrap().as_q(), Some(Q::new(BigInt::from(3), BigInt::from(2))));
            prop_assert_eq!(r.mul(&r), f.clone());
            Ok(())
        })
        .unwrap();
}

#[test]
fn powers_add_exponents() {
    let theta = Poly::var("theta").unwrap();
    let a = theta.add(&Poly::from_q(&Q::new(BigInt::from(1), BigInt::from(2))));
    let b = theta.neg().add(&Poly::from_int(2));
    runner(12)
        .run(&series_poly(Some(q(1))), |f| {
            let lhs = f.pow(&a).unwrap().mul(&f.pow(&b).unwrap());
            let rhs = f.pow(&a.add(&b)).unwrap();
            prop_assert_eq!(lhs, rhs.clone());
            // integer exponent agrees with repeated multiplication
            prop_assert_eq!(rhs, f.powi(2).unwrap().mul(&f.pow(&Poly::from_q(&Q::new(1.into(), 2.into()))).unwrap()));
            Ok(())
        })
        .unwrap();
}

#[test]
fn preconditions_are_errors_not_panics() {
    let x = Series::<Q>::var(5);
    assert!(x.inv().is_err());
    assert!(x.log().is_err());
    assert!(Series::<Q>::one(5).exp().is_err());
    assert!(Series::<Q>::one(5).compose(&Series::one(5)).is_err());
    assert!(x.shift(1).revert().is_err()); // f'(0) = 0
    assert!(Series::constant(q(2), 5).sqrt().is_err());
    assert!(Series::constant(q(2), 5).pow(&q(3)).is_err());
    assert!(Series::<Q>::one(5).div(&x).is_err());
    let msg = x.inv().unwrap_err().to_string();
    assert!(msg.contains("constant term 0"), "{msg}");
}

#[test]
fn precision_bookkeeping() {
    let x = Series::<Q>::var(6);
    // x^2 * (1 + O(x^3)) is known to O(x^5).
    let f = Series::<Q>::one(3);
    assert_eq!(x.mul(&x).mul(&f).prec(), 5);
    // derivative loses one, integral gains one
    assert_eq!(x.derivative().prec(), 5);
    assert_eq!(x.integral().prec(), 7);
    // composition with an inner series of valuation 2
    let g = x.mul(&x); // x^2 + O(x^7)
    assert_eq!(Series::<Q>::one(4).compose(&g).unwrap().prec(), 7);
}
