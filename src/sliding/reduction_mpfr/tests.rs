//! Tests of the high-precision sliding solver against closed forms (docs/theory.md section 6) and the
//! single-punch limit [3.10], and of its internal consistency. Explorations that only print
//! (timings, edge cases, the sinusoid's load curve) are `examples/reduction_mpfr_explore.rs`.

use super::contact::{Contact, Size};
use super::pressure::Pressure;
use super::setup::Setup;
use super::solve::{solve_located, Checks};
use super::*;
use crate::model::OnPunchRow;
use crate::model::{Exact, Material, Period, PunchShape, SlidingLoad, SlidingProblem};
use crate::numerics::accuracy::agreement_mpfr;
use crate::numerics::gauss_jacobi_mpfr::{gauss_jacobi, GaussJacobiRule};
use crate::params::sliding::SlidingParamsMpfr;
use rug::{float::Constant, Float};
use std::sync::Arc;

fn q(s: &str) -> Exact {
    s.parse().expect("rational literal")
}

/// The exact rational `s` rounded to `prec` bits.
fn at_prec(s: &str, prec: u32) -> Float {
    Float::with_val(prec, crate::numerics::exact::to_rational(&q(s)))
}

/// Punch shape of a test case.
#[derive(Debug, Clone, Copy)]
enum Shape {
    /// g = k x^2 with this k.
    Parabola(&'static str),
    /// g = D (1 - cos(2 pi x/L)) with this D.
    Sinusoid(&'static str),
}

/// Inputs of one test problem (exact rationals as text; period "inf" is a single punch; speed 2).
#[derive(Debug, Clone, Copy)]
struct Case {
    nu: &'static str,
    e: &'static str,
    period: &'static str,
    shape: Shape,
    mu: &'static str,
    tau0: &'static str,
    cw: &'static str,
    convention: Convention,
}

/// Friction, adhesive friction and wear together (theta ~ -0.05): the default of these tests.
const BASE: Case = Case {
    nu: "1/4",
    e: "1",
    period: "1",
    shape: Shape::Parabola("1"),
    mu: "1/5",
    tau0: "1/100",
    cw: "1/10",
    convention: Convention::Paper,
};

/// No friction, adhesion or wear, nu = 1/2 (beta = 0, theta = 0): the closed forms' case.
const FRICTIONLESS: Case = Case { nu: "1/2", mu: "0", tau0: "0", cw: "0", ..BASE };

/// A periodic parabola with theta = -0.06 and tau0 > 0 (E* = 2): the consistency checks' case.
const MIXED: Case = Case { e: "2", mu: "3/10", tau0: "1/50", cw: "1/5", ..BASE };

impl Case {
    fn problem(self, load: SlidingLoad) -> SlidingProblem {
        let period = if self.period == "inf" { Period::Infinite } else { Period::finite(q(self.period)).unwrap() };
        let shape = match self.shape {
            Shape::Parabola(k) => PunchShape::parabolic(q(k)).unwrap(),
            Shape::Sinusoid(d) => PunchShape::sinusoidal(q(d)).unwrap(),
        };
        SlidingProblem::builder()
            .material(Material::from_contact_modulus(q(self.nu), q(self.e)).unwrap())
            .period(period)
            .shape(shape)
            .friction(q(self.mu))
            .adhesive_friction(q(self.tau0))
            .wear(q(self.cw))
            .speed(Some(q("2")))
            .load(load)
            .convention(self.convention)
            .build()
            .unwrap()
    }

    /// The inverse problem: the load P2 given.
    fn load(self, p2: &str) -> SlidingProblem {
        self.problem(SlidingLoad::NormalLoad(q(p2)))
    }

    /// The direct problem: the half-length l given.
    fn size(self, l: &str) -> SlidingProblem {
        self.problem(SlidingLoad::HalfLength(q(l)))
    }
}

/// -log10(|x - y|/|scale|), infinite for x = y (no cap: these tests compare with closed forms).
fn digits(x: &Float, y: &Float, scale: &Float) -> f64 {
    agreement_mpfr(x, y, scale, f64::INFINITY)
}

fn float_to_exact(x: &Float) -> Exact {
    let r = x.to_rational().expect("finite");
    r.to_string().parse().expect("rational")
}

/// One run at `digits` digits with the physicality checks, in the problem's units.
fn at(pb: &SlidingProblem, points: &[Exact], digits: u32) -> Vec<SlidingSolution> {
    solve_at(pb, points, NodeRule { digits: digits as f64, factor: 1.0 }, Checks::Physical, precision_for(digits))
        .unwrap()
}

/// One run at `digits` digits in the solver's units (E* = 1), with the parameters it used.
fn run(pb: &SlidingProblem, digits: u32) -> (SlidingParamsMpfr, Vec<SlidingSolution>) {
    let setup = Setup::new(pb).unwrap();
    let params = SlidingParamsMpfr::new(pb, precision_for(digits)).unwrap();
    let rule = NodeRule { digits: digits as f64, factor: 1.0 };
    let sols = solve_located(&setup, &params, &[], rule, Checks::Physical, None).unwrap();
    (params, sols.into_iter().map(|x| x.0).collect())
}

/// A solution's contact rebuilt from `run`'s parameters, with the 1/omega rule it used.
struct Rebuilt {
    size: Size,
    contact: Contact,
    rule: Arc<GaussJacobiRule>,
}

fn rebuild(params: &SlidingParamsMpfr, s: &SlidingSolution) -> Rebuilt {
    let size = Size::new(params, s.lambda.as_ref().unwrap_or(&s.l));
    let contact = Contact::new(params, &size, s.c.clone());
    let (a, b) = params.inverse_weight_exponents();
    let rule = gauss_jacobi(&a, &b, s.nodes, params.prec).unwrap();
    Rebuilt { size, contact, rule }
}

/// int_{-1}^{1} g(y) dy by tanh-sinh quadrature (step 1/64, |k| <= 300; nodes within 1e-35 of
/// +-1 left out, so an integrand singular at the ends must be integrable there).
fn tanh_sinh(prec: u32, mut g: impl FnMut(&Float) -> Float) -> Float {
    let pi = Float::with_val(prec, Constant::Pi);
    let h = Float::with_val(prec, 1u32) / 64u32;
    let mut sum = Float::with_val(prec, 0);
    for k in -300i32..=300 {
        let t = Float::with_val(prec, &h * k);
        let sh = Float::with_val(prec, t.sinh_ref()) * &pi / 2u32;
        let y = Float::with_val(prec, sh.tanh_ref());
        let w = Float::with_val(prec, t.cosh_ref()) * &pi / 2u32 / Float::with_val(prec, sh.cosh_ref()).square();
        if Float::with_val(prec, 1u32 - Float::with_val(prec, y.abs_ref())) < Float::with_val(53, 1e-35) || w.is_zero()
        {
            continue;
        }
        sum += g(&y) * w;
    }
    sum * h
}

#[test]
fn kuznetsov_periodic_parabola_frictionless() {
    // P2 = (E* k L^2/pi) ln sec(pi a/L) [2.15], docs/theory.md section 6. nu = 1/2: beta = 0, theta = 0.
    for a in ["1/10", "1/4", "3/10"] {
        let pb = Case { e: "3", shape: Shape::Parabola("2"), mu: "1/5", ..FRICTIONLESS }.size(a);
        let v = solve_verified(&pb, &[q("1/2")], 30).unwrap();
        assert_eq!(v.len(), 1);
        let s = &v[0].solution;
        assert!(v[0].accuracy.digits_verified >= 30.0, "{:?}", v[0].accuracy);
        let p = s.prec + 40;
        let pi = Float::with_val(p, Constant::Pi);
        let sec = Float::with_val(p, &pi * at_prec(a, p)).cos().recip();
        let expect = sec.ln() * 6u32 / &pi; // E* k L^2 = 3 * 2 * 1
        assert!(digits(&s.p2, &expect, &expect) >= 30.0, "a = {a}: {} vs {}", s.p2, expect);
        assert!(s.c.to_f64().abs() < 1e-35);
    }
}

#[test]
fn westergaard_sinusoid_frictionless() {
    // P2 = pi E* D sin^2(pi a/L) [2.17].
    for a in ["1/20", "1/5", "2/5"] {
        let pb = Case { e: "2", period: "3/2", shape: Shape::Sinusoid("1/7"), ..FRICTIONLESS }.size(a);
        let v = solve_verified(&pb, &[], 30).unwrap();
        assert_eq!(v.len(), 1);
        let s = &v[0].solution;
        assert!(v[0].accuracy.digits_verified >= 30.0, "{:?}", v[0].accuracy);
        let p = s.prec + 40;
        let pi = Float::with_val(p, Constant::Pi);
        let sn = Float::with_val(p, &pi * at_prec(a, p) * 2u32 / 3u32).sin();
        let expect = Float::with_val(p, sn.square_ref()) * &pi * 2u32 / 7u32;
        assert!(digits(&s.p2, &expect, &expect) >= 30.0, "a = {a}: {} vs {}", s.p2, expect);
    }
}

#[test]
fn westergaard_inverse_problem() {
    let pb = Case { e: "2", shape: Shape::Sinusoid("1/10"), ..FRICTIONLESS }.load("1/5");
    let v = solve_verified(&pb, &[], 30).unwrap();
    assert_eq!(v.len(), 1);
    let s = &v[0].solution;
    let p = s.prec;
    let pi = Float::with_val(p, Constant::Pi);
    let sn = Float::with_val(p, &pi * &s.a).sin();
    let p2 = Float::with_val(p, sn.square_ref()) * &pi * 2u32 / 10u32;
    assert!(digits(&p2, &s.p2, &s.p2) >= 30.0);
}

#[test]
fn single_punch_limit_with_friction_wear_and_adhesion() {
    // l_s = a0/sqrt(1 - 4 theta^2), rbar_s = 2 theta - T, a0 = sqrt(2 P2/(pi E* k)),
    // T = beta tau0/(E* k l_s) [3.10]. nu = 1/4: beta = 1/3.
    for (mu, cw, tau0) in [("3/10", "0", "1/100"), ("0", "1/2", "1/50"), ("1/2", "1/10", "0"), ("0", "0", "1/20")] {
        let pb = Case { e: "2", period: "inf", shape: Shape::Parabola("1/2"), mu, tau0, cw, ..BASE }.load("1");
        let v = solve_verified(&pb, &[q("0")], 30).unwrap();
        let s = &v[0].solution;
        assert!(v[0].accuracy.digits_verified >= 30.0, "{:?}", v[0].accuracy);
        assert!(s.wear_per_distance.is_none());
        let p = s.prec;
        let pi = Float::with_val(p, Constant::Pi);
        let th = &s.theta;
        let a0 = (Float::with_val(p, 2u32) / (Float::with_val(p, &pi * 2u32) / 2u32)).sqrt(); // E* k = 1
        let ls = Float::with_val(p, &a0 / (1u32 - Float::with_val(p, th.square_ref()) * 4u32).sqrt());
        assert!(digits(&s.l, &ls, &ls) >= 30.0, "l {} vs {}", s.l, ls);
        let beta = Float::with_val(p, 1u32) / 3u32;
        let tau = at_prec(tau0, p);
        let t = Float::with_val(p, &beta * &tau) / &ls;
        let rbar = Float::with_val(p, th * 2u32) - &t;
        let got = Float::with_val(p, &s.c / &s.l);
        assert!(digits(&got, &rbar, &Float::with_val(p, 1)) >= 30.0, "rbar {got} vs {rbar}");
        // P1 = mu P2 + 2 l tau0.
        let p1 = at_prec(mu, p) + Float::with_val(p, &s.l * &tau) * 2u32;
        assert!(digits(&s.p1, &p1, &s.p2) >= 30.0);
    }
}

#[test]
fn hertz_pressure_in_the_problems_units() {
    // p = E* k sqrt(a^2 - x^2), P2 = (pi/2) E* k a^2 with E* = 5, k = 3: the solver works in units
    // of E* and returns loads and stresses in the problem's.
    let pb = Case { e: "5", period: "inf", shape: Shape::Parabola("3"), ..FRICTIONLESS }.load("7");
    let pts = [q("-9/10"), q("-1/3"), q("0"), q("1/2"), q("99/100")];
    let v = solve_verified(&pb, &pts, 40).unwrap();
    let s = &v[0].solution;
    assert!(v[0].accuracy.digits_verified >= 40.0, "{:?}", v[0].accuracy);
    let p = s.prec;
    let a2 = Float::with_val(p, s.a.square_ref());
    for pt in &s.pressure {
        let expect = (Float::with_val(p, &a2 - Float::with_val(p, pt.x.square_ref()))).sqrt() * 15u32;
        assert!(digits(&pt.p, &expect, &s.max_pressure) >= 40.0, "x = {}: {} vs {}", pt.x, pt.p, expect);
    }
    let pi = Float::with_val(p, Constant::Pi);
    let p2 = Float::with_val(p, &pi * &a2) * 15u32 / 2u32;
    assert!(digits(&p2, &s.p2, &s.p2) >= 40.0);
    assert!(digits(&s.p2, &at_prec("7", p), &s.p2) >= 40.0);
}

#[test]
fn load_is_the_integral_of_the_pressure() {
    // P2 from [2.14] (given) against int p dx by a separate Gauss–Jacobi rule for omega.
    let cases = [
        MIXED.load("1/10"),
        Case { nu: "0", shape: Shape::Sinusoid("1/20"), cw: "0", ..BASE }.size("1/5"),
        Case { nu: "1/3", period: "inf", mu: "1/2", tau0: "1/10", cw: "1", ..BASE }.load("1"),
    ];
    for pb in cases {
        let (params, sols) = run(&pb, 30);
        for s in sols {
            let r = rebuild(&params, &s);
            let (aw, bw) = params.weight_exponents();
            let rule_w = gauss_jacobi(&aw, &bw, s.nodes, s.prec).unwrap();
            let pr = Pressure::new(&params, &r.contact, &r.rule);
            let (p2, fdef) = pr.load_and_deformation_force(&rule_w);
            assert!(digits(&p2, &s.p2, &s.p2) >= 30.0, "{p2} vs {}", s.p2);
            assert!(digits(&fdef, &s.f_def, &s.p2) >= 30.0);
        }
    }
}

/// Issue 14: D(u) of [`Pressure::d`] (its f64 screen of the nodes near u, its values of F at a raised
/// precision kept per precision) is bit for bit the plain sum of its doc: every node tested exactly
/// for nearness, F at the nodes recomputed at the raised precision for each point; at points far
/// from the nodes, within 2^-16 of one (raised precision, asked twice) and within 2^(-prec/2)
/// (the midpoint derivative), inside and outside [-1, 1].
#[test]
fn pressure_sum_is_the_plain_sum() {
    use rug::Assign;
    let (params, sols) = run(&MIXED.load("1/10"), 30);
    let s = &sols[0];
    let r = rebuild(&params, s);
    let pr = Pressure::new(&params, &r.contact, &r.rule);
    let p = params.prec;
    let plain = |u: &Float| -> Float {
        let min_gap = r.rule.nodes.iter().map(|x| (x.to_f64() - u.to_f64()).abs()).fold(f64::INFINITY, f64::min);
        let lost = if min_gap < 1.0 / 65536.0 { ((-min_gap.max(1e-300).log2()).ceil() as u32).min(p) } else { 0 };
        let wp = p + lost;
        let fu = r.contact.f(&params, u, wp);
        let near = Float::with_val(53, Float::i_exp(1, -(p as i32) / 2));
        let mut acc = Float::with_val(wp, 0);
        for (x, w) in r.rule.nodes.iter().zip(&r.rule.weights) {
            let d = Float::with_val(wp, x - u);
            let mut t = if Float::with_val(53, d.abs_ref()) < near {
                let mid = Float::with_val(wp, x + u) / 2u32;
                r.contact.f_prime(&params, &mid, wp)
            } else {
                let mut t = Float::new(wp);
                t.assign(&r.contact.f(&params, x, wp) - &fu);
                t / &d
            };
            t *= w;
            acc += &t;
        }
        Float::with_val(p, acc)
    };
    let node = &r.rule.nodes[r.rule.len() - 2];
    let points = [
        Float::with_val(p, 0.3),
        Float::with_val(p, 1.7),
        Float::with_val(p, -3.5),
        Float::with_val(p, node + 1e-7),
        Float::with_val(p, node - 3e-7),
        Float::with_val(p, node + 1e-7),
        Float::with_val(p, node + Float::with_val(p, Float::i_exp(1, -(p as i32) / 2 - 3))),
    ];
    for u in &points {
        let (got, want) = (pr.d(u), plain(u));
        assert!(got == want && got.is_finite(), "u = {u}: {got} vs {want}");
    }
}

#[test]
fn direct_and_inverse_problems_agree() {
    let cases = [
        (BASE, "1/20"),
        (Case { shape: Shape::Sinusoid("1/10"), ..BASE }, "1/10"),
        (Case { period: "inf", shape: Shape::Parabola("2"), ..BASE }, "1"),
    ];
    for (case, load) in cases {
        let s1 = &at(&case.load(load), &[q("1/3")], 30)[0];
        let s2 = &at(&case.problem(SlidingLoad::HalfLength(float_to_exact(&s1.l))), &[q("1/3")], 30)[0];
        assert!(digits(&s1.p2, &s2.p2, &s1.p2) >= 30.0, "{} vs {}", s1.p2, s2.p2);
        assert!(digits(&s1.c, &s2.c, &s1.l) >= 30.0);
        assert!(digits(&s1.pressure[0].p, &s2.pressure[0].p, &s1.max_pressure) >= 30.0);
    }
}

#[test]
fn adhesive_friction_does_not_change_lambda_for_the_parabola() {
    let s0 = &at(&Case { tau0: "0", ..BASE }.load("1/20"), &[], 30)[0];
    let s1 = &at(&BASE.load("1/20"), &[], 30)[0];
    let (l0, l1) = (s0.lambda.as_ref().unwrap(), s1.lambda.as_ref().unwrap());
    assert!(digits(l0, l1, l0) >= 30.0);
    assert!(s1.c < s0.c, "tau0 shifts the contact toward -x");
}

#[test]
fn contact_leaving_the_period_is_an_error() {
    // Parabola with wear (theta ~ 0.1, rbar ~ 2 theta), large contact: b = l + c reaches L/2;
    // strong adhesive friction pushes the contact out of the period.
    for pb in
        [Case { cw: "13/20", ..FRICTIONLESS }.size("9/20"), Case { nu: "0", tau0: "1", ..FRICTIONLESS }.size("1/4")]
    {
        let e = crate::error::Error::from(solve_verified(&pb, &[], 20).unwrap_err());
        assert_eq!(e.kind(), crate::error::ErrorKind::NotPhysical, "{e}");
        let text = e.to_string();
        assert!(text.contains("leaves the cell"), "{text}");
        assert!(
            text.contains("physical contacts have half_length in")
                || text.contains("no contact size gives a physical contact"),
            "{text}"
        );
    }
}

#[test]
fn theta_too_close_to_one_half_and_bad_points_are_errors() {
    let pb = Case { cw: "100000000", ..FRICTIONLESS }.load("1/100");
    let e = solve_verified(&pb, &[], 20).unwrap_err();
    assert!(matches!(&e, SlidingError::Parameter { parameter, .. } if parameter.starts_with("theta")), "{e}");
    let pb = FRICTIONLESS.load("1/100");
    let e = solve_verified(&pb, &[q("1")], 20).unwrap_err();
    assert!(matches!(&e, SlidingError::Parameter { parameter, .. } if parameter == "points"), "{e}");
    // A point that rounds to 1 in f64 is still inside (-1, 1): compared exactly.
    assert!(solve_verified(&pb, &[q("99999999999999999999/100000000000000000000")], 20).is_ok());
    // Variants built directly are validated once, when the problem is built.
    let e = pb.to_builder().shape(PunchShape::Sinusoidal { amplitude: q("1") }).period(Period::Infinite).build();
    assert_eq!(e.unwrap_err().parameter, "period");
    let e = pb.to_builder().shape(PunchShape::Parabolic { k: q("-1") }).build();
    assert_eq!(e.unwrap_err().parameter, "k");
}

/// The sinusoid with friction (theta = -0.102): P2(lambda) rises to a maximum (0.16247 at
/// 2l/L ~ 0.61) and falls again, so a load below the maximum has two roots of [2.14]. Under the
/// shared criterion (docs/theory.md section 8; in `paper` a negative gap is a warning) the larger root
/// is refused for p < 0 at the trailing end; P2 = 3/20 is solved with a gap warning beside the
/// closure defect M = (2/E*) beta P1 (asserted), and a load above the maximum is refused with the
/// admissible range (0, 0.16247]. The whole curve is charted by
/// `cargo run --release --example reduction_mpfr_explore -- load-curve`.
#[test]
fn non_monotone_sinusoid() {
    let case = Case { shape: Shape::Sinusoid("1/10"), mu: "1", tau0: "0", cw: "0", ..BASE };
    // Two roots of the equations at P2 = 1/10; the physical one is returned.
    let v = solve_verified(&case.load("1/10"), &[q("0")], 30).unwrap();
    assert_eq!(v.len(), 1);
    assert!(v[0].accuracy.digits_verified >= 30.0, "{:?}", v[0].accuracy);
    let lam = v[0].solution.lambda.as_ref().unwrap().to_f64();
    assert!(lam > 0.5 && lam < 0.8, "lambda = {lam}");
    // All roots of the equations, physical or not (run without the checks): two, sorted by size.
    let all = solve_at(&case.load("1/10"), &[], NodeRule { digits: 20.0, factor: 1.0 }, Checks::Skip, 128).unwrap();
    assert_eq!(all.len(), 2);
    assert!(all[0].l < all[1].l);
    let lam2 = all[1].lambda.as_ref().unwrap().to_f64();
    assert!(lam2 > 1.1 && lam2 < 1.4, "second root lambda = {lam2}");
    // The larger root is not physical (negative pressure at the trailing end).
    let e = crate::error::Error::from(
        solve_verified(&case.size(&float_to_exact(&all[1].l).to_string()), &[], 20).unwrap_err(),
    );
    assert_eq!(e.kind(), crate::error::ErrorKind::NotPhysical, "{e}");
    assert!(
        e.to_string().contains("negative pressure")
            && e.to_string().contains("physical contacts have half_length in (0, "),
        "{e}"
    );
    // Inside the physical range with a negative gap: solved, with the warning and the closure
    // defect M = (2/E*) beta P1 - cW P2 (E* = 1, cW = 0).
    let v = solve_verified(&case.load("3/20"), &[], 20).unwrap();
    let s = &v[0].solution;
    let ph = s.physicality.as_ref().expect("checked");
    assert!(ph.min_gap < 0.0 && ph.warning.as_deref().is_some_and(|w| w.contains("closure defect")), "{ph:?}");
    let m = (Float::with_val(s.prec, &SlidingParamsMpfr::new(&case.load("3/20"), s.prec).unwrap().beta * &s.p1) * 2u32)
        .to_f64();
    let defect = ph.closure_defect.expect("a period");
    assert!((defect - m).abs() < 1e-9 * m, "{defect} vs {m}");
    // Above the maximum of P2(lambda): no solution, the refusal states the admissible range.
    for load in ["1/5"] {
        let e = crate::error::Error::from(solve_verified(&case.load(load), &[], 20).unwrap_err());
        let text = e.to_string();
        assert!(text.contains(&format!("normal_load = {load}")), "{text}");
        let cap = largest_admissible_load(&text);
        assert!(cap > 0.1624 && cap < 0.1625, "{text}");
        assert_eq!(e.kind(), crate::error::ErrorKind::NoSolution, "{text}");
    }
}

/// The largest physical load quoted by a refusal ("normal_load in (0, X]").
fn largest_admissible_load(text: &str) -> f64 {
    crate::sliding::physicality::admissible::Admissible::quoted_largest_load(text)
        .unwrap_or_else(|| panic!("no admissible range in: {text}"))
}

/// See: issue 9. The refusal states the given load and the largest load in the problem's units
/// (the solver works in units of E*, which must not leak into messages): E* = 5, D = 1/10, L = 2,
/// frictionless; the scan of the admissible range reaches lambda = 1.525, where the sinusoid
/// carries pi E* D sin^2(1.525) = 1.5675 (Westergaard, docs/theory.md section 6); the load is above
/// full contact, pi E* D = 1.5708, which the refusal names.
#[test]
fn refusal_is_in_the_problems_units() {
    let pb = Case { e: "5", period: "2", shape: Shape::Sinusoid("1/10"), ..FRICTIONLESS }.load("7/3");
    let e = crate::error::Error::from(solve_verified(&pb, &[], 20).unwrap_err());
    assert_eq!(e.kind(), crate::error::ErrorKind::NoSolution, "{e}");
    let text = e.to_string();
    assert!(text.contains("normal_load = 7/3"), "{text}");
    let cap = largest_admissible_load(&text);
    let westergaard = std::f64::consts::PI * 5.0 * 0.1 * 1.525f64.sin().powi(2);
    assert!((cap - westergaard).abs() < 1e-6 * westergaard, "{cap} vs {westergaard}: {text}");
    assert!(
        text.starts_with(
            "no solution: no contact carries normal_load = 7/3: it exceeds the full-contact load pi E* D = 1.570796"
        ),
        "{text}"
    );
}

/// Issue 14: the admissible range is scanned once per problem without its load. The memo's key
/// ignores the load (the scan solves the direct problem only) but not friction, the memoized range
/// equals a fresh scan, and two loads of one problem refused for the same reason quote the same
/// range (theta = -0.4 by friction on the periodic parabola: physical loads up to about 0.0432,
/// the report's stability map).
#[test]
fn admissible_range_is_memoized_per_problem_without_its_load() {
    let base = Case { nu: "3/10", mu: "10771892/1000000", tau0: "0", cw: "0", ..BASE };
    let (p1, p2) = (base.load("1/5"), base.load("1/4"));
    let lo = |p: &SlidingProblem| Setup::new(p).unwrap().locate;
    let (l1, l2) = (lo(&p1), lo(&p2));
    assert_ne!(l1.target, l2.target);
    assert_eq!(super::solve::admissible_key(&l1, 1.5), super::solve::admissible_key(&l2, 1.5));
    let other = lo(&Case { mu: "10771893/1000000", ..base }.load("1/5"));
    assert_ne!(super::solve::admissible_key(&l1, 1.5), super::solve::admissible_key(&other, 1.5));
    assert_ne!(super::solve::admissible_key(&l1, 1.5), super::solve::admissible_key(&l1, 1.4));
    let s_max = super::solve::scan_max(&l1);
    let fresh = super::solve::admissible_scan(&l1, s_max).unwrap();
    assert_eq!(super::solve::admissible_range(&l2).unwrap(), fresh);
    assert_eq!(super::solve::admissible_range(&l1).unwrap(), fresh);
    let max = fresh.max_load().expect("a physical run").0;
    assert!(max > 0.0431 && max < 0.0433, "{fresh:?}");
    let text = |p: &SlidingProblem| crate::error::Error::from(solve_verified(p, &[], 20).unwrap_err()).to_string();
    let (t1, t2) = (text(&p1), text(&p2));
    assert_eq!(largest_admissible_load(&t1), largest_admissible_load(&t2), "{t1}\n{t2}");
}

/// Independent check of the reduction [2.13]-[2.14] for theta != 0, tau0 > 0 on a periodic row:
/// the pressure it returns satisfies the original equation [2.8]
///     kappa p(x) + H[p](x) = (E*/2) g'(x) + beta tau0,  H[p] = (1/L) PV int p(xi) cot(pi (x - xi)/L) dxi,
/// with H evaluated directly (no tangent map): PV int = int [p(xi) - p(x)] cot(...) dxi plus
/// p(x) (L/pi) ln|sin(pi (x + a)/L)/sin(pi (b - x)/L)|, the regular integral by tanh-sinh
/// quadrature in the linear variable (points off its nodes). Residuals below 1e-30 relative to
/// E* k l.
#[test]
fn original_cot_kernel_equation_is_satisfied() {
    let cases = [
        MIXED.load("1/10"),
        Case { nu: "0", shape: Shape::Sinusoid("1/20"), cw: "1/2", ..BASE }.size("1/5"),
        Case { nu: "1/3", period: "2", mu: "0", tau0: "0", cw: "1", ..BASE }.size("3/10"),
    ];
    for pb in cases {
        let (params, sols) = run(&pb, 30);
        let s = &sols[0];
        let prec = params.prec;
        assert!(s.theta.to_f64().abs() > 0.01);
        let r = rebuild(&params, s);
        let pr = Pressure::new(&params, &r.contact, &r.rule);
        let (big_l, pi, lam) = (params.period.clone().unwrap(), params.pi.clone(), s.lambda.clone().unwrap());
        let m = Float::with_val(prec, lam.tan_ref());
        // p at x - c = l y (linear variable y in (-1, 1)).
        let p_at = |y: &Float| -> Float { pr.p(&(Float::with_val(prec, &lam * y).tan() / &m)) };
        let mut worst = 0.0f64;
        for yx in ["-4/5", "-1/3", "1/7", "1/2", "9/10"] {
            let yx = at_prec(yx, prec);
            let px = p_at(&yx);
            let regular = tanh_sinh(prec, |y| {
                let arg = Float::with_val(prec, &yx - y) * &s.l * &pi / &big_l; // pi (x - xi)/L
                (p_at(y) - &px) * Float::with_val(prec, arg.tan_ref()).recip()
            }) * &s.l;
            let x = Float::with_val(prec, &s.l * &yx) + &s.c;
            let s1 = Float::with_val(prec, &pi * Float::with_val(prec, &x + &s.a)) / &big_l;
            let s2 = Float::with_val(prec, &pi * Float::with_val(prec, &s.b - &x)) / &big_l;
            let log = (Float::with_val(prec, s1.sin_ref()) / Float::with_val(prec, s2.sin_ref())).abs().ln();
            let hp = (regular + Float::with_val(prec, &px * log) * &big_l / &pi) / &big_l;
            let u = Float::with_val(prec, &lam * &yx).tan() / &m;
            let rhs = r.contact.f(&params, &u, prec) + Float::with_val(prec, &params.beta * &params.tau0);
            let lhs = Float::with_val(prec, &params.kappa * &px) + hp;
            let scale = Float::with_val(prec, &params.k * &s.l); // E* k l with E* = 1
            worst = worst.max(Float::with_val(64, Float::with_val(prec, &lhs - &rhs) / &scale).abs().to_f64());
        }
        assert!(worst < 1e-30, "residual of [2.8] relative to E* k l: {worst:e}");
    }
}

/// Independent check of the outside formula used by the gap check:
/// (E*/2) v'(x) = H[p](x) = F(t) + beta tau0 - X(t) cos(pi theta) D(t)/pi for x outside the contact,
/// against H[p] = (1/L) int p(xi) cot(pi (x - xi)/L) dxi by tanh-sinh (regular integrand).
#[test]
fn outside_displacement_formula() {
    let (params, sols) = run(&MIXED.load("1/10"), 30);
    let s = &sols[0];
    let prec = params.prec;
    let r = rebuild(&params, s);
    let pr = Pressure::new(&params, &r.contact, &r.rule);
    let (big_l, pi, lam) = (params.period.clone().unwrap(), params.pi.clone(), s.lambda.clone().unwrap());
    let m = Float::with_val(prec, lam.tan_ref());
    for off in ["13/10", "-3/2", "2"] {
        // x - c = off * l (outside the contact, inside (-L/2, L/2) relative to c).
        let xc = at_prec(off, prec) * &s.l;
        let hp_direct = tanh_sinh(prec, |y| {
            let u = Float::with_val(prec, &lam * y).tan() / &m;
            let arg = Float::with_val(prec, &xc - Float::with_val(prec, y * &s.l)) * &pi / &big_l;
            pr.p(&u) * Float::with_val(prec, arg.tan_ref()).recip()
        }) * &s.l
            / &big_l;
        // Formula: t = u(x), X(t) = sign(t)|t-1|^{1/2-theta}|t+1|^{1/2+theta}.
        let t = r.size.u_of(&params, &xc, prec);
        let e1 = Float::with_val(prec, &params.theta + 0.5f64);
        let e2 = Float::with_val(prec, 0.5f64 - Float::with_val(prec, &params.theta));
        use rug::ops::Pow;
        let mut xt = Float::with_val(prec, Float::with_val(prec, &t + 1u32).abs().pow(&e1))
            * Float::with_val(prec, &t - 1u32).abs().pow(&e2);
        if t.is_sign_negative() {
            xt = -xt;
        }
        let hp_formula = r.contact.f(&params, &t, prec) + Float::with_val(prec, &params.beta * &params.tau0)
            - xt * pr.d(&t) * &params.cos_pi_theta / &pi;
        let scale = Float::with_val(prec, &params.k * &s.l); // E* k l with E* = 1
        let rel = Float::with_val(64, (hp_direct - hp_formula) / scale).abs().to_f64();
        assert!(rel < 1e-25, "x - c = {off} l: relative difference {rel:e}");
    }
}

/// Integral over the free interval (b, L - a) of `gap_slope` (the gap slope without the tau0 step),
/// split at the kink of the periodic parabola x = L/2, tanh-sinh on each piece; in units of E*,
/// with the solution and the parameters.
fn free_interval_gap_integral(pb: &SlidingProblem) -> (Float, SlidingSolution, SlidingParamsMpfr) {
    let (params, mut sols) = run(pb, 30);
    let s = sols.remove(0);
    let prec = params.prec;
    let r = rebuild(&params, &s);
    let pr = Pressure::new(&params, &r.contact, &r.rule);
    let big_l = params.period.clone().unwrap();
    let kink = Float::with_val(prec, &big_l / 2u32) - &s.c;
    let upper = Float::with_val(prec, &big_l - &s.l);
    let mut integral = Float::with_val(prec, 0);
    for (lo, hi) in [(s.l.clone(), kink.clone()), (kink, upper)] {
        let half = Float::with_val(prec, &hi - &lo) / 2u32;
        let mid = Float::with_val(prec, &hi + &lo) / 2u32;
        integral += tanh_sinh(prec, |y| pr.gap_slope(&(Float::with_val(prec, &half * y) + &mid))) * &half;
    }
    (integral, s, params)
}

/// Proof by computation of the convention note in [`Convention`]: with the paper's summation
/// and v' = g' - cW p, the gap does not close over a period. Outside the contact h' = g' - v'; its
/// integral over the free interval (b, L - a) is
///     M = (2/E*) beta P1 - cW P2,
/// since int_period g' = 0, int_contact (g' - v') = cW P2 and int_period (E*/2) v' = -beta P1.
/// `gap_slope` leaves out the step -2 beta tau0/E*, so it integrates to M + 2 beta tau0 (L - 2 l)/E*.
/// With `Convention::PeriodicSurface` (K added to [2.8]) the same integral is the step term alone:
/// the surface closes (M = 0). Evaluated in units of E* (E* = 1, P and tau0 over E*, cW E*).
#[test]
fn paper_convention_gap_mismatch() {
    for convention in [Convention::Paper, Convention::PeriodicSurface] {
        let (integral, s, params) = free_interval_gap_integral(&Case { convention, ..MIXED }.load("1/10"));
        let prec = s.prec;
        let span = Float::with_val(prec, params.period.as_ref().unwrap() - Float::with_val(prec, &s.l * 2u32));
        let step = Float::with_val(prec, &params.beta * &params.tau0) * 2u32 * &span;
        let m = match convention {
            Convention::Paper => {
                Float::with_val(prec, &params.beta * &s.p1) * 2u32 - Float::with_val(prec, &params.wear * &s.p2)
            }
            Convention::PeriodicSurface => Float::with_val(prec, 0),
        };
        let expect = Float::with_val(prec, &m + &step);
        let r = Float::with_val(64, Float::with_val(prec, &integral - &expect) / &step).abs().to_f64();
        assert!(r < 1e-20, "{convention:?}: integral {integral} vs predicted {expect}: relative {r:e}");
        if convention == Convention::Paper {
            assert!(m.to_f64().abs() > 1e-3, "the mismatch is not small");
        }
    }
}

/// With `Convention::PeriodicSurface` the sinusoid with friction (theta = -0.102, tau0 = 0):
/// P2 = 1/5, beyond the paper-convention maximum (~0.162, see `non_monotone_sinusoid`), has
/// exactly one physical solution. Without friction, wear and tau0 (K = 0) both conventions give
/// the same contact. (The load curve under this convention:
/// `cargo run --release --example reduction_mpfr_explore -- load-curve --periodic-surface`.)
#[test]
fn periodic_surface_convention() {
    let paper = Case { shape: Shape::Sinusoid("1/10"), mu: "1", tau0: "0", cw: "0", ..BASE };
    let periodic = Case { convention: Convention::PeriodicSurface, ..paper };
    let v = solve_verified(&periodic.load("1/5"), &[q("0")], 30).unwrap();
    assert_eq!(v.len(), 1);
    assert!(v[0].accuracy.digits_verified >= 30.0, "{:?}", v[0].accuracy);
    assert!(solve_verified(&paper.load("1/5"), &[], 20).is_err());
    let a = &solve_verified(&Case { mu: "0", ..periodic }.load("1/10"), &[], 30).unwrap()[0].solution;
    let b = &solve_verified(&Case { mu: "0", ..paper }.load("1/10"), &[], 30).unwrap()[0].solution;
    assert!(digits(&a.l, &b.l, &a.l) >= 30.0);
}

/// digits_verified is honest: the 30-digit solution agrees with a 60-digit one at least to the
/// verified digits (less one for the scale conventions).
#[test]
fn verified_digits_are_honest() {
    let cases = [BASE.load("1/5"), Case { shape: Shape::Sinusoid("1/10"), tau0: "0", ..BASE }.load("17/100")];
    for pb in cases {
        let v = solve_verified(&pb, &[q("1/3")], 30).unwrap().remove(0);
        let r = at(&pb, &[q("1/3")], 60).remove(0);
        let s = &v.solution;
        let k = SlidingParamsMpfr::new(&pb, s.prec).unwrap().k;
        let kl = Float::with_val(s.prec, Float::with_val(s.prec, &s.l * &s.p2) * &k);
        let got = [
            ("a", digits(&s.a, &r.a, &s.l)),
            ("c", digits(&s.c, &r.c, &s.l)),
            ("P1", digits(&s.p1, &r.p1, &s.p2)),
            ("F_def", digits(&s.f_def, &r.f_def, &kl)),
            ("p", digits(&s.pressure[0].p, &r.pressure[0].p, &s.max_pressure)),
        ];
        for (name, d) in got {
            assert!(
                d >= v.accuracy.digits_verified - 1.0,
                "{name}: true digits {d:.1} < verified {:.1}",
                v.accuracy.digits_verified
            );
        }
    }
}

/// Issue 11: the pressure returned for a polynomial or circular punch (docs/theory.md section 9)
/// satisfies the original equation [2.8] with the `periodic` convention's K where it applies,
///     kappa p(x) + H[p](x) = (E*/2) g'(x) + beta tau0 + K,  K = (kappa P2 - 2 beta l tau0)/L,
/// H by direct quadrature as in `original_cot_kernel_equation_is_satisfied`, and g' evaluated
/// here from the exact profile (not by the solver's `Contact::f`). Asymmetric cubic with a tilt,
/// an even quartic, and the circle; friction, tau0 and wear. Residuals below 1e-30 relative to
/// E* k l.
#[test]
fn general_profiles_satisfy_the_cot_kernel_equation() {
    let material = Material::from_contact_modulus(q("1/4"), q("1")).unwrap();
    let base = |shape: PunchShape, conv: Convention, load: &str| {
        SlidingProblem::builder()
            .material(material.clone())
            .period(Period::finite(q("1")).unwrap())
            .shape(shape)
            .friction(q("1/5"))
            .adhesive_friction(q("1/100"))
            .wear(q("1/10"))
            .normal_load(q(load))
            .convention(conv)
            .build()
            .unwrap()
    };
    let cubic = PunchShape::polynomial(["0", "1/50", "1", "1/2"].iter().map(|s| q(s)).collect()).unwrap();
    let quartic = PunchShape::polynomial(["0", "0", "1/4", "0", "1/2"].iter().map(|s| q(s)).collect()).unwrap();
    let circle = PunchShape::circular(q("2")).unwrap();
    let cases = [
        (base(cubic, Convention::Paper, "1/20"), vec!["1/50", "2", "3/2"]),
        (base(quartic, Convention::PeriodicSurface, "3/20"), vec!["0", "1/2", "0", "2"]),
        (base(circle, Convention::PeriodicSurface, "1/10"), vec![]),
    ];
    for (pb, slope_coeffs) in cases {
        let (params, sols) = run(&pb, 30);
        let s = &sols[0];
        let prec = params.prec;
        // g'(x) from the exact input: polynomial slope coefficients written out above, or
        // x/sqrt(R^2 - x^2) with R = 2.
        let slope = |x: &Float| -> Float {
            if slope_coeffs.is_empty() {
                let r2 = Float::with_val(prec, 4u32);
                Float::with_val(prec, x / Float::with_val(prec, r2 - Float::with_val(prec, x.square_ref())).sqrt())
            } else {
                let mut acc = Float::with_val(prec, 0);
                for c in slope_coeffs.iter().rev() {
                    acc = acc * x + at_prec(c, prec);
                }
                acc
            }
        };
        let r = rebuild(&params, s);
        let pr = Pressure::new(&params, &r.contact, &r.rule);
        let (big_l, pi, lam) = (params.period.clone().unwrap(), params.pi.clone(), s.lambda.clone().unwrap());
        let m = Float::with_val(prec, lam.tan_ref());
        let p_at = |y: &Float| -> Float { pr.p(&(Float::with_val(prec, &lam * y).tan() / &m)) };
        let k_const = match pb.convention() {
            Convention::PeriodicSurface => {
                let kp2 = Float::with_val(prec, &params.kappa * &s.p2);
                let bt = Float::with_val(prec, &params.beta * &params.tau0) * &s.l * 2u32;
                Float::with_val(prec, kp2 - bt) / &big_l
            }
            Convention::Paper => Float::with_val(prec, 0),
        };
        let mut worst = 0.0f64;
        for yx in ["-4/5", "-1/3", "1/7", "1/2", "9/10"] {
            let yx = at_prec(yx, prec);
            let px = p_at(&yx);
            let regular = tanh_sinh(prec, |y| {
                let arg = Float::with_val(prec, &yx - y) * &s.l * &pi / &big_l;
                (p_at(y) - &px) * Float::with_val(prec, arg.tan_ref()).recip()
            }) * &s.l;
            let x = Float::with_val(prec, &s.l * &yx) + &s.c;
            let s1 = Float::with_val(prec, &pi * Float::with_val(prec, &x + &s.a)) / &big_l;
            let s2 = Float::with_val(prec, &pi * Float::with_val(prec, &s.b - &x)) / &big_l;
            let log = (Float::with_val(prec, s1.sin_ref()) / Float::with_val(prec, s2.sin_ref())).abs().ln();
            let hp = (regular + Float::with_val(prec, &px * log) * &big_l / &pi) / &big_l;
            let rhs = slope(&x) / 2u32 + Float::with_val(prec, &params.beta * &params.tau0) + &k_const;
            let lhs = Float::with_val(prec, &params.kappa * &px) + hp;
            let scale = Float::with_val(prec, &params.k * &s.l);
            worst = worst.max(Float::with_val(64, Float::with_val(prec, &lhs - &rhs) / &scale).abs().to_f64());
        }
        assert!(worst < 1e-30, "{:?}: residual of [2.8] relative to E* k l: {worst:e}", pb.shape());
    }
}

#[test]
fn sign_scan_locates_the_same_sizes() {
    use super::bracket::{LOCATE_DIGITS, LOCATE_NODES};
    use super::nodes::{lambda_cap, nodes_for};
    use super::scan::{scan_signs, scan_values};
    use super::solve::locate_with;
    // The sinusoid's scan with and without scan_signs: the same sizes bit for bit (the brackets'
    // ends, which Brent's method receives, carry the full scan rule's values in both), over loads
    // with one, two (non-monotone) and no roots, both conventions, with and without friction.
    let scene = Case { nu: "3/10", shape: Shape::Sinusoid("1/100"), mu: "1/2", tau0: "0", cw: "0", ..BASE };
    let steep = Case { shape: Shape::Sinusoid("1/10"), mu: "1", tau0: "0", cw: "0", ..BASE };
    let periodic = Case { convention: Convention::PeriodicSurface, ..scene };
    let frictionless = Case { shape: Shape::Sinusoid("1/100"), ..FRICTIONLESS };
    let mut roots = 0;
    for (case, loads) in [
        (scene, &["1/2000", "1/200", "1/100", "1/50", "3/100"][..]),
        (steep, &["1/100", "1/10", "3/20", "1/5"][..]),
        (periodic, &["1/200", "1/50", "1/20"][..]),
        (frictionless, &["1/1000", "1/50"][..]),
    ] {
        for load in loads {
            let setup = Setup::new(&case.load(load)).unwrap();
            let (a, b) = (locate_with(&setup, true), locate_with(&setup, false));
            assert_eq!(format!("{a:?}"), format!("{b:?}"), "{case:?} P2 = {load}");
            roots += a.map_or(0, |v| v.len());
        }
    }
    assert!(roots >= 8, "{roots}");
    // At the cap of the scene's scan (lambda = 1.5258, where the scan's own rule has 384 nodes)
    // the signs come from the pair (128, 192) and agree with that rule's.
    let params = Setup::new(&scene.load("1/200")).unwrap().locate;
    let target = 0.005;
    let rel = |v: &equation::ShiftSolution| (v.p2.to_f64() - target) / target;
    let cap = lambda_cap(LOCATE_DIGITS, LOCATE_NODES);
    assert!(nodes_for(cap, 8.0) > 256, "{}", nodes_for(cap, 8.0));
    let signs = scan_signs(&params, cap, 384, &rel).unwrap().expect("settled");
    let full = scan_values(&params, cap, 384, &rel).unwrap();
    for (x, y) in signs.iter().zip(&full) {
        let (x, y) = (x.unwrap(), y.unwrap());
        assert!(x * y > 0.0 && (x - y).abs() < 1e-4 * y.abs(), "{x} vs {y}");
    }
}
