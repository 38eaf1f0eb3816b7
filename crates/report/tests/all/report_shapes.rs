//! Report section "Punch shapes" (`src/report/shapes.rs`, issue 11): on the shipped scenes'
//! polynomial and circular profiles, the solvers' frictionless loads agree with the closed form of
//! THEORY.md section 9 (computed independently, `src/verification/closed_form_load.rs`): Problem 1
//! MPFR to >= 25 digits and f64 to >= 12, Problem 2 at nu = 1/2 (MPFR) to >= 25; the single
//! punch with the power law; the odd cubic has no closed form (MPFR and f64 agree to >= 12); a
//! size beyond the slope limit is solved (issue 30: a warning, not a refusal); the section's text and charts.

use periodic_contact::model::{Exact, PunchShape};
use periodic_contact_report::runner::RunCache;
use periodic_contact_report::section::{Ctx, Profile};
use periodic_contact_report::shapes::{cases, grid, row, single_punch, ShapeCase};
use periodic_contact_report::{calibration, load_scenes};

fn shipped() -> Vec<(String, periodic_contact::scene::Scene)> {
    load_scenes(concat!(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."), "/scenes").as_ref()).unwrap()
}

fn q(s: &str) -> Exact {
    exact_series::parse_rational(s).unwrap()
}

fn case_with(all: &[ShapeCase], coefficients: Option<&[&str]>) -> ShapeCase {
    all.iter()
        .find(|c| match (&c.shape, coefficients) {
            (PunchShape::Polynomial { coefficients: have }, Some(want)) => {
                have.len() == want.len() && have.iter().zip(want).all(|(h, w)| *h == q(w))
            }
            (PunchShape::Circular { .. }, None) => true,
            _ => false,
        })
        .cloned()
        .unwrap_or_else(|| panic!("no case {coefficients:?}"))
}

const QUARTIC_A: &[&str] = &["0", "0", "1", "0", "1/10"];
const QUARTIC_B: &[&str] = &["0", "0", "1/4", "0", "1/2"];
const CUBIC: &[&str] = &["0", "1/50", "1", "1/2"];

#[test]
fn cases_are_the_distinct_new_profiles_of_the_scenes() {
    let all = cases(&shipped());
    assert_eq!(all.len(), 4, "{all:?}");
    // adhesion_quartic and the two quartic friction scenes share one profile, period and E*.
    let b = case_with(&all, Some(QUARTIC_B));
    assert_eq!(b.scenes, ["adhesion_quartic", "quartic_friction_paper", "quartic_friction_periodic"]);
    assert!(b.even() && case_with(&all, None).even() && case_with(&all, Some(QUARTIC_A)).even());
    assert!(!case_with(&all, Some(CUBIC)).even());
    // Slope edges, by hand: x/2 + 2 x^3 = 1/2 at x = 1/2 (the cell's edge, L = 1); the circle
    // R = 1/2: x/sqrt(R^2 - x^2) = 1/2 at x = R/sqrt(5).
    assert!((b.slope_edge(1.0) - 0.5).abs() < 1e-12);
    assert!((case_with(&all, None).slope_edge(1.0) - 0.5 / 5f64.sqrt()).abs() < 1e-11);
    // 2 x + 0.4 x^3 = 1/2 at x = 0.24699 (lambda = 0.776, quoted by the stability map's text).
    let edge = case_with(&all, Some(QUARTIC_A)).slope_edge(1.0);
    assert!((2.0 * edge + 0.4 * edge.powi(3) - 0.5).abs() < 1e-11);
    assert!((edge * std::f64::consts::PI - 0.776).abs() < 5e-4, "{edge}");
}

/// The stated agreement: lambda = 0.5 and 1.1 for the flat quartic (its slope stays below 1/2 up
/// to the cell's edge), lambda = 0.5 for the circle R = L/2 and the steeper quartic (whose slope
/// limit is at lambda = 0.70 and 0.78).
#[test]
fn even_profiles_agree_with_the_closed_form() {
    let all = cases(&shipped());
    let cache = RunCache::default();
    for (case, lambdas) in [
        (case_with(&all, Some(QUARTIC_B)), &[0.5, 1.1][..]),
        (case_with(&all, None), &[0.5][..]),
        (case_with(&all, Some(QUARTIC_A)), &[0.5][..]),
    ] {
        for (a, beyond) in grid(&case, lambdas) {
            assert!(!beyond, "{:?}", case.shape);
            let r = row(&cache, &case, &a, false);
            let closed = r.closed.as_ref().unwrap().as_ref().unwrap();
            assert!(closed.digits(77.0) >= 60.0, "closed form: {:?}", closed.abs_err);
            let name = format!("{} a = {a}", case.shape.name());
            let m = r.mpfr_agreement().unwrap_or_else(|| panic!("{name}: {:?}", r.mpfr.as_ref().err()));
            assert!(m >= 25.0, "{name}: MPFR agrees to {m} digits");
            let f = r.f64_agreement().unwrap_or_else(|| panic!("{name}: f64 {:?}", r.f64));
            assert!(f >= 12.0, "{name}: f64 agrees to {f} digits");
            let p = r.adhesion_agreement().unwrap_or_else(|| panic!("{name}: Problem 2 {:?}", r.adhesion));
            assert!(p >= 25.0, "{name}: Problem 2 at nu = 1/2 agrees to {p} digits");
            let pf = r.adhesion_f64_agreement().unwrap_or_else(|| panic!("{name}: Problem 2 f64 {:?}", r.adhesion_f64));
            assert!(pf >= 12.0, "{name}: Problem 2 f64 at nu = 1/2 agrees to {pf} digits");
        }
    }
}

#[test]
fn single_punch_follows_the_power_law() {
    let all = cases(&shipped());
    let cache = RunCache::default();
    for case in [case_with(&all, Some(QUARTIC_A)), case_with(&all, None)] {
        let sp = single_punch(&cache, &case, &q("3/20"));
        let m = sp.mpfr_agreement().unwrap_or_else(|| panic!("{:?}", sp.mpfr.as_ref().err()));
        assert!(m >= 25.0, "{}: MPFR agrees to {m} digits", case.shape.name());
        let f = sp.f64_agreement().unwrap_or_else(|| panic!("{:?}", sp.f64.as_ref().err()));
        assert!(f >= 12.0, "{}: f64 agrees to {f} digits", case.shape.name());
    }
    // The quartic's law by hand at a = 3/20, E* = 1: pi (c2 a^2/2 + 3 c4 a^4/4), c2 = 1, c4 = 1/10.
    let sp = single_punch(&cache, &case_with(&all, Some(QUARTIC_A)), &q("3/20"));
    let a: f64 = 0.15;
    let hand = std::f64::consts::PI * (a * a / 2.0 + 0.075 * a.powi(4));
    let law = sp.closed.as_ref().unwrap().value.to_f64();
    assert!((law - hand).abs() < 1e-15 * hand, "{law} vs {hand}");
}

#[test]
fn odd_profile_has_no_closed_form_and_its_methods_agree() {
    let all = cases(&shipped());
    let case = case_with(&all, Some(CUBIC));
    let cache = RunCache::default();
    let (a, _) = grid(&case, &[0.5]).remove(0);
    let r = row(&cache, &case, &a, false);
    assert!(r.closed.is_none() && r.adhesion.is_none());
    let d = r.f64_vs_mpfr().unwrap();
    assert!(d >= 12.0, "f64 vs MPFR: {d}");
    // The odd terms move the centre without friction.
    let o = r.mpfr.as_ref().unwrap();
    assert!(o.centre.to_f64().abs() > 1e-2 * o.size.to_f64(), "c = {}", o.centre);
}

#[test]
fn beyond_the_slope_limit_the_size_is_solved() {
    let all = cases(&shipped());
    let case = case_with(&all, Some(QUARTIC_A));
    // lambda 0.5, the edge (0.99 of lambda = 0.776), then 1.1 beyond it.
    let g = grid(&case, &[0.5, 1.1, 1.4]);
    assert_eq!(g.len(), 3, "{g:?}");
    assert_eq!(g.iter().map(|x| x.1).collect::<Vec<_>>(), [false, false, true]);
    let (a, beyond) = g.last().unwrap();
    let r = row(&RunCache::default(), &case, a, *beyond);
    // Issue 30: the small-slope rule is a warning (docs/theory.md section 9): MPFR answers, and
    // agrees with the closed form there as below the limit.
    assert!(r.max_slope > 0.5, "{}", r.max_slope);
    assert!(r.mpfr.is_ok(), "{:?}", r.mpfr);
    assert!(r.f64.is_none() && r.adhesion.is_none());
    assert!(r.closed.as_ref().unwrap().is_ok());
    assert!(r.mpfr_agreement().is_some_and(|d| d > 20.0), "{:?}", r.mpfr_agreement());
}

#[test]
fn section_text_and_charts() {
    let scenes: Vec<_> = shipped().into_iter().filter(|(n, _)| n == "circle" || n == "kuznetsov_parabola").collect();
    let mut ctx = Ctx {
        profile: Profile::Fast,
        cache: Default::default(),
        progress: indicatif::ProgressBar::hidden(),
        table: calibration::Table::committed().unwrap(),
    };
    let s = periodic_contact_report::shapes::section(&mut ctx, &scenes);
    let md = &s.markdown;
    assert!(md.starts_with("## 8. Punch shapes"), "{md}");
    assert!(md.contains("### circular radius = 1/2, L = 1, E* = 1 (scenes `circle`)"), "{md}");
    // Fast grid: lambda = 0.5, the edge (0.99 x 0.702), then 1.1 refused; and the single punch.
    let refused = md.lines().filter(|l| l.starts_with("| 0.") && l.contains("refused")).count();
    assert_eq!(refused, 0, "{md}");
    assert!(md.contains("| single punch, a = "), "{md}");
    assert!(md.contains("small slope"), "{md}");
    assert_eq!(s.charts.len(), 1);
    let c = &s.charts[0];
    assert_eq!(c.curves.len(), 4);
    assert!(c.curves.iter().any(|c| c.name.starts_with("closed form")));
    assert!(c.svg().unwrap().contains("[-]"));
    // No scene with a new profile: no text (the report's snapshot set has none).
    let parabola: Vec<_> = shipped().into_iter().filter(|(n, _)| n == "kuznetsov_parabola").collect();
    let s = periodic_contact_report::shapes::section(&mut ctx, &parabola);
    assert!(s.markdown.is_empty() && s.charts.is_empty());
}
