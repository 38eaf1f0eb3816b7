//! What `derive` is asked (docs/theory.md sections 5, 10, 16): a [`SeriesRequest`] names an object,
//! an order and exact options as text, and [`SeriesRequest::validate`] turns it, once, into a
//! [`ValidSeries`]: the exact route (an object of [`crate::asymptotics::catalog`] with its
//! substitutions), the numerical route of the adhesion series at given nu
//! ([`crate::asymptotics::adhesion_numeric`]) or the loading-law series
//! ([`crate::asymptotics::loading_law`]). [`OPTIONS`] is the one table of which options each
//! object takes; the command line, the Rust front door and Python all validate here, with the
//! command line's messages (options named as its flags, `--theta`). Tests: below, and the CLI's
//! tests of every refusal (`tests/all/series_objects.rs`, `tests/all/cli.rs`).

mod profile;

use crate::asymptotics::catalog::{SeriesObject, Substitutions};
use crate::asymptotics::sliding::SlidingShape;
use crate::model::{Convention, ModelError};
use exact_series::{parse_rational, Q};
use num_traits::Signed;
use profile::polynomial_profile;

/// The objects `derive` knows, by the command line's names.
pub const OBJECTS: [&str; 6] = ["kernel", "weight", "jacobi", "sliding", "adhesion", "loading-law"];

/// Which options each object takes (option names as [`SeriesRequest::options`] keys; `order` is
/// always required). `adhesion` takes `digits` only with `nu` (its numerical route); `sliding`
/// takes `coefficients`, `degree` and `rbar_s` only with `shape = polynomial`, `adhesion` takes
/// `coefficients` or `degree` (an even polynomial profile, kept exact) instead of `nu`;
/// `loading-law` takes `shape = parabolic` and `convention = paper` only.
pub const OPTIONS: [(&str, &[&str]); 6] = [
    ("kernel", &[]),
    ("weight", &["theta", "xh"]),
    ("jacobi", &["theta"]),
    ("sliding", &["theta", "xh", "T", "shape", "coefficients", "degree", "rbar_s", "convention"]),
    ("adhesion", &["nu", "digits", "coefficients", "degree"]),
    ("loading-law", &["nu", "ratio", "shape", "convention"]),
];

/// Every option name (the command line's flags without dashes, `rbar_s` for `--rbar-s`).
pub const OPTION_NAMES: [&str; 11] =
    ["theta", "xh", "T", "nu", "digits", "ratio", "shape", "coefficients", "degree", "rbar_s", "convention"];

/// A request to derive a series: `object` through power `order`, with exact options as text
/// (`("theta", "1/10")`, `("coefficients", "0,0,1,0,1/10")`, `("shape", "sinusoidal")`).
///
/// ```
/// use periodic_contact::series_request::{SeriesRequest, ValidSeries};
/// let r = SeriesRequest::new("sliding", 4).option("theta", "1/10");
/// assert!(matches!(r.validate()?, ValidSeries::Exact { order: 4, .. }));
/// # Ok::<(), periodic_contact::model::ModelError>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct SeriesRequest {
    /// One of [`OBJECTS`].
    pub object: String,
    /// The order as given (an integer; text so that a command line's `--order abc` is refused
    /// with the same message as a number out of range).
    pub order: String,
    /// `(name, value)` pairs, names from [`OPTION_NAMES`], values exact as text.
    pub options: Vec<(String, String)>,
    /// Also build the Pade approximants (the exact route only).
    pub pade: bool,
}

/// A validated request: which route derives it, with exact inputs.
#[derive(Debug, Clone)]
pub enum ValidSeries {
    /// The exact objects (kernel, weight, jacobi, sliding, adhesion): coefficients in Q,
    /// Q\[symbols\] or its fraction field.
    Exact {
        /// The object.
        object: SeriesObject,
        /// Terms through power `order`.
        order: usize,
        /// Exact substitutions.
        subs: Box<Substitutions>,
        /// Surface convention (sliding only; `paper` otherwise).
        convention: Convention,
        /// Also the Pade approximants.
        pade: bool,
    },
    /// The adhesion series at a given nu beyond the exact route's order, or with `digits`.
    AdhesionNumeric {
        /// Poisson's ratio.
        nu: Q,
        /// Terms through lambda^order.
        order: usize,
        /// Digits asked.
        digits: u32,
    },
    /// The loading-law series at given nu and n = P1/P2 (numerical coefficients).
    LoadingLaw {
        /// Poisson's ratio.
        nu: Q,
        /// n = P1/P2.
        ratio: Q,
        /// Terms through lambda^order.
        order: usize,
    },
}

/// Largest order accepted per object, where the exact derivation still takes seconds (the
/// coefficients of Y grow like order^2 terms each; `series adhesion --order 24`: 3.8 s on a shared
/// 2-core machine, docs/performance.md). The adhesion series with `nu` goes beyond, by its
/// numerical route, up to [`crate::asymptotics::adhesion_numeric::MAX_ORDER`].
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
pub(crate) fn order_limit_text(object: SeriesObject) -> &'static str {
    match object {
        SeriesObject::Kernel => "the kernel series' limit",
        SeriesObject::Jacobi => "the Jacobi moments' limit",
        SeriesObject::Weight => "the weight series' limit",
        SeriesObject::Sliding(_) => "the sliding series' limit",
        SeriesObject::Adhesion => "the adhesion series' exact route; with --nu R the numerical route takes up to 1000",
        SeriesObject::PolynomialSliding | SeriesObject::PolynomialAdhesion => {
            "the limit of a polynomial profile's series"
        }
    }
}

/// An order error that names whose limit it is: "... must be an integer in [0, max] (`what`)".
pub fn order_limit(e: ModelError, what: &str) -> ModelError {
    ModelError { expected: format!("{} ({what})", e.expected), ..e }
}

/// Parses an order (an integer in [0, max]); `flag` names it in the message.
pub fn parse_order(flag: &str, text: &str, max: usize) -> Result<usize, ModelError> {
    text.trim()
        .parse::<usize>()
        .ok()
        .filter(|&n| n <= max)
        .ok_or_else(|| ModelError::new(flag, text, format!("must be an integer in [0, {max}]")))
}

/// Parses an exact rational option.
pub(crate) fn parse_exact(flag: &str, text: &str) -> Result<Q, ModelError> {
    parse_rational(text).map_err(|_| {
        ModelError::new(flag, text, "must be an exact number: an integer, a ratio like 1/10, or a decimal like 0.25")
    })
}

/// The command line's flag of an option name (`rbar_s` -> `--rbar-s`).
fn flag(name: &str) -> String {
    format!("--{}", name.replace('_', "-"))
}

impl SeriesRequest {
    /// `object` through power `order`, no options.
    pub fn new(object: &str, order: usize) -> Self {
        SeriesRequest { object: object.to_string(), order: order.to_string(), ..Default::default() }
    }

    /// With option `name = value` (exact text).
    pub fn option(mut self, name: &str, value: &str) -> Self {
        self.options.push((name.to_string(), value.to_string()));
        self
    }

    /// With the Pade approximants.
    pub fn pade(mut self, pade: bool) -> Self {
        self.pade = pade;
        self
    }

    /// The value of option `name` (the last one given).
    fn get(&self, name: &str) -> Option<&str> {
        self.options.iter().rev().find(|(k, _)| k == name).map(|(_, v)| v.as_str())
    }

    /// Validates the request once: unknown objects and options, options the object does not
    /// take, values out of range, the order beyond the route's limit; each error names the
    /// option as the command line's flag, its value and the valid range.
    pub fn validate(&self) -> Result<ValidSeries, ModelError> {
        if !OBJECTS.contains(&self.object.as_str()) {
            return Err(ModelError::new("OBJECT", &self.object, format!("must be one of {}", OBJECTS.join(", "))));
        }
        for (k, _) in &self.options {
            if !OPTION_NAMES.contains(&k.as_str()) {
                return Err(ModelError::new("option", k, format!("must be one of {}", OPTION_NAMES.join(", "))));
            }
        }
        let shape = self.get("shape").map(shape_of).transpose()?.unwrap_or(ShapeName::Parabolic);
        let convention = self.get("convention").map(convention_of).transpose()?;
        if self.pade && self.object == "loading-law" {
            return Err(ModelError::new(
                "--pade",
                "with loading-law",
                "the Pade approximants are built for kernel, weight, sliding and adhesion",
            ));
        }
        if self.object == "loading-law" {
            return self.loading_law(shape, convention);
        }
        if let Some(r) = self.get("ratio") {
            return Err(ModelError::new("--ratio", r, "only the loading-law series takes a ratio"));
        }
        if let (Some(c), false) = (convention, self.object == "sliding") {
            return Err(ModelError::new(
                "--convention",
                convention_name(c),
                "only the sliding series has a surface convention",
            ));
        }
        let convention = convention.unwrap_or(Convention::Paper);
        let (coefficients, degree) = (self.get("coefficients"), self.get("degree"));
        let object = match self.object.as_str() {
            "kernel" => SeriesObject::Kernel,
            "weight" => SeriesObject::Weight,
            "jacobi" => SeriesObject::Jacobi,
            "adhesion" if coefficients.is_some() || degree.is_some() => SeriesObject::PolynomialAdhesion,
            "adhesion" => SeriesObject::Adhesion,
            _ => match shape {
                ShapeName::Parabolic => SeriesObject::Sliding(SlidingShape::Parabolic),
                ShapeName::Sinusoidal => SeriesObject::Sliding(SlidingShape::Sinusoidal),
                ShapeName::Polynomial => SeriesObject::PolynomialSliding,
            },
        };
        let profile = polynomial_profile(object, coefficients, degree)?;
        let rbar_s = self.get("rbar_s").map(|v| parse_exact("--rbar-s", v)).transpose()?;
        if let (Some(v), false) = (&rbar_s, object == SeriesObject::PolynomialSliding) {
            return Err(ModelError::new("--rbar-s", v, "only the sliding series with --shape polynomial has rbar_s"));
        }
        let nu_given = self.get("nu");
        // The adhesion series with nu takes any order up to the numerical route's cap.
        let numeric_possible = object == SeriesObject::Adhesion && nu_given.is_some();
        let numeric_max = crate::asymptotics::adhesion_numeric::MAX_ORDER;
        let order = if numeric_possible {
            parse_order("--order", &self.order, numeric_max).map_err(|e| {
                order_limit(e, "the adhesion series at --nu: exact in symbols up to 24, by the numerical route beyond")
            })?
        } else {
            parse_order("--order", &self.order, max_order(object))
                .map_err(|e| order_limit(e, order_limit_text(object)))?
        };
        let digits = self
            .get("digits")
            .map(|d| {
                let max = crate::asymptotics::adhesion_numeric::MAX_DIGITS;
                d.trim()
                    .parse::<u32>()
                    .ok()
                    .filter(|v| (1..=max).contains(v))
                    .ok_or_else(|| ModelError::new("--digits", d, format!("must be an integer in [1, {max}]")))
            })
            .transpose()?;
        if let (Some(d), false) = (digits, numeric_possible) {
            return Err(ModelError::new(
                "--digits",
                d,
                "only the adhesion series with --nu R (its numerical route) takes digits",
            ));
        }
        let theta = self.get("theta").map(|t| parse_exact("--theta", t)).transpose()?;
        if let Some(t) = &theta {
            if t.abs() >= Q::new(1.into(), 2.into()) {
                return Err(ModelError::new("--theta", t, "must satisfy |theta| < 1/2"));
            }
            if object == SeriesObject::Kernel {
                return Err(ModelError::new("--theta", t, "the kernel has no theta"));
            }
        }
        let xh = self.get("xh").map(|t| parse_exact("--xh", t)).transpose()?;
        if let Some(x) = &xh {
            if x.abs() > Q::from_integer(1.into()) {
                return Err(ModelError::new("--xh", x, "must lie in [-1, 1]"));
            }
            if !matches!(object, SeriesObject::Weight | SeriesObject::Sliding(_)) {
                return Err(ModelError::new("--xh", x, "only the weight and sliding series have xh"));
            }
        }
        let t = self.get("T").map(|v| parse_exact("--T", v)).transpose()?;
        if let Some(v) = &t {
            if v.is_negative() {
                return Err(ModelError::new("--T", v, "must be >= 0 (T = beta tau0/(E* k l_s))"));
            }
            if !matches!(object, SeriesObject::Sliding(_)) {
                return Err(ModelError::new("--T", v, "only the sliding series has T"));
            }
        }
        let nu = nu_given.map(|v| parse_exact("--nu", v)).transpose()?;
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
            if self.pade {
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
            self.check_table()?;
            let digits = digits.unwrap_or(crate::asymptotics::catalog::VALUE_DIGITS as u32);
            return Ok(ValidSeries::AdhesionNumeric { nu: v.clone(), order, digits });
        }
        self.check_table()?;
        let subs = Box::new(Substitutions { theta, xh, t, nu, rbar_s, profile });
        Ok(ValidSeries::Exact { object, order, subs, convention, pade: self.pade })
    }

    /// Refuses an option that [`OPTIONS`] does not list for the object (after the specific checks,
    /// whose messages say more).
    fn check_table(&self) -> Result<(), ModelError> {
        let takes = OPTIONS.iter().find(|(o, _)| *o == self.object).map_or(&[][..], |(_, t)| *t);
        match self.options.iter().find(|(k, _)| !takes.contains(&k.as_str())) {
            None => Ok(()),
            Some((k, v)) => Err(ModelError::new(
                flag(k),
                v,
                match takes {
                    [] => format!("the {} series takes no option but --order", self.object),
                    t => format!(
                        "the {} series takes only {}",
                        self.object,
                        t.iter().map(|o| flag(o)).collect::<Vec<_>>().join(", ")
                    ),
                },
            )),
        }
    }

    /// Validates `loading-law`: nu in [0, 1/2] and ratio >= 0 required (exact), the order, the
    /// paper convention and the parabola only.
    fn loading_law(&self, shape: ShapeName, convention: Option<Convention>) -> Result<ValidSeries, ModelError> {
        use crate::asymptotics::loading_law::MAX_ORDER;
        let taken = ["nu", "ratio", "shape", "convention"];
        if let Some((k, v)) = self.options.iter().find(|(k, _)| !taken.contains(&k.as_str())) {
            return Err(ModelError::new(
                flag(k),
                v,
                "the loading-law series takes only --nu, --ratio, --order, --format",
            ));
        }
        if shape != ShapeName::Parabolic {
            return Err(ModelError::new("--shape", shape.name(), "the loading-law series is for the parabola"));
        }
        if convention == Some(Convention::PeriodicSurface) {
            return Err(ModelError::new(
                "--convention",
                "periodic",
                "the loading-law series is derived in the paper convention only",
            ));
        }
        let nu = parse_exact(
            "--nu",
            self.get("nu").ok_or_else(|| {
                ModelError::new("--nu", "(missing)", "the loading-law series needs Poisson's ratio --nu R in [0, 1/2]")
            })?,
        )?;
        if nu.is_negative() || nu > Q::new(1.into(), 2.into()) {
            return Err(ModelError::new("--nu", &nu, "must lie in [0, 1/2]"));
        }
        let ratio = parse_exact(
            "--ratio",
            self.get("ratio").ok_or_else(|| {
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
        let order = parse_order("--order", &self.order, MAX_ORDER)
            .map_err(|e| order_limit(e, "the loading-law series' limit"))?;
        Ok(ValidSeries::LoadingLaw { nu, ratio, order })
    }
}

/// The punch shapes of the sliding series.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum ShapeName {
    Parabolic,
    Sinusoidal,
    Polynomial,
}

impl ShapeName {
    fn name(self) -> &'static str {
        match self {
            ShapeName::Parabolic => "parabolic",
            ShapeName::Sinusoidal => "sinusoidal",
            ShapeName::Polynomial => "polynomial",
        }
    }
}

/// `shape`: parabolic, sinusoidal or polynomial, or their aliases parabola, sinusoid, poly (the one
/// alias table of every shape name, [`crate::scene::keys::SHAPE_ALIASES`]).
fn shape_of(text: &str) -> Result<ShapeName, ModelError> {
    match crate::scene::keys::canonical_shape(text.trim()) {
        "parabolic" => Ok(ShapeName::Parabolic),
        "sinusoidal" => Ok(ShapeName::Sinusoidal),
        "polynomial" => Ok(ShapeName::Polynomial),
        other => Err(ModelError::new(
            "--shape",
            other,
            "must be parabolic (alias parabola), sinusoidal (alias sinusoid) or polynomial (alias poly)",
        )),
    }
}

/// `convention`: paper or periodic.
fn convention_of(text: &str) -> Result<Convention, ModelError> {
    match text.trim() {
        "paper" => Ok(Convention::Paper),
        "periodic" => Ok(Convention::PeriodicSurface),
        other => Err(ModelError::new("--convention", other, "must be paper or periodic")),
    }
}

/// The command line's name of a convention.
fn convention_name(c: Convention) -> &'static str {
    match c {
        Convention::Paper => "paper",
        Convention::PeriodicSurface => "periodic",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_names_every_object_and_only_known_options() {
        assert_eq!(OPTIONS.map(|(o, _)| o), OBJECTS);
        for (_, opts) in OPTIONS {
            assert!(opts.iter().all(|o| OPTION_NAMES.contains(o)), "{opts:?}");
        }
    }

    /// Every option an object does not take is refused (and every option it takes is read).
    #[test]
    fn options_outside_the_table_are_refused() {
        let value = |o: &str| match o {
            "shape" => "parabolic",
            "convention" => "paper",
            "coefficients" => "0,0,1",
            "degree" => "2",
            "digits" => "20",
            "nu" => "3/10",
            _ => "1/10",
        };
        for (object, takes) in OPTIONS {
            for o in OPTION_NAMES {
                let r = SeriesRequest::new(object, 2).option(o, value(o));
                if !takes.contains(&o) {
                    assert!(r.validate().is_err(), "{object} took {o}");
                }
            }
        }
    }

    #[test]
    fn routes() {
        let r = SeriesRequest::new("adhesion", 30).option("nu", "1/4");
        assert!(matches!(r.validate().unwrap(), ValidSeries::AdhesionNumeric { order: 30, digits: 30, .. }));
        let r = SeriesRequest::new("adhesion", 6).option("nu", "1/4");
        assert!(matches!(r.validate().unwrap(), ValidSeries::Exact { order: 6, .. }));
        let r = SeriesRequest::new("loading-law", 6).option("nu", "3/10").option("ratio", "1/5");
        assert!(matches!(r.validate().unwrap(), ValidSeries::LoadingLaw { order: 6, .. }));
        let e = SeriesRequest::new("rolling", 2).validate().unwrap_err();
        assert!(e.to_string().contains("must be one of kernel, weight"), "{e}");
    }
}
