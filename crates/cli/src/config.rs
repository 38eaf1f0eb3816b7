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
use periodic_contact::series_request::{order_limit, parse_order, SeriesRequest, ValidSeries};
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
    /// The directories this run writes files into (the report's folder, the calibration file's):
    /// where an interrupted run's temporary files are looked for.
    pub fn output_dirs(&self) -> Vec<PathBuf> {
        match self {
            RunConfig::Report { out, .. } => vec![out.clone()],
            RunConfig::Calibrate { out } => {
                vec![out
                    .parent()
                    .filter(|d| !d.as_os_str().is_empty())
                    .map_or_else(|| PathBuf::from("."), PathBuf::from)]
            }
            _ => vec![],
        }
    }

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
                            MethodName::Analytic => "analytic",
                        }
                        .to_string()
                    }),
                    order: order
                        .map(|o| {
                            parse_order("--order", &o, periodic_contact::scene::keys::MAX_SERIES_ORDER)
                                .map_err(|e| order_limit(e, "the series and pade methods' limit"))
                        })
                        .transpose()?,
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
                let order = parse_order("--order", &order, 40)
                    .map_err(|e| order_limit(e, "the report's coefficient tables"))?;
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

#[cfg(test)]
mod tests {
    use super::*;
    use clap::{CommandFactory, Parser, ValueEnum};
    use periodic_contact::asymptotics::catalog::SeriesObject;
    use periodic_contact::series_request::max_order;

    fn config(args: &[&str]) -> Result<RunConfig, String> {
        let raw = RawArgs::try_parse_from(std::iter::once("periodic-contact").chain(args.iter().copied()))
            .map_err(|e| e.to_string())?;
        RunConfig::from_args(raw).map_err(|e| e.to_string())
    }

    /// Issue 30: one canonical name per shape, its one alias accepted by `scene --shape`,
    /// `series --shape` and the scene's `[punch] shape` alike, and both stated in the help.
    #[test]
    fn shape_names_and_aliases_agree_everywhere() {
        use periodic_contact::scene::keys::{canonical_shape, SHAPES, SHAPE_ALIASES};
        for (alias, canonical) in SHAPE_ALIASES {
            assert!(SHAPES.contains(&canonical) && canonical_shape(alias) == canonical);
            let t = TemplateShape::from_str(alias, false).unwrap();
            assert_eq!(t.to_possible_value().unwrap().get_name(), canonical, "{alias}");
            assert!(t.to_possible_value().unwrap().matches(alias, false));
            if let Ok(s) = ShapeName::from_str(alias, false) {
                assert_eq!(s.to_possible_value().unwrap().get_name(), canonical, "{alias}");
            } else {
                assert_eq!(canonical, "circular", "series --shape lacks {alias}");
            }
        }
        for shape in SHAPES {
            assert_eq!(canonical_shape(shape), shape);
        }
        // Both names give the same template; the help names each alias.
        for (alias, canonical) in [("parabola", "parabolic"), ("sinusoid", "sinusoidal")] {
            let text = |s: &str| match config(&["scene", "--template", "sliding", "--shape", s]).unwrap() {
                RunConfig::SceneTemplate { text } => text,
                other => panic!("{other:?}"),
            };
            assert_eq!(text(alias), text(canonical));
            assert!(config(&["series", "sliding", "--order", "2", "--shape", alias]).is_ok(), "{alias}");
        }
        let mut cmd = RawArgs::command();
        for sub in ["scene", "series"] {
            let help = cmd.find_subcommand_mut(sub).unwrap().render_long_help().to_string();
            for (alias, canonical) in SHAPE_ALIASES.iter().take(3) {
                assert!(help.contains(canonical) && help.contains(&format!("alias: {alias}")), "{sub}: {help}");
            }
        }
    }

    const KUZNETSOV: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../scenes/kuznetsov_parabola.toml");

    /// Issue 30: `--order` states the limit of the object and the route asked, and the help's
    /// list of limits is the one the parser checks.
    #[test]
    fn order_errors_state_the_limit_of_the_object_and_route() {
        for (args, max, what) in [
            (vec!["series", "kernel"], 2000, "kernel"),
            (vec!["series", "jacobi"], 2000, "Jacobi"),
            (vec!["series", "weight"], 80, "weight"),
            (vec!["series", "sliding"], 24, "sliding"),
            (vec!["series", "sliding", "--shape", "polynomial", "--degree", "4"], 16, "polynomial"),
            (vec!["series", "adhesion"], 24, "the numerical route takes up to 1000"),
            (vec!["series", "adhesion", "--nu", "0"], 1000, "exact in symbols up to 24"),
            (vec!["series", "loading-law", "--nu", "0", "--ratio", "1"], 24, "loading-law"),
            (vec!["solve", KUZNETSOV, "--method", "series"], 24, "series and pade"),
        ] {
            let mut a = args.clone();
            a.extend(["--order", "abc"]);
            let e = config(&a).unwrap_err();
            assert!(e.contains(&format!("must be an integer in [0, {max}]")) && e.contains(what), "{a:?}: {e}");
        }
        for (object, max) in [
            (SeriesObject::Kernel, 2000),
            (SeriesObject::Jacobi, 2000),
            (SeriesObject::Weight, 80),
            (SeriesObject::Adhesion, 24),
            (SeriesObject::PolynomialSliding, 16),
        ] {
            assert_eq!(max_order(object), max);
        }
        assert_eq!(periodic_contact::asymptotics::loading_law::MAX_ORDER, 24);
        assert_eq!(periodic_contact::asymptotics::adhesion_numeric::MAX_ORDER, 1000);
        let mut cmd = RawArgs::command();
        let help = cmd.find_subcommand_mut("series").unwrap().render_long_help().to_string();
        let flat = help.split_whitespace().collect::<Vec<_>>().join(" ");
        assert!(
            flat.contains("kernel, jacobi 2000; weight 80; sliding, adhesion, loading-law 24; a polynomial profile 16; adhesion --nu R 1000"),
            "{flat}"
        );
    }
}
