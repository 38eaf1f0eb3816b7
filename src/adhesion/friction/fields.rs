//! The single punch's fields q1, q2, psi at points x/a and the checks of its inequalities
//! (docs/theory.md sections 17.3, 17.5, 17.6), `f64`.
//!
//! Fields, superposed from the unit increment s of [`super::increment_f64`] (a = 1, E* k = 1,
//! dP2 = 2 C_P a' da', self-similarity): with y = x/a',
//!     q(x, 1) = 2 C_P int_x^1 s(x/a') da' = 2 C_P x int_x^1 s(y) y^-2 dy          (q = q2 + i q1),
//!     psi/(k a) = u'/(k a) = 4 C_P x int_max(x, gamma)^inf T(y) y^-2 dy,
//!     T = -H\[s1\] - beta s2   ((E*/2) du' of the unit increment, docs/theory.md section 2),
//! T = 0 on the stick zone (the stuck points do not move), so psi = 2 C k x there (u' = 2 C k |x|,
//! (17.5)); psi is complete adhesion's psi (section 4: psi = phi', u = phi on the stick zone).
//! Both integrals are exact for the piecewise-constant s (the y^-2 moments of ln|y - w| in closed
//! form). The error of a field is the largest difference over the points of the solutions on n and
//! 2 n stick elements (each at its own gamma and C_P).
//!
//! Checks, from the independent current state of [`super::state_f64`] at each mesh's gamma (their
//! error: the difference of the two meshes):
//! - `stick_ratio`: max over the stick zone of |q1|/(mu q2) (Coulomb: <= 1, tight at the stick edge),
//!   the last stick element left out (the state's boundedness condition sets it to 1 there);
//! - `pressure_min`: min q2 / max q2 (>= 0: no tension);
//! - `outward_slip`: max over the slip zones of du/da (the slip rate relative to the punch, x > 0)
//!   over its largest magnitude (<= 0: every slip zone slips inward, against q1 = mu q2; a positive
//!   value would be a slip reversal).

use super::increment_f64::{increment, Increment};
use super::state_f64::{state, State};
use crate::growing_contact::error::AdhesionError;

/// q1, q2 (on the scale E* k a) and psi (on the scale k a) at one point (`f64` here; MPFR from
/// the spectral method, `spectral_punch_fields.rs`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointFields<T = f64> {
    /// q1/(E* k a), the shear traction on the body.
    pub q1: T,
    /// q2/(E* k a), the pressure.
    pub q2: T,
    /// psi/(k a) = u'/(k a).
    pub psi: T,
}

/// A check's value on the finer mesh and its difference from the coarser one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Check {
    /// The value (2 n stick elements).
    pub value: f64,
    /// |value(n) - value(2 n)|.
    pub error: f64,
}

/// The inequality checks of the module doc.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Checks {
    /// max over the stick zone of |q1|/(mu q2).
    pub stick_ratio: Check,
    /// min q2 / max q2.
    pub pressure_min: Check,
    /// max over the slip zones of du/da over max |du/da|.
    pub outward_slip: Check,
}

/// The fields at the points and the checks.
#[derive(Debug, Clone, PartialEq)]
pub struct FieldsF64 {
    /// The fields at the points (2 n stick elements).
    pub points: Vec<PointFields>,
    /// The largest difference of the n and 2 n meshes over the points: q1, q2 (scale E* k a) and
    /// psi (scale k a).
    pub errors: PointFields,
    /// The inequality checks.
    pub checks: Checks,
}

/// The fields at `x_over_a` (each in [0, 1]) and the checks, from the (gamma, C_P) of the n and
/// 2 n meshes (`pair`, [`super::single_punch::solve_pair`]).
pub fn fields(
    beta: f64,
    mu: f64,
    pair: [(f64, f64); 2],
    n: usize,
    x_over_a: &[f64],
) -> Result<FieldsF64, AdhesionError> {
    let [(g1, p1), (g2, p2)] = pair;
    let (coarse, fine) = (increment(beta, mu, g1, n, true)?, increment(beta, mu, g2, 2 * n, true)?);
    let pc: Vec<PointFields> = x_over_a.iter().map(|&x| superposed(&coarse, p1, beta, x)).collect();
    let pf: Vec<PointFields> = x_over_a.iter().map(|&x| superposed(&fine, p2, beta, x)).collect();
    let mut errors: PointFields = PointFields { q1: 0.0, q2: 0.0, psi: 0.0 };
    for (c, f) in pc.iter().zip(&pf) {
        errors.q1 = errors.q1.max((c.q1 - f.q1).abs());
        errors.q2 = errors.q2.max((c.q2 - f.q2).abs());
        errors.psi = errors.psi.max((c.psi - f.psi).abs());
    }
    let (cc, cf) = (inequalities(&state(beta, mu, g1, n)?, mu), inequalities(&state(beta, mu, g2, 2 * n)?, mu));
    let check = |c: f64, f: f64| Check { value: f, error: (f - c).abs() };
    let checks = Checks {
        stick_ratio: check(cc[0], cf[0]),
        pressure_min: check(cc[1], cf[1]),
        outward_slip: check(cc[2], cf[2]),
    };
    Ok(FieldsF64 { points: pf, errors, checks })
}

/// The fields at x in [0, 1] superposed from the unit increment (module doc).
fn superposed(inc: &Increment, cp: f64, beta: f64, x: f64) -> PointFields {
    let m = &inc.mesh;
    let gamma = m.nodes[m.stick];
    // int_from^1 f(y) y^-2 dy for piecewise-constant f
    let moment = |f: &[f64], from: f64| -> f64 {
        (0..m.elements())
            .filter(|&j| m.nodes[j + 1] > from)
            .map(|j| f[j] * (1.0 / m.nodes[j].max(from) - 1.0 / m.nodes[j + 1]))
            .sum()
    };
    let (q2, q1) = if x == 0.0 {
        // q2(0) = 2 C_P s2(0), s2(0) read as the first element's mean (an even quadratic through
        // the first two means converges no faster: s2(0) 1e-5 apart on n = 80, 160 at nu = 0, mu = 1/2)
        (2.0 * cp * inc.s2[0], 0.0)
    } else {
        (2.0 * cp * x * moment(&inc.s2, x), 2.0 * cp * x * moment(&inc.s1, x))
    };
    // J = int_X^inf T y^-2 dy, X = max(x, gamma): -sum_j s1_j int_X^inf (odd Cauchy weight of j)
    // y^-2 dy - beta int_X^1 s2 y^-2 dy
    let big_x = x.max(gamma);
    let mut j_int = -beta * moment(&inc.s2, big_x);
    for j in 0..m.elements() {
        let (u, v) = (m.nodes[j], m.nodes[j + 1]);
        let odd_cauchy = log_moment(big_x, u) - log_moment(big_x, v) - log_moment(big_x, -v) + log_moment(big_x, -u);
        j_int -= inc.s1[j] * odd_cauchy / std::f64::consts::PI;
    }
    // + 0.0: no -0 at x = 1
    PointFields { q1: q1 + 0.0, q2: q2 + 0.0, psi: 4.0 * cp * x * j_int + 0.0 }
}

/// int_X^inf ln|y - w| y^-2 dy (X > 0): -F(X) with F(y) = ln|y - w| (y - w)/(w y) - ln|y|/w the
/// primitive vanishing at infinity (w = 0: F = -(ln y + 1)/y); its first term is 0 at y = w.
fn log_moment(big_x: f64, w: f64) -> f64 {
    if w == 0.0 {
        return (big_x.ln() + 1.0) / big_x;
    }
    let d = big_x - w;
    let first = if d == 0.0 { 0.0 } else { d.abs().ln() * d / (w * big_x) };
    big_x.ln() / w - first
}

/// [stick ratio, pressure minimum, outward slip] of one state (module doc).
fn inequalities(s: &State, mu: f64) -> [f64; 3] {
    let ns = s.mesh.stick;
    let stick = (0..ns - 1).map(|j| s.q1[j].abs() / (mu * s.q2[j])).fold(0.0, f64::max);
    let top = s.q2.iter().cloned().fold(0.0, f64::max);
    let low = s.q2.iter().cloned().fold(f64::INFINITY, f64::min);
    let rates: Vec<f64> = (ns..s.mesh.elements()).map(|j| s.slip_rate(j)).collect();
    let size = rates.iter().map(|r| r.abs()).fold(0.0, f64::max);
    let outward = rates.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
    [stick, low / top, outward / size]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::adhesion::friction::single_punch::{from_pair, solve_pair, Method};

    /// nu = 0, mu = 1/2 at the self-similar gamma: the inequalities hold to within their mesh
    /// differences, the fields have their parities and the stick zone's psi is linear in x
    /// (u' = 2 C k |x|, docs/theory.md (17.5)); the centre pressure agrees with the one superposed
    /// from the increment method's unit increments.
    #[test]
    fn fields_and_checks_at_the_boundary_element_case() {
        let (beta, mu) = (0.5, 0.5);
        let pair = solve_pair(beta, mu, 40, Method::Increment).unwrap();
        let r = from_pair(pair);
        let xs = [0.0, 0.1, 0.2, 0.5, 0.9, 1.0];
        let f = fields(beta, mu, pair, 40, &xs).unwrap();
        eprintln!("{:?}\n{:?}\n{:?}", f.points, f.errors, f.checks);
        let c = &f.checks;
        assert!(c.stick_ratio.value < 1.0 + c.stick_ratio.error && c.stick_ratio.value > 0.5, "{c:?}");
        assert!(c.pressure_min.value > -c.pressure_min.error - 1e-6, "{c:?}");
        assert!(c.outward_slip.value < c.outward_slip.error + 1e-3, "{c:?}");
        let p = &f.points;
        assert_eq!(p[0].q1, 0.0);
        assert!(p[5].q1 == 0.0 && p[5].q2 == 0.0);
        // psi linear on the stick zone (0.1 and 0.2 < gamma = 0.52): psi(0.2) = 2 psi(0.1)
        assert!((p[2].psi - 2.0 * p[1].psi).abs() < 2.0 * f.errors.psi + 1e-4, "{p:?}");
        // slip zone: q1 = mu q2 at x = 0.9
        assert!((p[4].q1 - mu * p[4].q2).abs() < 1e-12, "{p:?}");
        // the centre pressure superposed from the unit increments (docs/theory.md 17.3:
        // q(x, 1) = 2 C_P int_|x|^1 s(x/t) dt, so q2(0) = 2 C_P s2(0)): an independent route
        let inc = crate::adhesion::friction::increment_f64::increment(beta, mu, r.gamma, 80, true).unwrap();
        let superposed = 2.0 * r.load_coefficient * inc.s2[0];
        assert!((p[0].q2 - superposed).abs() < 2e-3, "q2(0) {} against {superposed}", p[0].q2);
        assert!(f.errors.q2 < 1e-3 && f.errors.q1 < 1e-3 && f.errors.psi < 1e-2, "{:?}", f.errors);
    }
}
