//! s2 of a solved increment of the spectral method at a point (docs/theory.md section 17.7):
//! [`Density`], its basis storage reused from point to point ([`Spectral::density`],
//! [`Spectral::normal_density`]), and the parabola's load coefficient C_P = 1/(2 I),
//! I = (1/pi) int_0^1 s2 (-ln(1 - xi^2)/xi^2) dxi of (17.9) ([`Spectral::load_coefficient`]),
//! stationary in gamma at the self-similar root.
//!
//! Checked in `spectral_tests.rs` (C_P: pi/2 exactly at nu = 1/2 and in the uncoupled problem;
//! against the increment method and the verified MPFR values) and by
//! `pair_is_the_families_sum_bit_for_bit` (`fields.rs`: [`Density::at`] against the families'
//! sum).

use super::super::quadrature::graded;
use super::super::real::Real;
use super::basis::Node;
use super::{Spectral, SpectralIncrement};

impl<T: Real> Spectral<T> {
    /// s2 of a solved increment at a point of the stick zone (`slip` false; d_a = x + gamma,
    /// d_b = gamma - x) or of the right slip zone (`slip` true; d_a = x - gamma, d_b = 1 - x).
    pub fn normal_density(&self, inc: &SpectralIncrement<T>, slip: bool, d_a: &T, d_b: &T) -> T {
        self.density(inc).at(slip, d_a, d_b)
    }

    /// [`Spectral::normal_density`] of `inc` at many points, its storage reused from point to
    /// point.
    pub fn density<'a>(&'a self, inc: &'a SpectralIncrement<T>) -> Density<'a, T> {
        Density { sp: self, inc, nd: Node::new(&inc.gamma, self.n), tmp: inc.gamma.lit(0.0) }
    }

    /// C_P = 1/(2 I) of the parabola (17.9) from a solved increment.
    pub fn load_coefficient(&self, inc: &SpectralIncrement<T>) -> T {
        let gamma = &inc.gamma;
        let zero = gamma.lit(0.0);
        let one = gamma.lit(1.0);
        let mut dens = self.density(inc);
        let mut i_stick = zero.clone();
        let len = gamma.lit(2.0) * gamma.clone();
        let edge = self.edge(&inc.zones);
        self.rule.sweep(&len, &graded(&zero, &len, edge, edge), |d_a, d_b, w| {
            let xi = (d_a.clone() - d_b.clone()) * gamma.lit(0.5);
            let y = xi.clone() * xi;
            let kern = if y == zero { one.clone() } else { -(-y.clone()).ln_1p() / y };
            let s2 = dens.at(false, d_a, d_b);
            i_stick = i_stick.clone() + w.clone() * kern * s2;
        });
        let mut i_slip = zero.clone();
        let len = one.clone() - gamma.clone();
        self.rule.sweep(&len, &graded(&zero, &len, None, None), |d_a, d_b, w| {
            let eta = gamma.clone() + d_a.clone();
            let kern = -(d_b.ln() + (one.clone() + eta.clone()).ln()) / (eta.clone() * eta);
            let s2 = dens.at(true, d_a, d_b);
            i_slip = i_slip.clone() + w.clone() * kern * s2;
        });
        let i = (i_stick * gamma.lit(0.5) + i_slip) / gamma.pi();
        one / (gamma.lit(2.0) * i)
    }
}

/// s2 of one solved increment at many points ([`Spectral::density`]).
pub struct Density<'a, T> {
    pub(super) sp: &'a Spectral<T>,
    pub(super) inc: &'a SpectralIncrement<T>,
    pub(super) nd: Node<T>,
    pub(super) tmp: T,
}

impl<T: Real> Density<'_, T> {
    /// s2 at a point of the stick zone (`slip` false; d_a = x + gamma, d_b = gamma - x) or of
    /// the right slip zone (`slip` true; d_a = x - gamma, d_b = 1 - x).
    pub fn at(&mut self, slip: bool, d_a: &T, d_b: &T) -> T {
        let (n, zn) = (self.sp.n, &self.inc.zones);
        let c = if slip { &self.inc.coeffs[4 * n..6 * n] } else { &self.inc.coeffs[..2 * n] };
        let nd = &mut self.nd;
        let fac = if slip {
            self.sp.slip_node(zn, d_a, d_b, nd);
            [Some(&nd.fac[0]), Some(&nd.fac[1])]
        } else {
            self.sp.stick_node(zn, d_a, d_b, nd);
            [None, Some(&nd.fac[0])]
        };
        let mut acc = d_a.lit(0.0);
        for (f, cf) in fac.iter().zip(c.chunks(n)) {
            for (tj, cj) in nd.t.iter().zip(cf) {
                match f {
                    None => acc.add_mul(cj, tj),
                    Some(v) => {
                        self.tmp.set_mul(v, tj);
                        acc.add_mul(cj, &self.tmp);
                    }
                }
            }
        }
        acc
    }
}
