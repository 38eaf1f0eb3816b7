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
