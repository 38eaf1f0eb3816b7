//! The Newton solve of one block of the march ([`super`], "Discretisation"): the block's 2 m
//! residuals (both edge equations at each of its m right-Radau points, divided by lambda: the
//! history's sum over the earlier blocks plus the current block's tanh-sinh part, less the
//! punch's slope G(chi_e), docs/theory.md section 10), Newton's iteration on the block's values
//! from the previous block's interpolant continued (at most 40 steps, the iterate of least
//! residual kept where the corrections stall at round-off), and the Jacobian by forward
//! differences for polynomial laws (the linear law's is in closed form, [`super::jacobian`]).
//! Tested through the march: `matches_the_collocation_values`, `single_punch_is_self_similar`
//! (module `super::tests`) and `closed_form_jacobian_equals_the_differences` ([`super::jacobian`]).

use super::history::{HistoryNodes, PartialNode};
use super::{jacobian, poly, recedes, March};
use crate::growing_contact::chebyshev_f64::cheb;
use crate::growing_contact::error::AdhesionError;
use crate::growing_contact::kernel_f64::{Side, C64};

impl March {
    /// [`Self::partial`] of the last block with its nodes at lambda tabled ([`Self::point_nodes`]).
    /// On each of `sides` at once: the divided difference of gamma, P' and n at a node serve both
    /// ends (the same values and sums as one side at a time; a side's result is its first error).
    fn partial_with(&self, sides: &[Side], lambda: f64, nodes: &[PartialNode]) -> [Result<C64, AdhesionError>; 2] {
        let b = &self.blocks[self.blocks.len() - 1];
        let span = lambda - b.start;
        let (tilt, kernel) = (self.setting.tilt, &self.setting.kernel);
        let mut acc = [C64::new(0.0, 0.0); 2];
        let mut failed = [false; 2];
        let ul = b.u(lambda);
        let gm_l = cheb(&b.g, ul);
        for q in nodes {
            let e = b.gamma_dd_at(ul, gm_l, q.eta);
            let (ratio, pp) = (self.ratio_in(b, q.eta), b.p_prime(q.eta));
            for (i, &side) in sides.iter().enumerate() {
                if failed[i] {
                    continue;
                }
                let d = q.gap * (1.0 + side.sign() * e);
                if d.is_nan() || d <= 0.0 {
                    failed[i] = true;
                    continue;
                }
                acc[i] += kernel.increment_outside_node(&q.factors, side, d, q.eta, ratio, tilt) * pp * q.weight;
            }
        }
        let side_result = |i: usize| match sides.get(i) {
            Some(&side) if failed[i] => Err(recedes(side, lambda)),
            _ => Ok(acc[i] * span),
        };
        [side_result(0), side_result(1)]
    }

    /// The residuals (2 per point: leading, trailing) of the last block, divided by lambda, the
    /// history integrals (for the Jacobian) and the edge integrals' imaginary parts, psi_hat at
    /// the points' ends (for [`Self::psi_hat_integrals`]).
    #[allow(clippy::type_complexity)]
    pub(super) fn residual(
        &self,
        lambdas: &[f64],
        gammas: &[f64],
        with_history: Option<&[[C64; 2]]>,
        nodes: &[HistoryNodes],
    ) -> Result<(Vec<f64>, Vec<[C64; 2]>, Vec<[f64; 2]>), AdhesionError> {
        let k = self.blocks.len() - 1;
        let sides: &[Side] = if self.setting.symmetric() { &[Side::Right] } else { &[Side::Right, Side::Left] };
        let mut out = Vec::with_capacity(sides.len() * lambdas.len());
        let mut hist = Vec::with_capacity(lambdas.len());
        let mut ims = Vec::with_capacity(lambdas.len());
        for (j, (&lam, &gl)) in lambdas.iter().zip(gammas).enumerate() {
            let mut h = [C64::new(0.0, 0.0); 2];
            let mut im = [0.0; 2];
            let mut parts = (!nodes[j].partial.is_empty()).then(|| self.partial_with(sides, lam, &nodes[j].partial));
            for (i, &side) in sides.iter().enumerate() {
                h[i] = match with_history {
                    Some(hs) => hs[j][i],
                    None => self.history_at(&nodes[j], side, gl)?,
                };
                let part = match parts.as_mut() {
                    Some(p) => std::mem::replace(&mut p[i], Ok(C64::new(0.0, 0.0)))?,
                    None => self.partial(side, lam, k)?,
                };
                let total = h[i] + part;
                im[i] = total.im;
                out.push((total.re - poly(&self.setting.profile, gl + side.sign() * lam)) / lam);
            }
            hist.push(h);
            ims.push(im);
        }
        Ok((out, hist, ims))
    }
}

/// Newton for the last block's values from `x` (at most 40 steps): Ok(true) converged (the
/// block installed), Ok(false) not within 40 steps; with the closed-form Jacobian ([`jacobian`])
/// or by differences.
pub(super) fn newton(
    mar: &mut March,
    mut x: Vec<f64>,
    lambdas: &[f64],
    nodes: &[HistoryNodes],
    closed: bool,
    install: &dyn Fn(&mut March, &[f64]),
) -> Result<bool, AdhesionError> {
    let m = lambdas.len();
    let symmetric = x.len() == m;
    // The Jacobian's LU factors, kept while the Jacobian is (the same factors each step).
    let mut jac: Option<nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>> = None;
    let mut previous = f64::INFINITY;
    let mut done = false;
    // Near round-off the corrections stall at the noise of the residual times the
    // conditioning (small nu: ~1e-12); then the iterate of least residual is kept.
    let mut best = (f64::INFINITY, x.clone(), Vec::new());
    // psi_hat at the points from the last residual (the iterate before the last correction).
    let mut last_ims: Vec<[f64; 2]> = Vec::new();
    let mut stalls = 0;
    for _ in 0..40 {
        mar.steps += 1;
        let gammas: Vec<f64> =
            if symmetric { vec![0.0; m] } else { lambdas.iter().zip(&x[m..]).map(|(l, g)| l * g).collect() };
        let (r, hist, ims) = mar.residual(lambdas, &gammas, None, nodes)?;
        let rmax = r.iter().fold(0f64, |a, v| a.max(v.abs()));
        if rmax < best.0 {
            best = (rmax, x.clone(), ims.clone());
        }
        last_ims = ims;
        if jac.is_none() {
            jac = Some(
                if closed {
                    jacobian::closed_form_jacobian(mar, &x, lambdas, &gammas, &hist, nodes)?
                } else {
                    jacobian_by_differences(mar, &x, lambdas, &gammas, &r, &hist, nodes, install)?
                }
                .lu(),
            );
            install(mar, &x);
        }
        let lu = jac.as_ref().expect("set above");
        let delta = lu.solve(&nalgebra::DVector::from_column_slice(&r)).ok_or(AdhesionError::NotConverged {
            what: "loading-law march Newton",
            reason: "singular Jacobian".into(),
        })?;
        let size = delta.iter().fold(0f64, |a, v| a.max(v.abs()));
        for (xi, d) in x.iter_mut().zip(delta.iter()) {
            *xi -= d;
        }
        install(mar, &x);
        if !size.is_finite() {
            break;
        }
        let scale = x.iter().fold(1f64, |a, v| a.max(v.abs()));
        if size < 4e-15 * scale {
            done = true;
            break;
        }
        if size < 1e-9 * scale {
            if size > 0.3 * previous {
                stalls += 1;
            }
            if stalls >= 3 {
                x = best.1.clone();
                last_ims = best.2.clone();
                install(mar, &x);
                done = true;
                break;
            }
        } else if size > 0.1 * previous {
            jac = None;
        }
        previous = size;
    }
    if done && !symmetric {
        let k = mar.blocks.len() - 1;
        let side = |i: usize| mar.rules.coefficients(&last_ims.iter().map(|v| v[i]).collect::<Vec<f64>>());
        mar.psi[k] = Some([side(0), side(1)]);
    }
    Ok(done)
}

/// The Jacobian of the last block's residuals: the block's own part by forward differences in
/// each value, the history's by one difference in gamma(lambda) per point (for polynomial laws,
/// whose ratio n moves with the block's load; the linear law's is in closed form, [`jacobian`]).
#[allow(clippy::too_many_arguments)]
fn jacobian_by_differences(
    mar: &mut March,
    x: &[f64],
    lambdas: &[f64],
    gammas: &[f64],
    r: &[f64],
    hist: &[[C64; 2]],
    nodes: &[HistoryNodes],
    install: &dyn Fn(&mut March, &[f64]),
) -> Result<nalgebra::DMatrix<f64>, AdhesionError> {
    let m = lambdas.len();
    // x holds m values (symmetric: F only) or 2 m (F and Gm); as many equations.
    let q = x.len();
    let mut jac = nalgebra::DMatrix::zeros(q, q);
    for i in 0..q {
        let step = 1e-7 * (1.0 + x[i].abs());
        let mut xp = x.to_vec();
        xp[i] += step;
        install(mar, &xp);
        let gp: Vec<f64> =
            if q == m { gammas.to_vec() } else { lambdas.iter().zip(&xp[m..]).map(|(l, g)| l * g).collect() };
        // The history at the unperturbed gamma: its dependence is added below.
        let (rp, _, _) = mar.residual(lambdas, &gp, Some(hist), nodes)?;
        for row in 0..q {
            jac[(row, i)] = (rp[row] - r[row]) / step;
        }
        // The residual above moved G(chi_e) with gamma; the history's share is added here.
        if i >= m {
            let j = i - m;
            for (s, side) in [Side::Right, Side::Left].into_iter().enumerate() {
                let lam = lambdas[j];
                let dg = 1e-7 * lam.max(1e-300);
                let hp = mar.history_at(&nodes[j], side, gammas[j] + dg)?;
                // d(history)/d gamma times d gamma/d g (= lambda), over lambda.
                jac[(2 * j + s, i)] += (hp.re - hist[j][s].re) / dg;
            }
        }
    }
    Ok(jac)
}
