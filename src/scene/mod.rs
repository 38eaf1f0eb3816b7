//! Scene files (TOML): a problem statement plus what to output. Parsed strictly ([`parse`]):
//! unknown keys are rejected (the valid keys, their meaning, unit and range: the one table
//! [`keys::KEYS`], printed by `periodic-contact scene --template`), numbers are read exactly from their text (a decimal or a ratio such
//! as "1/3", quoted or not) and never pass through `f64`.
//!
//! ```toml
//! [problem]
//! kind = "sliding"
//! convention = "paper"           # or "periodic"; optional, default "paper"
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
//! `convention` is the surface convention of Problem 1 (docs/theory.md section 8;
//! [`crate::model::Convention`]): `"paper"` solves the paper's equation [2.8] as it stands (its
//! expansions run in even powers of lambda; the surface then does not close over a period when
//! friction, wear or tau0 act: mismatch (2/E*) beta P1 - cW P2); `"periodic"` adds
//! K = (kappa P2 - 2 beta l tau0)/L to the right side of [2.8], so that the surface closes over every
//! period (the consistent model of a row of identical punches at one height). The two coincide
//! when K = 0 (e.g. frictionless without wear and tau0). Any other value is an input error.
//! The series method has only the paper's expansions and refuses `"periodic"` when K can be
//! nonzero. In Problem 2 `"periodic"` makes the tangential displacement u periodic (a laterally
//! rigid row), `"paper"` keeps the Flamant far field sigma_xx = -P2/L (docs/theory.md section 8);
//! the stick condition feels the difference. `periodic-contact solve --convention` overrides the key.
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
//!
//! Problem 2 under a loading law P1 = N(P2) (docs/theory.md section 10; an asymmetric contact
//! [-a, b]) is an adhesion scene whose `[adhesion]` states the law; it parses to
//! [`SceneProblem::LoadingLaw`], and `[problem] convention` matters there (`periodic`: no rotation
//! with P1 != 0 and u periodic):
//!
//! ```toml
//! [adhesion]
//! tangential_ratio = "1/5"       # P1 = n P2; or loading_law = ["0", "1/5", "1/100"] (numpy order)
//! half_length = "1/6"            # l = (a + b)/2; or normal_load = "..."; half_width is refused
//! [output]
//! points = ["-0.9", "0", "0.9"]  # xh = (x - c)/l in (-1, 1)
//! ```
//!
//! Either problem may add a sweep for load-size curves (`periodic-contact report`): one key, an
//! array of exact values, each replacing the scene's own load or size in turn (the scene's own
//! value is kept for `solve`).
//!
//! ```toml
//! [sweep]
//! normal_load = ["0.001", "0.01", "0.1"]   # sliding or adhesion; or half_length (sliding,
//!                                          # loading law), or half_width (adhesion)
//! ```
//!
//! `[output] target_digits = 12` asks for the cheapest method meeting 12 digits (chosen by the
//! report from the committed calibration table, `calibration/methods.csv`); `digits` forces a
//! working precision instead.

pub mod keys;
pub mod parse;

use crate::model::OnPunchRow;
use crate::model::{AdhesionProblem, Exact, LoadingLawProblem, SlidingProblem};

/// The solution method a scene or the command line asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// High precision (MPFR), verified by a second run.
    Mpfr,
    /// Fast f64, error estimated by a second run with more nodes.
    F64,
    /// The truncated exact series evaluated in MPFR.
    Series,
    /// The Pade approximants of the same series (docs/theory.md section 11).
    Pade,
    /// Problem 2: the member analytic at zero size, continued (crate::adhesion::analytic).
    Analytic,
}

impl Method {
    /// Parses a method name.
    pub fn parse(name: &str) -> Option<Method> {
        match name {
            "mpfr" => Some(Method::Mpfr),
            "f64" => Some(Method::F64),
            "series" => Some(Method::Series),
            "pade" => Some(Method::Pade),
            "analytic" => Some(Method::Analytic),
            _ => None,
        }
    }
    /// The method's name.
    pub fn name(self) -> &'static str {
        match self {
            Method::Mpfr => "mpfr",
            Method::F64 => "f64",
            Method::Series => "series",
            Method::Pade => "pade",
            Method::Analytic => "analytic",
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
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum SceneProblem {
    /// Problem 1.
    Sliding(SlidingProblem),
    /// Problem 2.
    Adhesion(AdhesionProblem),
    /// Problem 2 under a loading law P1 = N(P2) (docs/theory.md section 10; asymmetric contact).
    LoadingLaw(LoadingLawProblem),
}

/// The quantity a `[sweep]` varies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SweepParameter {
    /// Load per punch P2 (either problem).
    NormalLoad,
    /// Half-length l of the sliding contact (Problem 1, direct problem) or of the loading-law
    /// contact, l = (a + b)/2.
    HalfLength,
    /// Half-width a of the adhesive contact (Problem 2).
    HalfWidth,
}

impl SweepParameter {
    /// The TOML key.
    pub fn key(self) -> &'static str {
        match self {
            SweepParameter::NormalLoad => "normal_load",
            SweepParameter::HalfLength => "half_length",
            SweepParameter::HalfWidth => "half_width",
        }
    }
}

/// A sweep: the scene's load or size replaced by each value in turn (every value validated).
#[derive(Debug, Clone, PartialEq)]
pub struct Sweep {
    /// What is varied.
    pub parameter: SweepParameter,
    /// The values, in the order given (at least one).
    pub values: Vec<Exact>,
}

/// A parsed, validated scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// The problem.
    pub problem: SceneProblem,
    /// The output request.
    pub output: OutputSpec,
    /// Optional sweep for load-size curves.
    pub sweep: Option<Sweep>,
}

impl Scene {
    /// The problems of the sweep, one per value (empty without a sweep).
    pub fn sweep_problems(&self) -> Vec<SceneProblem> {
        let Some(sw) = &self.sweep else { return Vec::new() };
        sw.values.iter().filter_map(|v| with_value(&self.problem, sw.parameter, v)).collect()
    }
}

/// The problem with its load or size replaced by `v` (None if the parameter does not apply or the
/// value is invalid; the parser rejects both).
pub(crate) fn with_value(problem: &SceneProblem, parameter: SweepParameter, v: &Exact) -> Option<SceneProblem> {
    use crate::model::{AdhesionSize, LawSize, SlidingLoad};
    match (problem, parameter) {
        (SceneProblem::Sliding(p), SweepParameter::NormalLoad | SweepParameter::HalfLength) => {
            let load = if parameter == SweepParameter::NormalLoad {
                SlidingLoad::NormalLoad(v.clone())
            } else {
                SlidingLoad::HalfLength(v.clone())
            };
            p.to_builder().load(load).build().ok().map(SceneProblem::Sliding)
        }
        (SceneProblem::Adhesion(p), SweepParameter::NormalLoad | SweepParameter::HalfWidth) => {
            let size = if parameter == SweepParameter::NormalLoad {
                AdhesionSize::NormalLoad(v.clone())
            } else {
                AdhesionSize::HalfWidth(v.clone())
            };
            AdhesionProblem::new(p.material().clone(), p.period().clone(), p.shape().clone(), size)
                .ok()
                .map(|q| SceneProblem::Adhesion(q.with_convention(p.convention())))
        }
        (SceneProblem::LoadingLaw(p), SweepParameter::NormalLoad | SweepParameter::HalfLength) => {
            let size = if parameter == SweepParameter::NormalLoad {
                LawSize::NormalLoad(v.clone())
            } else {
                LawSize::HalfLength(v.clone())
            };
            rebuild_law(p, size, p.convention()).ok().map(SceneProblem::LoadingLaw)
        }
        _ => None,
    }
}

/// `p` with another size and convention (the model keeps its fields private and validates in
/// [`LoadingLawProblem::new`]; the rest of the statement is kept).
pub(crate) fn rebuild_law(
    p: &LoadingLawProblem,
    size: crate::model::LawSize,
    convention: crate::model::Convention,
) -> Result<LoadingLawProblem, crate::model::ModelError> {
    LoadingLawProblem::new(
        p.material().clone(),
        p.period().clone(),
        crate::model::PunchShape::Parabolic { k: p.k().clone() },
        p.law().clone(),
        size,
        convention,
    )
}
