//! The periodic row's load gap 1 - P/P_ca as mu grows at nu = 3/10 (issue 32, docs/theory.md
//! section 17.8), by the `f64` spectral load (`spectral_row_load::load_with`, the convention's
//! node rule) with each node's stick edge by the root in ln(1 - gamma_T) of the narrow method
//! (`Spectral::narrow`, `spectral_punch::slip_width_root`), on two discretisations, against
//! complete adhesion's verified MPFR load of the same row (Problem 2 through `solve`):
//! `cargo run --release --example mu_rate_row -- paper|periodic LAMBDA NODES1,N1 NODES2,N2 MU...`
//! (`OLD=1`: each node's stick edge by the default root, `spectral_row::increment_f64`).
//! A bad argument stops it with a message naming the argument, its value and the valid form,
//! the usage line, and exit code 2.

use std::time::Instant;

use periodic_contact::adhesion::friction::spectral::Spectral;
use periodic_contact::adhesion::friction::spectral_punch::slip_width_root;
use periodic_contact::adhesion::friction::spectral_row::{increment_f64, physical_ratio};
use periodic_contact::adhesion::friction::spectral_row_load::{load_with, NodeRule};
use periodic_contact::api::{self, SolveOptions};

const USAGE: &str =
    "usage: cargo run --release --example mu_rate_row -- paper|periodic LAMBDA NODES1,N1 NODES2,N2 MU...";

/// The parsed command line: the convention, lambda = pi a/L, two (nodes, n) and the mu.
struct Args {
    convention: String,
    lambda: f64,
    discs: [(usize, usize); 2],
    mus: Vec<(String, f64)>,
}

/// The error naming argument `what`, its value `text` and the valid form.
fn bad(what: &str, text: &str, valid: &str) -> String {
    format!("{what} = `{text}`: expected {valid}")
}

fn parse_args(args: &[String]) -> Result<Args, String> {
    if args.len() < 5 {
        return Err(format!("{} arguments; expected CONVENTION LAMBDA, two NODES,N and at least one MU", args.len()));
    }
    let convention = args[0].clone();
    if convention != "paper" && convention != "periodic" {
        return Err(bad("CONVENTION", &convention, "paper or periodic"));
    }
    let lambda = args[1]
        .parse::<f64>()
        .ok()
        .filter(|l| *l > 0.0 && *l < std::f64::consts::FRAC_PI_2)
        .ok_or_else(|| bad("LAMBDA", &args[1], "pi a/L in (0, pi/2)"))?;
    let disc = |text: &String| {
        text.split_once(',')
            .and_then(|(a, b)| Some((a.parse::<usize>().ok()?, b.parse::<usize>().ok()?)))
            .filter(|&(nodes, n)| nodes >= 1 && n >= 1)
            .ok_or_else(|| bad("NODES,N", text, "two integers >= 1: the load's nodes and the polynomials per family"))
    };
    let discs = [disc(&args[2])?, disc(&args[3])?];
    let mus = args[4..]
        .iter()
        .map(|a| {
            let mu = a.parse::<f64>().ok().filter(|m| m.is_finite() && *m > 0.0);
            mu.map(|m| (a.clone(), m)).ok_or_else(|| bad("MU", a, "a friction coefficient, finite and > 0"))
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Args { convention, lambda, discs, mus })
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Args { convention, lambda, discs, mus } = parse_args(&args).unwrap_or_else(|e| {
        eprintln!("mu_rate_row: {e}\n{USAGE}");
        std::process::exit(2)
    });
    let periodic = convention == "periodic";
    let beta = 2.0 / 7.0;
    // OLD=1: the stick edges by the default method's root (`spectral_row::increment_f64`)
    let old = std::env::var("OLD").is_ok();
    let text = format!(
        "[problem]\nkind = \"adhesion\"\n[material]\npoisson_ratio = \"3/10\"\ncontact_modulus = \"1\"\n\
         [punch]\nshape = \"parabolic\"\nk = \"1\"\nperiod = \"1\"\n[adhesion]\nhalf_width = \"{:.18}\"\n",
        lambda / std::f64::consts::PI
    );
    let opts = SolveOptions { convention: Some(convention.clone()), ..Default::default() };
    let (p2, digits) = api::solve_toml(&text, &opts)
        .map_err(|e| e.to_string())
        .and_then(|ca| ca.get("P2").map(|q| (q.value, q.digits)).ok_or_else(|| "no P2 in the answer".to_string()))
        .unwrap_or_else(|e| {
            eprintln!("mu_rate_row: complete adhesion at lambda {lambda} ({convention}): {e}");
            std::process::exit(1)
        });
    let p_ca = p2 * std::f64::consts::PI.powi(2);
    println!("{convention} lambda {lambda}: complete adhesion P = {p_ca:.13} ({digits:.1} digits)");
    for (m, mu) in mus.iter().map(|(text, mu)| (text, *mu)) {
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
