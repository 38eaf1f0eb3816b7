//! The error estimate of the truncated series (docs/theory.md section 5): how far the value through
//! Lambda^N may be from the sum of the whole series. Estimated, never verified.
//!
//! Every quantity q (l, c, F_def, p(xh)) is a series in Lambda^2; with V_m its value through
//! Lambda^(2m), its terms are t_0 = V_0 and t_m = V_m - V_(m-1), m = 1..K, K = N/2. The
//! remainder after t_K is estimated as a geometric tail:
//!
//! ```text
//! E_q = max(|t_K|, S M rho/(1 - rho)),   M = max_{0 <= i < W} |t_(K-i)| rho^i,
//! ```
//!
//! In the `periodic` convention (docs/theory.md section 8) the series hold every power of Lambda; the
//! terms are then taken in pairs, t_m = V_m - V_(m-1) with V_m the value through Lambda^(N-2(K-m))
//! (the terms of Lambda^(n-1) and Lambda^n together), so rho is still a rate per Lambda^2 and the
//! parabola's l/l_s, even in both conventions, gives no zero terms. The remainder after
//! Lambda^N is then O(Lambda^(N+1)) (not O(Lambda^(N+2)) as for the paper's even series): the last
//! pair term is O(Lambda^(N-1)) and the geometric tail S M rho/(1 - rho), rho ~ Lambda^2, is of the
//! order Lambda^(N+1) of that remainder.
//!
//! - rho, the rate of the terms per power of Lambda^2, is read from the half-length l (all
//!   quantities are series in the same Lambda^2 and share its singularities; the terms of l are
//!   regular while those of p(xh) at a fixed point change sign and stall): the largest
//!   (e_j/e_(j-2))^(1/2) over the last W terms of l/l_s, e_j = max(|t_j|, |t_(j-1)|) the envelope
//!   of a pair of terms ([`rate`]): the parabola's terms alternate large and small (its nearest
//!   singularities are the pair Lambda^2 = +-2 pi i), so single-step ratios from a small term to
//!   a large one exceed 1 inside the radius (they refused the frictionless parabola at
//!   Lambda = 1.77, where the pairs fall by 0.44 per Lambda^2);
//! - M, the envelope of the last W terms of q, keeps an accidentally small last term (a zero of
//!   the term's coefficient) from passing for convergence;
//! - S = 3: where the series' radius of convergence is near (the sinusoid as Lambda -> 1) the
//!   ratios of consecutive terms rise toward their limit, so a geometric tail from the last ratios
//!   falls short. With S = 1 the test `estimate_never_exceeds_the_true_digits` fails (frictionless
//!   sinusoid, pi a/L = 1, order 8); S = 2 passes it; S = 3 keeps a margin for problems off its grid
//!   (T != 0, other theta). Measured by running that test with `SAFETY` changed;
//! - never less than the last kept term |t_K| (the estimate of earlier versions: order N against
//!   N - 2), so these digits are never more than those.
//!
//! The digits of q are `verified_digits(E_q, scale_q, cap)` (`crate::numerics::accuracy`; cap: the
//! digits requested, also the digits of a quantity whose terms all vanish, e.g. c at theta = T = 0), with
//! the scales of the MPFR method: l for l, a, b, c; P2 for loads; k l P2 for F_def; max p (over the
//! requested points) for p. The series is refused when the terms of l do not decrease (rho >= 1)
//! or when the estimate leaves less than one digit: the refusal follows the estimate, not a fixed
//! bound on Lambda.

use rug::Float;

/// The safety factor S of the geometric tail (module doc).
pub const SAFETY: u32 = 3;

/// The number W of last terms the rate and the envelope are read from (module doc).
pub const WINDOW: usize = 3;

/// |t_0|, |t_1|, ..., |t_K| from the values V_0, ..., V_K of a quantity through Lambda^0,
/// Lambda^2, ..., Lambda^(2K).
pub fn terms(values: &[Float]) -> Vec<Float> {
    values
        .iter()
        .enumerate()
        .map(|(j, v)| if j == 0 { v.clone().abs() } else { Float::with_val(v.prec(), v - &values[j - 1]).abs() })
        .collect()
}

/// The rate rho of the terms |t_0|, ..., |t_K| (module doc): the largest of
/// (e_j/e_(j-2))^(1/2) over the last [`WINDOW`] terms (j >= 3), with the envelope of two
/// consecutive terms e_j = max(|t_j|, |t_(j-1)|), and also |t_j/t_(j-1)| and |t_j/t_(j-2)|^(1/2)
/// where |t_(j-2)| >= |t_(j-1)| >= |t_j| (monotone, no alternation); with K < 3 (fewer than two
/// pair envelopes) the largest of |t_j/t_(j-1)| and |t_j/t_(j-2)|^(1/2). Infinite when an envelope (a term) follows a
/// zero one; 0 when the terms read are all zero; infinite when K = 0 (no term to read a rate from).
///
/// Pairs, not single terms: a series whose nearest singularities are a complex-conjugate pair
/// has terms that alternate large and small (the parabola's l/l_s: Kuznetsov's
/// arccos(exp(-Lambda^2/2))/Lambda is singular at Lambda^2 = +-2 pi i, so at Lambda^2 = pi the
/// terms go 7.3e-6, 2.3e-7, 1.4e-6 at j = 11, 12, 13: single-step ratios up to 6, pair envelopes
/// falling by 0.44 per Lambda^2, the true rate 1/2). A geometric sequence r^j gives r; where the
/// terms decrease monotonically the single-step ratios count as before, since near the radius of
/// convergence (the sinusoid as Lambda -> 1) they rise toward their limit and the pair envelope
/// lags behind them (without them the test `estimate_never_exceeds_the_true_digits` fails:
/// frictionless sinusoid, pi a/L = 1.4, order 8, estimated 1.20 digits against 1.03 true).
pub fn rate(terms: &[Float]) -> f64 {
    let k = terms.len().saturating_sub(1);
    if k == 0 {
        return f64::INFINITY;
    }
    // (a/b)^(1/d); None: a zero term read, Some(inf): a term after a zero one.
    let ratio = |a: &Float, b: &Float, d: f64| -> Option<f64> {
        if a.is_zero() {
            None
        } else if b.is_zero() {
            Some(f64::INFINITY)
        } else {
            Some(Float::with_val(64, a / b).to_f64().powf(1.0 / d))
        }
    };
    let mut rho: f64 = 0.0;
    if k < 3 {
        // Too few terms for two pair envelopes: the single and two-step ratios.
        for j in 1..=k {
            for d in 1..=j.min(2) {
                if let Some(r) = ratio(&terms[j], &terms[j - d], d as f64) {
                    rho = rho.max(r);
                }
            }
        }
        return rho;
    }
    let env = |j: usize| -> &Float {
        if terms[j] > terms[j - 1] {
            &terms[j]
        } else {
            &terms[j - 1]
        }
    };
    for j in k.saturating_sub(WINDOW - 1).max(3)..=k {
        if let Some(r) = ratio(env(j), env(j - 2), 2.0) {
            rho = rho.max(r);
        }
        // Where the terms decrease monotonically (no alternation), the latest ratios too: near
        // the radius they rise toward their limit and the pair envelope lags behind them.
        if terms[j] <= terms[j - 1] && terms[j - 1] <= terms[j - 2] {
            for (b, d) in [(&terms[j - 1], 1.0), (&terms[j - 2], 2.0)] {
                if let Some(r) = ratio(&terms[j], b, d) {
                    rho = rho.max(r);
                }
            }
        }
    }
    rho
}

/// The error estimate E_q of a quantity with terms |t_0|, ..., |t_K| at the rate `rho` < 1
/// (module doc), at the precision of the terms.
///
/// # Panics
/// When `terms` is empty or `rho` is not in [0, 1) (the caller refuses rho >= 1).
pub fn tail(terms: &[Float], rho: f64) -> Float {
    assert!((0.0..1.0).contains(&rho), "the rate {rho} must lie in [0, 1)");
    let k = terms.len() - 1;
    let prec = terms[k].prec();
    let mut envelope = Float::with_val(prec, 0);
    let mut weight = 1.0;
    for i in 0..WINDOW.min(k) {
        let v = Float::with_val(prec, &terms[k - i] * weight);
        if v > envelope {
            envelope = v;
        }
        weight *= rho;
    }
    let geometric = envelope * (SAFETY as f64 * rho / (1.0 - rho));
    if geometric > terms[k] {
        geometric
    } else {
        terms[k].clone()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn seq(v: &[f64]) -> Vec<Float> {
        v.iter().map(|x| Float::with_val(100, *x)).collect()
    }

    #[test]
    fn geometric_terms_give_their_ratio_and_tail() {
        // t_j = 2^-j: rho = 1/2, tail S * 2^-K * (1/2)/(1/2) = 3 * 2^-K.
        let t = seq(&[1.0, 0.5, 0.25, 0.125, 0.0625]);
        assert_eq!(rate(&t), 0.5);
        assert_eq!(tail(&t, 0.5).to_f64(), 3.0 * 0.0625);
    }

    #[test]
    fn a_small_last_term_does_not_pass_for_convergence() {
        // The last term is accidentally tiny: the envelope keeps the one before (times rho).
        let t = seq(&[1.0, 0.1, 0.01, 1e-9]);
        let rho = 0.1;
        let e = tail(&t, rho).to_f64();
        assert!((e - 3.0 * 0.01 * 0.1 * 0.1 / 0.9).abs() < 1e-15, "{e}");
    }

    #[test]
    fn stalling_or_zero_terms() {
        // A zero term between non-zero ones is the extreme of alternation: the pair envelopes
        // (1, 0.01) give 0.1; a non-zero envelope after a zero one is infinite.
        assert_eq!(rate(&seq(&[1.0, 0.1, 0.0, 0.01])), 0.1);
        assert_eq!(rate(&seq(&[0.0, 0.0, 0.0, 0.01])), f64::INFINITY);
        // Alternating large and small (Kuznetsov's l/l_s at Lambda^2 = pi, j = 10..13, true rate
        // 1/2): pair envelopes fall by 0.44, single steps reach 6.1.
        let r = rate(&seq(&[1.0, 1.5e-6, 7.3e-6, 2.3e-7, 1.4e-6]));
        assert!((r - (1.4e-6f64 / 7.3e-6).sqrt()).abs() < 1e-12, "{r}");
        assert!(rate(&seq(&[1.0, 0.5, 0.6])) > 1.0);
        assert_eq!(rate(&seq(&[1.0, 0.0, 0.0])), 0.0);
        assert_eq!(tail(&seq(&[0.0, 0.0, 0.0]), 0.0).to_f64(), 0.0);
        assert_eq!(rate(&seq(&[1.0])), f64::INFINITY);
    }
}
