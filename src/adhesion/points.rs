//! The requested points of a Problem 2 solution: x/a in [0, 1] (the solution is symmetric).

use super::error::AdhesionError;
use crate::model::{readable, Exact};

/// Validates the points (x/a in [0, 1]).
pub(crate) fn check_points(points: &[Exact]) -> Result<(), AdhesionError> {
    for p in points {
        if p < &Exact::from_integer(0.into()) || p > &Exact::from_integer(1.into()) {
            return Err(AdhesionError::InvalidArgument {
                parameter: "points",
                value: readable(p),
                expected: "x/a must lie in [0, 1] (the solution is symmetric: q2, psi even; q1, phi odd)".into(),
            });
        }
    }
    Ok(())
}
