//! The load of the periodic row with finite friction from the edge-slope Volterra equation at high
//! order (docs/theory.md section 17.8, (17.11)), the increments by the spectral method of
//! [`super::spectral_row`], generic over `f64` and MPFR.
//!
//! Units L = pi, E* = k = 1 (P2 = E* k (L/pi)^2 P). With W(chi, eta) the outside slope of the unit
//! increment at contact eta, the load P(lambda) solves
//!     int_0^chi W(chi, eta) P'(eta) d eta = chi,   0 < chi <= lambda.                      (17.11)
//! Discretisation: P'(eta) = tan(eta) F(eta), F the polynomial through its values at the N
//! Chebyshev points eta_j of (0, lambda) (barycentric form), collocated at chi_i = eta_i: N
//! equations, solved by least squares (square). The factor tan(eta) carries the pole of P' at full
//! contact eta = pi/2 (Kuznetsov: F = pi; with eta F the nodes converge like 2.9^-N at
//! lambda = 1.2, the pole's Bernstein ellipse). The kernel is never needed at a new contact: in the tangent
//! variable W(chi, eta) = G(tan(chi)/tan(eta), eta)/tan(eta), G(T, eta) = H\[S2^eta\](T), whose
//! singular point T = 1 does not move with eta, so G is interpolated in eta at fixed T from the
//! increments solved at the same N points (each at its own stick edge), as G cos(eta), which
//! has no pole at eta = pi/2 (Kuznetsov: G cos(eta) = 1/(pi sqrt(T^2 - 1)), independent of eta). The integral over eta is
//! tanh-sinh on (0, chi_i) ([`DoubleExp`], end singularity (chi - eta)^(-1/2 + theta0)), and
//! P(lambda) = int_0^lambda tan(eta) F(eta) d eta by the same rule. The stick ratio at lambda is solved
//! there ([`super::spectral_row`]). Verified digits come from two runs (N and n raised).

use super::quadrature::{graded, least_squares, DoubleExp};
use super::real::Real;
use super::spectral::{Spectral, SpectralIncrement};
use crate::growing_contact::error::AdhesionError;

/// The increment at contact eta: the method and the solved increment at its stick edge.
pub type RowIncrement<T> = (Spectral<T>, SpectralIncrement<T>);

/// P(lambda) = P2/(E* k (L/pi)^2) on `nodes` Chebyshev points, the increments at contact eta
/// from `increment_at` (with the exponent theta0 = atan(beta mu)/pi for the quadrature).
pub fn load<T: Real>(
    lambda: &T,
    theta0: f64,
    nodes: usize,
    increment_at: impl Fn(&T) -> Result<RowIncrement<T>, AdhesionError>,
) -> Result<T, AdhesionError> {
    let one = lambda.lit(1.0);
    let zero = lambda.lit(0.0);
    let pi = lambda.pi();
    let nf = lambda.lit(nodes as f64);
    // Chebyshev points of the first kind on (0, lambda) and their barycentric weights
    let mut eta = Vec::with_capacity(nodes);
    let mut bary = Vec::with_capacity(nodes);
    for j in 0..nodes {
        let th = pi.clone() * lambda.lit((2 * j + 1) as f64) / (lambda.lit(2.0) * nf.clone());
        let s = (th.clone() * lambda.lit(0.5)).sin();
        eta.push(lambda.clone() * s.clone() * s);
        let sign = if j % 2 == 0 { one.clone() } else { -one.clone() };
        bary.push(sign * th.sin());
    }
    let incs: Vec<RowIncrement<T>> = eta.iter().map(&increment_at).collect::<Result<_, _>>()?;
    let cosines: Vec<T> = eta.iter().map(|e| e.cos()).collect();
    // the Lagrange basis at e
    let basis = |e: &T| -> Vec<T> {
        if let Some(k) = eta.iter().position(|x| x == e) {
            return (0..nodes).map(|j| if j == k { one.clone() } else { zero.clone() }).collect();
        }
        let terms: Vec<T> = (0..nodes).map(|j| bary[j].clone() / (e.clone() - eta[j].clone())).collect();
        let sum = terms.iter().fold(zero.clone(), |a, t| a + t.clone());
        terms.into_iter().map(|t| t / sum.clone()).collect()
    };
    let rule = DoubleExp::new(&one, 0.5 + theta0);
    let mut rows = Vec::with_capacity(nodes);
    let mut rhs = Vec::with_capacity(nodes);
    for chi in &eta {
        let mut row = vec![zero.clone(); nodes];
        rule.sweep(chi, &graded(&zero, chi, None, None), |d_a, d_b, w| {
            let e = d_a.clone();
            // T - 1 = sin(chi - eta)/(cos(chi) sin(eta)), without cancellation
            let beyond = d_b.sin() / (chi.cos() * e.sin());
            // eta underflowing to 0 (f64 tail nodes): W eta -> 0 there
            if !(beyond > zero && beyond < one.lit(1e300)) {
                return;
            }
            let l = basis(&e);
            let g = incs.iter().zip(&l).zip(&cosines).fold(zero.clone(), |acc, (((sp, inc), lj), cj)| {
                acc + lj.clone() * cj.clone() * sp.outside_slope(inc, &beyond)
            });
            // W tan(eta) = G = (G cos(eta))/cos(eta), P' = tan(eta) F
            let k = w.clone() * g / e.cos();
            for (r, lj) in row.iter_mut().zip(&l) {
                *r = r.clone() + k.clone() * lj.clone();
            }
        });
        rows.push(row);
        rhs.push(chi.clone());
    }
    let f = least_squares(rows, rhs).ok_or_else(|| AdhesionError::NotConverged {
        what: "periodic-row load (spectral Volterra collocation)",
        reason: "the collocation system is singular".into(),
    })?;
    let mut p = zero.clone();
    rule.sweep(lambda, &graded(&zero, lambda, None, None), |d_a, _, w| {
        let l = basis(d_a);
        let fe = l.iter().zip(&f).fold(zero.clone(), |a, (lj, fj)| a + lj.clone() * fj.clone());
        p = p.clone() + w.clone() * d_a.sin() / d_a.cos() * fe;
    });
    Ok(p)
}
