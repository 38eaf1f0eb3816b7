//! The setting of a loading-law solve and its increment at one precision (docs/theory.md section
//! 10): the exact inputs ([`LawSetting`]), the material and law constants every increment needs
//! ([`Increment`]), and the Chebyshev helpers that both the collocation residual
//! ([`super::collocation`]) and its closed-form Jacobian (`jacobian.rs`) use: t Phi(t), the
//! divided difference of a Chebyshev series, the advance factor 1 +- E of an end. Tested through
//! the collocation (`closed_form_jacobian_equals_finite_differences`, the n = 0 and nu = 1/2
//! reductions).

use crate::growing_contact::error::AdhesionError;
use crate::growing_contact::kernel::{Row, SizeFactors, TiltedPunch};
use crate::model::{Convention, Exact, LoadingLaw, Material};
use crate::numerics::chebyshev;
use crate::numerics::exact::to_float;
use crate::numerics::tanh_sinh::TanhSinh;
use crate::params::adhesion::AdhesionParamsMpfr;
use rug::float::Constant;
use rug::{Complex, Float};

/// What the collocation needs besides the unknowns: exact inputs, rounded once per precision.
#[derive(Debug, Clone)]
pub struct LawSetting {
    /// The half-plane's material (eps and C_P are derived at each precision).
    pub material: Material,
    /// The law P1 = N(P2).
    pub law: LoadingLaw,
    /// E* k L^2: P2 = (E* k L^2/pi^2) P (periodic); E* k U^2 for the single punch in the length
    /// unit U (P2 = E* k U^2 P, [`Row::Single`]).
    pub load_scale: Exact,
    /// l/L at the final size, exact (Lambda = pi l/L); l/U for the single punch (Lambda = l/U).
    pub size_over_period: Exact,
    /// Periodic row or single punch ([`Row`]).
    pub row: Row,
    /// The surface convention (docs/theory.md section 8): `periodic` adds the tilted punch's increment
    /// ([`crate::growing_contact::kernel::TiltedPunch`]).
    pub convention: Convention,
}

impl LawSetting {
    /// The linear law n with E* k L^2 = 1 (tests and the dimensionless problem).
    pub fn linear(material: Material, n: Exact, size_over_period: Exact, convention: Convention) -> Self {
        LawSetting {
            material,
            law: LoadingLaw::Linear(n),
            load_scale: Exact::from_integer(1.into()),
            size_over_period,
            row: Row::Periodic,
            convention,
        }
    }

    /// Lambda at `prec` bits: pi l/L, or l/U for the single punch.
    pub fn lambda_max(&self, prec: u32) -> Float {
        match self.row {
            Row::Periodic => to_float(&self.size_over_period, prec) * Float::with_val(prec, Constant::Pi),
            Row::Single => to_float(&self.size_over_period, prec),
        }
    }
}

/// The material and law constants every increment needs, at one precision.
#[derive(Debug, Clone)]
pub struct Increment {
    /// eps.
    pub eps: Float,
    /// cosh(pi eps).
    pub cosh_pi_eps: Float,
    /// beta.
    pub beta: Float,
    /// N'(P2) coefficients (numpy order, in powers of P2).
    pub slope: Vec<Float>,
    /// N(P2) coefficients.
    pub law: Vec<Float>,
    /// E* k L^2/pi^2 (P2 per unit P).
    pub p2_per_p: Float,
    /// Whether the `periodic` convention's rotation increment is added (never for the single
    /// punch: the rotation -beta P1/L vanishes as L -> infinity).
    pub periodic: bool,
    /// Periodic row or single punch.
    pub row: Row,
}

impl Increment {
    /// From the setting at `prec` bits.
    pub fn new(setting: &LawSetting, prec: u32) -> Self {
        let constants = AdhesionParamsMpfr::new(&setting.material, prec);
        let pi2 = match setting.row {
            Row::Periodic => Float::with_val(prec, Constant::Pi).square(),
            Row::Single => Float::with_val(prec, 1),
        };
        let law = match &setting.law {
            LoadingLaw::Linear(n) => vec![Exact::from_integer(0.into()), n.clone()],
            LoadingLaw::Polynomial(c) => c.clone(),
        };
        Increment {
            eps: constants.eps,
            cosh_pi_eps: constants.cosh_pi_eps,
            beta: constants.beta,
            slope: setting.law.derivative().iter().map(|c| to_float(c, prec)).collect(),
            law: law.iter().map(|c| to_float(c, prec)).collect(),
            p2_per_p: to_float(&setting.load_scale, prec) / pi2,
            periodic: setting.convention == Convention::PeriodicSurface && setting.row == Row::Periodic,
            row: setting.row,
        }
    }
    /// Whether n = N' is constant along the loading (linear law).
    pub(crate) fn constant_ratio(&self) -> bool {
        self.slope.len() <= 1
    }
    /// n = N'(P2) at P2 = p2_per_p `p`.
    pub(crate) fn ratio_at(&self, p: &Float) -> Float {
        let prec = p.prec();
        let p2 = Float::with_val(prec, p * &self.p2_per_p);
        self.slope.iter().rev().fold(Float::with_val(prec, 0), |acc, c| acc * &p2 + c)
    }
    /// N(P2) at P2 = p2_per_p `p`, in units of p2_per_p (i.e. P1/p2_per_p).
    pub(crate) fn law_at(&self, p: &Float) -> Float {
        let prec = p.prec();
        let p2 = Float::with_val(prec, p * &self.p2_per_p);
        self.law.iter().rev().fold(Float::with_val(prec, 0), |acc, c| acc * &p2 + c) / &self.p2_per_p
    }
}

/// The factors of one increment's kernels that depend on its size eta alone: the kernel's
/// ([`SizeFactors`]) and, in the `periodic` convention, the tilted punch
/// ([`TiltedPunch::rotation_at`]), for both ends.
#[derive(Debug, Clone)]
pub struct SizeTerms {
    /// sin, cos, sinh, cosh of eta's multiples.
    pub size: SizeFactors,
    /// The tilted punch of the `periodic` convention.
    pub tilt: Option<TiltedPunch>,
}

impl SizeTerms {
    /// At eta, `prec` bits.
    pub fn new(inc: &Increment, eta: &Float, prec: u32) -> Self {
        let size = SizeFactors::new(inc.row, eta, &inc.eps, prec);
        let tilt = inc.periodic.then(|| TiltedPunch::rotation_at(&size, &inc.cosh_pi_eps));
        SizeTerms { size, tilt }
    }
}

/// [`SizeTerms`] at eta = (Lambda t_i) s_q for every collocation node t_i and rule point s_q,
/// rounded as the edge integrals round them: these sizes do not change between the iterations of
/// a solve (only the distances to the ends do), so the residuals and Jacobians of one
/// discretisation share them (nodes on every CPU).
pub(crate) fn size_terms(
    inc: &Increment,
    lambda_max: &Float,
    nodes: &[Float],
    rule: &TanhSinh,
    prec: u32,
) -> Vec<Vec<SizeTerms>> {
    crate::numerics::parallel::map(nodes, |_, t| {
        let lambda = Float::with_val(prec, lambda_max * t);
        rule.s.iter().map(|s| SizeTerms::new(inc, &Float::with_val(prec, &lambda * s), prec)).collect()
    })
}

/// Chebyshev coefficients of t Phi(t) (t = (x + 1)/2, x T_j = (T_(j+1) + T_|j-1|)/2) from those
/// of Phi: P(Lambda t) = Lambda^2 int_0^t t' Phi(t') dt'.
pub(super) fn times_t(phi: &[Float], prec: u32) -> Vec<Float> {
    let n = phi.len();
    let mut x_phi = vec![Float::with_val(prec, 0); n + 1];
    for (j, c) in phi.iter().enumerate() {
        if j == 0 {
            x_phi[1] += c;
        } else {
            let h = Float::with_val(prec, c / 2u32);
            x_phi[j + 1] += &h;
            x_phi[j - 1] += &h;
        }
    }
    for (j, c) in phi.iter().enumerate() {
        x_phi[j] += c;
    }
    x_phi.into_iter().map(|v| v / 2u32).collect()
}

/// sum_j c_j [T_j(x) - T_j(y)]/(x - y), accurate as y -> x (the derivative at y = x): the
/// Chebyshev series in y of [`divided_difference_series`] at x, summed at y.
pub(super) fn divided_difference(c: &[Float], x: &Float, y: &Float, prec: u32) -> Float {
    chebyshev::evaluate(&divided_difference_series(c, x, prec), y, prec)
}

/// The Chebyshev coefficients a_j in y of [p(x) - p(y)]/(x - y), p = sum_j c_j T_j, for one x
/// (one Clenshaw pass; each y is then one Clenshaw sum, where the three-term recurrence of the
/// divided differences of T_j took seven operations per term at every y). With Clenshaw's
/// b_k = c_k + 2 x b_(k+1) - b_(k+2) at x, c_k = b_k - 2 x b_(k+1) + b_(k+2) and the
/// recurrence of T_k at y give p(y) = b_0 + b_1 (y - 2 x) + 2 (y - x) sum_(k>=2) b_k T_(k-1)(y)
/// and p(x) = b_0 - x b_1, so
///   [p(x) - p(y)]/(x - y) = b_1 + 2 sum_(k>=2) b_k T_(k-1)(y):  a_0 = b_1, a_j = 2 b_(j+1).
/// No difference of nearby values is formed, so the accuracy holds as y -> x (checked against
/// the derivative and the plain quotient in the tests).
pub(super) fn divided_difference_series(c: &[Float], x: &Float, prec: u32) -> Vec<Float> {
    let n = c.len();
    if n < 2 {
        return vec![Float::with_val(prec, 0)];
    }
    // b_k for k = n - 1 down to 1.
    let mut b = vec![Float::with_val(prec, 0); n + 1];
    let two_x = Float::with_val(prec, x * 2u32);
    for k in (1..n).rev() {
        let next = Float::with_val(prec, &two_x * &b[k + 1]) - &b[(k + 2).min(n)];
        b[k] = next + &c[k];
    }
    (0..n - 1).map(|j| if j == 0 { b[1].clone() } else { Float::with_val(prec, &b[j + 1] * 2u32) }).collect()
}

/// 1 +- E, the rate at which the leading (`sign` = 1) or trailing (-1) end advances relative to
/// the half-length; an error when it does not (the contact must grow at both ends).
pub(super) fn advance_factor(e: &Float, sign: i32, lambda: &Float) -> Result<Float, AdhesionError> {
    let factor = Float::with_val(e.prec(), e * sign) + 1u32;
    if factor > 0 {
        return Ok(factor);
    }
    Err(AdhesionError::NotConverged {
        what: "loading-law collocation",
        reason: format!(
            "the {} end recedes at lambda = {:.4} (the contact must grow at both ends)",
            if sign > 0 { "leading" } else { "trailing" },
            lambda.to_f64()
        ),
    })
}

/// The multiple i beta (1 + i n) = -beta n + i beta of the tilted punch in an increment of unit dP2
/// (docs/theory.md section 8, Problem 2: (H + i beta) d sigma = i beta dP/L on the contact in the
/// `periodic` convention, dP = (1 + i n) dP2).
pub(super) fn periodic_factor(beta: &Float, n: &Float, prec: u32) -> Complex {
    Complex::with_val(prec, (-Float::with_val(prec, beta * n), beta))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`divided_difference_series`] summed at y equals the plain quotient [p(x) - p(y)]/(x - y)
    /// at separated points (to 1e-60 at 256 bits) and the derivative (central difference, step
    /// 1e-20: 1e-35) at y = x, for a series of 12 terms; a constant has zero divided difference.
    #[test]
    fn divided_difference_series_equals_quotient_and_derivative() {
        let prec = 256;
        let c: Vec<Float> =
            (0..12).map(|j| Float::with_val(prec, 1.0 / (1.0 + j as f64)) * if j % 3 == 1 { -1 } else { 1 }).collect();
        let p = |x: &Float| chebyshev::evaluate(&c, x, prec);
        let f = |v: f64| Float::with_val(prec, v);
        for (x, y) in [(0.3, -0.7), (-0.95, 0.9), (0.5, 0.5 + 1e-12)] {
            let (x, y) = (f(x), f(y));
            let quotient = Float::with_val(prec, p(&x) - p(&y)) / Float::with_val(prec, &x - &y);
            let got = divided_difference(&c, &x, &y, prec);
            let e = Float::with_val(prec, &got - &quotient).abs().to_f64();
            // The quotient itself loses digits to cancellation at y - x = 1e-12.
            assert!(e < 1e-60, "{x} {y}: {got} vs {quotient}: {e:e}");
        }
        let (x, h) = (f(-0.4), Float::with_val(prec, 1e-20));
        let central = Float::with_val(prec, p(&Float::with_val(prec, &x + &h)) - p(&Float::with_val(prec, &x - &h)))
            / Float::with_val(prec, &h * 2u32);
        let e = Float::with_val(prec, divided_difference(&c, &x, &x, prec) - &central).abs().to_f64();
        assert!(e < 1e-35, "derivative: {e:e}");
        let constant = divided_difference_series(&c[..1], &x, prec);
        assert!(chebyshev::evaluate(&constant, &f(0.2), prec).is_zero());
    }
}
