//! The Padé method of Problem 1 ([`crate::sliding::series::pade`]) as a [`super::render::SlidingAnswer`]:
//! the series method's answer with the Padé values and their estimated (never verified) digits,
//! `provenance.method = "pade"`, and a `pade` list naming the approximant [L/M] chosen per
//! quantity, its estimated digits and its poles in w.

use super::answer_series;
use super::render;
use crate::model::Convention;
use crate::sliding::series::pade::PadeSolution;
use serde_json::{json, Map, Value};

/// The JSON object of one Padé solution at `requested` digits, and its answer (for its claim).
pub fn sliding_json(
    s: &PadeSolution,
    requested: u32,
    convention: Convention,
) -> (Map<String, Value>, render::SlidingAnswer) {
    let mut answer = answer_series::sliding_answer(&s.solution, requested, convention);
    answer.provenance.method = "pade";
    let w = if s.w_is_square { "w = Lambda^2" } else { "w = Lambda" };
    answer.note = Some(format!(
        "estimated by the agreement of each quantity's Pade approximant [L/M] in {w} with its neighbours [L-1/M] and \
         [L/M-1] and with a second run at 32 more bits (series through order {}); approximants with a pole within {}% of \
         |w| of the segment [0, w] not matched by a zero are refused; not verified",
        s.solution.order,
        crate::numerics::pade::POLE_MARGIN * 100.0
    ));
    let mut m = render::sliding_json(&answer, requested);
    let chosen: Vec<Value> = s
        .chosen
        .iter()
        .map(|c| {
            json!({
                "quantity": c.quantity,
                "approximant": format!("[{}/{}]", c.l, c.m),
                "digits_estimated": render::digits_text(c.digits),
                "poles": c.poles,
                "map": c.map.unwrap_or("none: Pade in w"),
            })
        })
        .collect();
    m.insert("pade".into(), json!({ "variable": w, "approximants": chosen }));
    (m, answer)
}
