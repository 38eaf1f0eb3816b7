//! One run of one method with one knob, timed, and its error against a reference run.
//!
//! The quantities compared are those a load-size curve needs: for Problem 1 the contact
//! half-length l and centre c (error max(|dl|, |dc|)/l_ref) when the load is given, the load P2
//! (|dP2|/P2_ref) when l is given; for Problem 2 the load P2 when a is given, a when P2 is given.
//! Values are kept as MPFR floats so that errors far below f64 round-off are measured.

use periodic_contact::adhesion::{self, volterra_mpfr::VolterraParams};
use periodic_contact::asymptotics::sliding::{sliding_expansion_with, SlidingExpansion, SlidingShape};
use periodic_contact::model::OnPunchRow;
use periodic_contact::model::{AdhesionProblem, AdhesionSize, Convention, PunchShape, SlidingLoad, SlidingProblem};
use periodic_contact::scene::SceneProblem;
use periodic_contact::sliding::series::series_point;
use periodic_contact::sliding::{self, collocation_f64, Checks, NodeRule};
use rug::Float;
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock, PoisonError};
use std::time::Instant;

/// Working precision of comparisons (bits): errors down to 1e-70 are resolved.
pub const COMPARE_BITS: u32 = 256;

pub use periodic_contact::solve::choice::Knob;

/// What a run produced: the size/load quantities at [`COMPARE_BITS`].
#[derive(Debug, Clone)]
pub struct Outcome {
    /// Problem 1: l; Problem 2: a.
    pub size: Float,
    /// Problem 1: c (0 for Problem 2).
    pub centre: Float,
    /// P2.
    pub load: Float,
    /// lambda = pi l/L or pi a/L (0 for a single punch), f64.
    pub lambda: f64,
    /// Verified digits when the method verifies itself (MPFR verified).
    pub verified_digits: Option<f64>,
    /// Wall time of the run in seconds.
    pub seconds: f64,
}

/// Relative error of `o` against `reference` (see module doc); `given_size` says which quantity
/// the problem fixes.
pub fn error(o: &Outcome, reference: &Outcome, given_size: bool) -> f64 {
    let p = COMPARE_BITS;
    if given_size {
        let d = Float::with_val(p, &o.load - &reference.load).abs();
        (d / reference.load.clone().abs()).to_f64()
    } else {
        let dl = Float::with_val(p, &o.size - &reference.size).abs();
        let dc = Float::with_val(p, &o.centre - &reference.centre).abs();
        (dl.max(&dc) / reference.size.clone().abs()).to_f64()
    }
}

/// Digits from a relative error: the accuracy rule ([`periodic_contact::numerics::accuracy::verified_digits`])
/// at scale 1, capped at `cap`.
pub fn digits_of(err: f64, cap: f64) -> f64 {
    periodic_contact::numerics::accuracy::verified_digits(err, 1.0, cap)
}

/// Whether the problem fixes the size (direct problem) rather than the load.
pub fn given_size(p: &SceneProblem) -> bool {
    match p {
        SceneProblem::Sliding(s) => matches!(s.load(), SlidingLoad::HalfLength(_)),
        SceneProblem::Adhesion(a) => matches!(a.size(), AdhesionSize::HalfWidth(_)),
        SceneProblem::LoadingLaw(p) => matches!(p.size(), periodic_contact::model::LawSize::HalfLength(_)),
    }
}

/// What one report run shares across its sections, cells and threads, so that nothing is computed
/// twice (issue 14):
/// - the exact expansions, derived once per (shape, convention) and kept at the largest order
///   asked so far (derivation time is not part of a run's time: it is a one-off, like the
///   coefficient tables). The parabola's are derived at once through [`MAX_SERIES_ORDER`] (under a
///   second); the sinusoid's only through the order asked, since their cost grows steeply with the
///   order (release build: `paper` about 3 s at order 12 and 24 s at 16, `periodic` about 2.5 s at
///   order 8 and 100 s at 12; measured by `cargo run --release --example expansion_timing`);
/// - every run of [`run`], keyed exactly by (problem, knob): a cell, a sweep point or a check
///   that asks for the same run gets the first one's outcome (and its measured time);
/// - the verified MPFR solutions of Problem 1 ([`verified_sliding`]), which the load-size curves,
///   the stability maps and "paper vs periodic" share.
///
/// Thread-safe: a value being computed by one thread is waited for, not computed again by another.
/// A computation behind the cache must not wait on the report's thread pool (no rayon inside a
/// solver called from here), or a worker waiting for its own slot would deadlock.
#[derive(Default)]
pub struct RunCache {
    expansions: Mutex<HashMap<(bool, bool), ExpansionSlot>>,
    runs: Memo<(SceneProblem, Knob), Result<Outcome, String>>,
    verified: Memo<(SlidingProblem, u32), Result<VerifiedRun, String>>,
    adhesion_verified: Memo<(AdhesionProblem, u32), (AdhesionVerifiedResult, f64)>,
}

type AdhesionVerifiedResult = Result<Arc<adhesion::VerifiedSolution>, adhesion::AdhesionError>;

type ExpansionSlot = Arc<Mutex<Option<(usize, Arc<SlidingExpansion>)>>>;

/// A memo: one slot per key, filled once.
struct Memo<K, V>(Mutex<HashMap<K, Arc<OnceLock<V>>>>);

impl<K, V> Default for Memo<K, V> {
    fn default() -> Self {
        Memo(Mutex::new(HashMap::new()))
    }
}

impl<K: std::hash::Hash + Eq, V: Clone> Memo<K, V> {
    /// The value of `key`, computed by `f` the first time it is asked.
    fn get_or(&self, key: K, f: impl FnOnce() -> V) -> V {
        let slot = self.0.lock().unwrap_or_else(PoisonError::into_inner).entry(key).or_default().clone();
        slot.get_or_init(f).clone()
    }
}

/// A verified MPFR solution of Problem 1 (the first, smallest physical contact) with the wall time
/// of the solve.
#[derive(Debug, Clone)]
pub struct VerifiedRun {
    /// The solution and its verified digits.
    pub solution: Arc<sliding::VerifiedSolution>,
    /// Wall time of the solve in seconds.
    pub seconds: f64,
}

/// [`sliding::solve_verified`] at `digits` (the first physical solution), once per (problem, digits)
/// in `cache`; errors as the report states them.
pub fn verified_sliding(cache: &RunCache, p: &SlidingProblem, digits: u32) -> Result<VerifiedRun, String> {
    cache.verified.get_or((p.clone(), digits), || {
        let start = Instant::now();
        let sols = sliding::solve_verified(p, &[], digits).map_err(why)?;
        let seconds = start.elapsed().as_secs_f64();
        let v = sols.into_iter().next().ok_or("no physical solution")?;
        Ok(VerifiedRun { solution: Arc::new(v), seconds })
    })
}

/// [`adhesion::solve_verified`] at `digits`, once per (problem, digits) in `cache`, with the wall
/// time of the solve: the stability map's cells and the Pade section's Problem 2 references share
/// it. The error is the solver's own (each caller words it as before).
pub fn verified_adhesion_timed(cache: &RunCache, p: &AdhesionProblem, digits: u32) -> (AdhesionVerifiedResult, f64) {
    cache.adhesion_verified.get_or((p.clone(), digits), || {
        let start = Instant::now();
        let r = adhesion::solve_verified(p, &[], digits).map(Arc::new);
        (r, start.elapsed().as_secs_f64())
    })
}

/// [`verified_adhesion_timed`] without the time.
pub fn verified_adhesion(cache: &RunCache, p: &AdhesionProblem, digits: u32) -> AdhesionVerifiedResult {
    verified_adhesion_timed(cache, p, digits).0
}

impl RunCache {
    /// The expansion of `shape` in `convention` through at least Lambda^order.
    pub fn expansion(
        &self,
        shape: SlidingShape,
        convention: Convention,
        order: usize,
    ) -> Result<Arc<SlidingExpansion>, String> {
        let key = (shape == SlidingShape::Parabolic, convention == Convention::PeriodicSurface);
        let slot = self.expansions.lock().unwrap_or_else(PoisonError::into_inner).entry(key).or_default().clone();
        let mut have = slot.lock().unwrap_or_else(PoisonError::into_inner);
        if let Some((at, e)) = have.as_ref() {
            if *at >= order {
                return Ok(e.clone());
            }
        }
        let at = if key.0 { MAX_SERIES_ORDER.max(order) } else { order };
        let e = Arc::new(sliding_expansion_with(shape, at, convention).map_err(|e| e.to_string())?);
        *have = Some((at, e.clone()));
        Ok(e)
    }
}

/// Largest series order the report uses.
pub const MAX_SERIES_ORDER: usize = 16;

fn f(x: f64) -> Float {
    Float::with_val(COMPARE_BITS, x)
}

/// A method's failure as the report states it: through the project's error type, so that its kind
/// prefix ("no solution:", "not physical:", ...) is said once and its numbers are readable.
fn why(e: impl Into<periodic_contact::error::Error>) -> String {
    e.into().to_string()
}

/// Working precision of the series evaluations of the report: 128 bits (38 digits), beyond the
/// accuracy of every truncated series the report shows (at most ~30 digits at its smallest
/// contacts), so that rounding never shows in their measured errors.
pub const SERIES_BITS: u32 = 128;

/// Why a loading-law scene (docs/theory.md section 10) has no row in the report's method sections.
pub const LOADING_LAW_NOT_IN_REPORT: &str =
    "the loading-law problem is solved by `periodic-contact solve` (MPFR only) and in the section \"Loading law\", not by this section's methods";

/// Runs `knob` on `problem`, once per (problem, knob) in `cache`. Errors are the method's own (no
/// solution, no convergence, not applicable), as text for the report.
pub fn run(problem: &SceneProblem, knob: Knob, cache: &RunCache) -> Result<Outcome, String> {
    cache.runs.get_or((problem.clone(), knob), || run_uncached(problem, knob, cache))
}

fn run_uncached(problem: &SceneProblem, knob: Knob, cache: &RunCache) -> Result<Outcome, String> {
    match problem {
        SceneProblem::Sliding(p) => run_sliding(p, knob, cache),
        SceneProblem::Adhesion(p) => run_adhesion(p, knob, cache),
        SceneProblem::LoadingLaw(_) => Err(LOADING_LAW_NOT_IN_REPORT.into()),
    }
}

fn run_sliding(p: &SlidingProblem, knob: Knob, cache: &RunCache) -> Result<Outcome, String> {
    let pi = std::f64::consts::PI;
    let period = match p.period() {
        periodic_contact::model::Period::Finite(l) => periodic_contact::numerics::exact::to_f64(l),
        periodic_contact::model::Period::Infinite => None,
    };
    let lam = |l: f64| period.map_or(0.0, |big_l| pi * l / big_l);
    match knob {
        Knob::Series(n) => {
            let shape = periodic_contact::sliding::series::expansion_shape(p).map_err(|e| e.to_string())?;
            let e = cache.expansion(shape, p.convention(), n)?;
            let prec = SERIES_BITS;
            let start = Instant::now();
            let sp = series_point(p, prec).map_err(|e| e.to_string())?;
            let (l, c) = sp.contact(&e, n);
            let seconds = start.elapsed().as_secs_f64();
            let load = match p.load() {
                SlidingLoad::NormalLoad(x) => periodic_contact::numerics::exact::to_float(x, COMPARE_BITS),
                SlidingLoad::HalfLength(_) => return Err("the series expands at a given load".into()),
            };
            let lf = l.to_f64();
            Ok(Outcome {
                size: Float::with_val(COMPARE_BITS, &l),
                centre: Float::with_val(COMPARE_BITS, &c),
                load,
                lambda: lam(lf),
                verified_digits: None,
                seconds,
            })
        }
        Knob::F64(nodes) => {
            let opts = collocation_f64::SolverOptions {
                nodes,
                accept: if nodes.is_some() { 1.0 } else { 1e-8 },
                ..Default::default()
            };
            let start = Instant::now();
            let s = collocation_f64::solve_sliding_f64(p, &[], &opts).map_err(why)?;
            let seconds = start.elapsed().as_secs_f64();
            let s = s.primary();
            Ok(Outcome {
                size: f(s.l),
                centre: f(s.c),
                load: f(s.p2),
                lambda: lam(s.l),
                verified_digits: None,
                seconds,
            })
        }
        Knob::Mpfr(d) => {
            let start = Instant::now();
            let sols = sliding::solve_at(
                p,
                &[],
                NodeRule { digits: d as f64, factor: 1.0 },
                Checks::Physical,
                sliding::precision_for(d),
            )
            .map_err(why)?;
            let seconds = start.elapsed().as_secs_f64();
            let s = sols.first().ok_or("no physical solution")?;
            Ok(Outcome {
                size: Float::with_val(COMPARE_BITS, &s.l),
                centre: Float::with_val(COMPARE_BITS, &s.c),
                load: Float::with_val(COMPARE_BITS, &s.p2),
                lambda: lam(s.l.to_f64()),
                verified_digits: None,
                seconds,
            })
        }
        Knob::MpfrVerified(d) => {
            let VerifiedRun { solution: v, seconds } = verified_sliding(cache, p, d)?;
            let s = &v.solution;
            Ok(Outcome {
                size: Float::with_val(COMPARE_BITS, &s.l),
                centre: Float::with_val(COMPARE_BITS, &s.c),
                load: Float::with_val(COMPARE_BITS, &s.p2),
                lambda: lam(s.l.to_f64()),
                verified_digits: Some(v.accuracy.digits_verified),
                seconds,
            })
        }
    }
}

/// Largest order of the Problem 2 series in the report (its exact derivation at order 12 takes a
/// few seconds; it is built once per process).
pub const ADHESION_SERIES_ORDER: usize = 12;

fn adhesion_expansion_cached() -> Result<&'static periodic_contact::asymptotics::adhesion::AdhesionExpansion, String> {
    use std::sync::OnceLock;
    static CELL: OnceLock<Result<periodic_contact::asymptotics::adhesion::AdhesionExpansion, String>> = OnceLock::new();
    CELL.get_or_init(|| {
        periodic_contact::asymptotics::adhesion::adhesion_expansion_with(ADHESION_SERIES_ORDER, false)
            .map_err(|e| e.to_string())
    })
    .as_ref()
    .map_err(|e| e.clone())
}

/// Problem 2 by its truncated exact series [3.18]: P2 = C_P E* k a^2 sum_{2j <= n} c_2j lambda^2j,
/// coefficients evaluated at the scene's nu; given P2, a is found by the fixed point
/// a = sqrt(P2 / (C_P E* k S(lambda))), lambda = pi a/L (a contraction for small lambda).
fn adhesion_series(p: &AdhesionProblem, n: usize) -> Result<Outcome, String> {
    if n > ADHESION_SERIES_ORDER {
        return Err(format!("the report builds the Problem 2 series through order {ADHESION_SERIES_ORDER}"));
    }
    let e = adhesion_expansion_cached()?;
    let prec = SERIES_BITS;
    let start = Instant::now();
    let v = periodic_contact::asymptotics::adhesion::adhesion_values(e, p.material().poisson_ratio(), prec)
        .map_err(|e| e.to_string())?;
    let to = |q: &periodic_contact::model::Exact| periodic_contact::numerics::exact::to_float(q, prec);
    let k = match p.shape() {
        PunchShape::Parabolic { k } => to(k),
        _ => return Err("the adhesion problem is parabolic only".into()),
    };
    let pi = Float::with_val(prec, rug::float::Constant::Pi);
    let big_l = match p.period() {
        periodic_contact::model::Period::Finite(l) => Some(to(l)),
        periodic_contact::model::Period::Infinite => None,
    };
    let ck = Float::with_val(prec, &v.load_constant * to(p.material().contact_modulus())) * &k;
    let lambda_of = |a: &Float| big_l.as_ref().map_or(Float::with_val(prec, 0), |l| Float::with_val(prec, &pi * a) / l);
    let bracket = |lam: &Float| {
        let l2 = Float::with_val(prec, lam * lam);
        let mut acc = Float::with_val(prec, 0);
        for j in (0..=n / 2).rev() {
            acc *= &l2;
            acc += &v.load[2 * j];
        }
        acc
    };
    let (a, load) = match p.size() {
        AdhesionSize::HalfWidth(a) => {
            let a = to(a);
            let load = Float::with_val(prec, &ck * Float::with_val(prec, &a * &a)) * bracket(&lambda_of(&a));
            (a, load)
        }
        AdhesionSize::NormalLoad(p2) => {
            let p2 = to(p2);
            let mut a = Float::with_val(prec, &p2 / &ck).sqrt();
            for _ in 0..200 {
                let next = Float::with_val(prec, &p2 / Float::with_val(prec, &ck * bracket(&lambda_of(&a)))).sqrt();
                let done = Float::with_val(prec, &next - &a).abs() <= Float::with_val(prec, &a * 1e-36);
                a = next;
                if done {
                    break;
                }
            }
            (a, p2)
        }
    };
    let seconds = start.elapsed().as_secs_f64();
    Ok(Outcome {
        size: Float::with_val(COMPARE_BITS, &a),
        centre: Float::with_val(COMPARE_BITS, 0),
        load: Float::with_val(COMPARE_BITS, &load),
        lambda: lambda_of(&a).to_f64(),
        verified_digits: None,
        seconds,
    })
}

fn run_adhesion(p: &AdhesionProblem, knob: Knob, cache: &RunCache) -> Result<Outcome, String> {
    let zero = Float::with_val(COMPARE_BITS, 0);
    match knob {
        Knob::Series(n) => adhesion_series(p, n),
        Knob::F64(Some(_)) => Err("the f64 method of Problem 2 has no node knob".into()),
        Knob::F64(None) => {
            let start = Instant::now();
            let s = adhesion::solve_f64(p, &[]).map_err(why)?;
            let seconds = start.elapsed().as_secs_f64();
            Ok(Outcome {
                size: f(s.half_width),
                centre: zero,
                load: f(s.normal_load),
                lambda: s.lambda,
                verified_digits: None,
                seconds,
            })
        }
        Knob::Mpfr(d) => {
            let start = Instant::now();
            let s = adhesion::solve_mpfr_with(p, &[], VolterraParams::for_digits(d), adhesion::TensionZones::Skip)
                .map_err(why)?;
            let seconds = start.elapsed().as_secs_f64();
            Ok(Outcome {
                size: Float::with_val(COMPARE_BITS, &s.half_width),
                centre: zero,
                load: Float::with_val(COMPARE_BITS, &s.normal_load),
                lambda: s.lambda.to_f64(),
                verified_digits: None,
                seconds,
            })
        }
        Knob::MpfrVerified(d) => {
            let (v, seconds) = verified_adhesion_timed(cache, p, d.clamp(5, 300));
            let v = v.map_err(why)?;
            let s = &v.solution;
            Ok(Outcome {
                size: Float::with_val(COMPARE_BITS, &s.half_width),
                centre: zero,
                load: Float::with_val(COMPARE_BITS, &s.normal_load),
                lambda: s.lambda.to_f64(),
                verified_digits: Some(v.digits_verified.headline),
                seconds,
            })
        }
    }
}
