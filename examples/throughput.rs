//! Throughput for sweeps (issue 33, goal 5): solved contacts per second on every core, through
//! the library's batch entry point `api::solve_many` (one scene per thread at a time, std scoped
//! threads), for
//! - Problem 1 f64: `scenes/sliding_friction.toml` (periodic parabola, mu = 0.3) at loads
//!   P2 = 0.001 .. 0.1 (a geometric sweep of exact decimals);
//! - Problem 1 MPFR at 30 verified digits: the same scenes;
//! - Problem 2 f64: `scenes/adhesion_nu03.toml` (complete adhesion, nu = 0.3) at half-widths
//!   0.02 .. 0.4;
//! - Westergaard's sinusoid (Problem 1 frictionless, E* = D = L = 1, `scenes/westergaard_sinusoid.toml`
//!   with D = 1) at the loads of a/L = 0.05 and 0.25, f64: the job Tamaas's FFT boundary-element
//!   solver does; with `--tamaas PYTHON` the same contacts are solved by Tamaas 2.9
//!   (PolonskyKeerRey, tol 1e-10, one process per core) in the same run, at N = 2^10 .. 2^16, and
//!   each solver's error in the half-width a against the closed form P = pi E* D sin^2(pi a/L)
//!   is printed beside its rate (the errors differ by orders of magnitude: at matched accuracy
//!   Tamaas would need N far beyond 2^18).
//!
//! Each line: contacts solved / asked, wall time, contacts per second, the least digits claimed
//! (`digits_verified` or `digits_estimated` of every answer). Run:
//! `cargo run --release --example throughput [-- --scale K] [--tamaas PYTHON]` (K multiplies the
//! batch sizes; the figures are in docs/performance.md).

use periodic_contact::api::{parse_scene, solve_many, Method, Scene, SolveRequest};
use serde_json::Value;
use std::time::Instant;

/// Scenes from `base` with the value of `key` replaced by each of `values`.
fn batch(base: &str, key: &str, old: &str, values: &[String]) -> Vec<Scene> {
    let from = format!("{key} = \"{old}\"");
    assert!(base.contains(&from), "{from} not in the scene");
    values
        .iter()
        .map(|v| parse_scene(&base.replace(&from, &format!("{key} = \"{v}\""))).expect("a valid scene"))
        .collect()
}

/// `n` values from `lo` to `hi` in geometric steps, as 6-digit decimals.
fn geometric(lo: f64, hi: f64, n: usize) -> Vec<String> {
    (0..n)
        .map(|i| {
            let t = if n > 1 { i as f64 / (n - 1) as f64 } else { 0.0 };
            format!("{:.6e}", lo * (hi / lo).powf(t))
        })
        .collect()
}

fn digits(v: &Value) -> f64 {
    let get = |k: &str| v.get(k).and_then(Value::as_str).and_then(|s| s.parse::<f64>().ok());
    get("digits_verified").or_else(|| get("digits_estimated")).unwrap_or(f64::NAN)
}

/// Solves the batch on every core, prints its line and returns the answers (refusals left out).
fn run(label: &str, scenes: &[Scene], request: SolveRequest) -> Vec<Value> {
    let t = Instant::now();
    let results = solve_many(scenes, request, None);
    let secs = t.elapsed().as_secs_f64();
    let answers: Vec<Value> = results.into_iter().filter_map(Result::ok).map(|a| a.json).collect();
    let least = answers.iter().map(digits).fold(f64::INFINITY, f64::min);
    println!(
        "{label:<44} {:>5}/{:<5} {secs:>8.3} s {:>10.1} contacts/s  least digits claimed {least:.1}",
        answers.len(),
        scenes.len(),
        answers.len() as f64 / secs
    );
    answers
}

/// Westergaard's load per period at a/L (E* = D = L = 1): pi sin^2(pi a/L), as a 20-digit decimal.
fn westergaard_load(a_over_l: f64) -> String {
    let s = (std::f64::consts::PI * a_over_l).sin();
    format!("{:.19e}", std::f64::consts::PI * s * s)
}

/// Tamaas on the same contacts, one process per core (the script prints one line per N).
const TAMAAS: &str = r#"
import math, sys, time, multiprocessing as mp
import numpy as np
import tamaas as tm
def solve(job):
    N, aL = job
    tm.set_log_level(tm.LogLevel.error)
    pbar = math.pi * math.sin(math.pi * aL) ** 2
    model = tm.ModelFactory.createModel(tm.model_type.basic_1d, [1.0], [N])
    model.E, model.nu = 1.0, 0.0
    x = np.arange(N) / N
    solver = tm.PolonskyKeerRey(model, -np.cos(2 * np.pi * x), 1e-10)
    solver.max_iter = 20000
    solver.solve(pbar)
    p = np.array(model.traction).reshape(-1)
    s = x - 0.5
    idx = np.where((p > 0) & (s > 0))[0]
    k = idx[np.argsort(s[idx])][-4:]
    c = np.linalg.lstsq(np.vstack([s[k], np.ones_like(s[k])]).T, p[k] ** 2, rcond=None)[0]
    return abs(-c[1] / c[0] - aL) / aL
if __name__ == "__main__":
    cores, per = int(sys.argv[1]), int(sys.argv[2])
    print(f"tamaas {tm.__version__}, PolonskyKeerRey tol 1e-10, {cores} processes")
    with mp.Pool(cores) as pool:
        for N in (2**10, 2**12, 2**14, 2**16):
            jobs = [(N, (0.05, 0.25)[i % 2]) for i in range(max(cores, per // (N // 1024)))]
            t = time.perf_counter()
            errs = pool.map(solve, jobs, chunksize=1)
            dt = time.perf_counter() - t
            print(f"Westergaard, Tamaas N = {N:<6}                  {len(jobs):>5}/{len(jobs):<5} {dt:8.3f} s {len(jobs)/dt:10.1f} contacts/s  largest rel. error of a {max(errs):.1e}", flush=True)
"#;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let flag = |name: &str| args.iter().position(|a| a == name).and_then(|i| args.get(i + 1)).cloned();
    let scale: usize = flag("--scale").and_then(|s| s.parse().ok()).unwrap_or(1).max(1);
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    println!("threads: {cores} (std::thread::available_parallelism); batch sizes x{scale}");
    let f64_request = SolveRequest { method: Method::F64, digits: 30, series_order: 12 };
    let sliding = include_str!("../scenes/sliding_friction.toml");
    let loads = geometric(1e-3, 0.1, 400 * scale);
    run("Problem 1 f64 (parabola, mu = 0.3)", &batch(sliding, "normal_load", "0.01", &loads), f64_request);
    let loads = geometric(1e-3, 0.1, 40 * scale);
    let mpfr = SolveRequest { method: Method::Mpfr, digits: 30, series_order: 12 };
    run("Problem 1 MPFR 30 digits (the same)", &batch(sliding, "normal_load", "0.01", &loads), mpfr);
    let adhesion = include_str!("../scenes/adhesion_nu03.toml");
    let widths = geometric(0.02, 0.4, 400 * scale);
    run("Problem 2 f64 (parabola, nu = 0.3)", &batch(adhesion, "half_width", "0.1", &widths), f64_request);
    // Westergaard, D = 1: the two contact sizes alternating.
    let sinusoid =
        include_str!("../scenes/westergaard_sinusoid.toml").replace("amplitude = \"0.01\"", "amplitude = \"1\"");
    let sizes = [0.05, 0.25];
    let loads: Vec<String> = (0..400 * scale).map(|i| westergaard_load(sizes[i % 2])).collect();
    let answers = run("Westergaard, ours f64", &batch(&sinusoid, "normal_load", "0.005", &loads), f64_request);
    // The error of a (= l for this symmetric contact) against the closed form: 0 when the printed
    // value (13 significant digits) is the exact a.
    let errs: Vec<f64> = answers
        .iter()
        .zip(sizes.iter().cycle())
        .map(|(v, al)| {
            let l: f64 = v["l"].as_str().and_then(|s| s.parse().ok()).unwrap_or(f64::NAN);
            (l - al).abs() / al
        })
        .collect();
    let err = errs.iter().copied().fold(0.0f64, f64::max);
    assert!(errs.iter().all(|e| e.is_finite()), "an answer without a readable l");
    println!("  ours: largest rel. error of a against the closed form {err:.1e} (as printed, 13 significant digits)");
    if let Some(python) = flag("--tamaas") {
        let out = std::process::Command::new(python)
            .args(["-c", TAMAAS, &cores.to_string(), &(64 * scale).to_string()])
            .output()
            .expect("the Python of --tamaas runs");
        print!("{}", String::from_utf8_lossy(&out.stdout));
        eprint!("{}", String::from_utf8_lossy(&out.stderr));
    }
}
