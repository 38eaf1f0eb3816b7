//! The periodic row's fields in MPFR (`row_fields::History<Mp>`, docs/theory.md section 17.8,
//! (17.12)-(17.13)): how q1, q2, psi at one point converge with the load's nodes N, the
//! polynomials per family n and the bits, the node increments solved to full stick-edge roots
//! and their coefficients (times cos eta) interpolated in the node rule's variable. nu = 0
//! (beta = 1/2) unless `nu12` (beta = 0, where q2 = arccosh(cos chi/cos lambda)), mu = 1/2,
//! k = L = E* = 1 (units L = pi, so a = lambda):
//! `cargo run --release --example row_fields_mpfr -- paper|periodic LAMBDA X_OVER_A eta|eta2 [nu12] N,n,BITS ...`
//! Each run prints the fields, their difference from the previous run, and its wall time; then
//! the `f64` fields of `solve`'s discretisations (8, 6) and (10, 8) (nodes in eta).

use periodic_contact::adhesion::friction::real::Mp;
use periodic_contact::adhesion::friction::row_fields::History;
use periodic_contact::adhesion::friction::spectral_row::{increment_f64, increment_mpfr_root};
use periodic_contact::adhesion::friction::spectral_row_load::{load_rate, NodeRule};
use rug::Float;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let periodic = args[1] == "periodic";
    let lambda: f64 = args[2].parse().expect("LAMBDA");
    let x: f64 = args[3].parse().expect("X_OVER_A");
    let rule = if args[4] == "eta2" { NodeRule::EtaSquared } else { NodeRule::Eta };
    let incompressible = args.iter().any(|a| a == "nu12");
    let (b, m): (f64, f64) = (if incompressible { 0.0 } else { 0.5 }, 0.5);
    let theta0 = (b * m).atan() / std::f64::consts::PI;
    let mut last: Option<[Float; 3]> = None;
    for spec in args[5..].iter().filter(|a| a.contains(',')) {
        let v: Vec<u32> = spec.split(',').map(|s| s.parse().expect("N,n,BITS")).collect();
        let (nodes, n, bits) = (v[0] as usize, v[1] as usize, v[2]);
        let t = std::time::Instant::now();
        let (beta, mu) = (Float::with_val(bits + 64, b), Float::with_val(bits + 64, m));
        // lambda as the decimal given, exactly at the run's precision
        let lam = Float::with_val(bits + 64, Float::parse(&args[2]).expect("LAMBDA"));
        // the least squares amplify rounding by about 10^(1.2 n) (spectral_row_load::knobs)
        let digits = ((bits as f64 - 16.0) / 3.33 - 1.2 * n as f64) as u32;
        let at = |e: &Mp| {
            let start = if incompressible { 0.5 } else { increment_f64(b, m, e.0.to_f64(), 10, periodic)?.1.gamma };
            increment_mpfr_root((&beta, &mu, &e.0), periodic, (n, bits, digits), start, false)
        };
        let rate = load_rate(&Mp(Float::with_val(bits, &lam)), theta0, nodes, rule, at).expect("load");
        let lm = Mp(Float::with_val(bits, &lam));
        let h =
            History::new(&rate, lm.clone(), (Mp(Float::with_val(bits, b)), Mp(Float::with_val(bits, m))), n, periodic)
                // above the working precision: nearer an edge 1 - x loses every digit (psi NaN)
                .with_edge_cut(10f64.powi(-(2 * digits as i32 + 4)).max(2f64.powi(16 - bits as i32)));
        let loaded = t.elapsed().as_secs_f64();
        let chi = Mp(Float::with_val(bits, x) * &lm.0);
        let p = h.fields(&chi, true);
        let now = [p.q1.0, p.q2.0, p.psi.0];
        println!(
            "(N, n, bits) = ({nodes}, {n}, {bits}): P = {:.25}\n  q1 = {:.25}\n  q2 = {:.25}\n  psi = {:.25}\n  load {loaded:.1} s, fields {:.1} s",
            rate.load.0,
            now[0],
            now[1],
            now[2],
            t.elapsed().as_secs_f64() - loaded
        );
        if incompressible {
            let c = Float::with_val(bits, chi.0.cos_ref()) / Float::with_val(bits, lm.0.cos_ref());
            let exact = c.acosh();
            println!("  q2 - arccosh(cos chi/cos lambda) = {:.2e}", Float::with_val(bits, &now[1] - &exact).to_f64());
        }
        if let Some(prev) = &last {
            let d: Vec<f64> = prev.iter().zip(&now).map(|(a, b)| Float::with_val(bits, a - b).to_f64()).collect();
            println!("  difference from the previous run: q1 {:.2e}, q2 {:.2e}, psi {:.2e}", d[0], d[1], d[2]);
        }
        last = Some(now);
    }
    for (nodes, n) in [(8, 6), (10, 8), (14, 10)] {
        let rate = load_rate(&lambda, theta0, nodes, NodeRule::Eta, |e: &f64| increment_f64(b, m, *e, n, periodic))
            .expect("f64 load");
        let h = History::new(&rate, lambda, (b, m), n, periodic);
        let p = h.fields(&(x * lambda), true);
        println!("f64 ({nodes}, {n}): q1 = {:.16}, q2 = {:.16}, psi = {:.16}", p.q1, p.q2, p.psi);
    }
}
