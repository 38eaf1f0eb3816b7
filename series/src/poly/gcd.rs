//! Exact division and the multivariate gcd of [`Poly`] (used by its `div_exact` and `gcd` methods
//! and by the fraction field [`crate::Frac`]).
//!
//! The gcd is the recursive primitive pseudo-remainder sequence (Collins / Brown; Geddes, Czapor,
//! Labahn, "Algorithms for Computer Algebra", 1992, sec. 7.3), with a cheap coprimality
//! certificate first, adequate for the small rational functions in eps, B, S that Problem 2 produces.

use super::coprime::coprime_certificate;
use super::{Monomial, Poly};
use crate::ring::Q;
use crate::{Ring, Symbol};
use num_bigint::BigInt;
use num_traits::{One, Zero};
use std::cmp::Ordering;
use std::collections::btree_map::Entry;
use std::collections::BTreeMap;

/// Pure lex comparison of monomials: the alphabetically first symbol is the most significant.
fn lex_cmp(a: &Monomial, b: &Monomial) -> Ordering {
    let (fa, fb) = (a.factors(), b.factors());
    let (mut i, mut j) = (0, 0);
    loop {
        match (fa.get(i), fb.get(j)) {
            (None, None) => return Ordering::Equal,
            (Some(_), None) => return Ordering::Greater,
            (None, Some(_)) => return Ordering::Less,
            (Some(&(sa, ea)), Some(&(sb, eb))) => match sa.cmp(&sb) {
                Ordering::Less => return Ordering::Greater, // a has a more significant symbol
                Ordering::Greater => return Ordering::Less,
                Ordering::Equal => match ea.cmp(&eb) {
                    Ordering::Equal => {
                        i += 1;
                        j += 1;
                    }
                    o => return o,
                },
            },
        }
    }
}

/// The leading term (lex) of a non-zero polynomial.
pub(super) fn leading(p: &Poly) -> (Monomial, Q) {
    let (m, n) = p
        .terms
        .iter()
        .reduce(|best, t| if lex_cmp(&t.0, &best.0) == Ordering::Greater { t } else { best })
        .expect("leading term of a non-zero polynomial");
    (m.clone(), Q::new(n.clone(), p.den.clone()))
}

/// `m / d` when `d` divides `m`.
fn mono_div(m: &Monomial, d: &Monomial) -> Option<Monomial> {
    let mut out = Monomial::one();
    for &(s, e) in m.factors() {
        let f = d.exponent(s);
        if f > e {
            return None;
        }
        out = out.mul(&Monomial::power(s, e - f));
    }
    d.factors().iter().all(|&(s, _)| m.exponent(s) > 0).then_some(out)
}

/// A monomial ordered by [`lex_cmp`] (a monomial order: compatible with multiplication).
#[derive(PartialEq, Eq)]
struct Lex(Monomial);

impl PartialOrd for Lex {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Lex {
    fn cmp(&self, other: &Self) -> Ordering {
        lex_cmp(&self.0, &other.0)
    }
}

/// `lc^k`, from a cache of the powers computed so far.
fn power_of<'c>(cache: &'c mut Vec<BigInt>, k: u32) -> &'c BigInt {
    while cache.len() <= k as usize {
        let next = cache.last().expect("cache starts with lc^0") * &cache[1];
        cache.push(next);
    }
    &cache[k as usize]
}

/// Exact division `a / b` in Q[symbols], `None` if `b` does not divide `a`.
///
/// Multivariate long division in lex order, in integers: with a = A/d_a and b = B/d_b (A, B
/// the integer numerators of the canonical form), a/b = (A/B) d_b/d_a, and every coefficient
/// met while dividing A by B is an integer over a power of lc = lc(B), kept as the pair
/// (numerator, exponent): no gcd until the quotient is built. The remainder lives in a map
/// ordered by monomial, so each quotient term costs one pass over the terms of `b`:
/// O(|q| |b| log |a|) integer operations. A quick degree test refuses first (a divisor of `a`
/// has at most `a`'s degree in every symbol).
pub(super) fn div_exact(a: &Poly, b: &Poly) -> Option<Poly> {
    if b.is_zero() {
        return None;
    }
    if a.is_zero() {
        return Some(Poly::zero());
    }
    if let Some(q) = b.as_q() {
        return Some(a.scale(&q.recip()));
    }
    if b.symbols().into_iter().any(|s| b.degree_in(s) > a.degree_in(s)) {
        return None;
    }
    let mut bt: Vec<(Monomial, BigInt)> = b.terms.clone();
    bt.sort_by(|x, y| lex_cmp(&y.0, &x.0));
    let (lm_b, lc) = bt[0].clone();
    let mut pow = vec![BigInt::one(), lc];
    let mut r: BTreeMap<Lex, (BigInt, u32)> = a.terms.iter().map(|(m, n)| (Lex(m.clone()), (n.clone(), 0))).collect();
    let mut quotient: Vec<(Monomial, BigInt, u32)> = Vec::new();
    while let Some((Lex(lm_r), (n, e))) = r.pop_last() {
        let m = mono_div(&lm_r, &lm_b)?;
        // The quotient term is (n / lc^(e+1)) m; subtract it times the other terms of b.
        let e1 = e + 1;
        for (mb, nb) in &bt[1..] {
            let d = &n * nb;
            match r.entry(Lex(m.mul(mb))) {
                Entry::Vacant(v) => {
                    v.insert((-d, e1));
                }
                Entry::Occupied(mut o) => {
                    let (n2, e2) = o.get_mut();
                    match (*e2).cmp(&e1) {
                        Ordering::Equal => *n2 -= d,
                        Ordering::Less => {
                            *n2 = &*n2 * power_of(&mut pow, e1 - *e2) - d;
                            *e2 = e1;
                        }
                        Ordering::Greater => *n2 -= d * power_of(&mut pow, *e2 - e1),
                    }
                    if n2.is_zero() {
                        o.remove();
                    }
                }
            }
        }
        quotient.push((m, n, e1));
    }
    let emax = quotient.iter().map(|t| t.2).max().unwrap_or(0);
    let mut terms: Vec<(Monomial, BigInt)> =
        quotient.into_iter().map(|(m, n, e)| (m, n * power_of(&mut pow, emax - e) * &b.den)).collect();
    terms.sort_by(|x, y| x.0.cmp(&y.0));
    let den = power_of(&mut pow, emax) * &a.den;
    Some(Poly::normalized(terms, den))
}

/// Coefficients of `p` as a polynomial in `x`: `p = sum_k c_k x^k`, `c_k` free of `x`.
fn coeffs_in(p: &Poly, x: Symbol) -> Vec<Poly> {
    p.split_in(x)
}

/// Content of `p` with respect to `x`: the gcd of its coefficients in `x`.
fn content_in(p: &Poly, x: Symbol) -> Poly {
    coeffs_in(p, x).iter().filter(|c| !c.is_zero()).fold(Poly::zero(), |g, c| gcd(&g, c))
}

/// Pseudo-remainder of `a` by `b` in `x` (deg_x b >= 0, b non-zero).
fn prem(a: &Poly, b: &Poly, x: Symbol) -> Poly {
    let cb = coeffs_in(b, x);
    let n = cb.len() - 1;
    let lcb = cb[n].clone();
    let mut r = a.clone();
    while !r.is_zero() && r.degree_in(x) as usize >= n {
        let cr = coeffs_in(&r, x);
        let m = cr.len() - 1;
        let shift = Poly::term(&Q::from_integer(1.into()), Monomial::power(x, (m - n) as u32));
        r = r.mul(&lcb).sub(&cr[m].mul(&shift).mul(b));
    }
    r
}

/// Makes the lex-leading coefficient 1 (the canonical associate over Q).
fn monic(p: &Poly) -> Poly {
    if p.is_zero() {
        return p.clone();
    }
    let (_, lc) = leading(p);
    p.scale(&lc.recip())
}

/// The monic gcd of two polynomials in Q[symbols] (gcd(0, 0) = 0).
pub(super) fn gcd(a: &Poly, b: &Poly) -> Poly {
    if a.is_zero() {
        return monic(b);
    }
    if b.is_zero() {
        return monic(a);
    }
    if coprime_certificate(a, b) {
        return Poly::one();
    }
    if let Some((g, _, _)) = super::heu::gcd_cofactors(a, b) {
        return g;
    }
    prs_gcd(a, b)
}

/// `(g, a/g, b/g)`, `g` the monic gcd: the certificate, then GCDHEU (which yields the cofactors
/// from its division check), then the PRS and two exact divisions.
pub(super) fn gcd_cofactors(a: &Poly, b: &Poly) -> (Poly, Poly, Poly) {
    if !a.is_zero() && !b.is_zero() {
        if coprime_certificate(a, b) {
            return (Poly::one(), a.clone(), b.clone());
        }
        if let Some(r) = super::heu::gcd_cofactors(a, b) {
            return r;
        }
    }
    let g = if a.is_zero() || b.is_zero() { gcd(a, b) } else { prs_gcd(a, b) };
    if g.is_zero() {
        return (g, Poly::zero(), Poly::zero());
    }
    let (fa, fb) = (div_exact(a, &g).expect("the gcd divides"), div_exact(b, &g).expect("the gcd divides"));
    (g, fa, fb)
}

/// The monic gcd of two non-zero polynomials by the recursive primitive PRS.
pub(super) fn prs_gcd(a: &Poly, b: &Poly) -> Poly {
    let mut syms = a.symbols();
    syms.extend(b.symbols());
    syms.sort();
    syms.dedup();
    let Some(&x) = syms.first() else {
        return Poly::one(); // two non-zero constants
    };
    let (da, db) = (a.degree_in(x), b.degree_in(x));
    if da == 0 {
        return gcd(a, &content_in(b, x));
    }
    if db == 0 {
        return gcd(&content_in(a, x), b);
    }
    let (ca, cb) = (content_in(a, x), content_in(b, x));
    let g_content = gcd(&ca, &cb);
    // Every member of the sequence is made primitive in x (its content, a polynomial in the other
    // symbols, divided out) and over Z (coprime integer coefficients): when x is the last symbol
    // the content is a number,
    // which the division by `content_in` (gcd of non-zero constants = 1) leaves in place, and the
    // pseudo-remainders' integers then grew exponentially along the sequence (a Series<Frac> in
    // Q(a, b) with denominators sharing factors: its inverse through x^5 ran over 100 s).
    let mut p = div_exact(a, &ca).expect("content divides").primitive_integer();
    let mut q = div_exact(b, &cb).expect("content divides").primitive_integer();
    if p.degree_in(x) < q.degree_in(x) {
        std::mem::swap(&mut p, &mut q);
    }
    while !q.is_zero() && q.degree_in(x) > 0 {
        let r = prem(&p, &q, x);
        p = q;
        q = if r.is_zero() {
            r
        } else {
            div_exact(&r, &content_in(&r, x)).expect("content divides").primitive_integer()
        };
    }
    let g_prim = if q.is_zero() { p } else { Poly::one() };
    monic(&g_content.mul(&g_prim))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(s: &str) -> Poly {
        Poly::var(s).unwrap()
    }

    /// Exact division undoes multiplication (canonical quotient, content 1 included) and
    /// refuses a non-divisor, by the degree test or by a failing leading term.
    #[test]
    fn exact_division_inverts_multiplication() {
        let (x, y, z) = (p("x"), p("y"), p("z"));
        let q = |n: i64, d: i64| Poly::from_q(&Q::new(n.into(), d.into()));
        let a = x.mul(&x).mul(&x).mul(&y).sub(&z.mul(&x).mul(&q(2, 3))).add(&q(5, 7));
        let b = y.mul(&z).sub(&x.mul(&x).mul_int(3)).add(&q(1, 2));
        let prod = a.mul(&b);
        let got = div_exact(&prod, &b).unwrap();
        assert_eq!(got, a);
        assert!(got.is_canonical() && prod.is_canonical());
        assert_eq!(div_exact(&prod, &a).unwrap(), b);
        assert!(div_exact(&prod.add(&Poly::one()), &b).is_none());
        assert!(div_exact(&a, &x.mul(&x).mul(&x).mul(&x)).is_none());
        assert!(div_exact(&prod, &b.add(&x)).is_none());
        assert_eq!(div_exact(&Poly::zero(), &b).unwrap(), Poly::zero());
        assert_eq!(div_exact(&a, &q(2, 5)).unwrap(), a.scale(&Q::new(5.into(), 2.into())));
    }

    /// The coprimality certificate never claims coprime for a common factor, and the gcd is
    /// unchanged by it.
    #[test]
    fn certificate_is_sound() {
        let (x, y, z) = (p("x"), p("y"), p("z"));
        let g = x.mul(&y).sub(&z.mul_int(3)).add(&Poly::one()); // xy - 3z + 1
        let a = g.mul(&x.add(&y.mul(&y)));
        let b = g.mul(&z.sub(&x));
        assert!(!coprime_certificate(&a, &b));
        assert_eq!(gcd(&a, &b), monic(&g));
        let c = x.mul(&x).add(&y).add(&Poly::one());
        assert!(coprime_certificate(&a, &c.mul(&z)) || gcd(&a, &c.mul(&z)).is_one());
        assert!(gcd(&a, &c).is_one());
        // a factor in one variable only: y^2 - 2 divides both.
        let h = y.mul(&y).sub(&Poly::from_int(2));
        assert!(!coprime_certificate(&h.mul(&x), &h.mul(&z)));
        assert_eq!(gcd(&h.mul(&x), &h.mul(&z)), h);
        // symbols in neither in common: coprime.
        assert!(coprime_certificate(&x.add(&Poly::one()), &z));
    }

    /// A random polynomial in a, b, c: up to 4 terms, exponents up to 2, coefficients in -9..=9
    /// over 1..=3.
    fn arb_poly() -> impl proptest::strategy::Strategy<Value = Poly> {
        use proptest::prelude::*;
        proptest::collection::vec(((0u32..3, 0u32..3, 0u32..3), -9i64..=9, 1i64..=3), 1..=4).prop_map(|terms| {
            let syms = ["a", "b", "c"].map(|s| Symbol::new(s).unwrap());
            Poly::from_rational_terms(terms.into_iter().map(|((i, j, k), n, d)| {
                let m = Monomial::power(syms[0], i).mul(&Monomial::power(syms[1], j)).mul(&Monomial::power(syms[2], k));
                (m, crate::ring::Q::new(n.into(), d.into()))
            }))
        })
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(96))]
        /// On products g p, g q the heuristic gcd of `heu.rs` (when it answers) agrees with the primitive PRS, its
        /// cofactors multiply back, and the planted factor g divides the gcd.
        #[test]
        fn agrees_with_the_prs(g in arb_poly(), p in arb_poly(), q in arb_poly()) {
            let (x, y) = (g.mul(&p), g.mul(&q));
            proptest::prop_assume!(!x.is_zero() && !y.is_zero());
            let prs = prs_gcd(&x, &y);
            if let Some((d, fx, fy)) = super::super::heu::gcd_cofactors(&x, &y) {
                proptest::prop_assert_eq!(&d, &prs);
                proptest::prop_assert_eq!(d.mul(&fx), x.clone());
                proptest::prop_assert_eq!(d.mul(&fy), y.clone());
            }
            let (d, fx, fy) = x.gcd_cofactors(&y);
            proptest::prop_assert_eq!(&d, &prs);
            proptest::prop_assert_eq!(d.mul(&fx), x);
            proptest::prop_assert_eq!(d.mul(&fy), y);
            proptest::prop_assert!(g.is_zero() || d.div_exact(&g).is_some());
        }
    }
}
