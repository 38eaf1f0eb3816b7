//! The periodic row's load gap 1 - P/P_ca as mu grows at nu = 3/10 (issue 32, docs/theory.md
//! section 17.8), by the `f64` spectral load (`spectral_row_load::load_with`, the convention's
//! node rule) with each node's stick edge by the root in ln(1 - gamma_T) of the narrow method
//! (`Spectral::narrow`, `spectral_punch::slip_width_root`), on two discretisations, against
//! complete adhesion's verified MPFR load of the same row (Problem 2 through `solve`):
//! `cargo run --release --example mu_rate_row -- paper|periodic LAMBDA NODES1,N1 NODES2,N2 MU...`
//! (`OLD=1`: each node's stick edge by the default root, `spectral_row::increment_f64`).

use std::time::Instant;

use periodic_contact::adhesion::friction::spectral::Spectral;
use periodic_contact::adhesion::friction::spectral_punch::slip_width_root;
use periodic_contact::adhesion::friction::spectral_row::{increment_f64, physical_ratio};
use periodic_contact::adhesion::friction::spectral_row_load::{load_with, NodeRule};
use periodic_contact::api::{self, SolveOptions};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let periodic = args[1] == "periodic";
    let lambda: f64 = args[2].parse().unwrap();
    let disc = |s: &str| -> (usize, usize) {
        let (a, b) = s.split_once(',').unwrap();
        (a.parse().unwrap(), b.parse().unwrap())
    };
    let discs = [disc(&args[3]), disc(&args[4])];
    let beta = 2.0 / 7.0;
    // OLD=1: the stick edges by the default method's root (`spectral_row::increment_f64`)
    let old = std::env::var("OLD").is_ok();
    let text = format!(
        "[problem]\nkind = \"adhesion\"\n[material]\npoisson_ratio = \"3/10\"\ncontact_modulus = \"1\"\n\
         [punch]\nshape = \"parabolic\"\nk = \"1\"\nperiod = \"1\"\n[adhesion]\nhalf_width = \"{:.18}\"\n",
        lambda / std::f64::consts::PI
    );
    let opts = SolveOptions { convention: Some(args[1].clone()), ..Default::default() };
    let ca = api::solve_toml(&text, &opts).unwrap_or_else(|e| panic!("{e}"));
    let p_ca = ca.get("P2").unwrap().value * std::f64::consts::PI.powi(2);
    println!(
        "{} lambda {lambda}: complete adhesion P = {p_ca:.13} ({:.1} digits)",
        args[1],
        ca.get("P2").unwrap().digits
    );
    for m in &args[5..] {
        let mu: f64 = m.parse().unwrap();
        let theta0 = (beta * mu).atan() / std::f64::consts::PI;
        let mut out = Vec::new();
        for (nodes, n) in discs {
            let t = Instant::now();
            let inc_at = |e: &f64| {
                if old {
                    return increment_f64(beta, mu, *e, n, periodic);
                }
                let sp = Spectral::row(beta, mu, n, e.tan(), periodic).narrow();
                let inc = slip_width_root(&sp, 1e-3, 1e-12)?;
                Ok((sp, inc))
            };
            let p = load_with(&lambda, theta0, nodes, NodeRule::of_convention(periodic), inc_at);
            let sp = Spectral::row(beta, mu, n, lambda.tan(), periodic).narrow();
            let g = slip_width_root(&sp, 1e-3, 1e-12).map(|inc| physical_ratio(&inc.gamma, &lambda));
            match (p, g) {
                (Ok(p), Ok(g)) => {
                    println!(
                        "  mu {m} ({nodes}, {n}): P {p:.12}  1 - P/P_ca {:.6e}  1 - c/a {:.6e}  [{:.1?}]",
                        1.0 - p / p_ca,
                        1.0 - g,
                        t.elapsed()
                    );
                    out.push((p, g));
                }
                (p, g) => println!("  mu {m} ({nodes}, {n}): {:?} {:?}", p.err(), g.err()),
            }
        }
        if let [(p1, g1), (p2, g2)] = out[..] {
            println!("  mu {m}: difference P {:.1e} relative, c/a {:.1e}", (p1 - p2).abs() / p2, (g1 - g2).abs());
        }
    }
}
