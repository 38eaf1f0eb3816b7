//! The periodic row's load with finite friction in MPFR with verified digits
//! (`spectral_row_load::verified_mpfr`, docs/theory.md section 17.8): nu = 0 (beta = 1/2),
//! mu = 1/2, lambda = 1.2, k = L = E* = 1, the convention and digits asked:
//! `cargo run --release --example row_load_mpfr -- paper|periodic DIGITS`.
//! A bad argument stops it with a message naming the argument, its value and the valid form,
//! the usage line, and exit code 2.

use periodic_contact::adhesion::friction::spectral_row_load::verified_mpfr;
use rug::Float;

const USAGE: &str = "usage: cargo run --release --example row_load_mpfr -- [paper|periodic [DIGITS]]";

/// (periodic, digits) from the command line: `paper` and 8 digits when absent.
fn parse_args(args: &[String]) -> Result<(bool, u32), String> {
    let periodic = match args.first().map(String::as_str) {
        Some("periodic") => true,
        Some("paper") | None => false,
        Some(other) => return Err(format!("CONVENTION = `{other}`: expected paper or periodic")),
    };
    let digits = match args.get(1) {
        None => 8,
        Some(text) => match text.parse::<u32>() {
            Ok(d) if (1..=MAX_DIGITS).contains(&d) => d,
            _ => return Err(format!("DIGITS = `{text}`: expected an integer in 1 ..= {MAX_DIGITS}")),
        },
    };
    if args.len() > 2 {
        return Err(format!("{} arguments; expected at most CONVENTION DIGITS", args.len()));
    }
    Ok((periodic, digits))
}

/// Beyond this the runs take hours (about 1 h of 2 cores at 20 digits, docs/theory.md 17.8).
const MAX_DIGITS: u32 = 30;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (periodic, digits) = parse_args(&args).unwrap_or_else(|e| {
        eprintln!("row_load_mpfr: {e}\n{USAGE}");
        std::process::exit(2)
    });
    let half = Float::with_val(512, 0.5);
    let lambda = Float::with_val(512, 12) / 10u32;
    let v = verified_mpfr(&half, &half, &lambda, periodic, digits).unwrap_or_else(|e| {
        eprintln!("row_load_mpfr: {e}");
        std::process::exit(1)
    });
    let pi2 = Float::with_val(512, rug::float::Constant::Pi).square();
    println!(
        "periodic {periodic}: P = {:.30} ({:.1} digits), P2 = P/pi^2 = {:.30}\n  c/a = {:.30} ({:.1} digits)\n  \
         f64: P = {:.16}, c/a = {:.16}\n  runs (nodes, n, bits) {:?}, {:.0?} s",
        v.load,
        v.load_digits,
        Float::with_val(512, &v.load / &pi2),
        v.stick_ratio,
        v.stick_digits,
        v.load_f64,
        v.stick_ratio_f64,
        v.runs,
        v.seconds
    );
}
