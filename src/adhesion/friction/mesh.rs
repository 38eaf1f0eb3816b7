//! The graded mesh of the single punch's half contact (0, 1) with its stick edge gamma, and the
//! exact integrals of piecewise-constant densities against the kernels of docs/theory.md
//! section 17: the logarithm (displacements), the Cauchy kernel (slopes), the outside-slope weight.

use nalgebra::{DMatrix, DVector};

use crate::growing_contact::error::AdhesionError;
use std::f64::consts::PI;

/// The grading power: element widths shrink like (j/n)^4 toward gamma and toward 1, where the
/// densities behave like |x - gamma|^(+-1/2 - theta0) and (1 - x)^(-+1/2 + theta0)).
pub const GRADING: f64 = 4.0;

/// Elements on (0, 1): `stick` of them on (0, gamma) graded toward gamma, the rest on (gamma, 1)
/// graded toward gamma and toward 1 (half of them on each half of (gamma, 1)).
#[derive(Debug, Clone)]
pub struct Mesh {
    /// Element ends 0 = x_0 < ... < x_len = 1, with x_stick = gamma.
    pub nodes: Vec<f64>,
    /// Elements in the stick zone (0, gamma).
    pub stick: usize,
}

impl Mesh {
    /// `n` elements on (0, gamma) and 2 `n` on (gamma, 1), grading power [`GRADING`].
    pub fn graded(gamma: f64, n: usize) -> Mesh {
        let p = GRADING;
        let mut nodes = Vec::with_capacity(3 * n + 1);
        for j in 0..n {
            nodes.push(gamma * (1.0 - (1.0 - j as f64 / n as f64).powf(p)));
        }
        let mid = 0.5 * (gamma + 1.0);
        for j in 0..n {
            nodes.push(gamma + (mid - gamma) * (j as f64 / n as f64).powf(p));
        }
        for j in 0..=n {
            nodes.push(1.0 - (1.0 - mid) * (1.0 - j as f64 / n as f64).powf(p));
        }
        Mesh { nodes, stick: n }
    }

    /// Number of elements.
    pub fn elements(&self) -> usize {
        self.nodes.len() - 1
    }

    /// Midpoint of element j (the collocation point).
    pub fn mid(&self, j: usize) -> f64 {
        0.5 * (self.nodes[j] + self.nodes[j + 1])
    }

    /// Width of element j.
    pub fn width(&self, j: usize) -> f64 {
        self.nodes[j + 1] - self.nodes[j]
    }

    /// int_0^x f for piecewise-constant f at the midpoint of element i: the weight of element j
    /// (its width for j < i, half of it for j = i, 0 beyond).
    pub(crate) fn running_weight(&self, i: usize, j: usize) -> f64 {
        match j.cmp(&i) {
            std::cmp::Ordering::Less => self.width(j),
            std::cmp::Ordering::Equal => 0.5 * self.width(j),
            std::cmp::Ordering::Greater => 0.0,
        }
    }

    /// (1/pi) int ln|x - xi| over element j and its mirror image, for an even (`odd = false`) or
    /// odd density: the displacement kernel Lambda of docs/theory.md (17.4).
    pub(crate) fn log_weight(&self, x: f64, j: usize, odd: bool) -> f64 {
        let (u, v) = (self.nodes[j], self.nodes[j + 1]);
        let mirror = log_panel(x, -v, -u);
        log_panel(x, u, v) + if odd { -mirror } else { mirror }
    }

    /// (1/pi) PV int 1/(x - xi) over element j and its mirror image, even or odd density: the
    /// Hilbert operator H of docs/theory.md section 2 (L -> infinity).
    pub(crate) fn cauchy_weight(&self, x: f64, j: usize, odd: bool) -> f64 {
        let (u, v) = (self.nodes[j], self.nodes[j + 1]);
        let here = ((x - u) / (x - v)).abs().ln();
        let mirror = ((x + v) / (x + u)).abs().ln();
        (here + if odd { -mirror } else { mirror }) / PI
    }

    /// The collocation matrix of the displacement forms shared by both methods, with `extra`
    /// columns and rows left zero for the caller's unknowns and conditions. Columns: q2 (or s2)
    /// on every element, then q1 on the stick elements (on the slip ones q1 = mu q2). Rows: at
    /// every midpoint Lambda\[q2\] - beta_n int_0^x q1 (the normal equation, (17.4), (17.7)), then at
    /// every stick midpoint Lambda\[q1\] + beta int_0^x q2 (the tangential one, (17.5), (17.7)).
    pub(crate) fn displacement_rows(&self, beta_n: f64, beta: f64, mu: f64, extra: usize) -> DMatrix<f64> {
        let (len, ns) = (self.elements(), self.stick);
        let size = len + ns + extra;
        let mut a = DMatrix::<f64>::zeros(size, size);
        for i in 0..len {
            let x = self.mid(i);
            for j in 0..len {
                a[(i, j)] += self.log_weight(x, j, false);
            }
            for j in 0..=i {
                let w = self.running_weight(i, j);
                if j < ns {
                    a[(i, len + j)] -= beta_n * w;
                } else {
                    a[(i, j)] -= beta_n * mu * w;
                }
            }
        }
        for i in 0..ns {
            let (x, row) = (self.mid(i), len + i);
            for j in 0..len {
                let k = self.log_weight(x, j, true);
                if j < ns {
                    a[(row, len + j)] += k;
                } else {
                    a[(row, j)] += mu * k;
                }
            }
            for j in 0..=i {
                a[(row, j)] += beta * self.running_weight(i, j);
            }
        }
        a
    }

    /// Solves the collocation system (`what` names it in the error) and unpacks the densities.
    pub fn solve(
        &self,
        a: DMatrix<f64>,
        rhs: &DVector<f64>,
        mu: f64,
        what: &'static str,
    ) -> Result<Densities, AdhesionError> {
        let (len, ns) = (self.elements(), self.stick);
        let sol = a.lu().solve(rhs).ok_or_else(|| AdhesionError::NotConverged {
            what,
            reason: format!("singular collocation matrix at gamma = {}", self.nodes[ns]),
        })?;
        let q2: Vec<f64> = (0..len).map(|j| sol[j]).collect();
        let q1: Vec<f64> = (0..len).map(|j| if j < ns { sol[len + j] } else { mu * sol[j] }).collect();
        Ok(Densities { q2, q1, solution: sol })
    }

    /// int over element j of -ln(1 - xi^2)/xi^2 (the outside-slope weight of docs/theory.md (17.9)).
    pub(crate) fn outside_weight(&self, j: usize) -> f64 {
        outside_primitive(self.nodes[j + 1]) - outside_primitive(self.nodes[j])
    }
}

/// The solution of a collocation system: the densities per element and every unknown.
#[derive(Debug, Clone)]
pub struct Densities {
    /// q2 (or s2) per element of (0, 1).
    pub q2: Vec<f64>,
    /// q1 (or s1) per element, mu q2 on the slip elements.
    pub q1: Vec<f64>,
    /// The whole solution vector (the densities, then the caller's extra unknowns).
    pub solution: DVector<f64>,
}

/// t ln|t| - t, the primitive of ln|t| (0 at t = 0).
fn f_log(t: f64) -> f64 {
    if t == 0.0 {
        0.0
    } else {
        t * t.abs().ln() - t
    }
}

/// (1/pi) int_u^v ln|x - xi| dxi.
fn log_panel(x: f64, u: f64, v: f64) -> f64 {
    (f_log(x - u) - f_log(x - v)) / PI
}

/// G(x) = ln(1 - x^2)/x + ln((1 + x)/(1 - x)), the primitive of -ln(1 - x^2)/x^2 with G(0) = 0,
/// G(1) = 2 ln 2.
fn outside_primitive(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else if x == 1.0 {
        2.0 * std::f64::consts::LN_2
    } else {
        (1.0 - x * x).ln() / x + ((1.0 + x) / (1.0 - x)).ln()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The flat punch s = 1/(pi sqrt(1 - x^2)) has int_1^inf H\[s\](y)/y^2 dy = 1/pi (Hertz's
    /// C_P = pi/2): the outside weight integrated against it, element by element on a fine mesh.
    #[test]
    fn outside_weight_of_the_flat_punch_is_one_over_pi() {
        let mesh = Mesh::graded(0.5, 400);
        let mut i = 0.0;
        for j in 0..mesh.elements() {
            // the element mean of 1/(pi sqrt(1 - x^2)), exact: (asin v - asin u)/(pi w)
            let mean = (mesh.nodes[j + 1].asin() - mesh.nodes[j].asin()) / (PI * mesh.width(j));
            i += mean * mesh.outside_weight(j) / PI;
        }
        assert!((i - 1.0 / PI).abs() < 3e-5, "I = {i}");
    }

    /// The log and Cauchy weights are a primitive and its derivative: a difference quotient of
    /// the log weight in x matches the Cauchy weight.
    #[test]
    fn cauchy_weight_is_the_derivative_of_the_log_weight() {
        let mesh = Mesh::graded(0.4, 6);
        let (x, h) = (0.7, 1e-6);
        for j in [0, 3, 10, 17] {
            for odd in [false, true] {
                let dq = (mesh.log_weight(x + h, j, odd) - mesh.log_weight(x - h, j, odd)) / (2.0 * h);
                assert!((dq - mesh.cauchy_weight(x, j, odd)).abs() < 1e-7, "j {j} odd {odd}");
            }
        }
    }
}
