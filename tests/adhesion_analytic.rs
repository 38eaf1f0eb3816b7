//! Method `analytic` of Problem 2 (issue 31, `crate::adhesion::analytic`): the member analytic at
//! zero size, continued past lambda_h. The fast case runs in the normal tier; the slow ones are
//! `#[ignore]` and belong to the long tier (`scripts/test --long`, or
//! `cargo test --release --test adhesion_analytic -- --ignored --nocapture`).

use periodic_contact::adhesion::analytic::continue_to;
use periodic_contact::adhesion::{solve_verified, VerifiedSolution};
use periodic_contact::model::{AdhesionProblem, AdhesionSize, Material, Period, PunchShape};
use periodic_contact::numerics::accuracy::verified_digits_mpfr;
use rug::Float;

type Q = num_rational::BigRational;

fn q(s: &str) -> Q {
    s.parse().unwrap()
}

fn material(nu: &str) -> Material {
    Material::from_contact_modulus(q(nu), q("1")).unwrap()
}

/// The default (verified MPFR) solution at half-width a, L = 1, k = E* = 1, and its P(lambda) =
/// P2 (pi/L)^2/(E* k).
fn default_load(nu: &str, a: &str, digits: u32) -> (Float, f64) {
    let p = AdhesionProblem::new(
        material(nu),
        Period::Finite(q("1")),
        PunchShape::Parabolic { k: q("1") },
        AdhesionSize::HalfWidth(q(a)),
    )
    .unwrap();
    let v: VerifiedSolution = solve_verified(&p, &[], digits).unwrap();
    let prec = v.solution.prec;
    let pi = Float::with_val(prec, rug::float::Constant::Pi);
    (Float::with_val(prec, &v.solution.normal_load * pi.square()), v.digits_verified.size)
}

fn lambda_of(a: &str) -> Float {
    let prec = 256;
    Float::with_val(prec, rug::float::Constant::Pi) * periodic_contact::numerics::exact::to_float(&q(a), prec)
}

/// Below lambda_h both methods compute the same member: at nu = 0, a = 0.13 (lambda = 0.41), the
/// analytic P (15 digits asked) agrees with the verified MPFR P (20 asked) to the digits both verify.
#[test]
#[ignore = "long tier: 2e+01 s in debug on a loaded 2-core machine (scripts/test --long)"]
fn below_the_horizon_it_equals_the_default_method() {
    let (reference, ref_digits) = default_load("0", "13/100", 20);
    let sol = continue_to(&material("0"), &lambda_of("13/100"), 15).unwrap();
    let agree = verified_digits_mpfr(&Float::with_val(256, &sol.load - &reference), &reference, 40.0);
    eprintln!(
        "lambda = 0.41: analytic {:.1} digits, default {ref_digits:.1}, agreement {agree:.1}, {:.1} s",
        sol.digits, sol.seconds
    );
    assert!(sol.digits >= 15.0, "{}", sol.digits);
    assert!(agree >= ref_digits.min(sol.digits) - 0.5, "agreement {agree}");
}

/// nu = 0, lambda = 0.8 (a = 0.8/pi to 16 digits), beyond lambda_h(0, 20) = 0.766: the analytic method verifies >= 20 digits and
/// equals the verified MPFR method to every digit that method keeps there (about 17). Measured
/// once: analytic 31.0 digits (A = 10^86), default 17.5, agreement 18.9, 261 s.
#[test]
#[ignore]
fn at_lambda_0_8_it_equals_the_default_method() {
    let a = "2546479089470325/10000000000000000";
    let (reference, ref_digits) = default_load("0", a, 20);
    let sol = continue_to(&material("0"), &lambda_of(a), 20).unwrap();
    let agree = verified_digits_mpfr(&Float::with_val(256, &sol.load - &reference), &reference, 40.0);
    eprintln!(
        "nu = 0, lambda = 0.8: analytic {:.1} digits (A = 10^{:.0}), default {ref_digits:.1}, agreement {agree:.1}, {:.0} s",
        sol.digits, sol.amplification_log10, sol.seconds
    );
    assert!(sol.digits >= 20.0, "{}", sol.digits);
    assert!(agree >= ref_digits - 0.5, "agreement {agree}, default keeps {ref_digits}");
}

/// nu = 0, lambda = 1.2: >= 20 verified digits (two eta0, two precisions). Measured once: P =
/// 7.267031970225463569118926 with 34.9 digits, A = 10^104, 1435 s (machine loaded 8 deep).
#[test]
#[ignore]
fn at_nu_0_lambda_1_2_it_verifies_twenty_digits() {
    let sol = continue_to(&material("0"), &Float::with_val(256, 1.2), 20).unwrap();
    eprintln!(
        "nu = 0, lambda = 1.2: P = {} with {:.1} digits (A = 10^{:.0}), {:.0} s",
        sol.load.to_string_radix(10, Some(25)),
        sol.digits,
        sol.amplification_log10,
        sol.seconds
    );
    assert!(sol.digits >= 20.0, "{}", sol.digits);
}

/// The cases the method does not take are refused before any run, naming the parameter: the single
/// punch, the `periodic` convention (the mode is not excited there), a given load, another shape.
#[test]
fn what_it_does_not_take_is_refused() {
    use periodic_contact::error::ErrorKind;
    use periodic_contact::model::Convention;
    use periodic_contact::solve::answer_analytic::analytic_answer;
    let make = |period: Period, shape: PunchShape, size: AdhesionSize| {
        AdhesionProblem::new(material("0"), period, shape, size).unwrap()
    };
    let parabola = || PunchShape::Parabolic { k: q("1") };
    let a = || AdhesionSize::HalfWidth(q("1/10"));
    let cases = [
        (make(Period::Infinite, parabola(), a()), "period"),
        (make(Period::Finite(q("1")), parabola(), a()).with_convention(Convention::PeriodicSurface), "convention"),
        (make(Period::Finite(q("1")), parabola(), AdhesionSize::NormalLoad(q("1/100"))), "normal_load"),
        (make(Period::Finite(q("1")), PunchShape::Circular { radius: q("2") }, a()), "shape"),
    ];
    for (p, param) in cases {
        let e = analytic_answer(&p, 20).err().unwrap_or_else(|| panic!("{param}: not refused"));
        assert_eq!(e.kind(), ErrorKind::Input, "{param}: {e}");
        assert!(e.to_string().contains(param), "{param}: {e}");
    }
}
