//! `periodic-contact scene --template` (issue 15): every template parses and solves, every key
//! the parser accepts appears in some template, and the commands' `--help` stand on their own.

use super::common;
use common::{run, scene_file};
use periodic_contact::scene::keys::KEYS;

/// Every valid (template, shape, law) combination.
const TEMPLATES: &[(&str, &str, bool)] = &[
    ("sliding", "parabola", false),
    ("sliding", "sinusoid", false),
    ("sliding", "polynomial", false),
    ("sliding", "circular", false),
    ("adhesion", "parabola", false),
    ("adhesion", "polynomial", false),
    ("adhesion", "circular", false),
    ("adhesion", "parabola", true),
];

fn template(kind: &str, shape: &str, law: bool) -> String {
    let mut args = vec!["scene", "--template", kind, "--shape", shape];
    if law {
        args.push("--law");
    }
    let (code, out, err) = run(&args);
    assert_eq!(code, 0, "{args:?}: {err}");
    out
}

#[test]
fn each_template_parses_and_solves() {
    for &(kind, shape, law) in TEMPLATES {
        let text = template(kind, shape, law);
        periodic_contact::scene::parse::parse_scene(&text).unwrap_or_else(|e| panic!("{kind} {shape}: {e}\n{text}"));
        let path = scene_file(&format!("template_{kind}_{shape}_{law}.toml"), &text);
        let (code, out, err) = run(&["solve", &path, "--digits", "6", "--json"]);
        assert_eq!(code, 0, "{kind} {shape} law={law}: {err}\n{text}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        assert!(v["P2"].is_string(), "{kind} {shape}: {out}");
    }
}

#[test]
fn every_key_the_parser_accepts_appears_in_a_template() {
    let texts: Vec<String> = TEMPLATES.iter().map(|&(k, s, l)| template(k, s, l)).collect();
    for key in KEYS {
        let found = texts.iter().any(|t| {
            let Some(start) = t.find(&format!("\n[{}]\n", key.table)) else { return false };
            let section = &t[start + 1..];
            let section = &section[..section[1..].find("\n[").map_or(section.len(), |e| e + 1)];
            section.lines().any(|l| {
                let l = l.strip_prefix("# ").unwrap_or(l);
                l.starts_with(&format!("{} = ", key.name))
            })
        });
        assert!(found, "[{}] {} is in no template", key.table, key.name);
        // Each key says what it means, its unit and its range.
        assert!(!key.meaning.is_empty() && !key.unit.is_empty() && !key.range.is_empty());
    }
}

#[test]
fn commented_keys_parse_when_set() {
    // Setting an optional key from the template (one at a time) keeps a valid scene: the examples
    // are valid values. Alternatives (give one, not both) are swapped in for the key they replace.
    let text = template("sliding", "parabola", false);
    for (from, to) in [
        ("# convention = \"paper\"", "convention = \"periodic\""),
        ("# adhesive_friction = \"0\"", "adhesive_friction = \"0\""),
        ("# wear = \"0\"", "wear = \"0\""),
        ("# speed = \"1\"", "speed = \"1\""),
        ("# method = \"f64\"", "method = \"f64\""),
        ("# series_order = 12", "series_order = 12"),
    ] {
        assert!(text.contains(from), "{from}");
        let t = text.replace(from, to);
        periodic_contact::scene::parse::parse_scene(&t).unwrap_or_else(|e| panic!("{to}: {e}"));
    }
    let swapped = text
        .replace("normal_load = \"0.005\"\n", "# normal_load\n")
        .replace("# half_length = \"0.05\"", "half_length = \"0.05\"");
    periodic_contact::scene::parse::parse_scene(&swapped).unwrap();
}

#[test]
fn invalid_template_requests_are_input_errors() {
    for (args, needle) in [
        (vec!["scene", "--template", "adhesion", "--shape", "sinusoid"], "--shape"),
        (vec!["scene", "--template", "adhesion", "--shape", "circular", "--law"], "parabolic"),
        (vec!["scene", "--template", "sliding", "--law"], "--law"),
        (vec!["scene", "--template", "wear"], "possible values"),
    ] {
        let (code, out, err) = run(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(out.is_empty() && err.contains(needle), "{args:?}: {err}");
    }
}

#[test]
fn help_is_enough_to_use_each_command() {
    let (code, out, _) = run(&["solve", "--help"]);
    assert_eq!(code, 0);
    assert!(!out.contains("latex") && !out.to_lowercase().contains("align"), "solve offers text or json only:\n{out}");
    for needle in ["target_digits", "--method", "--digits", "scene --template", "Exit codes"] {
        assert!(out.contains(needle), "solve --help lacks {needle}:\n{out}");
    }
    let (_, out, _) = run(&["scene", "--help"]);
    for needle in ["--template", "--shape", "--law", "unit", "range"] {
        assert!(out.contains(needle), "scene --help lacks {needle}:\n{out}");
    }
    let (code, _, err) = run(&["solve", "x.toml", "--format", "latex"]);
    assert_eq!(code, 2, "{err}");
}
