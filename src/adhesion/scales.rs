//! The scales of the outputs of Problem 2 and the digits relative to them: the one table both
//! methods (and the renderers) use, under the accuracy rule of [`crate::numerics::accuracy`].
//!
//! Scalings (docs/theory.md section 4; exact inputs rounded once): P2 = E* k a^2 P2~, psi = k a psi~,
//! phi = k a^2 phi~, q1, q2 = E* k a q~, where the dimensionless ~ quantities depend on nu and
//! lambda = pi a/L only. The accuracy of each output is stated relative to its scale:
//!
//! | output | scale |
//! | --- | --- |
//! | P2 (given a) | P2 |
//! | a (given P2) | a |
//! | lambda | lambda (a relative accuracy, as the size) |
//! | psi | k a |
//! | phi | k a^2 |
//! | q1, q2 | E* k a |

use crate::model::OnPunchRow;
use crate::model::{AdhesionProblem, AdhesionSize};
use crate::numerics::exact::{to_f64, to_float};
use rug::Float;

/// The scales of the outputs in MPFR (module doc).
#[derive(Debug, Clone)]
pub struct ScalesMpfr {
    /// P2, the scale of the load.
    pub load: Float,
    /// a, the scale of the half-width.
    pub half_width: Float,
    /// k a, the scale of psi.
    pub psi: Float,
    /// k a^2, the scale of phi.
    pub phi: Float,
    /// E* k a, the scale of q1 and q2.
    pub stress: Float,
}

impl ScalesMpfr {
    /// The scales of `problem` at the computed half-width and load, at `prec` bits.
    pub fn new(problem: &AdhesionProblem, half_width: &Float, normal_load: &Float, prec: u32) -> Self {
        let k = to_float(problem.curvature(), prec);
        let e_star = to_float(problem.material().contact_modulus(), prec);
        let psi = Float::with_val(prec, &k * half_width);
        let phi = Float::with_val(prec, &psi * half_width);
        let stress = Float::with_val(prec, &psi * &e_star);
        ScalesMpfr {
            load: Float::with_val(prec, normal_load),
            half_width: Float::with_val(prec, half_width),
            psi,
            phi,
            stress,
        }
    }

    /// The scale of the computed size: P2 when a is given, a when P2 is given.
    pub fn size(&self, given: &AdhesionSize) -> &Float {
        match given {
            AdhesionSize::HalfWidth(_) => &self.load,
            AdhesionSize::NormalLoad(_) => &self.half_width,
        }
    }

    /// The scales of (psi, phi, q1, q2), in the order of [`Digits::from_points`].
    pub(crate) fn point_scales(&self) -> [&Float; 4] {
        [&self.psi, &self.phi, &self.stress, &self.stress]
    }
}

/// The scales of the outputs in `f64` (module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScalesF64 {
    /// P2.
    pub load: f64,
    /// a.
    pub half_width: f64,
    /// k a.
    pub psi: f64,
    /// k a^2.
    pub phi: f64,
    /// E* k a.
    pub stress: f64,
}

impl ScalesF64 {
    /// The scales of `problem` at the computed half-width and load (k, E* rounded once; `NaN`
    /// when they do not fit in `f64`, which verifies nothing).
    pub fn new(problem: &AdhesionProblem, half_width: f64, normal_load: f64) -> Self {
        let k = to_f64(problem.curvature()).unwrap_or(f64::NAN);
        let e_star = to_f64(problem.material().contact_modulus()).unwrap_or(f64::NAN);
        let psi = k * half_width;
        ScalesF64 { load: normal_load, half_width, psi, phi: psi * half_width, stress: psi * e_star }
    }

    /// The scale of the computed size: P2 when a is given, a when P2 is given.
    pub fn size(&self, given: &AdhesionSize) -> f64 {
        match given {
            AdhesionSize::HalfWidth(_) => self.load,
            AdhesionSize::NormalLoad(_) => self.half_width,
        }
    }

    /// The scales of (psi, phi, q1, q2), in the order of [`Digits::from_points`].
    pub(crate) fn point_scales(&self) -> [f64; 4] {
        [self.psi, self.phi, self.stress, self.stress]
    }
}

/// Digits per output relative to its scale (verified by a second MPFR run, or estimated by a
/// second f64 run), the minimum over the requested points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Digits {
    /// P2 (given a) or a (given P2).
    pub size: f64,
    /// psi, scale k a.
    pub psi: f64,
    /// phi, scale k a^2.
    pub phi: f64,
    /// q1, scale E* k a.
    pub q1: f64,
    /// q2, scale E* k a.
    pub q2: f64,
    /// The minimum of the above.
    pub headline: f64,
}

impl Digits {
    /// From the digits of the size and of (psi, phi, q1, q2) at each point; a quantity without
    /// points gets `cap` (nothing to lose).
    pub fn from_points(size: f64, points: impl IntoIterator<Item = [f64; 4]>, cap: f64) -> Self {
        let mut q = [cap; 4];
        for p in points {
            for (m, d) in q.iter_mut().zip(p) {
                *m = m.min(d);
            }
        }
        let [psi, phi, q1, q2] = q;
        Digits { size, psi, phi, q1, q2, headline: size.min(psi).min(phi).min(q1).min(q2) }
    }

    /// Every entry at most `cap` (e.g. the digits a homogeneous mode leaves,
    /// [`crate::asymptotics::adhesion_mode::digits_kept`]).
    pub fn at_most(&self, cap: f64) -> Self {
        let m = |d: f64| d.min(cap);
        Digits {
            size: m(self.size),
            psi: m(self.psi),
            phi: m(self.phi),
            q1: m(self.q1),
            q2: m(self.q2),
            headline: m(self.headline),
        }
    }
}
