//! The library's front door (issue 16): the three things users do, each one call, each through
//! the same validation, defaults and messages as the command line (the CLI's raw arguments ->
//! validated configuration of [`crate::cli`], then the same library functions):
//!
//! 1. **derive an object** ([`derive()`]): the exact series of `periodic-contact series OBJECT`,
//!    e.g. the Problem 1 expansions in $\Lambda = \pi l_s / L$ ([3.7]-[3.12] of the paper),
//!    $l/l_s = 1 + (\theta^2/3 - 1/12)\Lambda^2 + O(\Lambda^4)$;
//! 2. **solve a problem** ([`solve_toml`], [`solve_file`], or [`solve`] on a parsed [`Scene`]):
//!    the JSON of `periodic-contact solve SCENE --json`, every number with its verified digits;
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
//! let parts = api::derive("sliding", 2, &[("theta", "1/10")])?.json();
//! assert_eq!(parts["parts"][0]["object"], "l_over_ls");
//! assert_eq!(parts["parts"][0]["coefficients"][1]["text"], "-2/25");
//! # Ok::<(), api::ApiError>(())
//! ```

use crate::cli::{args::RawArgs, config::RunConfig};
use clap::Parser;
use serde_json::Value;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};

pub use crate::asymptotics::adhesion_numeric::AdhesionNumeric;
pub use crate::asymptotics::catalog::Derived;
pub use crate::asymptotics::loading_law::LawSeries;
pub use crate::error::{Error, ErrorKind};
pub use crate::model::ModelError;
pub use crate::scene::{parse::parse_scene, Method, Scene};
pub use crate::solve::{solve_scene as solve, SolveRequest};
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
    },
    /// `loading-law`: numerical coefficients at given nu and n (MPFR, verified by a second run).
    LoadingLaw(Box<LawSeries>),
    /// `adhesion` with `nu` beyond the exact route's order or with `digits`: numerical
    /// coefficients at nu (MPFR, verified by a second run).
    AdhesionNumeric(Box<AdhesionNumeric>),
}

impl Derivation {
    /// The JSON of `--format json`: one part as `{"object", "variable", "order", "symbols",
    /// "coefficients": [{"power", "text", "latex"}]}`, several as `{"object", "parts": [...]}`.
    pub fn json(&self) -> Value {
        match self {
            Derivation::Exact { object, parts } => match parts.as_slice() {
                [one] => one.json(),
                many => serde_json::json!({
                    "object": object,
                    "parts": many.iter().map(|d| d.json()).collect::<Vec<_>>(),
                }),
            },
            Derivation::LoadingLaw(s) => s.json(),
            Derivation::AdhesionNumeric(s) => s.json(),
        }
    }

    /// The plain text of `--format text`.
    pub fn text(&self) -> String {
        match self {
            Derivation::Exact { parts, .. } => parts.iter().map(|d| d.text()).collect::<Vec<_>>().join("\n"),
            Derivation::LoadingLaw(s) => s.text(),
            Derivation::AdhesionNumeric(s) => s.text(),
        }
    }
}

/// Option names of [`derive()`] (the CLI's flags without the dashes, `rbar_s` for `--rbar-s`).
pub const SERIES_OPTIONS: [&str; 11] =
    ["theta", "xh", "T", "nu", "digits", "ratio", "shape", "coefficients", "degree", "rbar_s", "convention"];

/// The clap error's message without its `error: ` prefix and usage lines.
fn clap_message(e: &clap::Error) -> String {
    let text = e.to_string();
    let first: Vec<&str> = text.lines().take_while(|l| !l.trim_start().starts_with("Usage:")).collect();
    first.join(" ").trim().trim_start_matches("error: ").split_whitespace().collect::<Vec<_>>().join(" ")
}

/// Parses the CLI arguments `args` (after the program name) into a validated configuration.
fn config(args: &[String], what: &str) -> Result<RunConfig, ApiError> {
    let argv = std::iter::once("periodic-contact".to_string()).chain(args.iter().cloned());
    let raw = RawArgs::try_parse_from(argv).map_err(|e| ModelError::new(what, args.join(" "), clap_message(&e)))?;
    Ok(RunConfig::from_args(raw)?)
}

/// Derives `object` (`kernel`, `weight`, `jacobi`, `sliding`, `adhesion`, `loading-law`) through
/// power `order`, exactly as `periodic-contact series OBJECT --order ORDER --KEY VALUE ...` does,
/// with `options` as `(key, value)` pairs, keys from [`SERIES_OPTIONS`] and values as on the
/// command line (exact rationals as text: `("theta", "1/10")`, `("coefficients", "0,0,1,0,1/10")`,
/// `("shape", "sinusoidal")`, `("convention", "periodic")`).
///
/// # Errors
/// [`ApiError::Problem`] with [`Error::Input`] for an unknown key or an invalid value (the
/// message names the flag, the value and the valid range, as the CLI's); [`ApiError::Series`]
/// when the engine fails; the loading-law series' own errors.
pub fn derive(object: &str, order: usize, options: &[(&str, &str)]) -> Result<Derivation, ApiError> {
    let mut args = vec!["series".to_string(), object.to_string(), "--order".into(), order.to_string()];
    for (key, value) in options {
        if !SERIES_OPTIONS.contains(key) {
            return Err(ModelError::new("option", key, format!("must be one of {}", SERIES_OPTIONS.join(", "))).into());
        }
        args.push(format!("--{}", key.replace('_', "-")));
        args.push(value.to_string());
    }
    args.extend(["--format".to_string(), "json".to_string()]);
    match config(&args, &format!("series {object}"))? {
        RunConfig::Series { object, order, subs, convention, .. } => {
            let parts = object.derive_in(convention, order, &subs)?;
            Ok(Derivation::Exact { object: object.name(), parts })
        }
        RunConfig::LoadingLawSeries { nu, ratio, order, .. } => {
            let digits = crate::asymptotics::catalog::VALUE_DIGITS as u32;
            Ok(Derivation::LoadingLaw(Box::new(crate::asymptotics::loading_law::loading_law_series(
                &nu, &ratio, order, digits,
            )?)))
        }
        RunConfig::AdhesionNumericSeries { nu, order, digits, .. } => Ok(Derivation::AdhesionNumeric(Box::new(
            crate::asymptotics::adhesion_numeric::adhesion_numeric(&nu, order, digits)?,
        ))),
        _ => unreachable!("a `series` command line validates to a series configuration"),
    }
}

/// Options of [`solve_toml`] and [`solve_file`]: the flags of `periodic-contact solve`; `None`
/// leaves the scene's `[output]` (or the CLI's default) in force.
#[derive(Debug, Clone, Default)]
pub struct SolveOptions {
    /// `--digits N` (default: the scene's `digits`, else 30).
    pub digits: Option<u32>,
    /// `--method mpfr|f64|series` (default: the scene's `method`, else `mpfr`).
    pub method: Option<String>,
    /// `--order N`: the series order of `--method series` (default 12).
    pub order: Option<usize>,
    /// `--convention paper|periodic` (default: the scene's, else `paper`).
    pub convention: Option<String>,
}

impl SolveOptions {
    fn flags(&self) -> Vec<String> {
        let mut v = Vec::new();
        let mut push = |flag: &str, value: Option<String>| {
            if let Some(x) = value {
                v.push(flag.to_string());
                v.push(x);
            }
        };
        push("--digits", self.digits.map(|d| d.to_string()));
        push("--method", self.method.clone());
        push("--order", self.order.map(|d| d.to_string()));
        push("--convention", self.convention.clone());
        v
    }
}

/// Solves the scene file at `path` as `periodic-contact solve PATH --json [flags]` does and returns
/// its JSON (string values; keys documented in docs/theory.md section 14).
///
/// # Errors
/// [`ApiError::Scene`] for an invalid scene, [`ApiError::Problem`] otherwise (invalid option, no
/// solution, not physical, no convergence), each with the CLI's message.
pub fn solve_file(path: &Path, options: &SolveOptions) -> Result<Value, ApiError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| ModelError::new("SCENE", path.display(), format!("cannot be read: {e}")))?;
    parse_scene(&text).map_err(ApiError::Scene)?;
    let mut args = vec!["solve".to_string(), path.display().to_string(), "--json".to_string()];
    args.extend(options.flags());
    match config(&args, "solve")? {
        RunConfig::Solve { scene, choice, .. } => {
            // As `periodic-contact solve --json`: the chosen method's answer with its `choice`.
            let (mut v, choice) = crate::solve::choice::solve_chosen(&scene, choice)?;
            if let Some(m) = v.as_object_mut() {
                m.insert("choice".into(), choice.json());
            }
            Ok(v)
        }
        _ => unreachable!("a `solve` command line validates to a solve configuration"),
    }
}

/// Solves a scene given as TOML text (the format of `scenes/*.toml`, documented in
/// [`crate::scene`]) like [`solve_file`]. The text goes through the command line's own path (a
/// private temporary file, removed afterwards), so defaults and messages cannot drift apart.
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
/// let v = solve_toml(scene, &opts)?;
/// // l = 0.0794891890084214444... (`solve scenes/sliding_friction.toml`, MPFR, 34 digits).
/// let l: f64 = v["l"].as_str().unwrap().parse().unwrap();
/// assert!((l - 0.0794891890084214444).abs() < 1e-14 * l);
/// # Ok::<(), periodic_contact::api::ApiError>(())
/// ```
pub fn solve_toml(scene: &str, options: &SolveOptions) -> Result<Value, ApiError> {
    parse_scene(scene).map_err(ApiError::Scene)?;
    static COUNTER: AtomicUsize = AtomicUsize::new(0);
    let path = std::env::temp_dir().join(format!(
        "periodic-contact-api-{}-{}.toml",
        std::process::id(),
        COUNTER.fetch_add(1, Ordering::Relaxed)
    ));
    std::fs::write(&path, scene)
        .map_err(|e| ModelError::new("scene", path.display(), format!("cannot be written: {e}")))?;
    let r = solve_file(&path, options);
    let _ = std::fs::remove_file(&path);
    r
}

/// The CLI's JSON text of a [`Value`] (`serde_json::to_string_pretty`, a newline at the end),
/// byte for byte what `periodic-contact solve ... --json` prints.
pub fn json_text(v: &Value) -> String {
    format!("{}\n", serde_json::to_string_pretty(v).expect("a JSON value always serialises"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unknown_option_names_the_valid_ones() {
        let e = derive("sliding", 4, &[("tehta", "1/10")]).unwrap_err();
        assert_eq!(e.kind(), Some(ErrorKind::Input));
        assert!(e.to_string().starts_with("invalid option = tehta: must be one of theta, xh, T"), "{e}");
    }

    #[test]
    fn invalid_values_carry_the_cli_message() {
        let e = derive("sliding", 4, &[("theta", "1/2")]).unwrap_err();
        assert_eq!(e.to_string(), "invalid --theta = 1/2: must satisfy |theta| < 1/2");
        let e = derive("sliding", 4, &[("shape", "square")]).unwrap_err();
        assert!(e.to_string().contains("invalid value 'square' for '--shape"), "{e}");
        let e = derive("kernel", 100000, &[]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "invalid --order = 100000: must be an integer in [0, 2000] (the kernel series' limit)"
        );
    }

    #[test]
    fn kernel_is_z_cot_z() {
        // z cot z = 1 - z^2/3 - z^4/45 - ... (DLMF 4.19.6).
        let d = derive("kernel", 4, &[]).unwrap();
        let v = d.json();
        let texts: Vec<&str> =
            v["coefficients"].as_array().unwrap().iter().map(|c| c["text"].as_str().unwrap()).collect();
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
