//! Validated, typed configuration built from [`super::args::RawArgs`] before any computation.

use super::args::{
    ConventionName, Format, MethodName, ObjectName, RawArgs, RawCommand, ShapeName, SolveFormat, TemplateName,
    TemplateShape,
};
use crate::asymptotics::catalog::{SeriesObject, Substitutions};
use crate::asymptotics::polynomial::PolynomialProfile;
use crate::asymptotics::sliding::SlidingShape;
use crate::model::{Convention, ModelError};
use crate::scene::{parse::parse_scene, Method, Scene, SceneProblem};
use crate::solve::choice::{solve_choice, Forced, MethodChoice};
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
        /// Also print the Pade approximants (text only, [`crate::asymptotics::pade`]).
        pade: bool,
    },
    /// `series adhesion --nu R --order N [--digits D]` beyond the exact route's order or with
    /// `--digits` (numerical coefficients, [`crate::asymptotics::adhesion_numeric`]).
    AdhesionNumericSeries {
        /// Poisson's ratio.
        nu: Q,
        /// Terms through lambda^order.
        order: usize,
        /// Digits asked.
        digits: u32,
        /// Output format (text or json).
        format: Format,
    },
    /// `series loading-law --nu R --ratio R --order N` (numerical coefficients,
    /// [`crate::asymptotics::loading_law::loading_law_series`]).
    LoadingLawSeries {
        /// Poisson's ratio.
        nu: Q,
        /// n = P1/P2.
        ratio: Q,
        /// Terms through lambda^order.
        order: usize,
        /// Output format (text or json).
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

/// Largest order accepted per object, where the exact derivation still takes seconds (the
/// coefficients of Y grow like order^2 terms each; `series adhesion --order 24`: 3.8 s on a shared
/// 2-core machine, docs/performance.md "Speed of the exact engine"). The adhesion series with `--nu` goes
/// beyond, by its numerical route, up to [`crate::asymptotics::adhesion_numeric::MAX_ORDER`].
pub fn max_order(object: SeriesObject) -> usize {
    match object {
        SeriesObject::Kernel | SeriesObject::Jacobi => 2000,
        SeriesObject::Weight => 80,
        SeriesObject::Sliding(_) => 24,
        SeriesObject::Adhesion => 24,
        SeriesObject::PolynomialSliding | SeriesObject::PolynomialAdhesion => 16,
    }
}

/// What each object's order limit is, as the `--order` error states it (issue 30: the limit of the
/// object and route asked, not another object's).
pub fn order_limit_text(object: SeriesObject) -> &'static str {
    match object {
        SeriesObject::Kernel => "the kernel series' limit",
        SeriesObject::Jacobi => "the Jacobi moments' limit",
        SeriesObject::Weight => "the weight series' limit",
        SeriesObject::Sliding(_) => "the sliding series' limit",
        SeriesObject::Adhesion => {
            "the adhesion series' exact route; with --nu R its numerical route takes orders up to 1000"
        }
        SeriesObject::PolynomialSliding | SeriesObject::PolynomialAdhesion => {
            "the limit of a polynomial profile's series"
        }
    }
}

/// Parses `--order` (an integer in [0, max]); `what` names whose limit `max` is.
pub fn parse_order(text: &str, max: usize, what: &str) -> Result<usize, ModelError> {
    text.trim()
        .parse::<usize>()
        .ok()
        .filter(|&n| n <= max)
        .ok_or_else(|| ModelError::new("--order", text, format!("must be an integer in [0, {max}] ({what})")))
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

/// Parses an exact rational flag.
pub fn parse_exact(flag: &str, text: &str) -> Result<Q, ModelError> {
    parse_rational(text).map_err(|_| {
        ModelError::new(flag, text, "must be an exact number: an integer, a ratio like 1/10, or a decimal like 0.25")
    })
}

/// The polynomial profile of `--coefficients` (`?` = symbolic) or `--degree` (every coefficient
/// symbolic; the adhesion series keeps the even ones only), for the polynomial objects; refused
/// for the others, and required by them.
fn polynomial_profile(
    object: SeriesObject,
    coefficients: Option<&str>,
    degree: Option<&str>,
) -> Result<Option<PolynomialProfile>, ModelError> {
    let polynomial = matches!(object, SeriesObject::PolynomialSliding | SeriesObject::PolynomialAdhesion);
    let even = object == SeriesObject::PolynomialAdhesion;
    let profile = match (coefficients, degree) {
        (Some(_), Some(d)) => return Err(ModelError::new("--degree", d, "give either --coefficients or --degree")),
        (None, None) if polynomial => {
            return Err(ModelError::new("--shape", "polynomial", "needs --coefficients LIST or --degree D"))
        }
        (None, None) => return Ok(None),
        (Some(list), None) => {
            let c = list
                .split(',')
                .map(|item| match item.trim() {
                    "?" => Ok(None),
                    x => parse_rational(x).map(Some).map_err(|_| {
                        ModelError::new(
                            "--coefficients",
                            list,
                            format!("{x:?} is not an exact number (or ? for a symbol)"),
                        )
                    }),
                })
                .collect::<Result<Vec<_>, _>>()?;
            PolynomialProfile::new(c)
        }
        (None, Some(d)) => {
            let n = d.trim().parse::<usize>().map_err(|_| ModelError::new("--degree", d, "must be an integer"))?;
            if even && n % 2 == 1 {
                return Err(ModelError::new(
                    "--degree",
                    d,
                    "the adhesion series needs an even profile: an even degree",
                ));
            }
            let mut p = PolynomialProfile::symbolic(n)?;
            if even {
                let c = p
                    .coefficients()
                    .iter()
                    .enumerate()
                    .map(|(j, c)| if j % 2 == 1 { Some(Q::from_integer(0.into())) } else { c.clone() })
                    .collect();
                p = PolynomialProfile::new(c)?;
            }
            Ok(p)
        }
    }
    .map_err(|e| ModelError { parameter: e.parameter.replace("coefficients", "--coefficients"), ..e })?;
    if !polynomial {
        return Err(ModelError::new(
            if coefficients.is_some() { "--coefficients" } else { "--degree" },
            coefficients.or(degree).unwrap_or_default(),
            "only the sliding series with --shape polynomial and the adhesion series take a polynomial profile",
        ));
    }
    if even && !profile.is_even() {
        return Err(ModelError::new(
            "--coefficients",
            coefficients.unwrap_or_default(),
            "the adhesion series needs an even profile: every odd coefficient 0",
        ));
    }
    Ok(Some(profile))
}

/// The model's convention named on the command line.
fn convention_of(name: ConventionName) -> Convention {
    match name {
        ConventionName::Paper => Convention::Paper,
        ConventionName::Periodic => Convention::PeriodicSurface,
    }
}

/// `--convention` replaces the scene's `[problem] convention` (Problem 1 and the loading-law
/// problem; the symmetric Problem 2 is the same problem in both conventions, so there it changes
/// nothing).
fn override_convention(scene: &mut Scene, name: ConventionName) -> Result<(), ModelError> {
    let c = convention_of(name);
    match &scene.problem {
        SceneProblem::Sliding(p) => scene.problem = SceneProblem::Sliding(p.to_builder().convention(c).build()?),
        SceneProblem::LoadingLaw(p) => {
            scene.problem = SceneProblem::LoadingLaw(crate::scene::rebuild_law(p, p.size().clone(), c)?)
        }
        SceneProblem::Adhesion(_) => {}
    }
    Ok(())
}

/// The flags of `series loading-law`.
struct LawFlags<'a> {
    order: &'a str,
    nu: Option<&'a str>,
    ratio: Option<&'a str>,
    /// Flags the loading-law series does not take, with their values.
    refused: Vec<(&'static str, String)>,
    shape: ShapeName,
    convention: Option<ConventionName>,
    format: Format,
}

/// Validates `series loading-law`: --nu in [0, 1/2] and --ratio >= 0 required (exact), the
/// order, text or json, the paper convention and parabola only.
fn loading_law_series(f: LawFlags) -> Result<RunConfig, ModelError> {
    use crate::asymptotics::loading_law::MAX_ORDER;
    if let Some((flag, value)) = f.refused.first() {
        return Err(ModelError::new(
            *flag,
            value,
            "the loading-law series takes only --nu, --ratio, --order, --format",
        ));
    }
    if f.shape != ShapeName::Parabolic {
        return Err(ModelError::new(
            "--shape",
            format!("{:?}", f.shape).to_lowercase(),
            "the loading-law series is for the parabola",
        ));
    }
    if let Some(ConventionName::Periodic) = f.convention {
        return Err(ModelError::new(
            "--convention",
            "periodic",
            "the loading-law series is derived in the paper convention only",
        ));
    }
    if !matches!(f.format, Format::Text | Format::Json) {
        return Err(ModelError::new(
            "--format",
            format!("{:?}", f.format).to_lowercase(),
            "the loading-law series prints text or json (its coefficients are numbers)",
        ));
    }
    let nu = parse_exact(
        "--nu",
        f.nu.ok_or_else(|| {
            ModelError::new("--nu", "(missing)", "the loading-law series needs Poisson's ratio --nu R in [0, 1/2]")
        })?,
    )?;
    if nu.is_negative() || nu > Q::new(1.into(), 2.into()) {
        return Err(ModelError::new("--nu", &nu, "must lie in [0, 1/2]"));
    }
    let ratio = parse_exact(
        "--ratio",
        f.ratio.ok_or_else(|| {
            ModelError::new("--ratio", "(missing)", "the loading-law series needs n = P1/P2 >= 0: --ratio R")
        })?,
    )?;
    if ratio.is_negative() {
        return Err(ModelError::new(
            "--ratio",
            &ratio,
            "must be >= 0 (n = P1/P2 with N' >= 0; the mirror image x -> -x gives n < 0)",
        ));
    }
    let order = parse_order(f.order, MAX_ORDER, "the loading-law series' limit")?;
    Ok(RunConfig::LoadingLawSeries { nu, ratio, order, format: f.format })
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
                if pade && object == ObjectName::LoadingLaw {
                    return Err(ModelError::new(
                        "--pade",
                        "with loading-law",
                        "the Pade approximants are built for kernel, weight, sliding and adhesion",
                    ));
                }
                if object == ObjectName::LoadingLaw {
                    let given = [("--theta", &theta), ("--xh", &xh), ("--T", &t), ("--coefficients", &coefficients)];
                    let more = [("--degree", &degree), ("--rbar-s", &rbar_s), ("--digits", &digits)];
                    return loading_law_series(LawFlags {
                        order: &order,
                        nu: nu.as_deref(),
                        ratio: ratio.as_deref(),
                        refused: given
                            .into_iter()
                            .chain(more)
                            .filter_map(|(k, v)| v.as_ref().map(|v| (k, v.clone())))
                            .collect(),
                        shape,
                        convention,
                        format,
                    });
                }
                if let Some(r) = &ratio {
                    return Err(ModelError::new("--ratio", r, "only the loading-law series takes a ratio"));
                }
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
                    ObjectName::Adhesion if coefficients.is_some() || degree.is_some() => {
                        SeriesObject::PolynomialAdhesion
                    }
                    ObjectName::Adhesion => SeriesObject::Adhesion,
                    ObjectName::LoadingLaw => unreachable!("series loading-law returned above"),
                    ObjectName::Sliding => match shape {
                        ShapeName::Parabolic => SeriesObject::Sliding(SlidingShape::Parabolic),
                        ShapeName::Sinusoidal => SeriesObject::Sliding(SlidingShape::Sinusoidal),
                        ShapeName::Polynomial => SeriesObject::PolynomialSliding,
                    },
                };
                let profile = polynomial_profile(object, coefficients.as_deref(), degree.as_deref())?;
                let rbar_s = rbar_s.map(|v| parse_exact("--rbar-s", &v)).transpose()?;
                if let (Some(v), false) = (&rbar_s, object == SeriesObject::PolynomialSliding) {
                    return Err(ModelError::new(
                        "--rbar-s",
                        v,
                        "only the sliding series with --shape polynomial has rbar_s",
                    ));
                }
                // The adhesion series with --nu takes any order up to the numerical route's cap.
                let numeric_possible = object == SeriesObject::Adhesion && nu.is_some();
                let order = if numeric_possible {
                    parse_order(
                        &order,
                        crate::asymptotics::adhesion_numeric::MAX_ORDER,
                        "the adhesion series at --nu: exact in symbols up to 24, by the numerical route beyond",
                    )?
                } else {
                    parse_order(&order, max_order(object), order_limit_text(object))?
                };
                let digits =
                    digits
                        .map(|d| {
                            let max = crate::asymptotics::adhesion_numeric::MAX_DIGITS;
                            d.trim().parse::<u32>().ok().filter(|v| (1..=max).contains(v)).ok_or_else(|| {
                                ModelError::new("--digits", &d, format!("must be an integer in [1, {max}]"))
                            })
                        })
                        .transpose()?;
                if let (Some(d), false) = (digits, numeric_possible) {
                    return Err(ModelError::new(
                        "--digits",
                        d,
                        "only the adhesion series with --nu R (its numerical route) takes digits",
                    ));
                }
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
                        return Err(ModelError::new(
                            "--nu",
                            v,
                            "only the adhesion series of the parabola takes nu (a polynomial profile keeps symbols)",
                        ));
                    }
                }
                if let (Some(v), true) = (&nu, order > max_order(object) || digits.is_some()) {
                    if !matches!(format, Format::Text | Format::Json) {
                        return Err(ModelError::new(
                            "--format",
                            format!("{format:?}").to_lowercase(),
                            format!(
                                "the numerical route of the adhesion series (order > {} or --digits) prints text or json (its coefficients are numbers)",
                                max_order(object)
                            ),
                        ));
                    }
                    if pade {
                        return Err(ModelError::new(
                            "--pade",
                            "given",
                            format!(
                                "the Pade approximants are built by the exact route (order <= {}, no --digits); drop --pade or \
                                 lower --order",
                                max_order(object)
                            ),
                        ));
                    }
                    let digits = digits.unwrap_or(crate::asymptotics::catalog::VALUE_DIGITS as u32);
                    return Ok(RunConfig::AdhesionNumericSeries { nu: v.clone(), order, digits, format });
                }
                let subs = Substitutions { theta, xh, t, nu, rbar_s, profile };
                Ok(RunConfig::Series { object, order, subs, convention, format, pade })
            }
            RawCommand::Solve { scene, digits, method, order, convention, format, json } => {
                let text = std::fs::read_to_string(&scene)
                    .map_err(|e| ModelError::new("SCENE", scene.display(), format!("cannot be read: {e}")))?;
                let mut parsed = parse_scene(&text)?;
                if let Some(c) = convention {
                    override_convention(&mut parsed, c)?;
                }
                let digits = match digits {
                    Some(d) => Some(
                        d.trim()
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
                    ),
                    None => None,
                };
                let method = method.map(|m| match m {
                    MethodName::Mpfr => Method::Mpfr,
                    MethodName::F64 => Method::F64,
                    MethodName::Series => Method::Series,
                    MethodName::Pade => Method::Pade,
                });
                let series_order = order
                    .map(|o| {
                        parse_order(&o, crate::scene::keys::MAX_SERIES_ORDER, "the series and pade methods' limit")
                    })
                    .transpose()?;
                let forced = Forced { method, digits, series_order };
                let choice = solve_choice(&parsed, forced)
                    .map_err(|e| ModelError::new("calibration/methods.csv", "(compiled in)", e.to_string()))?;
                let format = if json || format == Some(SolveFormat::Json) { Format::Json } else { Format::Text };
                Ok(RunConfig::Solve { scene: Box::new(parsed), choice, format })
            }
            RawCommand::Report { out, scenes, order, fast, jobs } => {
                let order = parse_order(&order, 40, "the report's coefficient tables")?;
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

/// `scene --template KIND --shape SHAPE [--law]` ([`crate::scene::keys::template`]).
fn scene_template(template: TemplateName, shape: TemplateShape, law: bool) -> Result<RunConfig, ModelError> {
    use crate::scene::keys::{template as make, Kind};
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

    fn config(args: &[&str]) -> Result<RunConfig, String> {
        let raw = RawArgs::try_parse_from(std::iter::once("periodic-contact").chain(args.iter().copied()))
            .map_err(|e| e.to_string())?;
        RunConfig::from_args(raw).map_err(|e| e.to_string())
    }

    /// Issue 30: one canonical name per shape, its one alias accepted by `scene --shape`,
    /// `series --shape` and the scene's `[punch] shape` alike, and both stated in the help.
    #[test]
    fn shape_names_and_aliases_agree_everywhere() {
        use crate::scene::keys::{canonical_shape, SHAPES, SHAPE_ALIASES};
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
            assert!(matches!(config(&["series", "sliding", "--order", "2", "--shape", alias]), Ok(_)), "{alias}");
        }
        let mut cmd = RawArgs::command();
        for sub in ["scene", "series"] {
            let help = cmd.find_subcommand_mut(sub).unwrap().render_long_help().to_string();
            for (alias, canonical) in SHAPE_ALIASES.iter().take(3) {
                assert!(help.contains(canonical) && help.contains(&format!("alias: {alias}")), "{sub}: {help}");
            }
        }
    }

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
            (vec!["series", "adhesion"], 24, "numerical route takes orders up to 1000"),
            (vec!["series", "adhesion", "--nu", "0"], 1000, "exact in symbols up to 24"),
            (vec!["series", "loading-law", "--nu", "0", "--ratio", "1"], 24, "loading-law"),
            (vec!["solve", "scenes/kuznetsov_parabola.toml", "--method", "series"], 24, "series and pade"),
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
        assert_eq!(crate::asymptotics::loading_law::MAX_ORDER, 24);
        assert_eq!(crate::asymptotics::adhesion_numeric::MAX_ORDER, 1000);
        let mut cmd = RawArgs::command();
        let help = cmd.find_subcommand_mut("series").unwrap().render_long_help().to_string();
        let flat = help.split_whitespace().collect::<Vec<_>>().join(" ");
        assert!(
            flat.contains("kernel, jacobi 2000; weight 80; sliding, adhesion, loading-law 24; a polynomial profile 16; adhesion --nu R 1000"),
            "{flat}"
        );
    }
}
