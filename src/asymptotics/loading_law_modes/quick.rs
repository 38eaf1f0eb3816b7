//! The mode check's usual answer, no real zero of det M on (0, [`MU_MAX`]], without MPFR: both
//! runs of [`super::mode_exponent`] (their rules: bits and refinement) rebuilt in f64 with a
//! bound on every datum's distance from its exact value on the same rule, and the scan of
//! [`super::Symbol::first_zero`] run on the f64 screen ([`super::screen`]) with those bounds
//! added. Where the screen answers every question of both scans and neither finds a sign change,
//! the exact determinants have the screened signs, and so have the MPFR ones (within 2^-11 of the
//! screen's bound of the exact values, module `screen`): the MPFR runs find no zero either, and
//! [`super::problem_mode`] gives their answer (no exponent, the digits cap) without running
//! them. Anywhere else it runs them.
//!
//! The data (per node and side sigma, as [`super::Symbol`]): the rule with its bounds
//! ([`crate::numerics::tanh_sinh::tanh_sinh_f64_bounded`]); f_0, g_0 by the f64 Newton of
//! [`super::self_similar`], their errors bounded by twice |J^-1| (|R| + rho), R the residual at
//! them and rho its evaluation's error bound (a linearisation: the Newton remainder is of the
//! order of the squared step, 1e-30, and the factor 2 covers it and J's own rounding); then
//! k = sigma exp(a1 (ln(1 - s) + ln N_0) + a2 ln D_0), wf = Re (1 + i n) w s k and
//! wg = Re (1 + i n) w s k f_0 sigma (a1/N_0 + a2 (1 - s)/D_0), each with the first-order
//! propagation of the roundings (u = 2^-53, every libm call within 4 u), of eps's (2 u) and of
//! the errors of the rule and of f_0, g_0 (|d ln k/d g_0| <= |a1|/N_0 + |a1| (1 - s)/D_0), with
//! 1 % for the second order. Tests below: the data within their bounds of the MPFR symbol's,
//! and the answer equal to the MPFR runs' wherever it is given.

use super::screen::{Screen, ScreenNode};
use super::{scan, scan_grid, self_similar, ModeExponent, MU_MAX};
use crate::numerics::accuracy::digits_cap_for_bits;
use crate::numerics::exact::to_f64;
use crate::numerics::precision::{bits_for_digits, SOLVER_GUARD_BITS, VERIFY_EXTRA_BITS};
use crate::numerics::tanh_sinh::tanh_sinh_f64_bounded;
use crate::params::adhesion::AdhesionParamsF64;
use nalgebra::Complex;
use rug::Float;

type C64 = Complex<f64>;
type Q = num_rational::BigRational;

const U: f64 = f64::EPSILON / 2.0;
/// One libm call's error relative to its result (2 ulp).
const CALL: f64 = 4.0 * U;

/// One node of the rule and its relative error bound.
#[derive(Debug, Clone, Copy)]
struct RuleNode {
    s: f64,
    c: f64,
    w: f64,
    err: f64,
}

/// One node's data on one side at (f_0, g_0), with bounds (module doc).
#[derive(Debug, Clone, Copy)]
struct SideData {
    /// wf and its error with f_0, g_0 taken as exact.
    wf: f64,
    wf_err: f64,
    /// wg and its error with f_0, g_0 taken as exact.
    wg: f64,
    wg_err: f64,
    /// |(1 + i n) w s k|, |term| and the bounds on |d ln k/d g_0| and |d term/d g_0|.
    wk_abs: f64,
    term_abs: f64,
    dlnk_dg: f64,
    dterm_dg: f64,
}

/// The problem's constants in f64.
struct Setting {
    eps: f64,
    load_constant: f64,
    n: f64,
}

fn side_data(set: &Setting, q: &RuleNode, sigma: f64, f: f64, g: f64) -> SideData {
    let (eps, n) = (set.eps, set.n);
    let d_eps = 2.0 * U * eps.abs();
    let m = (0.25 + eps * eps).sqrt() * (1.0 + 2.0 * U);
    let (a1, a2) = (C64::new(-0.5, -sigma * eps), C64::new(-0.5, sigma * eps));
    let e = q.err;
    let ln_c = q.c.ln();
    let n0 = 1.0 + sigma * g;
    let ln_n0 = n0.ln();
    let d0 = q.c * sigma * g + q.s + 1.0;
    let ln_d0 = d0.ln();
    // Absolute errors of the logarithms, and of the exponent.
    let e_d0 = ((q.c * g).abs() * (e + 2.0 * U) + q.s * (e + U)) / d0 + U;
    let (l_c, l_n0, l_d0) = (e + CALL * ln_c.abs(), U + CALL * ln_n0.abs(), e_d0 + CALL * ln_d0.abs());
    let x = ln_c + ln_n0;
    let expo = a1 * x + a2 * ln_d0;
    let e_expo = m * (l_c + l_n0 + l_d0) + (d_eps + 4.0 * U * m) * (x.abs() + ln_d0.abs()) + U * expo.norm();
    let k = expo.exp() * sigma;
    let e_k = e_expo + 2.0 * CALL + 2.0 * U;
    let ws = q.w * q.s;
    let wk = k * ws * C64::new(1.0, n);
    let e_wk = e_k + 2.0 * e + 8.0 * U;
    let term = a1 / n0 + a2 * q.c / d0;
    let term_err = (2.0 * U * m + d_eps) / n0 + q.c / d0 * (m * (e + e_d0 + 3.0 * U) + d_eps) + U * term.norm();
    let wk_abs = wk.norm() * (1.0 + 2.0 * U);
    let term_abs = term.norm() * (1.0 + 2.0 * U);
    SideData {
        wf: wk.re,
        wf_err: 1.01 * wk_abs * e_wk,
        wg: (wk * term).re * f * sigma,
        wg_err: 1.01 * f.abs() * wk_abs * (term_err + term_abs * (e_wk + 4.0 * U)),
        wk_abs,
        term_abs,
        dlnk_dg: 1.01 * m * (1.0 / n0 + q.c / d0),
        dterm_dg: 1.01 * m * (1.0 / (n0 * n0) + q.c * q.c / (d0 * d0)),
    }
}

/// The rule of one run (`bits`, `refine`) with its bounds, on the nodes the MPFR symbol keeps.
fn rule(bits: u32, refine: f64) -> Vec<RuleNode> {
    tanh_sinh_f64_bounded(bits, refine)
        .into_iter()
        .map(|(s, c, w, err)| RuleNode { s, c, w, err })
        .filter(|q| q.c > 0.0 && q.s > 0.0)
        .collect()
}

/// f_0, g_0 on `rule` with their bounds: (f_0, g_0, df_0, dg_0) and each node's data on both
/// sides at them (module doc), or None.
#[allow(clippy::type_complexity)]
fn start(set: &Setting, rule: &[RuleNode]) -> Option<((f64, f64, f64, f64), Vec<[SideData; 2]>)> {
    let pts: Vec<(f64, f64, f64, f64)> = rule.iter().map(|q| (q.s, q.c, q.w * q.s, q.c.ln())).collect();
    let (f, g) = self_similar::newton_f64_on(set.eps, set.load_constant, set.n, &pts)?;
    let data: Vec<[SideData; 2]> =
        rule.iter().map(|q| [side_data(set, q, 1.0, f, g), side_data(set, q, -1.0, f, g)]).collect();
    let pi = std::f64::consts::PI;
    let count = rule.len() as f64 + 4.0;
    // Per side: R = f sum wf - pi (sigma + g), its error bound, and the Jacobian's row.
    let mut r = [0.0; 2];
    let mut rho = [0.0; 2];
    let mut jac = [[0.0; 2]; 2];
    for (row, sigma) in [1.0f64, -1.0].into_iter().enumerate() {
        let (mut sf, mut sf_abs, mut sf_err, mut sg) = (0.0, 0.0, 0.0, 0.0);
        for d in data.iter().map(|sides| &sides[row]) {
            sf += d.wf;
            sf_abs += d.wf.abs();
            sf_err += d.wf_err;
            sg += d.wg;
        }
        let rhs = pi * (sigma + g);
        r[row] = f * sf - rhs;
        rho[row] = f.abs() * sf_err + count * U * (f.abs() * sf_abs + pi * (1.0 + g.abs()));
        jac[row] = [sf, sg - pi];
    }
    let det = jac[0][0] * jac[1][1] - jac[0][1] * jac[1][0];
    let inv = [[jac[1][1] / det, -jac[0][1] / det], [-jac[1][0] / det, jac[0][0] / det]];
    let size = [r[0].abs() + rho[0], r[1].abs() + rho[1]];
    let df = 2.0 * (inv[0][0].abs() * size[0] + inv[0][1].abs() * size[1]);
    let dg = 2.0 * (inv[1][0].abs() * size[0] + inv[1][1].abs() * size[1]);
    // Far beyond the f64 Newton's 1e-14: not this path's case.
    (df.is_finite() && dg.is_finite() && df <= 1e-10 * f.abs() && dg <= 1e-10 && g.abs() + dg < 1.0)
        .then_some(((f, g, df, dg), data))
}

/// The screen of one run (`bits` and `refine` of its rule) and its start (f_0, g_0, df_0, dg_0),
/// or None.
fn screen(set: &Setting, bits: u32, refine: f64) -> Option<(Screen, (f64, f64, f64, f64))> {
    let rule = rule(bits, refine);
    let ((f, g, df, dg), data) = start(set, &rule)?;
    let nodes = rule
        .iter()
        .zip(&data)
        .map(|(q, both)| {
            let mut sides = [[0.0; 2]; 2];
            let mut sides_err = [[0.0; 2]; 2];
            for (k, d) in both.iter().enumerate() {
                sides[k] = [d.wf, d.wg];
                let moved_k = d.dlnk_dg * dg;
                sides_err[k] = [
                    d.wf_err + 1.01 * d.wk_abs * moved_k,
                    d.wg_err
                        + 1.01
                            * (f.abs() * d.wk_abs * (d.dterm_dg * dg + d.term_abs * moved_k)
                                + d.wk_abs * d.term_abs * df),
                ];
            }
            // ln s from the complement near s = 1, as the MPFR symbol takes it.
            let (ln_s, ln_s_abs) = if q.s > 0.5 {
                let v = (-q.c).ln_1p();
                (v, q.c * q.err / q.s + CALL * v.abs())
            } else {
                let v = q.s.ln();
                (v, q.err + CALL * v.abs())
            };
            let ln_s_err = 1.01 * ln_s_abs / ln_s.abs();
            ScreenNode { ln_s, r: ln_s / q.c, sides, ln_s_err, r_err: ln_s_err + q.err + U, sides_err }
        })
        .collect();
    Some((Screen::from_f64(nodes), (f, g, df, dg)))
}

/// The answer of [`super::mode_exponent`]`(nu, ratio, digits)` where both its runs find no zero
/// and the f64 screens prove it (module doc): no exponent, the digits cap, g_0 and det M(0) in
/// f64 (53 bits). None where that is not proved (the MPFR runs then decide), also for input
/// they refuse.
pub(super) fn no_zero(nu: &Q, ratio: &Q, digits: u32) -> Option<ModeExponent> {
    let material = super::mode_material(nu, ratio).ok()?;
    let params = AdhesionParamsF64::new(&material);
    let set = Setting { eps: params.eps, load_constant: params.load_constant, n: to_f64(ratio)? };
    let bits = bits_for_digits(digits) + SOLVER_GUARD_BITS;
    if bits < super::screen::MIN_PREC {
        return None;
    }
    let grid = scan_grid(MU_MAX);
    let mut first = None;
    for (extra, refine) in [(0, 1.0), (VERIFY_EXTRA_BITS, 1.25)] {
        let (screen, (_, g0, _, _)) = screen(&set, bits + extra, refine)?;
        if scan::first_change(None, Some(&screen), &grid, 2)?.is_some() {
            return None;
        }
        first.get_or_insert((g0, screen.det(0.0).value));
    }
    let (g0, det0) = first?;
    Some(ModeExponent {
        nu: nu.clone(),
        ratio: ratio.clone(),
        mu: None,
        digits: digits_cap_for_bits(bits),
        g0: Float::with_val(53, g0),
        det_at_zero: Float::with_val(53, det0),
    })
}

#[cfg(test)]
mod tests {
    use super::super::{mode_exponent, Symbol};
    use super::*;
    use crate::model::Material;
    use crate::numerics::tanh_sinh::TanhSinh;
    use crate::params::adhesion::AdhesionParamsMpfr;

    fn q(n: i64, d: i64) -> Q {
        Q::new(n.into(), d.into())
    }

    /// Every f64 datum of both runs' screens within its bound of the MPFR symbol's (the MPFR
    /// values rounded once: one more u): the rule's nodes and weights, f_0 and g_0 (against the
    /// MPFR self-similar solution), the weights, ln s and r; and det M within the screen's bound
    /// of the MPFR determinant along the scan. At nu = 0, 1/10, 3/10, 1/2 and n = 0, 1/5, 1, the
    /// mode check's precisions (76 bits, and 108 on the finer rule).
    #[test]
    fn the_f64_data_lie_within_their_bounds() {
        let bits = bits_for_digits(12) + SOLVER_GUARD_BITS;
        let mut worst = 0f64;
        for nu in [q(0, 1), q(1, 10), q(3, 10), q(1, 2)] {
            for n in [q(0, 1), q(1, 5), q(1, 1)] {
                let material = Material::from_contact_modulus(nu.clone(), q(1, 1)).unwrap();
                let p64 = AdhesionParamsF64::new(&material);
                let set = Setting { eps: p64.eps, load_constant: p64.load_constant, n: to_f64(&n).unwrap() };
                for (extra, refine) in [(0, 1.0), (VERIFY_EXTRA_BITS, 1.25)] {
                    let prec = bits + extra;
                    let params = AdhesionParamsMpfr::new(&material, prec);
                    let rule = TanhSinh::new(prec, refine, prec);
                    let sym = Symbol::new_fast(&params, &Float::with_val(prec, set.n), &rule, prec).unwrap();
                    let (screen, (f, g0, df, dg)) = screen(&set, prec, refine).expect("the f64 start converges");
                    let case = format!("nu = {nu}, n = {n}, {prec} bits");
                    let bounded = tanh_sinh_f64_bounded(prec, refine);
                    assert_eq!(bounded.len(), rule.len(), "{case}");
                    for (j, &(s, c, w, err)) in bounded.iter().enumerate() {
                        for (x, y) in [(s, &rule.s[j]), (c, &rule.c[j]), (w, &rule.w[j])] {
                            let y = y.to_f64();
                            assert!((x - y).abs() <= (err + U) * y.abs(), "{case}: node {j}: {x} vs {y}, {err}");
                        }
                    }
                    assert!((f - sym.f0.to_f64()).abs() <= df + U * f.abs(), "{case}: f0");
                    assert!((g0 - sym.g0.to_f64()).abs() <= dg + U * g0.abs(), "{case}: g0");
                    worst = worst.max((g0 - sym.g0.to_f64()).abs() / dg);
                    assert_eq!(screen.nodes.len(), sym.nodes.len(), "{case}");
                    let mpfr = Screen::new(&sym.nodes);
                    for (a, b) in screen.nodes.iter().zip(&mpfr.nodes) {
                        let within = |x: f64, y: f64, bound: f64| (x - y).abs() <= bound + U * y.abs();
                        assert!(within(a.ln_s, b.ln_s, a.ln_s_err * a.ln_s.abs()), "{case}: ln s {a:?} {b:?}");
                        assert!(within(a.r, b.r, a.r_err * a.r.abs()), "{case}: r {a:?} {b:?}");
                        for k in 0..2 {
                            for j in 0..2 {
                                assert!(within(a.sides[k][j], b.sides[k][j], a.sides_err[k][j]), "{case}: {a:?} {b:?}");
                                worst = worst.max((a.sides[k][j] - b.sides[k][j]).abs() / a.sides_err[k][j]);
                            }
                        }
                    }
                    for mu in [0.0, 1.0, 7.0, 31.0, 178.0, 604.0, 1999.0] {
                        let a = screen.det(mu);
                        let exact = sym.det(&Float::with_val(prec, mu)).to_f64();
                        assert!((a.value - exact).abs() <= a.bound, "{case}, mu = {mu}: {a:?} vs {exact}");
                    }
                }
            }
        }
        eprintln!("largest error / bound of g0 and the weights: {worst:.2e}");
    }

    /// The f64 answer equals the MPFR runs' wherever it is given, and it is given at the shipped
    /// scene (nu = 3/10, n = 1/5) and the other cases without a zero below; where det M has a
    /// zero (nu = 0, n = 1/5, 1/2, 1 and n = 0: mu* = 178.3, 31.8, 1.09, 603.7; nu = 3/10, n = 1:
    /// 252.0), it is not. At nu = 1/2 (eps = 0) det M is -pi^2 to 1e-8 at every mu up to 1000: the
    /// scan's comparisons of |det M| at neighbours are below the screen's bound, and the MPFR runs
    /// answer (no zero).
    #[test]
    fn answers_as_the_mpfr_runs() {
        let cases = [
            (q(3, 10), q(1, 5), true),
            (q(3, 10), q(1, 2), true),
            (q(1, 5), q(1, 5), true),
            (q(2, 5), q(1, 2), true),
            (q(1, 10), q(0, 1), true),
            (q(3, 10), q(1, 1), false),
            (q(1, 2), q(1, 1), false),
            (q(0, 1), q(1, 5), false),
            (q(0, 1), q(1, 2), false),
            (q(0, 1), q(1, 1), false),
            (q(0, 1), q(0, 1), false),
        ];
        for (nu, n, given) in cases {
            let quick = no_zero(&nu, &n, 12);
            assert_eq!(quick.is_some(), given, "nu = {nu}, n = {n}");
            let mpfr = mode_exponent(&nu, &n, 12).unwrap();
            if let Some(m) = quick {
                assert!(mpfr.mu.is_none() && m.mu.is_none(), "nu = {nu}, n = {n}");
                assert_eq!(m.digits, mpfr.digits);
                assert_eq!(m.json(0), mpfr.json(0));
                assert!((m.g0.to_f64() - mpfr.g0.to_f64()).abs() < 1e-14);
            } else {
                assert_eq!(mpfr.mu.is_some(), nu != q(1, 2), "nu = {nu}, n = {n}");
            }
        }
        assert!(no_zero(&q(3, 5), &q(1, 5), 12).is_none() && no_zero(&q(0, 1), &q(-1, 5), 12).is_none());
    }

    /// The same over a grid, nu = 0, 1/20, .., 1/2 and n = 0, 1/10, .., 1 (121 cases): wherever
    /// the f64 answer is given, the MPFR runs find no zero either, with the same JSON; it is given
    /// in most cases without a zero (measured: 51 of 62, all but the 11 at nu = 1/2; 7.1 s in the
    /// test profile).
    #[test]
    fn answers_as_the_mpfr_runs_on_a_grid() {
        let (mut given, mut none) = (0, 0);
        for j in 0..=10 {
            for k in 0..=10 {
                let (nu, n) = (q(j, 20), q(k, 10));
                let mpfr = mode_exponent(&nu, &n, 12).unwrap();
                none += usize::from(mpfr.mu.is_none());
                if let Some(m) = no_zero(&nu, &n, 12) {
                    given += 1;
                    assert!(mpfr.mu.is_none(), "nu = {nu}, n = {n}: MPFR finds {:?}", mpfr.mu);
                    assert_eq!(m.json(0), mpfr.json(0), "nu = {nu}, n = {n}");
                }
            }
        }
        eprintln!("the f64 answer given in {given} of the {none} cases without a zero");
        assert!(4 * given >= 3 * none, "{given} of {none}");
    }
}
