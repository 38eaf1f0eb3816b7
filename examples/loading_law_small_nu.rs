//! The loading-law problem at small nu (issue 12's open point): the MPFR collocation's verified
//! digits at nu = 0 and 1/10 for n = 1/5 and 1/2 (the f64 march refuses nu <= 0.1; see
//! `src/growing_contact/march.rs`, "Stability"). Run:
//! `cargo run --release --example loading_law_small_nu`.
use periodic_contact::loading_law::verified::solve_law;
use periodic_contact::model::{
    Convention, Exact, LawSize, LoadingLaw, LoadingLawProblem, Material, Period, PunchShape,
};

fn q(n: i64, d: i64) -> Exact {
    Exact::new(n.into(), d.into())
}

fn main() {
    let cases = [
        ((0, 1), (1, 5), (1, 8), Convention::Paper),
        ((0, 1), (1, 5), (1, 16), Convention::Paper),
        ((0, 1), (1, 2), (1, 8), Convention::Paper),
        ((0, 1), (1, 5), (1, 8), Convention::PeriodicSurface),
        ((1, 10), (1, 5), (1, 8), Convention::Paper),
    ];
    for (nu, n, l, convention) in cases {
        let material = Material::from_contact_modulus(q(nu.0, nu.1), q(1, 1)).expect("valid material");
        let problem = LoadingLawProblem::new(
            material,
            Period::Finite(q(1, 1)),
            PunchShape::Parabolic { k: q(1, 1) },
            LoadingLaw::Linear(q(n.0, n.1)),
            LawSize::HalfLength(q(l.0, l.1)),
            convention,
        )
        .expect("valid problem");
        let t = std::time::Instant::now();
        let label =
            format!("nu = {}/{}, n = {}/{}, l/L = {}/{}, {}", nu.0, nu.1, n.0, n.1, l.0, l.1, convention.name());
        match solve_law(&problem, &[], 12) {
            Ok(s) => println!(
                "{label}: c/l = {:.6}, verified {:.1} digits (12 requested), {:.1} s",
                s.values.c.to_f64() / s.values.l.to_f64(),
                s.digits.headline,
                t.elapsed().as_secs_f64()
            ),
            Err(e) => println!("{label}: {e}"),
        }
    }
}
