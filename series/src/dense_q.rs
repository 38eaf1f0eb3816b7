//! Dense truncated series over Q in common-denominator form over GMP integers: the fast path of
//! `Series<Q>` (issue 14: the engine against FLINT's `fmpq_poly` series).
//!
//! A series `sum_k c_k x^k` is held as integer numerators `n_k` and one positive denominator `d`
//! (`c_k = n_k/d`), the representation of FLINT's `fmpq_poly`. The operations:
//! - product by Kronecker substitution: both numerator vectors are packed into one GMP integer
//!   each (the value at `x = 2^s`, slots of `s` bits, a multiple of 64, wide enough for every
//!   product coefficient with its sign), one GMP multiplication, signed-digit unpacking;
//! - inverse, log and exp by Newton iteration on doubling precision (Brent-Kung):
//!   `b <- b + b (1 - a b)`, `log f = int f'/f`, `g <- g (1 + h - log g)`; exp starts from its
//!   first (up to 23) coefficients by the recurrence `g' = f' g` over one common denominator;
//! - power `f^alpha = exp(alpha log f)` (`f(0) = 1`, `alpha` rational);
//! - reversion by Lagrange inversion with baby steps and giant steps (FLINT's
//!   `_fmpq_poly_revert_series_lagrange_fast`): with `P = (f/x)^(-1)`,
//!   `[y^n] f^(-1) = (1/n) [x^(n-1)] P^n`, `P^(jm+i) = P^i (P^m)^j`, so the `N` coefficients
//!   need `m + N/m` products (`m = ceil(sqrt N)`) and `N` dot products.
//!
//! The content (gcd of the numerators and the denominator) is removed after each operation, so
//! the numbers stay at the size of the reduced coefficients. Results are converted back to
//! reduced [`Q`]s: the values are exact, hence identical to the generic recurrences' (tests
//! compare both routes coefficient by coefficient).
//!
//! With the cargo feature `flint` (off by default) the product, inverse, log, exp and power go to
//! FLINT's `fmpq_poly` instead, and the reversion from `flint_q::REVERT_MIN` coefficients on
//! (`src/flint_q.rs`); the tests in `tests::flint` compare that route with this one.

use crate::gmp::{to_big, to_rug};
use crate::ring::Q;
use num_bigint::BigInt;
use rug::integer::Order;
use rug::{Assign, Integer};

/// `num[k]/den`, `den > 0`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Dense {
    num: Vec<Integer>,
    den: Integer,
}

impl Dense {
    /// From reduced rationals: the denominator is the lcm of theirs.
    pub(crate) fn from_q(c: &[Q]) -> Dense {
        let mut den = Integer::from(1);
        let dens: Vec<Integer> = c.iter().map(|q| to_rug(q.denom())).collect();
        for d in &dens {
            if *d != 1 {
                den.lcm_mut(d);
            }
        }
        let num = c
            .iter()
            .zip(&dens)
            .map(|(q, d)| {
                let n = to_rug(q.numer());
                if *d == den {
                    n
                } else {
                    n * Integer::from(&den / d)
                }
            })
            .collect();
        Dense { num, den }
    }

    /// The coefficients as reduced rationals.
    pub(crate) fn to_q(&self) -> Vec<Q> {
        let mut g = Integer::new();
        self.num
            .iter()
            .map(|n| {
                if n.cmp0() == std::cmp::Ordering::Equal {
                    return Q::new_raw(BigInt::from(0), BigInt::from(1));
                }
                g.assign(n.gcd_ref(&self.den));
                if g == 1 {
                    Q::new_raw(to_big(n), to_big(&self.den))
                } else {
                    Q::new_raw(to_big(&Integer::from(n / &g)), to_big(&Integer::from(&self.den / &g)))
                }
            })
            .collect()
    }

    fn len(&self) -> usize {
        self.num.len()
    }

    fn truncated(&self, n: usize) -> Dense {
        let mut num: Vec<Integer> = self.num.iter().take(n).cloned().collect();
        num.resize(n, Integer::new());
        Dense { num, den: self.den.clone() }
    }

    /// Removes the content: divides the numerators and the denominator by their gcd.
    fn reduce(&mut self) {
        let mut g = self.den.clone();
        for n in &self.num {
            if g == 1 {
                return;
            }
            g.gcd_mut(n);
        }
        if g != 1 {
            for n in &mut self.num {
                n.div_exact_mut(&g);
            }
            self.den.div_exact_mut(&g);
        }
    }

    /// The constant `c`.
    fn constant(c: Integer, den: Integer, n: usize) -> Dense {
        let mut num = vec![Integer::new(); n.max(1)];
        num[0] = c;
        Dense { num, den }
    }

    /// From the parts of the FLINT backend.
    #[cfg(feature = "flint")]
    fn from_parts((num, den): crate::flint_q::Parts) -> Dense {
        Dense { num, den }
    }

    /// `self * other` through `x^(n-1)`: FLINT's `fmpq_poly_mullow` with the feature `flint`,
    /// else one Kronecker product.
    pub(crate) fn mullow(&self, other: &Dense, n: usize) -> Dense {
        #[cfg(feature = "flint")]
        return Dense::from_parts(crate::flint_q::mullow((&self.num, &self.den), (&other.num, &other.den), n));
        #[cfg(not(feature = "flint"))]
        self.mullow_gmp(other, n)
    }

    /// `1/self` through `x^(n-1)` (constant term non-zero): FLINT or Newton (as [`Dense::mullow`]).
    pub(crate) fn inv(&self, n: usize) -> Dense {
        #[cfg(feature = "flint")]
        return Dense::from_parts(crate::flint_q::inv(&self.num, &self.den, n));
        #[cfg(not(feature = "flint"))]
        self.inv_gmp(n)
    }

    /// `log self` through `x^(n-1)` (`self(0) = 1`): FLINT or Newton (as [`Dense::mullow`]).
    pub(crate) fn log(&self, n: usize) -> Dense {
        #[cfg(feature = "flint")]
        return Dense::from_parts(crate::flint_q::log(&self.num, &self.den, n));
        #[cfg(not(feature = "flint"))]
        self.log_gmp(n)
    }

    /// `exp self` through `x^(n-1)` (`self(0) = 0`): FLINT or Newton (as [`Dense::mullow`]).
    pub(crate) fn exp(&self, n: usize) -> Dense {
        #[cfg(feature = "flint")]
        return Dense::from_parts(crate::flint_q::exp(&self.num, &self.den, n));
        #[cfg(not(feature = "flint"))]
        self.exp_gmp(n)
    }

    /// `self^(p/q)` through `x^(n-1)` (`self(0) = 1`, `q > 0`): FLINT or GMP (as [`Dense::mullow`]).
    pub(crate) fn pow(&self, p: &Integer, q: &Integer, n: usize) -> Dense {
        #[cfg(feature = "flint")]
        return Dense::from_parts(crate::flint_q::pow(&self.num, &self.den, p, q, n));
        #[cfg(not(feature = "flint"))]
        self.pow_gmp(p, q, n)
    }

    /// The compositional inverse (`self(0) = 0`, `self'(0) != 0`): FLINT's
    /// `fmpq_poly_revert_series` with the feature `flint` from `flint_q::REVERT_MIN`
    /// coefficients on, else Lagrange inversion.
    pub(crate) fn revert(&self) -> Dense {
        #[cfg(feature = "flint")]
        if self.len() >= crate::flint_q::REVERT_MIN {
            return Dense::from_parts(crate::flint_q::revert(&self.num, &self.den));
        }
        self.revert_gmp()
    }

    /// `self * other` through `x^(n-1)`.
    fn mullow_gmp(&self, other: &Dense, n: usize) -> Dense {
        let mut d = Dense { num: kronecker(&self.num, &other.num, n), den: Integer::from(&self.den * &other.den) };
        d.reduce();
        d
    }

    /// `self * other` through `x^(n-1)` when `other = O(x^shift)`: `x^shift (self * other/x^shift)`,
    /// a product of the shorter length `n - shift`.
    fn mullow_shifted(&self, other: &Dense, shift: usize, n: usize) -> Dense {
        if shift >= n {
            return Dense::constant(Integer::new(), Integer::from(1), n);
        }
        let o = Dense { num: other.num.iter().skip(shift).cloned().collect(), den: other.den.clone() };
        let p = self.mullow_gmp(&o, n - shift);
        let mut num = vec![Integer::new(); shift];
        num.extend(p.num);
        Dense { num, den: p.den }
    }

    /// `self + other` (same length as the longer), over the lcm of the denominators and not
    /// reduced: every sum in the Newton steps goes into a product, which removes the content
    /// (reducing here too cost 3-10% of the Q job at N = 60 and 100, docs/performance.md).
    fn add(&self, other: &Dense) -> Dense {
        let n = self.len().max(other.len());
        let (fa, fb) = common_factors(&self.den, &other.den);
        let mut num = vec![Integer::new(); n];
        for (k, v) in num.iter_mut().enumerate() {
            if let Some(a) = self.num.get(k) {
                *v += a * &fa;
            }
            if let Some(b) = other.num.get(k) {
                *v += b * &fb;
            }
        }
        Dense { num, den: Integer::from(&self.den * &fa) }
    }

    fn neg(&self) -> Dense {
        Dense { num: self.num.iter().map(|n| Integer::from(-n)).collect(), den: self.den.clone() }
    }

    /// `self * p/q` for integers (q > 0).
    #[cfg_attr(feature = "flint", allow(dead_code))] // with FLINT: the tests' GMP route
    fn scale(&self, p: &Integer, q: &Integer) -> Dense {
        let mut d =
            Dense { num: self.num.iter().map(|n| Integer::from(n * p)).collect(), den: Integer::from(&self.den * q) };
        d.reduce();
        d
    }

    /// `f'`, one coefficient shorter.
    #[cfg_attr(feature = "flint", allow(dead_code))] // with FLINT: the tests' GMP route
    fn derivative(&self) -> Dense {
        let num = self.num.iter().enumerate().skip(1).map(|(k, c)| Integer::from(c * k as u64)).collect();
        let mut d = Dense { num, den: self.den.clone() };
        d.reduce();
        d
    }

    /// `int_0^x f`, one coefficient longer: `c_k/(k+1)` over the common denominator
    /// `den lcm(1..len)`.
    #[cfg_attr(feature = "flint", allow(dead_code))] // with FLINT: the tests' GMP route
    fn integral(&self) -> Dense {
        let n = self.len();
        let mut l = Integer::from(1);
        for k in 1..=n as u64 {
            l.lcm_u_mut(k as u32);
        }
        let mut num = Vec::with_capacity(n + 1);
        num.push(Integer::new());
        for (k, c) in self.num.iter().enumerate() {
            num.push(c * Integer::from(&l / (k as u64 + 1)));
        }
        let mut d = Dense { num, den: Integer::from(&self.den * &l) };
        d.reduce();
        d
    }

    /// `1/self` through `x^(n-1)`; the constant term must be non-zero. Newton:
    /// `b <- b + b (1 - a b)` on doubling precision.
    fn inv_gmp(&self, n: usize) -> Dense {
        // b_0 = den/num_0 (sign moved to the numerator).
        let c0 = &self.num[0];
        let (mut p, mut q) = (self.den.clone(), c0.clone());
        if q.cmp0() == std::cmp::Ordering::Less {
            p = -p;
            q = -q;
        }
        let mut b = Dense::constant(p, q, 1);
        b.reduce();
        let mut m = 1;
        while m < n {
            let half = m;
            m = (2 * m).min(n);
            let ab = self.truncated(m).mullow_gmp(&b, m);
            let e = Dense::constant(ab.den.clone(), ab.den.clone(), m).add(&ab.neg()); // 1 - a b = O(x^half)
            let corr = b.mullow_shifted(&e, half, m);
            b = b.truncated(m).add(&corr);
        }
        b.truncated(n)
    }

    /// `log self` through `x^(n-1)`; requires `self(0) = 1`.
    #[cfg_attr(feature = "flint", allow(dead_code))] // with FLINT: the tests' GMP route
    fn log_gmp(&self, n: usize) -> Dense {
        if n <= 1 {
            return Dense::constant(Integer::new(), Integer::from(1), n.max(1)).truncated(n);
        }
        // f'/f through x^(n-2) (n - 1 coefficients) by Karp-Markstein: h = 1/f to half the length,
        // q0 = f' h, q = q0 + h (f' - f q0) (the bracket is O(x^half)).
        let len = n - 1;
        let df = self.truncated(n).derivative();
        let q = if len < 4 {
            df.mullow_gmp(&self.inv_gmp(len), len)
        } else {
            let half = len.div_ceil(2);
            let h = self.inv_gmp(half);
            let q0 = df.truncated(half).mullow_gmp(&h, half);
            let r = df.truncated(len).add(&self.truncated(len).mullow_gmp(&q0, len).neg());
            q0.truncated(len).add(&h.mullow_shifted(&r, half, len))
        };
        q.integral().truncated(n)
    }

    /// `exp self` through `x^(n-1)`; requires `self(0) = 0`. Newton with the inverse carried
    /// along (Hanrot-Zimmermann; Bostan's lecture notes, algorithm "exp"): with `g = exp f` and
    /// `h = 1/g` both known mod `x^m`,
    /// `h <- h (2 - g h) mod x^m`, `w = f' + h (g' - g f') mod x^(2m-1)`,
    /// `g <- g (1 + f - int w) mod x^(2m)`: no logarithm (and no inverse from scratch) per step;
    /// the first `g` and `h` come from [`exp_basecase`].
    #[cfg_attr(feature = "flint", allow(dead_code))] // with FLINT: the tests' GMP route
    fn exp_gmp(&self, n: usize) -> Dense {
        let df = self.truncated(n).derivative();
        // The first m < 24 coefficients by the basecase recurrence (m = n halved until below 24,
        // so that the doublings below end at n), as FLINT's exp starts; measured side by side,
        // cutoffs 16, 24 and 40 alike, all 1.1x to 1.2x faster than Newton from m = 1
        // (docs/performance.md, "The profile, side by side with FLINT").
        let cutoff = 24;
        let mut m = n.max(1);
        while m >= cutoff {
            m = m.div_ceil(2);
        }
        let mut g = exp_basecase(&df, m);
        let mut h = g.inv_gmp(m);
        while m < n {
            let m2 = (2 * m).min(n);
            if m > 1 {
                // h = h (2 - g h) mod x^m
                let gh = g.mullow_gmp(&h, m);
                let two = Dense::constant(Integer::from(&gh.den * 2u32), gh.den.clone(), m);
                h = h.mullow_gmp(&two.add(&gh.neg()), m);
            }
            // w = f' + h (g' - g f') mod x^(m2 - 1)
            let q = df.truncated(m2 - 1);
            let gq = g.mullow_gmp(&q, m2 - 1);
            let r = g.derivative().truncated(m2 - 1).add(&gq.neg());
            let w = q.add(&h.mullow_shifted(&r, m - 1, m2 - 1)); // r = O(x^(m-1))
                                                                 // g = g (1 + f - int w) mod x^m2
                                                                 // t = f - int w = O(x^m) (g is right mod x^m)
            let t = self.truncated(m2).add(&w.integral().truncated(m2).neg());
            g = g.truncated(m2).add(&g.mullow_shifted(&t, m, m2));
            m = m2;
        }
        g.truncated(n)
    }

    /// `self^(p/q)` through `x^(n-1)`; requires `self(0) = 1`.
    #[cfg_attr(feature = "flint", allow(dead_code))] // with FLINT: the tests' GMP route
    fn pow_gmp(&self, p: &Integer, q: &Integer, n: usize) -> Dense {
        self.log_gmp(n).scale(p, q).exp_gmp(n)
    }

    /// The compositional inverse, `len` coefficients like `self`; requires `self(0) = 0` and
    /// `self'(0) != 0`. Lagrange inversion with baby and giant steps (module doc).
    fn revert_gmp(&self) -> Dense {
        let big_n = self.len();
        let mut out = vec![Integer::new(); big_n];
        if big_n < 2 {
            return Dense { num: out, den: Integer::from(1) };
        }
        // h = f/x (n - 1 coefficients), P = 1/h.
        let h = Dense { num: self.num[1..].to_vec(), den: self.den.clone() };
        let len = big_n - 1; // coefficients of P needed: x^0 .. x^(N-2)
        let p = h.inv_gmp(len);
        let m = ((len as f64).sqrt().ceil() as usize).max(1);
        // baby steps P^1 .. P^m
        let mut baby = vec![p.clone()];
        for _ in 1..m {
            let next = baby.last().expect("non-empty").mullow_gmp(&p, len);
            baby.push(next);
        }
        let giant_step = baby[m - 1].clone();
        // g_n for n = 1 .. N-1: n = j m + i, 1 <= i <= m; [x^(n-1)] P^i G_j, G_j = (P^m)^j.
        let mut dens: Vec<Integer> = vec![Integer::from(1); big_n];
        let mut giant = Dense::constant(Integer::from(1), Integer::from(1), len);
        let mut j = 0;
        loop {
            for i in 1..=m {
                let nn = j * m + i;
                if nn >= big_n {
                    break;
                }
                let b = &baby[i - 1];
                let mut acc = Integer::new();
                for k in 0..nn {
                    let (x, y) = (&b.num[k], &giant.num[nn - 1 - k]);
                    if x.cmp0() != std::cmp::Ordering::Equal && y.cmp0() != std::cmp::Ordering::Equal {
                        acc += x * y;
                    }
                }
                out[nn] = acc;
                dens[nn] = Integer::from(&b.den * &giant.den) * nn as u64;
            }
            j += 1;
            if j * m + 1 >= big_n {
                break;
            }
            giant = giant.mullow_gmp(&giant_step, len);
        }
        // Common denominator of the results.
        let mut den = Integer::from(1);
        for (c, d) in out.iter_mut().zip(dens.iter_mut()).skip(1) {
            let g = Integer::from(c.gcd_ref(d));
            c.div_exact_mut(&g);
            d.div_exact_mut(&g);
            den.lcm_mut(d);
        }
        for (nn, c) in out.iter_mut().enumerate().skip(1) {
            *c *= Integer::from(&den / &dens[nn]);
        }
        let mut d = Dense { num: out, den };
        d.reduce();
        d
    }
}

/// `exp f` through `x^(n-1)` from `df = f'` (`f(0) = 0`) by the recurrence `g' = f' g` over one
/// common denominator (FLINT's `_fmpq_poly_exp_series_basecase_deriv`): with `f' = A/d` and
/// `L = (n-1)! d^(n-1)`, the numerators `N_k = L g_k` are integers and
/// `N_k = (sum_{j<k} A_j N_(k-1-j)) / (k d)`, an exact division; `O(n^2)` products but no gcd.
fn exp_basecase(df: &Dense, n: usize) -> Dense {
    let (a, d) = (&df.num, &df.den);
    let mut fact = Integer::from(1);
    for k in 2..n as u64 {
        fact *= k;
    }
    let den = fact * Integer::from(rug::ops::Pow::pow(d, n.saturating_sub(1) as u32));
    let mut num = vec![Integer::new(); n];
    num[0] = den.clone();
    for k in 1..n {
        let mut t = Integer::new();
        for j in 0..a.len().min(k) {
            if a[j].cmp0() != std::cmp::Ordering::Equal {
                t += &a[j] * &num[k - 1 - j];
            }
        }
        t.div_exact_mut(&Integer::from(d * k as u64));
        num[k] = t;
    }
    let mut g = Dense { num, den };
    g.reduce();
    g
}

/// `(a, b)` with `da a = db b = lcm(da, db)`.
fn common_factors(da: &Integer, db: &Integer) -> (Integer, Integer) {
    if da == db {
        return (Integer::from(1), Integer::from(1));
    }
    let g = Integer::from(da.gcd_ref(db));
    (Integer::from(db / &g), Integer::from(da / &g))
}

/// The product of two integer polynomials through `x^(n-1)` by Kronecker substitution.
fn kronecker(a: &[Integer], b: &[Integer], n: usize) -> Vec<Integer> {
    let a = &a[..a.len().min(n)];
    let b = &b[..b.len().min(n)];
    let mut out = vec![Integer::new(); n];
    if a.is_empty() || b.is_empty() {
        return out;
    }
    let bits = |v: &[Integer]| v.iter().map(|x| x.significant_bits()).max().unwrap_or(0) as usize;
    let (ba, bb) = (bits(a), bits(b));
    if ba == 0 || bb == 0 {
        return out;
    }
    let terms = a.len().min(b.len());
    let log = usize::BITS as usize - terms.leading_zeros() as usize;
    let slot_bits = ba + bb + log + 2; // + sign
    let limbs = slot_bits.div_ceil(64);
    let pa = pack(a, limbs);
    let pb = pack(b, limbs);
    let prod = pa * pb;
    unpack(&prod, limbs, &mut out);
    out
}

/// The value at `x = 2^(64 limbs)`.
fn pack(c: &[Integer], limbs: usize) -> Integer {
    let mut pos = vec![0u64; c.len() * limbs];
    let mut neg = vec![0u64; c.len() * limbs];
    let mut any_neg = false;
    for (i, x) in c.iter().enumerate() {
        let digits = x.to_digits::<u64>(Order::Lsf);
        let target = if x.cmp0() == std::cmp::Ordering::Less {
            any_neg = true;
            &mut neg
        } else {
            &mut pos
        };
        target[i * limbs..i * limbs + digits.len()].copy_from_slice(&digits);
    }
    let p = Integer::from_digits(&pos, Order::Lsf);
    if any_neg {
        p - Integer::from_digits(&neg, Order::Lsf)
    } else {
        p
    }
}

/// The signed slots of `v = sum_i c_i 2^(64 limbs i)`, `|c_i| < 2^(64 limbs - 1)`, into `out`.
fn unpack(v: &Integer, limbs: usize, out: &mut [Integer]) {
    let negative = v.cmp0() == std::cmp::Ordering::Less;
    let digits = v.to_digits::<u64>(Order::Lsf);
    let half = Integer::from(1) << (64 * limbs as u32 - 1);
    let full = Integer::from(1) << (64 * limbs as u32);
    let mut carry = false;
    for (i, o) in out.iter_mut().enumerate() {
        let lo = i * limbs;
        let mut s = if lo < digits.len() {
            Integer::from_digits(&digits[lo..(lo + limbs).min(digits.len())], Order::Lsf)
        } else {
            Integer::new()
        };
        if carry {
            s += 1;
        }
        carry = s >= half;
        if carry {
            s -= &full;
        }
        *o = if negative { -s } else { s };
    }
}

/// `s` as a `Series<Q>` when `R = Q`.
fn as_q<R: crate::Ring>(s: &crate::Series<R>) -> Option<&crate::Series<Q>> {
    (s as &dyn std::any::Any).downcast_ref::<crate::Series<Q>>()
}

/// The series of these rational coefficients as a `Series<R>`; only called when `R = Q`
/// (after [`as_q`] succeeded).
fn from_q<R: crate::Ring>(c: Vec<Q>) -> crate::Series<R> {
    let s: Box<dyn std::any::Any> = Box::new(crate::Series::<Q>::from_coeffs(c));
    *s.downcast::<crate::Series<R>>().expect("from_q is called only when R = Q")
}

/// The fast route of a `Series<R>` operation: when `R = Q` and `s` has at least [`DENSE_MIN`]
/// coefficients, `op` applied to its dense form and the result returned as reduced rationals;
/// `None` otherwise (the caller runs its generic recurrence). The callers check the operation's
/// precondition first.
pub(crate) fn dense_route<R: crate::Ring>(
    s: &crate::Series<R>,
    op: impl FnOnce(&Dense) -> Dense,
) -> Option<crate::Series<R>> {
    if s.prec() < DENSE_MIN {
        return None;
    }
    let a = as_q(s)?;
    Some(from_q(op(&Dense::from_q(a.coeffs())).to_q()))
}

/// `s` in dense form when `R = Q` (the second operand of a product).
pub(crate) fn dense_of<R: crate::Ring>(s: &crate::Series<R>) -> Option<Dense> {
    as_q(s).map(|a| Dense::from_q(a.coeffs()))
}

/// The fast-path threshold: below this many coefficients the generic recurrences are as fast.
pub(crate) const DENSE_MIN: usize = 24;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Ring, Series};
    use proptest::prelude::*;

    fn q(n: i64, d: i64) -> Q {
        Q::new(n.into(), d.into())
    }

    fn series(c: &[(i64, i64)]) -> Series<Q> {
        Series::from_coeffs(c.iter().map(|&(n, d)| q(n, d)).collect())
    }

    #[test]
    fn kronecker_matches_schoolbook_with_signs() {
        let a: Vec<Integer> = [3i64, -5, 0, 7, -1].iter().map(|&x| Integer::from(x) << 100).collect();
        let b: Vec<Integer> = [-2i64, 4, 9, -11].iter().map(|&x| Integer::from(x) << 70).collect();
        let got = kronecker(&a, &b, 8);
        for (k, g) in got.iter().enumerate() {
            let mut want = Integer::new();
            for i in 0..=k {
                if i < a.len() && k - i < b.len() {
                    want += &a[i] * &b[k - i];
                }
            }
            assert_eq!(*g, want, "coefficient {k}");
        }
    }

    #[test]
    fn round_trip_and_known_series() {
        let f = series(&[(1, 1), (-1, 6), (0, 1), (1, 120), (2, 3), (-7, 9)]);
        assert_eq!(Dense::from_q(f.coeffs()).to_q(), f.coeffs());
        // exp(x) and log(1/(1-x))
        let x = Series::<Q>::var(30);
        let e = Dense::from_q(x.coeffs()).exp(30).to_q();
        assert_eq!(e, x.exp().unwrap().coeffs());
        let tan = x.tan().unwrap();
        assert_eq!(Dense::from_q(tan.coeffs()).revert().to_q(), tan.revert_generic().unwrap().coeffs());
    }

    fn arb_series(len: usize) -> impl Strategy<Value = Vec<(i64, i64)>> {
        prop::collection::vec((-50i64..50, 1i64..40), len)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]
        /// The dense route equals the generic recurrences exactly (inverse, log, exp, power,
        /// product, reversion) for random rational series across the threshold.
        #[test]
        fn dense_equals_generic(c in arb_series(40), d in arb_series(40), len in 2usize..40, p in -7i64..7, qd in 1i64..5) {
            let mut c = c[..len].to_vec();
            let d = series(&d[..len]);
            c[0] = (1, 1);
            let f = series(&c);
            let df = Dense::from_q(f.coeffs());
            prop_assert_eq!(df.inv(len).to_q(), f.inv_generic().unwrap().coeffs().to_vec());
            prop_assert_eq!(df.log(len).to_q(), f.log_generic().unwrap().coeffs().to_vec());
            let alpha = q(p, qd);
            prop_assert_eq!(
                df.pow(&Integer::from(p), &Integer::from(qd), len).to_q(),
                f.pow_generic(&alpha).unwrap().coeffs().to_vec()
            );
            prop_assert_eq!(
                df.mullow(&Dense::from_q(d.coeffs()), len).to_q(),
                f.mul_trunc_generic(&d, len).coeffs().to_vec()
            );
            let mut h = c.clone();
            h[0] = (0, 1);
            if h.len() > 1 && h[1].0 == 0 { h[1] = (1, 3); }
            let g = series(&h);
            prop_assert_eq!(Dense::from_q(g.coeffs()).exp(len).to_q(), g.exp_generic().unwrap().coeffs().to_vec());
            prop_assert_eq!(Dense::from_q(g.coeffs()).revert().to_q(), g.revert_generic().unwrap().coeffs().to_vec());
        }
    }

    /// The FLINT backend against the GMP route (feature `flint`, `scripts/test-flint`).
    #[cfg(feature = "flint")]
    mod flint {
        use super::*;
        use crate::flint_q;

        fn flint_of(p: flint_q::Parts) -> Vec<Q> {
            Dense::from_parts(p).to_q()
        }

        proptest! {
            #![proptest_config(ProptestConfig::with_cases(24))]
            /// Product, inverse, log, exp, power and reversion: FLINT's coefficients are the GMP
            /// route's reduced rationals, on random series of 1 to 120 coefficients (both sides of
            /// the reversion's threshold `REVERT_MIN`).
            #[test]
            fn flint_equals_gmp(c in arb_series(120), d in arb_series(120), len in 1usize..120, p in -7i64..7, qd in 1i64..5) {
                let mut c = c[..len].to_vec();
                c[0] = (1, 1);
                let f = Dense::from_q(series(&c).coeffs());
                let g = Dense::from_q(series(&d[..len]).coeffs());
                prop_assert_eq!(flint_of(flint_q::mullow((&f.num, &f.den), (&g.num, &g.den), len)), f.mullow_gmp(&g, len).to_q());
                prop_assert_eq!(flint_of(flint_q::inv(&f.num, &f.den, len)), f.inv_gmp(len).to_q());
                prop_assert_eq!(flint_of(flint_q::log(&f.num, &f.den, len)), f.log_gmp(len).to_q());
                let (pi, qi) = (Integer::from(p), Integer::from(qd));
                prop_assert_eq!(flint_of(flint_q::pow(&f.num, &f.den, &pi, &qi, len)), f.pow_gmp(&pi, &qi, len).to_q());
                let mut h = c.clone();
                h[0] = (0, 1);
                if h.len() > 1 && h[1].0 == 0 { h[1] = (1, 3); }
                let e = Dense::from_q(series(&h).coeffs());
                prop_assert_eq!(flint_of(flint_q::exp(&e.num, &e.den, len)), e.exp_gmp(len).to_q());
                prop_assert_eq!(flint_of(flint_q::revert(&e.num, &e.den)), e.revert_gmp().to_q());
            }
        }

        /// The Q job at N = 100 (issue 33: `(sin x/x)^(5/6)` and the reversion of x times it):
        /// the public route, which goes to FLINT at this length, gives the GMP route's
        /// coefficients and the generic recurrences'.
        #[test]
        fn the_q_job_at_100_is_the_same_through_flint() {
            let n = 100;
            assert!(n >= flint_q::REVERT_MIN, "the job must exercise the FLINT route");
            let a = q(5, 6);
            let s = Series::<Q>::sinc_series(n);
            let routed = s.pow(&a).unwrap();
            let gmp = Dense::from_q(s.coeffs()).pow_gmp(&Integer::from(5), &Integer::from(6), n).to_q();
            assert_eq!(routed.coeffs(), gmp);
            assert_eq!(routed.coeffs(), s.pow_generic(&a).unwrap().coeffs());
            let y = routed.shift(1).truncate(n);
            let rev = y.revert().unwrap();
            assert_eq!(rev.coeffs(), Dense::from_q(y.coeffs()).revert_gmp().to_q());
            assert_eq!(rev.coeffs(), y.revert_generic().unwrap().coeffs());
        }
    }

    #[test]
    fn sinc_power_matches_generic() {
        let n = 60;
        let a = q(5, 6);
        let s = Series::<Q>::sinc_series(n);
        let fast = Dense::from_q(s.coeffs()).pow(&Integer::from(5), &Integer::from(6), n).to_q();
        assert_eq!(fast, s.pow_generic(&a).unwrap().coeffs());
        let y = Series::from_coeffs(fast).shift(1).truncate(n);
        assert_eq!(Dense::from_q(y.coeffs()).revert().to_q(), y.revert_generic().unwrap().coeffs());
        assert!(Series::<Q>::one(1).coeffs()[0].is_one());
    }
}
