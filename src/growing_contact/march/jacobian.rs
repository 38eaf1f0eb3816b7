//! The Newton Jacobian of one block's residuals ([`super`], "Discretisation") in closed form,
//! where the law's ratio n = N'(P2) is constant (the linear law).
//!
//! Residual of point j, side s: r = [Re(H + Q) - G(gl + s lambda)]/lambda, with H the history
//! (the earlier blocks; it depends on the unknowns only through gl = gamma(lambda) = lambda
//! Gm_j) and Q the current block's part, the tanh-sinh sum
//!   Q = span sum_q w_q K(d_q; eta_q) P'(eta_q),   P'(eta) = eta sum_i f_i T_i(u(eta)),
//!   d_q = span c_q (1 + s E_q),   E_q = sum_i g_i [T_i(u_l) + eta_q D_i(u_l, u_q) 2/h],
//! K the increment's slope (1 + i n) (L K + i beta R) and D_i = (T_i(x) - T_i(y))/(x - y) (the
//! divided difference of [`super::Block::gamma_dd`]). Q is linear in the coefficients f_i:
//!   dQ/df_i = span sum_q w_q K_q eta_q T_i(u_q),
//! and depends on g_i through d_q alone:
//!   dQ/dg_i = span sum_q w_q K'(d_q) P'(eta_q) span c_q s [T_i(u_l) + eta_q D_i 2/h],
//! K' the derivative in d ([`KernelF64::increment_with_derivative`]). The coefficients are
//! the values' images under the block's Chebyshev matrix, so the columns of the values follow by
//! one matrix product. The history's dH/dgl stays a difference in gl (one history per point and
//! side, as before), and G(gl + s lambda) adds -G'(gl + s lambda) to the column of Gm_j.
//!
//! Against central differences in every value (step 1e-7): equal to 4e-10 of the largest entry
//! (test `closed_form_jacobian_equals_the_differences`); the march's forward differences
//! (`newton::jacobian_by_differences`, kept for polynomial laws, where n moves with the block's
//! load) err by about 1e-5 in the columns of Gm. The cost is about one residual instead of one per
//! unknown (the differences took two thirds of the f64 loading law's kernel evaluations on the
//! shipped scene: 1.27 of 1.88 million in its two marches).

use super::{poly, recedes, HistoryNodes, March, PartialNode};
use crate::growing_contact::chebyshev_f64::cheb;
use crate::growing_contact::error::AdhesionError;
use crate::growing_contact::kernel_f64::{KernelF64, Side, C64};

impl March {
    /// d Re Q/d f_i and d Re Q/d g_i (module doc) of the last block at the size `lambda` on
    /// `side`, added into `df` and `dg` (length m each).
    fn partial_gradient(
        &self,
        side: Side,
        lambda: f64,
        nodes: &[PartialNode],
        df: &mut [f64],
        dg: &mut [f64],
    ) -> Result<(), AdhesionError> {
        let k = self.blocks.len() - 1;
        let b = &self.blocks[k];
        let sg = side.sign();
        let span = lambda - b.start;
        let n = self.setting.ratio(0.0);
        let kern: &KernelF64 = &self.setting.kernel;
        let m = df.len();
        let ul = b.u(lambda);
        // T_i(u_l).
        let mut tl = vec![0.0; m];
        chebyshev_values(ul, &mut tl);
        let gm_l = cheb(&b.g, ul);
        let (mut tq, mut dd) = (vec![0.0; m], vec![0.0; m]);
        for q in nodes {
            let (gap, eta, w) = (q.gap, q.eta, q.weight);
            let uq = b.u(eta);
            let d = gap * (1.0 + sg * b.gamma_dd_at(ul, gm_l, eta));
            if d.is_nan() || d <= 0.0 {
                return Err(recedes(side, lambda));
            }
            let (kv, kd) = kern.increment_with_derivative_node(&q.factors, side, d, eta, n, self.setting.tilt);
            chebyshev_values(uq, &mut tq);
            divided_differences(ul, &tq, &mut dd);
            let pp = b.p_prime(eta);
            let wf = kv * (w * span * eta);
            let wg = kd * (w * span * pp * gap * sg);
            for i in 0..m {
                df[i] += (wf * tq[i]).re;
                dg[i] += (wg * (tl[i] + eta * dd[i] * 2.0 / b.h)).re;
            }
        }
        Ok(())
    }
}

/// T_i(x), i < out.len().
fn chebyshev_values(x: f64, out: &mut [f64]) {
    let (mut prev, mut cur) = (1.0, x);
    for (i, o) in out.iter_mut().enumerate() {
        *o = match i {
            0 => 1.0,
            1 => x,
            _ => {
                let next = 2.0 * x * cur - prev;
                prev = cur;
                cur = next;
                next
            }
        };
    }
}

/// D_i = (T_i(x) - T_i(y))/(x - y) from T_i(y) = `ty[i]`, by D_(i+1) = 2 x D_i + 2 T_i(y) -
/// D_(i-1), D_0 = 0, D_1 = 1 (as [`super::super::chebyshev_f64`]'s divided difference).
fn divided_differences(x: f64, ty: &[f64], out: &mut [f64]) {
    let m = out.len();
    if m == 0 {
        return;
    }
    out[0] = 0.0;
    if m > 1 {
        out[1] = 1.0;
    }
    for i in 1..m.saturating_sub(1) {
        out[i + 1] = 2.0 * x * out[i] + 2.0 * ty[i] - out[i - 1];
    }
}

/// The Jacobian of the last block's residuals in the values `x` (m of F, then m of Gm unless
/// symmetric) at `lambdas`, `gammas`, with the history integrals `hist` at them (module doc).
pub(super) fn closed_form_jacobian(
    mar: &March,
    x: &[f64],
    lambdas: &[f64],
    gammas: &[f64],
    hist: &[[C64; 2]],
    nodes: &[HistoryNodes],
) -> Result<nalgebra::DMatrix<f64>, AdhesionError> {
    let m = lambdas.len();
    let q = x.len();
    let sides: &[Side] = if q == m { &[Side::Right] } else { &[Side::Right, Side::Left] };
    // Rows: (point, side); columns: the coefficients f_i, then g_i.
    let mut by_coefficient = nalgebra::DMatrix::zeros(q, q);
    let (mut df, mut dg) = (vec![0.0; m], vec![0.0; m]);
    let profile_slope: Vec<f64> = mar.setting.profile.iter().enumerate().skip(1).map(|(j, p)| j as f64 * p).collect();
    let mut extra = vec![0.0; q];
    for (j, &lam) in lambdas.iter().enumerate() {
        for (i, &side) in sides.iter().enumerate() {
            df.iter_mut().chain(dg.iter_mut()).for_each(|v| *v = 0.0);
            mar.partial_gradient(side, lam, &nodes[j].partial, &mut df, &mut dg)?;
            let row = sides.len() * j + i;
            for c in 0..m {
                by_coefficient[(row, c)] = df[c] / lam;
                if q > m {
                    by_coefficient[(row, m + c)] = dg[c] / lam;
                }
            }
            if q > m {
                // The history's dH/dgl by a difference in gl, and -G'(gl + s lambda).
                let dgl = 1e-7 * lam.max(1e-300);
                let hp = mar.history_at(&nodes[j], side, gammas[j] + dgl)?;
                extra[row] = (hp.re - hist[j][i].re) / dgl - poly(&profile_slope, gammas[j] + side.sign() * lam);
            }
        }
    }
    // Values -> coefficients: f = C x_F, g = C x_G.
    let to_cheb = &mar.rules.to_cheb;
    let mut jac = nalgebra::DMatrix::zeros(q, q);
    jac.columns_mut(0, m).copy_from(&(by_coefficient.columns(0, m) * to_cheb));
    if q > m {
        jac.columns_mut(m, m).copy_from(&(by_coefficient.columns(m, m) * to_cheb));
        for j in 0..m {
            for i in 0..sides.len() {
                let row = sides.len() * j + i;
                jac[(row, m + j)] += extra[row];
            }
        }
    }
    Ok(jac)
}

#[cfg(test)]
mod tests {
    use super::super::{march, MarchEnd, MarchOptions};
    use super::*;

    /// The closed form against central differences in every value (step 1e-7, the history's
    /// share by its difference in gl as the closed form takes it), at the last block of a march to
    /// lambda = 0.3 (nu = 0.3, n = 1/5, periodic row; `paper` and `periodic` conventions, the latter
    /// with the tilted punch), rows leading and trailing: equal to 1e-8 of the largest entry
    /// (measured 4e-10).
    #[test]
    fn closed_form_jacobian_equals_the_differences() {
        for tilt in [false, true] {
            let s = super::super::tests::test_setting(tilt);
            let mut mar = march(&s, &MarchOptions::NOMINAL, MarchEnd::Size(0.3)).unwrap();
            let k = mar.blocks.len() - 1;
            let b = mar.blocks[k].clone();
            let lambdas: Vec<f64> = mar.rules.radau.iter().map(|u| b.start + b.h * (1.0 + u) / 2.0).collect();
            let x: Vec<f64> =
                lambdas.iter().map(|l| b.p_prime(*l) / l).chain(lambdas.iter().map(|l| b.gamma(*l) / l)).collect();
            let gammas: Vec<f64> = lambdas.iter().map(|l| b.gamma(*l)).collect();
            let table: Vec<HistoryNodes> = lambdas.iter().map(|&l| mar.point_nodes(l, k, b.start)).collect();
            let (_, hist, _) = mar.residual(&lambdas, &gammas, None, &table).unwrap();
            let closed = closed_form_jacobian(&mar, &x, &lambdas, &gammas, &hist, &table).unwrap();
            let (start, h, load_start) = (b.start, b.h, mar.blocks[k - 1].load_at(b.start));
            let nodes = lambdas.len();
            let install = |mar: &mut March, x: &[f64]| {
                let g = mar.rules.coefficients(&x[nodes..]);
                mar.blocks[k] = super::super::Block::new(start, h, mar.rules.coefficients(&x[..nodes]), g, load_start);
            };
            // Central differences (the march's forward ones err by about 1e-5 in the columns of Gm,
            // their second-order term) and the history's share as the closed form takes it.
            let central = |i: usize, h: f64, mar: &mut March| {
                let mut column = vec![0.0; 2 * nodes];
                for sign in [1.0, -1.0] {
                    let mut xp = x.clone();
                    xp[i] += sign * h;
                    install(mar, &xp);
                    let gp: Vec<f64> = lambdas.iter().zip(&xp[nodes..]).map(|(l, g)| l * g).collect();
                    let (rp, _, _) = mar.residual(&lambdas, &gp, Some(&hist), &table).unwrap();
                    for (c, v) in column.iter_mut().zip(rp) {
                        *c += sign * v / (2.0 * h);
                    }
                }
                column
            };
            let mut diff = nalgebra::DMatrix::zeros(2 * nodes, 2 * nodes);
            for i in 0..2 * nodes {
                let column = central(i, 1e-7 * (1.0 + x[i].abs()), &mut mar);
                for (row, v) in column.into_iter().enumerate() {
                    diff[(row, i)] = v;
                }
                if i >= nodes {
                    let j = i - nodes;
                    for (side_index, side) in [Side::Right, Side::Left].into_iter().enumerate() {
                        let dgl = 1e-7 * lambdas[j];
                        let hp = mar.history(side, lambdas[j], gammas[j] + dgl, k).unwrap();
                        diff[(2 * j + side_index, i)] += (hp.re - hist[j][side_index].re) / dgl;
                    }
                }
            }
            install(&mut mar, &x);
            let scale = diff.iter().fold(0f64, |a, v| a.max(v.abs()));
            let err = (&closed - &diff).iter().fold(0f64, |a, v| a.max(v.abs()));
            assert!(err < 1e-8 * scale, "tilt {tilt}: {err:e} of {scale:e}");
        }
    }
}
