//! Padé approximants of a truncated series over a field (`Q`, `Frac`): the rational function
//! P/Q with deg P <= L, deg Q <= M, Q(0) = 1 and f Q - P = O(x^(L+M+1)).
//!
//! Algorithm (Kronecker; Baker and Graves-Morris, *Padé Approximants*, 2nd ed., section 2.3):
//! the extended Euclidean algorithm on r_(-1) = x^(L+M+1) and r_0 = T = c_0 + ... + c_(L+M)
//! x^(L+M), keeping the cofactor t_j with r_j = t_j T (mod x^(L+M+1)); at the first remainder of
//! degree <= L, deg t_j <= M, and (P, Q) = (r_j, t_j) scaled to Q(0) = 1. This gives the
//! approximant in degenerate blocks of the Padé table too (e.g. [L/M] of 1/(1 - x) for every
//! M >= 1, where the Toeplitz system of the denominator is singular); when t_j(0) = 0 after the
//! common power of x is cancelled, or the reduced P/Q matches f through fewer than L+M+1
//! coefficients, the [L/M] approximant does not exist and the answer is
//! [`SeriesError::PadeDoesNotExist`]. Exact arithmetic: over `Q` the approximant is the exact one
//! of the coefficients given.

use crate::{Ring, Series, SeriesError};

/// The [L/M] Padé approximant P(x)/Q(x) of a series: `numer` = p_0 .. p_L', `denom` = 1, q_1 ..
/// q_M' (L' <= L, M' <= M: trailing zero coefficients are dropped, so a rational function of lower
/// degrees is returned in its lowest terms).
#[derive(Debug, Clone, PartialEq)]
pub struct Pade<R: Ring> {
    /// The requested numerator degree bound L.
    pub l: usize,
    /// The requested denominator degree bound M.
    pub m: usize,
    /// p_0, ..., p_L' (empty: P = 0).
    pub numer: Vec<R>,
    /// q_0 = 1, q_1, ..., q_M'.
    pub denom: Vec<R>,
}

fn trim<R: Ring>(mut p: Vec<R>) -> Vec<R> {
    while p.last().is_some_and(|c| c.is_zero()) {
        p.pop();
    }
    p
}

/// Degree of a trimmed polynomial (`None` for 0).
fn degree<R: Ring>(p: &[R]) -> Option<usize> {
    p.len().checked_sub(1)
}

fn poly_sub<R: Ring>(a: &[R], b: &[R]) -> Vec<R> {
    let n = a.len().max(b.len());
    trim(
        (0..n)
            .map(|i| match (a.get(i), b.get(i)) {
                (Some(x), Some(y)) => x.sub(y),
                (Some(x), None) => x.clone(),
                (None, Some(y)) => y.neg(),
                (None, None) => R::zero(),
            })
            .collect(),
    )
}

fn poly_mul<R: Ring>(a: &[R], b: &[R]) -> Vec<R> {
    if a.is_empty() || b.is_empty() {
        return vec![];
    }
    let mut out = vec![R::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j].fma_lazy(x, y);
        }
    }
    for c in out.iter_mut() {
        c.canonicalize();
    }
    trim(out)
}

/// Quotient and remainder of `a` by the non-zero trimmed `b` over a field.
fn poly_divrem<R: Ring>(a: &[R], b: &[R]) -> Result<(Vec<R>, Vec<R>), SeriesError> {
    let db = degree(b).expect("divisor is not zero");
    let lead_inv = b[db]
        .inv()
        .ok_or_else(|| SeriesError::NotInvertible { operation: "Pade (Euclid over a field)", value: b[db].text() })?;
    let mut r = trim(a.to_vec());
    let mut q = vec![R::zero(); r.len().saturating_sub(db)];
    while let Some(dr) = degree(&r) {
        if dr < db {
            break;
        }
        let c = r[dr].mul(&lead_inv);
        let k = dr - db;
        for (i, bi) in b.iter().enumerate() {
            r[k + i] = r[k + i].sub(&c.mul(bi));
        }
        q[k] = c;
        r = trim(r);
    }
    Ok((trim(q), r))
}

impl<R: Ring> Pade<R> {
    /// The [L/M] approximant of `f` (module doc). Needs the coefficients of x^0 .. x^(L+M)
    /// ([`SeriesError::PadeOrder`] otherwise) and a field of coefficients ([`SeriesError::NotInvertible`]
    /// for a non-unit leading coefficient, e.g. over `Poly`).
    pub fn new(f: &Series<R>, l: usize, m: usize) -> Result<Self, SeriesError> {
        let n = l + m + 1;
        if f.prec() < n {
            return Err(SeriesError::PadeOrder { l, m, known: f.prec() });
        }
        let mut r_prev: Vec<R> = vec![R::zero(); n];
        r_prev.push(R::one());
        let mut r = trim(f.coeffs()[..n].to_vec());
        let (mut t_prev, mut t): (Vec<R>, Vec<R>) = (vec![], vec![R::one()]);
        while degree(&r).is_some_and(|d| d > l) {
            let (q, rem) = poly_divrem(&r_prev, &r)?;
            let t_next = poly_sub(&t_prev, &poly_mul(&q, &t));
            r_prev = std::mem::replace(&mut r, rem);
            t_prev = std::mem::replace(&mut t, t_next);
        }
        // Cancel the common power of x, then normalise Q(0) = 1.
        let vp = r.iter().position(|c| !c.is_zero()).unwrap_or(usize::MAX);
        let vq = t.iter().position(|c| !c.is_zero()).expect("the cofactor is not zero");
        let s = vq.min(vp);
        let (numer, denom): (Vec<R>, Vec<R>) =
            (r.iter().skip(s).cloned().collect(), t.iter().skip(s).cloned().collect());
        if denom[0].is_zero() {
            return Err(SeriesError::PadeDoesNotExist { l, m, matched: 0 });
        }
        let q0_inv = denom[0]
            .inv()
            .ok_or_else(|| SeriesError::NotInvertible { operation: "Pade (Q(0) = 1)", value: denom[0].text() })?;
        let numer = trim(numer.iter().map(|c| c.mul(&q0_inv)).collect());
        let denom = trim(denom.iter().map(|c| c.mul(&q0_inv)).collect());
        let p = Pade { l, m, numer, denom };
        let matched = p.matched(f);
        if matched < n {
            return Err(SeriesError::PadeDoesNotExist { l, m, matched });
        }
        Ok(p)
    }

    /// The number of leading coefficients of `f` that the expansion of P/Q reproduces (up to the
    /// known precision of `f`): the first k with [x^k](f Q - P) != 0.
    pub fn matched(&self, f: &Series<R>) -> usize {
        (0..f.prec())
            .find(|&k| {
                let mut acc = R::zero();
                for (j, q) in self.denom.iter().enumerate().take(k + 1) {
                    acc.fma_lazy(q, &f.coeffs()[k - j]);
                }
                acc.canonicalize();
                let p = self.numer.get(k).cloned().unwrap_or_else(R::zero);
                !acc.sub(&p).is_zero()
            })
            .unwrap_or(f.prec())
    }

    /// The expansion of P/Q through x^(prec-1).
    pub fn expand(&self, prec: usize) -> Series<R> {
        let p = Series::new(self.numer.clone(), prec);
        let q = Series::new(self.denom.clone(), prec);
        p.mul(&q.inv().expect("Q(0) = 1"))
    }

    /// P(x)/Q(x) at an element x of the field; `None` where Q(x) = 0.
    pub fn eval(&self, x: &R) -> Option<R> {
        let horner = |c: &[R]| c.iter().rev().fold(R::zero(), |acc, a| acc.mul(x).add(a));
        let q = horner(&self.denom);
        q.inv().filter(|_| !q.is_zero()).map(|qi| horner(&self.numer).mul(&qi))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Q;

    fn q(n: i64, d: i64) -> Q {
        Q::new(n.into(), d.into())
    }
    fn qs(v: &[(i64, i64)]) -> Vec<Q> {
        v.iter().map(|&(n, d)| q(n, d)).collect()
    }

    #[test]
    fn exp_two_two_is_the_classical_one() {
        // [2/2] of e^x = (1 + x/2 + x^2/12)/(1 - x/2 + x^2/12).
        let f = Series::<Q>::var(5).exp().unwrap();
        let p = Pade::new(&f, 2, 2).unwrap();
        assert_eq!(p.numer, qs(&[(1, 1), (1, 2), (1, 12)]));
        assert_eq!(p.denom, qs(&[(1, 1), (-1, 2), (1, 12)]));
        // Every near-diagonal entry reproduces its L+M+1 coefficients.
        let f = Series::<Q>::var(13).exp().unwrap();
        for (l, m) in [(6, 6), (7, 5), (5, 7), (0, 12), (12, 0), (3, 4)] {
            let p = Pade::new(&f, l, m).unwrap();
            assert!(p.matched(&f) >= l + m + 1, "[{l}/{m}]");
            assert_eq!(p.expand(l + m + 1), f.truncate(l + m + 1), "[{l}/{m}]");
        }
    }

    #[test]
    fn log_one_plus_x() {
        // [2/2] of log(1 + x) = (6x + 3x^2)/(6 + 6x + x^2); [1/1] = 2x/(2 + x).
        let f = Series::<Q>::var(6).add(&Series::one(6)).log().unwrap();
        let p = Pade::new(&f, 2, 2).unwrap();
        assert_eq!(p.numer, qs(&[(0, 1), (1, 1), (1, 2)]));
        assert_eq!(p.denom, qs(&[(1, 1), (1, 1), (1, 6)]));
        let p = Pade::new(&f, 1, 1).unwrap();
        assert_eq!((p.numer, p.denom), (qs(&[(0, 1), (1, 1)]), qs(&[(1, 1), (1, 2)])));
    }

    #[test]
    fn a_rational_function_is_recovered_exactly() {
        // f = (1 + 2x - x^2)/(1 - x/3 + x^2/5 - x^3): every [L/M] with L >= 2, M >= 3 is f itself,
        // in lowest terms, although the Toeplitz systems of M > 3 are singular.
        let num = Series::<Q>::new(qs(&[(1, 1), (2, 1), (-1, 1)]), 20);
        let den = Series::<Q>::new(qs(&[(1, 1), (-1, 3), (1, 5), (-1, 1)]), 20);
        let f = num.mul(&den.inv().unwrap());
        for (l, m) in [(2, 3), (3, 3), (5, 5), (2, 8), (9, 9), (4, 6)] {
            let p = Pade::new(&f, l, m).unwrap();
            assert_eq!(p.numer, num.coeffs()[..3].to_vec(), "[{l}/{m}]");
            assert_eq!(p.denom, den.coeffs()[..4].to_vec(), "[{l}/{m}]");
            assert_eq!(p.eval(&q(1, 2)), Some(q(7, 4) / (q(1, 1) - q(1, 6) + q(1, 20) - q(1, 8))));
        }
        // 1/(1 - x): [L/M] = 1/(1 - x) for every L >= 0, M >= 1.
        let g = Series::<Q>::one(12).sub(&Series::var(12)).inv().unwrap();
        for (l, m) in [(0, 1), (3, 1), (0, 5), (4, 4), (5, 6)] {
            let p = Pade::new(&g, l, m).unwrap();
            assert_eq!((p.numer.clone(), p.denom.clone()), (qs(&[(1, 1)]), qs(&[(1, 1), (-1, 1)])), "[{l}/{m}]");
        }
        // [L/0] is the Taylor polynomial.
        let p = Pade::new(&g, 3, 0).unwrap();
        assert_eq!(p.numer, qs(&[(1, 1); 4]));
    }

    #[test]
    fn missing_coefficients_and_non_existence_are_errors() {
        let f = Series::<Q>::var(5).exp().unwrap();
        assert_eq!(Pade::new(&f, 3, 3), Err(SeriesError::PadeOrder { l: 3, m: 3, known: 5 }));
        // f = 1 + x^2: [1/1] would be (a + b x)/(1 + c x) matching 1, 0, 1: c_1 = 0 forces
        // b = a c and then c_2 = -c (b - a c) = 0 != 1. The block [1/1] does not exist.
        let g = Series::<Q>::new(qs(&[(1, 1), (0, 1), (1, 1)]), 3);
        assert!(matches!(Pade::new(&g, 1, 1), Err(SeriesError::PadeDoesNotExist { l: 1, m: 1, .. })));
        // x (a zero constant term) has no [0/1] approximant: P = p_0, and x Q - p_0 = O(x^2)
        // forces p_0 = 0, q_0 = 0.
        let h = Series::<Q>::var(2);
        assert!(matches!(Pade::new(&h, 0, 1), Err(SeriesError::PadeDoesNotExist { .. })));
        // The zero series: P = 0, Q = 1.
        let z = Series::<Q>::zero(5);
        let p = Pade::new(&z, 2, 2).unwrap();
        assert!(p.numer.is_empty() && p.denom == vec![q(1, 1)]);
    }

    #[test]
    fn over_a_polynomial_ring_is_refused() {
        let t = crate::Poly::var("theta").unwrap();
        // 1 + x + theta x^2: the first Euclid step divides by theta.
        let f = Series::<crate::Poly>::new(vec![crate::Poly::one(), crate::Poly::one(), t], 3);
        assert!(matches!(Pade::new(&f, 1, 1), Err(SeriesError::NotInvertible { .. })));
    }
}
