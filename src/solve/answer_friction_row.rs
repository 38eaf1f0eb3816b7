//! The periodic row with finite friction (`[adhesion] friction`, a finite period; docs/theory.md
//! section 17.5) as an [`AdhesionAnswer`]: the parabola g = k x^2, normal loading, both surface
//! conventions, by the f64 march of [`crate::adhesion::friction::row_load_f64`] (the load P(lambda),
//! P2 = E* k (L/pi)^2 P) and the stick ratio of [`crate::adhesion::friction::row_f64`] at the
//! answer's lambda = pi a/L:
//!     given a:  lambda = pi a/L, P2 from the march to lambda, c = (c/a) a;
//!     given P2: the march to [`LAMBDA_MAX`], lambda where the march's P (quadratic through three
//!               neighbouring points) equals P2/(E* k (L/pi)^2), then c/a there.
//! Two discretisations, (n, m) = (10, 16) and (20, 32) (stick elements, load intervals), and the
//! stick ratio on n = 10, 20 and 40; the error estimate is [`super::answer_friction::ESTIMATE_SAFETY`]
//! times their difference (at nu = 1/2, where Kuznetsov's load is known, the true error of the
//! finer is 0.5 of the difference, `row_load_f64` tests). About 2-3 digits in P2, 4 in c/a. The
//! fields and the checks of the single punch are not computed for the row.

use super::answer_friction::{digits, refuse_method, solvable_parabola, ESTIMATE_SAFETY, FRICTION_NOTE_ROW};
use super::render::{AdhesionAnswer, DigitsKind, Measured, Provenance, StickSlip};
use crate::adhesion::friction::row_f64::row_stick_ratio;
use crate::adhesion::friction::row_load_f64::{march, RowPoint};
use crate::error::Error;
use crate::model::{AdhesionProblem, AdhesionSize, Exact, OnPunchRow};
use std::f64::consts::PI;

/// The largest lambda the march covers under a given load.
pub const LAMBDA_MAX: f64 = 1.5;

/// The two discretisations (stick elements, load intervals).
const MESHES: [(usize, usize); 2] = [(10, 16), (20, 32)];

/// lambda where the march's load equals `target` (quadratic through three neighbouring points),
/// None above the march's last load.
fn lambda_at(points: &[RowPoint], target: f64) -> Option<f64> {
    let mut pts = vec![RowPoint { lambda: 0.0, stick_ratio: 0.0, load: 0.0 }];
    pts.extend_from_slice(points);
    let i = pts.iter().position(|p| p.load >= target)?;
    let j = i.clamp(1, pts.len() - 2);
    let (p0, p1, p2) = (pts[j - 1], pts[j], pts[j + 1]);
    // the inverse function lambda(P) through the three points (Lagrange)
    let l = |a: RowPoint, b: RowPoint, c: RowPoint| {
        a.lambda * (target - b.load) * (target - c.load) / ((a.load - b.load) * (a.load - c.load))
    };
    Some(l(p0, p1, p2) + l(p1, p0, p2) + l(p2, p0, p1))
}

/// The answer of the periodic row of parabolic punches with period `period` and friction
/// `mu_exact` by `method` (refused unless f64, [`refuse_method`]).
pub fn row_answer(
    p: &AdhesionProblem,
    mu_exact: &Exact,
    period: &Exact,
    method: crate::scene::Method,
) -> Result<AdhesionAnswer, Error> {
    refuse_method(method, false)?;
    let k = solvable_parabola(p)?;
    let f = |x: &Exact, what: &str| {
        crate::numerics::exact::to_f64(x)
            .filter(|v| v.is_finite())
            .ok_or_else(|| Error::input(what, crate::model::readable(x), "representable as f64"))
    };
    let (beta, mu) = (f(&p.material().beta(), "material.poisson_ratio")?, f(mu_exact, "friction")?);
    let (e_star, k, l) =
        (f(p.material().contact_modulus(), "material.contact_modulus")?, f(k, "punch.k")?, f(period, "period")?);
    let periodic = p.periodic_surface();
    let unit = e_star * k * (l / PI).powi(2);
    // (lambda, P) of each discretisation
    let mut found = Vec::new();
    for (n, m) in MESHES {
        let (lambda, load) = match p.size() {
            AdhesionSize::HalfWidth(a) => {
                let lambda = PI * f(a, "half_width")? / l;
                if !(lambda > 0.0 && lambda <= LAMBDA_MAX) {
                    return Err(Error::input(
                        "half_width",
                        crate::model::readable(a),
                        format!("0 < lambda = pi a/L <= {LAMBDA_MAX} (the f64 march of the row with friction)"),
                    ));
                }
                (lambda, march(beta, mu, lambda, n, m, periodic, None)?.last().map_or(0.0, |q| q.load))
            }
            AdhesionSize::NormalLoad(p2) => {
                let target = f(p2, "normal_load")? / unit;
                let pts = march(beta, mu, LAMBDA_MAX, n, m, periodic, None)?;
                let lambda = lambda_at(&pts, target).ok_or_else(|| {
                    Error::input(
                        "normal_load",
                        crate::model::readable(p2),
                        format!(
                            "a load up to {} (lambda = pi a/L <= {LAMBDA_MAX}, the f64 march of the row with friction)",
                            crate::numerics::accuracy::readable_f64(pts.last().map_or(0.0, |q| q.load) * unit)
                        ),
                    )
                })?;
                (lambda, target)
            }
        };
        found.push((lambda, load));
    }
    let [(l1, p1), (l2, p2)] = [found[0], found[1]];
    // c/a on n = 10, 20, 40: the difference of the last two can vanish by chance (paper, nu = 0,
    // mu = 1/2, lambda = 1.2: 3e-7 where n = 80 differs by 2.3e-6), so the first order is assumed
    // from the first two as well
    let g = |n| row_stick_ratio(beta, mu, l2, n, periodic);
    let (g0, g1, g2) = (g(10)?, g(20)?, g(40)?);
    let stick_error = (g2 - g1).abs().max(0.5 * (g1 - g0).abs());
    let rel_size = ESTIMATE_SAFETY * ((l2 - l1).abs() / l2).max((p2 - p1).abs() / p2);
    let size_digits = digits(rel_size);
    let a = l2 * l / PI;
    let rel_a = ESTIMATE_SAFETY * (l2 - l1).abs() / l2;
    let stick_digits = digits(ESTIMATE_SAFETY * stick_error + g2 * rel_a);
    Ok(AdhesionAnswer {
        provenance: Provenance {
            method: "f64",
            bits: Some(53),
            nodes: Some(MESHES[1].1),
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
            checks: Vec::new(),
        }),
        accuracy: vec![("size".into(), size_digits), ("stick".into(), stick_digits)],
        fields: Vec::new(),
        tension_zones: None,
        warnings: vec![
            "the periodic row with friction: q1, q2, psi at the points and the checks are computed for the single \
             punch only (period = \"inf\"); none printed here"
                .into(),
        ],
    })
}
