//! The periodic row with finite friction (`[adhesion] friction`, a finite period; docs/theory.md
//! sections 17.5 and 17.8) as an [`AdhesionAnswer`]: the parabola g = k x^2, normal loading, both
//! surface conventions, by the spectral method in `f64`: the load P(lambda) of the edge-slope
//! Volterra equation (17.11) ([`crate::adhesion::friction::spectral_row_load::load_rate`], nodes
//! in eta, [`row_load_rate`], P2 = E* k (L/pi)^2 P) and the stick ratio c/a(lambda) of the increment (17.10)
//! ([`crate::adhesion::friction::spectral_row::stick_ratio_f64`]):
//!     given a:  lambda = pi a/L, P2 = P(lambda) E* k (L/pi)^2, c = (c/a)(lambda) a;
//!     given P2: lambda where P(lambda) = P2/(E* k (L/pi)^2) ([`invert`]: the frictionless shape
//!               r (-pi ln cos lambda) with r fitted to the last load, then secant steps), then c/a.
//! P and c/a on two discretisations of their own, [`ANSWER_LOAD`] (load nodes in
//! [`NodeRule::of_convention`], polynomials per family; [`answer_load`]) and [`ANSWER_STICK`]: the
//! answer is the finer's, its error estimate [`ESTIMATE_SAFETY`] times their difference (in P2, a
//! and c, each discretisation at its own lambda under a given load) plus `ANSWER_ROUNDING`.
//! Measured at nu = 0, mu = 1/2, lambda = 1.2 (docs/theory.md section 17.8): 12.5 (`paper`) and
//! 13.0 (`periodic`) digits claimed in P2 and c, true errors 1.7e-16 .. 3.3e-16 in P2 (against the
//! verified MPFR P, `paper`, and a 24-node load, `periodic`) and 4.9e-15 .. 5.7e-15 in c (against
//! the verified MPFR c/a); `tests/friction_scene.rs` checks that the claims hold.
//!
//! The fields q1, q2, psi at the scene's points x/a (scales E* k L/pi and k L/pi in the row's
//! units, printed in the scene's) and the inequality checks are superposed from each
//! discretisation's load and increments ([`crate::adhesion::friction::row_fields`],
//! docs/theory.md (17.12)-(17.14)); a field's error estimate is [`FIELD_SAFETY`] times the two
//! discretisations' largest difference over the points (twice undershot it: q1 at x/a = 0.9,
//! nu = 0, mu = 1/2, lambda = 1.2, `paper`, is 1.9e-6 from 14 nodes against a claim of 1.6e-6; the
//! interpolated increments carry a floor of about 2e-6, docs/theory.md section 17.8), plus the
//! relative error of the size times the field, `ROUNDING` and `INTERPOLATION`. `checks`: the same keys as the single punch's (max |q1|/(mu q2) on
//! the stick zone, min q2/max q2, the outward slip rate over all load nodes), each with
//! [`ESTIMATE_SAFETY`] times its two discretisations' difference, and the difference of c/a from
//! the independent f64 march of [`crate::adhesion::friction::row_f64`] (piecewise constants on a
//! graded mesh, n = 20) against twice that method's own n = 10 / 20 difference.
//!
//! `--method mpfr` ([`row_mpfr_answer`]): P and c/a by the verified MPFR load of
//! [`crate::adhesion::friction::spectral_row_load::verified_mpfr_runs`] (two runs, their agreement
//! printed as verified digits), given `half_width` only (under a given load lambda would need
//! the verified load inverted: several such loads), at most [`MPFR_ROW_MAX_DIGITS`] digits (the
//! cost: about 4 min of CPU at 6 digits, lambda = 1.2; section 17.8). With points the two runs'
//! node increments are full stick-edge roots (the fields are first order in the stick edge), and
//! q1, q2, psi and the three inequality checks are superposed from each run
//! ([`crate::adhesion::friction::row_fields::verified_row_fields`]): the fields' digits are where
//! the runs agree, on the scales E* k L/pi and k L/pi, fewer than the load's (they converge with
//! the load's nodes at the load's rate from a larger error; docs/theory.md section 17.8, "The
//! row's fields in MPFR"), each check's error twice the runs' difference.

use super::answer_friction::FRICTION_NOTE_ROW;
use super::answer_friction::{
    digits, field_column, finite_f64, inequality_checks, mpfr_field_rows, solvable_parabola, ESTIMATE_SAFETY,
    FIELD_SAFETY,
};
use super::render::{AdhesionAnswer, DigitsKind, FieldRow, FrictionCheck, Measured, Provenance, StickSlip};
use crate::adhesion::friction::fields::PointFields;
use crate::adhesion::friction::real::Mp;
use crate::adhesion::friction::row_f64::row_stick_ratio;
use crate::adhesion::friction::row_fields::{row_fields, verified_row_fields, History, RowFieldsF64};
use crate::adhesion::friction::spectral_row::{increment_f64, stick_ratio_f64};
use crate::adhesion::friction::spectral_row_load::{load_rate, loads_below, LoadRate, NodeRule};
use crate::error::Error;
use crate::model::{AdhesionProblem, AdhesionSize, Exact, OnPunchRow};
use std::f64::consts::PI;

/// The largest lambda = pi a/L answered (the load's nodes converge like the distance of full
/// contact's pole at pi/2; at 1.4 the two node counts still agree to 1e-5, section 17.8).
pub const LAMBDA_MAX: f64 = 1.5;

/// The fields' coarser discretisation: (load nodes in eta, polynomials per family of the increment).
pub const COARSE: (usize, usize) = (8, 6);

/// The fields' finer discretisation (their answer; the fields' claims were validated with it).
pub const FINE: (usize, usize) = (10, 8);

/// Relative error added to every field's estimate for the f64 rounding of the least squares of
/// the fields' discretisations [`COARSE`] and [`FINE`] (nodes in eta; section 17.8).
const ROUNDING: f64 = 3e-8;

/// The answer's discretisations of the load P (nodes in [`NodeRule::of_convention`], polynomials
/// per family), coarser then finer, `paper` and `periodic`: at nu = 0, mu = 1/2, lambda = 1.2 the
/// loads at 12, 14, 16, 18, 20 nodes (n = 12) are 3.5e-13, 5.1e-14, 2.0e-15, 0.6e-15, 0.3e-15 from
/// the verified `paper` P, and `periodic` moves by 8.5e-11, 4.2e-12, 6.0e-13, 3.5e-15 from 12 to
/// 20 nodes (24 nodes, n = 14: 2.7e-15 from 20).
pub const ANSWER_LOAD: [[(usize, usize); 2]; 2] = [[(12, 12), (16, 12)], [(18, 12), (20, 12)]];

/// The answer's polynomials per family of c/a, coarser then finer: at lambda = 1.2 n = 12 and 14
/// are 1.6e-13 and 1.5e-14 (`paper`), 1.2e-14 and 1.3e-14 (`periodic`) from the verified c/a.
pub const ANSWER_STICK: (usize, usize) = (12, 14);

/// Relative error added to the answer's P, a and c for the f64 rounding: the load moves by up to
/// 2.2e-15 between n = 12 and 14 at 20 nodes, and `periodic`'s c/a at n = 10 .. 14 stays 1.2e-14
/// .. 1.5e-14 from the verified one while the three agree to 3e-15 (section 17.8).
const ANSWER_ROUNDING: f64 = 1e-13;

/// Relative error added to every field for the increments interpolated between the load's
/// nodes: twice the largest measured density error of the interpolated increment against one
/// solved at its eta (9.0e-5 `periodic`, 5.4e-6 `paper` at nu = 0, mu = 1/2, lambda = 1.2, 10
/// nodes; `row_fields_tests::interpolated_increment_is_the_solved_one`), which the two
/// discretisations' difference does not see (`periodic`, q2 at x/a = 1/2: 9.3e-5 from 14 nodes,
/// eight differences 4.0e-5).
const INTERPOLATION: f64 = 2e-4;

/// Relative step of lambda below which [`invert`] stops.
const LAMBDA_TOL: f64 = 1e-13;

/// The load P(lambda) on the discretisation `(nodes, n)` ([`row_load_rate`]'s nodes).
pub fn row_load(beta: f64, mu: f64, lambda: f64, mesh: (usize, usize), periodic: bool) -> Result<f64, Error> {
    Ok(row_load_rate(beta, mu, lambda, mesh, periodic)?.load)
}

/// The load with its rate and increments ([`LoadRate`]) on the discretisation `(nodes, n)`, nodes
/// in eta in both conventions: the fields' claims (`friction_scene::row_field_claims_hold_against_a_finer_load`)
/// were validated with them, and with `paper`'s eta^2 nodes psi at x/a = 1/2 missed its claim
/// (2.8e-4 against 1.6e-4, nu = 0, mu = 1/2, lambda = 1.2); the load alone converges faster in
/// eta^2 (`spectral_row_load::NodeRule`, used by [`row_loads`] and the verified MPFR load).
pub fn row_load_rate(
    beta: f64,
    mu: f64,
    lambda: f64,
    (nodes, n): (usize, usize),
    periodic: bool,
) -> Result<LoadRate<f64>, Error> {
    // the canonical exponent with kappa = beta mu (docs/theory.md (17.2): tan(pi theta0) = beta mu)
    let theta0 = crate::params::sliding::theta_f64(beta * mu);
    Ok(load_rate(&lambda, theta0, nodes, NodeRule::Eta, |e: &f64| increment_f64(beta, mu, *e, n, periodic))?)
}

/// The load P(lambda) of the answer on the discretisation `(nodes, n)`, nodes in
/// [`NodeRule::of_convention`] (eta^2 for `paper`, whose load converges 10^1.05 per node in it;
/// docs/theory.md section 17.8): the answer's P and, under a given load, its lambda.
pub fn answer_load(beta: f64, mu: f64, lambda: f64, (nodes, n): (usize, usize), periodic: bool) -> Result<f64, Error> {
    let theta0 = crate::params::sliding::theta_f64(beta * mu);
    let rule = NodeRule::of_convention(periodic);
    Ok(load_rate(&lambda, theta0, nodes, rule, |e: &f64| increment_f64(beta, mu, *e, n, periodic))?.load)
}

/// P at each of `lambdas` (in (0, `lambda_max`]) on the discretisation `(nodes, n)` from one
/// collocation on (0, `lambda_max`) ([`crate::adhesion::friction::spectral_row_load::loads_below`]):
/// one load's cost for a whole column of the report's stability map with friction.
pub fn row_loads(
    beta: f64,
    mu: f64,
    lambda_max: f64,
    lambdas: &[f64],
    (nodes, n): (usize, usize),
    periodic: bool,
) -> Result<Vec<f64>, Error> {
    let theta0 = crate::params::sliding::theta_f64(beta * mu);
    let at = |e: &f64| increment_f64(beta, mu, *e, n, periodic);
    Ok(loads_below(&lambda_max, lambdas, theta0, nodes, NodeRule::of_convention(periodic), at)?)
}

/// lambda = pi a/L of the given half width `a` within (0, [`LAMBDA_MAX`]], or the input error
/// naming `half_width`.
fn answered_lambda(lambda: f64, a: &Exact) -> Result<(), Error> {
    if lambda > 0.0 && lambda <= LAMBDA_MAX {
        return Ok(());
    }
    Err(Error::input(
        "half_width",
        crate::model::readable(a),
        format!("0 < lambda = pi a/L <= {LAMBDA_MAX} (the row with friction)"),
    ))
}

/// Kuznetsov's frictionless load -pi ln cos(lambda), the shape [`invert`] starts from.
fn frictionless(lambda: f64) -> f64 {
    -PI * lambda.cos().ln()
}

/// lambda in (0, [`LAMBDA_MAX`]] where `p(lambda) = target`, and the size of the last step (not
/// evaluated). From `start` = (lambda, dP/dlambda) the first step is Newton's with that slope;
/// without it the search starts at r (-pi ln cos lambda) = target, r = 1.2, and until two loads
/// are known the next lambda solves that with r the last load over the frictionless one; then
/// secant steps. `Ok(Err(P))`: the load P at [`LAMBDA_MAX`] is below the target.
pub fn invert(
    p: impl Fn(f64) -> Result<f64, Error>,
    target: f64,
    start: Option<(f64, f64)>,
) -> Result<Result<(f64, f64), f64>, Error> {
    let shape = |r: f64| (-target / (PI * r)).exp().acos().min(LAMBDA_MAX);
    let mut seen: Vec<(f64, f64)> = Vec::new();
    let mut lambda = start.map_or(shape(1.2), |s| s.0);
    for _ in 0..30 {
        let load = p(lambda)?;
        if lambda >= LAMBDA_MAX && load < target {
            return Ok(Err(load));
        }
        seen.push((lambda, load));
        let next = match seen[..] {
            [.., (l0, p0), (l1, p1)] if p1 != p0 => l1 + (target - p1) * (l1 - l0) / (p1 - p0),
            _ => match start {
                Some((_, slope)) => lambda + (target - load) / slope,
                None => shape(load / frictionless(lambda)),
            },
        };
        let next = next.clamp(0.5 * lambda, LAMBDA_MAX);
        let step = (next - lambda).abs();
        lambda = next;
        if step <= LAMBDA_TOL * lambda {
            return Ok(Ok((lambda, step)));
        }
    }
    Err(Error::NoConvergence {
        what: format!(
            "the periodic row with friction: the secant search for lambda under the load {target} (units E* k \
             (L/pi)^2) did not settle in 30 steps"
        ),
    })
}

/// The answer of the periodic row of parabolic punches with period `period` and friction
/// `mu_exact` by `method`: f64 (module doc), or mpfr with `digits_asked` ([`row_mpfr_answer`]),
/// with the fields at `points` (x/a in [0, 1]).
pub fn row_answer(
    p: &AdhesionProblem,
    mu_exact: &Exact,
    period: &Exact,
    (method, digits_asked): (crate::scene::Method, u32),
    points: &[Exact],
) -> Result<AdhesionAnswer, Error> {
    refuse_method(method)?;
    crate::adhesion::points::check_points(points)?;
    if method == crate::scene::Method::Mpfr {
        return row_mpfr_answer(p, mu_exact, period, digits_asked, points);
    }
    let k = solvable_parabola(p)?;
    let f = finite_f64;
    let (beta, mu) = (f(&p.material().beta(), "material.poisson_ratio")?, f(mu_exact, "friction")?);
    let (e_star, k, l) =
        (f(p.material().contact_modulus(), "material.contact_modulus")?, f(k, "punch.k")?, f(period, "period")?);
    let periodic = p.periodic_surface();
    let unit = e_star * k * (l / PI).powi(2);
    let at = |mesh, lambda| row_load(beta, mu, lambda, mesh, periodic);
    let [coarse_mesh, fine_mesh] = ANSWER_LOAD[usize::from(periodic)];
    let answer_at = |mesh, lambda| answer_load(beta, mu, lambda, mesh, periodic);
    let rate = |mesh, lambda| row_load_rate(beta, mu, lambda, mesh, periodic);
    // (lambda, load and its history) of the two discretisations, and the last unevaluated step of lambda
    let (coarse, fine, step) = match p.size() {
        AdhesionSize::HalfWidth(a) => {
            let lambda = PI * f(a, "half_width")? / l;
            answered_lambda(lambda, a)?;
            let loads = (answer_at(coarse_mesh, lambda)?, answer_at(fine_mesh, lambda)?);
            ((lambda, loads.0, rate(COARSE, lambda)?), (lambda, loads.1, rate(FINE, lambda)?), 0.0)
        }
        AdhesionSize::NormalLoad(p2) => {
            let target = f(p2, "normal_load")? / unit;
            let refuse = |top: f64| {
                Error::input(
                    "normal_load",
                    crate::model::readable(p2),
                    format!(
                        "a load up to {} (lambda = pi a/L <= {LAMBDA_MAX}, the row with friction)",
                        crate::numerics::accuracy::readable_f64(top * unit)
                    ),
                )
            };
            // the fields' coarse load first, then each answer's search from the last root with the
            // coarse slope there
            let (l0, _) = invert(|x| at(COARSE, x), target, None)?.map_err(refuse)?;
            let h = 1e-4 * l0;
            let slope = (target - at(COARSE, l0 - h)?) / h;
            let (lc, _) = invert(|x| answer_at(coarse_mesh, x), target, Some((l0, slope)))?.map_err(refuse)?;
            let (lf, step) = invert(|x| answer_at(fine_mesh, x), target, Some((lc, slope)))?.map_err(refuse)?;
            (
                (lc, answer_at(coarse_mesh, lc)?, rate(COARSE, lc)?),
                (lf, answer_at(fine_mesh, lf)?, rate(FINE, lf)?),
                step,
            )
        }
    };
    let ((l1, p1, r1), (l2, p2, r2)) = (coarse, fine);
    let g = |lambda, n| Ok::<f64, Error>(stick_ratio_f64(beta, mu, lambda, n, periodic)?);
    let (g1, g2) = (g(l1, ANSWER_STICK.0)?, g(l2, ANSWER_STICK.1)?);
    let rel_size = ESTIMATE_SAFETY * (((l2 - l1).abs() + step) / l2).max((p2 - p1).abs() / p2) + ANSWER_ROUNDING;
    let size_digits = digits(rel_size);
    let a = l2 * l / PI;
    // c on the scale a: the two discretisations' c = (c/a) lambda L/pi, each at its own lambda
    let stick_digits = digits(ESTIMATE_SAFETY * ((g2 * l2 - g1 * l1).abs() + g2 * step) / l2 + ANSWER_ROUNDING);
    let xs = points.iter().map(|x| f(x, "points")).collect::<Result<Vec<_>, _>>()?;
    let histories =
        (History::new(&r1, l1, (beta, mu), COARSE.1, periodic), History::new(&r2, l2, (beta, mu), FINE.1, periodic));
    let fl = row_fields(&histories.0, &histories.1, &xs);
    let (stress, strain) = (e_star * k * l / PI, k * l / PI);
    // each discretisation's fields at its own lambda: their difference holds a's; the last
    // unevaluated step of lambda and the rounding are added relative to the field
    let (fields, field_digits) =
        field_rows(&fl, points, (stress, strain), ESTIMATE_SAFETY * step / l2 + ROUNDING + INTERPOLATION);
    let mut checks = row_checks(&fl);
    checks.push(march_check(beta, mu, l2, periodic, g2));
    Ok(AdhesionAnswer {
        provenance: Provenance {
            method: "f64",
            bits: Some(53),
            nodes: Some(fine_mesh.0),
            order: None,
            convention: periodic.then_some("periodic"),
        },
        kind: DigitsKind::Estimated,
        lambda: Some(Measured::f64(l2, l2, size_digits)),
        p2: Measured::f64(p2 * unit, p2 * unit, size_digits),
        half_width: Measured::f64(a, a, size_digits),
        stick: Some(StickSlip {
            friction: exact_series::q_text(mu_exact),
            stick_half_width: Measured::f64(g2 * a, a, stick_digits),
            note: FRICTION_NOTE_ROW,
            checks,
        }),
        accuracy: [("size".into(), size_digits), ("stick".into(), stick_digits)]
            .into_iter()
            .chain(field_digits)
            .collect(),
        fields,
        tension_zones: None,
        warnings: Vec::new(),
    })
}

/// The fields psi, q1, q2 at the points on their scales (E* k L/pi, k L/pi) with their digits
/// (module doc), and the digits per field for `accuracy`; nothing without points.
#[allow(clippy::type_complexity)]
fn field_rows(
    fl: &RowFieldsF64,
    points: &[Exact],
    (stress, strain): (f64, f64),
    relative: f64,
) -> (Vec<(String, Vec<FieldRow>)>, Vec<(String, f64)>) {
    if points.is_empty() {
        return (Vec::new(), Vec::new());
    }
    type Get = fn(&PointFields) -> f64;
    let all: [(&str, Get, f64); 3] = [("psi", |q| q.psi, strain), ("q1", |q| q.q1, stress), ("q2", |q| q.q2, stress)];
    let mut rows = Vec::new();
    let mut accuracy = Vec::new();
    for (name, get, scale) in all {
        let big = fl.points.iter().map(|q| get(q).abs()).fold(0.0, f64::max);
        let d = digits(FIELD_SAFETY * get(&fl.errors) + relative * big);
        rows.push((name.to_string(), field_column(&fl.points, points, get, scale, d)));
        accuracy.push((name.to_string(), d));
    }
    (rows, accuracy)
}

/// The inequality checks of the row (module doc), errors times [`ESTIMATE_SAFETY`], keys as the
/// single punch's.
fn row_checks(fl: &RowFieldsF64) -> Vec<FrictionCheck> {
    let how = format!(
        "superposed from the increments of the load on {} and {} nodes (the answer's); error: twice their difference",
        COARSE.0, FINE.0
    );
    inequality_checks(&fl.checks, check_means(&how))
}

/// What the row's three inequality checks mean, computed `how` (module doc).
fn check_means(how: &str) -> [String; 3] {
    [
        format!(
            "max of |q1|/(mu q2) at x/c = 0.1 .. 0.9 and 1 - 10^-k (k = 2 .. 6) at the answer's contact: \
             Coulomb's inequality holds where it is <= 1 (it tends to 1 at the stick edge); {how}"
        ),
        format!("min q2 / max q2 at x/a = j/16 (j = 0 .. 15) and the points: >= 0 is no tension; {how}"),
        format!(
            "max over the load's nodes (the contacts of the loading history) and the slip zones c < x < a of the \
             slip rate du/dP2 (outward positive) over its largest magnitude: <= 0 is inward slip against \
             q1 = mu q2 sign(x) at every stage, no slip reversal; {how}"
        ),
    ]
}

/// The refusal of a method other than f64 and mpfr for the row (module doc).
fn refuse_method(method: crate::scene::Method) -> Result<(), Error> {
    match method {
        crate::scene::Method::F64 | crate::scene::Method::Mpfr => Ok(()),
        other => Err(Error::input(
            "--method",
            other.name(),
            "the periodic row with finite friction ([adhesion] friction) is solved by the spectral method only: \
             --method f64 (the default, 12-13 digits at lambda = 1.2) or --method mpfr (verified digits, given half_width)",
        )),
    }
}

/// The most digits `--method mpfr` answers for the row: the verified load's two runs grow with
/// them (knobs of `spectral_row_load::knobs`; at 6 digits, lambda = 1.2, 218-245 s of CPU, and
/// about 25 times that for 20 digits, docs/theory.md section 17.8).
pub const MPFR_ROW_MAX_DIGITS: u32 = 12;

/// The answer of the row by the verified MPFR load (module doc): lambda = pi a/L from the exact
/// half width, P2 = E* k (L/pi)^2 P and c = (c/a) a with the two runs' agreement as their digits,
/// and with `points` (x/a) the fields and checks of both runs.
pub fn row_mpfr_answer(
    p: &AdhesionProblem,
    mu_exact: &Exact,
    period: &Exact,
    digits_asked: u32,
    points: &[Exact],
) -> Result<AdhesionAnswer, Error> {
    use crate::adhesion::friction::spectral_row_load::{finer_knobs, verified_mpfr_runs};
    use crate::numerics::exact::to_float;
    use rug::Float;
    if digits_asked > MPFR_ROW_MAX_DIGITS {
        return Err(Error::input(
            "digits",
            digits_asked.to_string(),
            format!(
                "at most {MPFR_ROW_MAX_DIGITS} for the periodic row with finite friction and --method mpfr (its \
                 verified load's cost grows with the digits: about 4 min of CPU at 6 digits, lambda = 1.2; \
                 docs/theory.md section 17.8); --method f64 gives 12-13 digits (lambda = 1.2) in seconds"
            ),
        ));
    }
    let k = solvable_parabola(p)?;
    let a = match p.size() {
        AdhesionSize::HalfWidth(a) => a,
        AdhesionSize::NormalLoad(p2) => {
            return Err(Error::input(
                "normal_load",
                crate::model::readable(p2),
                "a given half_width with --method mpfr on the periodic row with friction (under a given load \
                 lambda would need the verified load inverted, several loads of minutes each: not built); \
                 --method f64 takes normal_load",
            ))
        }
    };
    let incompressible = num_traits::Zero::is_zero(&p.material().beta());
    // the inputs at the finer run's bits and a guard of 64
    let prec = finer_knobs(digits_asked, incompressible, p.periodic_surface()).2 + 64;
    let (a_f, l_f) = (to_float(a, prec), to_float(period, prec));
    let pi_over_l = Float::with_val(prec, rug::float::Constant::Pi) / &l_f;
    let lambda = Float::with_val(prec, &pi_over_l * &a_f);
    let lam = lambda.to_f64();
    answered_lambda(lam, a)?;
    let periodic = p.periodic_surface();
    let (beta, mu) = (to_float(&p.material().beta(), prec), to_float(mu_exact, prec));
    // with points the node roots are full (the fields are first order in the stick edge)
    let (v, rates) = verified_mpfr_runs(&beta, &mu, &lambda, periodic, digits_asked, !points.is_empty())?;
    let unit = to_float(p.material().contact_modulus(), prec) * to_float(k, prec)
        / Float::with_val(prec, pi_over_l.square_ref());
    let p2 = Float::with_val(prec, &v.load * &unit);
    let c = Float::with_val(prec, &v.stick_ratio * &a_f);
    let (size_digits, stick_digits) = (v.load_digits, v.stick_digits);
    // a and lambda = pi a/L are exact inputs, rounded once at `prec`
    let exact = crate::numerics::accuracy::digits_cap_for_bits(prec);
    let mut checks = vec![march_check(beta.to_f64(), mu.to_f64(), lam, periodic, v.stick_ratio.to_f64())];
    let mut accuracy = vec![("size".into(), size_digits), ("stick".into(), stick_digits)];
    let (mut fields, mut warnings) = (Vec::new(), Vec::new());
    if !points.is_empty() {
        let histories: Vec<History<Mp>> = rates
            .iter()
            .zip(v.runs)
            .map(|(rate, (_, n, bits))| {
                let at = |x: &Float| Mp(Float::with_val(bits, x));
                // the strain's nodes within 10^-(2 D + 8) of an edge left out (both runs alike: at
                // most about 10^-(D + 4) of psi), above the working precision (about 2.2 D + 13
                // digits at the knobs' bits: nearer, 1 - x loses every digit and psi is NaN)
                History::new(rate, at(&lambda), (at(&beta), at(&mu)), n, periodic)
                    .with_edge_cut(10f64.powi(-(2 * digits_asked as i32 + 8)))
            })
            .collect();
        let xs: Vec<Float> = points.iter().map(|x| to_float(x, prec)).collect();
        let fl = verified_row_fields(&histories[0], &histories[1], &xs);
        // the fields' scales E* k L/pi and k L/pi (the runs' values are on the scale 1)
        let strain = Float::with_val(prec, to_float(k, prec) / &pi_over_l);
        let stress = Float::with_val(prec, &strain * to_float(p.material().contact_modulus(), prec));
        let (rows, field_digits) = mpfr_field_rows(&fl, points, (&stress, &strain), 0.0);
        let least = field_digits.iter().map(|(_, d)| *d).fold(f64::INFINITY, f64::min);
        if least < digits_asked as f64 {
            warnings.push(format!(
                "q1, q2 and psi carry {least:.1} verified digits, fewer than the {digits_asked} asked: superposed from \
                 the node increments interpolated in eta, they converge more slowly than P2 and c in the load's \
                 discretisation (docs/theory.md section 17.8, \"The row's fields in MPFR\")"
            ));
        }
        fields = rows;
        accuracy.extend(field_digits);
        let how = format!(
            "superposed from the increments of the verified load's two runs on {} and {} nodes; error: twice their \
             difference",
            v.runs[0].0, v.runs[1].0
        );
        checks.splice(0..0, inequality_checks(&fl.checks, check_means(&how)));
    }
    Ok(AdhesionAnswer {
        provenance: Provenance {
            method: "mpfr",
            bits: Some(v.runs[1].2),
            nodes: Some(v.runs[1].0),
            order: None,
            convention: periodic.then_some("periodic"),
        },
        kind: DigitsKind::Verified,
        lambda: Some(Measured::mpfr(lambda.clone(), &lambda, exact)),
        p2: Measured::mpfr(p2.clone(), &p2, size_digits),
        half_width: Measured::mpfr(a_f.clone(), &a_f, exact),
        stick: Some(StickSlip {
            friction: exact_series::q_text(mu_exact),
            stick_half_width: Measured::mpfr(c, &a_f, stick_digits),
            note: FRICTION_NOTE_ROW,
            checks,
        }),
        accuracy,
        fields,
        tension_zones: None,
        warnings,
    })
}

/// c/a's difference from the f64 march (n = 20) against twice the march's n = 10 / 20 difference.
fn march_check(beta: f64, mu: f64, lambda: f64, periodic: bool, stick_ratio: f64) -> FrictionCheck {
    let name = "methods_difference_stick_ratio";
    match (row_stick_ratio(beta, mu, lambda, 10, periodic), row_stick_ratio(beta, mu, lambda, 20, periodic)) {
        (Ok(m10), Ok(m20)) => FrictionCheck {
            name,
            value: Some((m20 - stick_ratio).abs()),
            error: ESTIMATE_SAFETY * (m20 - m10).abs(),
            means: "|difference| of c/a between the spectral method (the answer) and the independent f64 march \
                    (piecewise constants on a graded mesh, n = 20 stick elements); error: twice the march's n = 10 / \
                    20 difference; agreement is a value below its error"
                .into(),
        },
        (Err(e), _) | (_, Err(e)) => FrictionCheck {
            name,
            value: None,
            error: 0.0,
            means: format!("not computed: the f64 march does not resolve this case ({e})"),
        },
    }
}
