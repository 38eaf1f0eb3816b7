//! Reliability of the command line: random argument lists never panic in parsing or validation.

use clap::Parser;
use periodic_contact_cli::{args::RawArgs, config::RunConfig};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

fn runner(seed: u8, cases: u32) -> TestRunner {
    let config = Config { cases, failure_persistence: None, ..Config::default() };
    TestRunner::new_with_rng(config, TestRng::from_seed(RngAlgorithm::ChaCha, &[seed; 32]))
}

#[test]
fn command_line_never_panics() {
    let word = prop_oneof![
        Just("series".to_string()),
        Just("solve".to_string()),
        Just("report".to_string()),
        Just("kernel".to_string()),
        Just("weight".to_string()),
        Just("sliding".to_string()),
        Just("--order".to_string()),
        Just("--theta".to_string()),
        Just("--xh".to_string()),
        Just("--T".to_string()),
        Just("--digits".to_string()),
        Just("--format".to_string()),
        Just("json".to_string()),
        "-?[0-9]{0,12}(/[0-9]{0,5})?".prop_map(|s| s),
        "[ -~]{0,8}".prop_map(|s| s),
    ];
    let strat = proptest::collection::vec(word, 0..7);
    runner(22, 600)
        .run(&strat, |words| {
            let mut argv = vec!["periodic-contact".to_string()];
            argv.extend(words);
            if let Ok(raw) = RawArgs::try_parse_from(&argv) {
                // Validation must not panic either (no computation happens here, except reading
                // a scene file that does not exist).
                let _ = RunConfig::from_args(raw);
            }
            Ok(())
        })
        .unwrap();
}
