//! [`Series`]: a truncated power series whose truncation order is part of the value.

use crate::ring::Q;
use crate::Ring;

/// `c_0 + c_1 x + ... + c_{p-1} x^{p-1} + O(x^p)` with coefficients in `R`, `p = prec()`.
///
/// Invariant: exactly `prec` coefficients are stored (zeros included), so two series are equal
/// exactly when they have the same precision and the same known coefficients. Every operation
/// computes the precision of its result from those of its operands (FLINT's convention, refined
/// by valuations: `x^2 * (1 + O(x^3))` is known to `O(x^5)`).
///
/// Order convention of the project (THEORY.md section 5): "order N" keeps every term through
/// x^N, i.e. `prec = N + 1`; see [`Series::order`].
///
/// ```
/// use exact_series::{Series, Q, Ring};
/// let x = Series::<Q>::var(6);
/// let f = x.add(&Series::one(6)).inv().unwrap(); // 1/(1+x)
/// assert_eq!(f.text("x"), "1 - x + x^2 - x^3 + x^4 - x^5 + O(x^6)");
/// ```
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub struct Series<R: Ring> {
    pub(crate) coeffs: Vec<R>,
}

impl<R: Ring> Series<R> {
    /// The series with the given known coefficients; `prec = coeffs.len()`.
    pub fn from_coeffs(coeffs: Vec<R>) -> Self {
        Series { coeffs }
    }
    /// The series with the given coefficients, padded with zeros or truncated to `prec`.
    pub fn new(mut coeffs: Vec<R>, prec: usize) -> Self {
        coeffs.resize(prec, R::zero());
        Series { coeffs }
    }
    /// `0 + O(x^prec)`.
    pub fn zero(prec: usize) -> Self {
        Series { coeffs: vec![R::zero(); prec] }
    }
    /// `1 + O(x^prec)`.
    pub fn one(prec: usize) -> Self {
        Series::constant(R::one(), prec)
    }
    /// `c + O(x^prec)`.
    pub fn constant(c: R, prec: usize) -> Self {
        Series::new(vec![c], prec)
    }
    /// `x + O(x^prec)`.
    pub fn var(prec: usize) -> Self {
        Series::new(vec![R::zero(), R::one()], prec)
    }
    /// A series from a coefficient function `k -> c_k`, `k < prec`.
    pub fn from_fn(prec: usize, f: impl FnMut(usize) -> R) -> Self {
        Series { coeffs: (0..prec).map(f).collect() }
    }
    /// The number of known coefficients `p` (the series is known up to `O(x^p)`).
    pub fn prec(&self) -> usize {
        self.coeffs.len()
    }
    /// The highest power kept, `prec - 1` ("order N keeps every term through x^N");
    /// `None` for a series with no known coefficient.
    pub fn order(&self) -> Option<usize> {
        self.coeffs.len().checked_sub(1)
    }
    /// The coefficient of `x^k` (`None` when `k >= prec`: unknown, not zero).
    pub fn coeff(&self, k: usize) -> Option<&R> {
        self.coeffs.get(k)
    }
    /// All known coefficients.
    pub fn coeffs(&self) -> &[R] {
        &self.coeffs
    }
    /// The index of the first non-zero coefficient (`prec` if all known ones are zero).
    pub fn valuation(&self) -> usize {
        self.coeffs.iter().position(|c| !c.is_zero()).unwrap_or(self.coeffs.len())
    }
    /// The same series known to `min(prec, self.prec())` only.
    pub fn truncate(&self, prec: usize) -> Self {
        Series { coeffs: self.coeffs[..prec.min(self.prec())].to_vec() }
    }
    /// Whether the first `n` coefficients agree (FLINT's `equal_trunc`); both must know them.
    pub fn eq_trunc(&self, other: &Self, n: usize) -> bool {
        n <= self.prec() && n <= other.prec() && self.coeffs[..n] == other.coeffs[..n]
    }
    /// Applies `f` to every coefficient (e.g. substitution of a symbol, a change of ring).
    pub fn map<S: Ring>(&self, f: impl FnMut(&R) -> S) -> Series<S> {
        Series { coeffs: self.coeffs.iter().map(f).collect() }
    }
    /// `self + other`, known to the smaller precision.
    pub fn add(&self, other: &Self) -> Self {
        let p = self.prec().min(other.prec());
        Series { coeffs: (0..p).map(|k| self.coeffs[k].add(&other.coeffs[k])).collect() }
    }
    /// `self - other`, known to the smaller precision.
    pub fn sub(&self, other: &Self) -> Self {
        let p = self.prec().min(other.prec());
        Series { coeffs: (0..p).map(|k| self.coeffs[k].sub(&other.coeffs[k])).collect() }
    }
    /// `-self`.
    pub fn neg(&self) -> Self {
        self.map(|c| c.neg())
    }
    /// `c * self` for a ring element `c`.
    pub fn mul_scalar(&self, c: &R) -> Self {
        self.map(|a| a.mul(c))
    }
    /// `q * self` for a rational `q`.
    pub fn scale(&self, q: &Q) -> Self {
        self.map(|a| a.scale(q))
    }
    /// `x^k * self` (precision grows by `k`).
    pub fn shift(&self, k: usize) -> Self {
        let mut coeffs = vec![R::zero(); k];
        coeffs.extend(self.coeffs.iter().cloned());
        Series { coeffs }
    }
    /// `self(c x)`: the coefficient of `x^k` is multiplied by `c^k`.
    pub fn rescale_var(&self, c: &R) -> Self {
        let mut p = R::one();
        let mut out = Vec::with_capacity(self.prec());
        for a in &self.coeffs {
            out.push(a.mul(&p));
            p = p.mul(c);
        }
        Series { coeffs: out }
    }
    /// `d/dx self` (known to `prec - 1`).
    pub fn derivative(&self) -> Self {
        Series { coeffs: self.coeffs.iter().enumerate().skip(1).map(|(k, c)| c.mul_int(k as i64)).collect() }
    }
    /// The antiderivative vanishing at 0 (known to `prec + 1`).
    pub fn integral(&self) -> Self {
        let mut coeffs = Vec::with_capacity(self.prec() + 1);
        coeffs.push(R::zero());
        coeffs.extend(self.coeffs.iter().enumerate().map(|(k, c)| c.div_int(k as i64 + 1)));
        Series { coeffs }
    }
    /// Whether every odd coefficient is zero.
    pub fn is_even(&self) -> bool {
        self.coeffs.iter().skip(1).step_by(2).all(|c| c.is_zero())
    }
    /// Whether every even coefficient is zero.
    pub fn is_odd(&self) -> bool {
        self.coeffs.iter().step_by(2).all(|c| c.is_zero())
    }
}
