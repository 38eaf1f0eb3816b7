//! Times one MPFR increment solve of the periodic row's spectral method (docs/theory.md section
//! 17.8) at nu = 0, mu = 1/2, lambda = 1.2: `cargo run --release --example row_increment_timing
//! -- N BITS [GAMMA]` (defaults 26, 200, 0.126), for profiling (`perf record`). After the timing it
//! prints, to the working precision, the stick-edge defect and the outside slope H\[s2\](1 + b) at
//! b = 1e-3, 0.1 of that solve, and the same of the `f64` solve at n = 14 (17 digits): the figures
//! two builds of the method are compared by (docs/performance.md, "The row's MPFR increment").

use periodic_contact::adhesion::friction::real::{Mp, Real};
use periodic_contact::adhesion::friction::spectral::{Spectral, SpectralIncrement};

fn print_values<T: Real>(label: &str, sp: &Spectral<T>, inc: &SpectralIncrement<T>, show: impl Fn(&T) -> String) {
    println!("{label} defect {}", show(&inc.stick_edge_defect()));
    for b in [1e-3, 0.1] {
        println!("{label} slope({b:e}) {}", show(&sp.outside_slope(inc, &inc.gamma.lit(b))));
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args.get(1).map_or(26, |s| s.parse().expect("N"));
    let bits: u32 = args.get(2).map_or(200, |s| s.parse().expect("BITS"));
    let gamma: f64 = args.get(3).map_or(0.126, |s| s.parse().expect("GAMMA"));
    let half = Mp::new(bits, 0.5);
    let tau = Mp(rug::Float::with_val(bits, 1.2f64).tan());
    let sp = Spectral::row(half.clone(), half.clone(), n, tau, false);
    let t = std::time::Instant::now();
    let inc = sp.solve(&Mp::new(bits, gamma)).expect("solve");
    println!("n {n} bits {bits}: defect {:.3e}, {:.2?}", inc.stick_edge_defect().0.to_f64(), t.elapsed());
    let digits = (bits as f64 * std::f64::consts::LOG10_2).ceil() as usize;
    print_values("mpfr", &sp, &inc, |v: &Mp| format!("{:.*e}", digits, v.0));
    let sp64 = Spectral::row(0.5, 0.5, 14, 1.2f64.tan(), false);
    let inc64 = sp64.solve(&gamma).expect("f64 solve");
    print_values("f64", &sp64, &inc64, |v: &f64| format!("{v:.17e}"));
}
