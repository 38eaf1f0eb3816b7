//! Truncated power series in one variable with complex MPFR coefficients: the numerical twin of
//! the exact engine's `Series` (`exact_series`), for expansions whose coefficients are only known
//! as numbers (the loading-law expansion of `crate::asymptotics::loading_law`).
//!
//! A series holds the coefficients of t^0 .. t^(len-1); every operation keeps the shorter length
//! of its operands (the terms from t^len on are unknown, FLINT `_series` style). Precision is the
//! coefficients' own (`prec`, fixed at construction).
//! Formulas (power series identities, e.g. Knuth TAOCP vol. 2, 4.7):
//! - exp: b = e^a, b_0 = e^(a_0), k b_k = sum_{j=1}^{k} j a_j b_(k-j);
//! - log: b = log a (a_0 != 0, principal branch), k a_0 b_k = k a_k - sum_{j=1}^{k-1} j b_j a_(k-j);
//! - reciprocal: a_0 b_k = -sum_{j=1}^{k} a_j b_(k-j);
//! - composition f(u) with u_0 = 0 by Horner (only f_0 .. f_(len-1) matter).

use rug::{Complex, Float};

/// A truncated series sum_k c_k t^k + O(t^len).
#[derive(Debug, Clone, PartialEq)]
pub struct ComplexSeries {
    coeffs: Vec<Complex>,
}

impl ComplexSeries {
    /// From coefficients (len = their number).
    pub fn new(coeffs: Vec<Complex>) -> Self {
        ComplexSeries { coeffs }
    }
    /// From real coefficients.
    pub(crate) fn from_real(coeffs: &[Float], prec: u32) -> Self {
        ComplexSeries { coeffs: coeffs.iter().map(|c| Complex::with_val(prec, c)).collect() }
    }
    /// The constant `c` + O(t^len).
    pub fn constant(c: Complex, len: usize) -> Self {
        let prec = c.prec().0;
        let mut coeffs = vec![Complex::new(prec); len];
        if len > 0 {
            coeffs[0] = c;
        }
        ComplexSeries { coeffs }
    }
    /// Zero + O(t^len).
    pub fn zero(len: usize, prec: u32) -> Self {
        ComplexSeries { coeffs: vec![Complex::new(prec); len] }
    }
    /// Number of known coefficients.
    pub fn len(&self) -> usize {
        self.coeffs.len()
    }
    /// Whether no coefficient is known.
    pub fn is_empty(&self) -> bool {
        self.coeffs.is_empty()
    }
    /// The coefficients.
    pub fn coeffs(&self) -> &[Complex] {
        &self.coeffs
    }
    /// Coefficient of t^k (`None` beyond the known terms).
    pub fn coeff(&self, k: usize) -> Option<&Complex> {
        self.coeffs.get(k)
    }
    fn prec(&self) -> u32 {
        self.coeffs.first().map_or(64, |c| c.prec().0)
    }
    /// Truncated to `len` terms (never longer).
    pub fn truncate(mut self, len: usize) -> Self {
        self.coeffs.truncate(len);
        self
    }
    /// self + other.
    pub fn add(&self, other: &Self) -> Self {
        let n = self.len().min(other.len());
        ComplexSeries {
            coeffs: (0..n).map(|k| Complex::with_val(self.prec(), &self.coeffs[k] + &other.coeffs[k])).collect(),
        }
    }
    /// self - other.
    pub fn sub(&self, other: &Self) -> Self {
        let n = self.len().min(other.len());
        ComplexSeries {
            coeffs: (0..n).map(|k| Complex::with_val(self.prec(), &self.coeffs[k] - &other.coeffs[k])).collect(),
        }
    }
    /// self + c (added to the constant term).
    pub(crate) fn add_constant(&self, c: &Complex) -> Self {
        let mut out = self.clone();
        if let Some(c0) = out.coeffs.first_mut() {
            *c0 += c;
        }
        out
    }
    /// c self.
    pub fn scale(&self, c: &Complex) -> Self {
        ComplexSeries { coeffs: self.coeffs.iter().map(|a| Complex::with_val(self.prec(), a * c)).collect() }
    }
    /// x self, x real.
    pub(crate) fn scale_real(&self, x: &Float) -> Self {
        ComplexSeries { coeffs: self.coeffs.iter().map(|a| Complex::with_val(self.prec(), a * x)).collect() }
    }
    /// t self (the length is kept: the top coefficient is dropped).
    pub fn shift(&self) -> Self {
        let mut coeffs = Vec::with_capacity(self.len());
        if !self.is_empty() {
            coeffs.push(Complex::new(self.prec()));
            coeffs.extend(self.coeffs[..self.len() - 1].iter().cloned());
        }
        ComplexSeries { coeffs }
    }
    /// self other, truncated.
    pub fn mul(&self, other: &Self) -> Self {
        let n = self.len().min(other.len());
        let prec = self.prec();
        let coeffs = (0..n)
            .map(|k| {
                let mut acc = Complex::new(prec);
                for j in 0..=k {
                    acc += Complex::with_val(prec, &self.coeffs[j] * &other.coeffs[k - j]);
                }
                acc
            })
            .collect();
        ComplexSeries { coeffs }
    }
    /// e^self (module doc).
    pub fn exp(&self) -> Self {
        let prec = self.prec();
        let mut b: Vec<Complex> = Vec::with_capacity(self.len());
        for k in 0..self.len() {
            if k == 0 {
                b.push(Complex::with_val(prec, self.coeffs[0].exp_ref()));
                continue;
            }
            let mut acc = Complex::new(prec);
            for j in 1..=k {
                acc += Complex::with_val(prec, &self.coeffs[j] * &b[k - j]) * j as u32;
            }
            b.push(acc / k as u32);
        }
        ComplexSeries { coeffs: b }
    }
    /// log self, principal branch at the constant term; `None` if the constant term is 0.
    pub fn log(&self) -> Option<Self> {
        let prec = self.prec();
        let a0 = self.coeffs.first()?;
        if a0.is_zero() {
            return None;
        }
        let mut b: Vec<Complex> = Vec::with_capacity(self.len());
        b.push(Complex::with_val(prec, a0.ln_ref()));
        for k in 1..self.len() {
            let mut acc = Complex::with_val(prec, &self.coeffs[k] * k as u32);
            for (j, bj) in b.iter().enumerate().skip(1) {
                acc -= Complex::with_val(prec, bj * &self.coeffs[k - j]) * j as u32;
            }
            b.push(acc / a0 / k as u32);
        }
        Some(ComplexSeries { coeffs: b })
    }
    /// self^e = exp(e log self), principal branch; `None` if the constant term is 0.
    pub fn pow(&self, e: &Complex) -> Option<Self> {
        Some(self.log()?.scale(e).exp())
    }
    /// 1/self; `None` if the constant term is 0.
    pub fn recip(&self) -> Option<Self> {
        let prec = self.prec();
        let a0 = self.coeffs.first()?;
        if a0.is_zero() {
            return None;
        }
        let inv0 = Complex::with_val(prec, a0.recip_ref());
        let mut b = vec![inv0.clone()];
        for k in 1..self.len() {
            let mut acc = Complex::new(prec);
            for j in 1..=k {
                acc += Complex::with_val(prec, &self.coeffs[j] * &b[k - j]);
            }
            b.push(-(acc * &inv0));
        }
        Some(ComplexSeries { coeffs: b })
    }
    /// f(self) = sum_k f_k self^k for a series with zero constant term (`None` otherwise), by
    /// Horner; `f` lists f_0, f_1, ... (terms beyond `len` are not needed).
    pub fn compose(&self, f: &[Complex]) -> Option<Self> {
        if self.coeffs.first().is_some_and(|c| !c.is_zero()) {
            return None;
        }
        let n = self.len();
        let prec = self.prec();
        let top = f.len().min(n);
        let mut acc = ComplexSeries::zero(n, prec);
        for k in (0..top).rev() {
            acc = acc.mul(self).add_constant(&f[k]);
        }
        Some(acc)
    }
}

/// The coefficients of sinc(z) = sin(z)/z as a series in u = z^2: (-1)^k/(2k+1)!, k < `len`.
pub(crate) fn sinc_in_square(len: usize, prec: u32) -> Vec<Complex> {
    alternating_factorials(len, 1, prec)
}

/// The coefficients of cos(z) as a series in u = z^2: (-1)^k/(2k)!, k < `len`.
pub(crate) fn cos_in_square(len: usize, prec: u32) -> Vec<Complex> {
    alternating_factorials(len, 0, prec)
}

/// (-1)^k/(2k + shift)!.
fn alternating_factorials(len: usize, shift: u32, prec: u32) -> Vec<Complex> {
    let mut out = Vec::with_capacity(len);
    let mut term = Float::with_val(prec, 1);
    for m in 1..=shift {
        term /= m;
    }
    for k in 0..len as u32 {
        if k > 0 {
            term /= (2 * k + shift - 1) * (2 * k + shift);
            term = -term;
        }
        out.push(Complex::with_val(prec, &term));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    const PREC: u32 = 200;

    fn c(re: f64, im: f64) -> Complex {
        Complex::with_val(PREC, (re, im))
    }

    fn close(a: &Complex, b: &Complex, tol: f64) -> bool {
        Float::with_val(PREC, Complex::with_val(PREC, a - b).abs_ref()).to_f64() < tol
    }

    /// log(exp a) = a and exp(log a) = a (a_0 complex), a (1/a) = 1, a^(1/2) a^(1/2) = a.
    #[test]
    fn identities() {
        let a = ComplexSeries::new(vec![c(0.7, 0.2), c(-1.3, 0.5), c(0.25, -2.0), c(3.0, 0.0), c(0.0, 1.0)]);
        let back = a.exp().log().unwrap();
        let again = a.log().unwrap().exp();
        let one = a.mul(&a.recip().unwrap());
        let half = a.pow(&c(0.5, 0.0)).unwrap();
        let sq = half.mul(&half);
        for k in 0..a.len() {
            assert!(close(&back.coeffs()[k], &a.coeffs()[k], 1e-50), "log exp {k}");
            assert!(close(&again.coeffs()[k], &a.coeffs()[k], 1e-50), "exp log {k}");
            assert!(close(&one.coeffs()[k], &c(if k == 0 { 1.0 } else { 0.0 }, 0.0), 1e-50), "recip {k}");
            assert!(close(&sq.coeffs()[k], &a.coeffs()[k], 1e-50), "pow {k}");
        }
    }

    /// The coefficients in u = z^2 summed at u = 0.3 give MPFR's sin(z)/z and cos(z); the
    /// composition of exp with u = t + t^2 equals exp(u) computed by the exp recurrence.
    #[test]
    fn elementary_coefficients_and_composition() {
        let n = 30;
        let t = Float::with_val(PREC, 0.3);
        let z = Float::with_val(PREC, t.sqrt_ref());
        let sum = |f: &[Complex]| f.iter().rev().fold(Complex::new(PREC), |acc, c| acc * &t + c);
        let sinc = Complex::with_val(PREC, Float::with_val(PREC, z.sin_ref()) / &z);
        let cos = Complex::with_val(PREC, z.cos_ref());
        assert!(close(&sum(&sinc_in_square(n, PREC)), &sinc, 1e-45));
        assert!(close(&sum(&cos_in_square(n, PREC)), &cos, 1e-45));
        let len = 8;
        let mut u = ComplexSeries::zero(len, PREC);
        u.coeffs[1] = c(1.0, 0.0);
        u.coeffs[2] = c(1.0, 0.0);
        let mut exp_coeffs = vec![c(1.0, 0.0)];
        for k in 1..len {
            exp_coeffs.push(exp_coeffs[k - 1].clone() / k as u32);
        }
        let composed = u.compose(&exp_coeffs).unwrap();
        let direct = u.exp();
        for k in 0..len {
            assert!(close(&composed.coeffs()[k], &direct.coeffs()[k], 1e-50), "compose {k}");
        }
        assert!(ComplexSeries::constant(c(1.0, 0.0), 3).compose(&exp_coeffs).is_none());
    }
}
