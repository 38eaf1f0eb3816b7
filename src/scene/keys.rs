//! The one table of scene keys: every key the parser accepts, where, with its meaning, unit and
//! valid range. The parser ([`super::parse`]) takes its lists of valid keys (and the range texts of
//! its messages) from [`KEYS`], and `periodic-contact scene --template` prints the same table as a
//! commented TOML scene ([`template`]), so the documentation cannot drift from the checks.

use std::fmt::Write as _;

/// Which scenes a key belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scope {
    /// Every scene.
    All,
    /// Problem 1 (sliding).
    Sliding,
    /// Problem 2 without a loading law.
    Adhesion,
    /// Problem 2 under a loading law.
    Law,
    /// Problem 2, with or without a law.
    AnyAdhesion,
    /// Problem 1 or the loading law (the keys sized by l).
    SlidingOrLaw,
    /// Problem 1 or Problem 2 without a law.
    SlidingOrAdhesion,
    /// `[punch]` of the named shape only.
    Shape(&'static str),
}

/// The scene kinds a template (or a parse) is for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Problem 1.
    Sliding,
    /// Problem 2.
    Adhesion,
    /// Problem 2 under a loading law.
    Law,
}

impl Scope {
    /// Whether the key applies to a scene of `kind` with punch `shape`.
    pub fn applies(self, kind: Kind, shape: &str) -> bool {
        match self {
            Scope::All => true,
            Scope::Sliding => kind == Kind::Sliding,
            Scope::Adhesion => kind == Kind::Adhesion,
            Scope::Law => kind == Kind::Law,
            Scope::AnyAdhesion => kind != Kind::Sliding,
            Scope::SlidingOrLaw => kind != Kind::Adhesion,
            Scope::SlidingOrAdhesion => kind != Kind::Law,
            Scope::Shape(s) => s == shape,
        }
    }
}

/// How a template shows a key.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shown {
    /// Set, with its example value.
    Set,
    /// Commented out: optional, or an alternative to a key that is set.
    Commented,
}

/// One key of a scene file.
#[derive(Debug, Clone, Copy)]
pub struct Key {
    /// The TOML table (`problem`, `material`, ...).
    pub table: &'static str,
    /// The key.
    pub name: &'static str,
    /// The scenes it belongs to.
    pub scope: Scope,
    /// What it means.
    pub meaning: &'static str,
    /// Its unit (any consistent system of units).
    pub unit: &'static str,
    /// Its valid values (the parser's message text after "must be").
    pub range: &'static str,
    /// The example value a template prints (TOML text).
    pub example: &'static str,
    /// Whether the template sets it or shows it commented out.
    pub shown: Shown,
}

/// The tables of a scene, in file order.
pub const TABLES: [&str; 7] = ["problem", "material", "punch", "sliding", "adhesion", "output", "sweep"];

const fn key(
    table: &'static str,
    name: &'static str,
    scope: Scope,
    meaning: &'static str,
    unit: &'static str,
    range: &'static str,
    example: &'static str,
    shown: Shown,
) -> Key {
    Key { table, name, scope, meaning, unit, range, example, shown }
}

use Scope::*;
use Shown::*;

/// Range text of `[output] digits` and `target_digits` (the parser checks [`super::parse::MAX_DIGITS`]).
pub const DIGITS_RANGE: &str = "an integer in [1, 1000]";
/// Range text of `[output] series_order`.
pub const SERIES_ORDER_RANGE: &str = "an integer in [0, 24]";
/// Largest `[output] series_order`.
pub const MAX_SERIES_ORDER: usize = 24;
/// Range text of `[output] method`.
pub const METHOD_RANGE: &str = "\"mpfr\", \"f64\", \"series\", \"pade\" or \"analytic\"";
/// Range text of `[problem] convention`.
pub const CONVENTION_RANGE: &str = "\"paper\" or \"periodic\"";
/// Range text of `[problem] kind`.
pub const KIND_RANGE: &str = "\"sliding\" or \"adhesion\"";
/// Range text of `[punch] shape`.
pub const SHAPE_RANGE: &str =
    "\"parabolic\", \"sinusoidal\", \"polynomial\" or \"circular\" (aliases \"parabola\", \"sinusoid\", \"poly\", \"circle\")";

/// The one alias of each punch shape (issue 30), accepted wherever a shape is named: the scene's
/// `[punch] shape` and the command line's `--shape`. Outputs print the canonical name.
pub const SHAPE_ALIASES: [(&str, &str); 4] =
    [("parabola", "parabolic"), ("sinusoid", "sinusoidal"), ("poly", "polynomial"), ("circle", "circular")];

/// The canonical name of a shape given by its name or its alias (other text unchanged).
pub fn canonical_shape(name: &str) -> &str {
    SHAPE_ALIASES.iter().find(|(alias, _)| *alias == name).map_or(name, |(_, canonical)| canonical)
}

/// Every key the parser accepts, table by table, in the order of its messages.
pub const KEYS: &[Key] = &[
    key("problem", "kind", All, "which problem: Problem 1 (steady sliding with friction and wear) or Problem 2 (indentation with complete adhesion)", "-", KIND_RANGE, "\"sliding\"", Set),
    key("problem", "convention", All, "surface convention (docs/theory.md section 8): \"paper\" solves the paper's [2.8] as it stands; \"periodic\" adds K = (kappa P2 - 2 beta l tau0)/L so that the surface closes over every period; in Problem 2 \"periodic\" makes u periodic (a laterally rigid row) where \"paper\" keeps the Flamant far field sigma_xx = -P2/L. Optional, default \"paper\"; `solve --convention` overrides it", "-", CONVENTION_RANGE, "\"paper\"", Commented),
    key("material", "poisson_ratio", All, "Poisson's ratio nu of the elastic half-plane (plane strain)", "-", "an exact number in [0, 1/2]", "\"0.3\"", Set),
    key("material", "youngs_modulus", All, "Young's modulus E (give it or contact_modulus, not both)", "stress", "an exact number > 0", "\"1\"", Commented),
    key("material", "contact_modulus", All, "contact modulus E* = E/(1 - nu^2) (give it or youngs_modulus, not both)", "stress", "an exact number > 0", "\"1\"", Set),
    key("punch", "shape", All, "punch profile g on the cell (-L/2, L/2), repeated with period L (docs/theory.md section 9)", "-", SHAPE_RANGE, "\"parabolic\"", Set),
    key("punch", "k", Shape("parabolic"), "curvature parameter of the parabola g = k x^2", "1/length", "an exact number > 0", "\"1\"", Set),
    key("punch", "amplitude", Shape("sinusoidal"), "amplitude D of the sinusoid g = D (1 - cos(2 pi x/L)) (needs a finite period)", "length", "an exact number > 0", "\"0.01\"", Set),
    key("punch", "coefficients", Shape("polynomial"), "coefficients c_j of g = sum_j c_j x^j in numpy order (index j multiplies x^j), exact numbers, c_0 = 0; the profile must be convex on the contact (beyond |g'| = 1/2 the answer carries a small-slope warning, docs/theory.md section 9)", "length^(1-j)", "a list of exact numbers with c_0 = 0 and some c_j != 0, j >= 2", "[\"0\", \"0\", \"1\", \"0\", \"1/10\"]", Set),
    key("punch", "radius", Shape("circular"), "radius R of the circular punch g = R - sqrt(R^2 - x^2) (the contact must stay within |x| < R)", "length", "an exact number > 0", "\"1/2\"", Set),
    key("punch", "period", All, "period L of the row of punches, or \"inf\" for a single punch", "length", "an exact number > 0, or \"inf\"", "\"1\"", Set),
    key("sliding", "normal_load", Sliding, "normal load P2 per punch (give it or half_length, not both)", "force/length", "an exact number > 0 that the punch can carry", "\"0.005\"", Set),
    key("sliding", "half_length", Sliding, "half-length l = (a + b)/2 of the contact (the direct problem; give it or normal_load)", "length", "an exact number > 0 with the contact inside its cell", "\"0.05\"", Commented),
    key("sliding", "friction", Sliding, "Coulomb friction coefficient mu (q1 = mu p + tau0). Optional, default 0", "-", "an exact number >= 0 (with wear: |theta| < 1/2)", "\"0.3\"", Set),
    key("sliding", "adhesive_friction", Sliding, "adhesive component tau0 of the friction stress. Optional, default 0", "stress", "an exact number >= 0", "\"0\"", Commented),
    key("sliding", "wear", Sliding, "linear wear coefficient cW (dW/dt = cW V p). Optional, default 0", "1/stress", "an exact number >= 0", "\"0\"", Commented),
    key("sliding", "speed", Sliding, "sliding speed V, for the wear rate cW V P2/L. Optional", "length/time", "an exact number > 0", "\"1\"", Commented),
    key("adhesion", "half_width", Adhesion, "half-width a of the symmetric contact (give it or normal_load)", "length", "an exact number > 0 with the contact inside its cell", "\"0.1\"", Set),
    key("adhesion", "friction", Adhesion, "Coulomb friction coefficient mu of the contact (docs/theory.md section 17): a central stick zone |x| < c and slip |q1| = mu q2 at the ends; solved for the single punch (period \"inf\") with the parabola by the f64 method, 4-5 digits. Optional, absent: complete adhesion", "-", crate::model::FRICTION_RANGE, "\"1/2\"", Commented),
    key("adhesion", "tangential_ratio", Law, "linear loading law P1 = n P2: the ratio n (give it or loading_law)", "-", "an exact number >= 0", "\"1/5\"", Set),
    key("adhesion", "loading_law", Law, "polynomial loading law P1 = sum_j c_j P2^j, numpy order, c_0 = 0, with N' >= 0 along the loading (give it or tangential_ratio)", "force^(1-j)", "a list of exact numbers with c_0 = 0", "[\"0\", \"1/5\", \"1/100\"]", Commented),
    key("adhesion", "half_length", Law, "half-length l = (a + b)/2 of the asymmetric contact [-a, b] (give it or normal_load)", "length", "an exact number > 0 with the contact inside its cell", "\"0.05\"", Set),
    key("adhesion", "normal_load", AnyAdhesion, "normal load P2 per punch (instead of the size: the size is then found)", "force/length", "an exact number > 0", "\"0.01\"", Commented),
    key("output", "digits", All, "digits requested: forces the verified MPFR method at this working precision (`solve --digits` overrides it)", "digits", DIGITS_RANGE, "30", Commented),
    key("output", "target_digits", All, "accuracy target: `solve` and the report run the cheapest method predicted to meet it (calibration/methods.csv), e.g. 8 for a fast f64 answer. Optional: without it and without digits `solve` runs verified MPFR at 30 digits", "digits", DIGITS_RANGE, "8", Commented),
    key("output", "points", All, "points where the fields are printed: Problem 1 and the loading law xh = (x - c)/l in (-1, 1); Problem 2 x/a in [0, 1]", "-", "exact numbers in (-1, 1) (xh) or [0, 1] (x/a)", "[\"-0.5\", \"0\", \"0.5\"]", Set),
    key("output", "method", All, "forces a method: \"mpfr\" (verified high precision), \"f64\" (fast, estimated digits), \"series\" (truncated exact series: Problem 1, parabolic or sinusoidal punch, a given normal_load and a finite period; a polynomial or circular punch is refused), \"pade\" (Pade approximants of that series, docs/theory.md section 11), \"analytic\" (Problem 2, parabolic punch, `paper` convention, a given half_width: the member analytic at zero size continued past lambda_h, docs/theory.md section 11); `solve --method` overrides it", "-", METHOD_RANGE, "\"f64\"", Commented),
    key("output", "series_order", All, "order N of the series and pade methods: every term through Lambda^N. Optional, default 12 (series) and 24 (pade); `solve --order` overrides it", "-", SERIES_ORDER_RANGE, "12", Commented),
    key("sweep", "normal_load", All, "load-size curve for the report: the scene's load replaced by each value in turn (one sweep key per scene; `solve` ignores the sweep)", "force/length", "a list of 1 to 64 exact numbers, each valid for the problem", "[\"0.001\", \"0.003\", \"0.005\"]", Set),
    key("sweep", "half_length", SlidingOrLaw, "load-size curve over the half-length l instead of the load", "length", "a list of 1 to 64 exact numbers, each valid for the problem", "[\"0.02\", \"0.05\"]", Commented),
    key("sweep", "half_width", Adhesion, "load-size curve over the half-width a instead of the load", "length", "a list of 1 to 64 exact numbers, each valid for the problem", "[\"0.05\", \"0.1\"]", Commented),
];

/// The keys of `table` that apply to a scene of `kind` with punch `shape`, in table order.
pub fn allowed(table: &str, kind: Kind, shape: &str) -> Vec<&'static str> {
    KEYS.iter().filter(|k| k.table == table && k.scope.applies(kind, shape)).map(|k| k.name).collect()
}

/// The keys of `table` whatever the shape (for tables without shape-specific keys).
pub(crate) fn allowed_any(table: &str, kind: Kind) -> Vec<&'static str> {
    allowed(table, kind, "")
}

/// The key `table.name` (a bug if absent: every caller names a key of [`KEYS`]).
pub fn get(table: &str, name: &str) -> &'static Key {
    KEYS.iter().find(|k| k.table == table && k.name == name).expect("a key of the table")
}

/// Punch shapes a template may show, and which problems take them.
pub const SHAPES: [&str; 4] = ["parabolic", "sinusoidal", "polynomial", "circular"];

/// Why a template cannot be made.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TemplateError {
    /// The parameter.
    pub parameter: &'static str,
    /// Its value.
    pub value: String,
    /// What is valid.
    pub expected: &'static str,
}

/// A commented TOML scene of `kind` with punch `shape` ("parabolic", ...): every key that applies,
/// with its meaning, unit and valid range; alternatives and optional keys commented out.
pub fn template(kind: Kind, shape: &str) -> Result<String, TemplateError> {
    if !SHAPES.contains(&shape) {
        return Err(TemplateError { parameter: "--shape", value: shape.into(), expected: SHAPE_RANGE });
    }
    if kind == Kind::Adhesion && shape == "sinusoidal" {
        return Err(TemplateError {
            parameter: "--shape",
            value: shape.into(),
            expected: "the adhesion problem takes \"parabolic\", \"polynomial\" (even) or \"circular\"",
        });
    }
    if kind == Kind::Law && shape != "parabolic" {
        return Err(TemplateError {
            parameter: "--shape",
            value: shape.into(),
            expected: "a loading law takes the \"parabolic\" punch only",
        });
    }
    let mut s = String::new();
    let what = match kind {
        Kind::Sliding => "Problem 1: steady sliding with friction and wear",
        Kind::Adhesion => "Problem 2: indentation with complete adhesion",
        Kind::Law => "Problem 2 under a loading law P1 = N(P2) (asymmetric contact)",
    };
    let _ = writeln!(s, "# Scene: {what}, {shape} punch.");
    s.push_str(
        "# Generated by `periodic-contact scene --template`. Numbers are exact: quote decimals and ratios\n\
         # (\"0.25\", \"1/3\", \"1e-3\"). Unknown keys are errors. Symbols: docs/theory.md section 12.\n\
         # Solve it: periodic-contact solve FILE [--json]\n",
    );
    let table_of_problem = if kind == Kind::Sliding { "sliding" } else { "adhesion" };
    for table in TABLES {
        if (table == "sliding" || table == "adhesion") && table != table_of_problem {
            continue;
        }
        let keys: Vec<&Key> = KEYS.iter().filter(|k| k.table == table && k.scope.applies(kind, shape)).collect();
        let _ = writeln!(s, "\n[{table}]");
        for k in keys {
            for line in wrap(k.meaning, 96) {
                let _ = writeln!(s, "# {line}");
            }
            let _ = writeln!(s, "#   unit: {}; valid: {}", k.unit, k.range);
            let example = match (k.table, k.name) {
                ("problem", "kind") if kind != Kind::Sliding => "\"adhesion\"",
                ("punch", "shape") => match shape {
                    "sinusoidal" => "\"sinusoidal\"",
                    "polynomial" => "\"polynomial\"",
                    "circular" => "\"circular\"",
                    _ => "\"parabolic\"",
                },
                // Problem 2 takes an even profile.
                ("punch", "coefficients") if kind != Kind::Sliding => "[\"0\", \"0\", \"1\", \"0\", \"1/10\"]",
                ("output", "points") if kind == Kind::Adhesion => "[\"0\", \"0.5\", \"0.9\"]",
                ("sweep", "normal_load") if kind == Kind::Law => "[\"0.002\", \"0.005\"]",
                ("sweep", "normal_load") if kind == Kind::Adhesion => "[\"0.005\", \"0.01\", \"0.02\"]",
                _ => k.example,
            };
            let hash = if k.shown == Shown::Commented { "# " } else { "" };
            let _ = writeln!(s, "{hash}{} = {example}", k.name);
        }
    }
    Ok(s)
}

/// Splits `text` into lines of at most `width` characters at spaces (a longer word stays whole).
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines = vec![String::new()];
    for word in text.split(' ') {
        let last = lines.last_mut().expect("one line");
        if !last.is_empty() && last.len() + 1 + word.len() > width {
            lines.push(word.to_string());
        } else {
            if !last.is_empty() {
                last.push(' ');
            }
            last.push_str(word);
        }
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn range_texts_match_the_parser_limits() {
        assert_eq!(SERIES_ORDER_RANGE, format!("an integer in [0, {MAX_SERIES_ORDER}]"));
    }

    #[test]
    fn every_key_is_in_a_known_table_once() {
        for (i, k) in KEYS.iter().enumerate() {
            assert!(TABLES.contains(&k.table), "{}", k.table);
            for other in &KEYS[..i] {
                let same_place = other.table == k.table && other.name == k.name;
                assert!(!same_place, "{}.{} twice", k.table, k.name);
            }
        }
    }
}
