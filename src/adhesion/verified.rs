//! `solve_verified`: the MPFR method run twice (the second with more bits, more Chebyshev nodes
//! and a finer quadrature step), and per-quantity verified digits
//! digits = -log10(|difference| / scale) with the scales of the issue: P2 for the load (a for the
//! half-width when the load is given), k a^2 for phi, k a for psi, E* k a for the stresses.
//! The headline is the minimum. The values reported are those of the finer run.
//! Conditioning warnings say where digits are lost (THEORY.md section 7).

use super::error::AdhesionError;
use super::solution::{solve_mpfr_with, AdhesionSolution};
use super::volterra_mpfr::VolterraParams;
use crate::model::{AdhesionProblem, AdhesionSize, Exact};
use crate::numerics::exact::to_float;
use rug::Float;
use std::time::Instant;

/// Below this many verified digits `solve_verified` returns `IllConditioned` instead of values.
pub const MIN_DIGITS: f64 = 2.0;

/// Verified digits per quantity (minimum over the points).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DigitsVerified {
    /// P2 (given a) or a (given P2).
    pub size: f64,
    /// psi, scale k a.
    pub psi: f64,
    /// phi, scale k a^2.
    pub phi: f64,
    /// q1, scale E* k a.
    pub q1: f64,
    /// q2, scale E* k a.
    pub q2: f64,
    /// The minimum of the above.
    pub headline: f64,
}

/// A verified MPFR solution.
#[derive(Debug, Clone)]
pub struct VerifiedSolution {
    /// The finer run.
    pub solution: AdhesionSolution,
    /// Verified digits.
    pub digits_verified: DigitsVerified,
    /// Requested digits.
    pub digits_requested: u32,
    /// Discretisations of the two runs.
    pub runs: [VolterraParams; 2],
    /// Wall time of both runs, seconds (measured, for reports).
    pub elapsed_seconds: f64,
    /// Human-readable notes on conditioning (empty when nothing to say).
    pub warnings: Vec<String>,
}

/// Digits from a difference and a scale; capped at `cap` when the difference is zero.
fn digits(diff: &Float, scale: &Float, cap: f64) -> f64 {
    let s = scale.clone().abs();
    if s.is_zero() {
        return if diff.is_zero() { cap } else { 0.0 };
    }
    let r = Float::with_val(64, diff.clone().abs() / &s).to_f64();
    if r == 0.0 {
        cap
    } else {
        (-r.log10()).clamp(0.0, cap)
    }
}

/// Two MPFR runs and their agreement (see module doc). `digits` in 5..=300.
pub fn solve_verified(
    problem: &AdhesionProblem,
    points: &[Exact],
    digits_requested: u32,
) -> Result<VerifiedSolution, AdhesionError> {
    if !(5..=300).contains(&digits_requested) {
        return Err(AdhesionError::InvalidArgument {
            parameter: "digits",
            value: digits_requested.to_string(),
            expected: "must lie in [5, 300]".into(),
        });
    }
    let start = Instant::now();
    let p1 = VolterraParams::for_digits(digits_requested);
    let p2 = p1.refined();
    let s1 = solve_mpfr_with(problem, points, p1, false)?;
    let s2 = solve_mpfr_with(problem, points, p2, true)?;
    let elapsed_seconds = start.elapsed().as_secs_f64();
    let cap = (p1.prec as f64) * std::f64::consts::LOG10_2;
    let prec = p2.prec;
    let d = |x: &Float, y: &Float| Float::with_val(prec, x - y);
    let size = match problem.size() {
        AdhesionSize::HalfWidth(_) => digits(&d(&s1.normal_load, &s2.normal_load), &s2.normal_load, cap),
        AdhesionSize::NormalLoad(_) => digits(&d(&s1.half_width, &s2.half_width), &s2.half_width, cap),
    };
    let a = &s2.half_width;
    let k = to_float(problem.curvature(), prec);
    let e_star = to_float(problem.material().contact_modulus(), prec);
    let ka = Float::with_val(prec, &k * a);
    let ka2 = Float::with_val(prec, &ka * a);
    let eka = Float::with_val(prec, &ka * &e_star);
    let (mut psi, mut phi, mut q1, mut q2) = (cap, cap, cap, cap);
    for (u, v) in s1.points.iter().zip(&s2.points) {
        psi = psi.min(digits(&d(&u.psi, &v.psi), &ka, cap));
        phi = phi.min(digits(&d(&u.phi, &v.phi), &ka2, cap));
        q1 = q1.min(digits(&d(&u.q1, &v.q1), &eka, cap));
        q2 = q2.min(digits(&d(&u.q2, &v.q2), &eka, cap));
    }
    let headline = size.min(psi).min(phi).min(q1).min(q2);
    let mut warnings = Vec::new();
    let lam = s2.lambda.to_f64();
    if headline < MIN_DIGITS {
        return Err(AdhesionError::IllConditioned {
            method: "mpfr-volterra",
            parameter: "lambda",
            value: format!("{lam}"),
            valid: "small nu: lambda below ~0.85 (nu = 0) or ~1.35 (nu = 0.3); lambda < pi/2 otherwise".into(),
            reason: format!(
                "two runs agree to only {headline:.1} digits: the Volterra equation of the incremental method is \
                 ill-conditioned here (see volterra_mpfr, Conditioning)"
            ),
        });
    }
    if headline < digits_requested as f64 {
        warnings.push(format!(
            "only {headline:.1} of {digits_requested} requested digits verified (lambda = {lam:.6}; \
             near full contact lambda -> pi/2 the solution is singular and the discretisation converges slowly)"
        ));
    }
    if s2.pivot_ratio > 1e12 {
        warnings.push(format!("collocation matrix pivot ratio {:.2e}: ill-conditioned, digits lost", s2.pivot_ratio));
    }
    if !s2.tension.zones.is_empty() {
        let z = &s2.tension.zones[0];
        warnings.push(format!(
            "tension q2 < 0 for 1 - x/a in ({:.6e}, {:.6e}) and in infinitely many thinner zones nearer the edge (oscillating edge singularity)",
            z.delta_inner.to_f64(),
            z.delta_outer.to_f64()
        ));
    }
    Ok(VerifiedSolution {
        solution: s2,
        digits_verified: DigitsVerified { size, psi, phi, q1, q2, headline },
        digits_requested,
        runs: [p1, p2],
        elapsed_seconds,
        warnings,
    })
}
