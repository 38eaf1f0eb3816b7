//! The scene parser: exact numbers, strict keys, clear errors.

use exact_series::Q;
use periodic_contact::model::OnPunchRow;
use periodic_contact::model::{Period, PunchShape, SlidingLoad};
use periodic_contact::scene::{parse::parse_scene, SceneProblem};

const BASE: &str = r#"
[problem]
kind = "sliding"
[material]
poisson_ratio = "0.25"
contact_modulus = 2
[punch]
shape = "parabolic"
k = 0.1
period = "1/3"
[sliding]
normal_load = 1e-3
friction = "0.3"
[output]
digits = 30
points = ["-0.6", 0.1, "7/10"]
"#;

fn q(n: i64, d: i64) -> Q {
    Q::new(n.into(), d.into())
}

#[test]
fn numbers_are_read_exactly_quoted_or_not() {
    let s = parse_scene(BASE).unwrap();
    let SceneProblem::Sliding(p) = &s.problem else { panic!("sliding") };
    assert_eq!(*p.material().poisson_ratio(), q(1, 4));
    assert_eq!(*p.material().contact_modulus(), q(2, 1));
    assert_eq!(*p.shape(), PunchShape::Parabolic { k: q(1, 10) });
    assert_eq!(*p.period(), Period::Finite(q(1, 3)));
    assert_eq!(*p.load(), SlidingLoad::NormalLoad(q(1, 1000)));
    assert_eq!(*p.friction(), q(3, 10));
    assert_eq!(s.output.points, vec![q(-3, 5), q(1, 10), q(7, 10)]);
    assert_eq!(s.output.digits, Some(30));
}

fn err(text: &str) -> String {
    parse_scene(text).unwrap_err().to_string()
}

#[test]
fn errors_name_the_parameter_value_and_range() {
    let cases = [
        (BASE.replace("digits = 30", "digits = 30\ncolour = \"red\""), "output.colour"),
        (BASE.replace("\"0.25\"", "\"0.75\""), "poisson_ratio = 3/4: must lie in [0, 1/2]"),
        (BASE.replace("contact_modulus = 2", "contact_modulus = 2\nyoungs_modulus = 3"), "not both"),
        (BASE.replace("k = 0.1", "k = -1"), "punch.k = -1: must be > 0"),
        (BASE.replace("period = \"1/3\"", "period = 0"), "punch.period = 0: must be > 0"),
        (BASE.replace("\"7/10\"", "\"1\""), "output.points[2] = 1: must lie in (-1, 1)"),
        (BASE.replace("friction = \"0.3\"", "friction = \"-0.3\""), "sliding.friction = -3/10: must be >= 0"),
        (BASE.replace("normal_load = 1e-3", ""), "give normal_load or half_length"),
        (BASE.replace("normal_load = 1e-3", "half_length = \"1/5\""), "2 l < L = 1/3"),
        (
            BASE.replace("digits = 30", "digits = 1000000000"),
            "output.digits = 1000000000: must be an integer in [1, 1000]",
        ),
        (BASE.replace("digits = 30", "digits = 0"), "output.digits = 0"),
        (BASE.replace("[sliding]", "[sliding\n"), "malformed TOML"),
        (BASE.replace("k = 0.1", "k = \"abc\""), "punch.k = abc: must be an exact number"),
        (BASE.replace("k = 0.1", "k = nan"), "punch.k = nan"),
        (BASE.replace("\"sliding\"", "\"rolling\""), "problem.kind = rolling"),
        (
            BASE.replace("shape = \"parabolic\"\nk = 0.1", "shape = \"sinusoidal\"\namplitude = 0.1")
                .replace("\"1/3\"", "\"inf\""),
            "finite period",
        ),
    ];
    for (text, needle) in cases {
        let e = err(&text);
        assert!(e.contains(needle), "expected {needle:?} in {e:?}");
    }
}

#[test]
fn single_punch_and_sinusoid() {
    let s = parse_scene(&BASE.replace("\"1/3\"", "\"inf\"")).unwrap();
    let SceneProblem::Sliding(p) = &s.problem else { panic!("sliding") };
    assert_eq!(*p.period(), Period::Infinite);
    let s =
        parse_scene(&BASE.replace("shape = \"parabolic\"\nk = 0.1", "shape = \"sinusoidal\"\namplitude = \"0.01\""))
            .unwrap();
    let SceneProblem::Sliding(p) = &s.problem else { panic!("sliding") };
    assert_eq!(*p.shape(), PunchShape::Sinusoidal { amplitude: q(1, 100) });
}

/// `[adhesion] friction` (issue 32): absent is complete adhesion, "1/2" is read exactly, mu <= 0
/// and a loading-law scene are refused naming the key.
#[test]
fn adhesion_friction_key() {
    let scene = |extra: &str| {
        format!(
            "[problem]\nkind = \"adhesion\"\n[material]\npoisson_ratio = \"0\"\ncontact_modulus = \"1\"\n[punch]\n\
             shape = \"parabolic\"\nk = \"1\"\nperiod = \"inf\"\n[adhesion]\nhalf_width = \"1\"\n{extra}"
        )
    };
    let friction = |text: &str| match parse_scene(text).unwrap().problem {
        SceneProblem::Adhesion(p) => p.friction().cloned(),
        other => panic!("{other:?}"),
    };
    assert_eq!(friction(&scene("")), None);
    assert_eq!(friction(&scene("friction = \"1/2\"")), Some(q(1, 2)));
    for bad in ["0", "-1/2"] {
        let e = err(&scene(&format!("friction = \"{bad}\"")));
        assert!(e.contains("adhesion.friction") && e.contains(bad) && e.contains("> 0"), "{e}");
    }
    let law =
        scene("friction = \"1/2\"").replace("half_width = \"1\"", "tangential_ratio = \"1/5\"\nhalf_length = \"1\"");
    assert!(err(&law).contains("friction"), "{}", err(&law));
}
