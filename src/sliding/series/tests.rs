//! The series method against the MPFR solution: its estimated digits never exceed the true ones;
//! its refusals and input errors.

use super::solve::{solve_series, solve_series_with, SeriesSolution};
use crate::asymptotics::sliding::{sliding_expansion_with, SlidingShape};
use crate::error::{Error, ErrorKind};
use crate::model::{Convention, Exact, Material, Period, PunchShape, SlidingProblem};
use crate::numerics::accuracy::verified_digits_mpfr;
use crate::sliding::SlidingSolution;
use rug::Float;

/// An exact rational within 1e-12 of `x`.
fn q(x: f64) -> Exact {
    exact_series::Q::new(((x * 1e12).round() as i64).into(), 1_000_000_000_000i64.into())
}

/// A grid problem: E* = 1, nu = 0.3, L = 1; theta set by friction (theta < 0, kappa = -beta mu)
/// or wear (theta > 0, kappa = cW/2); the load puts Lambda = pi l_s/L at `size` (parabola, k = 1)
/// or pi a/L at `size` for the frictionless sinusoid (D = 1/100, P2 = pi E* D sin^2(pi a/L) [2.17]).
fn grid_problem(sinusoid: bool, theta: f64, size: f64) -> SlidingProblem {
    let pi = std::f64::consts::PI;
    let beta = 0.4 / 1.4;
    let kappa = (pi * theta).tan();
    let (mu, cw) = if kappa < 0.0 { (-kappa / beta, 0.0) } else { (0.0, 2.0 * kappa) };
    let (shape, p2) = if sinusoid {
        let d = 0.01;
        (PunchShape::Sinusoidal { amplitude: q(d) }, pi * d * size.sin().powi(2))
    } else {
        let a0 = size / pi * (1.0 - 4.0 * theta * theta).sqrt();
        (PunchShape::Parabolic { k: q(1.0) }, pi * a0 * a0 / 2.0)
    };
    SlidingProblem::builder()
        .material(Material::from_contact_modulus(q(0.3), q(1.0)).unwrap())
        .period(Period::Finite(q(1.0)))
        .shape(shape)
        .friction(q(mu))
        .wear(q(cw))
        .normal_load(q(p2))
        .build()
        .unwrap()
}

/// True digits of the series solution `s` against the MPFR solution `m` (30 digits), per group
/// of the estimate, on the series' scales: (l, a, b, c), F_def, p.
fn true_digits(s: &SeriesSolution, m: &SlidingSolution, cap: f64) -> [f64; 3] {
    let d = |x: &Float, y: &Float, scale: &Float| verified_digits_mpfr(&Float::with_val(s.prec, x - y), scale, cap);
    let contact = [(&s.l, &m.l), (&s.a, &m.a), (&s.b, &m.b), (&s.c, &m.c)]
        .iter()
        .map(|(x, y)| d(x, y, &s.l))
        .fold(f64::INFINITY, f64::min);
    let kl_p2 = Float::with_val(s.prec, &s.k * &s.l) * &s.p2;
    let f_def = d(&s.f_def, &m.f_def, &kl_p2);
    let p =
        s.pressure.iter().zip(&m.pressure).map(|(x, y)| d(&x.p, &y.p, &s.max_pressure)).fold(f64::INFINITY, f64::min);
    [contact, f_def, p]
}

/// The grid: parabola and sinusoid; theta in {-0.2, 0, 0.2}; Lambda (parabola) or pi a/L
/// (sinusoid) in {0.2, 0.5, 0.8, 1.0, 1.2, 1.4}; orders {4, 8, 12}; p at xh = 0, +-0.5, +-0.9.
/// Where the MPFR method finds no physical solution (the parabola's contact leaving the cell,
/// the sinusoid beyond its largest load with friction or wear) there is nothing to compare.
/// Returns (pairs compared, pairs the series refused); panics when an estimate exceeds the truth.
fn estimate_grid(shapes: &[SlidingShape], convention: Convention) -> (usize, usize) {
    let digits = 30;
    // The series' own cap: one digit above the request (issue 34).
    let cap = digits as f64 + 1.0;
    let xh: Vec<Exact> = [-0.9, -0.5, 0.0, 0.5, 0.9].iter().map(|x| q(*x)).collect();
    let (mut compared, mut refused) = (0, 0);
    for &shape in shapes {
        let sinusoid = shape == SlidingShape::Sinusoidal;
        let e = sliding_expansion_with(shape, 12, convention).unwrap();
        for theta in [-0.2, 0.0, 0.2] {
            for size in [0.2, 0.5, 0.8, 1.0, 1.2, 1.4] {
                let p = grid_problem(sinusoid, theta, size).to_builder().convention(convention).build().unwrap();
                let Ok(m) = crate::sliding::solve_verified(&p, &xh, digits) else { continue };
                let m = &m[0].solution;
                for order in [4, 8, 12] {
                    let s = match solve_series_with(&e, &p, &xh, order, digits) {
                        Ok(s) => s,
                        Err(err) => {
                            assert_eq!(err.kind(), ErrorKind::NoConvergence, "{err}");
                            refused += 1;
                            continue;
                        }
                    };
                    let acc = &s.accuracy;
                    let est = [acc.contact, acc.f_def, acc.pressure.unwrap()];
                    let truth = true_digits(&s, m, cap);
                    for ((name, e), t) in ["l, a, b, c", "F_def", "p"].iter().zip(est).zip(truth) {
                        assert!(
                            e <= t + 0.05,
                            "{}: sinusoid {sinusoid}, theta {theta}, size {size}, order {order}: \
                             {name} estimated {e:.2} > true {t:.2}",
                            convention.name()
                        );
                    }
                    compared += 1;
                }
            }
        }
    }
    (compared, refused)
}

#[test]
fn estimate_never_exceeds_the_true_digits() {
    // 24 of the 36 grid problems have an MPFR solution under the shared physicality criterion (in
    // `paper` a negative gap is a warning, docs/theory.md section 8): 72 (problem, order) pairs, of
    // which the series refuses 4, all for the frictionless sinusoid near Lambda = 1 (pi a/L = 1.2
    // at order 4; pi a/L = 1.4, Lambda = 0.985, at every order).
    let counts = estimate_grid(&[SlidingShape::Parabolic, SlidingShape::Sinusoidal], Convention::Paper);
    assert_eq!(counts, (68, 4));
}

/// The same grid in the `periodic` convention for the parabola (the expansions hold every power
/// of Lambda and the estimate takes the terms in pairs): 18 problems with an MPFR solution, 54
/// pairs, of which the series refuses 2; the estimate never exceeds the truth. (The periodic
/// sinusoid's order-12 expansion is slow to derive today, so it is not in this grid.)
#[test]
fn estimate_never_exceeds_the_true_digits_periodic() {
    let counts = estimate_grid(&[SlidingShape::Parabolic], Convention::PeriodicSurface);
    assert_eq!(counts, (52, 2));
}

/// The refusal follows the estimate, not a bound on Lambda: the parabola's series converges at
/// Lambda = 1.2 (its terms decrease); the sinusoid's at pi a/L = 1.4 (Lambda = 0.985) through
/// Lambda^4 leaves less than one digit; beyond Lambda = 1 its terms grow.
#[test]
fn refusal_follows_the_estimate() {
    let s = solve_series(&grid_problem(false, 0.0, 1.2), &[], 8, 20).unwrap();
    assert!(s.big_lambda > 1.0 && s.accuracy.headline >= 3.0, "{:?}", s.accuracy);
    let err = solve_series(&grid_problem(true, 0.0, 1.4), &[q(0.0)], 4, 20).unwrap_err();
    assert_eq!(err.kind(), ErrorKind::NoConvergence, "{err}");
    assert!(err.to_string().contains("Lambda = pi l_s/L = 0.98"), "{err}");
    // Beyond the radius of convergence (sinusoid with wear, Lambda = 1.07): the terms grow.
    let err = solve_series(&grid_problem(true, 0.2, 1.4), &[], 8, 20).unwrap_err();
    assert_eq!(err.kind(), ErrorKind::NoConvergence, "{err}");
    assert!(err.to_string().contains("do not decrease at Lambda = pi l_s/L = 1.07"), "{err}");
}

/// Inside the radius but with alternating terms: the frictionless parabola at Lambda = pi^(1/2)
/// (Lambda^2 = pi, half the radius 2 pi of Kuznetsov's series; P2 = 1/2, lambda = 1.3614) was
/// refused ("the terms do not decrease": single-step ratios up to 4.8 at order 24). The pair
/// envelopes give rate 0.43 and an estimate the MPFR solution confirms.
#[test]
fn alternating_terms_inside_the_radius_are_accepted() {
    let e = sliding_expansion_with(SlidingShape::Parabolic, 24, Convention::Paper).unwrap();
    let p = grid_problem(false, 0.0, std::f64::consts::PI.sqrt());
    let m = crate::sliding::solve_verified(&p, &[], 30).unwrap();
    for (order, at_least) in [(12, 2.5), (24, 4.5)] {
        let s = solve_series_with(&e, &p, &[], order, 30).unwrap();
        assert!(s.accuracy.rate < 0.5, "order {order}: rate {}", s.accuracy.rate);
        assert!(s.accuracy.contact >= at_least, "order {order}: {:?}", s.accuracy);
        let d = verified_digits_mpfr(&Float::with_val(s.prec, &s.l - &m[0].solution.l), &s.l, 30.0);
        assert!(s.accuracy.contact <= d + 0.05, "order {order}: estimated {} > true {d}", s.accuracy.contact);
    }
}

#[test]
fn input_errors_say_what_was_given_and_what_to_do() {
    let base = grid_problem(false, 0.0, 0.5);
    let single = base.to_builder().period(Period::Infinite).build().unwrap();
    let sized = base.to_builder().half_length(q(0.1)).build().unwrap();
    let cases: [(SlidingProblem, usize, &str); 3] =
        [(single, 4, "punch.period"), (sized, 4, "sliding.half_length = 0.1"), (base, 1, "--order = 1")];
    for (p, order, what) in cases {
        let err = solve_series(&p, &[], order, 20).unwrap_err();
        assert!(matches!(err, Error::Input(_)), "{err}");
        let text = err.to_string();
        assert!(text.contains(what) && !text.contains("(given)"), "{text}");
    }
}
