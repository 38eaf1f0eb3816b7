//! The single punch's slip-zone width 1 - c/a and load gap 1 - C_P/C_P_ca as mu grows, by the
//! spectral method in `f64` with its stick zone resolved on the scale of the slip zone
//! (`Spectral::narrow`, `spectral_punch::slip_width`; docs/theory.md section 17.3 "Large mu"):
//! `cargo run --release --example mu_rate -- NU_NUM/NU_DEN OLD|NARROW|BITS START N... -- MU...`
//! (OLD: without `narrow`; BITS: MPFR at that precision, narrow; START the first mu's width, each
//! next mu starts from the last width).

use std::time::Instant;

use periodic_contact::adhesion::friction::real::Mp;
use periodic_contact::adhesion::friction::spectral::Spectral;
use periodic_contact::adhesion::friction::spectral_punch::{slip_width, slip_width_mpfr};
use rug::Float;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (num, den) = args[1].split_once('/').expect("NU as NUM/DEN");
    let (num, den): (f64, f64) = (num.parse().unwrap(), den.parse().unwrap());
    let narrow = args[2] != "OLD";
    let bits: Option<u32> = args[2].parse().ok();
    let mut start: f64 = args[3].parse().unwrap();
    let split = args.iter().position(|a| a == "--").expect("-- before the mu");
    let ns: Vec<usize> = args[4..split].iter().map(|a| a.parse().unwrap()).collect();
    let beta = (den - 2.0 * num) / (2.0 * (den - num));
    for m in &args[split + 1..] {
        let mu: f64 = m.parse().unwrap();
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
