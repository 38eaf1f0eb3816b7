//! Problem 2 by the `analytic` method ([`crate::adhesion::analytic`]): the member analytic at zero
//! size (C = 0), its load and size only, with the refusals of the cases it does not cover.

use super::render::{AdhesionAnswer, DigitsKind, Measured, Provenance};
use crate::adhesion::analytic::{continue_to, Analytic};
use crate::asymptotics::adhesion_mode::horizon_of;
use crate::error::Error;
use crate::model::OnPunchRow;
use crate::model::{AdhesionProblem, AdhesionSize, Period, PunchShape};
use crate::numerics::exact::to_float;
use rug::float::Constant;
use rug::Float;

/// Why the analytic method does not take this problem, if it does not.
fn refusal(p: &AdhesionProblem) -> Option<Error> {
    let refuse = |param: &str, value: &str, why: &str| Some(Error::input(param, value, why));
    if !matches!(p.shape(), PunchShape::Parabolic { .. }) {
        return refuse(
            "shape",
            p.shape().name(),
            "the analytic method takes the parabolic punch (its series is the parabola's)",
        );
    }
    if !matches!(p.period(), Period::Finite(_)) {
        return refuse(
            "period",
            "none (single punch)",
            "the analytic method takes a finite period (the single punch is self-similar: P' = pi eta/Re M_1 exactly, method mpfr)",
        );
    }
    if p.periodic_surface() {
        return refuse(
            "convention",
            "periodic",
            "the analytic method takes the `paper` convention: in the `periodic` convention the homogeneous mode has the same \
             symbol but is not excited (docs/theory.md section 8, Problem 2), and the default method verifies the digits \
             asked there",
        );
    }
    if let AdhesionSize::NormalLoad(_) = p.size() {
        return refuse(
            "normal_load",
            "given",
            "the analytic method takes a given half_width (a); give [adhesion] half_width",
        );
    }
    None
}

/// The answer of the analytic method at `digits`.
pub fn analytic_answer(p: &AdhesionProblem, digits: u32) -> Result<(AdhesionAnswer, Analytic), Error> {
    if let Some(e) = refusal(p) {
        return Err(e);
    }
    let (AdhesionSize::HalfWidth(a), Period::Finite(l)) = (p.size(), p.period()) else {
        unreachable!("refused above");
    };
    let prec = crate::numerics::precision::bits_for_digits(digits) + 64;
    let pi = Float::with_val(prec, Constant::Pi);
    let (a_f, l_f) = (to_float(a, prec), to_float(l, prec));
    let lambda = Float::with_val(prec, &pi * &a_f) / &l_f;
    let sol = continue_to(p.material(), &lambda, digits)?;
    // P2 = E* k (L/pi)^2 P.
    let e_star = to_float(p.material().contact_modulus(), prec);
    let k = to_float(p.curvature(), prec);
    let scale = Float::with_val(prec, &l_f / &pi).square() * &e_star * &k;
    let p2 = Float::with_val(prec, &scale * &sol.load);
    let d = sol.digits;
    let own = |x: &Float| Measured::mpfr(x.clone(), x, d);
    let lambda_h = horizon_of(p.material(), digits as f64);
    let costs: Vec<String> = sol
        .runs
        .iter()
        .map(|r| format!("eta0 = {}, {} bits, {} nodes, {} series terms", r.eta0, r.prec, r.nodes, r.terms))
        .collect();
    let warnings = vec![
        format!(
            "method analytic: the member of the incremental problem analytic at zero size (C = 0, the paper's series \
             continued: the series in tan eta to eta0, then a Chebyshev collocation of the Volterra equation from there; \
             docs/theory.md section 11); P2 and the size only (no fields, no tension zones); verified by three runs ({}), \
             {:.1} s in all",
            costs.join("; "),
            sol.seconds
        ),
        if lambda.to_f64() > lambda_h {
            format!(
                "ill-conditioned: lambda is beyond lambda_h = {} (the size up to which complete adhesion keeps {digits} \
                 digits): the physical problem does not select this member there, since a perturbation of the punch or \
                 the load at a size eta grows with the homogeneous mode H (docs/theory.md section 11); this solve \
                 amplified its own interpolation error by 10^{:.0} from eta0 to lambda (measured: the runs' difference \
                 over the first run's Chebyshev tail)",
                crate::asymptotics::adhesion_mode::horizon_text(lambda_h),
                sol.amplification_log10
            )
        } else {
            format!(
                "lambda is within lambda_h = {}: the default method verifies the same member to {digits} digits, faster; \
                 this solve amplified its interpolation error by 10^{:.0} from eta0 to lambda (measured)",
                crate::asymptotics::adhesion_mode::horizon_text(lambda_h),
                sol.amplification_log10
            )
        },
    ];
    let answer = AdhesionAnswer {
        provenance: Provenance {
            method: "analytic",
            bits: sol.runs.first().map(|r| r.prec),
            nodes: sol.runs.first().map(|r| r.nodes),
            order: None,
            convention: None,
        },
        kind: DigitsKind::Verified,
        lambda: Some(own(&lambda)),
        p2: own(&p2),
        half_width: own(&a_f),
        accuracy: vec![("size".to_string(), d)],
        fields: Vec::new(),
        tension_zones: None,
        stick: None,
        warnings,
    };
    Ok((answer, sol))
}
