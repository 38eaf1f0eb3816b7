//! Differential fuzzing of every method against verified MPFR at more digits (issue 34).
//!
//! `cargo run --release --example fuzz -- N SEED [--ci] [--jobs J] [--from I]` generates cases
//! SEED:I .. SEED:I+N-1 (`generate.rs`: every problem, shape, convention and option, sizes from
//! lambda = 1e-12 past the physical limit, loads near every limit, inputs over decades), runs
//! every check of `check.rs` on each (same verdict; printed values hold their claimed digits
//! against the truth; refusals agree with the closed forms; exact scaling laws), prints every
//! disagreement and the tally (cases, per-method answers and refusals by reason). `--ci` uses
//! the CI test's budget (fewer digits); `--jobs` runs cases on J threads; `--show I` prints the
//! scene of case I and its twin; `--tally FILE` writes the tally so far every 100 cases. Exit 1 when a
//! disagreement was found. The tally of the 10,000-case run is in docs/fuzzing.md.

#[allow(dead_code)]
mod check;
mod generate;

use std::collections::BTreeMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: fuzz N SEED [--ci] [--jobs J] [--from I] [--show I] [--tally FILE] [--times FILE]";
    let n: u64 = args.first().and_then(|s| s.parse().ok()).unwrap_or_else(|| {
        eprintln!("{usage}");
        std::process::exit(2)
    });
    let seed: u64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or_else(|| {
        eprintln!("{usage}");
        std::process::exit(2)
    });
    if let Some(i) = args.iter().position(|a| a == "--show").and_then(|i| args.get(i + 1)).and_then(|s| s.parse().ok())
    {
        // The scene of case SEED:I and its scaled twin.
        let case = generate::case(seed, i);
        println!("# case {i}: {}\n{}", case.statement.note, case.statement.toml());
        println!("# twin\n{}", case.statement.scaled(&case.scaling).toml());
        return;
    }
    let flag =
        |name: &str| args.iter().position(|a| a == name).and_then(|i| args.get(i + 1)).and_then(|s| s.parse().ok());
    let mut budget = if args.iter().any(|a| a == "--ci") { check::Budget::CI } else { check::Budget::FULL };
    // Overrides of the budget (for profiling): --digits D --truth T --law L --series-every K.
    let digits = |name: &str, d: u32| flag(name).map_or(d, |x: u64| x as u32);
    budget.digits = digits("--digits", budget.digits);
    budget.truth_digits = digits("--truth", budget.truth_digits);
    budget.law_digits = digits("--law", budget.law_digits);
    budget.series_every = flag("--series-every").unwrap_or(budget.series_every);
    let jobs: u64 = flag("--jobs").unwrap_or(1).max(1);
    let from: u64 = flag("--from").unwrap_or(0);
    let tally_path: Option<String> = args.iter().position(|a| a == "--tally").and_then(|i| args.get(i + 1)).cloned();
    // `--times FILE`: one line per case (index, problem, note, seconds in all and per run).
    let times: Option<Mutex<std::fs::File>> = args
        .iter()
        .position(|a| a == "--times")
        .and_then(|i| args.get(i + 1))
        .map(|p| Mutex::new(std::fs::File::create(p).expect("--times FILE can be created")));
    let start = std::time::Instant::now();
    let next = AtomicU64::new(from);
    let tally = Mutex::new(Tally::default());
    std::thread::scope(|scope| {
        for _ in 0..jobs {
            scope.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                if i >= from + n {
                    break;
                }
                let case = generate::case(seed, i);
                let t = std::time::Instant::now();
                let out = check::run(&case, &budget);
                let secs = t.elapsed().as_secs_f64();
                if let Some(f) = &times {
                    use std::io::Write as _;
                    let runs: Vec<String> = out.runs.iter().map(|r| format!("{}={:.3}", r.method, r.seconds)).collect();
                    let line = format!(
                        "{i}\t{secs:.3}\t{:?}\ttwin={:.3} {}\t{}\n",
                        case.statement.problem,
                        out.twin_seconds,
                        runs.join(" "),
                        case.statement.note
                    );
                    let _ = f.lock().unwrap().write_all(line.as_bytes());
                }
                let mut tally = tally.lock().unwrap();
                for d in &out.disagreements {
                    println!("DISAGREEMENT {d}\n  scene:\n{}", indent(&case.statement.toml()));
                }
                if let Some(e) = &out.invalid {
                    println!("INVALID case {i}: {e}\n{}", indent(&case.statement.toml()));
                }
                tally.add(&case, &out, secs);
                if let (Some(path), true) = (&tally_path, tally.cases % 100 == 0) {
                    // The tally so far (a long run may be stopped): written whole, then renamed.
                    let text = tally.text(seed, from, n, budget, jobs, start.elapsed().as_secs_f64());
                    let tmp = format!("{path}.tmp");
                    if std::fs::write(&tmp, text).is_ok() {
                        let _ = std::fs::rename(&tmp, path);
                    }
                }
                if tally.cases % 100 == 0 {
                    eprintln!(
                        "{} cases, {} disagreements, {:.0} s",
                        tally.cases,
                        tally.disagreements,
                        start.elapsed().as_secs_f64()
                    );
                }
            });
        }
    });
    let tally = tally.into_inner().unwrap();
    print!("{}", tally.text(seed, from, n, budget, jobs, start.elapsed().as_secs_f64()));
    if tally.disagreements > 0 {
        std::process::exit(1);
    }
}

fn indent(s: &str) -> String {
    s.lines().map(|l| format!("    {l}\n")).collect()
}

#[derive(Default)]
struct Tally {
    cases: u64,
    per_problem: BTreeMap<String, u64>,
    /// (method, verdict label) -> count.
    verdicts: BTreeMap<(String, String), u64>,
    disagreements: u64,
    values: u64,
    invalid: u64,
    slowest: (f64, u64),
    /// method -> (runs, seconds).
    seconds: BTreeMap<String, (u64, f64)>,
}

impl Tally {
    fn add(&mut self, case: &generate::Case, out: &check::Outcome, secs: f64) {
        self.cases += 1;
        *self.per_problem.entry(format!("{:?}", case.statement.problem)).or_default() += 1;
        for r in &out.runs {
            let method = r.method.split('@').next().unwrap_or(&r.method).to_string();
            let method = if r.method.contains("truth") { format!("{method} (truth)") } else { method };
            let t = self.seconds.entry(method.clone()).or_default();
            t.0 += 1;
            t.1 += r.seconds;
            *self.verdicts.entry((method, r.verdict.label())).or_default() += 1;
        }
        self.disagreements += out.disagreements.len() as u64;
        self.values += out.values_checked as u64;
        self.invalid += out.invalid.is_some() as u64;
        if secs > self.slowest.0 {
            self.slowest = (secs, case.index);
        }
    }

    fn text(&self, seed: u64, from: u64, n: u64, budget: check::Budget, jobs: u64, secs: f64) -> String {
        let mut s = format!(
            "fuzz: {} cases (seed {seed}, cases {from}..{}), budget {budget:?}, {jobs} thread(s), {secs:.0} s\n",
            self.cases,
            from + n
        );
        s += &format!("problems: {:?}\n", self.per_problem);
        s += &format!(
            "printed values checked: {}; invalid scenes: {}; disagreements: {}; slowest case {} ({:.1} s)\n",
            self.values, self.invalid, self.disagreements, self.slowest.1, self.slowest.0
        );
        for (m, (runs, t)) in &self.seconds {
            s += &format!("time {m}: {runs} runs, {t:.1} s\n");
        }
        s += "| method | verdict | cases |\n|---|---|---:|\n";
        for ((m, v), c) in &self.verdicts {
            s += &format!("| {m} | {v} | {c} |\n");
        }
        s
    }
}
