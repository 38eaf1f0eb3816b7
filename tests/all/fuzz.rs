//! The differential fuzzer in CI (issue 34): cases 0..300 of seed 34 under the CI budget
//! (`examples/fuzz`: MPFR at 12 digits against verified MPFR at 18, the f64, series and Pade
//! methods, the loading law's f64 method against its MPFR at 10; every case's scaled twin), on
//! two threads. Every disagreement fails the test, printed with its scene. The issue asked for
//! 300 cases within 60 s; measured on this machine (2 logical CPUs shared with other sessions) in
//! docs/fuzzing.md, "Cost of a case": about 233 CPU seconds for the 300 in release since the
//! loading law's speed-up (310 before; Problem 2's verified solves are 80 % of it now), 352 s of
//! wall time on two threads at a load average of 6; this test 7 min 13 s (3 min 49 s of CPU) at a
//! load average of 6-7 before the speed-up: it is in the long tier (`scripts/test --long`). The same cases from the command line: `cargo run --release --example fuzz -- 300 34
//! --ci --jobs 2`.

#[allow(dead_code)]
#[path = "../../examples/fuzz/check.rs"]
mod check;
#[allow(dead_code)]
#[path = "../../examples/fuzz/generate.rs"]
mod generate;

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;

/// Cases and seed of the CI run.
const CASES: u64 = 300;
const SEED: u64 = 34;

#[test]
#[ignore = "long tier (2.5 to 8 minutes on 2 shared CPUs): scripts/test --long"]
fn fuzz_300_cases_agree() {
    let next = AtomicU64::new(0);
    let found = Mutex::new(Vec::<String>::new());
    let values = AtomicU64::new(0);
    let start = std::time::Instant::now();
    std::thread::scope(|scope| {
        for _ in 0..2 {
            scope.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                if i >= CASES {
                    break;
                }
                let case = generate::case(SEED, i);
                let out = check::run(&case, &check::Budget::CI);
                values.fetch_add(out.values_checked as u64, Ordering::Relaxed);
                let mut found = found.lock().unwrap();
                for d in out.disagreements {
                    found.push(format!("{d}\n{}", case.statement.toml()));
                }
                if let Some(e) = out.invalid {
                    found.push(format!("case {i}: invalid scene: {e}\n{}", case.statement.toml()));
                }
            });
        }
    });
    let found = found.into_inner().unwrap();
    let values = values.into_inner();
    eprintln!("fuzz: {CASES} cases, {values} printed values compared, {:.1} s", start.elapsed().as_secs_f64());
    assert!(found.is_empty(), "{} disagreements:\n{}", found.len(), found.join("\n"));
    assert!(values > 1000 * CASES / 100, "only {values} values compared");
}
