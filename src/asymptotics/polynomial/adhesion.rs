//! Problem 2 for an even polynomial punch g = sum_m c_(2m) x^(2m) (docs/theory.md section 9): the
//! recurrence of [`crate::asymptotics::adhesion`] with the general right side, exact in
//! (eps, B, S) and the profile's ratios.
//!
//! # Equations \[reconstructed\]
//! docs/theory.md section 9: int_0^chi Re K(chi, eta) dP2/d eta d eta = (E* L/2) g'(L chi/pi). With
//! P2 = E* c_r (L/pi)^r P(lambda) and sigma_j = (c_j/c_r) (L/pi)^(j-r)
//! ([`PolynomialProfile::period_ratios`]) the right side over E* c_r (L/pi)^r is
//! pi sum_m m sigma_(2m) chi^(2m-1), so with the ansatz P'(eta) = pi sum_j p_j eta^(2j+1) the
//! parabola's recurrence holds with Re I_N = (N+1) sigma_(2N+2) in place of [N = 0]:
//!
//!   p_N Re M_(2N+1) = (N+1) sigma_(2N+2) - Re sum_{n=1}^{N} p_(N-n) T_(n,N-n),
//!
//! (for g = k x^2: sigma_2 = 1, the parabola's recurrence exactly). The load is
//! P(lambda)/pi = sum_j p_j lambda^(2j+2)/(2j+2), and the slope is unchanged in form:
//! psi(x) = -(2/(E* L)) Im int K dP2 = c_r (L/pi)^(r-1) sum_J psi_J chi^(2J+1),
//! psi_J = -2 Im sum_j p_j T_(J-j,j), so A_(2J+1) = c_r (pi/L)^(2J+2-r) psi_J and the
//! coefficient of chi^n is A_n/(c_r (pi/L)^(n+1-r)). The problem is linear in g: every p_j,
//! psi_J is linear in the sigma_j.

use super::profile::{coefficients_text, PolynomialProfile};
use crate::asymptotics::adhesion::volterra_solution;
use exact_series::{Frac, Poly, Ring, Series, SeriesError, Q};

/// The exact Problem 2 expansion for an even polynomial profile through lambda^order.
#[derive(Debug, Clone)]
pub struct PolynomialAdhesionExpansion {
    /// The profile.
    pub profile: PolynomialProfile,
    /// p_j (`P'(eta) = pi sum_j p_j eta^(2j+1)`), j = 0..=order/2.
    pub volterra: Vec<Frac>,
    /// `P(lambda)/pi = sum_j p_j lambda^(2j+2)/(2j+2)`, `P2 = E* c_r (L/pi)^r P(lambda)`,
    /// through lambda^(2 (order/2) + 2).
    pub load: Series<Frac>,
    /// `psi(x)/(c_r (L/pi)^(r-1)) = sum_J psi_J chi^(2J+1)` through chi^(order+1): the
    /// coefficient of chi^n is `A_n/(c_r (pi/L)^(n+1-r))`.
    pub slope: Series<Frac>,
}

/// Derives Problem 2's expansion for an even polynomial profile (module doc). An odd
/// coefficient that is not a known zero is refused (Problem 2 is posed for even profiles).
///
/// ```
/// use exact_series::{Q, Ring};
/// use periodic_contact::asymptotics::polynomial::{polynomial_adhesion_expansion, PolynomialProfile};
/// let c = |n: i64| Some(Q::from_integer(n.into()));
/// let e = polynomial_adhesion_expansion(&PolynomialProfile::new(vec![c(0), c(0), c(1)]).unwrap(), 2).unwrap();
/// // P/pi = p_0 lambda^2/2 + ...: C_P/pi = p_0/2 = 1/(2 (1 - 2 eps S)).
/// assert_eq!(e.load.coeff(2).unwrap().text(), "(-1/4)/(S*eps - 1/2)");
/// ```
pub fn polynomial_adhesion_expansion(
    profile: &PolynomialProfile,
    order: usize,
) -> Result<PolynomialAdhesionExpansion, SeriesError> {
    if !profile.is_even() {
        return Err(SeriesError::NotInvertible {
            operation: "Problem 2 needs an even profile (every odd coefficient 0)",
            value: coefficients_text(profile),
        });
    }
    let sigma = profile.period_ratios()?;
    let jmax = order / 2;
    let rhs: Vec<Poly> =
        (0..=jmax).map(|n| sigma.get(2 * n + 2).map_or_else(Poly::zero, |s| s.mul_int(n as i64 + 1))).collect();
    let v = volterra_solution(order, &rhs)?;
    let volterra = v.volterra();
    let mut load = vec![Frac::zero(); 2 * jmax + 3];
    for (j, pj) in volterra.iter().enumerate() {
        load[2 * j + 2] = pj.scale(&Q::new(1.into(), (2 * j as i64 + 2).into()));
    }
    Ok(PolynomialAdhesionExpansion {
        profile: profile.clone(),
        volterra,
        load: Series::from_coeffs(load),
        slope: v.slope(order),
    })
}
