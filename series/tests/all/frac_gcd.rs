//! The field of fractions: multivariate gcd and canonical forms.

use exact_series::{Frac, Poly, Ring, Q};

fn v(name: &str) -> Poly {
    Poly::var(name).unwrap()
}

#[test]
fn reduces_common_factors() {
    let (x, y, z) = (v("eps"), v("S"), v("B"));
    let g = x.add(&y.mul(&z)).add(&Poly::from_int(3)); // eps + B S + 3
    let p = x.mul(&x).sub(&y); // eps^2 - S
    let q = z.add(&Poly::from_int(-1)).mul(&x); // (B - 1) eps
    let a = Frac::new(p.mul(&g), q.mul(&g)).unwrap();
    let b = Frac::new(p.clone(), q.clone()).unwrap();
    assert_eq!(a, b);
    // squares and powers of the same factor
    let a = Frac::new(g.mul(&g).mul(&p), g.mul(&q).mul(&g).mul(&g)).unwrap();
    assert_eq!(a, Frac::new(p.clone(), q.mul(&g)).unwrap());
}

#[test]
fn field_arithmetic() {
    let (x, y) = (v("eps"), v("S"));
    let one = Frac::one();
    let d = Frac::from_poly(Poly::one().sub(&x.mul(&y).mul_int(2))); // 1 - 2 eps S
    let inv = d.inv().unwrap();
    assert_eq!(d.mul(&inv), one);
    // 1/(1-u) - 1 = u/(1-u), u = 2 eps S
    let u = Frac::from_poly(x.mul(&y).mul_int(2));
    assert_eq!(inv.sub(&one), u.mul(&inv));
    // a/b + c/d = (ad + bc)/(bd)
    let a = Frac::new(x.clone(), y.clone()).unwrap();
    let c = Frac::new(y.clone(), x.clone()).unwrap();
    let s = a.add(&c);
    assert_eq!(s, Frac::new(x.mul(&x).add(&y.mul(&y)), x.mul(&y)).unwrap());
    assert_eq!(Frac::new(Poly::from_q(&Q::new(1.into(), 2.into())), Poly::from_int(4)).unwrap().text(), "1/8");
}

#[test]
fn substitution() {
    let (x, y) = (v("eps"), v("S"));
    let f = Frac::new(x.clone(), Poly::one().sub(&x.mul(&y))).unwrap();
    let s = exact_series::Symbol::new("eps").unwrap();
    assert_eq!(f.subs(s, &Q::new(1.into(), 2.into())).unwrap().text(), "(-1)/(S - 2)");
    assert!(Frac::new(Poly::one(), x.clone()).unwrap().subs(s, &Q::from_integer(0.into())).is_none());
}

/// A fraction whose numerator and denominator are small random polynomials in a, b times powers
/// of the factors a + b, a - b, a^2 + b (so that sums and products share factors: the case of
/// the `frac_series` example).
fn arb_frac() -> impl proptest::strategy::Strategy<Value = Frac> {
    use proptest::prelude::*;
    let small = proptest::collection::vec((0u32..3, 0u32..3, -5i64..=5), 1..=3);
    (small.clone(), small, proptest::collection::vec(0u32..3, 6)).prop_map(|(n, d, e)| {
        let (a, b) = (v("a"), v("b"));
        let poly = |t: &[(u32, u32, i64)]| {
            t.iter().fold(Poly::zero(), |acc, &(i, j, c)| {
                let m = (0..i).fold(Poly::from_int(c), |p, _| p.mul(&a));
                acc.add(&(0..j).fold(m, |p, _| p.mul(&b)))
            })
        };
        let factors = [a.add(&b), a.sub(&b), a.mul(&a).add(&b)];
        let power = |k: usize| (0..e[k]).fold(Poly::one(), |p, _| p.mul(&factors[k % 3]));
        let num = poly(&n).mul(&power(0)).mul(&power(1));
        let den = poly(&d).add(&Poly::from_int(7)).mul(&power(2)).mul(&power(3)).mul(&power(4)).mul(&power(5));
        Frac::new(num, den).unwrap_or_else(Frac::one)
    })
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
    /// Henrici's sum and product agree with the textbook formulas reduced by one gcd
    /// (n1 d2 + n2 d1)/(d1 d2) and (n1 n2)/(d1 d2), and the field identities hold.
    #[test]
    fn henrici_matches_the_plain_formulas(x in arb_frac(), y in arb_frac()) {
        let (n1, d1, n2, d2) = (x.numer(), x.denom(), y.numer(), y.denom());
        let sum = x.add(&y);
        proptest::prop_assert_eq!(&sum, &Frac::new(n1.mul(d2).add(&n2.mul(d1)), d1.mul(d2)).unwrap());
        let prod = x.mul(&y);
        proptest::prop_assert_eq!(&prod, &Frac::new(n1.mul(n2), d1.mul(d2)).unwrap());
        proptest::prop_assert_eq!(sum.sub(&y), x.clone());
        if !y.is_zero() {
            proptest::prop_assert_eq!(prod.mul(&y.inv().unwrap()), x.clone());
        }
        proptest::prop_assert_eq!(x.sub(&x), Frac::zero());
    }
}
