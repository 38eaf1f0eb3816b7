//! Explorations of the high-precision sliding solver (`sliding::reduction_mpfr`) that only print:
//!
//! ```text
//! cargo run --release --example reduction_mpfr_explore -- timing
//!     solve_verified at 30 digits on nine cases, three calls each (the first builds the rules)
//! cargo run --release --example reduction_mpfr_explore -- edge-cases
//!     the edge cases of THEORY.md section 7 (tiny loads, theta near +-1/2, lambda near pi/2)
//! cargo run --release --example reduction_mpfr_explore -- load-curve [--periodic-surface]
//!     the sinusoid's load curve P2(lambda) on both centre branches, with physicality, for five
//!     friction/wear/adhesion sets (the paper's convention, or Convention::PeriodicSurface)
//! ```
//!
//! The numbers quoted in the docs from these charts (e.g. the maximum ~0.1624 at lambda ~ 0.96 of
//! the sinusoid with mu = 1) were read from `load-curve`.

use periodic_contact::model::{Convention, Exact, Material, Period, PunchShape, SlidingLoad, SlidingProblem};
use periodic_contact::numerics::gauss_jacobi_mpfr::gauss_jacobi;
use periodic_contact::params::sliding::SlidingParamsMpfr;
use periodic_contact::sliding::reduction_mpfr::contact::{Contact, Size};
use periodic_contact::sliding::reduction_mpfr::equation::{equation_terms, shift_solutions};
use periodic_contact::sliding::reduction_mpfr::physical::physicality;
use periodic_contact::sliding::reduction_mpfr::pressure::Pressure;
use periodic_contact::sliding::reduction_mpfr::solve::nodes_for;
use periodic_contact::sliding::solve_verified;
use rug::Float;

fn q(s: &str) -> Exact {
    s.parse().expect("rational literal")
}

/// A problem: nu, E*, period ("inf": single punch), sinusoid?, k or D, mu, tau0, cW, load ("l=.."
/// for a given half-length), with speed 2.
#[allow(clippy::too_many_arguments)]
fn problem(
    nu: &str,
    e: &str,
    period: &str,
    sinusoid: bool,
    size: &str,
    (mu, tau0, cw): (&str, &str, &str),
    load: &str,
    convention: Convention,
) -> SlidingProblem {
    let shape = if sinusoid { PunchShape::sinusoidal(q(size)) } else { PunchShape::parabolic(q(size)) }.unwrap();
    let load = match load.strip_prefix("l=") {
        Some(l) => SlidingLoad::HalfLength(q(l)),
        None => SlidingLoad::NormalLoad(q(load)),
    };
    SlidingProblem::builder()
        .material(Material::from_contact_modulus(q(nu), q(e)).unwrap())
        .period(if period == "inf" { Period::Infinite } else { Period::finite(q(period)).unwrap() })
        .shape(shape)
        .friction(q(mu))
        .adhesive_friction(q(tau0))
        .wear(q(cw))
        .speed(Some(q("2")))
        .load(load)
        .convention(convention)
        .build()
        .unwrap()
}

type Row =
    (&'static str, &'static str, &'static str, &'static str, bool, &'static str, [&'static str; 3], &'static str);

/// (name, nu, E*, period, sinusoid, k or D, [mu, tau0, cW], load or "l=half-length").
const TIMING: [Row; 9] = [
    ("parabola periodic, theta=0, P2=1/20", "1/2", "1", "1", false, "1", ["0", "0", "0"], "1/20"),
    ("parabola periodic, mu, cW, tau0, P2=1/20", "1/4", "1", "1", false, "1", ["1/5", "1/100", "1/10"], "1/20"),
    ("parabola periodic, l=0.318 (lambda=1)", "1/4", "1", "1", false, "1", ["1/5", "0", "1/10"], "l=318/1000"),
    ("parabola single, mu, cW, tau0", "1/4", "1", "inf", false, "1", ["1/5", "1/100", "1/10"], "1"),
    ("sinusoid, theta=0, P2=1/5", "1/2", "2", "1", true, "1/10", ["0", "0", "0"], "1/5"),
    ("sinusoid, mu, cW, tau0, l=1/4", "1/4", "1", "1", true, "1/10", ["1/5", "1/100", "1/10"], "l=1/4"),
    ("parabola periodic, mu, cW, P2=1/5 (lambda~1)", "1/4", "1", "1", false, "1", ["1/5", "0", "1/10"], "1/5"),
    ("sinusoid, mu, cW, P2=17/100 (lambda~0.9)", "1/4", "1", "1", true, "1/10", ["1/5", "0", "1/10"], "17/100"),
    ("sinusoid, mu, cW, tau0, P2=1/10", "1/4", "1", "1", true, "1/10", ["1/5", "1/100", "1/10"], "1/10"),
];

const EDGE_CASES: [Row; 10] = [
    ("single, tiny load, tau0", "1/4", "1", "inf", false, "1", ["0", "1/100", "0"], "1/1000000"),
    ("periodic, tiny load, tau0", "1/4", "1", "1", false, "1", ["0", "1/100", "0"], "1/1000000"),
    ("periodic, theta=0.49 (wear)", "1/2", "1", "1", false, "1", ["0", "0", "6000/37"], "1/100"),
    ("periodic, theta=-0.45 (friction)", "0", "1", "1", false, "1", ["63/5", "0", "0"], "1/100"),
    ("periodic, lambda=1.4", "1/2", "1", "1", false, "1", ["0", "0", "0"], "l=4456/10000"),
    ("periodic, lambda=1.5", "1/2", "1", "1", false, "1", ["0", "0", "0"], "l=4775/10000"),
    ("periodic, lambda -> pi/2", "1/2", "1", "1", false, "1", ["0", "0", "0"], "l=4999999/10000000"),
    ("periodic, huge load", "1/2", "1", "1", false, "1", ["0", "0", "0"], "1000"),
    ("sinusoid, load above pi E* D", "1/2", "1", "1", true, "1", ["0", "0", "0"], "4"),
    ("sinusoid, wear theta=0.3", "1/2", "1", "1", true, "1/10", ["0", "0", "11/2"], "1/100"),
];

fn build(row: &Row) -> SlidingProblem {
    let (_, nu, e, period, sinusoid, size, [mu, tau0, cw], load) = *row;
    problem(nu, e, period, sinusoid, size, (mu, tau0, cw), load, Convention::Paper)
}

/// Each case `repeat` times at 30 digits, with the points xh = -1/2, 0, 1/2.
fn run_cases(rows: &[Row], repeat: usize) {
    let pts = [q("-1/2"), q("0"), q("1/2")];
    for row in rows {
        let pb = build(row);
        for call in 0..repeat {
            let t = std::time::Instant::now();
            let r = solve_verified(&pb, &pts, 30);
            let ms = t.elapsed().as_secs_f64() * 1e3;
            match r {
                Ok(v) => {
                    for s in &v {
                        let x = &s.solution;
                        println!(
                            "{} [call {call}]: {ms:.1} ms, {} solution(s), theta {:.4}, lambda {:?}, l {:.6e}, c {:.6e}, n {}, bits {}, digits_verified {:.1}",
                            row.0,
                            v.len(),
                            x.theta.to_f64(),
                            x.lambda.as_ref().map(|l| l.to_f64()),
                            x.l.to_f64(),
                            x.c.to_f64(),
                            x.nodes,
                            x.prec,
                            s.accuracy.digits_verified
                        );
                    }
                }
                Err(e) => println!("{} [call {call}]: {ms:.1} ms, error: {e}", row.0),
            }
        }
    }
}

/// The sinusoid D = 1/10, L = 1, nu = 1/4 at l = i L/62 (lambda = pi i/62): every centre branch
/// of [2.14] with its load and physicality, at 64 bits.
fn load_curve(convention: Convention) {
    for (mu, cw, tau0) in
        [("0", "0", "0"), ("1/5", "1/10", "1/100"), ("0", "1", "0"), ("1", "0", "0"), ("0", "0", "1/20")]
    {
        println!("{convention:?}: mu = {mu}, cW = {cw}, tau0 = {tau0}");
        for i in 1..=30 {
            let pb = problem("1/4", "1", "1", true, "1/10", (mu, tau0, cw), &format!("l={i}/62"), convention);
            let params = SlidingParamsMpfr::new(&pb, 64).unwrap();
            let lam = Float::with_val(64, std::f64::consts::PI * i as f64 / 62.0);
            let size = Size::new(&params, &lam);
            let (a, b) = params.inverse_weight_exponents();
            let rule = gauss_jacobi(&a, &b, nodes_for(lam.to_f64(), 16.0), 64).unwrap();
            let terms = equation_terms(&params, &size, &rule);
            let mut line = format!("  lambda {:.3} theta {:.4}:", lam.to_f64(), params.theta.to_f64());
            for s in shift_solutions(&params, &size, &terms) {
                let contact = Contact::new(&params, &size, s.c.clone());
                let pr = Pressure::new(&params, &contact, &rule);
                let l = &size.l;
                let p1 = Float::with_val(64, &params.mu * &s.p2) + Float::with_val(64, l * &params.tau0) * 2u32;
                let verdict = match physicality(&params, &contact, &pr, &p1, &s.p2) {
                    Ok(a) if a.warning.is_some() => format!("ok, warning: gap {:.2e}", a.min_gap),
                    Ok(_) => "ok".to_string(),
                    Err(r) => r.why().chars().take(110).collect::<String>(),
                };
                line += &format!(" [P2 {:.6} c {:.4} {verdict}]", s.p2.to_f64(), s.c.to_f64());
            }
            println!("{line}");
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("timing") => run_cases(&TIMING, 3),
        Some("edge-cases") => run_cases(&EDGE_CASES, 1),
        Some("load-curve") => load_curve(if args.iter().any(|a| a == "--periodic-surface") {
            Convention::PeriodicSurface
        } else {
            Convention::Paper
        }),
        _ => eprintln!("usage: reduction_mpfr_explore timing | edge-cases | load-curve [--periodic-surface]"),
    }
}
