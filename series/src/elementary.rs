//! Elementary functions of a series: exp, log, power with a symbolic exponent, sqrt, sin, cos,
//! tan, sinc, z cot z. Each states its precondition (FLINT-style) and returns a typed error when
//! it is not met.

use crate::dense_q::dense_route;
use crate::gmp::to_rug;
use crate::ring::Q;
use crate::{Ring, Series, SeriesError};
use num_bigint::BigInt;
use num_traits::One;

fn check_zero_constant<R: Ring>(f: &Series<R>, operation: &'static str) -> Result<(), SeriesError> {
    match f.coeffs.first() {
        Some(c) if !c.is_zero() => Err(SeriesError::NonZeroInnerConstant { operation, constant: c.text() }),
        _ => Ok(()),
    }
}

fn check_unit_constant<R: Ring>(f: &Series<R>, operation: &'static str) -> Result<(), SeriesError> {
    match f.coeffs.first() {
        Some(c) if c.is_one() => Ok(()),
        Some(c) => Err(SeriesError::ConstantTermRequired { operation, required: "1", constant: c.text() }),
        None => Ok(()),
    }
}

impl<R: Ring> Series<R> {
    /// `exp(self)`; requires `self(0) = 0` (exp of a non-zero constant is not exact).
    /// Recurrence from `g' = f' g`: `m g_m = sum_{k=1}^{m} k f_k g_{m-k}`.
    ///
    /// ```
    /// use exact_series::{Series, Q};
    /// let e = Series::<Q>::var(5).exp().unwrap();
    /// assert_eq!(e.text("x"), "1 + x + 1/2*x^2 + 1/6*x^3 + 1/24*x^4 + O(x^5)");
    /// ```
    pub fn exp(&self) -> Result<Self, SeriesError> {
        check_zero_constant(self, "exp")?;
        match dense_route(self, |a| a.exp(self.prec())) {
            Some(r) => Ok(r),
            None => self.exp_generic(),
        }
    }

    /// [`Series::exp`] by the recurrence in any ring.
    pub(crate) fn exp_generic(&self) -> Result<Self, SeriesError> {
        check_zero_constant(self, "exp")?;
        let p = self.prec();
        let kf: Vec<R> = self.coeffs.iter().enumerate().map(|(k, c)| c.mul_int(k as i64)).collect();
        let mut g: Vec<R> = Vec::with_capacity(p);
        if p > 0 {
            g.push(R::one());
        }
        for m in 1..p {
            let mut acc = R::zero();
            for k in 1..=m {
                if !kf[k].is_zero() && !g[m - k].is_zero() {
                    acc.fma_lazy(&kf[k], &g[m - k]);
                }
            }
            acc.canonicalize();
            g.push(acc.div_int(m as i64));
        }
        Ok(Series { coeffs: g })
    }

    /// `log(self)`; requires `self(0) = 1`. Computed as `integral(f'/f)`.
    pub fn log(&self) -> Result<Self, SeriesError> {
        check_unit_constant(self, "log")?;
        match dense_route(self, |a| a.log(self.prec())) {
            Some(r) => Ok(r),
            None => self.log_generic(),
        }
    }

    /// [`Series::log`] through the generic inverse and product.
    pub(crate) fn log_generic(&self) -> Result<Self, SeriesError> {
        check_unit_constant(self, "log")?;
        if self.prec() == 0 {
            return Ok(self.clone());
        }
        let q = self.derivative().mul_trunc_generic(&self.inv_generic()?, usize::MAX);
        Ok(q.integral())
    }

    /// `self^alpha` for an exponent `alpha` in the coefficient ring (e.g. `1/2 + theta`); requires
    /// `self(0) = 1`. J.C.P. Miller's recurrence:
    /// `g_0 = 1`, `m g_m = sum_{k=1}^{m} ((alpha + 1) k - m) f_k g_{m-k}`.
    ///
    /// ```
    /// use exact_series::{Poly, Ring, Series, Q};
    /// let x = Series::<Poly>::var(5);
    /// let alpha = Poly::var("theta").unwrap();
    /// let f = Series::one(5).add(&x).pow(&alpha).unwrap(); // (1+x)^theta
    /// assert_eq!(f.coeff(2).unwrap().text(), "1/2*theta^2 - 1/2*theta");
    /// ```
    pub fn pow(&self, alpha: &R) -> Result<Self, SeriesError> {
        check_unit_constant(self, "pow")?;
        if let Some(e) = (alpha as &dyn std::any::Any).downcast_ref::<Q>() {
            let (p, q) = (to_rug(e.numer()), to_rug(e.denom()));
            if let Some(r) = dense_route(self, |a| a.pow(&p, &q, self.prec())) {
                return Ok(r);
            }
        }
        self.pow_generic(alpha)
    }

    /// [`Series::pow`] by Miller's recurrence in any ring.
    pub(crate) fn pow_generic(&self, alpha: &R) -> Result<Self, SeriesError> {
        check_unit_constant(self, "pow")?;
        let p = self.prec();
        let a1 = alpha.add(&R::one());
        let mut g: Vec<R> = Vec::with_capacity(p);
        if p > 0 {
            g.push(R::one());
        }
        // Precompute (alpha + 1) k f_k and f_k.
        let af: Vec<R> = self.coeffs.iter().enumerate().map(|(k, c)| a1.mul_int(k as i64).mul(c)).collect();
        for m in 1..p {
            let mut acc = R::zero();
            for k in 1..=m {
                let fk = &self.coeffs[k];
                if fk.is_zero() || g[m - k].is_zero() {
                    continue;
                }
                // ((alpha+1) k - m) f_k = af_k - m f_k
                let w = af[k].sub(&fk.mul_int(m as i64));
                acc.fma_lazy(&w, &g[m - k]);
            }
            acc.canonicalize();
            g.push(acc.div_int(m as i64));
        }
        Ok(Series { coeffs: g })
    }

    /// `self^q` for a rational exponent `q`; requires `self(0) = 1`.
    pub fn pow_q(&self, q: &Q) -> Result<Self, SeriesError> {
        self.pow(&R::from_q(q))
    }

    /// `sqrt(self)`: the constant term must be an exact square of a unit (`c0 = s^2`); the result
    /// has constant term `s`. A leading `x^(2v)` factor is taken out first.
    pub fn sqrt(&self) -> Result<Self, SeriesError> {
        let v = self.valuation();
        if v > 0 && v < self.prec() {
            if v % 2 == 1 {
                return Err(SeriesError::NotASquare { constant: format!("x^{v} * ...") });
            }
            let inner = Series { coeffs: self.coeffs[v..].to_vec() };
            return Ok(inner.sqrt()?.shift(v / 2));
        }
        let c0 = self.coeffs.first().cloned().unwrap_or_else(R::zero);
        let s =
            c0.sqrt_exact().filter(|s| !s.is_zero()).ok_or_else(|| SeriesError::NotASquare { constant: c0.text() })?;
        let c0_inv = c0
            .inv()
            .ok_or_else(|| SeriesError::NonInvertibleConstantTerm { operation: "sqrt", constant: c0.text() })?;
        let half = Q::new(BigInt::one(), BigInt::from(2));
        Ok(self.mul_scalar(&c0_inv).pow_q(&half)?.mul_scalar(&s))
    }

    /// `(sin(self), cos(self))`, requires `self(0) = 0`. Recurrences from `s' = f' c`, `c' = -f' s`.
    pub fn sin_cos(&self) -> Result<(Self, Self), SeriesError> {
        check_zero_constant(self, "sin/cos")?;
        let p = self.prec();
        let kf: Vec<R> = self.coeffs.iter().enumerate().map(|(k, c)| c.mul_int(k as i64)).collect();
        let mut s: Vec<R> = Vec::with_capacity(p);
        let mut c: Vec<R> = Vec::with_capacity(p);
        if p > 0 {
            s.push(R::zero());
            c.push(R::one());
        }
        for m in 1..p {
            let (mut as_, mut ac) = (R::zero(), R::zero());
            for k in 1..=m {
                if kf[k].is_zero() {
                    continue;
                }
                if !c[m - k].is_zero() {
                    as_.fma_lazy(&kf[k], &c[m - k]);
                }
                if !s[m - k].is_zero() {
                    ac.fma_lazy(&kf[k], &s[m - k]);
                }
            }
            as_.canonicalize();
            ac.canonicalize();
            s.push(as_.div_int(m as i64));
            c.push(ac.div_int(m as i64).neg());
        }
        Ok((Series { coeffs: s }, Series { coeffs: c }))
    }

    /// `sin(self)`, requires `self(0) = 0`.
    pub fn sin(&self) -> Result<Self, SeriesError> {
        Ok(self.sin_cos()?.0)
    }

    /// `cos(self)`, requires `self(0) = 0`.
    pub fn cos(&self) -> Result<Self, SeriesError> {
        Ok(self.sin_cos()?.1)
    }

    /// `tan(self) = sin/cos`, requires `self(0) = 0`.
    pub fn tan(&self) -> Result<Self, SeriesError> {
        let (s, c) = self.sin_cos()?;
        s.div(&c)
    }

    /// The series of `sinc z = sin z / z = sum_k (-1)^k z^(2k)/(2k+1)!` in `z`, to `O(z^prec)`.
    pub fn sinc_series(prec: usize) -> Self {
        let mut out = Vec::with_capacity(prec);
        let mut fact = BigInt::one(); // (k+1)!
        for k in 0..prec {
            fact *= BigInt::from(k as u64 + 1);
            if k % 2 == 0 {
                let sign = if (k / 2) % 2 == 0 { BigInt::one() } else { -BigInt::one() };
                out.push(R::from_q(&Q::new(sign, fact.clone())));
            } else {
                out.push(R::zero());
            }
        }
        Series { coeffs: out }
    }

    /// The series of `z cot z = cos z / sinc z` in `z`, to `O(z^prec)` (THEORY.md section 5:
    /// the kernel Z(z), [3.2]). Its coefficients are `(-1)^k 2^(2k) B_(2k) / (2k)!`.
    pub fn zcot_series(prec: usize) -> Self {
        let z = Series::<R>::var(prec + 1);
        let cos = z.cos().expect("z has zero constant term").truncate(prec);
        cos.div(&Series::sinc_series(prec)).expect("sinc(0) = 1 is a unit")
    }

    /// `sinc(self) = sin(self)/self` (with sinc(0) = 1), requires `self(0) = 0`.
    pub fn sinc(&self) -> Result<Self, SeriesError> {
        check_zero_constant(self, "sinc")?;
        Series::sinc_series(self.prec()).compose(self)
    }

    /// `self * cot(self)`, requires `self(0) = 0`.
    pub fn zcot(&self) -> Result<Self, SeriesError> {
        check_zero_constant(self, "zcot")?;
        Series::zcot_series(self.prec()).compose(self)
    }
}
