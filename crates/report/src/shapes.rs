//! Report section "Punch shapes": the polynomial and circular punches of the scenes (docs/theory.md
//! section 9) against the closed-form frictionless load of an even profile,
//!     P2 = (E*/2) int_{-a}^{a} g'(x) sin(pi x/L) dx / sqrt(sin^2(pi a/L) - sin^2(pi x/L)),
//! computed independently of the solvers ([`periodic_contact::verification::closed_form_load`]).
//!
//! One case per distinct (profile, period, E*) among the scenes with a `polynomial` or `circular`
//! punch (Problem 1 or 2; friction, wear and nu dropped: the closed form is frictionless, and its
//! load does not depend on nu). For each case, on a grid of half-widths a (lambda = pi a/L in
//! 0.2 .. 1.4, up to the small-slope limit |g'| <= 1/2, [`MAX_CONTACT_SLOPE`]):
//! - Problem 1 frictionless, half-length given: P2 by the verified MPFR method at [`DIGITS`]
//!   digits and by the f64 method, each against the closed form (relative difference and the
//!   digits they agree to), beside the MPFR run's own verified digits;
//! - Problem 2 at nu = 1/2 (eps = 0, where complete adhesion is the frictionless problem; docs/theory.md
//!   section 9) by the verified MPFR method and by the f64 method, against the same closed form
//!   (even profiles);
//! - the first grid size beyond the small-slope limit, run by MPFR to show that the solvers answer it
//!   with the small-slope warning (docs/theory.md section 9), not a refusal;
//! - one single punch (period "inf") against the power law P2 = n pi E* A a^(2n) (2n-1)!!/(2n)!!
//!   summed over the even terms (polynomials) or the closed form's single-punch quadrature
//!   (circle).
//!
//! A profile with odd terms has no closed form (its contact is off centre even without friction):
//! its MPFR and f64 curves are shown against each other. The friction scenes of the new profiles,
//! in both conventions, are in report section 7 (c/l and F_def against the load).

use super::chart::{Chart, Curve, Draw, Legend};
use super::runner::{self, Knob, Outcome, RunCache, COMPARE_BITS};
use super::section::{fmt_digits, Ctx, Profile, Section};
use num_traits::Zero;
use periodic_contact::model::OnPunchRow;
use periodic_contact::model::{AdhesionProblem, AdhesionSize, Exact, Material, Period, PunchShape, SlidingProblem};
use periodic_contact::numerics::accuracy::{fmt_mpfr, print_mpfr, readable_f64, verified_digits_mpfr, F64_DIGITS_CAP};
use periodic_contact::numerics::exact::{to_f64, to_float};
use periodic_contact::params::sliding::MAX_CONTACT_SLOPE;
use periodic_contact::scene::{Scene, SceneProblem};
use periodic_contact::verification::closed_form_load::{
    frictionless_load_mpfr, single_punch_power_law_mpfr, EvenSlope, LoadEstimate,
};
use rug::Float;
use std::f64::consts::PI;
use std::fmt::Write as _;
use std::time::Instant;

/// Digits asked of the verified MPFR runs (both problems).
pub const DIGITS: u32 = 30;

/// Significant digits printed at most for P2.
const PRINTED: u32 = 12;

/// The grid of lambda = pi a/L of the full report (the fast profile keeps 0.5 and 1.1).
pub const LAMBDAS: [f64; 5] = [0.2, 0.5, 0.8, 1.1, 1.4];

/// One profile of the scenes.
#[derive(Debug, Clone)]
pub struct ShapeCase {
    /// The scenes with this profile, period and E*.
    pub scenes: Vec<String>,
    /// The profile.
    pub shape: PunchShape,
    /// The period.
    pub period: Period,
    /// The contact modulus E*.
    pub e_star: Exact,
    /// Poisson's ratio of the first scene (Problem 1's frictionless load does not depend on it).
    pub nu: Exact,
}

impl ShapeCase {
    /// Whether the profile is even (no odd polynomial term): the closed form then applies.
    pub fn even(&self) -> bool {
        match &self.shape {
            PunchShape::Polynomial { coefficients } => {
                coefficients.iter().enumerate().all(|(j, c)| j % 2 == 0 || c.is_zero())
            }
            _ => true,
        }
    }

    fn period_value(&self) -> Option<&Exact> {
        match &self.period {
            Period::Finite(l) => Some(l),
            Period::Infinite => None,
        }
    }

    /// The frictionless Problem 1 at half-length `a` (paper convention; frictionless, the two
    /// conventions coincide), in `period`.
    pub fn sliding(&self, a: &Exact, period: Period) -> Result<SlidingProblem, String> {
        let material =
            Material::from_contact_modulus(self.nu.clone(), self.e_star.clone()).map_err(|e| e.to_string())?;
        SlidingProblem::builder()
            .material(material)
            .period(period)
            .shape(self.shape.clone())
            .half_length(a.clone())
            .build()
            .map_err(|e| e.to_string())
    }

    /// Problem 2 at nu = 1/2 (eps = 0) at half-width `a`.
    pub fn adhesion(&self, a: &Exact) -> Result<AdhesionProblem, String> {
        let half = Exact::new(1.into(), 2.into());
        let material = Material::from_contact_modulus(half, self.e_star.clone()).map_err(|e| e.to_string())?;
        AdhesionProblem::new(material, self.period.clone(), self.shape.clone(), AdhesionSize::HalfWidth(a.clone()))
            .map_err(|e| e.to_string())
    }

    /// Largest |g'| on the centred contact [-a, a] (f64, from the exact profile; infinite where
    /// a circle's contact reaches |x| = R).
    pub fn max_slope(&self, a: f64) -> f64 {
        let slope = |x: f64| match &self.shape {
            PunchShape::Parabolic { k } => 2.0 * to_f64(k).unwrap_or(f64::NAN) * x,
            PunchShape::Polynomial { coefficients } => coefficients
                .iter()
                .enumerate()
                .skip(1)
                .rev()
                .fold(0.0, |acc, (j, c)| acc * x + j as f64 * to_f64(c).unwrap_or(f64::NAN)),
            PunchShape::Circular { radius } => {
                let r = to_f64(radius).unwrap_or(f64::NAN);
                if x.abs() >= r {
                    f64::INFINITY
                } else {
                    x / ((r - x) * (r + x)).sqrt()
                }
            }
            PunchShape::Sinusoidal { amplitude } => {
                let l = self.period_value().and_then(to_f64).unwrap_or(f64::NAN);
                2.0 * PI * to_f64(amplitude).unwrap_or(f64::NAN) / l * (2.0 * PI * x / l).sin()
            }
        };
        slope(a).abs().max(slope(-a).abs())
    }

    /// The largest half-width with [`ShapeCase::max_slope`] <= [`MAX_CONTACT_SLOPE`] and inside
    /// the cell (bisection in f64, to 1e-12 L).
    pub fn slope_edge(&self, big_l: f64) -> f64 {
        let ok = |a: f64| self.max_slope(a) <= MAX_CONTACT_SLOPE;
        let (mut lo, mut hi) = (0.0, 0.5 * big_l);
        if ok(hi) {
            return hi;
        }
        while hi - lo > 1e-12 * big_l {
            let mid = 0.5 * (lo + hi);
            if ok(mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        lo
    }
}

/// The cases of `scenes` (module doc), in scene order.
pub fn cases(scenes: &[(String, Scene)]) -> Vec<ShapeCase> {
    let mut out: Vec<ShapeCase> = Vec::new();
    for (name, scene) in scenes {
        let (shape, period, material) = match &scene.problem {
            SceneProblem::Sliding(p) => (p.shape(), p.period(), p.material()),
            SceneProblem::Adhesion(p) => (p.shape(), p.period(), p.material()),
            // The parabola only: not a new profile.
            SceneProblem::LoadingLaw(_) => continue,
        };
        if !matches!(shape, PunchShape::Polynomial { .. } | PunchShape::Circular { .. })
            || !matches!(period, Period::Finite(_))
        {
            continue;
        }
        let e_star = material.contact_modulus();
        match out.iter_mut().find(|c| &c.shape == shape && &c.period == period && &c.e_star == e_star) {
            Some(c) => c.scenes.push(name.clone()),
            None => out.push(ShapeCase {
                scenes: vec![name.clone()],
                shape: shape.clone(),
                period: period.clone(),
                e_star: e_star.clone(),
                nu: material.poisson_ratio().clone(),
            }),
        }
    }
    out
}

/// One size of a case.
#[derive(Debug, Clone)]
pub struct Row {
    /// The half-width a (exact: the solvers' input).
    pub a: Exact,
    /// lambda = pi a/L.
    pub lambda: f64,
    /// Largest |g'| on [-a, a].
    pub max_slope: f64,
    /// The closed form (`None`: the profile is not even).
    pub closed: Option<Result<LoadEstimate, String>>,
    /// Problem 1, verified MPFR.
    pub mpfr: Result<Outcome, String>,
    /// Problem 1, f64 (not run beyond the slope limit).
    pub f64: Option<Result<Outcome, String>>,
    /// Problem 2 at nu = 1/2, verified MPFR (even profiles; not run beyond the slope limit).
    pub adhesion: Option<Result<Outcome, String>>,
    /// Problem 2 at nu = 1/2 by the f64 method (even profiles, below the slope limit).
    pub adhesion_f64: Option<Result<Outcome, String>>,
}

fn agreement(x: &Float, closed: &LoadEstimate, cap: f64) -> f64 {
    let d = Float::with_val(COMPARE_BITS, x - &closed.value);
    verified_digits_mpfr(&d, &closed.value, cap.min(closed.digits(cap)))
}

fn relative(x: &Float, closed: &LoadEstimate) -> f64 {
    Float::with_val(COMPARE_BITS, Float::with_val(COMPARE_BITS, x - &closed.value) / &closed.value).abs().to_f64()
}

impl Row {
    fn closed_ok(&self) -> Option<&LoadEstimate> {
        self.closed.as_ref().and_then(|c| c.as_ref().ok())
    }
    /// Digits to which the MPFR load agrees with the closed form (capped at the closed form's own
    /// digits and the MPFR run's verified ones).
    pub fn mpfr_agreement(&self) -> Option<f64> {
        let (o, c) = (self.mpfr.as_ref().ok()?, self.closed_ok()?);
        Some(agreement(&o.load, c, o.verified_digits.unwrap_or(0.0).max(0.0) + 2.0))
    }
    /// Digits to which the f64 load agrees with the closed form (capped at 15).
    pub fn f64_agreement(&self) -> Option<f64> {
        let (o, c) = (self.f64.as_ref()?.as_ref().ok()?, self.closed_ok()?);
        Some(agreement(&o.load, c, F64_DIGITS_CAP))
    }
    /// Digits to which Problem 2's f64 method at nu = 1/2 agrees with the closed form (capped at 15).
    pub fn adhesion_f64_agreement(&self) -> Option<f64> {
        let (o, c) = (self.adhesion_f64.as_ref()?.as_ref().ok()?, self.closed_ok()?);
        Some(agreement(&o.load, c, F64_DIGITS_CAP))
    }
    /// Digits to which Problem 2 at nu = 1/2 agrees with the closed form.
    pub fn adhesion_agreement(&self) -> Option<f64> {
        let (o, c) = (self.adhesion.as_ref()?.as_ref().ok()?, self.closed_ok()?);
        Some(agreement(&o.load, c, o.verified_digits.unwrap_or(0.0).max(0.0) + 2.0))
    }
    /// Digits to which f64 agrees with MPFR (profiles without a closed form).
    pub fn f64_vs_mpfr(&self) -> Option<f64> {
        let (o, m) = (self.f64.as_ref()?.as_ref().ok()?, self.mpfr.as_ref().ok()?);
        let d = Float::with_val(COMPARE_BITS, &o.load - &m.load);
        Some(verified_digits_mpfr(&d, &m.load, F64_DIGITS_CAP))
    }
}

/// The grid of half-widths of `case` (exact, 6 decimals of L): the lambdas of `lambdas` below the
/// slope edge, the edge itself (99% of it) when the grid goes beyond it (and it is not within 2%
/// of the grid size below it), and the first grid lambda beyond it (flagged `true`: run by MPFR
/// only, to show the small-slope warning).
pub fn grid(case: &ShapeCase, lambdas: &[f64]) -> Vec<(Exact, bool)> {
    let Some(big_l) = case.period_value().and_then(to_f64) else { return Vec::new() };
    let edge = case.slope_edge(big_l) * PI / big_l;
    let exact = |lam: f64| super::calibration::rational(lam * big_l / PI);
    let mut out: Vec<(Exact, bool)> = lambdas.iter().filter(|&&l| l < edge).map(|&l| (exact(l), false)).collect();
    if let Some(&beyond) = lambdas.iter().find(|&&l| l >= edge) {
        // The edge, unless it is within 2% of the last grid size below it.
        let last = lambdas.iter().copied().filter(|&l| l < edge).fold(0.0, f64::max);
        if 0.99 * edge > 1.02 * last {
            out.push((exact(0.99 * edge), false));
        }
        out.push((exact(beyond), true));
    }
    out
}

/// Runs one size of `case`.
pub fn row(cache: &RunCache, case: &ShapeCase, a: &Exact, beyond: bool) -> Row {
    let prec = COMPARE_BITS;
    let big_l = case.period_value().map(|l| to_float(l, prec));
    let af = to_float(a, prec);
    let lambda = big_l.as_ref().map_or(0.0, |l| (Float::with_val(prec, &af * std::f64::consts::PI) / l).to_f64());
    let closed = case.even().then(|| {
        let slope = EvenSlope::new(&case.shape, case.period_value(), prec).map_err(|e| e.to_string())?;
        frictionless_load_mpfr(&slope, &to_float(&case.e_star, prec), &af, big_l.as_ref(), prec)
            .map_err(|e| e.to_string())
    });
    let sliding = case.sliding(a, case.period.clone());
    let run =
        |cache: &RunCache, k: Knob| sliding.clone().and_then(|p| runner::run(&SceneProblem::Sliding(p), k, cache));
    let mpfr = run(cache, Knob::MpfrVerified(DIGITS));
    let f64 = (!beyond).then(|| run(cache, Knob::F64(None)));
    let adhesion = (case.even() && !beyond).then(|| {
        case.adhesion(a).and_then(|p| runner::run(&SceneProblem::Adhesion(p), Knob::MpfrVerified(DIGITS), cache))
    });
    let adhesion_f64 = (case.even() && !beyond)
        .then(|| case.adhesion(a).and_then(|p| runner::run(&SceneProblem::Adhesion(p), Knob::F64(None), cache)));
    Row { a: a.clone(), lambda, max_slope: case.max_slope(af.to_f64()), closed, mpfr, f64, adhesion, adhesion_f64 }
}

/// The single punch (period "inf") at half-width `a`: the closed form (power law for a
/// polynomial, the single-punch quadrature for the circle), MPFR and f64.
#[derive(Debug, Clone)]
pub struct SinglePunch {
    /// Half-width.
    pub a: Exact,
    /// Which closed form.
    pub law: &'static str,
    /// Its value (P2).
    pub closed: Result<LoadEstimate, String>,
    /// Problem 1, verified MPFR, period "inf".
    pub mpfr: Result<Outcome, String>,
    /// Problem 1, f64, period "inf".
    pub f64: Result<Outcome, String>,
}

impl SinglePunch {
    /// Digits of agreement of MPFR with the law.
    pub fn mpfr_agreement(&self) -> Option<f64> {
        let (o, c) = (self.mpfr.as_ref().ok()?, self.closed.as_ref().ok()?);
        Some(agreement(&o.load, c, o.verified_digits.unwrap_or(0.0).max(0.0) + 2.0))
    }
    /// Digits of agreement of f64 with the law.
    pub fn f64_agreement(&self) -> Option<f64> {
        let (o, c) = (self.f64.as_ref().ok()?, self.closed.as_ref().ok()?);
        Some(agreement(&o.load, c, F64_DIGITS_CAP))
    }
}

/// The single punch of an even `case` at half-width `a`.
pub fn single_punch(cache: &RunCache, case: &ShapeCase, a: &Exact) -> SinglePunch {
    let prec = COMPARE_BITS;
    let (af, e) = (to_float(a, prec), to_float(&case.e_star, prec));
    let (law, closed) = match &case.shape {
        PunchShape::Polynomial { coefficients } => (
            "power law P2 = sum_n n pi E* c_2n a^(2n) (2n-1)!!/(2n)!!",
            Ok(LoadEstimate {
                value: single_punch_power_law_mpfr(coefficients, &e, &af, prec),
                abs_err: Float::with_val(prec, 0),
                points: 0,
            }),
        ),
        _ => (
            "closed form, single-punch quadrature",
            EvenSlope::new(&case.shape, None, prec)
                .and_then(|s| frictionless_load_mpfr(&s, &e, &af, None, prec))
                .map_err(|e| e.to_string()),
        ),
    };
    let p = case.sliding(a, Period::Infinite);
    let run = |k: Knob| p.clone().and_then(|p| runner::run(&SceneProblem::Sliding(p), k, cache));
    let mpfr = run(Knob::MpfrVerified(DIGITS));
    let f64 = run(Knob::F64(None));
    SinglePunch { a: a.clone(), law, closed, mpfr, f64 }
}

fn describe(case: &ShapeCase) -> String {
    let pars: Vec<String> = case.shape.parameters().into_iter().map(|(k, v)| format!("{k} = {v}")).collect();
    let l = case.period_value().map_or("inf".to_string(), periodic_contact::model::readable);
    format!(
        "{} {}, L = {l}, E* = {}",
        case.shape.name(),
        pars.join(", "),
        periodic_contact::model::readable(&case.e_star)
    )
}

fn p2_text(o: &Result<Outcome, String>, digits: f64) -> String {
    match o {
        Ok(o) => print_mpfr(&o.load, &o.load, digits, PRINTED),
        Err(_) => "refused".into(),
    }
}

fn rel_text(o: Option<&Result<Outcome, String>>, closed: Option<&LoadEstimate>) -> String {
    match (o, closed) {
        (Some(Ok(o)), Some(c)) => format!("{:.1e}", relative(&o.load, c)),
        (Some(Err(_)), _) => "refused".into(),
        _ => "-".into(),
    }
}

/// Builds the section; empty (no text) when no scene has a polynomial or circular punch.
pub fn section(ctx: &Ctx, scenes: &[(String, Scene)]) -> Section {
    let mut s = Section::default();
    let cases = cases(scenes);
    if cases.is_empty() {
        return s;
    }
    let lambdas: Vec<f64> = if ctx.profile == Profile::Full { LAMBDAS.to_vec() } else { vec![0.5, 1.1] };
    let _ = writeln!(
        s.markdown,
        "## 8. Punch shapes: polynomial and circular profiles against the closed form\n\n\
         docs/theory.md section 9. Without friction an even profile g carries, at half-width a, \
         P2 = (E*/2) int_{{-a}}^{{a}} g'(x) sin(pi x/L) dx / sqrt(sin^2(pi a/L) - sin^2(pi x/L)); this closed form \
         is computed here independently of the solvers (`src/verification/closed_form_load.rs`: g' from the \
         exact profile, substitution sin(pi x/L) = sin(lambda) sin(phi), trapezoid sums doubled until two agree \
         to {COMPARE_BITS} bits; its digits are those of that agreement). For each profile of the scenes \
         (friction, wear and nu dropped), on lambda = pi a/L in {lambdas:?} up to the small-slope limit \
         |g'| <= {MAX_CONTACT_SLOPE} ([1.9]: the theory assumes |g'| << 1): Problem 1 without friction at the \
         given half-length by the verified MPFR method ({DIGITS} digits asked) and by f64, and Problem 2 at \
         nu = 1/2 (eps = 0, where complete adhesion is the frictionless problem) by the verified MPFR method \
         and by f64, each against the closed form: relative difference and the digits they agree to (capped at the closed \
         form's digits and the run's verified digits + 2). The first grid size beyond the small-slope limit is run \
         by MPFR: the solvers answer it with the small slope warning of docs/theory.md section 9 (every shape, \
         both problems), not a refusal. One line per even profile: a single punch (period \"inf\") against the power law \
         P2 = n pi E* A a^(2n) (2n-1)!!/(2n)!! of g = A x^(2n), summed over the even terms (polynomial), or the \
         closed form's single-punch limit (circle). The friction scenes of these profiles, in both conventions, \
         are in section 7.\n"
    );
    let _ = writeln!(s.timings, "### Punch shapes\n\n| profile | seconds |\n|---|---:|");
    for (i, case) in cases.iter().enumerate() {
        let t0 = Instant::now();
        case_section(ctx, &mut s, case, i, &lambdas);
        let _ = writeln!(s.timings, "| {} | {:.2} |", describe(case), t0.elapsed().as_secs_f64());
    }
    s
}

fn case_section(ctx: &Ctx, s: &mut Section, case: &ShapeCase, index: usize, lambdas: &[f64]) {
    let scenes: Vec<String> = case.scenes.iter().map(|n| format!("`{n}`")).collect();
    let big_l = case.period_value().and_then(to_f64).unwrap_or(f64::NAN);
    let edge = case.slope_edge(big_l);
    let limit = if edge >= 0.5 * big_l {
        format!("|g'| <= {MAX_CONTACT_SLOPE} on the whole cell (a < L/2).")
    } else {
        format!(
            "|g'| <= {MAX_CONTACT_SLOPE} up to a/L = {} (lambda = {}).",
            readable_f64(edge / big_l),
            readable_f64(edge * PI / big_l)
        )
    };
    let _ = writeln!(s.markdown, "### {} (scenes {})\n\nSlope limit: {limit}\n", describe(case), scenes.join(", "));
    let mut rows = Vec::new();
    for (a, beyond) in grid(case, lambdas) {
        ctx.step(format!("punch shapes: {}, a = {}", case.shape.name(), periodic_contact::model::readable(&a)));
        rows.push(row(&ctx.cache, case, &a, beyond));
    }
    let even = case.even();
    if even {
        let _ = writeln!(
            s.markdown,
            "| a/L | lambda | max g' | closed-form P2 (digits) | MPFR P2 | MPFR verified | MPFR rel. diff | \
             MPFR agrees | f64 rel. diff | f64 agrees | Problem 2 (nu = 1/2) rel. diff | agrees | \
             Problem 2 f64 rel. diff | agrees |\n\
             |---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
        );
    } else {
        let _ = writeln!(
            s.markdown,
            "No closed form: the profile has odd terms (its contact is off centre even without friction; docs/theory.md \
             section 9's closed form is for even g). MPFR against f64.\n\n\
             | a/L | lambda | MPFR P2 | MPFR c/l | MPFR verified | f64 P2 | f64 agrees with MPFR |\n\
             |---:|---:|---:|---:|---:|---:|---:|"
        );
    }
    let mut refusals = Vec::new();
    for r in &rows {
        let d = r.mpfr.as_ref().ok().and_then(|o| o.verified_digits).unwrap_or(0.0);
        let a_over_l = readable_f64(to_f64(&r.a).unwrap_or(f64::NAN) / big_l);
        if even {
            let closed = r.closed_ok();
            let closed_text = match closed {
                Some(c) => {
                    let cd = c.digits(periodic_contact::numerics::accuracy::digits_cap_for_bits(COMPARE_BITS));
                    format!("{} ({:.0})", fmt_mpfr(&c.value, PRINTED as usize), cd)
                }
                None => "-".into(),
            };
            let _ = writeln!(
                s.markdown,
                "| {a_over_l} | {:.4} | {:.4} | {closed_text} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
                r.lambda,
                r.max_slope,
                p2_text(&r.mpfr, d),
                if r.mpfr.is_ok() { fmt_digits(Some(d)) } else { "-".into() },
                rel_text(Some(&r.mpfr), closed),
                r.mpfr_agreement().map_or("-".into(), |x| fmt_digits(Some(x))),
                rel_text(r.f64.as_ref(), closed),
                r.f64_agreement().map_or("-".into(), |x| fmt_digits(Some(x))),
                rel_text(r.adhesion.as_ref(), closed),
                r.adhesion_agreement().map_or("-".into(), |x| fmt_digits(Some(x))),
                rel_text(r.adhesion_f64.as_ref(), closed),
                r.adhesion_f64_agreement().map_or("-".into(), |x| fmt_digits(Some(x))),
            );
        } else {
            let col = r.mpfr.as_ref().ok().map(|o| {
                let c = Float::with_val(COMPARE_BITS, &o.centre / &o.size);
                print_mpfr(&c, &Float::with_val(COMPARE_BITS, 1), d, 10)
            });
            let f64_p2 = match &r.f64 {
                Some(Ok(o)) => fmt_mpfr(&o.load, 15),
                Some(Err(_)) => "refused".into(),
                None => "-".into(),
            };
            let _ = writeln!(
                s.markdown,
                "| {a_over_l} | {:.4} | {} | {} | {} | {f64_p2} | {} |",
                r.lambda,
                p2_text(&r.mpfr, d),
                col.unwrap_or_else(|| "-".into()),
                if r.mpfr.is_ok() { fmt_digits(Some(d)) } else { "-".into() },
                r.f64_vs_mpfr().map_or("-".into(), |x| fmt_digits(Some(x))),
            );
        }
        for (what, res) in [
            ("MPFR", Some(&r.mpfr)),
            ("f64", r.f64.as_ref()),
            ("Problem 2 MPFR", r.adhesion.as_ref()),
            ("Problem 2 f64", r.adhesion_f64.as_ref()),
        ] {
            if let Some(Err(e)) = res {
                refusals.push(format!("{what} at a/L = {a_over_l}: {e}"));
            }
        }
        if let Some(Err(e)) = &r.closed {
            refusals.push(format!("closed form at a/L = {a_over_l}: {e}"));
        }
    }
    if even {
        // The single punch at the grid's second solved size (or its first).
        let solved: Vec<&Row> = rows.iter().filter(|r| r.mpfr.is_ok()).collect();
        if let Some(a) = solved.get(1).or(solved.first()).map(|r| r.a.clone()) {
            ctx.step(format!("punch shapes: {}, single punch", case.shape.name()));
            let sp = single_punch(&ctx.cache, case, &a);
            let d = sp.mpfr.as_ref().ok().and_then(|o| o.verified_digits).unwrap_or(0.0);
            let closed = sp.closed.as_ref().ok();
            let _ = writeln!(
                s.markdown,
                "| single punch, a = {} | 0 | {:.4} | {} | {} | {} | {} | {} | {} | {} | - | - | - | - |",
                readable_f64(to_f64(&a).unwrap_or(f64::NAN)),
                case.max_slope(to_f64(&a).unwrap_or(f64::NAN)),
                closed.map_or("-".into(), |c| {
                    let digits = if c.abs_err.is_zero() {
                        "exact".to_string()
                    } else {
                        format!(
                            "{:.0}",
                            c.digits(periodic_contact::numerics::accuracy::digits_cap_for_bits(COMPARE_BITS))
                        )
                    };
                    format!("{} ({digits})", fmt_mpfr(&c.value, PRINTED as usize))
                }),
                p2_text(&sp.mpfr, d),
                if sp.mpfr.is_ok() { fmt_digits(Some(d)) } else { "-".into() },
                rel_text(Some(&sp.mpfr), closed),
                sp.mpfr_agreement().map_or("-".into(), |x| fmt_digits(Some(x))),
                rel_text(Some(&sp.f64), closed),
                sp.f64_agreement().map_or("-".into(), |x| fmt_digits(Some(x))),
            );
            let _ = writeln!(s.markdown, "\nSingle punch: {}.", sp.law);
            for (what, res) in [("single punch MPFR", &sp.mpfr), ("single punch f64", &sp.f64)] {
                if let Err(e) = res {
                    refusals.push(format!("{what}: {e}"));
                }
            }
        }
    }
    s.markdown.push('\n');
    if !refusals.is_empty() {
        let _ = writeln!(s.markdown, "Refusals and failures, as stated:\n");
        for r in &refusals {
            let _ = writeln!(s.markdown, "- {r}");
        }
        s.markdown.push('\n');
    }
    chart(s, case, index, &rows, big_l);
}

fn chart(s: &mut Section, case: &ShapeCase, index: usize, rows: &[Row], big_l: f64) {
    let stem = format!("shapes_{index}_{}", case.shape.name());
    // P2 in units of E* L.
    let unit = to_f64(&case.e_star).unwrap_or(f64::NAN) * big_l;
    let pts = |f: &dyn Fn(&Row) -> Option<f64>| -> Vec<(f64, f64)> {
        rows.iter().filter_map(|r| f(r).map(|y| (to_f64(&r.a).unwrap_or(f64::NAN) / big_l, y))).collect()
    };
    let ok = |o: Option<&Result<Outcome, String>>| o.and_then(|o| o.as_ref().ok()).map(|o| o.load.to_f64() / unit);
    let mut curves = vec![
        Curve {
            name: format!("Problem 1, MPFR verified ({DIGITS} digits)"),
            points: pts(&|r| ok(Some(&r.mpfr))),
            draw: Draw::LineMarkers,
            colour: None,
        },
        Curve {
            name: "Problem 1, f64".into(),
            points: pts(&|r| ok(r.f64.as_ref())),
            draw: Draw::Markers,
            colour: None,
        },
    ];
    if case.even() {
        curves.push(Curve {
            name: "Problem 2, nu = 1/2, MPFR verified".into(),
            points: pts(&|r| ok(r.adhesion.as_ref())),
            draw: Draw::Markers,
            colour: None,
        });
        // The closed form on a fine grid up to the largest admissible size (64 bits suffice for a
        // chart).
        let top = rows.iter().filter(|r| r.mpfr.is_ok()).filter_map(|r| to_f64(&r.a)).fold(0.0f64, f64::max);
        let prec = 64;
        if let Ok(slope) = EvenSlope::new(&case.shape, case.period_value(), prec) {
            let e = to_float(&case.e_star, prec);
            let l = Float::with_val(prec, big_l);
            let n = 40;
            let line: Vec<(f64, f64)> = (1..=n)
                .filter_map(|i| {
                    let a = top * i as f64 / n as f64;
                    frictionless_load_mpfr(&slope, &e, &Float::with_val(prec, a), Some(&l), prec)
                        .ok()
                        .map(|v| (a / big_l, v.value.to_f64() / unit))
                })
                .collect();
            curves.push(Curve {
                name: "closed form (docs/theory.md section 9)".into(),
                points: line,
                draw: Draw::Dashed,
                colour: None,
            });
        }
    }
    let _ = writeln!(s.markdown, "![{}: load-size curve]({stem}.svg) (data: `{stem}.csv`)\n", describe(case));
    s.charts.push(Chart {
        stem,
        title: format!("Load-size curve, {}", describe(case)),
        x_label: "contact half-width a/L [-]".into(),
        y_label: "load per punch P2/(E* L) [-]".into(),
        x_log: false,
        y_log: false,
        curves,
        legend: Legend::UpperLeft,
    });
}
