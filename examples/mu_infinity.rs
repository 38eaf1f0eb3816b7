//! The single punch's stick ratio c/a and load coefficient C_P as mu grows (issue 32, docs/theory.md
//! section 17.3 "Large mu"), by the spectral method in MPFR (`spectral_punch::slip_width_mpfr`, the
//! root in ln(1 - c/a), each start the previous mu's width where the `f64` method refuses) at
//! (n1, bits) and (n2, bits + 32), and by the `f64` increment method (n = 40, 80):
//! `cargo run --release --example mu_infinity -- NU_NUM/NU_DEN N1 N2 BITS MU...`.

use std::time::Instant;

use exact_series::Q;
use periodic_contact::adhesion::friction::real::Mp;
use periodic_contact::adhesion::friction::single_punch::{solve_once, Method};
use periodic_contact::adhesion::friction::spectral::Spectral;
use periodic_contact::adhesion::friction::spectral_punch::slip_width_mpfr;
use periodic_contact::model::Material;
use periodic_contact::params::adhesion::AdhesionParamsF64;
use rug::Float;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (num, den) = args[1].split_once('/').expect("NU as NUM/DEN");
    let (num, den): (i64, i64) = (num.parse().unwrap(), den.parse().unwrap());
    let n1: usize = args[2].parse().unwrap();
    let n2: usize = args[3].parse().unwrap();
    let bits: u32 = args[4].parse().unwrap();
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
    for m in &args[5..] {
        let mu = Float::with_val(bits + 64, Float::parse(m).unwrap());
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
