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
//!
//! The solver uses [`jacobian_f64`]: every term in `f64` (the state, the rule and the kernels of
//! [`crate::growing_contact::kernel_f64`] with K's log derivative; the tilted punch's derivative
//! by a central difference of relative step 1e-5 in d), cheap enough to take on the working
//! discretisation's own rule, where the MPFR one at 64 bits on a coarse rule it replaced
//! contracted the chord iteration only by 0.06 at its first step (docs/performance.md, "The
//! loading law", round three). The same matrix at `prec` bits with the MPFR kernels,
//! `mpfr::jacobian`, is checked against central differences of the residual, and the `f64` one
//! against it; the collocation falls back to it at 64 bits on a coarse rule where the `f64` one's
//! chord iteration does not contract (nu = 0 near the homogeneous mode).

use super::increment::Increment;
use crate::growing_contact::chebyshev_f64::{cheb, cheb_antiderivative, cheb_dd, cheb_times_x};
use crate::growing_contact::error::AdhesionError;
use crate::growing_contact::kernel::Row;
use crate::growing_contact::kernel_f64::{self, KernelF64, C64};
use crate::numerics::chebyshev;
use crate::numerics::tanh_sinh::TanhSinh;
use rug::Float;

/// The Jacobian in `f64` (module doc): the same rows and columns at `state`, on `rule`, without
/// the MPFR kernels (the rule's s, 1 - s and weights rounded to `f64`); the nodes' rows on every
/// CPU.
pub(super) fn jacobian_f64(
    rule: &TanhSinh,
    inc: &Increment,
    lambda_max: &Float,
    nodes: &[Float],
    state: &[Float],
) -> Result<Vec<Vec<f64>>, AdhesionError> {
    let n_nodes = nodes.len();
    let prec = state.first().map_or(64, Float::prec);
    let to_f64 = |v: &[Float]| v.iter().map(Float::to_f64).collect::<Vec<f64>>();
    let phi_c = to_f64(&chebyshev::coefficients(&state[..n_nodes], prec));
    let gam_c = to_f64(&chebyshev::coefficients(&state[n_nodes..], prec));
    let gam = to_f64(&state[n_nodes..]);
    let ts_nodes = to_f64(nodes);
    let (s_q, c_q, w_q) = (to_f64(&rule.s), to_f64(&rule.c), to_f64(&rule.w));
    let kernel = KernelF64 {
        eps: inc.eps.to_f64(),
        cosh_pi_eps: inc.cosh_pi_eps.to_f64(),
        beta: inc.beta.to_f64(),
        single: inc.row == Row::Single,
    };
    let lambda_max = lambda_max.to_f64();
    let slope = to_f64(&inc.slope);
    let p2_per_p = inc.p2_per_p.to_f64();
    // P(Lambda t)/Lambda^2 = int_0^t t' Phi(t') dt' = (1/2) A(2 t - 1), A the antiderivative from
    // -1 of t Phi = (x Phi + Phi)/2 (for n = N'(P2) along a polynomial law).
    let load_c = (!inc.constant_ratio()).then(|| {
        let mut tp = cheb_times_x(&phi_c);
        tp.iter_mut().zip(&phi_c).for_each(|(a, b)| *a += b);
        cheb_antiderivative(&tp.iter().map(|v| v / 2.0).collect::<Vec<_>>())
    });
    let ratio = |ts: f64| {
        let p = load_c.as_ref().map_or(0.0, |a| cheb(a, 2.0 * ts - 1.0) / 2.0 * lambda_max * lambda_max);
        slope.iter().rev().fold(0.0, |acc, c| acc * p * p2_per_p + c)
    };
    let weights: Vec<f64> = ts_nodes
        .iter()
        .enumerate()
        .map(|(j, t)| (t * (1.0 - t)).sqrt() * if j % 2 == 0 { 1.0 } else { -1.0 })
        .collect();
    let rows = crate::numerics::parallel::map(&ts_nodes, |i, &t| -> Result<[Vec<f64>; 2], AdhesionError> {
        let mut ell = vec![0.0; n_nodes];
        let lambda = lambda_max * t;
        let xt = 2.0 * t - 1.0;
        let (mut lead, mut trail) = (vec![0f64; 2 * n_nodes], vec![0f64; 2 * n_nodes]);
        for q in 0..s_q.len() {
            let (s, c, w) = (s_q[q], c_q[q], w_q[q]);
            let (ts, eta) = (t * s, lambda * s);
            let xs = 2.0 * ts - 1.0;
            let phi = cheb(&phi_c, xs);
            let e = gam[i] + 2.0 * ts * cheb_dd(&gam_c, xt, xs);
            cardinals_f64(&ts_nodes, &weights, ts, &mut ell);
            let rest: f64 = ell.iter().enumerate().filter(|(k, _)| *k != i).map(|(_, v)| v).sum();
            let n = ratio(ts);
            let ws = w * s * lambda;
            for (row, side, sign) in
                [(&mut lead, kernel_f64::Side::Right, 1.0), (&mut trail, kernel_f64::Side::Left, -1.0)]
            {
                let factor = 1.0 + sign * e;
                if factor <= 0.0 || factor.is_nan() {
                    let lam = Float::with_val(53, lambda);
                    super::increment::advance_factor(&Float::with_val(53, e), sign as i32, &lam)?;
                }
                let d = lambda * c * factor;
                let k = kernel.increment_outside(side, d, eta, n, inc.periodic);
                let mut dk = kernel.outside(side, d, eta) * kernel.outside_log_derivative(side, d, eta);
                if inc.periodic {
                    let h = 1e-5 * d;
                    let slope =
                        (kernel.tilt_outside(side, d + h, eta) - kernel.tilt_outside(side, d - h, eta)) / (2.0 * h);
                    dk += slope * C64::new(0.0, kernel.beta);
                }
                let dk = dk * C64::new(1.0, n);
                let wk = k.re * ws;
                let wdk = dk.re * ws * phi * lambda * sign;
                for j in 0..n_nodes {
                    row[j] += wk * ell[j];
                    let de = if j == i { s * rest + c } else { -s * ell[j] };
                    row[n_nodes + j] += wdk * de;
                }
            }
        }
        Ok([lead, trail])
    });
    let mut jac = vec![Vec::new(); 2 * n_nodes];
    for (i, pair) in rows.into_iter().enumerate() {
        for (r, row) in pair?.into_iter().enumerate() {
            jac[2 * i + r] = row;
            jac[2 * i + r][n_nodes + i] -= std::f64::consts::PI;
        }
    }
    Ok(jac)
}

/// The cardinal functions of `nodes` (barycentric `weights`) at y into `out` (exact 1 at a node).
fn cardinals_f64(nodes: &[f64], weights: &[f64], y: f64, out: &mut [f64]) {
    if let Some(j) = nodes.iter().position(|t| *t == y) {
        out.iter_mut().enumerate().for_each(|(k, v)| *v = f64::from(u8::from(k == j)));
        return;
    }
    let mut total = 0.0;
    for ((t, w), v) in nodes.iter().zip(weights).zip(out.iter_mut()) {
        *v = w / (y - t);
        total += *v;
    }
    out.iter_mut().for_each(|v| *v /= total);
}

/// The matrix at `prec` bits with the MPFR kernels: the chord Jacobian of the collocation's
/// fallback at 64 bits on a coarse rule (where the `f64` one's iteration does not contract), and
/// the reference the `f64` one is checked against (itself checked against central differences of
/// the residual).
pub(super) mod mpfr {
    use super::super::increment::{divided_difference_series, Increment, SizeTerms};
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
    /// [`super::super::increment::size_terms`]), at `prec` bits; the nodes' rows on every CPU.
    pub(in crate::loading_law) fn jacobian(
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
        let tphi = (!inc.constant_ratio()).then(|| super::super::increment::times_t(&phi_c, prec));
        let l2max = Float::with_val(prec, lambda_max.square_ref());
        let weights = barycentric_weights(nodes, prec);
        let factors =
            |n: &Float| (Complex::with_val(prec, (1, n)), super::super::increment::periodic_factor(&inc.beta, n, prec));
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
                    let factor = super::super::increment::advance_factor(&e, sign, &lambda)?;
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
}
