//! Strict scene parser (toml_edit keeps each literal's text, so numbers are read exactly).

use super::keys::{self, Kind};
use super::{with_value, Method, OutputSpec, Scene, SceneProblem, Sweep, SweepParameter};
use crate::model::{
    AdhesionProblem, AdhesionSize, Convention, Exact, LawSize, LoadingLaw, LoadingLawProblem, Material, ModelError,
    Period, PunchShape, SlidingLoad, SlidingProblem,
};
use exact_series::parse_rational;
use num_traits::{One, Signed};
use toml_edit::{DocumentMut, Item, Table, Value};

/// Largest `digits` accepted (the MPFR path handles it; beyond it a run takes minutes).
pub const MAX_DIGITS: u32 = 1000;

/// Parses and validates a scene from TOML text.
pub fn parse_scene(text: &str) -> Result<Scene, ModelError> {
    let doc: DocumentMut = text.parse().map_err(|e: toml_edit::TomlError| {
        ModelError::new("scene", "(file)", format!("malformed TOML: {}", e.to_string().trim()))
    })?;
    let root = doc.as_table();
    allow_keys(root, "", &keys::TABLES)?;
    let problem = table(root, "problem")?;
    allow_keys(problem, "problem", &keys::allowed_any("problem", Kind::Sliding))?;
    let kind = string(problem, "problem", "kind")?;
    let convention = parse_convention(problem)?;
    match kind.as_str() {
        "sliding" => {
            if root.contains_key("adhesion") {
                return Err(ModelError::new("adhesion", "(table)", "not allowed in a sliding scene"));
            }
            let output = parse_output(root, PointRange::OpenUnit)?;
            let problem = SceneProblem::Sliding(parse_sliding(root, convention)?);
            let sweep = parse_sweep(root, &problem)?;
            Ok(Scene { problem, output, sweep })
        }
        "adhesion" => {
            if root.contains_key("sliding") {
                return Err(ModelError::new("sliding", "(table)", "not allowed in an adhesion scene"));
            }
            let problem = if has_law(root) {
                let output = parse_output(root, PointRange::OpenUnit)?;
                (output, SceneProblem::LoadingLaw(parse_loading_law(root, convention)?))
            } else {
                (parse_output(root, PointRange::ClosedHalf)?, SceneProblem::Adhesion(parse_adhesion(root, convention)?))
            };
            let (output, problem) = problem;
            let sweep = parse_sweep(root, &problem)?;
            Ok(Scene { problem, output, sweep })
        }
        other => Err(ModelError::new("problem.kind", other, format!("must be {}", keys::KIND_RANGE))),
    }
}

/// `[problem] convention`: "paper" (the default) or "periodic" (docs/theory.md section 8). In
/// Problem 2 `periodic` makes u periodic (docs/theory.md section 8, Problem 2: the lateral term
/// i beta P/L); under a loading law (P1 != 0) it also removes the rotation.
fn parse_convention(problem: &Table) -> Result<Convention, ModelError> {
    match value(problem, "problem", "convention")? {
        None => Ok(Convention::Paper),
        Some(v) => {
            let name = literal(v).unwrap_or_else(|| v.to_string().trim().to_string());
            parse_convention_name(&name).ok_or_else(|| {
                ModelError::new("problem.convention", name.trim(), format!("must be {}", keys::CONVENTION_RANGE))
            })
        }
    }
}

/// A convention by its name: "paper" or "periodic" ([`Convention::name`]).
pub(crate) fn parse_convention_name(name: &str) -> Option<Convention> {
    [Convention::Paper, Convention::PeriodicSurface].into_iter().find(|c| c.name() == name)
}

fn path(prefix: &str, key: &str) -> String {
    if prefix.is_empty() {
        key.to_string()
    } else {
        format!("{prefix}.{key}")
    }
}

fn allow_keys(t: &Table, prefix: &str, allowed: &[&str]) -> Result<(), ModelError> {
    for (k, _) in t.iter() {
        if !allowed.contains(&k) {
            return Err(ModelError::new(
                path(prefix, k),
                "(present)",
                format!("unknown key; valid keys here: {}", allowed.join(", ")),
            ));
        }
    }
    Ok(())
}

fn table<'a>(t: &'a Table, key: &str) -> Result<&'a Table, ModelError> {
    match t.get(key) {
        Some(Item::Table(x)) => Ok(x),
        Some(_) => Err(ModelError::new(key, "(not a table)", format!("must be a [{key}] table"))),
        None => Err(ModelError::new(key, "(missing)", format!("a [{key}] table is required"))),
    }
}

fn value<'a>(t: &'a Table, prefix: &str, key: &str) -> Result<Option<&'a Value>, ModelError> {
    match t.get(key) {
        None => Ok(None),
        Some(Item::Value(v)) => Ok(Some(v)),
        Some(_) => Err(ModelError::new(path(prefix, key), "(table)", "must be a value")),
    }
}

fn string(t: &Table, prefix: &str, key: &str) -> Result<String, ModelError> {
    match value(t, prefix, key)? {
        Some(Value::String(s)) => Ok(s.value().clone()),
        Some(v) => Err(ModelError::new(path(prefix, key), v.to_string().trim(), "must be a string")),
        None => Err(ModelError::new(path(prefix, key), "(missing)", "is required")),
    }
}

/// The literal text of a number or string value (no f64 on the way).
fn literal(v: &Value) -> Option<String> {
    match v {
        Value::String(s) => Some(s.value().clone()),
        Value::Integer(i) => Some(i.display_repr().replace('_', "")),
        Value::Float(f) => Some(f.display_repr().replace('_', "")),
        _ => None,
    }
}

/// An exact number from a value, quoted or not.
fn exact_value(v: &Value, name: &str) -> Result<Exact, ModelError> {
    let text = literal(v)
        .ok_or_else(|| ModelError::new(name, v.to_string().trim(), "must be a number or a quoted exact number"))?;
    parse_rational(&text).map_err(|_| {
        ModelError::new(
            name,
            text.trim(),
            "must be an exact number: an integer, a ratio like 1/3, or a decimal like 0.25 or 1e-3",
        )
    })
}

fn exact_opt(t: &Table, prefix: &str, key: &str) -> Result<Option<Exact>, ModelError> {
    value(t, prefix, key)?.map(|v| exact_value(v, &path(prefix, key))).transpose()
}

fn exact_req(t: &Table, prefix: &str, key: &str) -> Result<Exact, ModelError> {
    exact_opt(t, prefix, key)?.ok_or_else(|| ModelError::new(path(prefix, key), "(missing)", "is required"))
}

fn parse_material(root: &Table) -> Result<Material, ModelError> {
    let m = table(root, "material")?;
    allow_keys(m, "material", &keys::allowed_any("material", Kind::Sliding))?;
    let nu = exact_req(m, "material", "poisson_ratio")?;
    match (exact_opt(m, "material", "youngs_modulus")?, exact_opt(m, "material", "contact_modulus")?) {
        (Some(_), Some(_)) => {
            Err(ModelError::new("material", "youngs_modulus and contact_modulus", "give one of them, not both"))
        }
        (Some(e), None) => Material::from_youngs_modulus(nu, e).map_err(|e| prefixed(e, "material")),
        (None, Some(e)) => Material::from_contact_modulus(nu, e).map_err(|e| prefixed(e, "material")),
        (None, None) => Err(ModelError::new("material", "(missing)", "give youngs_modulus or contact_modulus")),
    }
}

fn prefixed(mut e: ModelError, prefix: &str) -> ModelError {
    if !e.parameter.contains('.') {
        e.parameter = path(prefix, &e.parameter);
    }
    e
}

/// Whether `[punch] period` names the single punch: "inf" (as the template writes it), or
/// "infinity" in any case.
fn is_infinite_period(text: &str) -> bool {
    matches!(text.trim().to_ascii_lowercase().as_str(), "inf" | "infinity")
}

fn parse_punch(root: &Table) -> Result<(PunchShape, Period), ModelError> {
    let p = table(root, "punch")?;
    let shape = keys::canonical_shape(&string(p, "punch", "shape")?).to_string();
    let period = match value(p, "punch", "period")? {
        None => {
            return Err(ModelError::new(
                "punch.period",
                "(missing)",
                "is required: a number > 0, or \"inf\" for a single punch",
            ))
        }
        Some(Value::String(s)) if is_infinite_period(s.value()) => Period::Infinite,
        Some(v) => Period::finite(
            exact_value(v, "punch.period")
                .map_err(|e| ModelError { expected: format!("{}; or \"inf\" for a single punch", e.expected), ..e })?,
        )
        .map_err(|e| prefixed(e, "punch"))?,
    };
    if keys::SHAPES.contains(&shape.as_str()) {
        allow_keys(p, "punch", &keys::allowed("punch", Kind::Sliding, &shape))?;
    }
    let shape = match shape.as_str() {
        "parabolic" => PunchShape::parabolic(exact_req(p, "punch", "k")?).map_err(|e| prefixed(e, "punch"))?,
        "sinusoidal" => {
            PunchShape::sinusoidal(exact_req(p, "punch", "amplitude")?).map_err(|e| prefixed(e, "punch"))?
        }
        "polynomial" => PunchShape::polynomial(coefficients(p)?).map_err(|e| prefixed(e, "punch"))?,
        "circular" => PunchShape::circular(exact_req(p, "punch", "radius")?).map_err(|e| prefixed(e, "punch"))?,
        other => return Err(ModelError::new("punch.shape", other, format!("must be {}", keys::SHAPE_RANGE))),
    };
    Ok((shape, period))
}

/// `coefficients = ["0", "0", "1", "0", "1/10"]`: c_j of x^j (numpy's order), each an exact number
/// (quoted, or a literal read from its text).
fn coefficients(p: &Table) -> Result<Vec<Exact>, ModelError> {
    let name = "punch.coefficients";
    match value(p, "punch", "coefficients")? {
        None => Err(ModelError::new(name, "(missing)", "is required: a list of exact numbers c_0, c_1, c_2, ...")),
        Some(Value::Array(a)) => a.iter().enumerate().map(|(j, v)| exact_value(v, &format!("{name}[{j}]"))).collect(),
        Some(v) => Err(ModelError::new(name, v.to_string().trim(), "must be a list such as [\"0\", \"0\", \"1\"]")),
    }
}

fn parse_sliding(root: &Table, convention: Convention) -> Result<SlidingProblem, ModelError> {
    let material = parse_material(root)?;
    let (shape, period) = parse_punch(root)?;
    let s = table(root, "sliding")?;
    allow_keys(s, "sliding", &keys::allowed_any("sliding", Kind::Sliding))?;
    let zero = || Exact::from_integer(0.into());
    let load = match (exact_opt(s, "sliding", "normal_load")?, exact_opt(s, "sliding", "half_length")?) {
        (Some(_), Some(_)) => {
            return Err(ModelError::new("sliding", "normal_load and half_length", "give one of them, not both"))
        }
        (Some(p), None) => SlidingLoad::NormalLoad(p),
        (None, Some(l)) => SlidingLoad::HalfLength(l),
        (None, None) => return Err(ModelError::new("sliding", "(missing)", "give normal_load or half_length")),
    };
    SlidingProblem::builder()
        .material(material)
        .period(period)
        .shape(shape)
        .friction(exact_opt(s, "sliding", "friction")?.unwrap_or_else(zero))
        .adhesive_friction(exact_opt(s, "sliding", "adhesive_friction")?.unwrap_or_else(zero))
        .wear(exact_opt(s, "sliding", "wear")?.unwrap_or_else(zero))
        .speed(exact_opt(s, "sliding", "speed")?)
        .load(load)
        .convention(convention)
        .build()
        .map_err(|e| prefixed(e, "sliding"))
}

fn parse_adhesion(root: &Table, convention: Convention) -> Result<AdhesionProblem, ModelError> {
    let material = parse_material(root)?;
    let (shape, period) = parse_punch(root)?;
    let s = table(root, "adhesion")?;
    allow_keys(s, "adhesion", &keys::allowed_any("adhesion", Kind::Adhesion))?;
    let size = match (exact_opt(s, "adhesion", "half_width")?, exact_opt(s, "adhesion", "normal_load")?) {
        (Some(_), Some(_)) => {
            return Err(ModelError::new("adhesion", "half_width and normal_load", "give one of them, not both"))
        }
        (Some(a), None) => AdhesionSize::HalfWidth(a),
        (None, Some(p)) => AdhesionSize::NormalLoad(p),
        (None, None) => return Err(ModelError::new("adhesion", "(missing)", "give half_width or normal_load")),
    };
    let friction = exact_opt(s, "adhesion", "friction")?;
    let p = AdhesionProblem::new(material, period, shape, size)
        .map(|p| p.with_convention(convention))
        .map_err(|e| prefixed(e, "adhesion"))?;
    match friction {
        Some(mu) => p.with_friction(mu).map_err(|e| prefixed(e, "adhesion")),
        None => Ok(p),
    }
}

/// The keys of `[adhesion]` that make it the loading-law problem (docs/theory.md section 10).
const LAW_KEYS: [&str; 2] = ["tangential_ratio", "loading_law"];

/// Whether `[adhesion]` states a loading law (either key of [`LAW_KEYS`]).
fn has_law(root: &Table) -> bool {
    matches!(root.get("adhesion"), Some(Item::Table(t)) if LAW_KEYS.iter().any(|k| t.contains_key(k)))
}

/// `[adhesion]` with a loading law: `tangential_ratio = "1/5"` (P1 = n P2) or
/// `loading_law = ["0", "1/5", "1/100"]` (P1 = sum_j c_j P2^j, numpy order), and the size
/// `half_length` (l = (a + b)/2) or `normal_load`. `half_width` is refused: the contact is
/// asymmetric.
fn parse_loading_law(root: &Table, convention: Convention) -> Result<LoadingLawProblem, ModelError> {
    let material = parse_material(root)?;
    let (shape, period) = parse_punch(root)?;
    let s = table(root, "adhesion")?;
    if let Some(v) = value(s, "adhesion", "half_width")? {
        return Err(ModelError::new(
            "adhesion.half_width",
            literal(v).unwrap_or_else(|| v.to_string()).trim(),
            "not used under a loading law: the contact [-a, b] is asymmetric, give half_length l = (a + b)/2 \
             (or normal_load)",
        ));
    }
    allow_keys(s, "adhesion", &keys::allowed_any("adhesion", Kind::Law))?;
    let law = match (value(s, "adhesion", "tangential_ratio")?, value(s, "adhesion", "loading_law")?) {
        (Some(_), Some(_)) => {
            return Err(ModelError::new(
                "adhesion",
                "tangential_ratio and loading_law",
                "give one of them, not both (tangential_ratio = n is loading_law = [\"0\", n])",
            ))
        }
        (Some(v), None) => LoadingLaw::Linear(exact_value(v, "adhesion.tangential_ratio")?),
        (None, Some(Value::Array(a))) => LoadingLaw::Polynomial(
            a.iter()
                .enumerate()
                .map(|(j, v)| exact_value(v, &format!("adhesion.loading_law[{j}]")))
                .collect::<Result<_, _>>()?,
        ),
        (None, Some(v)) => {
            return Err(ModelError::new(
                "adhesion.loading_law",
                v.to_string().trim(),
                "must be a list of exact coefficients c_0, c_1, ... of P1 = sum_j c_j P2^j, e.g. [\"0\", \"1/5\"]",
            ))
        }
        (None, None) => return Err(ModelError::new("adhesion", "(missing)", "give tangential_ratio or loading_law")),
    };
    let size = match (exact_opt(s, "adhesion", "half_length")?, exact_opt(s, "adhesion", "normal_load")?) {
        (Some(_), Some(_)) => {
            return Err(ModelError::new("adhesion", "half_length and normal_load", "give one of them, not both"))
        }
        (Some(l), None) => LawSize::HalfLength(l),
        (None, Some(p)) => LawSize::NormalLoad(p),
        (None, None) => {
            return Err(ModelError::new(
                "adhesion",
                "(missing)",
                "give half_length (l = (a + b)/2) or normal_load under a loading law",
            ))
        }
    };
    LoadingLawProblem::new(material, period, shape, law, size, convention).map_err(|e| {
        let prefix = if matches!(e.parameter.as_str(), "period" | "shape") { "punch" } else { "adhesion" };
        prefixed(e, prefix)
    })
}

/// Where the output points of a problem live.
#[derive(Clone, Copy)]
enum PointRange {
    /// xh in (-1, 1) (Problem 1).
    OpenUnit,
    /// x/a in [0, 1] (Problem 2).
    ClosedHalf,
}

fn parse_digits(v: &Value, name: &str) -> Result<u32, ModelError> {
    let text = literal(v).unwrap_or_else(|| v.to_string());
    text.trim()
        .parse::<u32>()
        .ok()
        .filter(|d| (1..=MAX_DIGITS).contains(d))
        .ok_or_else(|| ModelError::new(name, text.trim(), format!("must be {}", keys::DIGITS_RANGE)))
}

fn parse_output(root: &Table, range: PointRange) -> Result<OutputSpec, ModelError> {
    let mut out =
        OutputSpec { digits: None, target_digits: None, points: Vec::new(), method: None, series_order: None };
    let Some(item) = root.get("output") else {
        return Ok(out);
    };
    let Item::Table(o) = item else {
        return Err(ModelError::new("output", "(not a table)", "must be an [output] table"));
    };
    allow_keys(o, "output", &keys::allowed_any("output", Kind::Sliding))?;
    out.digits = value(o, "output", "digits")?.map(|v| parse_digits(v, "output.digits")).transpose()?;
    out.target_digits =
        value(o, "output", "target_digits")?.map(|v| parse_digits(v, "output.target_digits")).transpose()?;
    if let Some(v) = value(o, "output", "method")? {
        let name = literal(v).unwrap_or_default();
        out.method = Some(
            Method::parse(&name)
                .ok_or_else(|| ModelError::new("output.method", &name, format!("must be {}", keys::METHOD_RANGE)))?,
        );
    }
    if let Some(v) = value(o, "output", "series_order")? {
        let text = literal(v).unwrap_or_default();
        out.series_order =
            Some(text.parse::<usize>().ok().filter(|n| *n <= keys::MAX_SERIES_ORDER).ok_or_else(|| {
                ModelError::new("output.series_order", &text, format!("must be {}", keys::SERIES_ORDER_RANGE))
            })?);
    }
    if let Some(v) = value(o, "output", "points")? {
        let Value::Array(a) = v else {
            return Err(ModelError::new("output.points", v.to_string().trim(), "must be an array of numbers"));
        };
        for (i, p) in a.iter().enumerate() {
            let name = format!("output.points[{i}]");
            let x = exact_value(p, &name)?;
            match range {
                PointRange::OpenUnit if x.abs() >= Exact::one() => {
                    return Err(ModelError::new(name, &x, "must lie in (-1, 1) (xh = (x - c)/l)"));
                }
                PointRange::ClosedHalf if x.is_negative() || x > Exact::one() => {
                    return Err(ModelError::new(name, &x, "must lie in [0, 1] (x/a)"));
                }
                _ => {}
            }
            out.points.push(x);
        }
    }
    Ok(out)
}

/// Most values of one sweep (each is a full solve in the report).
pub const MAX_SWEEP_VALUES: usize = 64;

/// `[sweep]`: exactly one key, an array of exact values, each valid for the problem.
fn parse_sweep(root: &Table, problem: &SceneProblem) -> Result<Option<Sweep>, ModelError> {
    let Some(item) = root.get("sweep") else {
        return Ok(None);
    };
    let Item::Table(t) = item else {
        return Err(ModelError::new("sweep", "(not a table)", "must be a [sweep] table"));
    };
    let kind = match problem {
        SceneProblem::Sliding(_) => Kind::Sliding,
        SceneProblem::Adhesion(_) => Kind::Adhesion,
        SceneProblem::LoadingLaw(_) => Kind::Law,
    };
    let allowed = keys::allowed_any("sweep", kind);
    allow_keys(t, "sweep", &allowed)?;
    let keys: Vec<&str> = t.iter().map(|(k, _)| k).collect();
    let [key] = keys.as_slice() else {
        return Err(ModelError::new(
            "sweep",
            format!("{} keys", keys.len()),
            format!("give exactly one of: {}", allowed.join(", ")),
        ));
    };
    let parameter = match *key {
        "normal_load" => SweepParameter::NormalLoad,
        "half_length" => SweepParameter::HalfLength,
        _ => SweepParameter::HalfWidth,
    };
    let name = path("sweep", key);
    let Some(Value::Array(a)) = value(t, "sweep", key)? else {
        return Err(ModelError::new(&name, "(not an array)", "must be an array of exact numbers"));
    };
    if a.is_empty() || a.len() > MAX_SWEEP_VALUES {
        return Err(ModelError::new(&name, a.len(), format!("must hold 1 to {MAX_SWEEP_VALUES} values")));
    }
    let mut values = Vec::new();
    for (i, v) in a.iter().enumerate() {
        let item = format!("{name}[{i}]");
        let x = exact_value(v, &item)?;
        if with_value(problem, parameter, &x).is_none() {
            return Err(ModelError::new(
                item,
                &x,
                "is not a valid value for this problem (must be > 0 and admissible)",
            ));
        }
        values.push(x);
    }
    Ok(Some(Sweep { parameter, values }))
}

#[cfg(test)]
mod tests {
    /// The key table's range text states the parser's limit.
    #[test]
    fn digits_range_text_matches_the_parser_limit() {
        assert_eq!(super::keys::DIGITS_RANGE, format!("an integer in [1, {}]", super::MAX_DIGITS));
    }

    const SCENE: &str = "[problem]\nkind = \"sliding\"\n[material]\npoisson_ratio = \"0.3\"\ncontact_modulus = \"1\"\n\
                         [punch]\nshape = \"parabolic\"\nk = \"1\"\nperiod = PERIOD\n[sliding]\nnormal_load = \"0.005\"\n";

    /// Issue 30: "Infinity" names the single punch as "inf" does, and a period that is neither a
    /// number nor infinite gets an error that says "inf" is accepted.
    #[test]
    fn the_single_punch_is_inf_or_infinity() {
        use crate::model::{OnPunchRow, Period};
        use crate::scene::SceneProblem;
        for text in ["\"inf\"", "\"Infinity\"", "\" INF \"", "\"infinity\""] {
            let s = super::parse_scene(&SCENE.replace("PERIOD", text)).unwrap_or_else(|e| panic!("{text}: {e}"));
            let SceneProblem::Sliding(p) = &s.problem else { panic!("sliding") };
            assert!(matches!(p.period(), Period::Infinite), "{text}");
        }
        let e = super::parse_scene(&SCENE.replace("PERIOD", "\"endless\"")).unwrap_err();
        assert_eq!(e.parameter, "punch.period");
        assert!(e.expected.contains("or \"inf\" for a single punch"), "{e}");
        let e = super::parse_scene(&SCENE.replace("PERIOD", "\"-1\"")).unwrap_err();
        assert!(e.to_string().contains("\"inf\""), "{e}");
    }
}
