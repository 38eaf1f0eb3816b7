//! JSON of the series method of Problem 1 ([`crate::sliding::series`]): the truncated exact
//! series evaluated at a scene's parameters, with estimated (never verified) digits.

use super::{SolveError, SolveRequest};
use crate::error::Error;
use crate::model::SlidingProblem;
use crate::scene::Scene;
use crate::sliding::series::solve_series;
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
    let s = solve_series(p, &scene.output.points, req.series_order, req.digits).map_err(solve_error)?;
    let mut m = Map::new();
    m.insert("problem".into(), json!("sliding"));
    m.extend(super::render::sliding_json(&super::answer_series::sliding_answer(&s, req.digits), req.digits));
    Ok(Value::Object(m))
}
