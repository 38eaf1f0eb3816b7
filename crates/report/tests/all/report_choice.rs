//! Method choice by accuracy target (report issue): on a few scenes the method chosen from the
//! committed calibration table meets the target, and the next cheaper candidate does not, both
//! judged by actual runs against an MPFR run at target + 20 digits.

use periodic_contact::scene::parse::parse_scene;
use periodic_contact_report::calibration::{choose, Table};
use periodic_contact_report::choice::check_choice;
use periodic_contact_report::runner::{Knob, RunCache};

fn scene(name: &str) -> periodic_contact::scene::Scene {
    let p = format!("{}/scenes/{name}.toml", concat!(env!("CARGO_MANIFEST_DIR"), "/../.."));
    parse_scene(&std::fs::read_to_string(p).unwrap()).unwrap()
}

#[test]
fn chosen_method_meets_the_target_and_the_next_cheaper_does_not() {
    let table = Table::committed().unwrap();
    let cache = RunCache::default();
    // (scene, the method family expected to win)
    for (name, family) in [
        ("kuznetsov_parabola", "series"),
        ("sliding_wear", "series"),
        ("westergaard_sinusoid", "f64"),
        ("adhesion_nu045", "f64"),
    ] {
        let s = scene(name);
        let target = s.output.target_digits.unwrap();
        let c = check_choice(&table, &s.problem, target, &cache).unwrap();
        eprintln!(
            "{name}: {} ({:?}); cheaper {:?} ({:?})",
            c.choice.knob().label(),
            c.chosen_digits,
            c.choice.next_cheaper(),
            c.cheaper_digits
        );
        assert_eq!(c.choice.knob().method(), family, "{name}: {}", c.choice.why());
        assert!(
            c.chosen_meets(),
            "{name}: chosen {} reached {:?} < {target}",
            c.choice.knob().label(),
            c.chosen_digits
        );
        assert!(c.cheaper_misses(), "{name}: the cheaper {:?} reached {:?}", c.choice.next_cheaper(), c.cheaper_digits);
    }
}

#[test]
fn the_choice_is_deterministic_and_falls_back_to_verified_mpfr() {
    let table = Table::committed().unwrap();
    let s = scene("kuznetsov_parabola");
    assert_eq!(choose(&table, &s.problem, 12), choose(&table, &s.problem, 12));
    // 40 digits: beyond f64 and every series order at this size.
    assert_eq!(choose(&table, &s.problem, 40).knob(), Knob::MpfrVerified(40));
    // The table round-trips through its CSV.
    assert_eq!(Table::parse(&table.to_csv()).unwrap().rows, table.rows);
}
