//! Composition and reversion.

use crate::dense_q::dense_route;
use crate::{Ring, Series, SeriesError};

impl<R: Ring> Series<R> {
    /// `self(g)`; requires `g(0) = 0`. Horner's scheme. Precision: `min(p_f * v_g, p_g)`.
    ///
    /// ```
    /// use exact_series::{Series, Q};
    /// let x = Series::<Q>::var(6);
    /// let e = x.exp().unwrap();
    /// let f = e.compose(&x.sin().unwrap()).unwrap(); // exp(sin x)
    /// assert_eq!(f.coeff(3).unwrap(), &Q::from_integer(0.into()));
    /// ```
    pub fn compose(&self, g: &Self) -> Result<Self, SeriesError> {
        if let Some(c) = g.coeffs.first()
            && !c.is_zero()
        {
            return Err(SeriesError::NonZeroInnerConstant { operation: "compose", constant: c.text() });
        }
        let vg = g.valuation().max(1);
        let p = (self.prec().saturating_mul(vg)).min(g.prec());
        let g = g.truncate(p);
        let mut result = Series::zero(p);
        for k in (0..self.prec().min(p.max(1))).rev() {
            result = result.mul_trunc(&g, p);
            result = Series::new(result.coeffs, p);
            if p > 0 {
                result.coeffs[0].add_assign(&self.coeffs[k]);
            }
        }
        Ok(Series::new(result.coeffs, p))
    }

    /// The compositional inverse `g` with `self(g(y)) = y`; requires `self(0) = 0` and `self'(0)`
    /// a unit. Lagrange inversion: with `self = a_1 x h(x)`, `h(0) = 1`,
    /// `[y^n] g = (1/n) a_1^(-n) [x^(n-1)] exp(-n log h)`. Known to the same precision.
    ///
    /// ```
    /// use exact_series::{Series, Q};
    /// let x = Series::<Q>::var(6);
    /// let atan = x.tan().unwrap().revert().unwrap();
    /// assert_eq!(atan.text("x"), "x - 1/3*x^3 + 1/5*x^5 + O(x^6)");
    /// ```
    pub fn revert(&self) -> Result<Self, SeriesError> {
        if self.coeffs.first().is_some_and(R::is_zero)
            && self.coeffs.get(1).is_some_and(|c| !c.is_zero())
            && let Some(r) = dense_route(self, |a| a.revert())
        {
            return Ok(r);
        }
        self.revert_generic()
    }

    /// [`Series::revert`] by Lagrange inversion with one exp per coefficient, in any ring.
    pub(crate) fn revert_generic(&self) -> Result<Self, SeriesError> {
        let p = self.prec();
        if let Some(c) = self.coeffs.first()
            && !c.is_zero()
        {
            return Err(SeriesError::NonZeroInnerConstant { operation: "revert", constant: c.text() });
        }
        if p < 2 {
            return Ok(Series::zero(p));
        }
        let a1 = &self.coeffs[1];
        let a1_inv = a1.inv().ok_or_else(|| SeriesError::NonInvertibleConstantTerm {
            operation: "revert (linear coefficient)",
            constant: a1.text(),
        })?;
        // h = self / (a1 x), known to p - 1 coefficients.
        let h = Series { coeffs: self.coeffs[1..].iter().map(|c| c.mul(&a1_inv)).collect() };
        let log_h = h.log_generic()?;
        let mut out = vec![R::zero(); p];
        let mut a1_pow = a1_inv.clone(); // a1^(-n)
        for n in 1..p {
            // [x^(n-1)] exp(-n log h), with exp truncated to n coefficients.
            let e = log_h.truncate(n).scale(&crate::Q::from_integer((-(n as i64)).into())).exp_generic()?;
            out[n] = e.coeffs[n - 1].mul(&a1_pow).div_int(n as i64);
            a1_pow = a1_pow.mul(&a1_inv);
        }
        Ok(Series { coeffs: out })
    }
}
