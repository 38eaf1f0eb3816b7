//! Validated, typed configuration built from [`super::args::RawArgs`] before any computation.

use super::args::{ConventionName, Format, MethodName, ObjectName, RawArgs, RawCommand, ShapeName};
use crate::asymptotics::catalog::{SeriesObject, Substitutions};
use crate::asymptotics::sliding::SlidingShape;
use crate::model::{Convention, ModelError};
use crate::scene::{parse::parse_scene, Method, Scene, SceneProblem};
use crate::solve::{SolveRequest, DEFAULT_DIGITS};
use exact_series::{parse_rational, Q};
use num_traits::Signed;
use std::path::PathBuf;

/// A validated run.
#[derive(Debug, Clone)]
pub enum RunConfig {
    /// `series OBJECT --order N ...`
    Series {
        /// The object.
        object: SeriesObject,
        /// Terms through power `order`.
        order: usize,
        /// Exact substitutions.
        subs: Substitutions,
        /// Surface convention (sliding only).
        convention: Convention,
        /// Output format.
        format: Format,
    },
    /// `solve SCENE`
    Solve {
        /// The parsed scene.
        scene: Box<Scene>,
        /// Method, digits, series order.
        request: SolveRequest,
        /// Output format.
        format: Format,
    },
    /// `report --out DIR --scenes DIR`
    Report {
        /// Output folder.
        out: PathBuf,
        /// Scene folder.
        scenes: PathBuf,
        /// Order of the coefficient tables.
        order: usize,
        /// Small grids.
        fast: bool,
    },
    /// `calibrate --out FILE`
    Calibrate {
        /// Output file.
        out: PathBuf,
    },
}

/// Largest order accepted per object: beyond it the exact derivation takes minutes (the
/// coefficients of Y grow like order^2 terms each).
pub fn max_order(object: SeriesObject) -> usize {
    match object {
        SeriesObject::Kernel | SeriesObject::Jacobi => 2000,
        SeriesObject::Weight => 80,
        SeriesObject::Sliding(_) => 24,
        SeriesObject::Adhesion => 16,
    }
}

/// Parses `--order` (an integer in [0, max]).
pub fn parse_order(text: &str, max: usize) -> Result<usize, ModelError> {
    text.trim()
        .parse::<usize>()
        .ok()
        .filter(|&n| n <= max)
        .ok_or_else(|| ModelError::new("--order", text, format!("must be an integer in [0, {max}]")))
}

/// Parses an exact rational flag.
pub fn parse_exact(flag: &str, text: &str) -> Result<Q, ModelError> {
    parse_rational(text).map_err(|_| {
        ModelError::new(flag, text, "must be an exact number: an integer, a ratio like 1/10, or a decimal like 0.25")
    })
}

/// The model's convention named on the command line.
fn convention_of(name: ConventionName) -> Convention {
    match name {
        ConventionName::Paper => Convention::Paper,
        ConventionName::Periodic => Convention::PeriodicSurface,
    }
}

/// `--convention` replaces the scene's `[problem] convention` (Problem 1; Problem 2 is the same
/// problem in both conventions, so there it changes nothing).
fn override_convention(scene: &mut Scene, name: ConventionName) -> Result<(), ModelError> {
    let c = convention_of(name);
    if let SceneProblem::Sliding(p) = &scene.problem {
        scene.problem = SceneProblem::Sliding(p.to_builder().convention(c).build()?);
    }
    Ok(())
}

impl RunConfig {
    /// Validates raw arguments.
    pub fn from_args(args: RawArgs) -> Result<RunConfig, ModelError> {
        match args.command {
            RawCommand::Series { object, order, theta, xh, t, nu, shape, convention, format } => {
                if let (Some(c), false) = (convention, object == ObjectName::Sliding) {
                    return Err(ModelError::new(
                        "--convention",
                        format!("{c:?}").to_lowercase(),
                        "only the sliding series has a surface convention",
                    ));
                }
                let convention = convention.map_or(Convention::Paper, convention_of);
                let object = match object {
                    ObjectName::Kernel => SeriesObject::Kernel,
                    ObjectName::Weight => SeriesObject::Weight,
                    ObjectName::Jacobi => SeriesObject::Jacobi,
                    ObjectName::Adhesion => SeriesObject::Adhesion,
                    ObjectName::Sliding => SeriesObject::Sliding(match shape {
                        ShapeName::Parabolic => SlidingShape::Parabolic,
                        ShapeName::Sinusoidal => SlidingShape::Sinusoidal,
                    }),
                };
                let order = parse_order(&order, max_order(object))?;
                let theta = theta.map(|t| parse_exact("--theta", &t)).transpose()?;
                if let Some(t) = &theta {
                    if t.abs() >= Q::new(1.into(), 2.into()) {
                        return Err(ModelError::new("--theta", t, "must satisfy |theta| < 1/2"));
                    }
                    if object == SeriesObject::Kernel {
                        return Err(ModelError::new("--theta", t, "the kernel has no theta"));
                    }
                }
                let xh = xh.map(|t| parse_exact("--xh", &t)).transpose()?;
                if let Some(x) = &xh {
                    if x.abs() > Q::from_integer(1.into()) {
                        return Err(ModelError::new("--xh", x, "must lie in [-1, 1]"));
                    }
                    if !matches!(object, SeriesObject::Weight | SeriesObject::Sliding(_)) {
                        return Err(ModelError::new("--xh", x, "only the weight and sliding series have xh"));
                    }
                }
                let t = t.map(|v| parse_exact("--T", &v)).transpose()?;
                if let Some(v) = &t {
                    if v.is_negative() {
                        return Err(ModelError::new("--T", v, "must be >= 0 (T = beta tau0/(E* k l_s))"));
                    }
                    if !matches!(object, SeriesObject::Sliding(_)) {
                        return Err(ModelError::new("--T", v, "only the sliding series has T"));
                    }
                }
                let nu = nu.map(|v| parse_exact("--nu", &v)).transpose()?;
                if let Some(v) = &nu {
                    if v.is_negative() || *v > Q::new(1.into(), 2.into()) {
                        return Err(ModelError::new("--nu", v, "must lie in [0, 1/2]"));
                    }
                    if object != SeriesObject::Adhesion {
                        return Err(ModelError::new("--nu", v, "only the adhesion series takes nu"));
                    }
                }
                Ok(RunConfig::Series { object, order, subs: Substitutions { theta, xh, t, nu }, convention, format })
            }
            RawCommand::Solve { scene, digits, method, order, convention, format, json } => {
                let text = std::fs::read_to_string(&scene)
                    .map_err(|e| ModelError::new("SCENE", scene.display(), format!("cannot be read: {e}")))?;
                let mut parsed = parse_scene(&text)?;
                if let Some(c) = convention {
                    override_convention(&mut parsed, c)?;
                }
                let digits = match digits {
                    Some(d) => d
                        .trim()
                        .parse::<u32>()
                        .ok()
                        .filter(|d| (1..=crate::scene::parse::MAX_DIGITS).contains(d))
                        .ok_or_else(|| {
                            ModelError::new(
                                "--digits",
                                &d,
                                format!("must be an integer in [1, {}]", crate::scene::parse::MAX_DIGITS),
                            )
                        })?,
                    None => parsed.output.digits.unwrap_or(DEFAULT_DIGITS),
                };
                let method = match method {
                    Some(MethodName::Mpfr) => Method::Mpfr,
                    Some(MethodName::F64) => Method::F64,
                    Some(MethodName::Series) => Method::Series,
                    None => parsed.output.method.unwrap_or(Method::Mpfr),
                };
                let series_order = match order {
                    Some(o) => parse_order(&o, 24)?,
                    None => parsed.output.series_order.unwrap_or(12),
                };
                let format = if json { Format::Json } else { format.unwrap_or(Format::Text) };
                if format == Format::Latex {
                    return Err(ModelError::new("--format", "latex", "solve prints text or json"));
                }
                Ok(RunConfig::Solve {
                    scene: Box::new(parsed),
                    request: SolveRequest { method, digits, series_order },
                    format,
                })
            }
            RawCommand::Report { out, scenes, order, fast } => {
                let order = parse_order(&order, 40)?;
                if !scenes.is_dir() {
                    return Err(ModelError::new("--scenes", scenes.display(), "must be a folder of *.toml scenes"));
                }
                Ok(RunConfig::Report { out, scenes, order, fast })
            }
            RawCommand::Calibrate { out } => Ok(RunConfig::Calibrate { out }),
        }
    }
}
