//! The peer-benchmark job (shared/peers/series_*.py): f(x) = (sin x / x)^(1/2 + theta) with theta
//! symbolic (coefficients in Q[theta]) to N coefficients, and the reversion of y = x f(x); also the
//! same job at theta = 1/3 over Q. Prints one JSON line per N with the best of `--repeat` runs
//! (seconds) and the x^7 reversion coefficient as a correctness stamp. The timed regions start
//! from the series of sin x / x, built before them (as the python-flint jobs do; SymPy's job
//! builds its input inside its timed region, with `rs_sin`).
//!
//! With `--q` only the job over Q is run (for a profile of the Q path alone); the symbolic
//! figures are then printed as `null`.
//!
//! Run: `cargo run --release -p exact-series --example sinc_power -- [--repeat R] [--q] 30 60 100`

use exact_series::{Poly, Ring, Series, Q};
use std::time::Instant;

fn best<T>(repeat: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut best = f64::INFINITY;
    let mut out = None;
    for _ in 0..repeat.max(1) {
        let t = Instant::now();
        let v = f();
        best = best.min(t.elapsed().as_secs_f64());
        out = Some(v);
    }
    (best, out.expect("at least one run"))
}

fn main() {
    let mut repeat = 3;
    let mut q_only = false;
    let mut ns = Vec::new();
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        if a == "--repeat" {
            repeat = args.next().and_then(|r| r.parse().ok()).unwrap_or(3);
        } else if a == "--q" {
            q_only = true;
        } else if let Ok(n) = a.parse::<usize>() {
            ns.push(n);
        } else {
            eprintln!("usage: sinc_power [--repeat R] [--q] N...");
            std::process::exit(2);
        }
    }
    if ns.is_empty() {
        ns = vec![30, 60, 100];
    }
    let half = Q::new(1.into(), 2.into());
    let alpha = Poly::var("theta").expect("valid symbol").add(&Poly::from_q(&half));
    let a_fixed = &half + Q::new(1.into(), 3.into());
    for n in ns {
        // The input series is built outside the timed region, as python-flint's jobs build theirs
        // (`series_peers.py`: the coefficients of sin x / x before `best`).
        let symbolic = (!q_only).then(|| {
            let sinc = Series::<Poly>::sinc_series(n);
            let (ts, f) = best(repeat, || sinc.pow(&alpha).expect("sinc(0) = 1"));
            let (tr, rev) = best(repeat, || f.shift(1).truncate(n).revert().expect("f(0) = 1"));
            (ts, tr, rev.coeff(7).map(|c| c.text()).unwrap_or_default())
        });
        let sinc_q = Series::<Q>::sinc_series(n);
        let (tqs, g) = best(repeat, || sinc_q.pow(&a_fixed).expect("sinc(0) = 1"));
        let (tqr, _) = best(repeat, || g.shift(1).truncate(n).revert().expect("g(0) = 1"));
        let (ts, tr, c7) = match symbolic {
            Some((ts, tr, c7)) => (format!("{ts:.6e}"), format!("{tr:.6e}"), format!("\"{c7}\"")),
            None => ("null".into(), "null".into(), "null".into()),
        };
        println!(
            "{{\"N\": {n}, \"symbolic_series_s\": {ts}, \"symbolic_reversion_s\": {tr}, \"q_series_s\": {tqs:.6e}, \"q_reversion_s\": {tqr:.6e}, \"rev_x7\": {c7}}}"
        );
    }
}
