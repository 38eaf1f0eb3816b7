//! Known series as checks, each with its independent source.

use exact_series::{Gaussian, Poly, Ring, Series, Q};
use num_bigint::BigInt;

fn fact(n: u64) -> BigInt {
    (1..=n).fold(BigInt::from(1), |a, k| a * BigInt::from(k))
}

/// Bernoulli numbers B_0..B_n (B_1 = +1/2 convention irrelevant: only even ones are used) by the
/// Akiyama–Tanigawa algorithm (Kaneko, "The Akiyama-Tanigawa algorithm for Bernoulli numbers",
/// J. Integer Sequences 3 (2000) 00.2.9): independent of the engine's cos/sinc division.
fn bernoulli(n: usize) -> Vec<Q> {
    let mut out = Vec::new();
    let mut a: Vec<Q> = Vec::new();
    for m in 0..=n {
        a.push(Q::new(BigInt::from(1), BigInt::from(m as u64 + 1)));
        for j in (1..=m).rev() {
            a[j - 1] = Q::from_integer(BigInt::from(j as u64)) * (&a[j - 1] - &a[j]);
        }
        out.push(a[0].clone());
    }
    out
}

#[test]
fn bernoulli_reference_values() {
    // B_2 = 1/6, B_4 = -1/30, B_12 = -691/2730 (DLMF Table 24.2.1).
    let b = bernoulli(12);
    assert_eq!(b[2], Q::new(1.into(), 6.into()));
    assert_eq!(b[4], Q::new((-1).into(), 30.into()));
    assert_eq!(b[12], Q::new((-691).into(), 2730.into()));
}

#[test]
fn z_cot_z_from_bernoulli_numbers() {
    // z cot z = sum_k (-1)^k 2^(2k) B_(2k) z^(2k) / (2k)!  (DLMF 4.19.6)
    let n = 41;
    let z = Series::<Q>::zcot_series(n);
    let b = bernoulli(n);
    for k in 0..n {
        let expected = if k % 2 == 1 {
            Q::zero()
        } else {
            let sign = if (k / 2) % 2 == 0 { BigInt::from(1) } else { -BigInt::from(1) };
            &b[k] * Q::new(sign * (BigInt::from(1) << k), fact(k as u64))
        };
        assert_eq!(z.coeff(k).unwrap(), &expected, "coefficient of z^{k}");
    }
    // The composition route agrees: Z(x) via zcot() of x.
    assert_eq!(Series::<Q>::var(n).zcot().unwrap(), z);
}

#[test]
fn tangent_numbers() {
    // tan x = sum T_n x^n / n!, T_1, T_3, ... = 1, 2, 16, 272, 7936, 353792, 22368256
    // (OEIS A000182).
    let t = Series::<Q>::var(14).tan().unwrap();
    let tangent = [1u64, 2, 16, 272, 7936, 353792, 22368256];
    for (i, &tn) in tangent.iter().enumerate() {
        let n = 2 * i + 1;
        assert_eq!(t.coeff(n).unwrap(), &Q::new(BigInt::from(tn), fact(n as u64)));
        assert!(t.coeff(n - 1).unwrap().is_zero());
    }
}

#[test]
fn sinc_against_sine_recurrence() {
    // sinc z = (-1)^k z^(2k)/(2k+1)!, checked against sin(x)/x from the sin/cos recurrence.
    let n = 30;
    let x = Series::<Q>::var(n + 1);
    let via_sin = x.sin().unwrap().div(&x).unwrap();
    assert_eq!(via_sin, Series::sinc_series(n));
    assert_eq!(Series::<Q>::sinc_series(4).text("z"), "1 - 1/6*z^2 + O(z^4)");
}

fn alpha() -> Poly {
    Poly::var("theta").unwrap().add(&Poly::from_q(&Q::new(1.into(), 2.into())))
}

#[test]
fn reversion_of_x_sinc_power() {
    // y = x (sin x / x)^(1/2 + theta); the x^7 coefficient of the reversion is
    // 49/1296 theta^3 + 91/1440 theta^2 + 1277/36288 theta + 263/40320 (SymPy 1.14 ring_series and
    // python-flint 0.9.0 agree: shared/peers/out_sympy.txt, out_flint.txt).
    let n = 8;
    let f = Series::<Poly>::sinc_series(n).pow(&alpha()).unwrap();
    assert_eq!(f.coeff(2).unwrap().text(), "-1/6*theta - 1/12");
    assert_eq!(f.coeff(6).unwrap().text(), "-1/1296*theta^3 - 1/4320*theta^2 - 1/181440*theta - 1/24192");
    let rev = f.shift(1).truncate(n).revert().unwrap();
    let expected = [
        "0",
        "1",
        "0",
        "1/6*theta + 1/12",
        "0",
        "5/72*theta^2 + 3/40*theta + 29/1440",
        "0",
        "49/1296*theta^3 + 91/1440*theta^2 + 1277/36288*theta + 263/40320",
    ];
    for (k, e) in expected.iter().enumerate() {
        assert_eq!(rev.coeff(k).unwrap().text(), *e, "x^{k}");
    }
}

#[test]
fn symbolic_route_matches_rational_route() {
    // The exp(alpha log sinc) route over Q at theta = 1/3 equals the Miller route over Q[theta]
    // with theta substituted (the check python-flint's script makes).
    let n = 24;
    let th = Q::new(1.into(), 3.into());
    let theta = exact_series::Symbol::new("theta").unwrap();
    let sym = Series::<Poly>::sinc_series(n).pow(&alpha()).unwrap();
    let sym_rev = sym.shift(1).truncate(n).revert().unwrap();
    let a = Q::new(1.into(), 2.into()) + &th;
    let fixed = Series::<Q>::sinc_series(n).log().unwrap().scale(&a).exp().unwrap();
    let fixed_rev = fixed.shift(1).truncate(n).revert().unwrap();
    assert_eq!(sym.map(|c| c.subs(theta, &th).as_q().unwrap()), fixed);
    assert_eq!(sym_rev.map(|c| c.subs(theta, &th).as_q().unwrap()), fixed_rev);
}

#[test]
fn gaussian_arithmetic() {
    type G = Gaussian<Q>;
    let one_plus_i = G::new(Q::one(), Q::one());
    assert_eq!(one_plus_i.mul(&one_plus_i.conj()), G::from_int(2));
    assert_eq!(one_plus_i.mul(&one_plus_i.inv().unwrap()), G::one());
    // exp(i x) = cos x + i sin x
    let x = Series::<G>::var(10);
    let e = x.mul_scalar(&G::i()).exp().unwrap();
    let (s, c) = Series::<Q>::var(10).sin_cos().unwrap();
    let expected = Series::from_fn(10, |k| G::new(c.coeff(k).unwrap().clone(), s.coeff(k).unwrap().clone()));
    assert_eq!(e, expected);
    assert_eq!(G::new(Q::new(1.into(), 2.into()), -Q::one()).text(), "1/2 - i");
}
