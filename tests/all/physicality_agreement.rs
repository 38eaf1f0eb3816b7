//! One physicality criterion for every method (THEORY.md section 8, `sliding::physicality`): the
//! f64 collocation and the MPFR reduction, given the same problem, reach the same verdict for the
//! same reason, over a grid of (theta, lambda, shape, convention, tau0); and they quote the same
//! admissible range (the sinusoid's largest physical load) when they refuse.

use periodic_contact::error::{Error, ErrorKind};
use periodic_contact::model::{Convention, Exact, Material, Period, PunchShape, SlidingLoad, SlidingProblem};
use periodic_contact::sliding::collocation_f64::{solve_sliding_f64, SolverOptions};
use periodic_contact::sliding::solve_verified;

fn q(s: &str) -> Exact {
    exact_series::parse_rational(s).unwrap()
}

/// nu = 0 (beta = 1/2), E* = 1, L = 1: kappa = cW/2 - mu/2.
fn problem(sinusoid: bool, mu: &str, wear: &str, tau0: &str, load: SlidingLoad, conv: Convention) -> SlidingProblem {
    let shape = if sinusoid { PunchShape::sinusoidal(q("1/10")) } else { PunchShape::parabolic(q("1")) };
    SlidingProblem::builder()
        .material(Material::from_contact_modulus(q("0"), q("1")).unwrap())
        .period(Period::finite(q("1")).unwrap())
        .shape(shape.unwrap())
        .friction(q(mu))
        .adhesive_friction(q(tau0))
        .wear(q(wear))
        .load(load)
        .convention(conv)
        .build()
        .unwrap()
}

/// A verdict with its reason class: per solution, whether it carries a gap warning; or the
/// refusal's kind and the first criterion it failed.
#[derive(Debug, PartialEq)]
enum Verdict {
    Solved(Vec<bool>),
    Refused(ErrorKind, &'static str),
}

fn reason(e: &Error) -> Verdict {
    let text = e.to_string();
    let class = ["negative pressure", "negative gap", "leaves the cell", "no contact carries", "no centre"]
        .into_iter()
        .find(|c| text.contains(c))
        .unwrap_or("other");
    Verdict::Refused(e.kind(), class)
}

fn f64_verdict(pb: &SlidingProblem) -> Verdict {
    match solve_sliding_f64(pb, &[], &SolverOptions::default()) {
        Ok(s) => Verdict::Solved(s.solutions.iter().map(|s| s.physicality.warning.is_some()).collect()),
        Err(e) => reason(&Error::from(e)),
    }
}

fn mpfr_verdict(pb: &SlidingProblem) -> Verdict {
    match solve_verified(pb, &[], 16) {
        Ok(v) => Verdict::Solved(
            v.iter().map(|s| s.solution.physicality.as_ref().expect("checked").warning.is_some()).collect(),
        ),
        Err(e) => reason(&Error::from(e)),
    }
}

/// theta in about {-0.17, -0.06, 0, 0.06, 0.17} (friction or wear), tau0 in {0, 1/200}; the
/// direct problem at lambda = pi l/L for l in {1/10, 1/5, 3/10, 2/5} (lambda 0.31 to 1.26); both
/// shapes, both conventions: 160 problems.
#[test]
#[ignore = "long tier: 6 s alone in the test profile (opt-level 2) on a loaded 2-core machine (scripts/test --long)"]
fn f64_and_mpfr_never_disagree_on_physicality() {
    let thetas = [("6/5", "0"), ("2/5", "0"), ("0", "0"), ("0", "2/5"), ("0", "6/5")];
    let mut table = vec![];
    let mut disagreements = vec![];
    for sinusoid in [false, true] {
        for (mu, wear) in thetas {
            for tau0 in ["0", "1/200"] {
                for l in ["1/10", "1/5", "3/10", "2/5"] {
                    for conv in [Convention::Paper, Convention::PeriodicSurface] {
                        let pb = problem(sinusoid, mu, wear, tau0, SlidingLoad::HalfLength(q(l)), conv);
                        let (f, m) = (f64_verdict(&pb), mpfr_verdict(&pb));
                        let line = format!(
                            "{} mu {mu} cW {wear} tau0 {tau0} l {l} {}: f64 {f:?} / mpfr {m:?}",
                            if sinusoid { "sinusoid" } else { "parabola" },
                            conv.name()
                        );
                        if f != m {
                            disagreements.push(line.clone());
                        }
                        table.push((line, f));
                    }
                }
            }
        }
    }
    assert!(disagreements.is_empty(), "f64 and MPFR disagree on:\n{}", disagreements.join("\n"));
    // The grid is not trivial: it has refusals of each kind, gap warnings (paper only) and clean
    // solutions.
    let count = |pred: &dyn Fn(&Verdict) -> bool| table.iter().filter(|(_, v)| pred(v)).count();
    let warned = count(&|v| matches!(v, Verdict::Solved(w) if w.iter().any(|x| *x)));
    let clean = count(&|v| matches!(v, Verdict::Solved(w) if w.iter().all(|x| !*x)));
    let refused = count(&|v| matches!(v, Verdict::Refused(..)));
    assert!(warned > 0 && clean > 0 && refused > 0, "warned {warned}, clean {clean}, refused {refused}");
    for (line, v) in &table {
        if line.contains("periodic") {
            assert!(!matches!(v, Verdict::Solved(w) if w.iter().any(|x| *x)), "a gap warning in periodic: {line}");
        }
    }
}

/// The largest physical load quoted by a refusal ("normal_load in (0, X]").
fn largest_admissible_load(text: &str) -> f64 {
    periodic_contact::sliding::physicality::admissible::Admissible::quoted_largest_load(text)
        .unwrap_or_else(|| panic!("no admissible range in: {text}"))
}

/// The sinusoid's largest physical load, from each method's own direct problem, agrees to the 7
/// digits the message prints (1e-6 relative), with friction (theta = -0.17, -0.06) and wear
/// (theta = 0.17), in both conventions, where the load 1/2 (above pi E* D = 0.314) is refused.
#[test]
fn both_methods_quote_the_same_largest_load() {
    for (mu, wear) in [("6/5", "0"), ("2/5", "0"), ("0", "6/5")] {
        for conv in [Convention::Paper, Convention::PeriodicSurface] {
            let pb = problem(true, mu, wear, "0", SlidingLoad::NormalLoad(q("1/2")), conv);
            let f = Error::from(solve_sliding_f64(&pb, &[], &SolverOptions::default()).unwrap_err());
            let m = Error::from(solve_verified(&pb, &[], 16).unwrap_err());
            assert_eq!(f.kind(), m.kind(), "{f} / {m}");
            let (cf, cm) = (largest_admissible_load(&f.to_string()), largest_admissible_load(&m.to_string()));
            assert!((cf - cm).abs() <= 1e-6 * cm, "mu {mu} cW {wear} {}: f64 {cf} vs MPFR {cm}", conv.name());
        }
    }
}

/// See: issue 13 ("never a search limit presented as physics"). Frictionless sinusoid (E* = 1,
/// D = 1/10, L = 1; full contact carries pi E* D = 0.3141593) and parabola (k = 1: every load has a
/// contact, Kuznetsov [2.15]). Both methods solve P2 = 0.31 (Westergaard lambda =
/// asin(sqrt(0.31/(pi/10))) = 1.455478523538) to their digits; P2 = 0.314, below full contact but
/// beyond both methods' reach (lambda = 1.548), is refused as out of reach (no convergence), naming
/// the physical limit; P2 = 0.32, above full contact, as no solution; the parabola at P2 = 2
/// (lambda = 1.5689) as out of reach, naming Kuznetsov.
#[test]
fn refusals_near_full_contact_name_the_physical_limit() {
    let conv = Convention::Paper;
    let westergaard = (0.31f64 / (std::f64::consts::PI / 10.0)).sqrt().asin();
    let at = problem(true, "0", "0", "0", SlidingLoad::NormalLoad(q("31/100")), conv);
    let f = solve_sliding_f64(&at, &[], &SolverOptions::default()).unwrap();
    assert!((f.solutions[0].lambda - westergaard).abs() < 1e-11, "f64 lambda {}", f.solutions[0].lambda);
    let m = solve_verified(&at, &[], 20).unwrap();
    let lm = m[0].solution.lambda.as_ref().unwrap().to_f64();
    assert!((lm - westergaard).abs() < 1e-14, "MPFR lambda {lm}");
    let cases = [
        (true, "314/1000", ErrorKind::NoConvergence, "full contact (lambda -> pi/2) carries P2 = pi E* D = 0.3141593"),
        (true, "32/100", ErrorKind::NoSolution, "it exceeds the full-contact load pi E* D = 0.3141593"),
        (false, "2", ErrorKind::NoConvergence, "physically every load has a contact"),
    ];
    for (sinusoid, load, kind, words) in cases {
        let pb = problem(sinusoid, "0", "0", "0", SlidingLoad::NormalLoad(q(load)), conv);
        let fe = Error::from(solve_sliding_f64(&pb, &[], &SolverOptions::default()).unwrap_err());
        let me = Error::from(solve_verified(&pb, &[], 20).unwrap_err());
        for e in [fe, me] {
            let text = e.to_string();
            assert_eq!(e.kind(), kind, "{load}: {text}");
            assert!(text.contains(words), "{load}: {text}");
            if kind == ErrorKind::NoConvergence {
                assert!(text.contains("beyond this method's reach") && !text.contains("no contact carries"), "{text}");
            }
        }
    }
}
