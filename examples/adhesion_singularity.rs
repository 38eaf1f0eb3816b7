//! Ratio (Domb-Sykes) analysis of the Problem 2 lambda^2-series (issue 13, eta_s(nu);
//! `asymptotics::adhesion_singularity`): per nu the local estimates sqrt(p_(j-1)/p_j) of eta_s at
//! j = 10, 40, 80, 160, 300, their ratio to cos phi_j = Re M_(2j+1)/|M_(2j+1)|, and the two
//! Domb-Sykes windows (radius, exponent g, digits of agreement). Run:
//! `cargo run --release --example adhesion_singularity` (or `-- 0,1/4,1/2 600 40`: nu list,
//! order, digits).
use periodic_contact::asymptotics::adhesion_singularity::singularity_analysis;

type Q = num_rational::BigRational;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let nus = args.get(1).map_or("0,1/20,1/10,3/20,1/5,1/4,3/10,7/20,2/5,9/20,1/2", |s| s.as_str());
    let order: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(600);
    let digits: u32 = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(40);
    println!("nu | local eta_s at j = 10, 40, 80, 160, 300 | (eta_s(j))^2/cos phi_j at 10, 80, 300 | Domb-Sykes J/2: eta_s, g | J: eta_s, g | agree (digits) | printed order");
    for nu in nus.split(',') {
        let Ok(nuq) = nu.parse::<Q>() else {
            eprintln!("not a rational: {nu}");
            std::process::exit(2);
        };
        let t = std::time::Instant::now();
        let s = match singularity_analysis(&nuq, order, digits) {
            Ok(s) => s,
            Err(e) => {
                eprintln!("nu = {nu}: {e}");
                continue;
            }
        };
        let at = |j: usize| s.rows.get(j - 1);
        let local: Vec<String> = [10, 40, 80, 160, 300]
            .iter()
            .map(|&j| at(j).map_or("-".into(), |r| format!("{:.5} ({:.0} d)", r.local_radius, r.digits)))
            .collect();
        let scaled: Vec<String> =
            [10, 80, 300].iter().map(|&j| at(j).map_or("-".into(), |r| format!("{:.3}", r.scaled))).collect();
        let [a, b] = &s.extrapolations;
        println!(
            "{nu} | {} | {} | j = {}: {:.8}, {:.4} | j = {}: {:.8}, {:.4} | {:.1}, {:.1} | {} ({:.1} s)",
            local.join(", "),
            scaled.join(", "),
            a.j,
            a.radius.to_f64(),
            a.exponent.to_f64(),
            b.j,
            b.radius.to_f64(),
            b.exponent.to_f64(),
            s.radius_digits,
            s.exponent_digits,
            s.series.printed_order(),
            t.elapsed().as_secs_f64()
        );
    }
}
