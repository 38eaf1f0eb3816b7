//! Problem 2 with finite friction (`[adhesion] friction = "mu"`, docs/theory.md section 17) as an
//! [`AdhesionAnswer`]: the single punch (`period = "inf"`), parabola g = k x^2, normal loading,
//! by the f64 unit-increment method of [`crate::adhesion::friction::single_punch`] on n = 40 and
//! n = 80 stick elements. The self-similar solution gives gamma = c/a and C_P = P/(E* k a^2)
//! (constant during loading, Spence 1975), so
//!     given a:  c = gamma a,  P2 = C_P E* k a^2;
//!     given P2: a = (P2/(C_P E* k))^(1/2),  c = gamma a,
//! and the slip zones are c < |x| < a. The digits are estimated from the two meshes
//! (|gamma(40) - gamma(80)|, |C_P(40) - C_P(80)|, propagated through the formulas above), times
//! [`ESTIMATE_SAFETY`]; `tests/all/friction_scene.rs` checks in five cases that the claimed error
//! covers twice the difference from n = 160 (the error of n = 80 for an order >= 1).
//!
//! The fields q1, q2, psi at the scene's points are superposed from the unit increments
//! ([`crate::adhesion::friction::fields`]), their digits from the two meshes as above; `checks`
//! holds the inequalities of the state method at the answer's stick ratio (|q1|/(mu q2) on the stick
//! zone, min q2/max q2, the outward slip rate) and the two methods' differences in c/a and C_P,
//! each with its error and what it means (docs/theory.md section 17.5).
//!
//! `--method mpfr` ([`mpfr_answer`], single punch): gamma and C_P by the spectral method with
//! verified digits ([`crate::adhesion::friction::spectral_punch::verified`], docs/theory.md section
//! 17.7), at most [`MPFR_MAX_DIGITS`] digits (its cost: 35 s at 14 digits from the release CLI at
//! load 3-6, 28 s at 16 in the test `verified_digits_at_nu0_mu_half` at load 2-3); the digits of a,
//! P2 and c propagated through the same formulas; its `checks` compare it
//! with the f64 increment method (independent discretisation). With points, q1, q2 and psi
//! are superposed from the two runs' spectral increments
//! ([`crate::adhesion::friction::spectral_punch_fields`]), their verified digits where the runs
//! agree (on the scales E* k a and k a), and the three inequality checks are the finer run's with
//! twice the runs' difference as error (same keys as the f64 answer's).
//!
//! Refused with an input error: a method other than f64 and mpfr ([`refuse_method`]), more digits than the mpfr method reaches, and a punch other than the
//! parabola ([`solvable_parabola`]).

use super::render::{AdhesionAnswer, DigitsKind, Measured, Provenance};
use super::render::{FieldRow, FrictionCheck};
use crate::adhesion::friction::fields::PointFields;
use crate::adhesion::friction::fields::{fields, Checks, FieldsF64};
use crate::adhesion::friction::single_punch::{self, Method, SinglePunchF64};
use crate::adhesion::friction::{spectral_punch, spectral_punch_fields};
use crate::error::Error;
use crate::model::{AdhesionProblem, AdhesionSize, Exact, OnPunchRow, PunchShape};
use crate::numerics::exact::to_f64;

/// Stick elements of the coarser mesh (the finer has twice as many).
pub const STICK_ELEMENTS: usize = 40;

/// Factor on the difference of the two meshes that makes the error estimate: where the answer is
/// known (the uncoupled problem, docs/theory.md section 17.4) the true error of n = 80 is
/// 0.07-0.69 of that difference; the factor 2 keeps a margin where the order is lower.
pub const ESTIMATE_SAFETY: f64 = 2.0;

/// Factor on the two meshes' difference of a field: the fields converge irregularly where the mesh
/// is coarse (q1 at x/a = 0.2, nu = 0, mu = 5/3: 0.30820, 0.30802, 0.30829, 0.30821 on n = 40, 80,
/// 160, 320 stick elements), so the difference of n = 40 and 80 can undershoot that of 80 and 160
/// (by 1.5 there); `tests/all/friction_scene.rs` asks the claim to cover twice the latter.
pub const FIELD_SAFETY: f64 = 8.0;

/// The model the answer solves, printed as its `friction_note`.
pub const FRICTION_NOTE: &str = "finite friction (docs/theory.md section 17): Coulomb slip |q1| = mu q2 in the \
     slip zones c < |x| < a at the ends, stick in the middle |x| < c; under monotone normal loading of the single \
     parabolic punch the solution is self-similar and c/a is constant during loading (D.A. Spence, J. Elasticity 5 \
     (1975) 297-319), here with the shear's effect on the normal displacement kept (the coupled problem). Solved \
     by the f64 unit-increment method on 40 and 80 stick elements; about 4-5 digits";

/// The refusal of a method other than f64 and mpfr for the single punch (the row has its own,
/// `answer_friction_row.rs`).
pub fn refuse_method(method: crate::scene::Method) -> Result<(), Error> {
    use crate::scene::Method as M;
    match method {
        M::F64 | M::Mpfr => Ok(()),
        _ => Err(Error::input(
            "--method",
            method.name(),
            "the single punch with finite friction ([adhesion] friction) is solved by the f64 method (4-5 digits) and \
             the mpfr method (verified digits): --method f64, --method mpfr, or no --method",
        )),
    }
}

/// Most digits the mpfr method is asked for: its two discretisations grow with the digits (n =
/// digits - 2 and n + 6 basis functions per family), and 14 to 16 already take half a minute.
pub const MPFR_MAX_DIGITS: u32 = 16;

/// The model the periodic row's answer solves, printed as its `friction_note`.
pub const FRICTION_NOTE_ROW: &str = "finite friction on the periodic row (docs/theory.md section 17): Coulomb slip \
     |q1| = mu q2 in the slip zones c < |x| < a at the ends of every punch, stick in the middle |x| < c, under \
     monotone normal loading; c/a depends on lambda = pi a/L (not constant during loading as for the single \
     punch). Solved by the spectral method in f64 (section 17.8: the unit increment bounded at the stick edge, the \
     load from the edge-slope Volterra equation on Chebyshev nodes) on two discretisations; P2 and c to about 12 digits up to lambda = 1.2, the fields at the points \
     to 2-4 (each printed with its own estimate)";

/// The model of a friction answer at nu = 1/2, printed as its `friction_note`.
pub const FRICTION_NOTE_INCOMPRESSIBLE: &str = "finite friction at nu = 1/2 (beta = 0; docs/theory.md section 17.3): \
     the shear does not move the surface normally nor the pressure laterally, nothing drives a slip, the whole \
     contact sticks (c = a) and the answer is the frictionless one at any mu, solved by the verified MPFR method \
     (Kuznetsov's load for the periodic row, Hertz's for the single punch)";

/// The parabola's k, after the refusal of a punch other than the parabola (not solved with finite
/// friction).
pub fn solvable_parabola(p: &AdhesionProblem) -> Result<&Exact, Error> {
    match p.shape() {
        PunchShape::Parabolic { k } => Ok(k),
        other => {
            Err(Error::input("shape", other.name(), "only the parabolic punch is solved with finite friction so far"))
        }
    }
}

/// `x` as a finite f64, or the input error naming `what` (the f64 methods' parameters).
pub(crate) fn finite_f64(x: &Exact, what: &str) -> Result<f64, Error> {
    to_f64(x)
        .filter(|v| v.is_finite())
        .ok_or_else(|| Error::input(what, crate::model::readable(x), "representable as f64"))
}

/// Digits of a relative error (the f64 cap for none).
pub(crate) fn digits(rel: f64) -> f64 {
    if rel > 0.0 {
        -rel.log10()
    } else {
        crate::numerics::accuracy::F64_DIGITS_CAP
    }
}

/// The answer of the single parabolic punch (`period = "inf"`; a finite period is the row's,
/// `answer_friction_row.rs`) with friction coefficient `mu_exact` by `method` (f64, or mpfr with
/// `digits_asked`: [`mpfr_answer`]), with the fields at `points` (x/a in [0, 1]).
pub fn friction_answer(
    p: &AdhesionProblem,
    mu_exact: &Exact,
    method: crate::scene::Method,
    digits_asked: u32,
    points: &[Exact],
) -> Result<AdhesionAnswer, Error> {
    refuse_method(method)?;
    let k = solvable_parabola(p)?;
    crate::adhesion::points::check_points(points)?;
    if method == crate::scene::Method::Mpfr {
        return mpfr_answer(p, mu_exact, k, digits_asked, points);
    }
    let f = finite_f64;
    let beta = f(&p.material().beta(), "material.poisson_ratio")?;
    let mu = f(mu_exact, "friction")?;
    let e_star = f(p.material().contact_modulus(), "material.contact_modulus")?;
    let k = f(k, "punch.k")?;
    let xs = points.iter().map(|x| f(x, "points")).collect::<Result<Vec<_>, _>>()?;
    let pair = single_punch::solve_pair(beta, mu, STICK_ELEMENTS, Method::Increment)?;
    let r = single_punch::from_pair(pair);
    let fl = fields(beta, mu, pair, STICK_ELEMENTS, &xs)?;
    let (gamma, cp) = (r.gamma, r.load_coefficient);
    let (dg, dcp) = (ESTIMATE_SAFETY * r.gamma_error, ESTIMATE_SAFETY * r.load_coefficient_error);
    // relative errors of a and P2
    let (a, p2, rel_a, rel_p2) = match p.size() {
        AdhesionSize::HalfWidth(a) => {
            let a = f(a, "half_width")?;
            (a, cp * e_star * k * a * a, 0.0, dcp / cp)
        }
        AdhesionSize::NormalLoad(p2) => {
            let p2 = f(p2, "normal_load")?;
            ((p2 / (cp * e_star * k)).sqrt(), p2, 0.5 * dcp / cp, 0.0)
        }
    };
    let size_digits = digits(rel_a.max(rel_p2));
    // c = gamma a on the scale a: dc/a = dgamma + gamma da/a
    let stick_digits = digits(dg + gamma * rel_a);
    // a field q~(x/a) on its scale (E* k a or k a): the two meshes' difference, plus the relative
    // error of a times the field (the scale and the point x = (x/a) a move with a)
    let largest = |get: fn(&crate::adhesion::friction::fields::PointFields) -> f64| {
        fl.points.iter().map(|q| get(q).abs()).fold(0.0, f64::max)
    };
    let field_digits = |err: f64, big: f64| digits(FIELD_SAFETY * err + rel_a * big);
    let d_q1 = field_digits(fl.errors.q1, largest(|q| q.q1));
    let d_q2 = field_digits(fl.errors.q2, largest(|q| q.q2));
    let d_psi = field_digits(fl.errors.psi, largest(|q| q.psi));
    let (stress, psi_scale) = (e_star * k * a, k * a);
    let field = |name: &str, get: fn(&crate::adhesion::friction::fields::PointFields) -> f64, scale: f64, d: f64| {
        (name.to_string(), field_column(&fl.points, points, get, scale, d))
    };
    let state_method = single_punch::solve(beta, mu, STICK_ELEMENTS, Method::State);
    Ok(AdhesionAnswer {
        provenance: Provenance {
            method: "f64",
            bits: Some(53),
            nodes: Some(2 * STICK_ELEMENTS),
            order: None,
            convention: None,
        },
        kind: DigitsKind::Estimated,
        lambda: None,
        p2: Measured::f64(p2, p2, size_digits),
        half_width: Measured::f64(a, a, size_digits),
        stick: Some(super::render::StickSlip {
            friction: exact_series::q_text(mu_exact),
            stick_half_width: Measured::f64(gamma * a, a, stick_digits),
            note: FRICTION_NOTE,
            checks: checks(&fl, &r, state_method),
        }),
        accuracy: vec![
            ("size".into(), size_digits),
            ("stick".into(), stick_digits),
            ("psi".into(), d_psi),
            ("q1".into(), d_q1),
            ("q2".into(), d_q2),
        ],
        fields: vec![
            field("psi", |q| q.psi, psi_scale, d_psi),
            field("q1", |q| q.q1, stress, d_q1),
            field("q2", |q| q.q2, stress, d_q2),
        ],
        tension_zones: None,
        warnings: Vec::new(),
    })
}

/// The three inequality checks (stick ratio, pressure minimum, outward slip) with what each
/// `means`, errors times [`ESTIMATE_SAFETY`]: the single punch's and the row's keys.
pub(crate) fn inequality_checks(c: &Checks, means: [String; 3]) -> Vec<FrictionCheck> {
    let names = ["stick_friction_ratio_max", "pressure_min_over_max", "outward_slip_rate_max"];
    let checks = [c.stick_ratio, c.pressure_min, c.outward_slip];
    names
        .into_iter()
        .zip(checks)
        .zip(means)
        .map(|((name, k), means)| FrictionCheck { name, value: Some(k.value), error: ESTIMATE_SAFETY * k.error, means })
        .collect()
}

/// The `checks` of a single-punch answer (module doc), errors times [`ESTIMATE_SAFETY`].
fn checks(
    fl: &FieldsF64,
    inc: &SinglePunchF64,
    state: Result<SinglePunchF64, crate::adhesion::AdhesionError>,
) -> Vec<FrictionCheck> {
    let c = &fl.checks;
    let mesh = "the state method (n = 80 stick elements) at the answer's c/a; error: twice its difference from n = 40";
    let mut out = inequality_checks(
        c,
        [
            format!(
                "max over the stick zone |x| < c of |q1|/(mu q2), the element at the stick edge left out: \
                 Coulomb's inequality holds where it is <= 1 (it tends to 1 at the stick edge); {mesh}"
            ),
            format!("min q2 / max q2 over the contact: >= 0 is no tension; {mesh}"),
            format!(
                "max over the slip zones c < x < a of the slip rate du/da (outward positive) over its largest \
                 magnitude: <= 0 is inward slip against q1 = mu q2 sign(x) everywhere, no slip reversal; {mesh}"
            ),
        ],
    );
    let between = "between the increment method (the answer) and the independent state method, each on n = 40 and 80; \
                   error: twice the sum of their two-mesh differences; agreement is a value below its error";
    match state {
        Ok(st) => {
            out.push(FrictionCheck {
                name: "methods_difference_stick_ratio",
                value: Some((inc.gamma - st.gamma).abs()),
                error: ESTIMATE_SAFETY * (inc.gamma_error + st.gamma_error),
                means: format!("|difference| of c/a {between}"),
            });
            out.push(FrictionCheck {
                name: "methods_difference_load_coefficient",
                value: Some((inc.load_coefficient - st.load_coefficient).abs()),
                error: ESTIMATE_SAFETY * (inc.load_coefficient_error + st.load_coefficient_error),
                means: format!("|difference| of P2/(E* k a^2) {between}"),
            });
        }
        Err(e) => out.push(FrictionCheck {
            name: "methods_difference_stick_ratio",
            value: None,
            error: 0.0,
            means: format!(
                "not computed: the state method (docs/theory.md section 17.4) does not resolve this case ({e})"
            ),
        }),
    }
    out
}

/// The answer by the spectral method in MPFR: gamma and C_P with verified digits, a, P2 and c by
/// the formulas of the module doc at the same precision.
pub fn mpfr_answer(
    p: &AdhesionProblem,
    mu_exact: &Exact,
    k: &Exact,
    digits_asked: u32,
    points: &[Exact],
) -> Result<AdhesionAnswer, Error> {
    use crate::numerics::exact::to_float;
    use rug::Float;
    if digits_asked > MPFR_MAX_DIGITS {
        return Err(Error::input(
            "digits",
            digits_asked.to_string(),
            format!(
                "at most {MPFR_MAX_DIGITS} with finite friction and --method mpfr (the spectral method's two \
                 discretisations grow with the digits: 14 or 16 digits take half a minute)"
            ),
        ));
    }
    let prec = (3.33 * (digits_asked + 14) as f64).ceil() as u32 + 64;
    let v = spectral_punch::verified(&to_float(&p.material().beta(), prec), &to_float(mu_exact, prec), digits_asked)?;
    let (gamma, cp) = (&v.gamma, &v.load_coefficient);
    let ek = to_float(p.material().contact_modulus(), prec) * to_float(k, prec);
    // relative digits of a and P2
    let (a, p2, size_digits) = match p.size() {
        AdhesionSize::HalfWidth(a) => {
            let a = to_float(a, prec);
            let p2 = Float::with_val(prec, cp * &ek) * &a * &a;
            (a, p2, v.load_digits)
        }
        AdhesionSize::NormalLoad(p2) => {
            let p2 = to_float(p2, prec);
            let a = (Float::with_val(prec, &p2 / cp) / &ek).sqrt();
            (a, p2, v.load_digits + std::f64::consts::LOG10_2)
        }
    };
    // c = gamma a on the scale a: dc/a = dgamma + gamma da/a
    let rel_a = match p.size() {
        AdhesionSize::HalfWidth(_) => 0.0,
        AdhesionSize::NormalLoad(_) => 10f64.powf(-size_digits),
    };
    let stick_digits = digits(10f64.powf(-v.gamma_digits) + gamma.to_f64() * rel_a);
    let c = Float::with_val(prec, gamma * &a);
    let mut checks = match (to_f64(&p.material().beta()), to_f64(mu_exact)) {
        (Some(b), Some(m)) if b.is_finite() && m.is_finite() => mpfr_checks(&v, b, m),
        _ => Vec::new(),
    };
    let (mut fields, mut accuracy) = (Vec::new(), vec![("size".into(), size_digits), ("stick".into(), stick_digits)]);
    if let (false, Some(runs)) = (points.is_empty(), &v.runs) {
        let xs: Vec<Float> = points.iter().map(|x| to_float(x, prec)).collect();
        let fl = spectral_punch_fields::verified(runs, &xs, digits_asked);
        let (stress, strain) = (Float::with_val(prec, &ek * &a), Float::with_val(prec, to_float(k, prec) * &a));
        let (rows, field_digits) = mpfr_field_rows(&fl, points, (&stress, &strain), rel_a);
        fields = rows;
        accuracy.extend(field_digits);
        let how = "the spectral method's two runs (the answer's increments); error: twice their difference";
        let inequalities = inequality_checks(&fl.checks, mpfr_inequality_means(how));
        checks.splice(0..0, inequalities);
    }
    Ok(AdhesionAnswer {
        provenance: Provenance { method: "mpfr", bits: Some(v.bits), nodes: None, order: None, convention: None },
        kind: DigitsKind::Verified,
        lambda: None,
        p2: Measured::mpfr(p2.clone(), &p2, size_digits),
        half_width: Measured::mpfr(a.clone(), &a, size_digits),
        stick: Some(super::render::StickSlip {
            friction: exact_series::q_text(mu_exact),
            stick_half_width: Measured::mpfr(c, &a, stick_digits),
            note: FRICTION_NOTE_MPFR,
            checks,
        }),
        accuracy,
        fields,
        tension_zones: None,
        warnings: Vec::new(),
    })
}

/// The fields psi, q1, q2 of two verified MPFR runs at the scene's `points` on their scales
/// (`stress` for q1, q2; `strain` for psi; the runs' values are on the scale 1), each with the
/// runs' agreement as its digits plus `rel_size` (the relative error of the size) times the
/// field's largest value, and those digits per field for `accuracy` (the single punch's and the
/// row's mpfr answers).
#[allow(clippy::type_complexity)]
pub(super) fn mpfr_field_rows(
    fl: &spectral_punch_fields::VerifiedFields,
    points: &[Exact],
    (stress, strain): (&rug::Float, &rug::Float),
    rel_size: f64,
) -> (Vec<(String, Vec<FieldRow>)>, Vec<(String, f64)>) {
    type Get = fn(&PointFields<rug::Float>) -> &rug::Float;
    let all: [(&str, Get, f64, &rug::Float); 3] = [
        ("psi", |q| &q.psi, fl.digits.psi, strain),
        ("q1", |q| &q.q1, fl.digits.q1, stress),
        ("q2", |q| &q.q2, fl.digits.q2, stress),
    ];
    let (mut fields, mut accuracy) = (Vec::new(), Vec::new());
    for (name, get, agree, scale) in all {
        // the runs' agreement on the field's scale, plus the size's relative error times the field
        let big = fl.points.iter().map(|q| get(q).to_f64().abs()).fold(0.0, f64::max);
        let d = digits(10f64.powf(-agree) + rel_size * big);
        let rows = fl
            .points
            .iter()
            .zip(points)
            .map(|(q, x)| FieldRow {
                x_over_a: exact_series::q_text(x),
                value: Measured::mpfr(rug::Float::with_val(scale.prec(), get(q) * scale), scale, d),
            })
            .collect();
        fields.push((name.to_string(), rows));
        accuracy.push((name.to_string(), d));
    }
    (fields, accuracy)
}

/// What the three inequality checks of an mpfr answer mean, computed `how`.
fn mpfr_inequality_means(how: &str) -> [String; 3] {
    [
        format!(
            "max of |q1|/(mu q2) at x/c = 0.1 .. 0.9 and 1 - 10^-k (k = 2 .. 6): Coulomb's inequality holds where it \
             is <= 1 (it tends to 1 at the stick edge); {how}"
        ),
        format!("min q2 / max q2 at x/a = j/16 (j = 0 .. 15) and the points: >= 0 is no tension; {how}"),
        format!(
            "max over the slip zones c < x < a of the slip rate du/da (outward positive) over its largest \
             magnitude: <= 0 is inward slip against q1 = mu q2 sign(x) everywhere, no slip reversal; {how}"
        ),
    ]
}

/// The `checks` of an mpfr answer: its difference from the f64 increment method (an independent
/// discretisation, n = 40 and 80 stick elements) in c/a and C_P, against that method's error.
fn mpfr_checks(v: &spectral_punch::VerifiedPunch, beta: f64, mu: f64) -> Vec<FrictionCheck> {
    let between = "between the spectral method (the answer) and the independent f64 increment method (n = 40 and \
                   80 stick elements); error: that method's estimate (twice its two-mesh difference); agreement is a \
                   value below its error";
    match single_punch::solve(beta, mu, STICK_ELEMENTS, Method::Increment) {
        Ok(inc) => vec![
            FrictionCheck {
                name: "methods_difference_stick_ratio",
                value: Some((inc.gamma - v.gamma.to_f64()).abs()),
                error: ESTIMATE_SAFETY * inc.gamma_error,
                means: format!("|difference| of c/a {between}"),
            },
            FrictionCheck {
                name: "methods_difference_load_coefficient",
                value: Some((inc.load_coefficient - v.load_coefficient.to_f64()).abs()),
                error: ESTIMATE_SAFETY * inc.load_coefficient_error,
                means: format!("|difference| of P2/(E* k a^2) {between}"),
            },
        ],
        Err(e) => vec![FrictionCheck {
            name: "methods_difference_stick_ratio",
            value: None,
            error: 0.0,
            means: format!("not computed: the f64 increment method does not resolve this case ({e})"),
        }],
    }
}

/// [`FRICTION_NOTE`] of the mpfr method.
pub const FRICTION_NOTE_MPFR: &str = "finite friction (docs/theory.md section 17): Coulomb slip |q1| = mu q2 in the \
     slip zones c < |x| < a at the ends, stick in the middle |x| < c; under monotone normal loading of the single \
     parabolic punch the solution is self-similar and c/a is constant during loading (D.A. Spence, J. Elasticity 5 \
     (1975) 297-319), here with the shear's effect on the normal displacement kept (the coupled problem). Solved \
     by the spectral method in MPFR (section 17.7), digits verified by two discretisations at two precisions";

/// One field at the scene's points x/a: `get` of each point's fields times `scale`, `d` digits
/// (the single punch's and the row's answers).
pub(super) fn field_column(
    fields: &[crate::adhesion::friction::fields::PointFields],
    points: &[Exact],
    get: fn(&crate::adhesion::friction::fields::PointFields) -> f64,
    scale: f64,
    d: f64,
) -> Vec<FieldRow> {
    fields
        .iter()
        .zip(points)
        .map(|(q, x)| FieldRow { x_over_a: exact_series::q_text(x), value: Measured::f64(get(q) * scale, scale, d) })
        .collect()
}
