//! The outside slope G(T) = H\[S2\](T), T > 1, of one solved increment of the periodic row
//! (docs/theory.md section 17.8, the kernel of (17.11)) at many T from one table of the density:
//! the same integral as [`Spectral::outside_slope`], with its density values computed once.
//!
//! The load's Volterra equation (17.11) needs G of each of its N increments at every pair
//! (collocation point, quadrature node): N^2 times the nodes of one tanh-sinh rule, each at its own
//! T. [`Spectral::outside_slope`] grades the slip zone toward T from scratch at every T and
//! evaluates the basis (three transcendental functions and 2 n terms per node) on every piece;
//! most of an MPFR load went there. Here the pieces are fixed and the values s2 w stored:
//! - stick zone (-gamma, gamma): graded toward its end gamma as for the nearest pole, T = 1 (the
//!   pole 1 - gamma + (T - 1) beyond the end is never nearer);
//! - slip zone (gamma, 1), in the distance d = 1 - x to the contact edge: the dyadic pieces
//!   P_k = (2^-(k+1), 2^-k) (1 - gamma), k < K, and every tail D_k = (0, 2^-k (1 - gamma)),
//!   1 <= k <= K. At T - 1 = b the slope sums P_0 .. P_(k0-1) and D_k0, k0 the least k >= 1 with
//!   2^-k (1 - gamma) <= b: every piece lies at least its own length from the pole at d = -b, the
//!   rule of `quadrature::graded` (which would cut the pieces b, 2 b, 4 b, ... instead).
//!   K = (bits + 8)/(omega + 1) + 4, omega = -1/2 + theta0, reaches the smallest b a tanh-sinh node of the load's rule can see
//!   (2^-(bits + 8)/(omega + 1), `quadrature.rs`); a smaller b falls back to
//!   [`Spectral::outside_slope`].
//!
//! Checked against [`Spectral::outside_slope`] in `spectral_row_tests.rs`
//! (`slope_table_is_the_outside_slope`).

use super::quadrature::graded;
use super::real::Real;
use super::spectral::{Spectral, SpectralIncrement};

/// The stored density of one increment: per node (distance to the near end, s2 times weight).
#[derive(Debug, Clone)]
pub struct SlopeTable<T> {
    gamma: T,
    /// Stick-zone nodes: (gamma - x, w s2).
    stick: Vec<(T, T)>,
    /// Slip-zone dyadic pieces P_k: nodes (1 - x, x, w s2).
    pieces: Vec<Vec<(T, T, T)>>,
    /// Tails D_k, k = 1 ..= K (index k - 1): nodes (1 - x, x, w s2).
    tails: Vec<Vec<(T, T, T)>>,
}

impl<T: Real> SlopeTable<T> {
    /// The table of the increment `inc` solved by `sp`.
    pub fn new(sp: &Spectral<T>, inc: &SpectralIncrement<T>) -> SlopeTable<T> {
        let gamma = inc.gamma.clone();
        let zero = gamma.lit(0.0);
        let one = gamma.lit(1.0);
        let rule = sp.rule();
        let len = gamma.lit(2.0) * gamma.clone();
        let mut stick = Vec::new();
        let mut dens = sp.density(inc);
        let pole = one.clone() - gamma.clone();
        rule.sweep(&len, &graded(&zero, &len, None, Some(&pole)), |d_a, d_b, w| {
            stick.push((d_b.clone(), w.clone() * dens.at(false, d_a, d_b)));
        });
        let len = one.clone() - gamma.clone();
        // the load's rule (end singularity distance^omega) reaches distances 2^-(bits + 8)/(omega + 1)
        let (_, omega) = inc.exponents();
        let edge_power = (omega.to_f64() + 1.0).max(0.02);
        let levels = ((sp.bits() + 8) as f64 / edge_power).ceil() as usize + 4;
        let mut piece = |lo: &T, hi: &T| -> Vec<(T, T, T)> {
            // offsets from gamma: (len - hi, len - lo)
            let mut out = Vec::new();
            let (p, q) = (len.clone() - hi.clone(), len.clone() - lo.clone());
            rule.sweep(&len, &[(p, q)], |d_a, d_b, w| {
                if *d_b == zero || *w == zero {
                    return; // a tail node underflowed (f64): it adds nothing
                }
                let x = gamma.clone() + d_a.clone();
                out.push((d_b.clone(), x, w.clone() * dens.at(true, d_a, d_b)));
            });
            out
        };
        let half = gamma.lit(0.5);
        let mut pieces = Vec::with_capacity(levels);
        let mut tails = Vec::with_capacity(levels);
        let mut hi = len.clone();
        for _ in 0..levels {
            let lo = hi.clone() * half.clone();
            pieces.push(piece(&lo, &hi));
            tails.push(piece(&zero, &lo));
            hi = lo;
            if hi == zero {
                break; // f64 underflow
            }
        }
        SlopeTable { gamma, stick, pieces, tails }
    }

    /// H\[s2\](t) at t = 1 + `beyond` (> 0), as [`Spectral::outside_slope`]; None where `beyond`
    /// is below the table's smallest piece.
    pub fn slope(&self, beyond: &T) -> Option<T> {
        let gamma = &self.gamma;
        let one = gamma.lit(1.0);
        let near = one.clone() - gamma.clone() + beyond.clone();
        let mut sum = gamma.lit(0.0);
        for (d_b, ws2) in &self.stick {
            sum = sum + ws2.clone() / (near.clone() + d_b.clone());
        }
        // k0: the least k >= 1 with 2^-k (1 - gamma) <= beyond
        let mut size = (one.clone() - gamma.clone()) * gamma.lit(0.5);
        let mut k0 = 1;
        while size > *beyond {
            size = size * gamma.lit(0.5);
            k0 += 1;
            if k0 > self.tails.len() {
                return None;
            }
        }
        let t = one.clone() + beyond.clone();
        let nodes = self.pieces[..k0].iter().chain(std::iter::once(&self.tails[k0 - 1])).flatten();
        for (d_b, x, ws2) in nodes {
            let kernel = one.clone() / (beyond.clone() + d_b.clone()) + one.clone() / (t.clone() + x.clone());
            sum = sum + ws2.clone() * kernel;
        }
        Some(sum / gamma.pi())
    }
}
