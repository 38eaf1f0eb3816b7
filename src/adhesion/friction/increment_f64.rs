//! Method 1 for the single punch: the unit increment of the self-similar solution (docs/theory.md
//! section 17, (17.7)-(17.9)), piecewise-constant collocation of the displacement form on the
//! graded [`Mesh`], `f64`.
//!
//! With a = 1, E* k = 1 and Lambda\[f\](x) = (1/pi) int f(xi) ln|x - xi| dxi, the increment
//! s = s2 + i s1 of unit load (s2 even, s1 odd) at stick half-width gamma solves
//!     Lambda\[s2\](x) - beta int_0^x s1 = v0      on (0, 1)      (17.7a: dv' = 0, the punch descends),
//!     Lambda\[s1\](x) + beta int_0^x s2 = 0       on (0, gamma)  (17.7b: du = 0, stuck points stay),
//!     s1 = mu s2 on (gamma, 1),   2 int_0^1 s2 = 1,
//! v0 the unknown descent. At a generic gamma the solution is unbounded at +-gamma like
//! |x -+ gamma|^(-1/2 - theta0) (tan(pi theta0) = beta mu, (17.3)); the self-similar gamma is the one
//! where it is bounded, found as the sign change of [`stick_edge_defect`] (r = s1 - mu s2 on the last
//! stick element times its width^(1/2 + theta0): the singular coefficient up to a positive
//! factor). The load coefficient of the parabola is C_P = P/(E* k a^2) = 1/(2 I),
//! I = (1/pi) int_0^1 s2(xi) (-ln(1 - xi^2)/xi^2) dxi (17.9: the accumulated slope at the edge is g').
//!
//! `coupled = false` drops beta int s1 from (17.7a): the uncoupled problem of Spence and Johnson
//! (s2 the flat punch, C_P = pi/2, gamma from K'(gamma)/K(gamma) = beta/mu), a check.

use nalgebra::DVector;

use super::mesh::Mesh;
use crate::growing_contact::error::AdhesionError;

/// The unit increment on one mesh.
#[derive(Debug, Clone)]
pub struct Increment {
    /// The mesh it was solved on.
    pub mesh: Mesh,
    /// s2 per element of (0, 1).
    pub s2: Vec<f64>,
    /// s1 per element (mu s2 on the slip elements).
    pub s1: Vec<f64>,
}

/// The unit increment with `n` stick elements at stick half-width `gamma` in (0, 1).
pub fn increment(beta: f64, mu: f64, gamma: f64, n: usize, coupled: bool) -> Result<Increment, AdhesionError> {
    let mesh = Mesh::graded(gamma, n);
    let (len, ns) = (mesh.elements(), mesh.stick);
    // unknowns: s2 (len), s1 on the stick elements (ns), v0
    let size = len + ns + 1;
    let mut a = mesh.displacement_rows(if coupled { beta } else { 0.0 }, beta, mu, 1);
    let mut rhs = DVector::<f64>::zeros(size);
    for i in 0..len {
        a[(i, size - 1)] = -1.0;
    }
    for j in 0..len {
        a[(size - 1, j)] = 2.0 * mesh.width(j);
    }
    rhs[size - 1] = 1.0;
    let d = mesh.solve(a, &rhs, mu, "single-punch increment collocation")?;
    Ok(Increment { mesh, s2: d.q2, s1: d.q1 })
}

/// The singular part of the increment at the stick edge, up to a positive factor: (s1 - mu s2) on
/// the last stick element times its width^(1/2 + theta0). Negative for gamma below the
/// self-similar value, positive above.
pub fn stick_edge_defect(inc: &Increment, beta: f64, mu: f64) -> f64 {
    let j = inc.mesh.stick - 1;
    let theta0 = (beta * mu).atan() / std::f64::consts::PI;
    (inc.s1[j] - mu * inc.s2[j]) * inc.mesh.width(j).powf(0.5 + theta0)
}

/// C_P = P/(E* k a^2) = 1/(2 I) (17.9), the element integrals of the outside weight exact.
pub(crate) fn load_coefficient(inc: &Increment) -> f64 {
    let i: f64 = (0..inc.s2.len()).map(|j| inc.s2[j] * inc.mesh.outside_weight(j)).sum::<f64>() / std::f64::consts::PI;
    1.0 / (2.0 * i)
}
