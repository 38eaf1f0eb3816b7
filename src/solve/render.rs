//! The one JSON renderer per problem. Every method (MPFR, f64, series) fills the same answer
//! struct of (value, scale, digits) triples, and [`sliding_json`] / [`adhesion_json`] print it under
//! the one accuracy rule of [`crate::numerics::accuracy`]: a value shows only the significant digits
//! its digits of its scale cover (at most the digits requested), and a value below
//! scale x 10^-digits (noise at this accuracy) prints as `0` with its accuracy stated.
//!
//! The scales are fixed per output in one table per problem: [`crate::params::sliding::SlidingScale`]
//! and the Problem 2 scales of `crate::adhesion`.

pub use super::values::DigitsKind;
use super::values::{Quantity, Values};
use crate::numerics::accuracy::readable_f64;
use crate::numerics::accuracy::{
    fmt_f64, fmt_mpfr, held_digits_f64, held_digits_mpfr, print_f64, print_mpfr, F64_PRINT_DIGITS,
};
use crate::sliding::physicality::Assessment;
use rug::Float;
use serde_json::{json, Map, Value};

/// A number of either type.
#[derive(Debug, Clone, PartialEq)]
pub enum Num {
    /// An `f64`.
    F64(f64),
    /// An MPFR float.
    Mpfr(Float),
}

impl Num {
    /// Printed with `sig` significant digits (no accuracy rule: for inputs and derived exact-ish
    /// parameters such as theta, rounded once from exact values).
    pub fn fmt(&self, sig: usize) -> String {
        match self {
            Num::F64(x) => fmt_f64(*x, sig),
            Num::Mpfr(x) => fmt_mpfr(x, sig),
        }
    }
}

/// A value and its scale, of one number type.
#[derive(Debug, Clone, PartialEq)]
enum ValueAndScale {
    F64(f64, f64),
    Mpfr(Float, Float),
}

/// A value known to `digits` digits of its scale (|error| <= 10^-digits |scale|).
#[derive(Debug, Clone, PartialEq)]
pub struct Measured {
    pair: ValueAndScale,
    digits: f64,
}

impl Measured {
    /// An MPFR value and its scale (the table of scales of the problem).
    pub fn mpfr(value: Float, scale: &Float, digits: f64) -> Self {
        Measured { pair: ValueAndScale::Mpfr(value, scale.clone()), digits }
    }

    /// An `f64` value and its scale.
    pub fn f64(value: f64, scale: f64, digits: f64) -> Self {
        Measured { pair: ValueAndScale::F64(value, scale), digits }
    }

    /// -value on the same scale and digits (the left end of a symmetric zone).
    pub fn negated(&self) -> Self {
        let pair = match &self.pair {
            ValueAndScale::F64(v, s) => ValueAndScale::F64(-v, *s),
            ValueAndScale::Mpfr(v, s) => ValueAndScale::Mpfr(Float::with_val(v.prec(), -v), s.clone()),
        };
        Measured { pair, digits: self.digits }
    }

    /// Printed under the accuracy rule, at most `requested` + 1 significant digits (a text of exactly
    /// the requested digits would hold fewer after its rounding; issue 34); an `f64` at most 17.
    pub fn print(&self, requested: u32) -> String {
        let most = requested.saturating_add(1);
        match &self.pair {
            ValueAndScale::F64(v, s) => print_f64(*v, *s, self.digits, most.min(F64_PRINT_DIGITS)),
            ValueAndScale::Mpfr(v, s) => print_mpfr(v, s, self.digits, most),
        }
    }

    /// The typed value of the text [`Measured::print`] gives: its text, value, held digits
    /// ([`Measured::held`]) and scale.
    pub fn quantity(&self, requested: u32, kind: DigitsKind) -> Quantity {
        let (value, scale) = match &self.pair {
            ValueAndScale::F64(v, s) => (*v, *s),
            ValueAndScale::Mpfr(v, s) => (v.to_f64(), s.to_f64()),
        };
        Quantity { text: self.print(requested), value, digits: self.held(requested), kind, scale: scale.abs() }
    }

    /// The digits of its scale that the text [`Measured::print`] gives holds (its own digits
    /// less what the rounding of the text costs: [`held_digits_mpfr`]).
    pub fn held(&self, requested: u32) -> f64 {
        let text = self.print(requested);
        match &self.pair {
            ValueAndScale::F64(v, s) => held_digits_f64(&text, *v, *s, self.digits),
            ValueAndScale::Mpfr(v, s) => held_digits_mpfr(&text, v, s, self.digits),
        }
    }
}

/// The smallest [`Measured::held`] of `values` (infinite for none).
fn held_min<'a>(values: impl IntoIterator<Item = &'a Measured>, requested: u32) -> f64 {
    values.into_iter().map(|m| m.held(requested)).fold(f64::INFINITY, f64::min)
}

/// The accuracy table as claimed for the printed texts: each entry at most what the printed values
/// of its key hold (`printed(key)`), and the headline at most what every other printed value holds
/// (`others`): a printed value holds the digits claimed for it (issue 34).
fn held_accuracy(accuracy: &[(String, f64)], printed: impl Fn(&str) -> f64, others: f64) -> (Vec<(String, f64)>, f64) {
    let table: Vec<(String, f64)> = accuracy.iter().map(|(k, d)| (k.clone(), d.min(printed(k)))).collect();
    let head = table.iter().map(|(_, d)| *d).fold(others, f64::min);
    (table, head)
}

/// Where an answer came from.
#[derive(Debug, Clone, PartialEq)]
pub struct Provenance {
    /// `mpfr`, `f64` or `series`.
    pub method: &'static str,
    /// Working precision in bits.
    pub bits: Option<u32>,
    /// Nodes (quadrature or collocation), or terms.
    pub nodes: Option<usize>,
    /// Order of the truncated series (series method).
    pub order: Option<usize>,
    /// Surface convention of Problem 1 (`paper` or `periodic`, docs/theory.md section 8); for
    /// Problem 2 `periodic` only (absent: `paper`, or the single punch, the same in both).
    pub convention: Option<&'static str>,
}

impl Provenance {
    /// `{"version", "method", "bits", "nodes", ["order"], ["convention"]}` (string values).
    pub fn json(&self) -> Value {
        let mut v = json!({
            "version": env!("CARGO_PKG_VERSION"),
            "method": self.method,
            "bits": self.bits.map(|b| b.to_string()),
            "nodes": self.nodes.map(|n| n.to_string()),
        });
        if let Some(o) = self.order {
            v["order"] = json!(o.to_string());
        }
        if let Some(c) = self.convention {
            v["convention"] = json!(c);
        }
        v
    }
}

/// The pressure at one requested point.
#[derive(Debug, Clone, PartialEq)]
pub struct PressureRow {
    /// xh = (x - c)/l as requested.
    pub xh: Num,
    /// x = c + l xh.
    pub x: Measured,
    /// p(x).
    pub p: Measured,
}

/// One answer of Problem 1, from any method.
#[derive(Debug, Clone, PartialEq)]
pub struct SlidingAnswer {
    /// Where it came from.
    pub provenance: Provenance,
    /// Verified or estimated digits.
    pub kind: DigitsKind,
    /// The digits the number type can show of an input-derived parameter (theta, kappa).
    pub parameter_digits: usize,
    /// theta = arctan(kappa)/pi.
    pub theta: Num,
    /// kappa.
    pub kappa: Num,
    /// lambda = pi l/L (None: single punch).
    pub lambda: Option<Measured>,
    /// l, a, b, c.
    pub l: Measured,
    /// a.
    pub a: Measured,
    /// b.
    pub b: Measured,
    /// c.
    pub c: Measured,
    /// P1.
    pub p1: Measured,
    /// P2.
    pub p2: Measured,
    /// F_def.
    pub f_def: Measured,
    /// cW P2/L (None: single punch).
    pub wear_per_distance: Option<Measured>,
    /// cW V P2/L (None without V or for a single punch).
    pub wear_rate: Option<Measured>,
    /// cW P2 per punch (every method of Problem 1 reports it; `Option` for a caller's own answer).
    pub worn_area_per_distance: Option<Measured>,
    /// Per-quantity digits, in print order.
    pub accuracy: Vec<(String, f64)>,
    /// Extra keys printed after `accuracy` notes (e.g. the series method's `Lambda`), in order.
    pub extra: Vec<(String, Value)>,
    /// An explanatory note in `accuracy` (e.g. how the series estimate was made).
    pub note: Option<String>,
    /// Pressure at the requested points.
    pub pressure: Vec<PressureRow>,
    /// What the shared physicality criterion reported beside the contact
    /// ([`crate::sliding::physicality`]); None where no check was made.
    pub physicality: Option<Assessment>,
}

impl SlidingAnswer {
    /// The headline digits: the minimum over the accuracy table.
    pub fn headline(&self) -> f64 {
        self.accuracy.iter().map(|(_, d)| *d).fold(f64::INFINITY, f64::min)
    }
}

/// Digits as printed in every answer: [`crate::numerics::accuracy::digits_text`] (one decimal,
/// rounded down).
pub use crate::numerics::accuracy::digits_text;

/// `digits_verified` (or `digits_verified: null` and `digits_estimated`): `head`, the minimum of
/// the accuracy table and of what the other printed values hold.
fn headline(m: &mut Map<String, Value>, kind: DigitsKind, head: f64) {
    let head = digits_text(head);
    match kind {
        DigitsKind::Verified => {
            m.insert("digits_verified".into(), json!(head));
        }
        DigitsKind::Estimated => {
            m.insert("digits_verified".into(), Value::Null);
            m.insert("digits_estimated".into(), json!(head));
        }
    }
}

fn opt(m: &Option<Measured>, requested: u32) -> Value {
    m.as_ref().map_or(Value::Null, |x| Value::String(x.print(requested)))
}

/// Every printed value of a Problem 1 answer under the key of the accuracy table that claims its
/// digits ("p" or "p[i]" for the pressure, "x" for its points), or none (then the headline
/// claims them).
fn sliding_keyed(ans: &SlidingAnswer) -> Vec<(String, &Measured)> {
    sliding_scalars(ans)
        .into_iter()
        .map(|(k, m)| (k.to_string(), m))
        .chain(ans.pressure.iter().enumerate().flat_map(|(i, r)| {
            let p_key = if ans.accuracy.iter().any(|(k, _)| k == "p") { "p".to_string() } else { format!("p[{i}]") };
            [("x".to_string(), &r.x), (p_key, &r.p)]
        }))
        .collect()
}

/// The scalars a Problem 1 answer prints, by JSON key (the optional ones where present).
fn sliding_scalars(ans: &SlidingAnswer) -> Vec<(&'static str, &Measured)> {
    [
        ("lambda", ans.lambda.as_ref()),
        ("l", Some(&ans.l)),
        ("a", Some(&ans.a)),
        ("b", Some(&ans.b)),
        ("c", Some(&ans.c)),
        ("P1", Some(&ans.p1)),
        ("P2", Some(&ans.p2)),
        ("F_def", Some(&ans.f_def)),
        ("wear_per_distance", ans.wear_per_distance.as_ref()),
        ("wear_rate", ans.wear_rate.as_ref()),
        ("worn_area_per_distance", ans.worn_area_per_distance.as_ref()),
    ]
    .into_iter()
    .filter_map(|(k, m)| m.map(|m| (k, m)))
    .collect()
}

/// The typed values of one Problem 1 answer ([`sliding_json`]'s numbers): the scalars by key,
/// the pressure's `x` and `p` at `xh`.
pub(crate) fn sliding_values(ans: &SlidingAnswer, requested: u32) -> Values {
    let mut v = Values::default();
    let par = (requested as usize).min(ans.parameter_digits).max(1);
    for (key, m) in sliding_scalars(ans) {
        v.push(key, m.quantity(requested, ans.kind));
    }
    for r in &ans.pressure {
        v.push_point("x", "xh", r.xh.fmt(par), r.x.quantity(requested, ans.kind));
        v.push_point("p", "xh", r.xh.fmt(par), r.p.quantity(requested, ans.kind));
    }
    v
}

/// The JSON object of one Problem 1 answer (string values; `digits_verified` or
/// `digits_estimated` by [`DigitsKind`]).
pub fn sliding_json(ans: &SlidingAnswer, requested: u32) -> Map<String, Value> {
    let mut m = Map::new();
    let par = (requested as usize).min(ans.parameter_digits).max(1);
    m.insert("theta".into(), json!(ans.theta.fmt(par)));
    m.insert("kappa".into(), json!(ans.kappa.fmt(par)));
    m.insert("lambda".into(), opt(&ans.lambda, requested));
    for (key, v) in [("l", &ans.l), ("a", &ans.a), ("b", &ans.b), ("c", &ans.c), ("P1", &ans.p1), ("P2", &ans.p2)] {
        m.insert(key.into(), json!(v.print(requested)));
    }
    m.insert("F_def".into(), json!(ans.f_def.print(requested)));
    m.insert("wear_per_distance".into(), opt(&ans.wear_per_distance, requested));
    m.insert("wear_rate".into(), opt(&ans.wear_rate, requested));
    if let Some(w) = &ans.worn_area_per_distance {
        m.insert("worn_area_per_distance".into(), json!(w.print(requested)));
    }
    for (k, v) in &ans.extra {
        m.insert(k.clone(), v.clone());
    }
    m.insert("digits_requested".into(), json!(requested.to_string()));
    let keyed = sliding_keyed(ans);
    let in_table = |k: &str| ans.accuracy.iter().any(|(t, _)| t == k);
    let printed = |key: &str| held_min(keyed.iter().filter(|(k, _)| k == key).map(|(_, m)| *m), requested);
    let others = held_min(keyed.iter().filter(|(k, _)| !in_table(k)).map(|(_, m)| *m), requested);
    let (accuracy, head) = held_accuracy(&ans.accuracy, printed, others);
    headline(&mut m, ans.kind, head);
    let mut acc = Map::new();
    if let Some(n) = &ans.note {
        acc.insert("note".into(), json!(n));
    }
    for (k, d) in &accuracy {
        acc.insert(k.clone(), json!(digits_text(*d)));
    }
    m.insert("accuracy".into(), Value::Object(acc));
    let pressure: Vec<Value> = ans
        .pressure
        .iter()
        .map(|r| json!({"xh": r.xh.fmt(par), "x": r.x.print(requested), "p": r.p.print(requested)}))
        .collect();
    m.insert("pressure".into(), Value::Array(pressure));
    if let Some(ph) = &ans.physicality {
        m.insert("physicality".into(), physicality_json(ph));
        let warnings: Vec<Value> = ph.warning.iter().map(|w| json!(w)).collect();
        m.insert("warnings".into(), Value::Array(warnings));
    }
    m.insert("provenance".into(), ans.provenance.json());
    m
}

/// The checks of the physicality criterion: the closure defect (value and sign), the most
/// negative gap and where (0 when none), the edge step (when tau0 > 0). These come from the
/// criterion's f64 quadrature of the gap (accurate to about 1e-8 of the largest gap, the
/// criterion's tolerance), so they are printed to 7 significant digits and labelled so.
fn physicality_json(ph: &Assessment) -> Value {
    let mut m = Map::new();
    m.insert("closure_defect".into(), ph.closure_defect.map_or(Value::Null, |d| json!(readable_f64(d))));
    m.insert("min_gap".into(), json!(readable_f64(ph.min_gap)));
    if ph.min_gap < 0.0 {
        m.insert("min_gap_x".into(), json!(readable_f64(ph.min_gap_x)));
    }
    if ph.edge_step != 0.0 {
        m.insert("edge_step".into(), json!(readable_f64(ph.edge_step)));
    }
    m.insert(
        "accuracy".into(),
        json!("checks from an f64 quadrature of the gap: about 8 digits of the largest gap, not verified"),
    );
    Value::Object(m)
}

/// One field of Problem 2 at a point x/a.
#[derive(Debug, Clone, PartialEq)]
pub struct FieldRow {
    /// x/a as requested (exact text).
    pub x_over_a: String,
    /// The value.
    pub value: Measured,
}

/// A tension zone (q2 < 0) of Problem 2, in x/a and in 1 - x/a (the zones crowd towards the
/// edge x/a = 1, where x/a alone rounds to 1).
#[derive(Debug, Clone, PartialEq)]
pub struct ZoneRow {
    /// Start (x/a).
    pub from: Num,
    /// End (x/a).
    pub to: Num,
    /// 1 - x/a at the start, accurate where x/a rounds to 1.
    pub from_one_minus: Num,
    /// 1 - x/a at the end.
    pub to_one_minus: Num,
    /// Whether its ends were refined by bisection.
    pub refined: bool,
}

/// Significant digits of 1 - x/a printed beside a zone.
pub const ZONE_DELTA_DIGITS: usize = 4;

/// The most nines [`zone_end_text`] prints after "0." (a zone nearer the edge than 10^-1000 of a
/// prints its 1 - x/a beside it, as every zone does).
pub const MAX_ZONE_NINES: usize = 1000;

/// x/a = 1 - `delta` printed with the digits that separate it from 1: six significant digits, or
/// as many as show [`ZONE_DELTA_DIGITS`] digits of `delta` (issue 30: 1 - 3.1e-11 printed
/// "1.00000" before). Computed as 1 - delta in MPFR at the precision those digits need, so a
/// delta below the solution's own 2^-prec still prints (x/a itself rounds to 1 there).
pub fn zone_end_text(delta: &Num) -> String {
    let d = match delta {
        Num::F64(x) => Float::with_val(64, *x),
        Num::Mpfr(x) => x.clone(),
    };
    // delta = m 10^-e with m in [1, 10): x/a = 0.99..9 (e - 1 nines) then delta's digits. The
    // logarithm in MPFR: a delta below f64's range (1e-400 from an MPFR solution) made
    // log10(0) = -inf and the count overflow (issue 34, fuzz seed 34 in the debug build); at most
    // MAX_ZONE_NINES nines are printed.
    let e = if d.is_zero() {
        0
    } else {
        let log = Float::with_val(64, d.abs_ref()).log10();
        (-log.to_f64()).floor().clamp(0.0, MAX_ZONE_NINES as f64) as usize + 1
    };
    let sig = 6usize.max(e - 1 + ZONE_DELTA_DIGITS);
    let bits = (sig as f64 * std::f64::consts::LOG2_10).ceil() as u32 + 16;
    fmt_mpfr(&(Float::with_val(bits, 1u32) - Float::with_val(bits, &d)), sig)
}

/// One answer of Problem 2, from any method.
#[derive(Debug, Clone, PartialEq)]
pub struct AdhesionAnswer {
    /// Where it came from.
    pub provenance: Provenance,
    /// Verified or estimated digits.
    pub kind: DigitsKind,
    /// lambda = pi a/L (None: single punch).
    pub lambda: Option<Measured>,
    /// P2.
    pub p2: Measured,
    /// a.
    pub half_width: Measured,
    /// Per-quantity digits (size, psi, phi, q1, q2).
    pub accuracy: Vec<(String, f64)>,
    /// psi, phi, q1, q2 at the requested points.
    pub fields: Vec<(String, Vec<FieldRow>)>,
    /// Tension zones (None where the method does not locate them).
    pub tension_zones: Option<Vec<ZoneRow>>,
    /// Warnings (conditioning, tension).
    pub warnings: Vec<String>,
    /// Stick and slip with finite friction (None: complete adhesion).
    pub stick: Option<StickSlip>,
}

/// The stick zone |x| < c of finite friction (docs/theory.md section 17); the slip zones are
/// c < |x| < a.
#[derive(Debug, Clone, PartialEq)]
pub struct StickSlip {
    /// The friction coefficient mu as the scene gives it (exact text).
    pub friction: String,
    /// c, on the scale a.
    pub stick_half_width: Measured,
    /// What the model is (printed as `friction_note`).
    pub note: &'static str,
    /// The checks of the solution (printed under `checks`).
    pub checks: Vec<FrictionCheck>,
}

/// One check of a finite-friction answer: a number, its error and what it means (docs/theory.md
/// section 17.6); printed as `checks.<name>.value` (a JSON number, or null where the check could
/// not be made), `.error` and `.means`.
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionCheck {
    /// The key under `checks`.
    pub name: &'static str,
    /// The value (None: not computed, `means` says why).
    pub value: Option<f64>,
    /// Its error estimate.
    pub error: f64,
    /// What it measures and what a sound solution gives.
    pub means: String,
}

/// `x` rounded to `sig` significant digits (a check's value and error as JSON numbers).
fn round_sig(x: f64, sig: usize) -> f64 {
    format!("{x:.*e}", sig - 1).parse().unwrap_or(x)
}

impl AdhesionAnswer {
    /// The headline digits: the minimum over the accuracy table.
    pub fn headline(&self) -> f64 {
        self.accuracy.iter().map(|(_, d)| *d).fold(f64::INFINITY, f64::min)
    }
}

/// The typed values of one Problem 2 answer ([`adhesion_json`]'s numbers): `lambda`, `P2`,
/// `half_width` and the fields at `x_over_a`.
pub fn adhesion_values(ans: &AdhesionAnswer, requested: u32) -> Values {
    let mut v = Values::default();
    if let Some(l) = &ans.lambda {
        v.push("lambda", l.quantity(requested, ans.kind));
    }
    v.push("P2", ans.p2.quantity(requested, ans.kind));
    v.push("half_width", ans.half_width.quantity(requested, ans.kind));
    if let Some(st) = &ans.stick {
        v.push("stick_half_width", st.stick_half_width.quantity(requested, ans.kind));
    }
    for (name, rows) in &ans.fields {
        for r in rows {
            v.push_point(name, "x_over_a", r.x_over_a.clone(), r.value.quantity(requested, ans.kind));
        }
    }
    v
}

/// The JSON object of one Problem 2 answer.
pub fn adhesion_json(ans: &AdhesionAnswer, requested: u32) -> Map<String, Value> {
    let mut m = Map::new();
    m.insert("problem".into(), json!("adhesion"));
    m.insert("lambda".into(), opt(&ans.lambda, requested));
    m.insert("P2".into(), json!(ans.p2.print(requested)));
    m.insert("half_width".into(), json!(ans.half_width.print(requested)));
    m.insert("digits_requested".into(), json!(requested.to_string()));
    let printed = |key: &str| match key {
        "size" => held_min([&ans.p2, &ans.half_width].into_iter().chain(&ans.lambda), requested),
        "stick" => held_min(ans.stick.as_ref().map(|st| &st.stick_half_width), requested),
        k => ans
            .fields
            .iter()
            .find(|(name, _)| name == k)
            .map_or(f64::INFINITY, |(_, rows)| held_min(rows.iter().map(|r| &r.value), requested)),
    };
    let (accuracy, head) = held_accuracy(&ans.accuracy, printed, f64::INFINITY);
    headline(&mut m, ans.kind, head);
    let acc: Map<String, Value> = accuracy.iter().map(|(k, d)| (k.clone(), json!(digits_text(*d)))).collect();
    m.insert("accuracy".into(), Value::Object(acc));
    for (name, rows) in &ans.fields {
        let list: Vec<Value> =
            rows.iter().map(|r| json!({"x_over_a": r.x_over_a, name.as_str(): r.value.print(requested)})).collect();
        m.insert(name.clone(), Value::Array(list));
    }
    if let Some(zones) = &ans.tension_zones {
        let z: Vec<Value> = zones
            .iter()
            .map(|z| {
                json!({
                    "from_x_over_a": zone_end_text(&z.from_one_minus),
                    "to_x_over_a": zone_end_text(&z.to_one_minus),
                    "from_1_minus_x_over_a": z.from_one_minus.fmt(ZONE_DELTA_DIGITS),
                    "to_1_minus_x_over_a": z.to_one_minus.fmt(ZONE_DELTA_DIGITS),
                    "refined": z.refined
                })
            })
            .collect();
        m.insert("tension_zones".into(), Value::Array(z));
    }
    if let Some(st) = &ans.stick {
        let (c, a) = (&st.stick_half_width, &ans.half_width);
        m.insert("friction".into(), json!(st.friction));
        m.insert("stick_half_width".into(), json!(c.print(requested)));
        m.insert(
            "slip_zones".into(),
            json!([
                {"from": a.negated().print(requested), "to": c.negated().print(requested)},
                {"from": c.print(requested), "to": a.print(requested)}
            ]),
        );
        m.insert("friction_note".into(), json!(st.note));
        if !st.checks.is_empty() {
            let checks: Map<String, Value> = st
                .checks
                .iter()
                .map(|c| {
                    let value = c.value.map_or(Value::Null, |v| json!(round_sig(v, 4)));
                    (c.name.to_string(), json!({"value": value, "error": round_sig(c.error, 2), "means": c.means}))
                })
                .collect();
            m.insert("checks".into(), Value::Object(checks));
        }
    }
    m.insert("warnings".into(), Value::Array(ans.warnings.iter().map(|w| json!(w)).collect()));
    m.insert("provenance".into(), ans.provenance.json());
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn noise_prints_as_zero_in_both_number_types() {
        // The frictionless F_def: 2.85e-44 (MPFR) and -1.32e-19 (f64) at scale k l P2.
        let p = 128;
        let scale = Float::with_val(p, 2.3e-3);
        let m = Measured::mpfr(Float::with_val(p, 2.85470179000802031743799538663e-44), &scale, 33.0);
        assert_eq!(m.print(30), "0");
        let f = Measured::f64(-1.32137139771671e-19, 2.3e-3, 14.0);
        assert_eq!(f.print(15), "0");
        // 0.123456789 known to 5e-7: places 1e-1 .. 1e-8 (a guard digit below the bound's 1e-7).
        let v = Measured::f64(0.123456789, 0.5, 6.0);
        assert_eq!(v.print(15), "1.2345679e-1");
        assert!(v.held(15) > 5.99 && v.held(15) <= 6.0);
    }

    /// Issue 34: a zone end below f64's range (1 - x/a = 1.2345e-400, from an MPFR solution)
    /// overflowed the count of nines (a panic in the debug build); it now prints the digits that
    /// separate it from 1, and a delta of 1e-5000 prints without a panic (MAX_ZONE_NINES nines at
    /// most).
    #[test]
    fn zone_ends_below_the_f64_range_print() {
        let delta = Float::with_val(256, Float::parse("1.2345e-400").unwrap());
        let text = zone_end_text(&Num::Mpfr(delta.clone()));
        let x = Float::with_val(2000, Float::parse(&text).unwrap());
        let back = Float::with_val(2000, Float::with_val(2000, 1u32) - x);
        let rel = Float::with_val(64, Float::with_val(2000, back - &delta) / &delta).abs().to_f64();
        assert!(rel < 1e-3, "{rel}");
        let text = zone_end_text(&Num::Mpfr(Float::with_val(256, Float::parse("1e-5000").unwrap())));
        assert!(text.len() > MAX_ZONE_NINES, "{text}");
    }

    /// Issue 30: a tension zone near the edge printed "1.00000 to 1.00000"; its ends now show the
    /// digits that separate them from 1 and from each other, and 1 - x/a beside them.
    #[test]
    fn zone_ends_near_the_edge_are_distinct_from_one() {
        let d = |x: f64| Num::Mpfr(Float::with_val(200, x));
        // An end far from the edge keeps six digits, as before.
        assert_eq!(zone_end_text(&d(1.963770e-3)), fmt_f64(1.0 - 1.963770e-3, 6));
        let outer = zone_end_text(&d(3.098824e-11));
        let inner = zone_end_text(&d(1.2e-27));
        assert_ne!(outer, inner);
        for (text, delta) in [(&outer, 3.098824e-11), (&inner, 1.2e-27)] {
            assert_ne!(text.trim_end_matches('0'), "1.");
            // Read back with MPFR: 1 - x/a to four digits.
            let x = Float::with_val(256, Float::parse(text).unwrap());
            let back = (Float::with_val(256, 1u32) - x).to_f64();
            assert!(((back - delta) / delta).abs() < 1e-3, "{text}: {back} vs {delta}");
        }
        let zone = ZoneRow {
            from: Num::Mpfr(Float::with_val(64, 1u32)),
            to: Num::Mpfr(Float::with_val(64, 1u32)),
            from_one_minus: d(3.098824e-11),
            to_one_minus: d(1.2e-27),
            refined: false,
        };
        assert_eq!(zone.from_one_minus.fmt(ZONE_DELTA_DIGITS), "3.099e-11");
    }
}
