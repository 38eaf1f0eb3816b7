//! Scene files (TOML): a problem statement plus what to output. Parsed strictly ([`parse`]):
//! unknown keys are rejected, numbers are read exactly from their text (a decimal or a ratio such
//! as "1/3", quoted or not) and never pass through `f64`.
//!
//! ```toml
//! [problem]
//! kind = "sliding"
//! [material]
//! poisson_ratio = "0.25"
//! contact_modulus = "1"          # or youngs_modulus = "..." (not both)
//! [punch]
//! shape = "parabolic"            # or "sinusoidal" with amplitude = "..."
//! k = "1"
//! period = "1"                   # or "inf" for a single punch
//! [sliding]
//! normal_load = "0.01"           # or half_length = "..."
//! friction = "0.3"
//! adhesive_friction = "0"
//! wear = "0"
//! speed = "1"                    # optional, for the wear rate
//! [output]
//! digits = 30
//! points = ["-0.6", "0.1", "0.7"] # xh = (x - c)/l in (-1, 1)
//! ```
//!
//! Problem 2 (adhesion, parabolic punch only) replaces `[sliding]` by
//!
//! ```toml
//! [problem]
//! kind = "adhesion"
//! [adhesion]
//! half_width = "0.1"             # or normal_load = "..." (then a is found)
//! [output]
//! points = ["0", "0.5", "0.9"]   # x/a in [0, 1]
//! ```

pub mod parse;

use crate::model::{AdhesionProblem, Exact, SlidingProblem};

/// The solution method a scene or the command line asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// High precision (MPFR), verified by a second run.
    Mpfr,
    /// Fast f64, error estimated by a second run with more nodes.
    F64,
    /// The truncated exact series evaluated in MPFR.
    Series,
}

impl Method {
    /// Parses a method name.
    pub fn parse(name: &str) -> Option<Method> {
        match name {
            "mpfr" => Some(Method::Mpfr),
            "f64" => Some(Method::F64),
            "series" => Some(Method::Series),
            _ => None,
        }
    }
    /// The method's name.
    pub fn name(self) -> &'static str {
        match self {
            Method::Mpfr => "mpfr",
            Method::F64 => "f64",
            Method::Series => "series",
        }
    }
}

/// What to output.
#[derive(Debug, Clone, PartialEq)]
pub struct OutputSpec {
    /// Digits requested (forces the working precision).
    pub digits: Option<u32>,
    /// Accuracy target (the cheapest method meeting it may be chosen).
    pub target_digits: Option<u32>,
    /// Points where the fields are wanted (Problem 1: xh in (-1, 1); Problem 2: x/a in [0, 1]).
    pub points: Vec<Exact>,
    /// Method asked for.
    pub method: Option<Method>,
    /// Series order for `Method::Series`.
    pub series_order: Option<usize>,
}

/// The problem a scene describes.
#[derive(Debug, Clone, PartialEq)]
pub enum SceneProblem {
    /// Problem 1.
    Sliding(SlidingProblem),
    /// Problem 2.
    Adhesion(AdhesionProblem),
}

/// A parsed, validated scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// The problem.
    pub problem: SceneProblem,
    /// The output request.
    pub output: OutputSpec,
}
