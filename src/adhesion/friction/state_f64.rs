//! Method 2 for the single punch: the current state of the self-similar solution (docs/theory.md
//! section 17, (17.4)-(17.6)), piecewise-constant collocation of the displacement form on the
//! graded [`Mesh`], `f64`; independent of method 1's superposition of increments.
//!
//! With a = 1, E* k = 1: the tractions q2 (even), q1 (odd) of the parabola g = k x^2 solve
//!     Lambda\[q2\](x) - beta int_0^x q1 = x^2/2 + v0        on (0, 1)      (17.4: v' = g'),
//!     Lambda\[q1\](x) + beta int_0^x q2 = -C x^2/2          on (0, gamma)  (17.5: u' = 2 C k |x|),
//!     q1 = mu q2 on (gamma, 1),
//! with (v0, C) fixed by boundedness at 1 and at gamma (q2 and r = q1 - mu q2 vanish on the last
//! element before each: the bounded solution vanishes there like (1 - x)^(1/2 + theta0) and
//! |x - gamma|^(3/2 - theta0)). Between the two, r behaves like b |x - gamma|^(1/2 - theta0) at
//! a generic gamma: b > 0 (above the self-similar gamma) breaks |q1| <= mu q2 next to the stick
//! edge, b < 0 (below it) makes the slip zone next to it slip against friction ((17.6), the
//! inequalities that fix gamma); [`State::stick_margin`] is r on the last stick element but one,
//! whose sign change is the self-similar gamma. The load coefficient is C_P = 2 int_0^1 q2
//! directly, and [`State::slip_rate`] gives du/da for the check of the slip direction.

use nalgebra::DVector;

use super::mesh::Mesh;
use crate::growing_contact::error::AdhesionError;

/// The current state on one mesh.
#[derive(Debug, Clone)]
pub struct State {
    /// The mesh it was solved on.
    pub mesh: Mesh,
    /// q2/(E* k a) per element of (0, 1).
    pub q2: Vec<f64>,
    /// q1/(E* k a) per element (mu q2 on the slip elements).
    pub q1: Vec<f64>,
    /// C of u' = 2 C k |x| on the stick zone.
    pub c: f64,
    /// beta (for the surface relations of [`State::slip_rate`]).
    beta: f64,
    /// The friction coefficient.
    mu: f64,
}

/// The current state with `n` stick elements at stick half-width `gamma` in (0, 1).
pub fn state(beta: f64, mu: f64, gamma: f64, n: usize) -> Result<State, AdhesionError> {
    let mesh = Mesh::graded(gamma, n);
    let (len, ns) = (mesh.elements(), mesh.stick);
    // unknowns: q2 (len), q1 on the stick elements (ns), v0, C
    let size = len + ns + 2;
    let (iv, ic) = (size - 2, size - 1);
    let mut a = mesh.displacement_rows(beta, beta, mu, 2);
    let mut rhs = DVector::<f64>::zeros(size);
    for i in 0..len {
        let x = mesh.mid(i);
        a[(i, iv)] = -1.0;
        rhs[i] = 0.5 * x * x;
    }
    for i in 0..ns {
        let x = mesh.mid(i);
        a[(len + i, ic)] = 0.5 * x * x;
    }
    // boundedness: q2 = 0 on the last element, q1 - mu q2 = 0 on the last stick element
    a[(len + ns, len - 1)] = 1.0;
    a[(len + ns + 1, len + ns - 1)] = 1.0;
    a[(len + ns + 1, ns - 1)] = -mu;
    let d = mesh.solve(a, &rhs, mu, "single-punch state collocation")?;
    Ok(State { mesh, q2: d.q2, q1: d.q1, c: d.solution[ic], beta, mu })
}

impl State {
    /// (E*/2)(2 u - x u')/(k a^2) at the midpoint of element i: the rate du/da of the surface
    /// point x relative to the punch (self-similarity, u = k a^2 U(x/a)); zero on the stick zone,
    /// negative (inward, x > 0) where the surface slips against q1 = mu q2 > 0.
    pub fn slip_rate(&self, i: usize) -> f64 {
        let (u, du) = self.lateral(i);
        2.0 * u - self.mesh.mid(i) * du
    }

    /// psi/(k a) = u'/(k a) at the midpoint of element i: (E*/2) u' = -H\[q1\] - beta q2
    /// (docs/theory.md section 2, L -> infinity), the same psi as complete adhesion's (section 4:
    /// psi = phi', u = phi on the stick zone); 2 C x/a on the stick zone.
    pub fn psi(&self, i: usize) -> f64 {
        2.0 * self.lateral(i).1
    }

    /// ((E*/2) u, (E*/2) u') at the midpoint of element i, on the scales E* k a^2 and E* k a.
    fn lateral(&self, i: usize) -> (f64, f64) {
        let x = self.mesh.mid(i);
        let (mut u, mut du) = (0.0, 0.0);
        for j in 0..self.q1.len() {
            u -=
                self.q1[j] * self.mesh.log_weight(x, j, true) + self.beta * self.q2[j] * self.mesh.running_weight(i, j);
            du -= self.q1[j] * self.mesh.cauchy_weight(x, j, true);
        }
        (u, du - self.beta * self.q2[i])
    }

    /// r = q1 - mu q2 on the last stick element but one (the sign of b, see the module doc).
    pub fn stick_margin(&self) -> f64 {
        let j = self.mesh.stick - 2;
        self.q1[j] - self.mu * self.q2[j]
    }

    /// C_P = P/(E* k a^2) = 2 int_0^1 q2.
    pub(crate) fn load_coefficient(&self) -> f64 {
        2.0 * (0..self.q2.len()).map(|j| self.q2[j] * self.mesh.width(j)).sum::<f64>()
    }
}
