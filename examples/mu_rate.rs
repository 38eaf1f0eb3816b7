//! The single punch's slip-zone width 1 - c/a and load gap 1 - C_P/C_P_ca as mu grows, by the
//! spectral method in `f64` with its stick zone resolved on the scale of the slip zone
//! (`Spectral::narrow`, `spectral_punch::slip_width`; docs/theory.md section 17.3 "Large mu"):
//! `cargo run --release --example mu_rate -- NU_NUM/NU_DEN OLD|NARROW|BITS START N... -- MU...`
//! (OLD: without `narrow`; BITS: MPFR at that precision, narrow; START the first mu's width, each
//! next mu starts from the last width).
//! A bad argument stops it with a message naming the argument, its value and the valid form,
//! the usage line, and exit code 2.

use std::time::Instant;

use periodic_contact::adhesion::friction::real::Mp;
use periodic_contact::adhesion::friction::spectral::Spectral;
use periodic_contact::adhesion::friction::spectral_punch::{slip_width, slip_width_mpfr};
use rug::Float;

const USAGE: &str = "usage: cargo run --release --example mu_rate -- NU_NUM/NU_DEN OLD|NARROW|BITS START N... -- MU...";

/// The parsed command line: nu = num/den, the method (`bits` Some: MPFR, narrow), the first mu's
/// width, the n and the mu.
struct Args {
    num: u64,
    den: u64,
    narrow: bool,
    bits: Option<u32>,
    start: f64,
    ns: Vec<usize>,
    mus: Vec<(String, f64)>,
}

/// `what` = `text` parsed and in range (`ok`), or the error naming the argument, its value and
/// the valid form.
fn parse<V: std::str::FromStr>(what: &str, text: &str, valid: &str, ok: impl Fn(&V) -> bool) -> Result<V, String> {
    match text.parse::<V>() {
        Ok(v) if ok(&v) => Ok(v),
        _ => Err(format!("{what} = `{text}`: expected {valid}")),
    }
}

fn parse_args(args: &[String]) -> Result<Args, String> {
    let split = args.iter().position(|a| a == "--").ok_or("no `--` before the MU list")?;
    if split < 4 {
        return Err(format!("{} arguments before `--`; expected NU MODE START and at least one N", split));
    }
    let nu_error = || format!("NU = `{}`: expected NUM/DEN, integers with DEN > 0 and 0 <= NUM/DEN <= 1/2", args[0]);
    let (num, den) = args[0]
        .split_once('/')
        .and_then(|(a, b)| Some((a.parse::<u64>().ok()?, b.parse::<u64>().ok()?)))
        .filter(|&(num, den)| den > 0 && num <= den / 2)
        .ok_or_else(nu_error)?;
    let mode = &args[1];
    let bits = match mode.as_str() {
        "OLD" | "NARROW" => None,
        _ => Some(parse::<u32>("MODE", mode, "OLD, NARROW or an MPFR precision in bits above f64's 53", |b| *b > 53)?),
    };
    let start = parse::<f64>("START", &args[2], "a slip-zone width 1 - c/a in (0, 1)", |w| *w > 0.0 && *w < 1.0)?;
    let ns = args[3..split]
        .iter()
        .map(|a| parse::<usize>("N", a, "polynomials per family, an integer >= 1", |n| *n >= 1))
        .collect::<Result<Vec<_>, _>>()?;
    let mus = args[split + 1..]
        .iter()
        .map(|a| {
            parse::<f64>("MU", a, "a friction coefficient, finite and > 0", |m| m.is_finite() && *m > 0.0)
                .map(|m| (a.clone(), m))
        })
        .collect::<Result<Vec<_>, _>>()?;
    if mus.is_empty() {
        return Err("no MU after `--`".into());
    }
    Ok(Args { num, den, narrow: mode != "OLD", bits, start, ns, mus })
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Args { num, den, narrow, bits, mut start, ns, mus } = parse_args(&args).unwrap_or_else(|e| {
        eprintln!("mu_rate: {e}\n{USAGE}");
        std::process::exit(2)
    });
    let (num, den) = (num as f64, den as f64);
    let beta = (den - 2.0 * num) / (2.0 * (den - num));
    for (m, mu) in mus.iter().map(|(text, mu)| (text, *mu)) {
        for &n in &ns {
            let t = Instant::now();
            if let Some(bits) = bits {
                let at = |v: f64| Mp(Float::with_val(bits, v));
                let beta = Mp(Float::with_val(bits, den - 2.0 * num) / Float::with_val(bits, 2.0 * (den - num)));
                let sp = Spectral::new(beta, at(mu), n, true).narrow();
                match slip_width_mpfr(&sp, start, 1e-12) {
                    Ok((w, p)) => {
                        println!("mu {m} n {n} {bits} bits: 1 - c/a {w:.14e}  C_P {p:.18}  [{:.1?}]", t.elapsed());
                        start = w.to_f64();
                    }
                    Err(e) => println!("mu {m} n {n}: {e}"),
                }
                continue;
            }
            let sp = Spectral::new(beta, mu, n, true);
            let sp = if narrow { sp.narrow() } else { sp };
            match slip_width(&sp, start, 1e-12) {
                Ok((w, p)) => {
                    println!("mu {m} n {n}: 1 - c/a {w:.10e}  C_P {p:.14}  [{:.1?}]", t.elapsed());
                    start = w;
                }
                Err(e) => println!("mu {m} n {n}: {e}"),
            }
        }
    }
}
