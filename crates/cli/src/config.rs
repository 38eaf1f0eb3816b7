//! Validated, typed configuration built from [`super::args::RawArgs`] before any computation: the
//! command line's flags become the library's requests ([`SeriesRequest`], [`SolveOptions`]),
//! validated by the library with its messages; only what is the command line's own (the output
//! format, files, threads) is checked here.

use super::args::{
    ConventionName, Format, MethodName, ObjectName, RawArgs, RawCommand, ShapeName, SolveFormat, TemplateName,
    TemplateShape,
};
use periodic_contact::api::SolveOptions;
use periodic_contact::model::ModelError;
use periodic_contact::scene::{parse::parse_scene, Scene};
use periodic_contact::series_request::{parse_order, SeriesRequest, ValidSeries};
use periodic_contact::solve::choice::MethodChoice;
use std::path::PathBuf;

/// A validated run.
#[derive(Debug, Clone)]
pub enum RunConfig {
    /// `series OBJECT --order N ...`: the validated request (exact route, the adhesion series'
    /// numerical route, or the loading law).
    Series {
        /// What to derive.
        valid: Box<ValidSeries>,
        /// Output format (the numerical routes: text or json).
        format: Format,
    },
    /// `solve SCENE`
    Solve {
        /// The parsed scene.
        scene: Box<Scene>,
        /// Method, digits, series order, and why.
        choice: MethodChoice,
        /// Output format.
        format: Format,
    },
    /// `scene --template KIND --shape SHAPE [--law]`: the commented scene, ready to print.
    SceneTemplate {
        /// The TOML text.
        text: String,
    },
    /// `completions SHELL`: the completion script of the shell.
    Completions {
        /// The shell.
        shell: clap_complete::Shell,
    },
    /// `man`: the man page.
    Man,
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
        /// Threads (`None`: one per logical CPU).
        jobs: Option<usize>,
    },
    /// `calibrate --out FILE`
    Calibrate {
        /// Output file.
        out: PathBuf,
    },
}

/// Largest `report --jobs`.
pub const MAX_JOBS: usize = 256;

/// Parses `report --jobs N`: an integer in [1, MAX_JOBS].
pub fn parse_jobs(text: &str) -> Result<usize, ModelError> {
    text.trim()
        .parse::<usize>()
        .ok()
        .filter(|n| (1..=MAX_JOBS).contains(n))
        .ok_or_else(|| ModelError::new("--jobs", text, format!("must be an integer in [1, {MAX_JOBS}]")))
}

impl RunConfig {
    /// Validates raw arguments.
    pub fn from_args(args: RawArgs) -> Result<RunConfig, ModelError> {
        match args.command {
            RawCommand::Series {
                object,
                order,
                theta,
                xh,
                t,
                nu,
                digits,
                ratio,
                shape,
                coefficients,
                degree,
                rbar_s,
                convention,
                format,
                pade,
            } => {
                if pade && format != Format::Text {
                    return Err(ModelError::new(
                        "--pade",
                        format!("with --format {}", format!("{format:?}").to_lowercase()),
                        "the Pade approximants are printed as text only: drop --format or --pade",
                    ));
                }
                let mut request =
                    SeriesRequest { object: object_name(object).into(), order, pade, ..Default::default() };
                let shape = shape.map(|s| match s {
                    ShapeName::Parabolic => "parabolic".to_string(),
                    ShapeName::Sinusoidal => "sinusoidal".to_string(),
                    ShapeName::Polynomial => "polynomial".to_string(),
                });
                let convention = convention.map(|c| convention_name(c).to_string());
                for (name, value) in [
                    ("theta", theta),
                    ("xh", xh),
                    ("T", t),
                    ("nu", nu),
                    ("digits", digits),
                    ("ratio", ratio),
                    ("shape", shape),
                    ("coefficients", coefficients),
                    ("degree", degree),
                    ("rbar_s", rbar_s),
                    ("convention", convention),
                ] {
                    if let Some(v) = value {
                        request.options.push((name.to_string(), v));
                    }
                }
                let valid = request.validate()?;
                // The numerical routes print numbers: text or json.
                let numeric = match &valid {
                    ValidSeries::Exact { .. } => None,
                    ValidSeries::LoadingLaw { .. } => {
                        Some("the loading-law series prints text or json (its coefficients are numbers)".to_string())
                    }
                    ValidSeries::AdhesionNumeric { .. } => Some(format!(
                        "the numerical route of the adhesion series (order > {} or --digits) prints text or json (its \
                         coefficients are numbers)",
                        periodic_contact::series_request::max_order(
                            periodic_contact::asymptotics::catalog::SeriesObject::Adhesion
                        )
                    )),
                };
                if let (Some(why), false) = (numeric, matches!(format, Format::Text | Format::Json)) {
                    return Err(ModelError::new("--format", format!("{format:?}").to_lowercase(), why));
                }
                Ok(RunConfig::Series { valid: Box::new(valid), format })
            }
            RawCommand::Solve { scene, digits, method, order, convention, format, json } => {
                let text = std::fs::read_to_string(&scene)
                    .map_err(|e| ModelError::new("SCENE", scene.display(), format!("cannot be read: {e}")))?;
                let mut parsed = parse_scene(&text)?;
                let max = periodic_contact::scene::parse::MAX_DIGITS;
                let digits =
                    digits
                        .map(|d| {
                            d.trim().parse::<u32>().ok().filter(|v| (1..=max).contains(v)).ok_or_else(|| {
                                ModelError::new("--digits", &d, format!("must be an integer in [1, {max}]"))
                            })
                        })
                        .transpose()?;
                let options = SolveOptions {
                    digits,
                    method: method.map(|m| {
                        match m {
                            MethodName::Mpfr => "mpfr",
                            MethodName::F64 => "f64",
                            MethodName::Series => "series",
                            MethodName::Pade => "pade",
                        }
                        .to_string()
                    }),
                    order: order.map(|o| parse_order("--order", &o, 24)).transpose()?,
                    convention: convention.map(|c| convention_name(c).to_string()),
                };
                let choice = options.choose(&mut parsed).map_err(|e| match e {
                    periodic_contact::error::Error::Input(m) => m,
                    other => ModelError::new("solve", "", other.to_string()),
                })?;
                let format = if json || format == Some(SolveFormat::Json) { Format::Json } else { Format::Text };
                Ok(RunConfig::Solve { scene: Box::new(parsed), choice, format })
            }
            RawCommand::Report { out, scenes, order, fast, jobs } => {
                let order = parse_order("--order", &order, 40)?;
                if !scenes.is_dir() {
                    return Err(ModelError::new("--scenes", scenes.display(), "must be a folder of *.toml scenes"));
                }
                let jobs = jobs.map(|j| parse_jobs(&j)).transpose()?;
                Ok(RunConfig::Report { out, scenes, order, fast, jobs })
            }
            RawCommand::Calibrate { out } => Ok(RunConfig::Calibrate { out }),
            RawCommand::Scene { template, shape, law } => scene_template(template, shape, law),
            RawCommand::Completions { shell } => Ok(RunConfig::Completions { shell }),
            RawCommand::Man => Ok(RunConfig::Man),
        }
    }
}

/// The library's name of a series object.
fn object_name(o: ObjectName) -> &'static str {
    match o {
        ObjectName::Kernel => "kernel",
        ObjectName::Weight => "weight",
        ObjectName::Jacobi => "jacobi",
        ObjectName::Sliding => "sliding",
        ObjectName::Adhesion => "adhesion",
        ObjectName::LoadingLaw => "loading-law",
    }
}

/// The library's name of a convention.
fn convention_name(c: ConventionName) -> &'static str {
    match c {
        ConventionName::Paper => "paper",
        ConventionName::Periodic => "periodic",
    }
}

/// `scene --template KIND --shape SHAPE [--law]` ([`periodic_contact::scene::keys::template`]).
fn scene_template(template: TemplateName, shape: TemplateShape, law: bool) -> Result<RunConfig, ModelError> {
    use periodic_contact::scene::keys::{template as make, Kind};
    let kind = match (template, law) {
        (TemplateName::Sliding, true) => {
            return Err(ModelError::new(
                "--law",
                "(present)",
                "a loading law is a Problem 2 setting: --template adhesion --law",
            ))
        }
        (TemplateName::Sliding, false) => Kind::Sliding,
        (TemplateName::Adhesion, false) => Kind::Adhesion,
        (TemplateName::Adhesion, true) => Kind::Law,
    };
    let shape = match shape {
        TemplateShape::Parabolic => "parabolic",
        TemplateShape::Sinusoidal => "sinusoidal",
        TemplateShape::Polynomial => "polynomial",
        TemplateShape::Circular => "circular",
    };
    let text = make(kind, shape).map_err(|e| ModelError::new(e.parameter, e.value, e.expected))?;
    Ok(RunConfig::SceneTemplate { text })
}
