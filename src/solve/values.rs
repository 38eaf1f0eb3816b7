//! The typed values of a solved scene: every number `solve --json` prints, as a [`Quantity`]
//! (its text, its value, the digits of its scale the text holds, verified or estimated, the
//! scale), the headline numbers by their JSON key and the fields at the requested points by name.
//! The renderers fill them from the same [`super::render::Measured`] values they print, so a
//! caller of the library reads numbers without parsing the JSON (issue 29). Tests:
//! `tests/all/typed_answers.rs` compares every quantity with the JSON text of the same answer.

/// Whether the digits of an answer were verified (by a second run) or estimated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DigitsKind {
    /// Verified by a second run with more precision (MPFR) or more nodes (f64).
    Verified,
    /// Estimated (the truncated series' tail bound; the f64 method of Problem 2).
    Estimated,
}

/// One printed number with its accuracy: |text - truth| <= 10^-digits |scale|.
#[derive(Debug, Clone, PartialEq)]
pub struct Quantity {
    /// The text `solve --json` prints (it holds `digits`).
    pub text: String,
    /// The value, rounded once to `f64` from the method's own number (MPFR or `f64`).
    pub value: f64,
    /// Digits of `scale` that `text` holds (what the JSON's accuracy table states for its group is
    /// at most this).
    pub digits: f64,
    /// Verified by a second run, or estimated.
    pub kind: DigitsKind,
    /// The scale of the digits (docs/theory.md section 14: l for lengths, P2 for loads, ...).
    pub scale: f64,
}

/// A field at the requested points: its name (`p`, `psi`, `phi`, `q1`, `q2`, `x`), the name of
/// the coordinate (`xh` or `x_over_a`) and, per point, the coordinate as given (exact text) and
/// the value.
#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    /// The JSON key of the field.
    pub name: String,
    /// The JSON key of the coordinate.
    pub at: &'static str,
    /// (coordinate, value) per requested point, in order.
    pub points: Vec<(String, Quantity)>,
}

/// The numbers of one solution: the headline quantities by JSON key (`l`, `a`, `P2`,
/// `half_width`, ...; absent keys print as `null`) and the fields.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Values {
    /// (JSON key, quantity), in print order.
    pub scalars: Vec<(String, Quantity)>,
    /// The fields at the requested points.
    pub fields: Vec<Field>,
}

impl Values {
    /// The quantity printed under `key` (`"P2"`, `"half_width"`, ...).
    pub fn get(&self, key: &str) -> Option<&Quantity> {
        self.scalars.iter().find(|(k, _)| k == key).map(|(_, q)| q)
    }

    /// The field named `name`.
    pub fn field(&self, name: &str) -> Option<&Field> {
        self.fields.iter().find(|f| f.name == name)
    }

    /// Adds a scalar.
    pub(crate) fn push(&mut self, key: &str, q: Quantity) {
        self.scalars.push((key.to_string(), q));
    }

    /// Adds the value of `name` at the point `at_value` (coordinate `at`), opening the field.
    pub(crate) fn push_point(&mut self, name: &str, at: &'static str, at_value: String, q: Quantity) {
        match self.fields.iter_mut().find(|f| f.name == name) {
            Some(f) => f.points.push((at_value, q)),
            None => self.fields.push(Field { name: name.to_string(), at, points: vec![(at_value, q)] }),
        }
    }
}
