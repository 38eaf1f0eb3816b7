//! The library's front door: the three things users do, each one call, each through the same
//! validation, defaults and messages as the command line (which is a client of these calls):
//!
//! 1. **derive an object** ([`derive()`] of a [`SeriesRequest`]): the series of
//!    `periodic-contact series OBJECT`,
//!    e.g. the Problem 1 expansions in $\Lambda = \pi l_s / L$ ([3.7]-[3.12] of the paper),
//!    $l/l_s = 1 + (\theta^2/3 - 1/12)\Lambda^2 + O(\Lambda^4)$;
//! 2. **solve a problem** ([`solve_toml`], [`solve_file`], or [`solve`] on a parsed [`Scene`]):
//!    an [`Answer`], every number typed with its digits and scale ([`Quantity`]), and the JSON of
//!    `periodic-contact solve SCENE --json`, one rendering of the same numbers (a batch of scenes
//!    on every core: [`solve_many`]);
//! 3. **check orders** ([`check_orders`]): the remainder of the series truncated after $m$
//!    corrections against the MPFR solution, observed slope of $\log|r_m|$ against
//!    $\log\Lambda$ vs the predicted $2m + 2$ (`paper` convention).
//!
//! Every failure is an [`ApiError`]: the problem's [`Error`] (input / no solution / not physical /
//! no convergence, with the CLI's message) or the series engine's [`SeriesError`].
//!
//! ```
//! use periodic_contact::api;
//! // Problem 1 at theta = 1/10: l/l_s = 1 + (theta^2/3 - 1/12) Lambda^2 + ... = 1 - 2/25 Lambda^2 + ...
//! let parts = api::derive(&api::SeriesRequest::new("sliding", 2).option("theta", "1/10"))?.json();
//! assert_eq!(parts["parts"][0]["object"], "l_over_ls");
//! assert_eq!(parts["parts"][0]["coefficients"][1]["text"], "-2/25");
//! # Ok::<(), api::ApiError>(())
//! ```

use crate::model::{Convention, Exact};
use crate::scene::SceneProblem;
use crate::solve::choice::{solve_choice, Forced, MethodChoice};
use serde_json::Value;
use std::path::Path;

pub use crate::asymptotics::adhesion_numeric::AdhesionNumeric;
pub use crate::asymptotics::catalog::Derived;
pub use crate::asymptotics::loading_law::LawSeries;
pub use crate::asymptotics::loading_law_modes::ModeExponent;
pub use crate::error::{Error, ErrorKind};
pub use crate::model::ModelError;
pub use crate::scene::{parse::parse_scene, Method, Scene};
pub use crate::series_request::{SeriesRequest, ValidSeries, OPTION_NAMES as SERIES_OPTIONS};
pub use crate::solve::batch::solve_many;
pub use crate::solve::render::DigitsKind;
pub use crate::solve::values::{Field, Quantity, Values};
pub use crate::solve::{Answer, Claim, SolveRequest};
pub use crate::verification::convergence::{
    parabola_case, sliding_convergence as check_orders, ConvergenceStudy, OrderRow,
};
pub use exact_series::SeriesError;

/// Why a call failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ApiError {
    /// The scene text itself is invalid (a TOML error, an unknown key, a value out of range): the
    /// message of [`parse_scene`], as `periodic-contact solve` prints it.
    #[error(transparent)]
    Scene(ModelError),
    /// The problem: an invalid option (exit code 2 on the command line), no solution, not
    /// physical, no convergence (exit code 1).
    #[error(transparent)]
    Problem(#[from] Error),
    /// The series engine (e.g. a denominator vanishing at the substituted values).
    #[error(transparent)]
    Series(#[from] SeriesError),
}

impl ApiError {
    /// The kind of failure: [`ErrorKind::Input`] for scene and option errors, the problem's kind
    /// otherwise; `None` for the series engine's errors.
    ///
    /// ```
    /// use periodic_contact::api::{self, ErrorKind, SolveOptions};
    /// let bad = "[problem]\nkind = \"sliding\"\n[material]\ncontact_modulus = \"1\"\n";
    /// let e = api::solve_toml(bad, &SolveOptions::default()).unwrap_err();
    /// assert_eq!(e.kind(), Some(ErrorKind::Input));
    /// assert!(e.to_string().contains("poisson_ratio"), "{e}");
    /// ```
    pub fn kind(&self) -> Option<ErrorKind> {
        match self {
            ApiError::Scene(_) => Some(ErrorKind::Input),
            ApiError::Problem(e) => Some(e.kind()),
            ApiError::Series(_) => None,
        }
    }
}

impl From<ModelError> for ApiError {
    fn from(e: ModelError) -> Self {
        ApiError::Problem(Error::Input(e))
    }
}

/// A derived object as `periodic-contact series` prints it.
#[derive(Debug, Clone)]
pub enum Derivation {
    /// The exact objects (`kernel`, `weight`, `jacobi`, `sliding`, `adhesion`): one part or
    /// several, coefficients in Q, Q\[symbols\] or its fraction field.
    Exact {
        /// The CLI's name of the object.
        object: &'static str,
        /// The parts (e.g. `l_over_ls`, `rbar_minus_rbar_s`, ... for `sliding`).
        parts: Vec<Derived>,
        /// Whether the Pade approximants were asked ([`Derivation::pade_text`]).
        pade: bool,
    },
    /// `loading-law`: numerical coefficients at given nu and n (MPFR, verified by a second run),
    /// with the homogeneous mode's exponent of the loading (docs/theory.md section 10).
    LoadingLaw {
        /// The coefficients.
        series: Box<LawSeries>,
        /// mu*, the exponent of the loading's homogeneous mode.
        mode: Box<ModeExponent>,
    },
    /// `adhesion` with `nu` beyond the exact route's order or with `digits`: numerical
    /// coefficients at nu (MPFR, verified by a second run).
    AdhesionNumeric(Box<AdhesionNumeric>),
}

impl Derivation {
    /// The JSON of `--format json`, one schema for every object (docs/theory.md section 16):
    /// `{"object", "parts": [{"object", "formula", "source", "variable", "order", "symbols",
    /// "sympy", "mathematica", "coefficients": [{"power", "text", "latex", "sympy"}]}]}`; the
    /// numerical routes' coefficients are `{"power", "value", "digits"}`, the loading law's
    /// answer carries its `mode`.
    ///
    /// ```
    /// use periodic_contact::api::{derive, SeriesRequest};
    /// let v = derive(&SeriesRequest::new("kernel", 4))?.json();
    /// assert_eq!(v["parts"][0]["coefficients"][1]["text"], "-1/3"); // z cot z = 1 - z^2/3 - ...
    /// # Ok::<(), periodic_contact::api::ApiError>(())
    /// ```
    pub fn json(&self) -> Value {
        match self {
            Derivation::Exact { object, parts, .. } => serde_json::json!({
                "object": object,
                "parts": parts.iter().map(|d| d.json()).collect::<Vec<_>>(),
            }),
            Derivation::LoadingLaw { series, mode } => {
                let mut v = series.json();
                v["mode"] = mode.json(series.order);
                v
            }
            Derivation::AdhesionNumeric(s) => s.json(),
        }
    }

    /// The plain text of `--format text` (with the Pade approximants when they were asked).
    ///
    /// ```
    /// use periodic_contact::api::{derive, SeriesRequest};
    /// let text = derive(&SeriesRequest::new("kernel", 4))?.text();
    /// assert!(text.contains("1/3"), "{text}");
    /// # Ok::<(), periodic_contact::api::ApiError>(())
    /// ```
    pub fn text(&self) -> String {
        match self {
            Derivation::Exact { object, parts, .. } => {
                crate::asymptotics::print::render(object, parts, crate::asymptotics::print::SeriesFormat::Text)
                    + &self.pade_text()
            }
            Derivation::LoadingLaw { series, mode } => series.text() + &mode.text(series.order),
            Derivation::AdhesionNumeric(s) => s.text(),
        }
    }

    /// The Pade approximants' text when they were asked (the exact route), else empty.
    ///
    /// ```
    /// use periodic_contact::api::{derive, SeriesRequest};
    /// assert!(derive(&SeriesRequest::new("kernel", 8))?.pade_text().is_empty());
    /// assert!(!derive(&SeriesRequest::new("kernel", 8).pade(true))?.pade_text().is_empty());
    /// # Ok::<(), periodic_contact::api::ApiError>(())
    /// ```
    pub fn pade_text(&self) -> String {
        match self {
            Derivation::Exact { parts, pade: true, .. } => crate::asymptotics::pade::pade_text(parts),
            _ => String::new(),
        }
    }
}

/// Derives what `request` asks, exactly as `periodic-contact series OBJECT --order N --KEY VALUE
/// ...` does: validated once by [`SeriesRequest::validate`] (the same table and messages as the
/// command line), then the exact route, the adhesion series' numerical route or the loading law.
///
/// ```
/// use periodic_contact::api::{derive, SeriesRequest};
/// // Problem 1 at theta = 1/10: l/l_s = 1 - 2/25 Lambda^2 + ...
/// let d = derive(&SeriesRequest::new("sliding", 2).option("theta", "1/10"))?;
/// assert_eq!(d.json()["parts"][0]["coefficients"][1]["text"], "-2/25");
/// # Ok::<(), periodic_contact::api::ApiError>(())
/// ```
///
/// # Errors
/// [`ApiError::Problem`] with [`Error::Input`] for an unknown object or option or an invalid
/// value (the message names the flag, the value and the valid range); [`ApiError::Series`] when
/// the engine fails; the numerical routes' own errors.
pub fn derive(request: &SeriesRequest) -> Result<Derivation, ApiError> {
    derive_valid(request.validate()?)
}

/// Derives a request already validated ([`SeriesRequest::validate`]; the command line validates
/// first, to check its output format against the route).
///
/// ```
/// use periodic_contact::api::{derive_valid, Derivation, SeriesRequest};
/// // The adhesion series at nu = 1/4 beyond the exact route's order 24: the numerical route.
/// let valid = SeriesRequest::new("adhesion", 30).option("nu", "1/4").validate()?;
/// assert!(matches!(derive_valid(valid)?, Derivation::AdhesionNumeric(_)));
/// # Ok::<(), periodic_contact::api::ApiError>(())
/// ```
///
/// # Errors
/// [`ApiError::Series`] when the engine fails; the numerical routes' own errors.
pub fn derive_valid(valid: ValidSeries) -> Result<Derivation, ApiError> {
    match valid {
        ValidSeries::Exact { object, order, subs, convention, pade } => {
            let parts = object.derive_in(convention, order, &subs)?;
            Ok(Derivation::Exact { object: object.name(), parts, pade })
        }
        ValidSeries::LoadingLaw { nu, ratio, order } => {
            use crate::asymptotics::{catalog::VALUE_DIGITS, loading_law, loading_law_modes};
            let series = loading_law::loading_law_series(&nu, &ratio, order, VALUE_DIGITS as u32)?;
            let mode = loading_law_modes::mode_exponent(&nu, &ratio, loading_law_modes::MODE_DIGITS)?;
            Ok(Derivation::LoadingLaw { series: Box::new(series), mode: Box::new(mode) })
        }
        ValidSeries::AdhesionNumeric { nu, order, digits } => Ok(Derivation::AdhesionNumeric(Box::new(
            crate::asymptotics::adhesion_numeric::adhesion_numeric(&nu, order, digits)?,
        ))),
    }
}

/// Options of [`solve_toml`] and [`solve_file`]: the flags of `periodic-contact solve`; `None`
/// leaves the scene's `[output]` (or the default) in force.
#[derive(Debug, Clone, Default)]
pub struct SolveOptions {
    /// `--digits N` (default: the scene's `digits`, else 30), in [1, 1000].
    pub digits: Option<u32>,
    /// `--method mpfr|f64|series|pade` (default: the scene's `method`, else the choice by
    /// `target_digits`, else `mpfr`).
    pub method: Option<String>,
    /// `--order N`: the series order of `--method series` or `pade` (default 12), at most 24.
    pub order: Option<usize>,
    /// `--convention paper|periodic` (default: the scene's, else `paper`).
    pub convention: Option<String>,
}

impl SolveOptions {
    /// Applies the options to a parsed scene (the convention replaces the scene's) and chooses
    /// the method: the one path of `periodic-contact solve` and of [`solve_toml`].
    ///
    /// ```
    /// use periodic_contact::api::{parse_scene, solve_with_choice, SolveOptions};
    /// let path = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/sliding_friction.toml");
    /// let mut scene = parse_scene(&std::fs::read_to_string(path).unwrap())?;
    /// let opts = SolveOptions { method: Some("f64".into()), ..Default::default() };
    /// let choice = opts.choose(&mut scene)?;
    /// assert_eq!(choice.reason, "forced by --method");
    /// let v = solve_with_choice(&scene, choice)?.json;
    /// assert_eq!(v["choice"]["method"], "f64");
    /// # Ok::<(), periodic_contact::api::ApiError>(())
    /// ```
    ///
    /// # Errors
    /// An [`Error::Input`] naming the option (`--digits`, `--method`, `--order`,
    /// `--convention`), its value and the valid range.
    pub fn choose(&self, scene: &mut Scene) -> Result<MethodChoice, Error> {
        if let Some(c) = &self.convention {
            let c = match c.trim() {
                "paper" => Convention::Paper,
                "periodic" => Convention::PeriodicSurface,
                other => return Err(Error::input("--convention", other, "must be paper or periodic")),
            };
            override_convention(scene, c)?;
        }
        let max = crate::scene::parse::MAX_DIGITS;
        if let Some(d) = self.digits.filter(|d| !(1..=max).contains(d)) {
            return Err(Error::input("--digits", d, format!("must be an integer in [1, {max}]")));
        }
        let method = match self.method.as_deref().map(str::trim) {
            None => None,
            Some("mpfr") => Some(Method::Mpfr),
            Some("f64") => Some(Method::F64),
            Some("series") => Some(Method::Series),
            Some("pade") => Some(Method::Pade),
            Some("analytic") => Some(Method::Analytic),
            Some(other) => return Err(Error::input("--method", other, "must be mpfr, f64, series, pade or analytic")),
        };
        if let Some(o) = self.order.filter(|o| *o > 24) {
            return Err(Error::input(
                "--order",
                o,
                "must be an integer in [0, 24] (the series and pade methods' limit)",
            ));
        }
        let forced = Forced { method, digits: self.digits, series_order: self.order };
        solve_choice(scene, forced)
            .map_err(|e| Error::Input(ModelError::new("calibration/methods.csv", "(compiled in)", e.to_string())))
    }
}

/// `--convention` replaces the scene's `[problem] convention` (Problem 1, Problem 2 and the
/// loading-law problem; docs/theory.md section 8).
fn override_convention(scene: &mut Scene, c: Convention) -> Result<(), ModelError> {
    match &scene.problem {
        SceneProblem::Sliding(p) => scene.problem = SceneProblem::Sliding(p.to_builder().convention(c).build()?),
        SceneProblem::LoadingLaw(p) => {
            scene.problem = SceneProblem::LoadingLaw(crate::scene::rebuild_law(p, p.size().clone(), c)?)
        }
        SceneProblem::Adhesion(p) => scene.problem = SceneProblem::Adhesion(p.clone().with_convention(c)),
    }
    Ok(())
}

/// Solves a parsed scene with the method `choice` names (escalating to dearer methods when the
/// answer's digits fall short of a `target_digits`): the typed answer, whose JSON is that of
/// `periodic-contact solve --json` with its `choice` (example: [`SolveOptions::choose`]).
///
/// # Errors
/// [`Error`]: no solution, not physical, no convergence (and input errors of the method).
pub fn solve_with_choice(scene: &Scene, choice: MethodChoice) -> Result<Answer, Error> {
    let (mut answer, choice) = crate::solve::choice::solve_chosen(scene, choice)?;
    if let Some(m) = answer.json.as_object_mut() {
        m.insert("choice".into(), choice.json());
    }
    Ok(answer)
}

/// Solves a parsed scene under `options` ([`SolveOptions::choose`], then
/// [`solve_with_choice`]): the one path of [`solve_toml`], [`solve_file`] and the command line.
///
/// ```
/// use periodic_contact::api::{self, SolveOptions};
/// let path = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/kuznetsov_parabola.toml");
/// let scene = api::parse_scene(&std::fs::read_to_string(path).unwrap())?;
/// let answer = api::solve(&scene, &SolveOptions { digits: Some(20), ..Default::default() })?;
/// let l = answer.get("l").unwrap();
/// // The number, its text as `solve --json` prints it, and the digits of its scale the text holds.
/// assert_eq!(l.text, answer.json["l"].as_str().unwrap());
/// assert!(l.digits >= 20.0, "{l:?}");
/// # Ok::<(), api::ApiError>(())
/// ```
///
/// # Errors
/// As [`solve_toml`].
pub fn solve(scene: &Scene, options: &SolveOptions) -> Result<Answer, ApiError> {
    let mut scene = scene.clone();
    let choice = options.choose(&mut scene)?;
    Ok(solve_with_choice(&scene, choice)?)
}

/// Solves the scene file at `path` as `periodic-contact solve PATH --json [flags]` does: the typed
/// answer, whose `json` is what the command prints (string values; keys in docs/theory.md
/// section 14).
///
/// ```
/// use periodic_contact::api::{solve_file, SolveOptions};
/// let path = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/sliding_friction.toml");
/// let answer = solve_file(path.as_ref(), &SolveOptions { method: Some("f64".into()), ..Default::default() })?;
/// assert_eq!(answer.json["problem"], "sliding");
/// let p2 = answer.get("P2").unwrap();
/// assert!((p2.value - 0.01).abs() < 1e-14 && p2.digits > 12.0, "{p2:?}");
/// # Ok::<(), periodic_contact::api::ApiError>(())
/// ```
///
/// # Errors
/// [`ApiError::Scene`] for an invalid scene, [`ApiError::Problem`] otherwise (an unreadable file,
/// an invalid option, no solution, not physical, no convergence), each with the CLI's message.
pub fn solve_file(path: &Path, options: &SolveOptions) -> Result<Answer, ApiError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| ModelError::new("SCENE", path.display(), format!("cannot be read: {e}")))?;
    solve_toml(&text, options)
}

/// Solves a scene given as TOML text (the format of `scenes/*.toml`, documented in
/// [`crate::scene`]) like [`solve_file`]: parsed once, the options applied
/// ([`SolveOptions::choose`]), solved ([`solve_with_choice`]).
///
/// ```
/// use periodic_contact::api::{solve_toml, SolveOptions};
/// let scene = r#"
/// [problem]
/// kind = "sliding"
/// [material]
/// poisson_ratio = "0.3"
/// contact_modulus = "1"
/// [punch]
/// shape = "parabolic"
/// k = "1"
/// period = "1"
/// [sliding]
/// normal_load = "0.01"
/// friction = "0.3"
/// "#;
/// let opts = SolveOptions { method: Some("f64".into()), ..Default::default() };
/// let answer = solve_toml(scene, &opts)?;
/// // l = 0.0794891890084214444... (`solve scenes/sliding_friction.toml`, MPFR, 34 digits).
/// let l = answer.get("l").unwrap();
/// assert!((l.value - 0.0794891890084214444).abs() < 1e-14 * l.value);
/// // It holds the digits it claims, of its scale.
/// assert!((l.value - 0.0794891890084214444).abs() <= 10f64.powf(-l.digits) * l.scale);
/// # Ok::<(), periodic_contact::api::ApiError>(())
/// ```
pub fn solve_toml(scene: &str, options: &SolveOptions) -> Result<Answer, ApiError> {
    let mut scene = parse_scene(scene).map_err(ApiError::Scene)?;
    let choice = options.choose(&mut scene)?;
    Ok(solve_with_choice(&scene, choice)?)
}

/// An exact number as text (`"1/10"`, `"0.25"`), for callers that hold exact inputs.
///
/// ```
/// let x = periodic_contact::api::exact("0.25")?;
/// assert_eq!(x, periodic_contact::api::exact("1/4")?);
/// # Ok::<(), periodic_contact::api::ModelError>(())
/// ```
pub fn exact(text: &str) -> Result<Exact, ModelError> {
    crate::series_request::parse_exact("value", text)
}

/// The CLI's JSON text of a [`Value`] (`serde_json::to_string_pretty`, a newline at the end),
/// byte for byte what `periodic-contact solve ... --json` prints.
///
/// ```
/// let text = periodic_contact::api::json_text(&serde_json::json!({"P2": "0.01"}));
/// assert_eq!(text, "{\n  \"P2\": \"0.01\"\n}\n");
/// ```
pub fn json_text(v: &Value) -> String {
    format!("{}\n", serde_json::to_string_pretty(v).expect("a JSON value always serialises"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unknown_option_names_the_valid_ones() {
        let e = derive(&SeriesRequest::new("sliding", 4).option("tehta", "1/10")).unwrap_err();
        assert_eq!(e.kind(), Some(ErrorKind::Input));
        assert!(e.to_string().starts_with("invalid option = tehta: must be one of theta, xh, T"), "{e}");
    }

    #[test]
    fn invalid_values_carry_the_cli_message() {
        let e = derive(&SeriesRequest::new("sliding", 4).option("theta", "1/2")).unwrap_err();
        assert_eq!(e.to_string(), "invalid --theta = 1/2: must satisfy |theta| < 1/2");
        let e = derive(&SeriesRequest::new("sliding", 4).option("shape", "square")).unwrap_err();
        assert!(e.to_string().starts_with("invalid --shape = square: must be parabolic"), "{e}");
        let e = derive(&SeriesRequest::new("kernel", 100000)).unwrap_err();
        assert_eq!(
            e.to_string(),
            "invalid --order = 100000: must be an integer in [0, 2000] (the kernel series' limit)"
        );
    }

    #[test]
    fn kernel_is_z_cot_z() {
        // z cot z = 1 - z^2/3 - z^4/45 - ... (DLMF 4.19.6).
        let d = derive(&SeriesRequest::new("kernel", 4)).unwrap();
        let v = d.json();
        let texts: Vec<&str> =
            v["parts"][0]["coefficients"].as_array().unwrap().iter().map(|c| c["text"].as_str().unwrap()).collect();
        assert_eq!(texts, ["1", "-1/3", "-1/45"]);
        assert!(d.text().contains("[z^4] -1/45"));
    }

    #[test]
    fn scene_errors_are_scene_errors() {
        let e = solve_toml("[problem]\nkind = \"rolling\"\n", &SolveOptions::default()).unwrap_err();
        assert!(matches!(e, ApiError::Scene(_)), "{e:?}");
        assert_eq!(e.kind(), Some(ErrorKind::Input));
    }
}
