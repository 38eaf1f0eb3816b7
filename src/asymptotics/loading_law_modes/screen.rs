//! det M(mu) in f64 with a bound on its error, so that the scan of [`super::Symbol::first_zero`]
//! decides most signs without MPFR.
//!
//! From the symbol's MPFR node data rounded once to f64 (ln s, r = ln s/(1 - s), the four side
//! weights), at a real mu >= 0:
//!   s^mu = exp(mu ln s),   e_mu = (1 - s^(mu+1))/(1 - s) = -(mu + 1) r h(x),
//!   h(x) = expm1(x)/x,     x = (mu + 1) ln s < 0
//! (h is 1 where x underflows to 0: no division by a 1 - s that may itself underflow), and
//!   M_sigma,f = sum wf_sigma s^mu,   M_sigma,g = sum wg_sigma e_mu - pi,
//!   det M = M_+,f M_-,g - M_+,g M_-,f.
//!
//! # The bound
//! With u = 2^-53: x carries a relative error of at most 4u (ln s and r rounded, mu + 1 and the
//! product rounded), so exp(mu ln s) and h(x) carry at most |x| 4u + 3u (|x h'(x)/h(x)| <= |x| and
//! |d ln exp(y)/dy| = 1 with |mu ln s| <= |x|); with the weight's and the products' roundings every
//! term is within (|x| + 8) 4u of its value relative to itself. A sum of N terms and pi adds at
//! most (N + 2) u (sum |terms| + pi) (the gamma_N bound), and an absolute 1e-290 covers weights
//! and terms that underflow. The determinant's error is then at most
//! |a| E_d + |d| E_a + E_a E_d + |b| E_c + |c| E_b + E_b E_c + 2u (|ad| + |bc|), doubled here for
//! slack. The MPFR evaluation at p >= [`MIN_PREC`] bits of the same stored data errs by the same
//! expression with 2^-p for u, at most 2^-11 of this bound, so where |det_f64| > 2 bound the exact
//! determinant and the MPFR value both have the sign of det_f64 (module [`super::scan`]).
//!
//! Data computed in f64 ([`super::quick`]) carry their own bounds: a relative error of ln s moves
//! s^mu, x and h(x) by at most |x| times it, one of r moves e_mu by itself, and the weights'
//! absolute errors enter times |s^mu| and |e_mu|; their sum (with 1 % for the second order) is
//! added to each entry's error. For the MPFR data they are zero and the bound is as above.

use super::Node;

/// The least working precision at which the screen is used (the MPFR value must be far more
/// accurate than the f64 one for a screened sign to equal MPFR's).
pub const MIN_PREC: u32 = 64;

const U: f64 = f64::EPSILON / 2.0;

/// f64 copies of one node's data, with bounds on their errors beyond rounding once (zero for
/// the copies of MPFR data; set by the f64 mode check, [`super::quick`]).
#[derive(Debug, Clone)]
pub(super) struct ScreenNode {
    pub(super) ln_s: f64,
    /// ln s/(1 - s).
    pub(super) r: f64,
    /// [wf_+, wg_+], [wf_-, wg_-] (as [`super::Node`]).
    pub(super) sides: [[f64; 2]; 2],
    /// Relative error of `ln_s`.
    pub(super) ln_s_err: f64,
    /// Relative error of `r`.
    pub(super) r_err: f64,
    /// Absolute errors of `sides`.
    pub(super) sides_err: [[f64; 2]; 2],
}

/// The f64 copy of the symbol's nodes.
#[derive(Debug, Clone)]
pub struct Screen {
    pub(super) nodes: Vec<ScreenNode>,
}

/// det M(mu) in f64 and a bound on |det_f64 - det|.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Approx {
    /// det M(mu) in f64.
    pub value: f64,
    /// Bound on its error (module doc).
    pub bound: f64,
}

impl Approx {
    /// The sign of the exact determinant (and of its MPFR value), if the bound decides it.
    pub fn negative(&self) -> Option<bool> {
        (self.value.abs() > 2.0 * self.bound).then_some(self.value < 0.0)
    }
}

impl Screen {
    /// From the symbol's nodes.
    pub(super) fn new(nodes: &[Node]) -> Self {
        let nodes = nodes
            .iter()
            .map(|n| ScreenNode {
                ln_s: n.ln_s.to_f64(),
                r: rug::Float::with_val(n.ln_s.prec(), &n.ln_s / &n.c).to_f64(),
                sides: [
                    [n.sides[0][0].to_f64(), n.sides[0][1].to_f64()],
                    [n.sides[1][0].to_f64(), n.sides[1][1].to_f64()],
                ],
                ln_s_err: 0.0,
                r_err: 0.0,
                sides_err: [[0.0; 2]; 2],
            })
            .collect();
        Screen { nodes }
    }

    /// From node data computed in f64 with their error bounds ([`super::quick`]).
    pub(super) fn from_f64(nodes: Vec<ScreenNode>) -> Self {
        Screen { nodes }
    }

    /// det M(`mu`) with its bound, `mu` >= 0 finite (else an infinite bound: undecided).
    pub fn det(&self, mu: f64) -> Approx {
        if !(mu.is_finite() && mu >= 0.0) {
            return Approx { value: 0.0, bound: f64::INFINITY };
        }
        let mu1 = mu + 1.0;
        // Per entry: the sum, the sum of |terms|, the sum of |term| (|x| + 8), and the data's
        // own errors (beyond rounding once) carried into the terms.
        let mut m = [[0.0f64; 2]; 2];
        let mut abs = [[0.0f64; 2]; 2];
        let mut rel = [[0.0f64; 2]; 2];
        let mut data = [[0.0f64; 2]; 2];
        for n in &self.nodes {
            let x = n.ln_s * mu1;
            let s_mu = (n.ln_s * mu).exp();
            let h = if x == 0.0 { 1.0 } else { x.exp_m1() / x };
            let e = -mu1 * n.r * h;
            let grow = x.abs() + 8.0;
            // An error of ln s relative to itself moves x, mu ln s (|mu ln s| <= |x|) and h
            // (|x h'/h| <= |x|) by |x| times it; r's moves e_mu by itself.
            let moved = x.abs() * n.ln_s_err;
            for k in 0..2 {
                let (tf, tg) = (n.sides[k][0] * s_mu, n.sides[k][1] * e);
                m[k][0] += tf;
                m[k][1] += tg;
                abs[k][0] += tf.abs();
                abs[k][1] += tg.abs();
                rel[k][0] += tf.abs() * grow;
                rel[k][1] += tg.abs() * grow;
                data[k][0] += tf.abs() * moved + n.sides_err[k][0] * s_mu;
                data[k][1] += tg.abs() * (moved + n.r_err) + n.sides_err[k][1] * e.abs();
            }
        }
        let pi = std::f64::consts::PI;
        let count = self.nodes.len() as f64 + 2.0;
        let mut err = [[0.0f64; 2]; 2];
        for k in 0..2 {
            m[k][1] -= pi;
            for j in 0..2 {
                let extra = if j == 1 { pi } else { 0.0 };
                // The data's errors to first order, with 1 % for the second.
                err[k][j] = 4.0 * U * rel[k][j] + count * U * (abs[k][j] + extra) + 1e-290 + 1.01 * data[k][j];
            }
        }
        let (a, b, c, d) = (m[0][0], m[0][1], m[1][0], m[1][1]);
        let (ea, eb, ec, ed) = (err[0][0], err[0][1], err[1][0], err[1][1]);
        let value = a * d - b * c;
        let bound = a.abs() * ed
            + d.abs() * ea
            + ea * ed
            + b.abs() * ec
            + c.abs() * eb
            + eb * ec
            + 2.0 * U * ((a * d).abs() + (b * c).abs());
        let bound = 2.0 * bound;
        if value.is_finite() && bound.is_finite() {
            Approx { value, bound }
        } else {
            Approx { value: 0.0, bound: f64::INFINITY }
        }
    }
}
