//! Multiplication, inverse and division of truncated series.

use crate::dense_q::{dense_of, dense_route, DENSE_MIN};
use crate::{Ring, Series, SeriesError};

impl<R: Ring> Series<R> {
    /// `self * other`. Precision: `min(p_a + v_b, p_b + v_a)` (v = valuation), which is exact:
    /// the first unknown term of the product is `x^(p_a + v_b)` or `x^(p_b + v_a)`.
    /// Schoolbook convolution, zero coefficients skipped.
    pub fn mul(&self, other: &Self) -> Self {
        let (va, vb) = (self.valuation(), other.valuation());
        let p = (self.prec() + vb).min(other.prec() + va);
        self.mul_trunc(other, p)
    }

    /// `self * other` truncated to `min(n, exact precision)` coefficients.
    pub fn mul_trunc(&self, other: &Self, n: usize) -> Self {
        let (va, vb) = (self.valuation(), other.valuation());
        let p = n.min((self.prec() + vb).min(other.prec() + va));
        if p >= DENSE_MIN
            && self.prec().min(other.prec()) >= DENSE_MIN
            && let Some(b) = dense_of(other)
            && let Some(r) = dense_route(self, |a| a.mullow(&b, p))
        {
            return r;
        }
        self.mul_trunc_generic(other, n)
    }

    /// [`Series::mul_trunc`] by the schoolbook convolution in any ring (the reference the fast
    /// route of `Series<Q>` is tested against).
    pub(crate) fn mul_trunc_generic(&self, other: &Self, n: usize) -> Self {
        let (va, vb) = (self.valuation(), other.valuation());
        let p = n.min((self.prec() + vb).min(other.prec() + va));
        let mut out = vec![R::zero(); p];
        for (i, a) in self.coeffs.iter().enumerate().take(p) {
            if a.is_zero() {
                continue;
            }
            for (j, b) in other.coeffs.iter().enumerate().take(p - i) {
                if b.is_zero() {
                    continue;
                }
                out[i + j].fma_lazy(a, b);
            }
        }
        out.iter_mut().for_each(R::canonicalize);
        Series { coeffs: out }
    }

    /// `1/self`; the constant term must be a unit of the ring.
    /// Recurrence `b_0 = 1/a_0`, `b_n = -b_0 sum_{k=1}^{n} a_k b_{n-k}`.
    ///
    /// ```
    /// use exact_series::{Series, Q};
    /// assert!(Series::<Q>::var(4).inv().is_err()); // 1/x is not a power series
    /// ```
    pub fn inv(&self) -> Result<Self, SeriesError> {
        if self.coeffs.first().is_some_and(|c| !c.is_zero())
            && let Some(r) = dense_route(self, |a| a.inv(self.prec()))
        {
            return Ok(r);
        }
        self.inv_generic()
    }

    /// [`Series::inv`] by the recurrence in any ring.
    pub(crate) fn inv_generic(&self) -> Result<Self, SeriesError> {
        let a0 = self.coeffs.first().cloned().unwrap_or_else(R::zero);
        let b0 =
            a0.inv().ok_or_else(|| SeriesError::NonInvertibleConstantTerm { operation: "inv", constant: a0.text() })?;
        let p = self.prec();
        let mut b: Vec<R> = Vec::with_capacity(p);
        b.push(b0.clone());
        for n in 1..p {
            let mut acc = R::zero();
            for k in 1..=n {
                let ak = &self.coeffs[k];
                if !ak.is_zero() && !b[n - k].is_zero() {
                    acc.fma_lazy(ak, &b[n - k]);
                }
            }
            acc.canonicalize();
            b.push(acc.mul(&b0).neg());
        }
        Ok(Series { coeffs: b })
    }

    /// `self / other`. When the divisor has valuation `v > 0`, `x^v` is cancelled first (the
    /// dividend must have valuation `>= v`); then the divisor's leading coefficient must be a unit.
    ///
    /// ```
    /// use exact_series::{Series, Q, Ring};
    /// let x = Series::<Q>::var(8);
    /// let sin = x.sin().unwrap();
    /// let sinc = sin.div(&x).unwrap(); // sin(x)/x, known to O(x^7)
    /// assert_eq!(sinc.prec(), 7);
    /// ```
    pub fn div(&self, other: &Self) -> Result<Self, SeriesError> {
        let v = other.valuation();
        if v == 0 {
            return Ok(self.mul(&other.inv()?));
        }
        let va = self.valuation();
        if va < v || v >= other.prec() {
            return Err(SeriesError::ValuationMismatch { dividend: va, divisor: v });
        }
        let a = Series { coeffs: self.coeffs[v..].to_vec() };
        let b = Series { coeffs: other.coeffs[v..].to_vec() };
        Ok(a.mul(&b.inv()?))
    }

    /// `self^n` for an integer `n` (negative `n` needs an invertible constant term).
    pub fn powi(&self, n: i64) -> Result<Self, SeriesError> {
        let base = if n < 0 { self.inv()? } else { self.clone() };
        let mut e = n.unsigned_abs();
        let mut result = Series::one(base.prec().max(1));
        let mut sq = base;
        let mut first = true;
        while e > 0 {
            if e & 1 == 1 {
                result = if first { sq.clone() } else { result.mul(&sq) };
                first = false;
            }
            e >>= 1;
            if e > 0 {
                sq = sq.mul(&sq);
            }
        }
        Ok(result)
    }
}

impl<R: Ring> std::ops::Add for &Series<R> {
    type Output = Series<R>;
    fn add(self, o: Self) -> Series<R> {
        Series::add(self, o)
    }
}
impl<R: Ring> std::ops::Sub for &Series<R> {
    type Output = Series<R>;
    fn sub(self, o: Self) -> Series<R> {
        Series::sub(self, o)
    }
}
impl<R: Ring> std::ops::Mul for &Series<R> {
    type Output = Series<R>;
    fn mul(self, o: Self) -> Series<R> {
        Series::mul(self, o)
    }
}
impl<R: Ring> std::ops::Neg for &Series<R> {
    type Output = Series<R>;
    fn neg(self) -> Series<R> {
        Series::neg(self)
    }
}
