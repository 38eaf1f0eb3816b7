//! The homogeneous mode eta^mu* of Problem 2 under the linear loading law (issue 12, small nu;
//! `asymptotics::loading_law_modes`): mu* at 12 digits over a grid of nu and n, with the
//! verified digits, the self-similar c/l and det M(0). Run:
//! `cargo run --release --example loading_law_modes` (or with two comma-separated lists:
//! `-- 0,1/10 1/5,1/2`).
use periodic_contact::asymptotics::loading_law_modes::mode_exponent;

type Q = num_rational::BigRational;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let nus = args.get(1).map_or("0,1/10,3/20,1/5,3/10", |s| s.as_str());
    let ratios = args.get(2).map_or("0,1/5,1/2,1", |s| s.as_str());
    for nu in nus.split(',') {
        for n in ratios.split(',') {
            let t = std::time::Instant::now();
            let (Ok(nuq), Ok(nq)) = (nu.parse::<Q>(), n.parse::<Q>()) else {
                eprintln!("not a rational: {nu} or {n}");
                std::process::exit(2);
            };
            match mode_exponent(&nuq, &nq, 12) {
                Ok(m) => println!(
                    "nu = {nu}, n = {n}: mu* = {} ({}), c/l = {:.6}, det M(0) = {:.4}, {:.2} s",
                    m.value_text().unwrap_or_else(|| "none below 2000".into()),
                    if m.mu.is_some() { format!("{:.1} digits verified", m.digits) } else { "no zero found".into() },
                    m.g0.to_f64(),
                    m.det_at_zero.to_f64(),
                    t.elapsed().as_secs_f64()
                ),
                Err(e) => println!("nu = {nu}, n = {n}: {e}"),
            }
        }
    }
}
