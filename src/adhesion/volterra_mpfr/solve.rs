//! The collocation solve of the Volterra equation at one lambda (module doc of
//! [`super`]): discretisation parameters, the a priori and adaptive Chebyshev size, the real
//! collocation system and its Gaussian elimination.

use super::kernel;
use super::right_side::RightSide;
use super::row_factors::{row_factors, FactorsKey};
use super::volterra::{JSource, VolterraSolution};
use crate::growing_contact::error::AdhesionError;
use crate::numerics::accuracy::{readable_f64, readable_mpfr};
use crate::numerics::chebyshev;
use crate::numerics::fixed_float::Fixed;
use crate::numerics::precision::{bits_for_digits, SOLVER_GUARD_BITS};
use crate::numerics::tanh_sinh::TanhSinh;
use crate::params::adhesion::AdhesionParamsMpfr;
use rug::{Assign, Float};
use std::sync::{Arc, OnceLock};

/// Largest collocation size accepted; beyond it lambda is too close to pi/2.
pub const MAX_NODES: usize = 320;

/// Discretisation of one run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VolterraParams {
    /// Working precision in bits.
    pub prec: u32,
    /// Target accuracy in bits (sets the node counts).
    pub target_bits: u32,
    /// Extra refinement of the quadrature step and the Chebyshev size (1 = nominal).
    pub refine: f64,
}

impl VolterraParams {
    /// Nominal parameters for `digits` decimal digits.
    pub fn for_digits(digits: u32) -> Self {
        let target_bits = bits_for_digits(digits) + 8;
        VolterraParams { prec: target_bits + SOLVER_GUARD_BITS, target_bits, refine: 1.0 }
    }
    /// The verification run: more bits, more nodes, finer quadrature.
    pub fn refined(&self) -> Self {
        VolterraParams { prec: self.prec + 24, target_bits: self.target_bits + 16, refine: self.refine * 1.15 }
    }
}

/// Chebyshev size for accuracy 2^-bits at this lambda (see module doc), or an error near pi/2.
pub fn chebyshev_size(lambda: f64, bits: u32, refine: f64) -> Result<usize, AdhesionError> {
    chebyshev_size_in(lambda, bits, refine, false)
}

/// [`chebyshev_size`] in either convention: `periodic` interpolates in sigma = eta/lambda, whose
/// singularity at full contact lies at sigma = pi/(2 lambda) (z = pi/lambda - 1), not at
/// tau = sigma^2 = (pi/(2 lambda))^2.
pub fn chebyshev_size_in(lambda: f64, bits: u32, refine: f64, periodic: bool) -> Result<usize, AdhesionError> {
    if lambda <= 0.0 {
        return Ok(2);
    }
    let half_pi = std::f64::consts::FRAC_PI_2;
    let tau_star = (half_pi / lambda).powi(2);
    let z = if periodic { 2.0 * (half_pi / lambda) - 1.0 } else { 2.0 * tau_star - 1.0 };
    // Observed (nu = 0) slower decay (rho ~ 2 + 3.2/lambda^2 at lambda = pi/5): cap rho so the
    // first size is usually sufficient and the adaptive re-solve rare.
    let rho = (z + (z * z - 1.0).max(0.0).sqrt()).min(2.0 + 3.0 / (lambda * lambda));
    let n = ((bits as f64 * std::f64::consts::LN_2 / rho.ln()) * refine).ceil() as usize + 4;
    if !(n <= MAX_NODES) {
        return Err(AdhesionError::IllConditioned {
            method: "mpfr-volterra",
            parameter: "lambda",
            value: readable_f64(lambda),
            valid: format!("lambda = pi a/L well below pi/2 (here {n} > {MAX_NODES} Chebyshev nodes would be needed)"),
            reason: "the solution is singular at full contact lambda = pi/2; the interpolant converges like ((pi/2 - lambda)/pi)^(n/2)".into(),
        });
    }
    Ok(n)
}

/// Solves the Volterra equation at `lambda` (0 <= lambda < pi/2), choosing the Chebyshev size
/// adaptively: a first size from [`chebyshev_size`], then, while the last three coefficients are
/// not below 2^-target_bits |c_0|, a larger size from the observed geometric decay (at most four
/// times). The a priori estimate assumes the singularity at full contact only; for eps > 0 the
/// coefficients decay more slowly (observed at nu = 0: ratio ~1/10 per coefficient at
/// lambda = pi/5 instead of the predicted 1/23; see the module doc on conditioning), hence the
/// a posteriori check.
///
/// `constants` are the derived parameters of the material at `params.prec` bits.
pub fn solve(
    constants: &AdhesionParamsMpfr,
    lambda: &Float,
    params: VolterraParams,
) -> Result<VolterraSolution, AdhesionError> {
    solve_rhs(constants, lambda, params, &RightSide::Parabola)
}

/// [`solve`] with the right side of a general even profile (docs/theory.md section 9,
/// [`RightSide`]): Re I(sigma) = pi g'(x)/(2 k x). The Chebyshev size is the larger of the
/// full-contact estimate and the right side's own ([`RightSide::min_nodes`]).
pub fn solve_rhs(
    constants: &AdhesionParamsMpfr,
    lambda: &Float,
    params: VolterraParams,
    rhs: &RightSide,
) -> Result<VolterraSolution, AdhesionError> {
    solve_rhs_in(constants, lambda, params, rhs, false)
}

/// [`solve_rhs`] in either surface convention: `periodic` (u periodic, docs/theory.md section 8,
/// Problem 2) solves with the kernel of [`kernel::LateralShift`] and F in sigma (at lambda = 0,
/// the single punch, the two coincide and the `paper` form is used).
pub fn solve_rhs_in(
    constants: &AdhesionParamsMpfr,
    lambda: &Float,
    params: VolterraParams,
    rhs: &RightSide,
    periodic: bool,
) -> Result<VolterraSolution, AdhesionError> {
    let periodic = periodic && !lambda.is_zero();
    let mut n = chebyshev_size_in(lambda.to_f64(), params.target_bits, params.refine, periodic)?
        .max(rhs.min_nodes(params.target_bits, params.refine));
    if n > MAX_NODES {
        return Err(AdhesionError::IllConditioned {
            method: "mpfr-volterra",
            parameter: "half_width",
            value: readable_mpfr(lambda),
            valid: format!("a contact for which {MAX_NODES} Chebyshev nodes suffice"),
            reason: "the profile's slope is singular too close to the contact's edge (circle: |x| = R)".into(),
        });
    }
    let goal = (params.target_bits as f64) * std::f64::consts::LN_2;
    for _ in 0..5 {
        // The residual check only for the size that is kept.
        let mut sol = solve_unchecked(constants, lambda, params, n, rhs, periodic)?;
        let c: Vec<f64> = sol.f_coeffs.iter().map(|x| x.clone().abs().to_f64()).collect();
        let c0 = c[0].max(f64::MIN_POSITIVE);
        let m = c.len();
        // Fewer than 8 coefficients: taken as converged (tail 0).
        let tail = if m < 8 { 0.0 } else { c[m - 3..].iter().cloned().fold(0f64, f64::max) / c0 };
        let tail_ln = if tail > 0.0 { tail.ln() } else { -goal - 1.0 };
        if tail_ln <= -goal {
            sol.residual = residual(&sol, rhs);
            return Ok(sol);
        }
        // Decay rate from the second half of the coefficients.
        let h = m / 2;
        let first = c[h..h + 3].iter().cloned().fold(0f64, f64::max) / c0;
        let rate = ((first.ln() - tail_ln) / ((m - 3 - h) as f64)).max(0.05);
        let extra = ((tail_ln + goal) / rate).ceil() as usize + 4;
        n = (n + extra).max(n + 4);
        if n > MAX_NODES {
            return Err(AdhesionError::IllConditioned {
                method: "mpfr-volterra",
                parameter: "lambda",
                value: readable_mpfr(lambda),
                valid: format!("a contact for which {MAX_NODES} Chebyshev nodes suffice"),
                reason: {
                    // Below nu = 1/2 slow decay is the homogeneous solution's share in F
                    // (asymptotics::adhesion_mode), not only the approach to full contact.
                    let f = constants.to_f64();
                    // Not in `periodic`, where the mode is not excited (docs/theory.md section 8).
                    let mode = if f.eps > 0.0 && !periodic {
                        format!(
                            "; {}",
                            crate::asymptotics::adhesion_mode::mode_sentence(
                                f.eps,
                                f.b,
                                f.s,
                                params.target_bits as f64 * std::f64::consts::LOG10_2
                            )
                        )
                    } else {
                        String::new()
                    };
                    format!("Chebyshev coefficients decay too slowly (rate {rate:.3} per node){mode}")
                },
            });
        }
    }
    Err(AdhesionError::NotConverged { what: "adaptive Chebyshev size", reason: "five enlargements".into() })
}

/// Solves with exactly `n` Chebyshev nodes.
pub fn solve_with_nodes(
    constants: &AdhesionParamsMpfr,
    lambda: &Float,
    params: VolterraParams,
    n: usize,
) -> Result<VolterraSolution, AdhesionError> {
    solve_with_nodes_rhs(constants, lambda, params, n, &RightSide::Parabola)
}

/// [`solve_with_nodes`] with the right side `rhs`.
pub fn solve_with_nodes_rhs(
    constants: &AdhesionParamsMpfr,
    lambda: &Float,
    params: VolterraParams,
    n: usize,
    rhs: &RightSide,
) -> Result<VolterraSolution, AdhesionError> {
    solve_with_nodes_in(constants, lambda, params, n, rhs, false)
}

/// [`solve_with_nodes_rhs`] in either convention ([`solve_rhs_in`]).
pub fn solve_with_nodes_in(
    constants: &AdhesionParamsMpfr,
    lambda: &Float,
    params: VolterraParams,
    n: usize,
    rhs: &RightSide,
    periodic: bool,
) -> Result<VolterraSolution, AdhesionError> {
    let periodic = periodic && !lambda.is_zero();
    let mut sol = solve_unchecked(constants, lambda, params, n, rhs, periodic)?;
    sol.residual = residual(&sol, rhs);
    Ok(sol)
}

/// [`solve_with_nodes_rhs`] without its residual check (`residual` left 0).
fn solve_unchecked(
    constants: &AdhesionParamsMpfr,
    lambda: &Float,
    params: VolterraParams,
    n: usize,
    rhs: &RightSide,
    periodic: bool,
) -> Result<VolterraSolution, AdhesionError> {
    let prec = params.prec;
    let eps = Float::with_val(prec, &constants.eps);
    let cosh_pi_eps = Float::with_val(prec, &constants.cosh_pi_eps);
    let rule = TanhSinh::new(params.target_bits + 8, params.refine, prec);
    let pre = kernel::VolterraNodes::new(&rule.s, &rule.c, prec);
    let shift = periodic.then(|| kernel::LateralShift::new(&eps, prec));
    // The nodes of the interpolation variable: tau = sigma^2 (`paper`) or sigma (`periodic`).
    let tau = chebyshev::nodes(n, prec);
    let key = FactorsKey::new(lambda, n, &rule, periodic);
    let (res, keep) = collocation_rows(key, &tau, lambda, &eps, &rule, &pre, shift.as_ref(), prec);
    let b: Vec<Float> = tau
        .iter()
        .map(|t| if periodic { rhs.at(&Float::with_val(prec, t * t), prec) } else { rhs.at(t, prec) })
        .collect();
    let (f_coeffs, pivot_ratio) = collocation_solve(&res, &keep, b, prec)?;
    Ok(VolterraSolution {
        prec,
        lambda: Float::with_val(prec, lambda),
        eps,
        cosh_pi_eps,
        f_coeffs,
        shift,
        j_source: JSource::Rows(Arc::new(keep)),
        j_coeffs: OnceLock::new(),
        residual: 0.0,
        pivot_ratio,
        rule,
        pre,
    })
}

/// The residual of Re I = pi g'/(2 k x) between collocation nodes (a posteriori check): the
/// largest of its moduli at sigma = 0.13, 0.42, 0.71, 1.
fn residual(sol: &VolterraSolution, rhs: &RightSide) -> f64 {
    let prec = sol.prec;
    let mut res = 0f64;
    for k in 0..4 {
        let sg = Float::with_val(prec, 0.13 + 0.29 * k as f64);
        let (re, _) = sol.integral_i(&sg);
        let want = rhs.at(&Float::with_val(prec, &sg * &sg), prec);
        res = res.max(Float::with_val(prec, re - want).abs().to_f64());
    }
    res
}

/// The data of the collocation rows at the nodes `tau`: per row i, re_iq = w_q Re z_iq and the
/// pairs (w_q Im z_iq, x_iq), x_iq = 2 tau_i s_q^2 - 1 (the second kept for J). With a `shift`
/// (`periodic`) the nodes are sigma_i and x_iq = 2 sigma_i s_q - 1. The material-free factors of
/// z_iq come from [`row_factors`] under `key` (that of `tau`, `rule` and `prec`).
#[allow(clippy::type_complexity, clippy::too_many_arguments)]
fn collocation_rows(
    key: FactorsKey,
    tau: &[Float],
    lambda: &Float,
    eps: &Float,
    rule: &TanhSinh,
    pre: &kernel::VolterraNodes,
    shift: Option<&kernel::LateralShift>,
    prec: u32,
) -> (Vec<Vec<Float>>, Vec<Vec<(Float, Float)>>) {
    let n = tau.len();
    let factors = row_factors(key, lambda, tau, rule, pre);
    let mut scratch = kernel::FactorScratch::new(prec);
    // Rows: A_ij = sum_q Re z_iq T_j(x_iq), x_iq = 2 tau_i s_q^2 - 1; keep Im z_iq, x_iq for J.
    let mut res: Vec<Vec<Float>> = Vec::with_capacity(n);
    let mut keep: Vec<Vec<(Float, Float)>> = Vec::with_capacity(n);
    for (tau_i, row) in tau.iter().zip(factors.iter()) {
        let mut row_res = Vec::with_capacity(rule.len());
        let mut row_keep = Vec::with_capacity(rule.len());
        for (q, (mag, log_sum)) in row.nodes.iter().enumerate() {
            let (re, im) = kernel::integrand_from_factors(
                &mut scratch,
                mag,
                log_sum,
                &rule.s[q],
                &row.chi,
                &row.sc_chi,
                eps,
                shift,
            );
            let re = re * &rule.w[q];
            let im = im * &rule.w[q];
            let x = match shift {
                Some(_) => Float::with_val(prec, tau_i * &rule.s[q]) * 2u32 - 1u32,
                None => Float::with_val(prec, tau_i * &pre.s2[q]) * 2u32 - 1u32,
            };
            row_res.push(re);
            row_keep.push((im, x));
        }
        res.push(row_res);
        keep.push(row_keep);
    }
    (res, keep)
}

/// The collocation system from the rows' data (per row i: re_iq = w_q Re z_iq and the pairs
/// (_, x_iq)): A_ij = sum_q re_iq T_j(x_iq) (q outer, j inner, each product and sum rounded to
/// `prec` bits), then A f = b by Gaussian elimination with partial pivoting. Up to 256 bits in
/// [`Fixed`] arithmetic, whose roundings are MPFR's (the same bits as [`row_sums_mpfr`] and
/// [`gauss_solve`], operation by operation, about twice as fast); beyond, in MPFR.
fn collocation_solve(
    res: &[Vec<Float>],
    xs: &[Vec<(Float, Float)>],
    b: Vec<Float>,
    prec: u32,
) -> Result<(Vec<Float>, f64), AdhesionError> {
    let n = b.len();
    match prec.div_ceil(64) {
        1 => gauss_solve_fixed::<1>(rows_fixed(res, xs, n, prec), b, prec),
        2 => gauss_solve_fixed::<2>(rows_fixed(res, xs, n, prec), b, prec),
        3 => gauss_solve_fixed::<3>(rows_fixed(res, xs, n, prec), b, prec),
        4 => gauss_solve_fixed::<4>(rows_fixed(res, xs, n, prec), b, prec),
        _ => gauss_solve(res.iter().zip(xs).map(|(r, x)| row_sums_mpfr(r, x, n, prec)).collect(), b, prec),
    }
}

/// The rows of [`collocation_solve`] by [`row_sums_fixed`].
fn rows_fixed<const L: usize>(
    res: &[Vec<Float>],
    xs: &[Vec<(Float, Float)>],
    n: usize,
    prec: u32,
) -> Vec<Vec<Fixed<L>>> {
    res.iter().zip(xs).map(|(r, x)| row_sums_fixed::<L>(r, x, n, prec)).collect()
}

/// One row of the collocation matrix in MPFR: sum_q re_q T_j(x_q) for j < n, `xs` holding
/// (_, x_q).
fn row_sums_mpfr(res: &[Float], xs: &[(Float, Float)], n: usize, prec: u32) -> Vec<Float> {
    let mut row = vec![Float::with_val(prec, 0); n];
    let mut tj = vec![Float::with_val(prec, 0); n];
    // Scratch for the products (in place: the same roundings as a fresh Float per product).
    let mut t = Float::new(prec);
    for (re, (_, x)) in res.iter().zip(xs) {
        chebyshev_values(x, &mut tj, prec);
        for (aij, tj) in row.iter_mut().zip(&tj) {
            t.assign(re * tj);
            *aij += &t;
        }
    }
    row
}

/// [`row_sums_mpfr`] in [`Fixed`] arithmetic of L limbs (64 (L - 1) < prec <= 64 L): the
/// recurrence of [`chebyshev_values`] and the sums, operation by operation.
fn row_sums_fixed<const L: usize>(res: &[Float], xs: &[(Float, Float)], n: usize, prec: u32) -> Vec<Fixed<L>> {
    let fixed = |x: &Float| Fixed::<L>::from_float(x).expect("a finite number of at most 64 L bits");
    let mut row = vec![Fixed::<L>::zero(false); n];
    let one = fixed(&Float::with_val(prec, 1u32));
    for (re, (_, x)) in res.iter().zip(xs) {
        let (re, x) = (fixed(re), fixed(x));
        let two_x = x.mul_2exp(1);
        let (mut t_prev, mut t) = (one, x);
        for (j, aij) in row.iter_mut().enumerate() {
            let tj = match j {
                0 => one,
                1 => x,
                _ => {
                    let next = two_x.mul(&t, prec).sub(&t_prev, prec);
                    t_prev = t;
                    t = next;
                    next
                }
            };
            *aij = aij.add(&re.mul(&tj, prec), prec);
        }
    }
    row
}

/// T_0..T_{n-1} at x.
fn chebyshev_values(x: &Float, out: &mut [Float], prec: u32) {
    let n = out.len();
    if n == 0 {
        return;
    }
    out[0] = Float::with_val(prec, 1u32);
    if n > 1 {
        out[1] = x.clone();
    }
    // T_j = 2 x T_{j-1} - T_{j-2}, in place (the caller's `out` holds `prec` bits). 2 x is exact
    // and rounding commutes with doubling, so round((2 x) T) = 2 round(x T): the bits of the
    // product rounded and then doubled, with one operation fewer.
    let two_x = Float::with_val(prec, x * 2u32);
    for j in 2..n {
        let (done, rest) = out.split_at_mut(j);
        let t = &mut rest[0];
        t.assign(&two_x * &done[j - 1]);
        *t -= &done[j - 2];
    }
}

/// |pivot| of column `k` as f64 for the pivot ratio; a zero or non-finite pivot is an error.
fn pivot_magnitude(piv: &Float, k: usize) -> Result<f64, AdhesionError> {
    let pa = piv.clone().abs().to_f64();
    if !(pa > 0.0) || !pa.is_finite() {
        return Err(AdhesionError::NotConverged {
            what: "collocation solve",
            reason: format!("zero or non-finite pivot at column {k}"),
        });
    }
    Ok(pa)
}

/// [`gauss_solve`] with the matrix in [`Fixed`] arithmetic (the row operations; the divisions,
/// the right side and the pivots' magnitudes in MPFR): the same operations, the same bits.
fn gauss_solve_fixed<const L: usize>(
    mut a: Vec<Vec<Fixed<L>>>,
    mut b: Vec<Float>,
    prec: u32,
) -> Result<(Vec<Float>, f64), AdhesionError> {
    let n = b.len();
    let fixed = |x: &Float| Fixed::<L>::from_float(x).expect("a finite number of at most 64 L bits");
    let mut t = Float::new(prec);
    let (mut pmax, mut pmin) = (0f64, f64::INFINITY);
    for k in 0..n {
        let p = (k..n).max_by(|&i, &j| a[i][k].cmp_abs(&a[j][k])).unwrap_or(k);
        a.swap(k, p);
        b.swap(k, p);
        let piv = a[k][k].to_float(prec);
        let pa = pivot_magnitude(&piv, k)?;
        pmax = pmax.max(pa);
        pmin = pmin.min(pa);
        let (top, below) = a.split_at_mut(k + 1);
        let (bk, b_below) = b.split_at_mut(k + 1);
        let (row_k, bk) = (&top[k], &bk[k]);
        for (row_i, bi) in below.iter_mut().zip(b_below.iter_mut()) {
            let m = Float::with_val(prec, row_i[k].to_float(prec) / &piv);
            if m.is_zero() {
                continue;
            }
            let mf = fixed(&m);
            for (aij, akj) in row_i[k..].iter_mut().zip(&row_k[k..]) {
                *aij = aij.sub(&mf.mul(akj, prec), prec);
            }
            t.assign(&m * bk);
            *bi -= &t;
        }
    }
    let mut x = vec![Fixed::<L>::zero(false); n];
    let mut out = vec![Float::with_val(prec, 0); n];
    for k in (0..n).rev() {
        let mut acc = fixed(&b[k]);
        for j in k + 1..n {
            acc = acc.sub(&a[k][j].mul(&x[j], prec), prec);
        }
        out[k] = acc.to_float(prec) / a[k][k].to_float(prec);
        x[k] = fixed(&out[k]);
    }
    Ok((out, pmax / pmin))
}

/// Gaussian elimination with partial pivoting; returns the solution and max/min |pivot|.
fn gauss_solve(mut a: Vec<Vec<Float>>, mut b: Vec<Float>, prec: u32) -> Result<(Vec<Float>, f64), AdhesionError> {
    let n = b.len();
    let mut t = Float::new(prec);
    let (mut pmax, mut pmin) = (0f64, f64::INFINITY);
    for k in 0..n {
        let p = (k..n).max_by(|&i, &j| a[i][k].cmp_abs(&a[j][k]).unwrap_or(std::cmp::Ordering::Equal)).unwrap_or(k);
        a.swap(k, p);
        b.swap(k, p);
        let piv = a[k][k].clone();
        let pa = pivot_magnitude(&piv, k)?;
        pmax = pmax.max(pa);
        pmin = pmin.min(pa);
        // Row operations in place (a scratch product: the same roundings as a fresh Float each).
        let (top, below) = a.split_at_mut(k + 1);
        let (bk, b_below) = b.split_at_mut(k + 1);
        let (row_k, bk) = (&top[k], &bk[k]);
        for (row_i, bi) in below.iter_mut().zip(b_below.iter_mut()) {
            let m = Float::with_val(prec, &row_i[k] / &piv);
            if m.is_zero() {
                continue;
            }
            for (aij, akj) in row_i[k..].iter_mut().zip(&row_k[k..]) {
                t.assign(&m * akj);
                *aij -= &t;
            }
            t.assign(&m * bk);
            *bi -= &t;
        }
    }
    let mut x = vec![Float::with_val(prec, 0); n];
    for k in (0..n).rev() {
        let mut acc = b[k].clone();
        for j in k + 1..n {
            t.assign(&a[k][j] * &x[j]);
            acc -= &t;
        }
        x[k] = acc / &a[k][k];
    }
    Ok((x, pmax / pmin))
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::model::{Exact, Material};
    use rug::float::Constant;

    fn material(nu: (i64, i64)) -> Material {
        Material::from_contact_modulus(Exact::new(nu.0.into(), nu.1.into()), Exact::from_integer(1.into())).unwrap()
    }

    #[test]
    fn adhesion_j_on_demand_is_im_i_and_follows_restrict_and_reduced() {
        // J(tau) = Im I(sqrt tau): the coefficients computed on demand from the solve's rows,
        // against Im I by the quadrature of `integral_i` (another evaluation order), at nu = 0.3.
        let params = VolterraParams::for_digits(20);
        let prec = params.prec;
        let constants = AdhesionParamsMpfr::new(&material((3, 10)), prec);
        let lam = Float::with_val(prec, 0.9);
        let sol = solve(&constants, &lam, params).unwrap();
        let j_at = |s: &VolterraSolution, tau: f64| {
            let x = Float::with_val(s.prec, tau * 2.0 - 1.0);
            chebyshev::evaluate(s.j_coeffs(), &x, s.prec).to_f64()
        };
        for t in [0.05, 0.3, 0.77, 1.0] {
            let sigma = Float::with_val(prec, t).sqrt();
            let im = sol.integral_i(&sigma).1.to_f64();
            assert!((j_at(&sol, t) - im).abs() < 1e-20 * im.abs().max(1.0), "tau {t}: {} vs {im}", j_at(&sol, t));
        }
        // Restricted to lambda' = 0.6: J'(tau) = J(tau (lambda'/lambda)^2), before and after the
        // parent's own J is computed (the parent above already has it; a fresh solve has not).
        let fresh = solve(&constants, &lam, params).unwrap();
        let small = Float::with_val(prec, 0.6);
        for parent in [&sol, &fresh] {
            let r = parent.restrict(&small);
            for t in [0.1, 0.5, 0.9] {
                let want = j_at(&sol, t * 0.36 / 0.81);
                assert!((j_at(&r, t) - want).abs() < 1e-20, "restricted tau {t}");
            }
        }
        // Rounded to 64 bits: the same coefficients rounded.
        let low = fresh.reduced(64);
        assert_eq!(low.j_coeffs().len(), sol.j_coeffs().len());
        for (a, b) in low.j_coeffs().iter().zip(sol.j_coeffs()) {
            assert_eq!(*a, Float::with_val(64, b));
        }
    }

    #[test]
    #[ignore = "long tier: 5 s alone in the test profile (opt-level 2) on a loaded 2-core machine (scripts/test --long)"]
    fn adhesion_fixed_collocation_is_bit_identical_to_mpfr() {
        // The assembly and elimination in Fixed arithmetic give the bits of the MPFR loops, at
        // one to four limbs and at limb boundaries (nu = 0.3, lambda = 1.2, 40 nodes).
        let constants_at = |prec| AdhesionParamsMpfr::new(&material((3, 10)), prec);
        for prec in [64u32, 65, 107, 128, 131, 164, 192, 200, 256] {
            let constants = constants_at(prec);
            let eps = Float::with_val(prec, &constants.eps);
            let rule = TanhSinh::new(prec - 24, 1.0, prec);
            let pre = kernel::VolterraNodes::new(&rule.s, &rule.c, prec);
            let tau = chebyshev::nodes(40, prec);
            let lambda = Float::with_val(prec, 1.2);
            let key = FactorsKey::new(&lambda, 40, &rule, false);
            let (res, keep) = collocation_rows(key, &tau, &lambda, &eps, &rule, &pre, None, prec);
            let b: Vec<Float> = tau.iter().map(|t| RightSide::Parabola.at(t, prec)).collect();
            let (fixed, ratio_fixed) = collocation_solve(&res, &keep, b.clone(), prec).unwrap();
            let rows = res.iter().zip(&keep).map(|(r, x)| row_sums_mpfr(r, x, 40, prec)).collect();
            let (mpfr, ratio_mpfr) = gauss_solve(rows, b, prec).unwrap();
            assert_eq!(fixed, mpfr, "prec {prec}");
            assert_eq!(ratio_fixed.to_bits(), ratio_mpfr.to_bits(), "prec {prec}");
        }
    }

    #[test]
    fn adhesion_kuznetsov_f_is_pi_tan() {
        // eps = 0: P' = pi tan eta (Kuznetsov), i.e. F(tau) = pi tan(lambda sqrt tau)/(lambda sqrt tau).
        let prec = 120;
        let lam = Float::with_val(prec, 0.5);
        let params = VolterraParams::for_digits(25);
        let constants = AdhesionParamsMpfr::new(&material((1, 2)), params.prec);
        let sol = solve(&constants, &lam, params).unwrap();
        for t in [0.0, 0.3, 0.77, 1.0] {
            let tau = Float::with_val(prec, t);
            let eta = Float::with_val(prec, tau.sqrt_ref()) * &lam;
            let want = if t == 0.0 {
                Float::with_val(prec, Constant::Pi)
            } else {
                Float::with_val(prec, eta.tan_ref()) / &eta * Float::with_val(prec, Constant::Pi)
            };
            let err = Float::with_val(prec, sol.f_at(&tau) - want).abs().to_f64();
            assert!(err < 1e-24, "tau {t}: {err:e}");
        }
    }
}
