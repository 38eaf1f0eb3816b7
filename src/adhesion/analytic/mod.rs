//! Method `analytic` (issue 31): the member of Problem 2's complete adhesion that is analytic at
//! zero size (C = 0 in docs/theory.md section 11: the paper's series, continued), to the digits
//! asked, for the parabolic punch in the `paper` convention at a given half-width.
//!
//! Below nu = 1/2 the incremental equation fixes P' only up to C H(eta), H ~ eta^m*
//! ([`crate::asymptotics::adhesion_mode`]); the verified MPFR method keeps only the digits the mode
//! leaves (lambda_h). This method selects C = 0 explicitly: Phi(t) = cos(eta) P'(eta) is the
//! tangent-variable series ([`crate::asymptotics::adhesion_numeric::tangent_coefficients`]) up to
//! t0 = tan eta0, and beyond it a Chebyshev collocation of the equation whose history is that series
//! ([`continuation`]). The forward solve amplifies every error of the history and of the
//! interpolant by the mode's growth from eta0 to lambda: a run's error is its interpolant's tail
//! times an amplification A, measured here as the two runs' difference over the first run's tail
//! (nu = 0, eta0 = 0.45, lambda = 1: A ~ 10^95). So the runs carry digits + log10 A +
//! [`GUARD_DIGITS`] digits and enough nodes for the tail to fall below 10^-(digits + 2)/A. This
//! holds while the mode's growth G from eta0 to lambda (frozen symbol) is representable, up to
//! [`GROWTH_CAP`] decades; beyond it (nu = 3/10: G = 2.3e5 from 0.45 to 1.35) the history does not
//! fix C, the runs agree only to the digits the mode leaves until full contact, whatever their
//! nodes, bits and eta0, and one attempt is made ([`reach`]: where the method holds the digits).
//!
//! # Verification
//! Three runs: A (eta0 = [`ETA0`], its precision and n nodes), B (the same eta0, 64 more bits and
//! 9/8 the nodes) and C (eta0 = [`ETA0_ALT`], A's precision and nodes). The digits are the smaller
//! agreement of B and of C with A (two precisions, two eta0, two node counts). When A and B agree
//! to fewer digits than asked, A's node count is raised by 30% and its precision by the measured A,
//! up to [`MAX_NODES`] (only where G <= [`GROWTH_CAP`]); then the method refuses with the
//! amplification it measured, the mode's growth, R(lambda) where the history does not fix C, and
//! the largest lambda that holds the digits asked at that nu ([`reach::Reach`]).
//!
//! The series part costs O(J^2) for J = [`continuation::SERIES_POWERS`], the collocation about
//! n^2 (n + quadrature nodes) multiplications per run.
//!
//! # Measured (release build, two cores shared by four jobs)
//! nu = 0: lambda = 0.41, 15 digits asked: 30.8 verified, equal to the verified MPFR method to 36.8
//! digits (test `below_the_horizon_it_equals_the_default_method`, normal tier, 12 s of CPU);
//! lambda = 0.6: 21.7 digits, A = 10^50, 56 s (`solve --method analytic --digits 20`, a = 0.19,
//! L = 1); lambda = 0.8: 30.7 digits (runs of 331/372/331 nodes at 459/523/459 bits), A = 10^86,
//! 178 s, where the verified MPFR method keeps about 17 (long tier:
//! `at_lambda_0_8_it_equals_the_default_method`); lambda = 1.2: P = 7.2670319702254635691189 with
//! 34.9 verified digits, A = 10^104, 1435 s on a machine loaded 8 deep (long tier:
//! `at_nu_0_lambda_1_2_it_verifies_twenty_digits`). nu = 3/10: lambda = 1.3, 37.0 digits asked 30;
//! lambda = 1.333 (the reach for 20 digits), 21.2 digits, 3.5 s; 1.337: 19.8; lambda = 1.35: two
//! runs agree to 13.9 digits (75 nodes; 12.7-15 with 75-240 nodes, 200-500 bits, eta0 0.42-0.6;
//! R(1.35) = 14.1), refused with the reach 1.333 (tests `at_nu_0_3_its_reach_holds_twenty_digits`,
//! `at_nu_0_3_lambda_1_5_the_refusal_names_its_reach`).

pub mod continuation;
pub mod product;
pub mod reach;

use crate::asymptotics::adhesion_mode::{digits_kept, KEPT_MARGIN};
use crate::error::Error;
use crate::model::Material;
use crate::numerics::accuracy::verified_digits_mpfr;
use crate::numerics::precision::bits_for_digits;
use crate::params::adhesion::AdhesionParamsF64;
use rug::Float;

/// eta0 of runs A and B.
pub const ETA0: f64 = 0.45;
/// eta0 of run C.
pub const ETA0_ALT: f64 = 0.42;
/// Digits carried beyond digits + log10 A.
pub const GUARD_DIGITS: u32 = 15;
/// Largest Chebyshev node count.
pub const MAX_NODES: usize = 640;
/// Smallest node count.
pub const FIRST_NODES: usize = 60;
/// Attempts (node and precision raises) before refusing.
pub const ATTEMPTS: usize = 3;
/// The first attempt carries GROWTH_FACTOR times the frozen symbol's decades of growth G from eta0
/// to lambda ([`reach::history_growth`]; nu = 0, lambda = 0.8: 75 against 86 measured) when G is
/// at most [`GROWTH_CAP`].
pub const GROWTH_FACTOR: f64 = 1.2;
/// The largest growth G (decades) through which the history fixes C ([`reach`]): beyond it the
/// mode is not representable by [`MAX_NODES`] nodes, and the runs, one attempt without raises, agree
/// only to the digits the mode leaves (nu = 3/10, lambda = 1.35: G = 2.3e5; 12.7-15 digits with
/// 75-240 nodes at 200-500 bits).
pub const GROWTH_CAP: f64 = 150.0;
/// Decay of the interpolant's tail per node (measured: 0.42 at nu = 0, lambda = 0.8; 0.18 at
/// nu = 3/10, lambda = 1.35), for the first node count.
pub const DIGITS_PER_NODE: f64 = 0.4;

/// The verified continuation at one size.
#[derive(Debug, Clone)]
pub struct Analytic {
    /// lambda = pi a/L.
    pub lambda: Float,
    /// P(lambda) = int_0^lambda P'(eta) d eta (P2 = E* k (L/pi)^2 P), run A's value.
    pub load: Float,
    /// Verified digits of P (min of the agreements of B and C with A).
    pub digits: f64,
    /// The measured amplification log10 A (module doc).
    pub amplification_log10: f64,
    /// Runs A, B, C.
    pub runs: Vec<continuation::Run>,
    /// Wall time of all runs (seconds), including the attempts that were raised.
    pub seconds: f64,
}

/// Agreement of two loads in digits relative to the first (capped by `cap`).
fn agreement(a: &Float, b: &Float, cap: f64) -> f64 {
    let diff = Float::with_val(a.prec(), a - b);
    verified_digits_mpfr(&diff, &Float::with_val(a.prec(), a.abs_ref()), cap)
}

/// eta0 of a run at size lambda: [`ETA0`] (or [`ETA0_ALT`]) below lambda, else 0.8 lambda (0.75).
fn eta0_for(lambda: f64, alt: bool) -> f64 {
    let e = if alt { ETA0_ALT } else { ETA0 };
    if lambda > e / 0.9 {
        e
    } else if alt {
        0.75 * lambda
    } else {
        0.8 * lambda
    }
}

/// The C = 0 member's P(lambda) at `digits` (module doc), for `material` and 0 < lambda < pi/2.
pub fn continue_to(material: &Material, lambda: &Float, digits: u32) -> Result<Analytic, Error> {
    let lam = lambda.to_f64();
    if !(lam > 0.0 && lam < std::f64::consts::FRAC_PI_2) {
        return Err(Error::input("lambda", lam, "must lie in (0, pi/2) for the analytic method"));
    }
    let start = std::time::Instant::now();
    let (e_a, e_c) = (eta0_for(lam, false), eta0_for(lam, true));
    // First guess from the frozen symbol: the mode's decades of growth from eta0 to lambda.
    let c = AdhesionParamsF64::new(material);
    let growth = reach::history_growth(c.eps, c.b, c.s, e_a, lam, GROWTH_CAP);
    let pinned = growth <= GROWTH_CAP;
    let mut amp = if pinned { GROWTH_FACTOR * growth } else { 0.0 };
    let attempts = if pinned { ATTEMPTS } else { 1 };
    let mut n = (((digits as f64 + amp + 10.0) / DIGITS_PER_NODE).ceil() as usize).clamp(FIRST_NODES, MAX_NODES);
    let mut last = None;
    for _ in 0..attempts {
        let prec = bits_for_digits(digits + amp.ceil() as u32 + GUARD_DIGITS);
        let lam_p = Float::with_val(prec + 64, lambda);
        let a = continuation::run(material, &lam_p, e_a, prec, n)?;
        let b = continuation::run(material, &lam_p, e_a, prec + 64, n + n / 8)?;
        let cap = (prec as f64) * std::f64::consts::LOG10_2 - 5.0;
        let ab = agreement(&a.load, &b.load, cap);
        // Measured amplification: the runs' relative difference over A's interpolation tail.
        let measured = (-ab - a.tail.log10()).max(0.0);
        if ab >= digits as f64 + 1.0 {
            let c = continuation::run(material, &lam_p, e_c, prec, n)?;
            let ac = agreement(&a.load, &c.load, cap);
            return Ok(Analytic {
                lambda: Float::with_val(prec, lambda),
                load: a.load.clone(),
                digits: ab.min(ac),
                amplification_log10: measured,
                runs: vec![a, b, c],
                seconds: start.elapsed().as_secs_f64(),
            });
        }
        last = Some((ab, measured, a.nodes));
        if a.nodes >= MAX_NODES {
            break;
        }
        n = (n + n * 3 / 10).min(MAX_NODES);
        amp = amp.max(measured + 5.0);
    }
    let (ab, measured, nodes) = last.expect("at least one attempt");
    let r = reach::reach(material, digits as f64, ETA0, GROWTH_CAP);
    let why = if pinned {
        format!("{MAX_NODES} nodes are the most this method takes")
    } else {
        format!(
            "the mode grows by more than 10^{GROWTH_CAP:.0} from eta0 = {e_a} to lambda (frozen symbol), so the series \
             history does not fix C and no node count or precision adds digits beyond those the mode leaves until full \
             contact, R(lambda) = {} here (docs/theory.md section 11)",
            crate::numerics::accuracy::digits_text(digits_kept(c.eps, c.b, c.s, lam) + KEPT_MARGIN)
        )
    };
    Err(Error::NoConvergence {
        what: format!(
            "analytic continuation at lambda = {lam}: with {nodes} Chebyshev nodes two runs agree to {} of the \
             {digits} digits asked; the forward solve amplifies the interpolation error by 10^{measured:.0} (measured: \
             the runs' difference over the first run's Chebyshev tail), and {why}; this method holds {digits} digits \
             at this nu {}",
            crate::numerics::accuracy::digits_text(ab),
            r.text()
        ),
    })
}
