//! JSON of the series method of Problem 1 ([`crate::sliding::series`]): the truncated exact
//! series evaluated at a scene's parameters, with estimated (never verified) digits.

use super::format::{digits_in_value, fmt_float};
use super::{provenance, SolveError, SolveRequest};
use crate::error::Error;
use crate::model::SlidingProblem;
use crate::scene::Scene;
use crate::sliding::series::{estimate, solve_series};
use serde_json::{json, Map, Value};

/// The kind-preserving map to the command's error (input -> exit code 2, the rest -> 1).
fn solve_error(e: Error) -> SolveError {
    match e {
        Error::Input(m) => m.into(),
        other => SolveError::Failed(other.to_string()),
    }
}

/// Runs the series method on a sliding scene.
pub fn sliding_series(p: &SlidingProblem, scene: &Scene, req: SolveRequest) -> Result<Value, SolveError> {
    let (n, digits) = (req.series_order, req.digits);
    let s = solve_series(p, &scene.output.points, n, digits).map_err(solve_error)?;
    let acc = &s.accuracy;
    let (g, fd, pd) = (acc.contact, acc.f_def, acc.pressure);
    let show =
        |x: &rug::Float, scale: &rug::Float, d: f64| Value::String(fmt_float(x, digits_in_value(x, scale, d, digits)));
    let mut m = Map::new();
    m.insert("problem".into(), json!("sliding"));
    m.insert("theta".into(), json!(fmt_float(&s.theta, digits as usize)));
    m.insert("kappa".into(), json!(fmt_float(&s.kappa, digits as usize)));
    m.insert("lambda".into(), show(&s.lambda, &s.lambda, g));
    m.insert("l".into(), show(&s.l, &s.l, g));
    m.insert("a".into(), show(&s.a, &s.l, g));
    m.insert("b".into(), show(&s.b, &s.l, g));
    m.insert("c".into(), show(&s.c, &s.l, g));
    m.insert("P1".into(), show(&s.p1, &s.p2, g));
    m.insert("P2".into(), json!(fmt_float(&s.p2, digits as usize)));
    let kl_p2 = rug::Float::with_val(s.prec, &s.l * &s.k) * &s.p2;
    m.insert("F_def".into(), show(&s.f_def, &kl_p2, fd));
    m.insert("wear_per_distance".into(), json!(fmt_float(&s.wear_per_distance, digits as usize)));
    m.insert("wear_rate".into(), s.wear_rate.as_ref().map_or(Value::Null, |w| json!(fmt_float(w, digits as usize))));
    m.insert("Lambda".into(), json!(fmt_float(&s.big_lambda, 10)));
    m.insert("digits_requested".into(), json!(digits.to_string()));
    m.insert("digits_verified".into(), Value::Null);
    m.insert("digits_estimated".into(), json!(format!("{:.1}", acc.headline)));
    let mut a = json!({
        "note": format!(
            "estimated from the terms kept through order {n} (geometric tail of their rate {:.2} per Lambda^2, \
             safety factor {}); not verified",
            acc.rate,
            estimate::SAFETY
        ),
        "a": format!("{g:.1}"), "b": format!("{g:.1}"), "c": format!("{g:.1}"), "F_def": format!("{fd:.1}")
    });
    if let Some(pd) = pd {
        a["p"] = json!(format!("{pd:.1}"));
    }
    m.insert("accuracy".into(), a);
    let pd = pd.unwrap_or(0.0);
    let pressure: Vec<Value> = s
        .pressure
        .iter()
        .map(|pt| {
            json!({
                "xh": fmt_float(&pt.xh, digits as usize),
                "x": fmt_float(&pt.x, digits_in_value(&pt.x, &s.l, g, digits)),
                "p": fmt_float(&pt.p, digits_in_value(&pt.p, &s.max_pressure, pd, digits)),
            })
        })
        .collect();
    m.insert("pressure".into(), Value::Array(pressure));
    let mut prov = provenance("series", Some(s.prec), None);
    prov["order"] = json!(n.to_string());
    m.insert("provenance".into(), prov);
    Ok(Value::Object(m))
}
