//! The Jacobian of the collocation residual ([`super::collocation`]) in closed form, for its
//! chord Newton: one pass over the nodes and the rule instead of one residual per unknown.
//!
//! With the Lagrange cardinal functions l_j of the nodes (barycentric, first-kind Chebyshev
//! weights w_j = (-1)^j sqrt(t_j (1 - t_j))), Phi(t s) = sum_j l_j(t s) Phi_j, and the residual at
//! node t_i, side +- (leading, trailing),
//!   R_i = Re lambda sum_q w_q s_q Phi(t_i s_q) k(d_q) - pi (Gam_i +- 1),
//!   d_q = lambda c_q (1 +- E_q),  E_q = Gam(t_i) + s_q t_i [Gam(t_i) - Gam(t_i s_q)]/(t_i c_q),
//! (c_q = 1 - s_q) has
//!   dR_i/dPhi_j = Re lambda sum_q w_q s_q l_j(t_i s_q) k(d_q),
//!   dR_i/dGam_j = Re lambda sum_q w_q s_q Phi(t_i s_q) k'(d_q) (+- lambda) [c_q delta_ij
//!                 + s_q (delta_ij - l_j(t_i s_q))] - pi delta_ij,
//! where delta_ii - l_i(y) is summed as sum_(k != i) l_k(y) (no cancellation as y -> t_i), and
//! k' = k d ln k/d d from [`crate::growing_contact::kernel::outside_kernel_log_derivative`] and
//! [`crate::growing_contact::kernel::TiltedPunch::outside_log_derivative`]. For a polynomial law the dependence of
//! n = N'(P2) on Phi is left out (a chord Jacobian; the iteration still converges, more slowly
//! when N'' P2 is not small). Checked against finite differences in the tests.

use super::increment::{divided_difference_series, Increment, SizeTerms};
use crate::growing_contact::error::AdhesionError;
use crate::growing_contact::kernel::Side;
use crate::numerics::chebyshev;
use crate::numerics::tanh_sinh::TanhSinh;
use rug::float::Constant;
use rug::{Complex, Float};

/// The barycentric weights w_j = (-1)^j sqrt(t_j (1 - t_j)) of `nodes` (first-kind Chebyshev
/// points on [0, 1]).
fn barycentric_weights(nodes: &[Float], prec: u32) -> Vec<Float> {
    nodes
        .iter()
        .enumerate()
        .map(|(j, t)| {
            let w = Float::with_val(prec, t * Float::with_val(prec, 1u32 - t)).sqrt();
            if j % 2 == 0 {
                w
            } else {
                -w
            }
        })
        .collect()
}

/// The cardinal functions l_j(y) of `nodes` with barycentric `weights` at y, by the barycentric
/// formula (exact 1 at a node).
fn cardinals(nodes: &[Float], weights: &[Float], y: &Float, prec: u32) -> Vec<Float> {
    let mut terms = Vec::with_capacity(nodes.len());
    for (j, (t, w)) in nodes.iter().zip(weights).enumerate() {
        let diff = Float::with_val(prec, y - t);
        if diff.is_zero() {
            return (0..nodes.len()).map(|k| Float::with_val(prec, u32::from(k == j))).collect();
        }
        terms.push(Float::with_val(prec, w / diff));
    }
    let total = terms.iter().fold(Float::with_val(prec, 0), |acc, v| acc + v);
    terms.into_iter().map(|v| v / &total).collect()
}

/// J (rows: leading then trailing residual per node; columns: Phi values then Gam values) at
/// `state` (Phi values, then Gam values at `nodes`), on `rule` (`sizes` its
/// [`super::increment::size_terms`]), at `prec` bits; the nodes' rows on every CPU.
pub(super) fn jacobian(
    rule: &TanhSinh,
    inc: &Increment,
    lambda_max: &Float,
    nodes: &[Float],
    sizes: &[Vec<SizeTerms>],
    state: &[Float],
    prec: u32,
) -> Result<Vec<Vec<f64>>, AdhesionError> {
    let n_nodes = nodes.len();
    let phi_c = chebyshev::coefficients(&state[..n_nodes], prec);
    let gam_c = chebyshev::coefficients(&state[n_nodes..], prec);
    let pi = Float::with_val(prec, Constant::Pi);
    let mut jac = vec![vec![0.0; 2 * n_nodes]; 2 * n_nodes];
    let tphi = (!inc.constant_ratio()).then(|| super::increment::times_t(&phi_c, prec));
    let l2max = Float::with_val(prec, lambda_max.square_ref());
    let weights = barycentric_weights(nodes, prec);
    let factors = |n: &Float| (Complex::with_val(prec, (1, n)), super::increment::periodic_factor(&inc.beta, n, prec));
    let constant = factors(&inc.ratio_at(&Float::with_val(prec, 0)));
    let rows = crate::numerics::parallel::map(nodes, |i, t| -> Result<[Vec<f64>; 2], AdhesionError> {
        let lambda = Float::with_val(prec, lambda_max * t);
        let xt = Float::with_val(prec, t * 2u32) - 1u32;
        let dd_c = divided_difference_series(&gam_c, &xt, prec);
        let gam_t = &state[n_nodes + i];
        // The rows (real parts: the residual is Re of the edge integral) accumulate in f64: J is
        // only the chord iteration's matrix, used in f64 (`solve_f64`); the kernels and their
        // derivatives stay at `prec`.
        let (mut lead, mut trail) = (vec![0f64; 2 * n_nodes], vec![0f64; 2 * n_nodes]);
        for (q, SizeTerms { size, tilt }) in sizes[i].iter().enumerate() {
            let (s, c, w) = (&rule.s[q], &rule.c[q], &rule.w[q]);
            let ts = Float::with_val(prec, t * s);
            let xs = Float::with_val(prec, &ts * 2u32) - 1u32;
            let phi = chebyshev::evaluate(&phi_c, &xs, prec);
            let dd = chebyshev::evaluate(&dd_c, &xs, prec) * 2u32;
            let e = Float::with_val(prec, gam_t + Float::with_val(prec, &ts * &dd));
            let ell: Vec<f64> = cardinals(nodes, &weights, &ts, prec).iter().map(Float::to_f64).collect();
            let rest: f64 = ell.iter().enumerate().filter(|(k, _)| *k != i).map(|(_, v)| v).sum();
            let (s64, c64) = (s.to_f64(), c.to_f64());
            let varying =
                tphi.as_ref().map(|tp| factors(&inc.ratio_at(&(chebyshev::integral(tp, &ts, prec) * &l2max))));
            let (one_in, tilt_factor) = varying.as_ref().unwrap_or(&constant);
            let ws = Float::with_val(prec, w * s) * &lambda;
            for (row, side, sign) in [(&mut lead, Side::Right, 1i32), (&mut trail, Side::Left, -1)] {
                let factor = super::increment::advance_factor(&e, sign, &lambda)?;
                let d = Float::with_val(prec, &lambda * c) * &factor;
                let point = size.point(side, &d);
                let mut k = size.kernel(&point) * one_in;
                let mut dk = Complex::with_val(prec, &k * &size.kernel_log_derivative(&point));
                if let Some(tilt) = tilt {
                    let value = tilt.outside_at(size, &point, &inc.cosh_pi_eps) * tilt_factor;
                    let log_t = tilt.outside_log_derivative_at(size, &point);
                    dk += Complex::with_val(prec, &value * &log_t);
                    k += value;
                }
                let wk = Complex::with_val(prec, &k * &ws);
                // d d/d Gam_j = +- lambda [c delta_ij + s (delta_ij - l_j)].
                let wdk = Complex::with_val(prec, &dk * &ws) * Float::with_val(prec, &phi * &lambda) * sign;
                let (wk, wdk) = (wk.real().to_f64(), wdk.real().to_f64());
                for j in 0..n_nodes {
                    row[j] += wk * ell[j];
                    let de = if j == i { s64 * rest + c64 } else { -s64 * ell[j] };
                    row[n_nodes + j] += wdk * de;
                }
            }
        }
        Ok([lead, trail])
    });
    for (i, pair) in rows.into_iter().enumerate() {
        // The rule's integral runs over s in (0, 1): d eta = lambda ds, already in ws.
        for (r, row) in pair?.into_iter().enumerate() {
            jac[2 * i + r] = row;
            jac[2 * i + r][n_nodes + i] -= pi.to_f64();
        }
    }
    Ok(jac)
}
