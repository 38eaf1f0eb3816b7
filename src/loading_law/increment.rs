//! The setting of a loading-law solve and its increment at one precision (docs/theory.md section
//! 10): the exact inputs ([`LawSetting`]), the material and law constants every increment needs
//! ([`Increment`]), and the Chebyshev helpers that both the collocation residual
//! ([`super::collocation`]) and its closed-form Jacobian (`jacobian.rs`) use: t Phi(t), the
//! divided difference of a Chebyshev series, the advance factor 1 +- E of an end. Tested through
//! the collocation (`closed_form_jacobian_equals_finite_differences`, the n = 0 and nu = 1/2
//! reductions).

use crate::growing_contact::error::AdhesionError;
use crate::growing_contact::kernel::Row;
use crate::model::{Convention, Exact, LoadingLaw, Material};
use crate::numerics::exact::to_float;
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

/// sum_j c_j [T_j(x) - T_j(y)]/(x - y) by the recurrence d_(j+1) = 2 x d_j + 2 T_j(y) - d_(j-1)
/// (d_0 = 0, d_1 = 1): accurate as y -> x.
pub(super) fn divided_difference(c: &[Float], x: &Float, y: &Float, prec: u32) -> Float {
    let mut acc = Float::with_val(prec, 0);
    let (mut d_prev, mut d) = (Float::with_val(prec, 0), Float::with_val(prec, 1));
    let (mut t_prev, mut t) = (Float::with_val(prec, 1), y.clone());
    for cj in c.iter().skip(1) {
        acc += Float::with_val(prec, cj * &d);
        // d_(j+1) and T_(j+1)(y).
        let d_next = Float::with_val(prec, x * &d) * 2u32 + Float::with_val(prec, &t * 2u32) - &d_prev;
        let t_next = Float::with_val(prec, y * &t) * 2u32 - &t_prev;
        d_prev = std::mem::replace(&mut d, d_next);
        t_prev = std::mem::replace(&mut t, t_next);
    }
    acc
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
