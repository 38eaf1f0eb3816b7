//! Issue 30 (a user's front page): the inconsistencies a new user trips over, each fixed and
//! checked here through the library (`solve` as the command line runs it, without the binary):
//! one small-slope rule for every shape in both problems (docs/theory.md section 9), the
//! `convention_note` of a `paper` answer that does not close, the f64 method's digits keys,
//! `worn_area_per_distance` from every method of Problem 1 (docs/theory.md section 14), the
//! templates' accuracy default, and tension zones next to the edge. Run:
//! `cargo test --test all front_page::`.

use periodic_contact::scene::keys::{template, Kind};
use periodic_contact::scene::parse::parse_scene;
use periodic_contact::scene::Method;
use periodic_contact::solve::choice::{solve_choice, Forced};
use periodic_contact::solve::{solve_scene, SolveRequest};
use serde_json::Value;

/// lambda = pi l/L = 1.2 at L = 1, to 20 digits.
const SIZE: &str = "0.38197186342054880584";

fn scene(kind: &str, punch: &str, size_key: &str, extra: &str) -> String {
    format!(
        "[problem]\nkind = \"{kind}\"\n[material]\npoisson_ratio = \"0.3\"\ncontact_modulus = \"1\"\n\
         [punch]\n{punch}\nperiod = \"1\"\n[{kind}]\n{size_key} = \"{SIZE}\"\n{extra}"
    )
}

fn solve(text: &str, method: Method, digits: u32) -> Result<Value, String> {
    let s = parse_scene(text).map_err(|e| e.to_string())?;
    solve_scene(&s, SolveRequest { method, digits, series_order: 12 }).map_err(|e| e.to_string())
}

fn warnings(v: &Value) -> Vec<String> {
    v["warnings"].as_array().into_iter().flatten().filter_map(|w| w.as_str().map(String::from)).collect()
}

fn slope_warnings(v: &Value) -> Vec<String> {
    warnings(v).into_iter().filter(|w| w.starts_with("small slope")).collect()
}

/// The acceptance case: the parabola k = 1 and the polynomial ["0", "0", "1"] (the same
/// profile) at lambda = 1.2, L = 1 (g'(a) = 0.764) get the same verdict, in both problems and by
/// both methods: solved, the same contact and load, the same small-slope warning.
#[test]
fn parabola_and_the_same_polynomial_get_the_same_verdict() {
    let parabola = "shape = \"parabolic\"\nk = \"1\"";
    let polynomial = "shape = \"polynomial\"\ncoefficients = [\"0\", \"0\", \"1\"]";
    for (kind, size_key) in [("sliding", "half_length"), ("adhesion", "half_width")] {
        for method in [Method::F64, Method::Mpfr] {
            let a = solve(&scene(kind, parabola, size_key, ""), method, 15).unwrap();
            let b = solve(&scene(kind, polynomial, size_key, ""), method, 15).unwrap();
            let (pa, pb) = (a["P2"].as_str().unwrap(), b["P2"].as_str().unwrap());
            let (x, y): (f64, f64) = (pa.parse().unwrap(), pb.parse().unwrap());
            assert!((x - y).abs() <= 1e-13 * x, "{kind} {method:?}: P2 {pa} vs {pb}");
            let (wa, wb) = (slope_warnings(&a), slope_warnings(&b));
            assert_eq!(wa.len(), 1, "{kind} {method:?}: {a}");
            assert_eq!(wa, wb, "{kind} {method:?}");
            assert!(wa[0].contains("|g'| = 0.76394") && wa[0].contains("0.5"), "{}", wa[0]);
        }
    }
    // Below the limit (lambda = 0.6: g'(a) = 0.38) neither is warned.
    let small = |punch: &str| scene("sliding", punch, "half_length", "").replace(SIZE, "0.19098593171027440292");
    for punch in [parabola, polynomial] {
        assert!(slope_warnings(&solve(&small(punch), Method::F64, 15).unwrap()).is_empty(), "{punch}");
    }
}

/// The same rule for the sinusoid (its g' peaks at L/4 inside a wide contact), the circle and the
/// loading law, and for a load-driven polynomial contact past the old refusal.
#[test]
fn every_shape_is_warned_not_refused_beyond_the_small_slope() {
    let cases = [
        // Sinusoid D = 0.1, L = 1: max g' = 2 pi D/L = 0.628 at x = L/4 (inside a contact of l = 0.38).
        scene("sliding", "shape = \"sinusoidal\"\namplitude = \"0.1\"", "half_length", ""),
        // Circle R = 1/2 at l = 0.3: g' = 0.3/0.4 = 0.75.
        scene("sliding", "shape = \"circular\"\nradius = \"1/2\"", "half_length", "").replace(SIZE, "0.3"),
        scene("adhesion", "shape = \"circular\"\nradius = \"1/2\"", "half_width", "").replace(SIZE, "0.3"),
        // The quartic x^2 + x^4 under a load whose contact passes g' = 1/2 (a = 0.34: g' = 0.83).
        scene(
            "adhesion",
            "shape = \"polynomial\"\ncoefficients = [\"0\", \"0\", \"1\", \"0\", \"1\"]",
            "normal_load",
            "",
        )
        .replace(SIZE, "0.3"),
        scene(
            "sliding",
            "shape = \"polynomial\"\ncoefficients = [\"0\", \"0\", \"1\", \"0\", \"1\"]",
            "normal_load",
            "",
        )
        .replace(SIZE, "0.3"),
    ];
    for text in &cases {
        let v = solve(text, Method::F64, 15).unwrap_or_else(|e| panic!("{e}\n{text}"));
        let w = slope_warnings(&v);
        assert_eq!(w.len(), 1, "{v}\n{text}");
    }
    let sinusoid = solve(&cases[0], Method::F64, 15).unwrap();
    assert!(
        slope_warnings(&sinusoid)[0].contains("at x = 0.25") || slope_warnings(&sinusoid)[0].contains("at x = -0.25")
    );
    // The loading law (a parabola, asymmetric contact [-a, b]).
    let law = "[problem]\nkind = \"adhesion\"\n[material]\npoisson_ratio = \"0.3\"\ncontact_modulus = \"1\"\n\
               [punch]\nshape = \"parabolic\"\nk = \"1\"\nperiod = \"1\"\n[adhesion]\ntangential_ratio = \"1/5\"\n\
               half_length = \"0.35\"\n";
    let v = solve(law, Method::F64, 12).unwrap();
    assert_eq!(slope_warnings(&v).len(), 1, "{v}");
}

/// `paper` with friction, wear or adhesive friction over a period says that `periodic` closes
/// the surface and how to ask for it; `periodic`, the frictionless case and the single punch do not.
#[test]
fn paper_answers_that_do_not_close_point_to_periodic() {
    let parabola = "shape = \"parabolic\"\nk = \"1\"";
    let small = |extra: &str| scene("sliding", parabola, "normal_load", extra).replace(SIZE, "0.05");
    for (extra, expected) in [
        ("friction = \"0.3\"\n", true),
        ("wear = \"0.4\"\n", true),
        ("adhesive_friction = \"0.01\"\n", true),
        ("", false),
    ] {
        for method in [Method::F64, Method::Mpfr, Method::Series] {
            let v = solve(&small(extra), method, 12).unwrap();
            let note = v["convention_note"].as_str();
            assert_eq!(note.is_some(), expected, "{extra} {method:?}: {v}");
            if let Some(n) = note {
                assert!(n.contains("--convention periodic") && n.contains("convention = \"periodic\""), "{n}");
            }
        }
        let periodic = small(extra).replace("[problem]\n", "[problem]\nconvention = \"periodic\"\n");
        assert!(solve(&periodic, Method::F64, 12).unwrap()["convention_note"].is_null());
        let single = small(extra).replace("period = \"1\"", "period = \"inf\"");
        assert!(solve(&single, Method::F64, 12).unwrap()["convention_note"].is_null());
    }
    // The loading law with a tangential load in `paper` too.
    let law = "[problem]\nkind = \"adhesion\"\n[material]\npoisson_ratio = \"0.3\"\ncontact_modulus = \"1\"\n\
               [punch]\nshape = \"parabolic\"\nk = \"1\"\nperiod = \"1\"\n[adhesion]\ntangential_ratio = \"1/5\"\n\
               half_length = \"0.1\"\n";
    assert!(solve(law, Method::F64, 12).unwrap()["convention_note"].is_string());
}

/// `--method f64` with no digits asked states 15, what f64 carries; with 30 asked it states 30
/// and `digits_note` says that f64 gives at most 15 and how to get more.
#[test]
fn f64_states_what_was_asked_and_what_it_can_give() {
    for path in ["scenes/kuznetsov_parabola.toml", "scenes/adhesion_nu03.toml", "scenes/adhesion_loading_law.toml"] {
        let text = std::fs::read_to_string(path).unwrap();
        let no_target: String = text
            .lines()
            .filter(|l| !l.starts_with("target_digits") && !l.starts_with("digits"))
            .collect::<Vec<_>>()
            .join("\n");
        let s = parse_scene(&no_target).unwrap();
        let forced = |digits| Forced { method: Some(Method::F64), digits, series_order: None };
        let c = solve_choice(&s, forced(None)).unwrap();
        let v = solve_scene(&s, c.request).unwrap();
        assert_eq!(v["digits_requested"], "15", "{path}");
        assert!(v["digits_note"].is_null(), "{path}");
        let c = solve_choice(&s, forced(Some(30))).unwrap();
        let v = solve_scene(&s, c.request).unwrap();
        assert_eq!(v["digits_requested"], "30", "{path}");
        let note = v["digits_note"].as_str().unwrap_or_else(|| panic!("{path}: {v}"));
        assert!(note.contains("30 digits were asked") && note.contains("at most 15") && note.contains("--method mpfr"));
    }
}

/// `worn_area_per_distance` = cW P2 is printed by every method of Problem 1, and they agree.
#[test]
fn worn_area_is_printed_by_every_method() {
    let s = parse_scene(&std::fs::read_to_string("scenes/sliding_wear.toml").unwrap()).unwrap();
    let mut values = Vec::new();
    for method in [Method::Mpfr, Method::F64, Method::Series, Method::Pade] {
        let v = solve_scene(&s, SolveRequest { method, digits: 20, series_order: 12 }).unwrap();
        let w: f64 = v["worn_area_per_distance"].as_str().unwrap_or_else(|| panic!("{method:?}: {v}")).parse().unwrap();
        let p2: f64 = v["P2"].as_str().unwrap().parse().unwrap();
        // cW = 0.4.
        assert!((w - 0.4 * p2).abs() <= 1e-14 * w, "{method:?}: {w} vs 0.4 x {p2}");
        values.push(w);
    }
    assert!(values.iter().all(|w| (w - values[0]).abs() <= 1e-14 * values[0]), "{values:?}");
}

/// A copied template runs what `solve` runs without it (verified MPFR at 30 digits), not 8 digits
/// silently: target_digits is shown commented out with its meaning. The sliding templates say
/// that the series method refuses a polynomial or circular punch, and it does.
#[test]
fn templates_default_to_solve_and_state_the_series_shapes() {
    for (kind, shape) in [
        (Kind::Sliding, "parabolic"),
        (Kind::Sliding, "polynomial"),
        (Kind::Adhesion, "circular"),
        (Kind::Law, "parabolic"),
    ] {
        let text = template(kind, shape).unwrap();
        assert!(text.contains("\n# target_digits = 8\n"), "{kind:?} {shape}:\n{text}");
        assert!(!text.lines().any(|l| l.starts_with("target_digits")));
        let s = parse_scene(&text).unwrap();
        let c = solve_choice(&s, Forced::default()).unwrap();
        assert_eq!((c.request.method, c.request.digits), (Method::Mpfr, 30), "{kind:?} {shape}");
    }
    let text = template(Kind::Sliding, "polynomial").unwrap();
    let flat = text.replace("\n# ", " ");
    assert!(flat.contains("a polynomial or circular punch is refused"), "{text}");
    let forced = text.replace("# method = \"f64\"", "method = \"series\"");
    let s = parse_scene(&forced).unwrap();
    let c = solve_choice(&s, Forced::default()).unwrap();
    let e = solve_scene(&s, c.request).unwrap_err().to_string();
    assert!(e.contains("punch.shape") && e.contains("polynomial"), "{e}");
}

/// Tension zones next to the edge (nu = 0: the second zone is 1 - x/a ~ 1e-27 wide of the edge):
/// their ends print distinct from 1 and from each other, with 1 - x/a beside them.
#[test]
fn tension_zones_next_to_the_edge_print_distinct_ends() {
    let s = parse_scene(&std::fs::read_to_string("scenes/adhesion_nu0.toml").unwrap()).unwrap();
    let v = solve_scene(&s, SolveRequest { method: Method::Mpfr, digits: 10, series_order: 12 }).unwrap();
    let zones = v["tension_zones"].as_array().unwrap();
    assert_eq!(zones.len(), 2, "{v}");
    for z in zones {
        let (from, to) = (z["from_x_over_a"].as_str().unwrap(), z["to_x_over_a"].as_str().unwrap());
        assert_ne!(from, to, "{z}");
        for (x, delta) in [(from, "from_1_minus_x_over_a"), (to, "to_1_minus_x_over_a")] {
            assert!(!x.starts_with("1.0"), "{z}");
            let d: f64 = z[delta].as_str().unwrap().parse().unwrap();
            assert!(d > 0.0 && d < 1e-2, "{z}");
        }
    }
}
