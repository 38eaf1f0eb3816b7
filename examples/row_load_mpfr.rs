//! The periodic row's load with finite friction in MPFR with verified digits
//! (`spectral_row_load::verified_mpfr`, docs/theory.md section 17.8): nu = 0 (beta = 1/2),
//! mu = 1/2, lambda = 1.2, k = L = E* = 1, the convention and digits asked:
//! `cargo run --release --example row_load_mpfr -- paper|periodic DIGITS`.

use periodic_contact::adhesion::friction::spectral_row_load::verified_mpfr;
use rug::Float;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let periodic = match args.get(1).map(String::as_str) {
        Some("periodic") => true,
        Some("paper") | None => false,
        Some(other) => panic!("convention: paper or periodic, not {other}"),
    };
    let digits: u32 = args.get(2).map_or(8, |s| s.parse().expect("DIGITS: a positive integer"));
    let half = Float::with_val(512, 0.5);
    let lambda = Float::with_val(512, 12) / 10u32;
    let v = verified_mpfr(&half, &half, &lambda, periodic, digits).expect("verified_mpfr");
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
