//! The polynomial punch profile of the exact series, g = sum_j c_j x^j (docs/theory.md section 9),
//! with each c_j either an exact rational or a symbol, and its dimensionless ratios rho_j.
//!
//! # Parameters: why rho_j = c_j l_s^(j-r) / c_r
//! The reference degree r is the lowest degree j >= 2 whose coefficient is not a known zero
//! (r = 2 whenever c_2 is non-zero or symbolic; g = A x^4 has r = 4). In the linear contact
//! variable xh = (x - c)/l, with y = c/l + xh = rbar + xh and l = rho l_s,
//!
//!   (E*/2) g'(x) = E* c_r l^(r-1) sum_j (j/2) rho_j rho^(j-r) y^(j-1),   rho_j = c_j l_s^(j-r)/c_r,
//!
//! so the right-hand side of [2.8] divided by E* c_r l^(r-1) is a polynomial in (xh, rbar, rho)
//! whose coefficients are the rho_j: exact, dimensionless, rho_r = 1, and constant when the
//! period varies at fixed load (l_s, the single-punch half-length at the same load, does not
//! depend on L). The parabola g = k x^2 has r = 2, every rho_j = 0 (j != 2), and
//! T = beta tau0/(E* k l_s) as in docs/theory.md section 5. The tilt enters only beside tau0:
//! (j/2) rho_1 rho^(1-r) = (rho_1/2) rho^(1-r) and beta tau0/(E* c_r l^(r-1)) = T rho^(1-r),
//! T = beta tau0/(E* c_r l_s^(r-1)), so [2.8] sees the sum T + rho_1/2 only.
//!
//! Symbols: `rho_j` for a symbolic coefficient (or a known one when c_r is symbolic), `rho_1` for
//! any non-zero tilt. A known c_j with a known c_r enters as the exact polynomial
//! (c_j/c_r) l_s^(j-r) in the symbol `l_s` (j > r, so the power is positive): the coefficients
//! then stay exact and `l_s` is the single-punch half-length in the unit of the c_j.

use crate::model::{readable, Exact, ModelError};
use exact_series::{Monomial, Poly, Ring, SeriesError, Symbol};
use num_traits::{Signed, Zero};

/// Symbol of the single-punch half-length (in the unit of the coefficients).
pub const LS: &str = "l_s";

/// Symbol of L/pi (Problem 2 with known coefficients).
pub const LPI: &str = "L_pi";

/// Largest degree accepted (the exact series grow quickly with the degree).
pub const MAX_DEGREE: usize = 12;

/// g = sum_j c_j x^j with c_0 = 0; `None` is a symbolic coefficient.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PolynomialProfile {
    coefficients: Vec<Option<Exact>>,
    reference: usize,
}

impl PolynomialProfile {
    /// A profile from its coefficients in numpy order (index j multiplies x^j). Trailing known
    /// zeros are dropped. Refused (the parameter is `coefficients`): c_0 not a known zero
    /// (g(0) = 0), no term of degree >= 2 that is not a known zero (a flat or tilted punch has
    /// no bounded contact), a known reference coefficient c_r of odd degree or <= 0 (the profile
    /// must be convex at its vertex), a degree above [`MAX_DEGREE`].
    pub fn new(coefficients: Vec<Option<Exact>>) -> Result<PolynomialProfile, ModelError> {
        let mut c = coefficients;
        let shown = |c: &[Option<Exact>]| {
            let parts: Vec<String> = c.iter().map(|x| x.as_ref().map_or("?".to_string(), readable)).collect();
            format!("[{}]", parts.join(", "))
        };
        while c.len() > 1 && c.last().is_some_and(|x| x.as_ref().is_some_and(Zero::is_zero)) {
            c.pop();
        }
        if !c.first().is_some_and(|x| x.as_ref().is_some_and(Zero::is_zero)) {
            return Err(ModelError::new(
                "coefficients",
                shown(&c),
                "c_0 must be 0 (g(0) = 0): index j is the coefficient of x^j",
            ));
        }
        if c.len() > MAX_DEGREE + 1 {
            return Err(ModelError::new("coefficients", shown(&c), format!("the degree must be at most {MAX_DEGREE}")));
        }
        let Some(reference) = (2..c.len()).find(|&j| !c[j].as_ref().is_some_and(Zero::is_zero)) else {
            return Err(ModelError::new(
                "coefficients",
                shown(&c),
                "needs a non-zero term of degree >= 2 (a flat or tilted punch has no bounded contact)",
            ));
        };
        if let Some(v) = &c[reference]
            && (reference % 2 == 1 || !v.is_positive())
        {
            return Err(ModelError::new(
                    "coefficients",
                    shown(&c),
                    format!(
                        "the lowest term of degree >= 2 (here x^{reference}) must have even degree and a positive coefficient (convex at the vertex)"
                    ),
                ));
        }
        Ok(PolynomialProfile { coefficients: c, reference })
    }

    /// The general polynomial of degree `degree` (2..=[`MAX_DEGREE`]) with every coefficient
    /// symbolic except c_0 = 0.
    pub fn symbolic(degree: usize) -> Result<PolynomialProfile, ModelError> {
        if !(2..=MAX_DEGREE).contains(&degree) {
            return Err(ModelError::new("--degree", degree, format!("must be an integer in [2, {MAX_DEGREE}]")));
        }
        let mut c = vec![None; degree + 1];
        c[0] = Some(<Exact as Zero>::zero());
        PolynomialProfile::new(c)
    }

    /// The coefficients (index j multiplies x^j; `None` = symbolic).
    pub fn coefficients(&self) -> &[Option<Exact>] {
        &self.coefficients
    }

    /// The degree D.
    pub fn degree(&self) -> usize {
        self.coefficients.len() - 1
    }

    /// The reference degree r (module doc).
    pub(crate) fn reference_degree(&self) -> usize {
        self.reference
    }

    /// Whether every odd coefficient is a known zero (g even: Problem 2 applies, and the
    /// frictionless Problem 1 is symmetric).
    pub(crate) fn is_even(&self) -> bool {
        self.coefficients.iter().skip(1).step_by(2).all(|c| c.as_ref().is_some_and(Zero::is_zero))
    }

    /// rho_j for j = 0..=D as exact polynomials (module doc): `rho[r] = 1`, `rho[0] = 0`.
    pub fn ratios(&self) -> Result<Vec<Poly>, SeriesError> {
        self.ratios_in(LS, "rho")
    }

    /// Ratios c_j/c_r times `length`^(j - r) for j = 0..=D (1 at r, 0 for a known zero), the
    /// symbol `{name}_j` where c_j or c_r is symbolic.
    fn ratios_in(&self, length: &str, name: &str) -> Result<Vec<Poly>, SeriesError> {
        let r = self.reference;
        let cr = self.coefficients[r].clone();
        let len = Symbol::new(length)?;
        self.coefficients
            .iter()
            .enumerate()
            .map(|(j, c)| {
                Ok(match (j, c, &cr) {
                    (_, Some(v), _) if Zero::is_zero(v) => Poly::zero(),
                    (j, _, _) if j == r => Poly::one(),
                    (j, Some(v), Some(cr)) if j > r => Poly::term(&(v / cr), Monomial::power(len, (j - r) as u32)),
                    (j, _, _) => Poly::symbol(Symbol::new(&format!("{name}_{j}"))?),
                })
            })
            .collect()
    }

    /// Problem 2's ratios sigma_j = (c_j/c_r) (L/pi)^(j-r) for j = 0..=D (`sigma[r] = 1`): the
    /// Volterra right side (docs/theory.md section 9) over E* c_r (L/pi)^(r-1) is
    /// (pi/2) sum_j j sigma_j chi^(j-1), chi = pi x/L. Problem 2 varies a at a fixed period, so
    /// the natural constants are period-based. A known c_j with a known c_r enters as
    /// (c_j/c_r) L_pi^(j-r) in the symbol `L_pi` = L/pi; otherwise `sigma_j` is a symbol.
    pub fn period_ratios(&self) -> Result<Vec<Poly>, SeriesError> {
        self.ratios_in(LPI, "sigma")
    }

    /// What each sigma_j stands for (Problem 2), for printed headers.
    pub(crate) fn period_ratio_definitions(&self) -> Vec<String> {
        let r = self.reference;
        self.coefficients
            .iter()
            .enumerate()
            .skip(1)
            .filter(|(j, c)| *j != r && !c.as_ref().is_some_and(Zero::is_zero))
            .map(|(j, _)| format!("sigma_{j} = (c_{j}/c_{r}) (L/pi)^{}", j as i64 - r as i64))
            .collect()
    }

    /// What each rho_j stands for, for printed headers: `rho_4 = c_4 l_s^2/c_2`, ...
    pub(crate) fn ratio_definitions(&self) -> Vec<String> {
        let r = self.reference;
        let mut out = Vec::new();
        for (j, c) in self.coefficients.iter().enumerate().skip(1) {
            if j == r || c.as_ref().is_some_and(Zero::is_zero) {
                continue;
            }
            let e = j as i64 - r as i64;
            let pow = match e {
                1 => " l_s".to_string(),
                0 => String::new(),
                e => format!(" l_s^({e})"),
            };
            out.push(format!("rho_{j} = c_{j}{pow}/c_{r}"));
        }
        out
    }
}

/// The profile's coefficient list as text, `[0, 0, 1, 0, 1/10]` (`?` for a symbol).
pub(crate) fn coefficients_text(p: &PolynomialProfile) -> String {
    let parts: Vec<String> =
        p.coefficients.iter().map(|x| x.as_ref().map_or("?".to_string(), exact_series::q_text)).collect();
    format!("[{}]", parts.join(", "))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Option<Exact> {
        Some(Exact::new(n.into(), d.into()))
    }

    #[test]
    fn quartic_ratios_are_exact_in_l_s() {
        let p = PolynomialProfile::new(vec![q(0, 1), q(0, 1), q(1, 1), q(0, 1), q(1, 10)]).unwrap();
        let rho = p.ratios().unwrap();
        assert_eq!(p.reference_degree(), 2);
        assert!(rho[2].is_one() && rho[1].is_zero() && rho[3].is_zero());
        assert_eq!(rho[4].text(), "1/10*l_s^2");
        assert!(p.is_even());
    }

    #[test]
    fn pure_quartic_is_its_own_reference() {
        let p = PolynomialProfile::new(vec![q(0, 1), q(0, 1), q(0, 1), q(0, 1), q(3, 1)]).unwrap();
        assert_eq!(p.reference_degree(), 4);
        assert!(p.ratios().unwrap()[4].is_one());
    }

    #[test]
    fn bad_profiles_are_refused_naming_the_parameter() {
        for c in [
            vec![q(1, 1), q(0, 1), q(1, 1)],
            vec![q(0, 1), q(1, 1)],
            vec![q(0, 1), q(0, 1), q(-1, 1)],
            vec![q(0, 1), q(0, 1), q(0, 1), q(1, 1)],
        ] {
            let e = PolynomialProfile::new(c).unwrap_err();
            assert_eq!(e.parameter, "coefficients", "{e}");
        }
        assert_eq!(PolynomialProfile::symbolic(1).unwrap_err().parameter, "--degree");
        assert_eq!(PolynomialProfile::symbolic(40).unwrap_err().parameter, "--degree");
    }

    #[test]
    fn symbolic_cubic_has_symbols_for_the_tilt_and_the_cubic_term() {
        let p = PolynomialProfile::symbolic(3).unwrap();
        let rho = p.ratios().unwrap();
        assert_eq!(rho[1].text(), "rho_1");
        assert!(rho[2].is_one());
        assert_eq!(rho[3].text(), "rho_3");
        assert_eq!(p.ratio_definitions(), vec!["rho_1 = c_1 l_s^(-1)/c_2", "rho_3 = c_3 l_s/c_2"]);
    }
}
