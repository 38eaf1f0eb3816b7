//! Times one MPFR increment solve of the periodic row's spectral method (docs/theory.md section
//! 17.8) at nu = 0, mu = 1/2, lambda = 1.2: `cargo run --release --example row_increment_timing
//! -- N BITS` (defaults 26, 200), for profiling (`perf record`).

use periodic_contact::adhesion::friction::real::Mp;
use periodic_contact::adhesion::friction::spectral::Spectral;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args.get(1).map_or(26, |s| s.parse().expect("N"));
    let bits: u32 = args.get(2).map_or(200, |s| s.parse().expect("BITS"));
    let half = Mp::new(bits, 0.5);
    let tau = Mp(rug::Float::with_val(bits, 1.2f64).tan());
    let sp = Spectral::row(half.clone(), half.clone(), n, tau, false);
    let t = std::time::Instant::now();
    let inc = sp.solve(&Mp::new(bits, 0.126)).expect("solve");
    println!("n {n} bits {bits}: defect {:.3e}, {:.2?}", inc.stick_edge_defect().0.to_f64(), t.elapsed());
}
