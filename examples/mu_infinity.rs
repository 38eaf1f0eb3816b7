//! The single punch's stick ratio c/a and load coefficient C_P as mu grows (issue 32, docs/theory.md
//! section 17.3 "Large mu"), by the spectral method in MPFR (`spectral_punch::slip_width_mpfr`, the
//! root in ln(1 - c/a), each start the previous mu's width where the `f64` method refuses) at
//! (n1, bits) and (n2, bits + 32), and by the `f64` increment method (n = 40, 80):
//! `cargo run --release --example mu_infinity -- NU_NUM/NU_DEN N1 N2 BITS MU...`.
//! A bad argument stops it with a message naming the argument, its value and the valid form,
//! the usage line, and exit code 2.

use std::time::Instant;

use exact_series::Q;
use periodic_contact::adhesion::friction::real::Mp;
use periodic_contact::adhesion::friction::single_punch::{solve_once, Method};
use periodic_contact::adhesion::friction::spectral::Spectral;
use periodic_contact::adhesion::friction::spectral_punch::slip_width_mpfr;
use periodic_contact::model::Material;
use periodic_contact::params::adhesion::AdhesionParamsF64;
use rug::Float;

const USAGE: &str = "usage: cargo run --release --example mu_infinity -- NU_NUM/NU_DEN N1 N2 BITS MU...";

/// The parsed command line: nu = num/den, the two n, the bits of the first, the mu as given.
struct Args {
    num: i64,
    den: i64,
    n1: usize,
    n2: usize,
    bits: u32,
    mus: Vec<String>,
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
    if args.len() < 5 {
        return Err(format!("{} arguments; expected NU N1 N2 BITS and at least one MU", args.len()));
    }
    let nu_error = || format!("NU = `{}`: expected NUM/DEN, integers with DEN > 0 and 0 <= NUM/DEN < 1/2", args[0]);
    let (num, den) = args[0]
        .split_once('/')
        .and_then(|(a, b)| Some((a.parse::<i64>().ok()?, b.parse::<i64>().ok()?)))
        .filter(|&(num, den)| den > 0 && num >= 0 && 2 * num < den)
        .ok_or_else(nu_error)?;
    let n = |what: &str, text: &str| parse::<usize>(what, text, "polynomials per family, an integer >= 2", |n| *n >= 2);
    let (n1, n2) = (n("N1", &args[1])?, n("N2", &args[2])?);
    let bits = parse::<u32>("BITS", &args[3], "an MPFR precision in bits, 64 ..= 4096", |b| (64..=4096).contains(b))?;
    for m in &args[4..] {
        let value = Float::parse(m).map(|v| Float::with_val(64, v));
        if !value.is_ok_and(|v| v.is_finite() && v > 0) {
            return Err(format!("MU = `{m}`: expected a friction coefficient, a finite number > 0"));
        }
    }
    Ok(Args { num, den, n1, n2, bits, mus: args[4..].to_vec() })
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Args { num, den, n1, n2, bits, mus } = parse_args(&args).unwrap_or_else(|e| {
        eprintln!("mu_infinity: {e}\n{USAGE}");
        std::process::exit(2)
    });
    let material = Material::from_contact_modulus(
        Q::from_integer(num.into()) / Q::from_integer(den.into()),
        Q::from_integer(1.into()),
    )
    .unwrap();
    let adhesion = AdhesionParamsF64::new(&material).load_constant;
    // beta = (1 - 2 nu)/(2 (1 - nu))
    let beta = Float::with_val(bits + 64, den - 2 * num) / Float::with_val(bits + 64, 2 * (den - num));
    println!("nu = {num}/{den}, beta = {:.6}, complete adhesion C_P = {adhesion:.12}", beta.to_f64());
    let mut start: Option<f64> = None;
    for m in &mus {
        // checked in parse_args
        let mu = Float::with_val(bits + 64, Float::parse(m).expect("MU checked"));
        let t = Instant::now();
        let inc = [40, 80].map(|n| solve_once(beta.to_f64(), mu.to_f64(), n, Method::Increment, true));
        let f64_line = match &inc {
            [Ok((g1, p1)), Ok((g2, p2))] => format!("f64 inc n=40,80: c/a {g1:.7} {g2:.7}  C_P {p1:.7} {p2:.7}"),
            [a, b] => format!(
                "f64 inc: {:?} {:?}",
                a.as_ref().err().map(|e| e.to_string()),
                b.as_ref().err().map(|e| e.to_string())
            ),
        };
        let d0 = match (&inc[1], start) {
            (Ok((g, _)), _) => 1.0 - *g,
            (Err(_), Some(s)) => s,
            // the f64 method refuses a slip zone below 1e-4 a: start there
            (Err(_), None) => 1e-4,
        };
        let root = |n: usize, bits: u32, start: f64| {
            let at = |x: &Float| Mp(Float::with_val(bits, x));
            let (w, p) = slip_width_mpfr(&Spectral::new(at(&beta), at(&mu), n, true), start, 1e-12).expect("root");
            (w.to_f64(), p.to_f64())
        };
        let r1 = root(n1, bits, d0);
        let r2 = root(n2, bits + 32, r1.0);
        let (dd, dp) = ((r1.0 - r2.0).abs(), (r1.1 - r2.1).abs());
        println!(
            "mu {m}: 1 - c/a {:.12e} (n {n1}: {:.12e}, diff {dd:.1e}), c/a {:.15}\n   C_P {:.15} (diff {dp:.1e}), 1 - C_P/C_ca {:.10e}\n   {f64_line}  [{:.0?}]",
            r2.0, r1.0, 1.0 - r2.0, r2.1, 1.0 - r2.1 / adhesion, t.elapsed()
        );
        start = Some(r2.0);
    }
}
