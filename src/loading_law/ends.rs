//! The stresses at the ends of the final contact and the friction complete adhesion needs
//! (issue 12: "the friction coefficient the solution needs, max |q1|/q2 near the ends").
//!
//! Near the leading end (distance d to b) the increments received since x entered add up to
//!   sigma = q2 + i q1 ~ C_b (d/l)^(1/2 - i eps),   near the trailing end C_a (d/l)^(1/2 + i eps)
//! (docs/theory.md 4's end behaviour), so arg sigma = phi_b - eps ln(d/l) (leading) and
//! phi_a + eps ln(d/l) (trailing) rotate without bound as d -> 0: the needed friction
//! |q1|/q2 = |tan arg sigma| has no finite maximum near an end when eps != 0, and q2 changes sign
//! (tension) within
//!   d/l = exp(-(pi/2 - phi_b)/eps)  (leading),   d/l = exp(-(pi/2 + phi_a)/eps)  (trailing),
//! the oscillating-singularity zones of the complete-adhesion solution. So the friction needed is
//! a function of how close to the ends one asks; this module gives it at fixed distances (none
//! inside the tension zone) and the end phases phi_b, phi_a from sigma at d/l = 1e-11, with the
//! change from d/l = 1e-9 as their error (the correction to the asymptote is O(d)).
//! In the paper convention, from sigma_flat's end factor and int_0^d D^(-1/2 -+ i eps) dD:
//!   phi_b = arctan n + arg cos(Lambda (1 - 2 i eps)) + eps ln(sin(2 Lambda)/Lambda) + arctan(2 eps),
//!   phi_a = arctan n - arg cos(Lambda (1 - 2 i eps)) - eps ln(sin(2 Lambda)/Lambda) - arctan(2 eps),
//! (single punch: cos -> 1, sin(2 Lambda)/Lambda -> 2), n = N'(P2) at the final load: checked
//! against the computed phases in the tests.

use super::collocation::LawCollocation;
use crate::growing_contact::kernel::Side;
use crate::numerics::tanh_sinh::TanhSinh;
use rug::float::Constant;
use rug::ops::Pow;
use rug::{Complex, Float};

/// Distances d/l = 10^k from an end at which the needed friction is given.
pub const DISTANCES: [i32; 4] = [-1, -2, -3, -4];

/// One end of the final contact.
#[derive(Debug, Clone)]
pub struct EndStress {
    /// phi_b or phi_a (module doc).
    pub phase: Float,
    /// |phase at d/l = 1e-9 - phase at 1e-11|: the asymptote's error.
    pub phase_error: Float,
    /// d/l within which q2 < 0 (0 when eps = 0).
    pub tension_within: Float,
    /// |q1|/q2 at d/l = 10^DISTANCES\[k\] (the full solution, not the asymptote); None where q2 <= 0.
    pub friction_needed: Vec<Option<Float>>,
}

impl LawCollocation {
    /// sigma_hat at distance `rel` l from the end on `side` (Right: leading end b), inside.
    pub(crate) fn sigma_near_end(&self, side: Side, rel: &Float, rule: &TanhSinh) -> Complex {
        let p = self.prec;
        let lambda = &self.lambda_max;
        let gamma = self.centre_at(lambda);
        let d = Float::with_val(p, rel * lambda);
        let chi = match side {
            Side::Right => Float::with_val(p, &gamma + lambda) - d,
            Side::Left => Float::with_val(p, &gamma - lambda) + d,
        };
        self.sigma_hat(&chi, rule)
    }

    /// phi_b or phi_a (module doc) from sigma at d/l = 10^`power`.
    fn end_phase(&self, side: Side, power: i32, rule: &TanhSinh) -> Float {
        let p = self.prec;
        let tiny = Float::with_val(p, Float::with_val(p, 10).pow(power));
        let sigma = self.sigma_near_end(side, &tiny, rule);
        let arg = Float::with_val(p, sigma.arg_ref());
        let log = Float::with_val(p, tiny.ln_ref()) * &self.inc.eps;
        match side {
            Side::Right => arg + log,
            Side::Left => arg - log,
        }
    }

    /// The end on `side` (module doc).
    pub fn end_stress(&self, side: Side, rule: &TanhSinh) -> EndStress {
        let p = self.prec;
        let eps = &self.inc.eps;
        let phase = self.end_phase(side, -11, rule);
        let phase_error = Float::with_val(p, self.end_phase(side, -9, rule) - &phase).abs();
        let half_pi = Float::with_val(p, Constant::Pi) / 2u32;
        let gap = match side {
            Side::Right => Float::with_val(p, &half_pi - &phase),
            Side::Left => Float::with_val(p, &half_pi + &phase),
        };
        let tension_within = if eps.is_zero() { Float::with_val(p, 0) } else { Float::with_val(p, -(gap / eps)).exp() };
        let friction_needed = DISTANCES
            .iter()
            .map(|k| {
                let rel = Float::with_val(p, Float::with_val(p, 10).pow(*k));
                let s = self.sigma_near_end(side, &rel, rule);
                (*s.real() > 0).then(|| Float::with_val(p, s.imag() / s.real()).abs())
            })
            .collect();
        EndStress { phase, phase_error, tension_within, friction_needed }
    }
}

#[cfg(test)]
mod tests {
    use super::super::collocation::{solve, LawSetting};
    use super::*;
    use crate::growing_contact::kernel::Row;
    use crate::model::{Convention, Exact, Material};

    /// The computed end phases equal the closed forms of the module doc (paper convention,
    /// nu = 0.3, n = 1/5; periodic Lambda = pi/6 and the single punch) to 1e-9 (measured 2e-10
    /// at d = 1e-9 l, the O(d) correction); the tension zone of the leading end is tiny but not
    /// zero (9.2e-6 l periodic, 6.1e-6 l single punch).
    #[test]
    fn end_phases_match_the_closed_form() {
        let prec = 128;
        let material =
            Material::from_contact_modulus(Exact::new(3.into(), 10.into()), Exact::from_integer(1.into())).unwrap();
        let n = Exact::new(1.into(), 5.into());
        let periodic =
            LawSetting::linear(material.clone(), n.clone(), Exact::new(1.into(), 6.into()), Convention::Paper);
        let mut single = LawSetting::linear(material, n, Exact::from_integer(1.into()), Convention::Paper);
        single.row = Row::Single;
        for setting in [periodic, single] {
            let sol = solve(&setting, 16, 80, prec).unwrap();
            let rule = TanhSinh::new(90, 1.0, prec);
            let (eps, lambda) = (sol.inc.eps.to_f64(), sol.lambda_max.to_f64());
            let (cos_arg, log) = match setting.row {
                Row::Periodic => {
                    let z = Complex::with_val(64, (lambda, -2.0 * eps * lambda)).cos();
                    (Float::with_val(64, z.arg_ref()).to_f64(), eps * ((2.0 * lambda).sin() / lambda).ln())
                }
                Row::Single => (0.0, eps * 2f64.ln()),
            };
            let base = 0.2f64.atan();
            let expect_b = base + cos_arg + log + (2.0 * eps).atan();
            let expect_a = base - cos_arg - log - (2.0 * eps).atan();
            let b = sol.end_stress(Side::Right, &rule);
            let a = sol.end_stress(Side::Left, &rule);
            eprintln!(
                "{:?}: phi_b {} ({expect_b}), phi_a {} ({expect_a}), tension within {:.3e} / {:.3e}, friction needed {:?} / {:?}",
                setting.row,
                b.phase.to_f64(),
                a.phase.to_f64(),
                b.tension_within.to_f64(),
                a.tension_within.to_f64(),
                b.friction_needed.iter().map(|v| v.as_ref().map(|v| v.to_f64())).collect::<Vec<_>>(),
                a.friction_needed.iter().map(|v| v.as_ref().map(|v| v.to_f64())).collect::<Vec<_>>()
            );
            assert!((b.phase.to_f64() - expect_b).abs() < 1e-9);
            assert!((a.phase.to_f64() - expect_a).abs() < 1e-9);
            assert!(b.phase_error.to_f64() < 1e-8 && b.phase_error.to_f64() > 1e-13, "{}", b.phase_error);
            assert!(b.tension_within.to_f64() > 0.0 && b.tension_within.to_f64() < 1e-3);
        }
    }
}
