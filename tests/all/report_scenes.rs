//! Scenes of the report: the `[sweep]` table (strict keys, exact values, validated) and the
//! shipped scene set (every `scenes/*.toml` parses).

use exact_series::Q;
use periodic_contact::model::SlidingLoad;
use periodic_contact::scene::{parse::parse_scene, SceneProblem, SweepParameter};

const BASE: &str = r#"
[problem]
kind = "sliding"
[material]
poisson_ratio = "0.3"
contact_modulus = "1"
[punch]
shape = "parabolic"
k = "1"
period = "1"
[sliding]
normal_load = "0.01"
[output]
target_digits = 12
"#;

fn q(n: i64, d: i64) -> Q {
    Q::new(n.into(), d.into())
}

#[test]
fn sweep_values_are_exact_and_replace_the_load() {
    let s = parse_scene(&format!("{BASE}[sweep]\nnormal_load = [\"1/1000\", 0.003, \"0.1\"]\n")).unwrap();
    let sw = s.sweep.as_ref().unwrap();
    assert_eq!(sw.parameter, SweepParameter::NormalLoad);
    assert_eq!(sw.values, vec![q(1, 1000), q(3, 1000), q(1, 10)]);
    assert_eq!(s.output.target_digits, Some(12));
    let probs = s.sweep_problems();
    assert_eq!(probs.len(), 3);
    let SceneProblem::Sliding(p) = &probs[1] else { panic!("sliding") };
    assert_eq!(*p.load(), SlidingLoad::NormalLoad(q(3, 1000)));
    // The scene's own load is kept for `solve`.
    let SceneProblem::Sliding(p0) = &s.problem else { panic!("sliding") };
    assert_eq!(*p0.load(), SlidingLoad::NormalLoad(q(1, 100)));
}

#[test]
fn sweep_errors_name_the_key() {
    let cases = [
        ("[sweep]\nload = [\"1\"]\n", "sweep.load"),
        ("[sweep]\nnormal_load = [\"0.1\"]\nhalf_length = [\"0.1\"]\n", "sweep"),
        ("[sweep]\nnormal_load = []\n", "sweep.normal_load"),
        ("[sweep]\nnormal_load = \"0.1\"\n", "sweep.normal_load"),
        ("[sweep]\nnormal_load = [\"0.1\", \"-1\"]\n", "sweep.normal_load[1]"),
        ("[sweep]\nnormal_load = [\"x\"]\n", "sweep.normal_load[0]"),
        ("[sweep]\nhalf_width = [\"0.1\"]\n", "sweep.half_width"),
        ("sweep = 3\n", "sweep"),
    ];
    for (extra, param) in cases {
        let text = if extra.starts_with("sweep =") {
            BASE.replacen("[problem]", &format!("{extra}[problem]"), 1)
        } else {
            format!("{BASE}{extra}")
        };
        let e = parse_scene(&text).unwrap_err();
        assert_eq!(e.parameter, param, "{extra}: {e}");
    }
}

#[test]
fn every_shipped_scene_parses() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes");
    let mut n = 0;
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_some_and(|x| x == "toml") {
            let s =
                parse_scene(&std::fs::read_to_string(&p).unwrap()).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
            assert!(s.sweep.is_some(), "{}: every shipped scene carries a sweep", p.display());
            n += 1;
        }
    }
    assert!(n >= 8);
}
