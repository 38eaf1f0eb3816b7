//! Where the `f64` stick edge of the periodic row loses its digits (docs/theory.md section 17.8,
//! issue 32 H80): `cargo run --example row_stick_rounding -- paper|periodic LAMBDA N...`.
//! For each n it prints the `f64` root c/a (the `solve` path, `spectral_row::stick_ratio_f64`)
//! and, at the 160-bit MPFR root of the same discretisation (3 (2 n + 2) points per zone, the
//! `f64` oversampling), the stick-edge defect's error in three mixes: `f64` rows with the `f64`
//! least squares, MPFR rows rounded to `f64` with the `f64` least squares (the least squares'
//! own rounding), `f64` rows with the MPFR least squares (the rows' rounding), each divided by
//! the defect's slope (its error in gamma_T).

use periodic_contact::adhesion::friction::quadrature::least_squares;
use periodic_contact::adhesion::friction::real::{Mp, Real};
use periodic_contact::adhesion::friction::spectral::{Spectral, F64_OVERSAMPLE};
use periodic_contact::adhesion::friction::spectral_punch::root_mpfr;
use periodic_contact::adhesion::friction::spectral_row::{physical_ratio, stick_ratio_f64};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let periodic = args.get(1).is_some_and(|s| s == "periodic");
    let lambda: f64 = args.get(2).map_or(1.2, |s| s.parse().expect("LAMBDA"));
    let ns: Vec<usize> = args.iter().skip(3).map(|s| s.parse().expect("N")).collect();
    let bits = 160;
    for n in if ns.is_empty() { vec![10] } else { ns } {
        let t = std::time::Instant::now();
        let ca = stick_ratio_f64(0.5, 0.5, lambda, n, periodic).expect("f64 root");
        let secs = t.elapsed().as_secs_f64();
        let gamma = (ca * lambda).tan() / lambda.tan();
        let half = Mp::new(bits, 0.5);
        let tau = Mp(rug::Float::with_val(bits, lambda).tan());
        let spm = Spectral::row(half.clone(), half, n, tau, periodic).oversampled(F64_OVERSAMPLE);
        let root = root_mpfr(&spm, gamma, 30).expect("MPFR root");
        let lam = Mp(rug::Float::with_val(bits, lambda));
        let ca_m = physical_ratio(&root.gamma, &lam).to_f64();
        println!(
            "n {n}: f64 c/a {ca:.16} ({secs:.1} s), MPFR of the same discretisation {ca_m:.16}: {:.1e}",
            ca - ca_m
        );
        let g = root.gamma.to_f64();
        let gm = Mp::new(bits, g);
        let sp = Spectral::row(0.5, 0.5, n, lambda.tan(), periodic);
        let (af, bf) = sp.system(&g);
        let (am, bm) = spm.system(&gm);
        let dm = |c: Vec<Mp>| spm.increment(&gm, c).stick_edge_defect().to_f64();
        let df = |c: Vec<f64>| sp.increment(&g, c).stick_edge_defect();
        let exact = dm(least_squares(am.clone(), bm.clone()).expect("MPFR solve"));
        let am64 = am.iter().map(|r| r.iter().map(Real::to_f64).collect()).collect();
        let af_mp = af.iter().map(|r| r.iter().map(|v| Mp::new(bits, *v)).collect()).collect();
        let mixes = [
            ("f64 rows, f64 least squares", df(least_squares(af, bf.clone()).expect("solve"))),
            (
                "MPFR rows, f64 least squares",
                df(least_squares(am64, bm.iter().map(Real::to_f64).collect()).expect("solve")),
            ),
            (
                "f64 rows, MPFR least squares",
                dm(least_squares(af_mp, bf.iter().map(|v| Mp::new(bits, *v)).collect()).expect("solve")),
            ),
        ];
        let gp = Mp::new(bits, g + 1e-6);
        let (ap, bp) = spm.system(&gp);
        let slope =
            (spm.increment(&gp, least_squares(ap, bp).expect("solve")).stick_edge_defect().to_f64() - exact) / 1e-6;
        for (label, d) in mixes {
            println!("  {label}: defect error {:.1e}, gamma_T error {:.1e}", d - exact, (d - exact) / slope);
        }
    }
}
