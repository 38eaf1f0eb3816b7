//! Tests of the high-precision sliding solver against closed forms (THEORY.md section 6) and the
//! single-punch limit [3.10], and of its internal consistency.

use super::contact::{Contact, Size};
use super::pressure::Pressure;
use super::setup::Setup;
use super::*;
use crate::model::{Exact, Material, Period, PunchShape, SlidingLoad, SlidingProblem};
use crate::numerics::gauss_jacobi_mpfr::gauss_jacobi;
use rug::{float::Constant, Float};

fn q(s: &str) -> Exact {
    s.parse().expect("rational literal")
}

/// Problem builder: nu, E*, period ("inf" or a ratio), shape, mu, tau0, cW, load.
#[allow(clippy::too_many_arguments)]
fn problem(
    nu: &str,
    e: &str,
    period: &str,
    shape: PunchShape,
    mu: &str,
    tau0: &str,
    cw: &str,
    load: SlidingLoad,
) -> SlidingProblem {
    let material = Material::from_contact_modulus(q(nu), q(e)).unwrap();
    let period = if period == "inf" { Period::Infinite } else { Period::finite(q(period)).unwrap() };
    SlidingProblem::builder()
        .material(material)
        .period(period)
        .shape(shape)
        .friction(q(mu))
        .adhesive_friction(q(tau0))
        .wear(q(cw))
        .speed(Some(q("2")))
        .load(load)
        .build()
        .unwrap()
}

/// -log10(|x - y|/|scale|).
fn digits(x: &Float, y: &Float, scale: &Float) -> f64 {
    let d = Float::with_val(x.prec().max(y.prec()), x - y).abs();
    if d.is_zero() {
        return f64::INFINITY;
    }
    -(Float::with_val(64, d / scale).log10().to_f64())
}

fn float_to_exact(x: &Float) -> Exact {
    let r = x.to_rational().expect("finite");
    r.to_string().parse().expect("rational")
}

#[test]
fn kuznetsov_periodic_parabola_frictionless() {
    // P2 = (E* k L^2/pi) ln sec(pi a/L) [2.15], THEORY.md section 6. nu = 1/2: beta = 0, theta = 0.
    for a in ["1/10", "1/4", "3/10"] {
        let pb = problem(
            "1/2",
            "3",
            "1",
            PunchShape::parabolic(q("2")).unwrap(),
            "1/5",
            "0",
            "0",
            SlidingLoad::HalfLength(q(a)),
        );
        let v = solve_verified(&pb, &[q("1/2")], 30).unwrap();
        assert_eq!(v.len(), 1);
        let s = &v[0].solution;
        assert!(v[0].accuracy.digits_verified >= 30.0, "{:?}", v[0].accuracy);
        let p = s.prec + 40;
        let pi = Float::with_val(p, Constant::Pi);
        let af = Float::with_val(p, crate::numerics::exact::to_rational(&q(a)));
        let sec = Float::with_val(p, &pi * &af).cos().recip();
        let expect = sec.ln() * 6u32 / &pi; // E* k L^2 = 3 * 2 * 1
        assert!(digits(&s.p2, &expect, &expect) >= 30.0, "a = {a}: {} vs {}", s.p2, expect);
        assert!(s.c.to_f64().abs() < 1e-35);
    }
}

#[test]
fn westergaard_sinusoid_frictionless() {
    // P2 = pi E* D sin^2(pi a/L) [2.17].
    for a in ["1/20", "1/5", "2/5"] {
        let pb = problem(
            "1/2",
            "2",
            "3/2",
            PunchShape::sinusoidal(q("1/7")).unwrap(),
            "0",
            "0",
            "0",
            SlidingLoad::HalfLength(q(a)),
        );
        let v = solve_verified(&pb, &[], 30).unwrap();
        assert_eq!(v.len(), 1);
        let s = &v[0].solution;
        assert!(v[0].accuracy.digits_verified >= 30.0, "{:?}", v[0].accuracy);
        let p = s.prec + 40;
        let pi = Float::with_val(p, Constant::Pi);
        let af = Float::with_val(p, crate::numerics::exact::to_rational(&q(a)));
        let sn = Float::with_val(p, &pi * af * 2u32 / 3u32).sin();
        let expect = Float::with_val(p, sn.square_ref()) * &pi * 2u32 / 7u32;
        assert!(digits(&s.p2, &expect, &expect) >= 30.0, "a = {a}: {} vs {}", s.p2, expect);
    }
}

#[test]
fn westergaard_inverse_problem() {
    let pb = problem(
        "1/2",
        "2",
        "1",
        PunchShape::sinusoidal(q("1/10")).unwrap(),
        "0",
        "0",
        "0",
        SlidingLoad::NormalLoad(q("1/5")),
    );
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
        let pb = problem(
            "1/4",
            "2",
            "inf",
            PunchShape::parabolic(q("1/2")).unwrap(),
            mu,
            tau0,
            cw,
            SlidingLoad::NormalLoad(q("1")),
        );
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
        let tau = Float::with_val(p, crate::numerics::exact::to_rational(&q(tau0)));
        let t = Float::with_val(p, &beta * &tau) / &ls;
        let rbar = Float::with_val(p, th * 2u32) - &t;
        let got = Float::with_val(p, &s.c / &s.l);
        assert!(digits(&got, &rbar, &Float::with_val(p, 1)) >= 30.0, "rbar {got} vs {rbar}");
        // P1 = mu P2 + 2 l tau0.
        let p1 =
            Float::with_val(p, crate::numerics::exact::to_rational(&q(mu))) + Float::with_val(p, &s.l * &tau) * 2u32;
        assert!(digits(&s.p1, &p1, &s.p2) >= 30.0);
    }
}

#[test]
fn hertz_pressure() {
    // p = E* k sqrt(a^2 - x^2), P2 = (pi/2) E* k a^2.
    let pb = problem(
        "1/2",
        "5",
        "inf",
        PunchShape::parabolic(q("3")).unwrap(),
        "0",
        "0",
        "0",
        SlidingLoad::NormalLoad(q("7")),
    );
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
}

#[test]
fn load_is_the_integral_of_the_pressure() {
    // P2 from [2.14] (given) against int p dx by a separate Gauss–Jacobi rule for omega.
    let cases = [
        problem(
            "1/4",
            "2",
            "1",
            PunchShape::parabolic(q("1")).unwrap(),
            "3/10",
            "1/50",
            "1/5",
            SlidingLoad::NormalLoad(q("1/10")),
        ),
        problem(
            "0",
            "1",
            "1",
            PunchShape::sinusoidal(q("1/20")).unwrap(),
            "1/5",
            "1/100",
            "0",
            SlidingLoad::HalfLength(q("1/5")),
        ),
        problem(
            "1/3",
            "1",
            "inf",
            PunchShape::parabolic(q("1")).unwrap(),
            "1/2",
            "1/10",
            "1",
            SlidingLoad::NormalLoad(q("1")),
        ),
    ];
    for pb in cases {
        let sols = solve_at(&pb, &[], NodeRule { digits: 30.0, factor: 1.0 }, true, precision_for(30)).unwrap();
        for s in sols {
            let setup = Setup::new(&pb, s.prec).unwrap();
            let sz = match &s.lambda {
                Some(l) => Size::new(&setup, l),
                None => Size::new(&setup, &s.l),
            };
            let contact = Contact::new(&setup, &sz, s.c.clone());
            let (a, b) = setup.inverse_weight_exponents();
            let rule = gauss_jacobi(&a, &b, s.nodes, s.prec).unwrap();
            let (aw, bw) = setup.weight_exponents();
            let rule_w = gauss_jacobi(&aw, &bw, s.nodes, s.prec).unwrap();
            let pr = Pressure::new(&setup, &contact, &rule);
            let (p2, fdef) = pr.load_and_deformation_force(&rule_w);
            assert!(digits(&p2, &s.p2, &s.p2) >= 30.0, "{p2} vs {}", s.p2);
            assert!(digits(&fdef, &s.f_def, &s.p2) >= 30.0);
        }
    }
}

#[test]
fn direct_and_inverse_problems_agree() {
    let shapes = [
        ("1", PunchShape::parabolic(q("1")).unwrap(), "1/20"),
        ("1", PunchShape::sinusoidal(q("1/10")).unwrap(), "1/10"),
        ("inf", PunchShape::parabolic(q("2")).unwrap(), "1"),
    ];
    for (period, shape, load) in shapes {
        let inv = problem("1/4", "1", period, shape.clone(), "1/5", "1/100", "1/10", SlidingLoad::NormalLoad(q(load)));
        let s1 = solve_at(&inv, &[q("1/3")], NodeRule { digits: 30.0, factor: 1.0 }, true, precision_for(30)).unwrap();
        let s1 = &s1[0];
        let dir =
            problem("1/4", "1", period, shape, "1/5", "1/100", "1/10", SlidingLoad::HalfLength(float_to_exact(&s1.l)));
        let s2 = solve_at(&dir, &[q("1/3")], NodeRule { digits: 30.0, factor: 1.0 }, true, precision_for(30)).unwrap();
        let s2 = &s2[0];
        assert!(digits(&s1.p2, &s2.p2, &s1.p2) >= 30.0, "{} vs {}", s1.p2, s2.p2);
        assert!(digits(&s1.c, &s2.c, &s1.l) >= 30.0);
        assert!(digits(&s1.pressure[0].p, &s2.pressure[0].p, &s1.max_pressure) >= 30.0);
    }
}

#[test]
fn adhesive_friction_does_not_change_lambda_for_the_parabola() {
    let mk = |tau0: &str| {
        problem(
            "1/4",
            "1",
            "1",
            PunchShape::parabolic(q("1")).unwrap(),
            "1/5",
            tau0,
            "1/10",
            SlidingLoad::NormalLoad(q("1/20")),
        )
    };
    let s0 = &solve_at(&mk("0"), &[], NodeRule { digits: 30.0, factor: 1.0 }, true, precision_for(30)).unwrap()[0];
    let s1 = &solve_at(&mk("1/100"), &[], NodeRule { digits: 30.0, factor: 1.0 }, true, precision_for(30)).unwrap()[0];
    let (l0, l1) = (s0.lambda.as_ref().unwrap(), s1.lambda.as_ref().unwrap());
    assert!(digits(l0, l1, l0) >= 30.0);
    assert!(s1.c < s0.c, "tau0 shifts the contact toward -x");
}

#[test]
fn contact_leaving_the_period_is_an_error() {
    // Parabola with wear (theta ~ 0.1, rbar ~ 2 theta), large contact: b = l + c reaches L/2.
    let pb = problem(
        "1/2",
        "1",
        "1",
        PunchShape::parabolic(q("1")).unwrap(),
        "0",
        "0",
        "13/20",
        SlidingLoad::HalfLength(q("9/20")),
    );
    let e = solve_verified(&pb, &[], 20).unwrap_err();
    assert!(matches!(e, SlidingError::ContactOutsidePeriod { .. }), "{e}");
    // Strong adhesive friction pushes the contact out of the period.
    let pb = problem(
        "0",
        "1",
        "1",
        PunchShape::parabolic(q("1")).unwrap(),
        "0",
        "1",
        "0",
        SlidingLoad::HalfLength(q("1/4")),
    );
    let e = solve_verified(&pb, &[], 20).unwrap_err();
    assert!(matches!(e, SlidingError::ContactOutsidePeriod { .. }), "{e}");
}

#[test]
fn theta_too_close_to_one_half_and_bad_points_are_errors() {
    let pb = problem(
        "1/2",
        "1",
        "1",
        PunchShape::parabolic(q("1")).unwrap(),
        "0",
        "0",
        "100000000",
        SlidingLoad::NormalLoad(q("1/100")),
    );
    let e = solve_verified(&pb, &[], 20).unwrap_err();
    assert!(matches!(&e, SlidingError::Parameter { parameter, .. } if parameter.starts_with("theta")), "{e}");
    let pb = problem(
        "1/2",
        "1",
        "1",
        PunchShape::parabolic(q("1")).unwrap(),
        "0",
        "0",
        "0",
        SlidingLoad::NormalLoad(q("1/100")),
    );
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

/// Timings of `solve_verified` at 30 digits (first call builds the rules, later calls reuse them).
/// Run: `cargo test -p periodic-contact --lib sliding::tests::timing -- --ignored --nocapture`.
#[test]
#[ignore]
fn timing() {
    let cases: Vec<(&str, SlidingProblem)> = vec![
        (
            "parabola periodic, theta=0, P2=1/20",
            problem(
                "1/2",
                "1",
                "1",
                PunchShape::parabolic(q("1")).unwrap(),
                "0",
                "0",
                "0",
                SlidingLoad::NormalLoad(q("1/20")),
            ),
        ),
        (
            "parabola periodic, mu, cW, tau0, P2=1/20",
            problem(
                "1/4",
                "1",
                "1",
                PunchShape::parabolic(q("1")).unwrap(),
                "1/5",
                "1/100",
                "1/10",
                SlidingLoad::NormalLoad(q("1/20")),
            ),
        ),
        (
            "parabola periodic, l=0.318 (lambda=1)",
            problem(
                "1/4",
                "1",
                "1",
                PunchShape::parabolic(q("1")).unwrap(),
                "1/5",
                "0",
                "1/10",
                SlidingLoad::HalfLength(q("318/1000")),
            ),
        ),
        (
            "parabola single, mu, cW, tau0",
            problem(
                "1/4",
                "1",
                "inf",
                PunchShape::parabolic(q("1")).unwrap(),
                "1/5",
                "1/100",
                "1/10",
                SlidingLoad::NormalLoad(q("1")),
            ),
        ),
        (
            "sinusoid, theta=0, P2=1/5",
            problem(
                "1/2",
                "2",
                "1",
                PunchShape::sinusoidal(q("1/10")).unwrap(),
                "0",
                "0",
                "0",
                SlidingLoad::NormalLoad(q("1/5")),
            ),
        ),
        (
            "sinusoid, mu, cW, tau0, l=1/4",
            problem(
                "1/4",
                "1",
                "1",
                PunchShape::sinusoidal(q("1/10")).unwrap(),
                "1/5",
                "1/100",
                "1/10",
                SlidingLoad::HalfLength(q("1/4")),
            ),
        ),
        (
            "parabola periodic, mu, cW, P2=1/5 (lambda~1)",
            problem(
                "1/4",
                "1",
                "1",
                PunchShape::parabolic(q("1")).unwrap(),
                "1/5",
                "0",
                "1/10",
                SlidingLoad::NormalLoad(q("1/5")),
            ),
        ),
        (
            "sinusoid, mu=1/5, cW=1/10, P2=17/100 (lambda~0.9)",
            problem(
                "1/4",
                "1",
                "1",
                PunchShape::sinusoidal(q("1/10")).unwrap(),
                "1/5",
                "0",
                "1/10",
                SlidingLoad::NormalLoad(q("17/100")),
            ),
        ),
        (
            "sinusoid, mu, cW, tau0, P2=1/10",
            problem(
                "1/4",
                "1",
                "1",
                PunchShape::sinusoidal(q("1/10")).unwrap(),
                "1/5",
                "1/100",
                "1/10",
                SlidingLoad::NormalLoad(q("1/10")),
            ),
        ),
    ];
    let pts = [q("-1/2"), q("0"), q("1/2")];
    for (name, pb) in &cases {
        for rep in 0..3 {
            let t = std::time::Instant::now();
            let r = solve_verified(pb, &pts, 30);
            let dt = t.elapsed();
            match r {
                Ok(v) => {
                    let s = &v[0];
                    println!(
                        "{name} [call {rep}]: {:.1} ms, {} solution(s), lambda = {:?}, n = {}, bits = {}, digits_verified = {:.1}",
                        dt.as_secs_f64() * 1e3,
                        v.len(),
                        s.solution.lambda.as_ref().map(|l| l.to_f64()),
                        s.solution.nodes,
                        s.solution.prec,
                        s.accuracy.digits_verified
                    );
                }
                Err(e) => println!("{name}: error {e}"),
            }
        }
    }
}

/// Chart of the sinusoid's load curve P2(lambda) on both centre branches, with physicality
/// (exploration; `-- --ignored --nocapture`; set PERIODIC_SURFACE=1 for `Convention::PeriodicSurface`).
#[test]
#[ignore]
fn explore_sinusoid_load_curve() {
    let convention =
        if std::env::var("PERIODIC_SURFACE").is_ok() { Convention::PeriodicSurface } else { Convention::Paper };
    for (mu, cw, tau0) in
        [("0", "0", "0"), ("1/5", "1/10", "1/100"), ("0", "1", "0"), ("1", "0", "0"), ("0", "0", "1/20")]
    {
        println!("{convention:?}: mu = {mu}, cW = {cw}, tau0 = {tau0}");
        for i in 1..=30 {
            let l = format!("{}/62", i);
            let pb = problem(
                "1/4",
                "1",
                "1",
                PunchShape::sinusoidal(q("1/10")).unwrap(),
                mu,
                tau0,
                cw,
                SlidingLoad::HalfLength(q(&l)),
            );
            let setup = Setup::with_convention(&pb, 64, convention).unwrap();
            let lam = Float::with_val(64, std::f64::consts::PI * i as f64 / 62.0);
            let size = Size::new(&setup, &lam);
            let n = super::solve::nodes_for(lam.to_f64(), 16.0);
            let (a, b) = setup.inverse_weight_exponents();
            let rule = gauss_jacobi(&a, &b, n, 64).unwrap();
            let terms = super::equation::equation_terms(&setup, &size, &rule);
            let br = super::equation::shift_solutions(&setup, &size, &terms);
            let mut line = format!("  lambda {:.3} theta {:.4}:", lam.to_f64(), setup.theta.to_f64());
            for s in br {
                let contact = Contact::new(&setup, &size, s.c.clone());
                let pr = Pressure::new(&setup, &contact, &rule);
                let ok = super::physical::check_pressure(&setup, &pr)
                    .map(|_| ())
                    .and_then(|_| super::physical::check_gap(&setup, &contact, &pr));
                line += &format!(
                    " [P2 {:.6} c {:.4} {}]",
                    s.p2.to_f64(),
                    s.c.to_f64(),
                    match ok {
                        Ok(_) => "ok".to_string(),
                        Err(e) => e.to_string().chars().skip(30).take(110).collect::<String>(),
                    }
                );
            }
            println!("{line}");
        }
    }
}

/// The sinusoid with friction (theta = -0.102): P2(lambda) rises to a maximum (~0.1624 at
/// lambda ~ 0.96) and falls again, so a load below the maximum has two roots of [2.14]. Charted with
/// `explore_sinusoid_load_curve`: physicality (gap, then p at the trailing end) is lost before the
/// maximum, so only the smaller root is physical; loads beyond the physical range are an error that
/// states the maximum physical load.
#[test]
fn non_monotone_sinusoid() {
    let mk =
        |load: SlidingLoad| problem("1/4", "1", "1", PunchShape::sinusoidal(q("1/10")).unwrap(), "1", "0", "0", load);
    // Two roots of the equations at P2 = 1/10; the physical one is returned.
    let v = solve_verified(&mk(SlidingLoad::NormalLoad(q("1/10"))), &[q("0")], 30).unwrap();
    assert_eq!(v.len(), 1);
    assert!(v[0].accuracy.digits_verified >= 30.0, "{:?}", v[0].accuracy);
    let lam = v[0].solution.lambda.as_ref().unwrap().to_f64();
    assert!(lam > 0.5 && lam < 0.8, "lambda = {lam}");
    // All roots of the equations, physical or not (run without the checks): two, sorted by size.
    let all =
        solve_at(&mk(SlidingLoad::NormalLoad(q("1/10"))), &[], NodeRule { digits: 20.0, factor: 1.0 }, false, 128)
            .unwrap();
    assert_eq!(all.len(), 2);
    assert!(all[0].l < all[1].l);
    let lam2 = all[1].lambda.as_ref().unwrap().to_f64();
    assert!(lam2 > 1.1 && lam2 < 1.4, "second root lambda = {lam2}");
    // The larger root is not physical (negative pressure at the trailing end).
    let e = solve_verified(&mk(SlidingLoad::HalfLength(float_to_exact(&all[1].l))), &[], 20).unwrap_err();
    assert!(matches!(e, SlidingError::NotPhysical { .. }), "{e}");
    // Above the physical range, and above the maximum of P2(lambda): errors stating the maximum.
    for load in ["3/20", "1/5"] {
        let e = solve_verified(&mk(SlidingLoad::NormalLoad(q(load))), &[], 20).unwrap_err();
        match &e {
            SlidingError::NoSolution { why, .. } => assert!(why.contains("at most P2 = 1.3"), "{e}"),
            _ => panic!("{e}"),
        }
    }
}

/// Independent check of the reduction [2.13]-[2.14] for theta != 0, tau0 > 0 on a periodic row:
/// the pressure it returns satisfies the original equation [2.8]
///     kappa p(x) + H[p](x) = (E*/2) g'(x) + beta tau0,  H[p] = (1/L) PV int p(xi) cot(pi (x - xi)/L) dxi,
/// with H evaluated directly (no tangent map): PV int = int [p(xi) - p(x)] cot(...) dxi
/// + p(x) (L/pi) ln|sin(pi (x + a)/L)/sin(pi (b - x)/L)|, the regular integral by tanh-sinh
/// quadrature (step 1/64) in the linear variable (points off its nodes). Residuals ~1e-35.
#[test]
fn original_cot_kernel_equation_is_satisfied() {
    let cases = [
        problem(
            "1/4",
            "2",
            "1",
            PunchShape::parabolic(q("1")).unwrap(),
            "3/10",
            "1/50",
            "1/5",
            SlidingLoad::NormalLoad(q("1/10")),
        ),
        problem(
            "0",
            "1",
            "1",
            PunchShape::sinusoidal(q("1/20")).unwrap(),
            "1/5",
            "1/100",
            "1/2",
            SlidingLoad::HalfLength(q("1/5")),
        ),
        problem(
            "1/3",
            "1",
            "2",
            PunchShape::parabolic(q("1")).unwrap(),
            "0",
            "0",
            "1",
            SlidingLoad::HalfLength(q("3/10")),
        ),
    ];
    for pb in cases {
        let prec = precision_for(30);
        let sols = solve_at(&pb, &[], NodeRule { digits: 30.0, factor: 1.0 }, true, prec).unwrap();
        let s = &sols[0];
        assert!(s.theta.to_f64().abs() > 0.01);
        let setup = Setup::new(&pb, prec).unwrap();
        let size = Size::new(&setup, s.lambda.as_ref().unwrap());
        let contact = Contact::new(&setup, &size, s.c.clone());
        let (a, b) = setup.inverse_weight_exponents();
        let rule = gauss_jacobi(&a, &b, s.nodes, prec).unwrap();
        let pr = Pressure::new(&setup, &contact, &rule);
        let big_l = setup.period.clone().unwrap();
        let pi = setup.pi.clone();
        let lam = s.lambda.clone().unwrap();
        let m = Float::with_val(prec, lam.tan_ref());
        // p at x - c = l y (linear variable y in (-1, 1)).
        let p_at = |y: &Float| -> Float {
            let u = Float::with_val(prec, &lam * y).tan() / &m;
            pr.p(&u)
        };
        let cot = |z: &Float| -> Float { Float::with_val(prec, z.tan_ref()).recip() };
        let mut worst = 0.0f64;
        for yx in ["-4/5", "-1/3", "1/7", "1/2", "9/10"] {
            let yx = Float::with_val(prec, crate::numerics::exact::to_rational(&q(yx)));
            let px = p_at(&yx);
            // Regular part by tanh-sinh on y in (-1, 1).
            let h = Float::with_val(prec, 1u32) / 64u32;
            let mut sum = Float::with_val(prec, 0);
            for k in -300i32..=300 {
                let t = Float::with_val(prec, &h * k);
                let sh = Float::with_val(prec, t.sinh_ref()) * &pi / 2u32;
                let y = Float::with_val(prec, sh.tanh_ref());
                let w =
                    Float::with_val(prec, t.cosh_ref()) * &pi / 2u32 / Float::with_val(prec, sh.cosh_ref()).square();
                if Float::with_val(prec, 1u32 - Float::with_val(prec, y.abs_ref())) < Float::with_val(53, 1e-35)
                    || w.is_zero()
                {
                    continue;
                }
                let dxi = Float::with_val(prec, &yx - &y) * &s.l; // x - xi
                let arg = Float::with_val(prec, &pi * &dxi) / &big_l;
                let f = (p_at(&y) - &px) * cot(&arg);
                sum += f * w;
            }
            let regular = sum * &h * &s.l;
            let x = Float::with_val(prec, &s.l * &yx) + &s.c;
            let s1 = Float::with_val(prec, &pi * Float::with_val(prec, &x + &s.a)) / &big_l;
            let s2 = Float::with_val(prec, &pi * Float::with_val(prec, &s.b - &x)) / &big_l;
            let log = (Float::with_val(prec, s1.sin_ref()) / Float::with_val(prec, s2.sin_ref())).abs().ln();
            let hp = (regular + Float::with_val(prec, &px * log) * &big_l / &pi) / &big_l;
            let u = Float::with_val(prec, &lam * &yx).tan() / &m;
            let rhs = contact.f(&setup, &u, prec) + Float::with_val(prec, &setup.beta * &setup.tau0);
            let lhs = Float::with_val(prec, &setup.kappa * &px) + hp;
            let scale = Float::with_val(prec, &setup.e_star * setup.osculating_k()) * &s.l;
            let r = Float::with_val(64, Float::with_val(prec, &lhs - &rhs) / &scale).abs().to_f64();
            worst = worst.max(r);
        }
        assert!(worst < 1e-30, "residual of [2.8] relative to E* k l: {worst:e}");
    }
}

/// Independent check of the outside formula used by the gap check:
/// (E*/2) v'(x) = H[p](x) = F(t) + beta tau0 - X(t) cos(pi theta) D(t)/pi for x outside the contact,
/// against H[p] = (1/L) int p(xi) cot(pi (x - xi)/L) dxi by tanh-sinh (regular integrand).
#[test]
fn outside_displacement_formula() {
    let pb = problem(
        "1/4",
        "2",
        "1",
        PunchShape::parabolic(q("1")).unwrap(),
        "3/10",
        "1/50",
        "1/5",
        SlidingLoad::NormalLoad(q("1/10")),
    );
    let prec = precision_for(30);
    let s = solve_at(&pb, &[], NodeRule { digits: 30.0, factor: 1.0 }, true, prec).unwrap().remove(0);
    let setup = Setup::new(&pb, prec).unwrap();
    let size = Size::new(&setup, s.lambda.as_ref().unwrap());
    let contact = Contact::new(&setup, &size, s.c.clone());
    let (a, b) = setup.inverse_weight_exponents();
    let rule = gauss_jacobi(&a, &b, s.nodes, prec).unwrap();
    let pr = Pressure::new(&setup, &contact, &rule);
    let big_l = setup.period.clone().unwrap();
    let pi = setup.pi.clone();
    let lam = s.lambda.clone().unwrap();
    let m = Float::with_val(prec, lam.tan_ref());
    for off in ["13/10", "-3/2", "2"] {
        // x - c = off * l (outside the contact, inside (-L/2, L/2) relative to c).
        let xc = Float::with_val(prec, crate::numerics::exact::to_rational(&q(off))) * &s.l;
        let h = Float::with_val(prec, 1u32) / 64u32;
        let mut sum = Float::with_val(prec, 0);
        for k in -300i32..=300 {
            let t = Float::with_val(prec, &h * k);
            let sh = Float::with_val(prec, t.sinh_ref()) * &pi / 2u32;
            let y = Float::with_val(prec, sh.tanh_ref());
            let w = Float::with_val(prec, t.cosh_ref()) * &pi / 2u32 / Float::with_val(prec, sh.cosh_ref()).square();
            if Float::with_val(prec, 1u32 - Float::with_val(prec, y.abs_ref())) < Float::with_val(53, 1e-35) {
                continue;
            }
            let u = Float::with_val(prec, &lam * &y).tan() / &m;
            let arg = Float::with_val(prec, &xc - Float::with_val(prec, &y * &s.l)) * &pi / &big_l;
            sum += pr.p(&u) * Float::with_val(prec, arg.tan_ref()).recip() * w;
        }
        let hp_direct = sum * &h * &s.l / &big_l;
        // Formula: t = u(x), X(t) = sign(t)|t-1|^{1/2-theta}|t+1|^{1/2+theta}.
        let t = size.u_of(&setup, &xc, prec);
        let e1 = Float::with_val(prec, &setup.theta + 0.5f64);
        let e2 = Float::with_val(prec, 0.5f64 - Float::with_val(prec, &setup.theta));
        use rug::ops::Pow;
        let mut xt = Float::with_val(prec, Float::with_val(prec, &t + 1u32).abs().pow(&e1))
            * Float::with_val(prec, &t - 1u32).abs().pow(&e2);
        if t.is_sign_negative() {
            xt = -xt;
        }
        let hp_formula = contact.f(&setup, &t, prec) + Float::with_val(prec, &setup.beta * &setup.tau0)
            - xt * pr.d(&t) * &setup.cos_pi_theta / &pi;
        let scale = Float::with_val(prec, &setup.e_star * setup.osculating_k()) * &s.l;
        let r = Float::with_val(64, (hp_direct - hp_formula) / scale).abs().to_f64();
        assert!(r < 1e-25, "x - c = {off} l: relative difference {r:e}");
    }
}

/// Edge cases of THEORY.md section 7 (exploration; `-- --ignored --nocapture`).
#[test]
#[ignore]
fn explore_edge_cases() {
    let cases: Vec<(&str, SlidingProblem)> = vec![
        (
            "single, tiny load, tau0",
            problem(
                "1/4",
                "1",
                "inf",
                PunchShape::parabolic(q("1")).unwrap(),
                "0",
                "1/100",
                "0",
                SlidingLoad::NormalLoad(q("1/1000000")),
            ),
        ),
        (
            "periodic, tiny load, tau0",
            problem(
                "1/4",
                "1",
                "1",
                PunchShape::parabolic(q("1")).unwrap(),
                "0",
                "1/100",
                "0",
                SlidingLoad::NormalLoad(q("1/1000000")),
            ),
        ),
        (
            "periodic, theta=0.49 (wear)",
            problem(
                "1/2",
                "1",
                "1",
                PunchShape::parabolic(q("1")).unwrap(),
                "0",
                "0",
                "6000/37",
                SlidingLoad::NormalLoad(q("1/100")),
            ),
        ),
        (
            "periodic, theta=-0.45 (friction)",
            problem(
                "0",
                "1",
                "1",
                PunchShape::parabolic(q("1")).unwrap(),
                "63/5",
                "0",
                "0",
                SlidingLoad::NormalLoad(q("1/100")),
            ),
        ),
        (
            "periodic, lambda=1.4",
            problem(
                "1/2",
                "1",
                "1",
                PunchShape::parabolic(q("1")).unwrap(),
                "0",
                "0",
                "0",
                SlidingLoad::HalfLength(q("4456/10000")),
            ),
        ),
        (
            "periodic, lambda=1.5",
            problem(
                "1/2",
                "1",
                "1",
                PunchShape::parabolic(q("1")).unwrap(),
                "0",
                "0",
                "0",
                SlidingLoad::HalfLength(q("4775/10000")),
            ),
        ),
        (
            "periodic, lambda -> pi/2",
            problem(
                "1/2",
                "1",
                "1",
                PunchShape::parabolic(q("1")).unwrap(),
                "0",
                "0",
                "0",
                SlidingLoad::HalfLength(q("4999999/10000000")),
            ),
        ),
        (
            "periodic, huge load",
            problem(
                "1/2",
                "1",
                "1",
                PunchShape::parabolic(q("1")).unwrap(),
                "0",
                "0",
                "0",
                SlidingLoad::NormalLoad(q("1000")),
            ),
        ),
        (
            "sinusoid, load above pi E* D",
            problem(
                "1/2",
                "1",
                "1",
                PunchShape::sinusoidal(q("1")).unwrap(),
                "0",
                "0",
                "0",
                SlidingLoad::NormalLoad(q("4")),
            ),
        ),
        (
            "sinusoid, wear theta=0.3",
            problem(
                "1/2",
                "1",
                "1",
                PunchShape::sinusoidal(q("1/10")).unwrap(),
                "0",
                "0",
                "11/2",
                SlidingLoad::NormalLoad(q("1/100")),
            ),
        ),
    ];
    for (name, pb) in &cases {
        let t = std::time::Instant::now();
        match solve_verified(pb, &[q("0")], 30) {
            Ok(v) => {
                for s in &v {
                    println!(
                        "{name}: {:.0} ms, theta {:.4} lambda {:?} l {:.6e} c {:.6e} n {} digits {:.1}",
                        t.elapsed().as_secs_f64() * 1e3,
                        s.solution.theta.to_f64(),
                        s.solution.lambda.as_ref().map(|x| x.to_f64()),
                        s.solution.l.to_f64(),
                        s.solution.c.to_f64(),
                        s.solution.nodes,
                        s.accuracy.digits_verified
                    );
                }
            }
            Err(e) => println!("{name}: {:.0} ms, error: {e}", t.elapsed().as_secs_f64() * 1e3),
        }
    }
}

/// Integral over the free interval (b, L - a) of `gap_slope` (the gap slope without the tau0 step),
/// split at the kink of the periodic parabola x = L/2, tanh-sinh on each piece. Returns it with the
/// solution and the setup.
fn free_interval_gap_integral(pb: &SlidingProblem, convention: Convention) -> (Float, SlidingSolution, Setup) {
    let prec = precision_for(30);
    let (s, _) =
        super::solve::solve_located(pb, &[], NodeRule { digits: 30.0, factor: 1.0 }, true, prec, None, convention)
            .unwrap()
            .remove(0);
    let setup = Setup::with_convention(pb, prec, convention).unwrap();
    let size = Size::new(&setup, s.lambda.as_ref().unwrap());
    let contact = Contact::new(&setup, &size, s.c.clone());
    let (a, b) = setup.inverse_weight_exponents();
    let rule = gauss_jacobi(&a, &b, s.nodes, prec).unwrap();
    let pr = Pressure::new(&setup, &contact, &rule);
    let big_l = setup.period.clone().unwrap();
    let pi = setup.pi.clone();
    let kink = Float::with_val(prec, &big_l / 2u32) - &s.c;
    let upper = Float::with_val(prec, &big_l - &s.l);
    let h = Float::with_val(prec, 1u32) / 64u32;
    let mut integral = Float::with_val(prec, 0);
    for (lo, hi) in [(s.l.clone(), kink.clone()), (kink.clone(), upper)] {
        let half = Float::with_val(prec, &hi - &lo) / 2u32;
        let mid = Float::with_val(prec, &hi + &lo) / 2u32;
        let mut sum = Float::with_val(prec, 0);
        for k in -300i32..=300 {
            let t = Float::with_val(prec, &h * k);
            let sh = Float::with_val(prec, t.sinh_ref()) * &pi / 2u32;
            let y = Float::with_val(prec, sh.tanh_ref());
            let w = Float::with_val(prec, t.cosh_ref()) * &pi / 2u32 / Float::with_val(prec, sh.cosh_ref()).square();
            if Float::with_val(prec, 1u32 - Float::with_val(prec, y.abs_ref())) < Float::with_val(53, 1e-35) {
                continue;
            }
            let xc = Float::with_val(prec, &half * &y) + &mid;
            sum += pr.gap_slope(&xc) * w;
        }
        integral += sum * &h * &half;
    }
    (integral, s, setup)
}

/// Proof by computation of the convention note in `setup::Convention`: with the paper's summation
/// and v' = g' - cW p, the gap does not close over a period. Outside the contact h' = g' - v'; its
/// integral over the free interval (b, L - a) is
///     M = (2/E*) beta P1 - cW P2,
/// since int_period g' = 0, int_contact (g' - v') = cW P2 and int_period (E*/2) v' = -beta P1.
/// `gap_slope` leaves out the step -2 beta tau0/E*, so it integrates to M + 2 beta tau0 (L - 2 l)/E*.
/// With `Convention::PeriodicSurface` (K added to [2.8]) the same integral is the step term alone:
/// the surface closes (M = 0).
#[test]
fn paper_convention_gap_mismatch() {
    let pb = problem(
        "1/4",
        "2",
        "1",
        PunchShape::parabolic(q("1")).unwrap(),
        "3/10",
        "1/50",
        "1/5",
        SlidingLoad::NormalLoad(q("1/10")),
    );
    for convention in [Convention::Paper, Convention::PeriodicSurface] {
        let (integral, s, setup) = free_interval_gap_integral(&pb, convention);
        let prec = s.prec;
        let span = Float::with_val(prec, setup.period.as_ref().unwrap() - Float::with_val(prec, &s.l * 2u32));
        let step = Float::with_val(prec, &setup.beta * &setup.tau0) * 2u32 * &span / &setup.e_star;
        let m = match convention {
            Convention::Paper => {
                Float::with_val(prec, &setup.beta * &s.p1) * 2u32 / &setup.e_star
                    - Float::with_val(prec, &setup.wear * &s.p2)
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

/// With `Convention::PeriodicSurface` the sinusoid with friction (theta = -0.102, tau0 = 0) has a
/// monotone, physical load curve (charted with `PERIODIC_SURFACE=1 ... explore_sinusoid_load_curve`):
/// P2 = 1/5, beyond the paper-convention maximum (~0.162), has exactly one physical solution. Without
/// friction, wear and tau0 (K = 0) both conventions give the same contact.
#[test]
fn periodic_surface_convention() {
    let mk = |mu: &str, load: &str| {
        problem(
            "1/4",
            "1",
            "1",
            PunchShape::sinusoidal(q("1/10")).unwrap(),
            mu,
            "0",
            "0",
            SlidingLoad::NormalLoad(q(load)),
        )
    };
    let v = solve_verified_with(&mk("1", "1/5"), &[q("0")], 30, Convention::PeriodicSurface).unwrap();
    assert_eq!(v.len(), 1);
    assert!(v[0].accuracy.digits_verified >= 30.0, "{:?}", v[0].accuracy);
    assert!(solve_verified(&mk("1", "1/5"), &[], 20).is_err());
    let a = &solve_verified_with(&mk("0", "1/10"), &[], 30, Convention::PeriodicSurface).unwrap()[0].solution;
    let b = &solve_verified(&mk("0", "1/10"), &[], 30).unwrap()[0].solution;
    assert!(digits(&a.l, &b.l, &a.l) >= 30.0);
}

/// Time of the phases of one inverse sinusoid case (exploration; `-- --ignored --nocapture`).
#[test]
#[ignore]
fn profile_phases() {
    let pb = problem(
        "1/4",
        "1",
        "1",
        PunchShape::sinusoidal(q("1/10")).unwrap(),
        "1/5",
        "0",
        "1/10",
        SlidingLoad::NormalLoad(q("17/100")),
    );
    let _ = solve_verified(&pb, &[q("0")], 30);
    let t = std::time::Instant::now();
    let found = super::solve::locate_for_profile(&pb, &q("17/100"));
    println!("locate: {:.1} ms -> {:?}", t.elapsed().as_secs_f64() * 1e3, found);
    let t = std::time::Instant::now();
    let r = super::solve::solve_located(
        &pb,
        &[q("0")],
        NodeRule { digits: 30.0, factor: 1.0 },
        true,
        precision_for(30),
        Some(&found),
        Convention::Paper,
    );
    println!("run 1 given located: {:.1} ms ({} ok)", t.elapsed().as_secs_f64() * 1e3, r.map(|v| v.len()).unwrap_or(0));
    let t = std::time::Instant::now();
    let r = super::solve::solve_located(
        &pb,
        &[q("0")],
        NodeRule { digits: 30.0, factor: 1.5 },
        false,
        precision_for(30) + 32,
        Some(&found[..1]),
        Convention::Paper,
    );
    println!("run 2 given located: {:.1} ms ({} ok)", t.elapsed().as_secs_f64() * 1e3, r.map(|v| v.len()).unwrap_or(0));
}

/// digits_verified is honest: the 30-digit solution agrees with a 60-digit one at least to the
/// verified digits (less one for the scale conventions).
#[test]
fn verified_digits_are_honest() {
    let cases = [
        problem(
            "1/4",
            "1",
            "1",
            PunchShape::parabolic(q("1")).unwrap(),
            "1/5",
            "1/100",
            "1/10",
            SlidingLoad::NormalLoad(q("1/5")),
        ),
        problem(
            "1/4",
            "1",
            "1",
            PunchShape::sinusoidal(q("1/10")).unwrap(),
            "1/5",
            "0",
            "1/10",
            SlidingLoad::NormalLoad(q("17/100")),
        ),
    ];
    for pb in cases {
        let v = solve_verified(&pb, &[q("1/3")], 30).unwrap().remove(0);
        let r = solve_at(&pb, &[q("1/3")], NodeRule { digits: 60.0, factor: 1.0 }, true, precision_for(60))
            .unwrap()
            .remove(0);
        let s = &v.solution;
        let kl = Float::with_val(
            s.prec,
            Float::with_val(s.prec, &s.l * &s.p2) * Setup::new(&pb, s.prec).unwrap().osculating_k(),
        );
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
