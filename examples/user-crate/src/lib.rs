//! A user's crate on top of `periodic-contact` (issue 16): it keeps its own snapshot of a derived
//! series (`tests/derived_series.rs`) and regenerates coefficient tables
//! (`cargo run --example regenerate -- DIR`).

use periodic_contact::api::{self, ApiError};

/// One coefficient of a derived series: the power and the exact coefficient as text
/// (`-2/25`, `1/3*theta^2 - 1/12`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Coefficient {
    /// The power of the expansion variable.
    pub power: u64,
    /// The exact coefficient.
    pub text: String,
}

/// The exact coefficients of the part `part` (e.g. `l_over_ls`) of the Problem 1 expansions of
/// the parabola at `theta` (exact, e.g. `"1/10"`), through Lambda^`order`.
pub fn sliding_part(part: &str, theta: &str, order: usize) -> Result<Vec<Coefficient>, ApiError> {
    let v = api::derive(&api::SeriesRequest::new("sliding", order).option("theta", theta))?.json();
    let parts = v["parts"].as_array().cloned().unwrap_or_default();
    let found = parts.iter().find(|p| p["object"] == part).cloned().unwrap_or_default();
    Ok(found["coefficients"]
        .as_array()
        .map(|cs| {
            cs.iter()
                .map(|c| Coefficient {
                    power: c["power"].as_u64().unwrap_or_default(),
                    text: c["text"].as_str().unwrap_or_default().to_string(),
                })
                .collect()
        })
        .unwrap_or_default())
}
