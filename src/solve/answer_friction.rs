//! Problem 2 with finite friction (`[adhesion] friction = "mu"`, docs/theory.md section 17) as an
//! [`AdhesionAnswer`]: the single punch (`period = "inf"`), parabola g = k x^2, normal loading,
//! by the f64 unit-increment method of [`crate::adhesion::friction::single_punch`] on n = 40 and
//! n = 80 stick elements. The self-similar solution gives gamma = c/a and C_P = P/(E* k a^2)
//! (constant during loading, Spence 1975), so
//!     given a:  c = gamma a,  P2 = C_P E* k a^2;
//!     given P2: a = (P2/(C_P E* k))^(1/2),  c = gamma a,
//! and the slip zones are c < |x| < a. The digits are estimated from the two meshes
//! (|gamma(40) - gamma(80)|, |C_P(40) - C_P(80)|, propagated through the formulas above), times
//! [`ESTIMATE_SAFETY`]; `tests/friction_scene.rs` checks in five cases that the claimed error
//! covers twice the difference from n = 160 (the error of n = 80 for an order >= 1).
//!
//! `--method mpfr` ([`mpfr_answer`]): gamma and C_P by the spectral method with verified digits
//! ([`crate::adhesion::friction::spectral_punch::verified`], docs/theory.md section 17.7), the
//! digits of a, P2 and c propagated through the same formulas.
//!
//! Refused with an input error ([`solvable_parabola`]): a method other than f64 and mpfr, a finite
//! period (the periodic row with stick and slip is not solved yet), a punch other than the
//! parabola.

use super::render::{AdhesionAnswer, DigitsKind, Measured, Provenance};
use crate::adhesion::friction::single_punch::{self, Method};
use crate::adhesion::friction::spectral_punch;
use crate::error::Error;
use crate::model::{AdhesionProblem, AdhesionSize, OnPunchRow, Period, PunchShape};
use crate::numerics::exact::to_f64;

/// Stick elements of the coarser mesh (the finer has twice as many).
pub const STICK_ELEMENTS: usize = 40;

/// Factor on the difference of the two meshes that makes the error estimate: where the answer is
/// known (the uncoupled problem, docs/theory.md section 17.4) the true error of n = 80 is
/// 0.07-0.69 of that difference; the factor 2 keeps a margin where the order is lower.
pub const ESTIMATE_SAFETY: f64 = 2.0;

/// The model the answer solves, printed as its `friction_note`.
pub const FRICTION_NOTE: &str = "finite friction (docs/theory.md section 17): Coulomb slip |q1| = mu q2 in the \
     slip zones c < |x| < a at the ends, stick in the middle |x| < c; under monotone normal loading of the single \
     parabolic punch the solution is self-similar and c/a is constant during loading (D.A. Spence, J. Elasticity 5 \
     (1975) 297-319), here with the shear's effect on the normal displacement kept (the coupled problem). Solved \
     by the f64 unit-increment method on 40 and 80 stick elements; about 4-5 digits";

/// The parabola's k, after the refusals of what is not solved with finite friction: `--method`
/// other than f64 and mpfr, a finite period, a punch other than the parabola.
pub fn solvable_parabola(p: &AdhesionProblem, method: crate::scene::Method) -> Result<&crate::model::Exact, Error> {
    if !matches!(method, crate::scene::Method::F64 | crate::scene::Method::Mpfr) {
        return Err(Error::input(
            "--method",
            method.name(),
            "finite friction ([adhesion] friction) is solved by the f64 method (4-5 digits) and the mpfr \
             method (verified digits): --method f64, --method mpfr, or no --method",
        ));
    }
    if let Period::Finite(l) = p.period() {
        return Err(Error::input(
            "period",
            crate::model::readable(l),
            "only the single punch (period = \"inf\") is solved with finite friction so far",
        ));
    }
    match p.shape() {
        PunchShape::Parabolic { k } => Ok(k),
        other => {
            Err(Error::input("shape", other.name(), "only the parabolic punch is solved with finite friction so far"))
        }
    }
}

/// The answer of the single parabolic punch with friction coefficient `mu_exact` by `method`
/// (f64 or mpfr with `digits` asked, see [`solvable_parabola`]).
pub fn friction_answer(
    p: &AdhesionProblem,
    mu_exact: &crate::model::Exact,
    method: crate::scene::Method,
    digits: u32,
) -> Result<AdhesionAnswer, Error> {
    let k = solvable_parabola(p, method)?;
    if method == crate::scene::Method::Mpfr {
        return mpfr_answer(p, mu_exact, k, digits);
    }
    let f = |x: &crate::model::Exact, what: &str| {
        to_f64(x)
            .filter(|v| v.is_finite())
            .ok_or_else(|| Error::input(what, crate::model::readable(x), "representable as f64"))
    };
    let beta = f(&p.material().beta(), "material.poisson_ratio")?;
    let mu = f(mu_exact, "friction")?;
    let e_star = f(p.material().contact_modulus(), "material.contact_modulus")?;
    let k = f(k, "punch.k")?;
    let r = single_punch::solve(beta, mu, STICK_ELEMENTS, Method::Increment)?;
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
    let digits = |rel: f64| if rel > 0.0 { -rel.log10() } else { crate::numerics::accuracy::F64_DIGITS_CAP };
    let size_digits = digits(rel_a.max(rel_p2));
    // c = gamma a on the scale a: dc/a = dgamma + gamma da/a
    let stick_digits = digits(dg + gamma * rel_a);
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
        }),
        accuracy: vec![("size".into(), size_digits), ("stick".into(), stick_digits)],
        fields: Vec::new(),
        tension_zones: None,
        warnings: Vec::new(),
    })
}

/// The answer by the spectral method in MPFR: gamma and C_P with verified digits, a, P2 and c by
/// the formulas of the module doc at the same precision.
pub fn mpfr_answer(
    p: &AdhesionProblem,
    mu_exact: &crate::model::Exact,
    k: &crate::model::Exact,
    digits: u32,
) -> Result<AdhesionAnswer, Error> {
    use crate::numerics::exact::to_float;
    use rug::Float;
    let prec = (3.33 * (digits + 14) as f64).ceil() as u32 + 64;
    let v = spectral_punch::verified(&to_float(&p.material().beta(), prec), &to_float(mu_exact, prec), digits)?;
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
    let stick_digits = -(10f64.powf(-v.gamma_digits) + gamma.to_f64() * rel_a).log10();
    let c = Float::with_val(prec, gamma * &a);
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
        }),
        accuracy: vec![("size".into(), size_digits), ("stick".into(), stick_digits)],
        fields: Vec::new(),
        tension_zones: None,
        warnings: Vec::new(),
    })
}

/// [`FRICTION_NOTE`] of the mpfr method.
pub const FRICTION_NOTE_MPFR: &str = "finite friction (docs/theory.md section 17): Coulomb slip |q1| = mu q2 in the \
     slip zones c < |x| < a at the ends, stick in the middle |x| < c; under monotone normal loading of the single \
     parabolic punch the solution is self-similar and c/a is constant during loading (D.A. Spence, J. Elasticity 5 \
     (1975) 297-319), here with the shear's effect on the normal displacement kept (the coupled problem). Solved \
     by the spectral method in MPFR (section 17.7), digits verified by two discretisations at two precisions";
