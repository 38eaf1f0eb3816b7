//! Measures the Problem 2 stability map with friction's column (crates/report/src/friction_map.rs):
//! P(lambda) of the periodic row at lambda < lambda_max from the one collocation on (0, lambda_max)
//! (`spectral_row_load::loads_below`) against a load solved at lambda itself, and the CPU time of
//! a column's loads and stick ratios, release build:
//!     cargo run --release --example friction_map_column -- NU MU LAMBDA_MAX
use periodic_contact::adhesion::friction::spectral_row::stick_ratio_f64;
use periodic_contact::solve::answer_friction_row::{row_load, row_loads};
use std::time::Instant;

fn main() {
    let args: Vec<f64> = std::env::args().skip(1).map(|a| a.parse().expect("a number")).collect();
    let (nu, mu, top) = (args[0], args[1], args[2]);
    let beta = (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu));
    let lambdas = [0.2, 0.5, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3, 1.4];
    for periodic in [false, true] {
        // MESHES="8,6;10,8" (the default): the discretisations (load nodes, polynomials)
        let meshes: Vec<(usize, usize)> = std::env::var("MESHES")
            .unwrap_or_else(|_| "8,6;10,8".into())
            .split(';')
            .map(|m| {
                let v: Vec<usize> = m.split(',').map(|x| x.parse().expect("a count")).collect();
                (v[0], v[1])
            })
            .collect();
        for &(nodes, n) in &meshes {
            let t = Instant::now();
            let column = row_loads(beta, mu, top, &lambdas, (nodes, n), periodic);
            let t_col = t.elapsed().as_secs_f64();
            let column = match column {
                Ok(c) => c,
                Err(e) => {
                    println!("periodic {periodic} ({nodes}, {n}): {e}");
                    continue;
                }
            };
            if std::env::var_os("COLUMN_ONLY").is_some() {
                println!("periodic {periodic} ({nodes}, {n}): column {t_col:.2} s, P(1.2) {}", column[6]);
                continue;
            }
            let t = Instant::now();
            let ratios: Vec<_> = lambdas.iter().map(|&l| stick_ratio_f64(beta, mu, l, n, periodic)).collect();
            let t_ratio = t.elapsed().as_secs_f64();
            println!("periodic {periodic} ({nodes}, {n}): column {t_col:.2} s, 9 c/a {t_ratio:.2} s");
            for (&l, (p, g)) in lambdas.iter().zip(column.iter().zip(&ratios)) {
                let t = Instant::now();
                let direct = row_load(beta, mu, l, (nodes, n), periodic);
                let secs = t.elapsed().as_secs_f64();
                match direct {
                    Ok(d) => println!(
                        "  lambda {l}: P {p:.10} direct {d:.10} rel {:.1e} ({secs:.2} s) c/a {g:?}",
                        p / d - 1.0
                    ),
                    Err(e) => println!("  lambda {l}: P {p:.10} direct refused: {e}"),
                }
            }
        }
    }
}
