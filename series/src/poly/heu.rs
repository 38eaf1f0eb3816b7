//! The heuristic gcd GCDHEU (Char, Geddes, Gonnet, "GCDHEU: heuristic polynomial GCD algorithm
//! based on integer GCD computation", J. Symbolic Comput. 7, 1989; Geddes, Czapor, Labahn,
//! "Algorithms for Computer Algebra", 1992, sec. 7.7), tried by [`super::gcd`] before the
//! primitive remainder sequence.
//!
//! For primitive a, b in Z[x_1, ..., x_k] and an integer xi > 2 min(|a|, |b|) + 2 (max-norms), the
//! gcd of the images a(x_k = xi), b(x_k = xi) (one symbol fewer, recursively; no symbol left: GMP's
//! integer gcd) is the image of gcd(a, b) times a small integer; its symmetric xi-adic expansion
//! gives a candidate whose primitive part, when it divides both a and b exactly, is gcd(a, b)
//! (op. cit., theorem 7.7). A candidate that does not divide is refused and xi grows (six tries,
//! then `None`: the caller's PRS decides). Above the recursion, [`gcd_cofactors`] proves the answer
//! independently of the theorem: the cofactors a/g and b/g must pass the modular coprimality
//! certificate, or the answer is refused.
//!
//! Exponents are packed into one `u64` (16 bits per symbol, at most 4 symbols, the alphabetically
//! first symbol in the most significant bits), so comparing packed monomials is pure lex order and
//! multiplying them is one addition; polynomials outside that range are left to the PRS.

use super::{Monomial, Poly};
use crate::gmp::{to_big, to_rug};
use crate::{Ring, Symbol};
use num_bigint::BigInt;
use rug::{Assign, Complete, Integer};
use std::collections::BTreeMap;

/// Bits per symbol in a packed monomial.
const FIELD: u32 = 16;
/// The largest exponent a packed monomial holds.
const MAX_EXP: u64 = (1 << FIELD) - 1;
/// The most symbols a packed monomial holds.
const MAX_SYMBOLS: usize = 4;
/// Tries of the evaluation point per level before giving up.
const TRIES: usize = 6;
/// The largest image (bits) the heuristic builds before giving up: `bits(xi) (deg + 1)`.
const MAX_IMAGE_BITS: u64 = 1 << 22;

/// A polynomial over Z: terms `(packed monomial, non-zero coefficient)`, in no particular order.
type ZPoly = Vec<(u64, Integer)>;

fn shift(var: usize) -> u32 {
    FIELD * (MAX_SYMBOLS - 1 - var) as u32
}

fn exponent(m: u64, var: usize) -> u64 {
    (m >> shift(var)) & MAX_EXP
}

/// Whether every exponent of `d` is at most the one of `m`.
fn divides(d: u64, m: u64, nvars: usize) -> bool {
    (0..nvars).all(|v| exponent(d, v) <= exponent(m, v))
}

fn degree(p: &[(u64, Integer)], var: usize) -> u64 {
    p.iter().map(|(m, _)| exponent(*m, var)).max().unwrap_or(0)
}

/// The gcd of the coefficients (positive).
fn content(p: &[(u64, Integer)]) -> Integer {
    let mut g = Integer::new();
    for (_, c) in p {
        g.gcd_mut(c);
        if g == 1 {
            break;
        }
    }
    g
}

/// The largest absolute value of a coefficient.
fn norm(p: &[(u64, Integer)]) -> Integer {
    p.iter().map(|(_, c)| c.as_abs()).max_by(|a, b| (**a).cmp(&**b)).map_or_else(Integer::new, |c| (*c).clone())
}

/// The leading term in lex order (the largest packed monomial).
fn leading(p: &[(u64, Integer)]) -> &(u64, Integer) {
    p.iter().max_by_key(|(m, _)| *m).expect("non-zero polynomial")
}

/// `p / c` for an integer `c` dividing every coefficient.
fn div_int(p: &[(u64, Integer)], c: &Integer) -> ZPoly {
    if *c == 1 {
        return p.to_vec();
    }
    p.iter().map(|(m, n)| (*m, n.div_exact_ref(c).complete())).collect()
}

/// The primitive part with a positive leading coefficient.
fn primitive(p: &[(u64, Integer)]) -> ZPoly {
    let mut c = content(p);
    if leading(p).1.is_negative() {
        c = -c;
    }
    div_int(p, &c)
}

/// `p` at `x_var = xi`, as a polynomial in the other symbols (zeros dropped).
fn evaluate(p: &[(u64, Integer)], var: usize, xi: &Integer) -> ZPoly {
    let d = degree(p, var) as usize;
    let mut powers = Vec::with_capacity(d + 1);
    powers.push(Integer::from(1));
    for k in 1..=d {
        let next = (&powers[k - 1] * xi).complete();
        powers.push(next);
    }
    let mask = !(MAX_EXP << shift(var));
    let mut acc: BTreeMap<u64, Integer> = BTreeMap::new();
    for (m, c) in p {
        let v = (c * &powers[exponent(*m, var) as usize]).complete();
        *acc.entry(m & mask).or_default() += v;
    }
    acc.into_iter().filter(|(_, c)| *c != 0).collect()
}

/// The symmetric xi-adic expansion of every coefficient of `h` (free of `x_var`) as a polynomial in
/// `x_var`: digits in `(-xi/2, xi/2]`. `None` when an exponent would not fit the packing.
fn reconstruct(h: &[(u64, Integer)], var: usize, xi: &Integer) -> Option<ZPoly> {
    let half = (xi >> 1u32).complete();
    let mut out = Vec::new();
    for (m, c) in h {
        let mut c = c.clone();
        let mut k: u64 = 0;
        while c != 0 {
            if k > MAX_EXP {
                return None;
            }
            let (mut q, mut r) = c.div_rem_euc_ref(xi).complete();
            if r > half {
                r -= xi;
                q += 1;
            }
            if r != 0 {
                out.push((m | (k << shift(var)), r));
            }
            c = q;
            k += 1;
        }
    }
    Some(out)
}

/// The exact quotient `a / b` in Z[x_1..x_nvars], `None` when `b` does not divide `a`. Lex long
/// division with every quotient coefficient an exact integer division (b primitive or not); a
/// quotient term beyond deg a - deg b in some symbol refuses at once.
fn divide(a: &[(u64, Integer)], b: &[(u64, Integer)], nvars: usize) -> Option<ZPoly> {
    let (lm, lc) = leading(b).clone();
    let bound: Vec<u64> = (0..nvars).map(|v| degree(a, v)).collect();
    let bdeg: Vec<u64> = (0..nvars).map(|v| degree(b, v)).collect();
    if (0..nvars).any(|v| bdeg[v] > bound[v]) {
        return None;
    }
    let rest: Vec<&(u64, Integer)> = b.iter().filter(|(m, _)| *m != lm).collect();
    let mut r: BTreeMap<u64, Integer> = a.iter().cloned().collect();
    let mut q = Vec::new();
    let mut t = Integer::new();
    while let Some((m, c)) = r.pop_last() {
        if !divides(lm, m, nvars) || !c.is_divisible(&lc) {
            return None;
        }
        let qm = m - lm; // field-wise: every field of lm is at most that of m
        if (0..nvars).any(|v| exponent(qm, v) + bdeg[v] > bound[v]) {
            return None;
        }
        let qc = c.div_exact(&lc);
        for (mb, cb) in &rest {
            t.assign(&qc * cb);
            let e = r.entry(qm + mb).or_default();
            *e -= &t;
            if *e == 0 {
                r.remove(&(qm + mb));
            }
        }
        q.push((qm, qc));
    }
    Some(q)
}

/// `(g, a/g, b/g)` with `g = gcd(a, b)` in Z[x_1..x_k] (content included: the gcd of the
/// contents times the primitive gcd, positive leading coefficient), by GCDHEU; `None` when the
/// heuristic gives up. The cofactors are the quotients of the division check.
fn heu(a: &[(u64, Integer)], b: &[(u64, Integer)], k: usize) -> Option<(ZPoly, ZPoly, ZPoly)> {
    let (ca, cb) = (content(a), content(b));
    let gc = ca.gcd_ref(&cb).complete();
    let (fa, fb) = (ca.div_exact_ref(&gc).complete(), cb.div_exact_ref(&gc).complete());
    let scaled = |p: ZPoly, c: &Integer| -> ZPoly {
        if *c == 1 {
            p
        } else {
            p.into_iter().map(|(m, x)| (m, x * c)).collect()
        }
    };
    if k == 0 {
        // Constants: the cofactors carry the signs (the contents are positive).
        let (qa, qb) = (a[0].1.div_exact_ref(&gc).complete(), b[0].1.div_exact_ref(&gc).complete());
        return Some((vec![(0, gc)], vec![(0, qa)], vec![(0, qb)]));
    }
    let var = k - 1;
    let (a1, b1) = (div_int(a, &ca), div_int(b, &cb));
    let (da, db) = (degree(&a1, var), degree(&b1, var));
    if da == 0 && db == 0 {
        let (h, qa, qb) = heu(&a1, &b1, var)?;
        return Some((scaled(h, &gc), scaled(qa, &fa), scaled(qb, &fb)));
    }
    let mut xi: Integer = norm(&a1).min(norm(&b1)) * 2u32 + 2u32;
    for _ in 0..TRIES {
        if u64::from(xi.significant_bits()) * (da.max(db) + 1) > MAX_IMAGE_BITS {
            return None;
        }
        let (ea, eb) = (evaluate(&a1, var, &xi), evaluate(&b1, var, &xi));
        if !ea.is_empty()
            && !eb.is_empty()
            && let Some((h, _, _)) = heu(&ea, &eb, var)
        {
            let g = primitive(&reconstruct(&h, var, &xi)?);
            if let Some(qa) = divide(&a1, &g, k)
                && let Some(qb) = divide(&b1, &g, k)
            {
                return Some((scaled(g, &gc), scaled(qa, &fa), scaled(qb, &fb)));
            }
        }
        // The growth factor of Char, Geddes and Gonnet (about xi^(5/4) times 2.73).
        let root = xi.clone().sqrt().sqrt();
        xi = xi * 73794u32 * root / 27011u32;
    }
    None
}

/// The packed integer numerators of `p` over the symbols `syms` (sorted); `None` when an exponent
/// does not fit.
fn pack(p: &Poly, syms: &[Symbol]) -> Option<ZPoly> {
    p.terms
        .iter()
        .map(|(m, n)| {
            let mut packed = 0u64;
            for &(s, e) in m.factors() {
                let v = syms.binary_search(&s).expect("symbol of p");
                if u64::from(e) > MAX_EXP {
                    return None;
                }
                packed |= u64::from(e) << shift(v);
            }
            Some((packed, to_rug(n)))
        })
        .collect()
}

/// The polynomial `scale * sum c m / den` in canonical form.
fn unpack(p: &[(u64, Integer)], syms: &[Symbol], scale: &Integer, den: &BigInt) -> Poly {
    let mut terms: Vec<(Monomial, BigInt)> = p
        .iter()
        .map(|(m, c)| {
            let mono = syms
                .iter()
                .enumerate()
                .filter_map(|(v, &s)| {
                    let e = exponent(*m, v) as u32;
                    (e > 0).then_some((s, e))
                })
                .collect();
            (Monomial(mono), to_big(&(c * scale).complete()))
        })
        .collect();
    terms.sort_by(|x, y| x.0.cmp(&y.0));
    Poly::normalized(terms, den.clone())
}

/// `(g, a/g, b/g)` with `g` the monic gcd of non-zero `a`, `b` by GCDHEU, proven: `g` divides both
/// exactly (the quotients are computed) and the cofactors pass the coprimality certificate.
/// `None` when the heuristic gives up, the polynomials do not fit the packing, or the proof is
/// inconclusive.
pub(super) fn gcd_cofactors(a: &Poly, b: &Poly) -> Option<(Poly, Poly, Poly)> {
    let mut syms = a.symbols();
    syms.extend(b.symbols());
    syms.sort();
    syms.dedup();
    if syms.len() > MAX_SYMBOLS {
        return None;
    }
    let (pa, pb) = (pack(a, &syms)?, pack(b, &syms)?);
    // Integer numerators: pa = G qa, pb = G qb with G = gc g, g primitive with lc(g) > 0.
    let (big_g, qa, qb) = heu(&pa, &pb, syms.len())?;
    let gc = content(&big_g);
    let g = div_int(&big_g, &gc);
    // a = pa / den_a; the monic gcd is g / lc(g), so a / gcd = (gc lc(g) / den_a) qa.
    let lc = leading(&g).1.clone();
    let one = BigInt::from(1);
    let gp = unpack(&g, &syms, &Integer::from(1), &one).scale(&crate::ring::Q::new(1.into(), to_big(&lc)));
    let s = (&gc * &lc).complete();
    let (fa, fb) = (unpack(&qa, &syms, &s, &a.den), unpack(&qb, &syms, &s, &b.den));
    if !g.iter().all(|(m, _)| *m == 0) && !super::coprime::coprime_certificate(&fa, &fb) {
        return None;
    }
    Some((gp, fa, fb))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Ring;

    fn v(s: &str) -> Poly {
        Poly::var(s).unwrap()
    }

    /// The heuristic finds a known common factor with its cofactors, in one to three symbols, and
    /// the constant gcd of coprime polynomials; exact division refuses a non-divisor.
    #[test]
    fn finds_known_gcds_with_cofactors() {
        let (a, b, c) = (v("a"), v("b"), v("c"));
        let g = a.mul(&b).sub(&c.mul_int(3)).add(&Poly::from_int(7)); // ab - 3c + 7
        let p = a.mul(&a).sub(&b.mul_int(5)).add(&c); // a^2 - 5b + c
        let q = b.mul(&b).mul(&c).add(&a.mul_int(2)).sub(&Poly::one()); // b^2 c + 2a - 1
        for (x, y) in [(g.mul(&p), g.mul(&q)), (g.mul(&g).mul(&p), g.mul(&q).mul_int(6))] {
            let (gg, fx, fy) = gcd_cofactors(&x, &y).expect("heuristic succeeds");
            assert_eq!(gg.mul(&fx), x);
            assert_eq!(gg.mul(&fy), y);
            assert_eq!(gg, g); // monic already: the lex-leading term is a b
        }
        let (gg, _, _) = gcd_cofactors(&p, &q).unwrap();
        assert!(gg.is_one());
        // univariate with rational coefficients: (t + 1/2)(t - 3) and (t + 1/2)^2
        let t = v("t");
        let h = t.add(&Poly::from_q(&crate::ring::Q::new(1.into(), 2.into())));
        let (gg, fx, fy) = gcd_cofactors(&h.mul(&t.sub(&Poly::from_int(3))), &h.mul(&h)).unwrap();
        assert_eq!((gg, fx, fy), (h.clone(), t.sub(&Poly::from_int(3)), h.clone()));
        // constants: the cofactors keep their signs
        let (m2, six) = (Poly::from_int(-2), Poly::from_int(6));
        assert_eq!(gcd_cofactors(&m2, &six).unwrap(), (Poly::one(), m2.clone(), six.clone()));
        assert_eq!(gcd_cofactors(&m2.mul(&g), &six.mul(&g)).unwrap(), (g.clone(), m2, six));
        let syms = [Symbol::new("a").unwrap(), Symbol::new("b").unwrap(), Symbol::new("c").unwrap()];
        let (px, pg) = (pack(&g.mul(&p).add(&Poly::one()), &syms).unwrap(), pack(&g, &syms).unwrap());
        assert!(divide(&px, &pg, 3).is_none());
    }
}
