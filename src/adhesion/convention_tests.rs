//! Tests of Problem 2 in the two surface conventions (docs/theory.md section 8, Problem 2):
//! `periodic` (u periodic) against the independent boundary-element values of issue 32; the two
//! methods (MPFR with the closed-form kernel, f64 with the tilted punch of the growing contact)
//! agree in `periodic` (and tests/all/loading_law_agreement.rs: the loading law with N = 0 is the same
//! problem in both conventions); nu = 1/2 and the single
//! punch are the same in both conventions; in `periodic` the homogeneous mode of section 11 is
//! not excited where it spoils `paper`.

use super::volterra_mpfr::{self, RightSide, VolterraParams};
use super::{solve_f64, solve_verified, AdhesionSolutionF64, VerifiedSolution};
use crate::model::{AdhesionProblem, AdhesionSize, Convention, Exact, Material, Period, PunchShape};
use crate::params::adhesion::AdhesionParamsMpfr;
use rug::Float;

fn q(n: i64, d: i64) -> Exact {
    Exact::new(n.into(), d.into())
}

/// a = lambda L/pi as an exact rational (33 digits of 1/pi), L = 1.
fn half_width_for(lambda: Exact) -> Exact {
    let inv_pi = Exact::new(
        "318309886183790671537767526745029".parse::<num_bigint::BigInt>().unwrap(),
        "1000000000000000000000000000000000".parse::<num_bigint::BigInt>().unwrap(),
    );
    lambda * inv_pi
}

fn material(nu: Exact) -> Material {
    Material::from_contact_modulus(nu, q(1, 1)).unwrap()
}

/// k = L = E* = 1.
fn problem(nu: Exact, period: Period, size: AdhesionSize, convention: Convention) -> AdhesionProblem {
    AdhesionProblem::new(material(nu), period, PunchShape::parabolic(q(1, 1)).unwrap(), size)
        .unwrap()
        .with_convention(convention)
}

fn row(nu: Exact, lambda: Exact, convention: Convention) -> AdhesionProblem {
    problem(nu, Period::finite(q(1, 1)).unwrap(), AdhesionSize::HalfWidth(half_width_for(lambda)), convention)
}

/// Points x/a inside the contact (at x/a = 1 the f64 march's stresses are round-off, ~1e-8 E* k a,
/// where MPFR returns the exact 0).
fn points() -> Vec<Exact> {
    vec![q(0, 1), q(1, 4), q(1, 2), q(9, 10), q(99, 100)]
}

/// The decimal digits to which the f64 solution agrees with the MPFR one: load and the fields at
/// the points, each on its scale (P2; k a for psi; k a^2 for phi; E* k a for the stresses).
fn agreement(m: &VerifiedSolution, f: &AdhesionSolutionF64) -> f64 {
    let s = &m.solution;
    let a = s.half_width.to_f64();
    let d = |x: &Float, y: f64, scale: f64| -((x.to_f64() - y).abs() / scale).log10();
    let mut worst = d(&s.normal_load, f.normal_load, s.normal_load.to_f64());
    for (pm, pf) in s.points.iter().zip(&f.points) {
        worst = worst
            .min(d(&pm.psi, pf.psi, a))
            .min(d(&pm.phi, pf.phi, a * a))
            .min(d(&pm.q1, pf.q1, a))
            .min(d(&pm.q2, pf.q2, a));
    }
    worst
}

/// Issue 32's boundary-element values (nu = 0, k = L = E* = 1): complete adhesion with u
/// periodic gives P2 = 0.22440(4) at lambda = 1.0 and about 0.0716 at lambda = 0.6, where the
/// Flamant far field gives 0.0791 (the project's `paper` value 0.0794278). Measured: `periodic`
/// 0.224395589552080523514 and 0.0716285886377452696391 (24 verified digits asked 20; an mpmath
/// collocation in t = tan eta with the same closed-form kernel: 0.224395589, 0.07162858864),
/// `paper` 0.0794278275812141160742. The f64 method (the growing contact's tilted punch, derived
/// apart from the MPFR kernel) agrees with MPFR to >= 14 digits in load and fields (measured 15).
#[test]
fn periodic_convention_matches_the_boundary_element_values() {
    let pts = points();
    for (lambda, want, tol) in [(q(1, 1), 0.22440, 0.00004), (q(6, 10), 0.0716, 0.00005)] {
        let pr = row(q(0, 1), lambda.clone(), Convention::PeriodicSurface);
        let m = solve_verified(&pr, &pts, 20).unwrap();
        assert!(m.digits_verified.headline >= 20.0, "lambda {lambda}: {:?}", m.digits_verified);
        let p2 = m.solution.normal_load.to_f64();
        assert!((p2 - want).abs() <= tol, "lambda {lambda}: P2 = {p2} against {want}({tol})");
        let f = solve_f64(&pr, &pts).unwrap();
        let agree = agreement(&m, &f);
        assert!(agree >= 14.0, "lambda {lambda}: f64 agrees to {agree:.1} digits");
        assert!(f.digits_estimated.headline >= 12.0, "{:?}", f.digits_estimated);
    }
    let paper = solve_verified(&row(q(0, 1), q(6, 10), Convention::Paper), &[], 20).unwrap();
    let p2 = paper.solution.normal_load.to_f64();
    assert!((p2 - 0.0794278).abs() < 1e-7, "paper at lambda = 0.6: {p2}");
}

/// At nu = 1/2 (beta = 0) the lateral term beta P2/L vanishes: `periodic` is Kuznetsov's load
/// (E* k L^2/pi) ln sec lambda exactly, as `paper`; the single punch (period "inf") is the same
/// problem in both conventions, bit for bit.
#[test]
fn conventions_coincide_at_nu_half_and_for_the_single_punch() {
    let pr = row(q(1, 2), q(4, 5), Convention::PeriodicSurface);
    let m = solve_verified(&pr, &[q(1, 2)], 25).unwrap();
    let prec = m.solution.prec;
    let lam = Float::with_val(prec, &m.solution.lambda);
    let want = Float::with_val(prec, lam.cos_ref()).recip().ln() / Float::with_val(prec, rug::float::Constant::Pi);
    let e = Float::with_val(prec, &m.solution.normal_load - &want).abs().to_f64() / want.to_f64();
    assert!(e < 1e-25, "{e:e}");
    let single = |c| problem(q(0, 1), Period::Infinite, AdhesionSize::HalfWidth(q(1, 5)), c);
    let (a, b) = (
        solve_verified(&single(Convention::Paper), &points(), 20).unwrap(),
        solve_verified(&single(Convention::PeriodicSurface), &points(), 20).unwrap(),
    );
    assert_eq!(a.solution.normal_load, b.solution.normal_load);
    for (x, y) in a.solution.points.iter().zip(&b.solution.points) {
        assert_eq!((&x.psi, &x.q1, &x.q2), (&y.psi, &y.q1, &y.q2));
    }
}

/// The homogeneous mode of docs/theory.md section 11 (Re M_m* = 0, m* = 605.73 at nu = 0) has the
/// same symbol in `periodic` (the lateral term is O(lambda) beside the single punch's kernel), but
/// there its local exponent grows with the contact instead of falling (section 8, Problem 2), so no
/// discretisation excites it: at nu = 0, lambda = 1 two MPFR collocations (60 and 100 Chebyshev
/// nodes, 200 bits) agree on F at sigma = 1 and on the load to 1e-30 in `periodic`, where in
/// `paper` they differ by 1.7e-4 (`tests.rs`' two_discretisations_differ_by_a_homogeneous_solution).
#[test]
fn periodic_discretisations_agree_where_the_mode_spoils_paper() {
    let p = VolterraParams { prec: 200, target_bits: 160, refine: 1.3 };
    let c = AdhesionParamsMpfr::new(&material(q(0, 1)), p.prec);
    let lam = Float::with_val(p.prec, 1);
    let runs: Vec<_> = [60, 100]
        .iter()
        .map(|&n| volterra_mpfr::solve_with_nodes_in(&c, &lam, p, n, &RightSide::Parabola, true).unwrap())
        .collect();
    let one = Float::with_val(p.prec, 1);
    let f = Float::with_val(p.prec, runs[0].f_at(&one) - runs[1].f_at(&one)).abs().to_f64();
    let load = Float::with_val(p.prec, runs[0].load_ratio() - runs[1].load_ratio()).abs().to_f64();
    eprintln!("periodic, nu = 0, lambda = 1: F(1) {f:e}, load {load:e}");
    assert!(f < 1e-30 && load < 1e-30, "{f:e} {load:e}");
}

/// A given load in `periodic` finds the half-width by both methods (MPFR: Newton on the load of one
/// collocation in sigma; f64: the collocation's Newton): P2 = 0.224395589552080523514 (the value
/// at lambda = 1, nu = 0, 21 digits) gives a = 1/pi to 1e-19 (MPFR) and 1e-13 (f64).
#[test]
fn a_given_load_finds_the_half_width_in_periodic() {
    let p2 = Exact::new(
        "224395589552080523514".parse::<num_bigint::BigInt>().unwrap(),
        "1000000000000000000000".parse::<num_bigint::BigInt>().unwrap(),
    );
    let pr =
        problem(q(0, 1), Period::finite(q(1, 1)).unwrap(), AdhesionSize::NormalLoad(p2), Convention::PeriodicSurface);
    let want = 1.0 / std::f64::consts::PI;
    let m = solve_verified(&pr, &[q(1, 2)], 20).unwrap();
    let prec = m.solution.prec;
    let inv_pi = Float::with_val(prec, rug::float::Constant::Pi).recip();
    let e = Float::with_val(prec, &m.solution.half_width - &inv_pi).abs().to_f64();
    assert!(e < 1e-19 && m.digits_verified.headline >= 18.0, "{e:e} {:?}", m.digits_verified);
    let f = solve_f64(&pr, &[q(1, 2)]).unwrap();
    assert!((f.half_width - want).abs() < 1e-13, "{} vs {want}", f.half_width);
}

/// Long tier (`cargo test --lib adhesion::convention_tests -- --ignored --nocapture`; the dev profile is optimised):
/// the report's full Problem 2 grid (nu = 0, 3/20, 3/10, 9/20, 1/2; lambda = 0.2, 0.5, 0.8, 1.1, 1.4)
/// in `periodic`: MPFR verifies >= 20 digits at 20 asked and f64 agrees with it to >= 12 at every
/// cell (the report's text says the `paper` refusals at small nu do not occur there). Measured
/// 2026-11-27 (17 s): MPFR 24.0-30.1 digits up to lambda = 1.1 and 21.2-21.3 at 1.4, agreement
/// 14.5-15.5.
#[test]
#[ignore = "long tier: 17 s, the report grid of 25 cells in MPFR and f64 (scripts/test --long)"]
fn periodic_map_grid_holds_20_digits() {
    for lam in [(1, 5), (1, 2), (4, 5), (11, 10), (7, 5)] {
        for nu in [(0, 1), (3, 20), (3, 10), (9, 20), (1, 2)] {
            let pr = row(q(nu.0, nu.1), q(lam.0, lam.1), Convention::PeriodicSurface);
            let m = solve_verified(&pr, &points(), 20).unwrap();
            let f = solve_f64(&pr, &points()).unwrap();
            let agree = agreement(&m, &f);
            eprintln!(
                "nu {}/{} lambda {}/{}: MPFR {:.1} digits, f64 estimated {:.1}, agreement {agree:.1}",
                nu.0, nu.1, lam.0, lam.1, m.digits_verified.headline, f.digits_estimated.headline
            );
            assert!(m.digits_verified.headline >= 20.0 && agree >= 12.0, "nu {nu:?} lambda {lam:?}");
        }
    }
}

/// A shortfall in `periodic` names full contact, not the homogeneous mode (not excited there,
/// docs/theory.md section 8, Problem 2): nu = 0, lambda = 1.54, 20 digits asked: 18.6 verified
/// (measured), with a warning naming full contact and no m*.
#[test]
#[ignore = "long tier: 4 s alone in the test profile (opt-level 2) on a loaded 2-core machine (scripts/test --long)"]
fn periodic_shortfall_names_full_contact() {
    let pr = row(q(0, 1), q(154, 100), Convention::PeriodicSurface);
    let v = solve_verified(&pr, &[q(1, 2)], 20).unwrap();
    assert!(v.digits_verified.headline < 20.0, "{:?}", v.digits_verified);
    let w = v.warnings.iter().find(|w| w.contains("requested digits verified")).expect("a shortfall warning");
    assert!(w.contains("full contact") && !w.contains("m* ="), "{w}");
}
