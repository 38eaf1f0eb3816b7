use super::candidates::candidates;
use super::profile::slope;
use super::*;
use crate::error::{Error, ErrorKind};
use crate::model::{Exact, Material, Period, PunchShape, SlidingLoad, SlidingProblem};
use crate::numerics::accuracy::readable_f64;
use crate::numerics::gauss_jacobi_f64::{gauss_jacobi, omega};
use crate::params::sliding::SlidingParamsF64;
use num_bigint::BigInt;
use std::f64::consts::PI;

fn r(n: i64, d: i64) -> Exact {
    Exact::new(BigInt::from(n), BigInt::from(d))
}

/// Problem with E* = 1, given (nu, L or None, shape, mu, tau0, cW, load).
fn problem(
    nu: Exact,
    period: Option<Exact>,
    shape: PunchShape,
    mu: Exact,
    tau0: Exact,
    cw: Exact,
    load: SlidingLoad,
) -> SlidingProblem {
    let mat = Material::from_contact_modulus(nu, r(1, 1)).unwrap();
    let per = match period {
        Some(l) => Period::finite(l).unwrap(),
        None => Period::Infinite,
    };
    SlidingProblem::builder()
        .material(mat)
        .period(per)
        .shape(shape)
        .friction(mu)
        .adhesive_friction(tau0)
        .wear(cw)
        .load(load)
        .build()
        .unwrap()
}

fn parabola(k: Exact) -> PunchShape {
    PunchShape::parabolic(k).unwrap()
}

fn sinusoid(d: Exact) -> PunchShape {
    PunchShape::sinusoidal(d).unwrap()
}

fn load(p2: Exact) -> SlidingLoad {
    SlidingLoad::NormalLoad(p2)
}

fn size(l: Exact) -> SlidingLoad {
    SlidingLoad::HalfLength(l)
}

/// P2 given as an f64 (exactly).
fn load_f(p2: f64) -> SlidingLoad {
    load(Exact::from_float(p2).unwrap())
}

/// l given as an f64 (exactly).
fn size_f(l: f64) -> SlidingLoad {
    size(Exact::from_float(l).unwrap())
}

fn rel(a: f64, b: f64, scale: f64) -> f64 {
    (a - b).abs() / scale
}

const TOL: f64 = 1e-12;

#[test]
fn hertz_single_punch() {
    // Hertz (docs/theory.md section 6): P2 = (pi/2) E* k a^2, p = E* k sqrt(a^2 - x^2).
    let pts = [-0.9, -0.3, 0.0, 0.5, 0.99];
    let pb = problem(r(1, 2), None, parabola(r(3, 1)), r(0, 1), r(0, 1), r(0, 1), load(r(2, 1)));
    let s = solve_sliding_f64(&pb, &pts, &SolverOptions::default()).unwrap();
    let s = s.primary();
    let a = (2.0 * 2.0 / (PI * 3.0)).sqrt();
    assert!(rel(s.l, a, a) < TOL && s.c.abs() < TOL * a, "{} vs {a}", s.l);
    for p in &s.pressure {
        let exact = 3.0 * (a * a - p.x * p.x).sqrt();
        assert!(rel(p.p, exact, 3.0 * a) < TOL, "{} vs {exact}", p.p);
    }
    assert!(s.f_def.abs() < TOL * 3.0 * a * 2.0);
}

#[test]
fn single_punch_with_friction_wear_and_adhesive_friction() {
    // l_s = a0/sqrt(1 - 4 theta^2), rbar_s = 2 theta - T, T = beta tau0/(E* k l_s),
    // F_def = 2 pi E* k^2 l^3 (1 - 4 theta^2) (rbar/2 + theta/3) (docs/theory.md [3.10]; F_def from
    // p = E* k l cos(pi theta) omega(xh) and the moments of omega).
    for (mu, cw, tau0) in [(r(3, 10), r(0, 1), r(1, 20)), (r(0, 1), r(7, 5), r(0, 1)), (r(1, 2), r(2, 5), r(1, 7))] {
        let (k, p2) = (2.0, 0.7);
        let pb = problem(r(1, 4), None, parabola(r(2, 1)), mu, tau0, cw, load(r(7, 10)));
        let prm = SlidingParamsF64::new(&pb).unwrap();
        let th = prm.theta;
        let s = solve_sliding_f64(&pb, &[0.2], &SolverOptions::default()).unwrap();
        let s = s.primary();
        // l_s and T of [3.10] from the parameters (E* = 1).
        let ls = prm.l_s(p2);
        let t = prm.t(p2);
        assert!(rel(s.l, ls, ls) < TOL, "theta {th}: {} vs {ls}", s.l);
        assert!(rel(s.c / s.l, 2.0 * th - t, 1.0) < TOL, "theta {th}: {} vs {}", s.c / s.l, 2.0 * th - t);
        let fdef = 2.0 * PI * k * k * ls.powi(3) * (1.0 - 4.0 * th * th) * ((2.0 * th - t) / 2.0 + th / 3.0);
        assert!(rel(s.f_def, fdef, k * ls * p2) < TOL, "{} vs {fdef}", s.f_def);
        let p = k * ls * (PI * th).cos() * omega(0.2, th);
        assert!(rel(s.pressure[0].p, p, s.max_pressure) < TOL);
        assert!(rel(s.p1, prm.mu * p2 + 2.0 * ls * prm.tau0, p2) < TOL);
    }
}

#[test]
fn kuznetsov_periodic_parabola() {
    // P2 = (E* k L^2/pi) ln sec(pi a/L) [2.15], frictionless; both directions.
    let (k, big_l) = (1.5, 2.0);
    for lam in [0.05, 0.3, 0.7, 1.0, 1.2, 1.3] {
        let a = lam * big_l / PI;
        let p2 = k * big_l * big_l / PI * (1.0 / lam.cos()).ln();
        let l_exact = Exact::from_float(a).unwrap();
        let pb = problem(r(1, 2), Some(r(2, 1)), parabola(r(3, 2)), r(0, 1), r(0, 1), r(0, 1), size(l_exact.clone()));
        let s = solve_sliding_f64(&pb, &[], &SolverOptions::default()).unwrap();
        let s = s.primary();
        assert!(rel(s.p2, p2, p2) < TOL, "lambda {lam}: P2 {} vs {p2}, err {:e}", s.p2, rel(s.p2, p2, p2));
        assert!(s.c.abs() < TOL * a);
        let pb = problem(r(1, 2), Some(r(2, 1)), parabola(r(3, 2)), r(0, 1), r(0, 1), r(0, 1), load_f(p2));
        let s = solve_sliding_f64(&pb, &[-0.99, -0.5, 0.0, 0.7], &SolverOptions::default()).unwrap();
        let s = s.primary();
        assert!(rel(s.a, a, a) < TOL, "lambda {lam}: a {} vs {a}, err {:e}", s.a, rel(s.a, a, a));
        // Pressure against the inversion formula [2.13] (no closed form is pinned).
        check_exact_reduction(&pb, s, TOL);
        assert!(s.accuracy.max() < 1e-12, "{:?}", s.accuracy);
    }
}

#[test]
fn westergaard_sinusoid() {
    // P2 = pi E* D sin^2(pi a/L) [2.17], p = (2 pi E* D/L) cos(pi x/L) sqrt(sin^2 lambda - sin^2(pi x/L)).
    let (d, big_l) = (0.1, 1.0);
    let pts = [-0.95, -0.5, 0.0, 0.3, 0.8];
    for lam in [0.1, 0.5, 0.9, 1.2, 1.3] {
        let a = lam * big_l / PI;
        let p2 = PI * d * lam.sin().powi(2);
        let shape = sinusoid(r(1, 10));
        let pb = problem(r(1, 2), Some(r(1, 1)), shape, r(0, 1), r(0, 1), r(0, 1), load_f(p2));
        let sols = solve_sliding_f64(&pb, &pts, &SolverOptions::default()).unwrap();
        assert_eq!(sols.solutions.len(), 1);
        let s = sols.primary();
        assert!(rel(s.a, a, a) < TOL && rel(s.b, a, a) < TOL, "lambda {lam}: a {} vs {a}: {:e}", s.a, rel(s.a, a, a));
        assert!(s.c.abs() < TOL * a);
        let pmax = 2.0 * PI * d / big_l * lam.sin();
        for p in &s.pressure {
            let chi = PI * p.x / big_l;
            let exact = 2.0 * PI * d / big_l * chi.cos() * (lam.sin().powi(2) - chi.sin().powi(2)).sqrt();
            assert!(
                rel(p.p, exact, pmax) < TOL,
                "lambda {lam} xh {}: {} vs {exact}: {:e}",
                p.xh,
                p.p,
                rel(p.p, exact, pmax)
            );
        }
    }
}

/// docs/theory.md section 3 exact reduction, evaluated independently in f64 (Gauss–Jacobi rule of
/// 1/omega, 400 nodes): E* cos(pi theta) X(i/m)/(2 pi i) int g'(x(u)) du/(omega (u - i/m))
/// should equal P2/L - i beta tau0 [2.14]; and p(u) = omega(u) cos^2(pi theta)/pi
/// int [F(u') - F(u)]/(u' - u) du'/omega(u') [2.13].
fn check_exact_reduction(pb: &SlidingProblem, s: &SlidingSolutionF64, tol: f64) {
    use nalgebra::Complex;
    let prm = SlidingParamsF64::new(pb).unwrap();
    let big_l = prm.period.unwrap();
    let th = prm.theta;
    let m = s.lambda.tan();
    let rule = gauss_jacobi(400, th - 0.5, -th - 0.5).unwrap();
    let x_of = |u: f64| s.c + big_l / PI * (m * u).atan();
    let z = Complex::new(0.0, 1.0 / m);
    let xz = (z - 1.0).powf(0.5 - th) * (z + 1.0).powf(0.5 + th);
    let mut integral = Complex::new(0.0, 0.0);
    for (u, w) in rule.nodes.iter().zip(&rule.weights) {
        integral += Complex::new(w * slope(&prm, x_of(*u)), 0.0) / (Complex::new(*u, 0.0) - z);
    }
    let lhs = xz * integral * (prm.e_star * (PI * th).cos()) / Complex::new(0.0, 2.0 * PI);
    let scale = s.p2 / big_l;
    assert!((lhs.re - s.p2 / big_l).abs() < tol * scale, "[2.14] real part {} vs {}", lhs.re, s.p2 / big_l);
    assert!(
        (lhs.im + prm.beta * prm.tau0).abs() < tol * scale,
        "[2.14] imaginary part {} vs {}",
        lhs.im,
        -prm.beta * prm.tau0
    );
    let f = |u: f64| 0.5 * prm.e_star * slope(&prm, x_of(u));
    for pp in &s.pressure {
        let u = (s.lambda * pp.xh).tan() / m;
        let mut acc = 0.0;
        for (t, w) in rule.nodes.iter().zip(&rule.weights) {
            acc += w * (f(*t) - f(u)) / (t - u);
        }
        let p = omega(u, th) * (PI * th).cos().powi(2) / PI * acc;
        assert!((p - pp.p).abs() < tol * s.max_pressure, "[2.13] at xh {}: {} vs {p}", pp.xh, pp.p);
    }
}

#[test]
fn periodic_parabola_with_friction_wear_and_adhesion_matches_exact_reduction() {
    let pts = [-0.97, -0.4, 0.0, 0.6, 0.95];
    for (mu, cw, tau0, p2) in [
        (r(3, 10), r(0, 1), r(1, 20), r(1, 10)),
        (r(0, 1), r(1, 2), r(0, 1), r(1, 10)),
        (r(1, 2), r(2, 5), r(1, 7), r(3, 20)),
    ] {
        let pb = problem(r(1, 4), Some(r(1, 1)), parabola(r(1, 1)), mu, tau0, cw, load(p2));
        let sols = solve_sliding_f64(&pb, &pts, &SolverOptions::default()).unwrap();
        assert_eq!(sols.solutions.len(), 1);
        let s = sols.primary();
        check_exact_reduction(&pb, s, TOL);
        assert!(s.accuracy.max() < TOL, "{:?}", s.accuracy);
        // The direct problem at the same l gives the same P2 and c.
        let pd = pb.to_builder().load(size_f(s.l)).build().unwrap();
        let d = solve_sliding_f64(&pd, &[], &SolverOptions::default()).unwrap();
        let d = d.primary();
        assert!(rel(d.p2, s.p2, s.p2) < TOL && rel(d.c, s.c, s.l) < TOL);
    }
}

#[test]
fn parabola_lambda_does_not_depend_on_tau0_and_c_shifts_by_beta_tau0() {
    // docs/theory.md section 3: for the parabola lambda does not depend on tau0; c is explicit,
    // and from the solvability condition dc = -beta dtau0/(E* k).
    let mk = |tau0: Exact| problem(r(1, 4), Some(r(2, 1)), parabola(r(3, 1)), r(2, 5), tau0, r(1, 3), load(r(1, 1)));
    let s0 = solve_sliding_f64(&mk(r(0, 1)), &[], &SolverOptions::default()).unwrap();
    let s1 = solve_sliding_f64(&mk(r(1, 10)), &[], &SolverOptions::default()).unwrap();
    let (s0, s1) = (s0.primary(), s1.primary());
    let beta = 1.0 / 3.0;
    assert!(rel(s0.lambda, s1.lambda, s0.lambda) < TOL);
    assert!(rel(s1.c - s0.c, -beta * 0.1 / 3.0, s0.l) < TOL);
}

#[test]
fn periodic_parabola_tends_to_the_single_punch() {
    // L -> infinity: l -> l_s, rbar -> 2 theta - T with corrections O(Lambda^2) (docs/theory.md [3.10]).
    let pb = problem(r(1, 4), Some(r(1000, 1)), parabola(r(1, 1)), r(2, 5), r(1, 30), r(1, 3), load(r(1, 1)));
    let s = solve_sliding_f64(&pb, &[], &SolverOptions::default()).unwrap();
    let s = s.primary();
    let single = pb.to_builder().period(Period::Infinite).build().unwrap();
    let t = solve_sliding_f64(&single, &[], &SolverOptions::default()).unwrap();
    let t = t.primary();
    let lam2 = (PI * t.l / 1000.0).powi(2);
    assert!(rel(s.l, t.l, t.l) < lam2 && rel(s.c, t.c, t.l) < lam2, "{} {} {} {}", s.l, t.l, s.c, t.c);
}

#[test]
fn sinusoid_with_wear_matches_exact_reduction_and_reports_maximum_load() {
    let shape = || sinusoid(r(1, 10));
    // theta = 0.148 (cW = 1, nu = 1/4): P2 at most about 0.43 pi E* D.
    let pb = problem(r(1, 4), Some(r(1, 1)), shape(), r(0, 1), r(0, 1), r(1, 1), load(r(1, 20)));
    let sols = solve_sliding_f64(&pb, &[-0.5, 0.0, 0.7], &SolverOptions::default()).unwrap();
    assert_eq!(sols.solutions.len(), 1);
    check_exact_reduction(&pb, sols.primary(), TOL);
    let pb = problem(r(1, 4), Some(r(1, 1)), shape(), r(0, 1), r(0, 1), r(1, 1), load(r(3, 20)));
    // Above the largest physical load: the refusal quotes the admissible range, computed.
    let prm = SlidingParamsF64::new(&pb).unwrap();
    let adm = super::admissible::admissible_range(&prm, &SolverOptions::default()).unwrap();
    let (max_load, lam) = adm.max_load().expect("a physical range");
    // Observed: 0.426 pi E* D at 2l/L = 0.59, where p < 0 starts at the leading end
    // (`cargo run --release --example collocation_f64_charts -- load-curve`).
    assert!(max_load > 0.40 * PI * 0.1 && max_load < 0.45 * PI * 0.1, "{max_load} {lam}");
    assert!(2.0 * lam / PI > 0.5 && 2.0 * lam / PI < 0.7, "{lam}");
    match solve_sliding_f64(&pb, &[], &SolverOptions::default()) {
        Err(SlidingF64Error::Refused(e)) => {
            let text = e.to_string();
            assert!(text.contains(&format!("normal_load in (0, {}]", readable_f64(max_load))), "{text}");
        }
        other => panic!("expected a refusal with the admissible range, got {other:?}"),
    }
    // Frictionless: above the full-contact load pi E* D: no contact carries it.
    let pb = problem(r(1, 2), Some(r(1, 1)), shape(), r(0, 1), r(0, 1), r(0, 1), load(r(4, 10)));
    match solve_sliding_f64(&pb, &[], &SolverOptions::default()) {
        Err(SlidingF64Error::Refused(e @ Error::NoSolution { .. })) => {
            assert!(e.to_string().contains("no contact carries normal_load = 2/5"), "{e}")
        }
        other => panic!("expected no solution, got {other:?}"),
    }
}

#[test]
fn invalid_inputs_are_typed_errors() {
    let pb = problem(r(1, 2), None, parabola(r(1, 1)), r(0, 1), r(0, 1), r(0, 1), load(r(1, 1)));
    assert_eq!(
        solve_sliding_f64(&pb, &[1.0], &SolverOptions::default()),
        Err(SlidingF64Error::InvalidPoint { value: 1.0 })
    );
    // Strong wear (theta = 0.35) shifts a large contact past L/2.
    let pb = problem(r(1, 4), Some(r(1, 1)), parabola(r(1, 1)), r(0, 1), r(0, 1), r(4, 1), size(r(3, 10)));
    match solve_sliding_f64(&pb, &[], &SolverOptions::default()) {
        Err(SlidingF64Error::Refused(e @ Error::NotPhysical { .. })) => {
            let text = e.to_string();
            assert!(
                text.contains("leaves the cell") && text.contains("physical contacts have half_length in"),
                "{text}"
            );
        }
        other => panic!("expected a refusal: contact leaving the cell, got {other:?}"),
    }
    let pb = problem(r(1, 4), None, parabola(r(1, 1)), r(0, 1), r(0, 1), r(10_000_000, 1), load(r(1, 1)));
    match solve_sliding_f64(&pb, &[], &SolverOptions::default()) {
        Err(SlidingF64Error::Input(Error::Input(m))) => assert!(m.parameter.contains("theta"), "{m}"),
        other => panic!("expected an input error on theta, got {other:?}"),
    }
    let huge = Exact::from_integer(BigInt::from(10).pow(400));
    let pb = problem(r(1, 2), None, parabola(huge), r(0, 1), r(0, 1), r(0, 1), load(r(1, 1)));
    match solve_sliding_f64(&pb, &[], &SolverOptions::default()) {
        Err(SlidingF64Error::Input(Error::Input(m))) => assert_eq!(m.parameter, "k", "{m}"),
        other => panic!("expected an input error on k, got {other:?}"),
    }
}

#[test]
fn convergence_in_the_number_of_nodes() {
    // Westergaard pressure at lambda = 1 (Nyström interpolant): the error falls like
    // tan(lambda/2)^{2n} (module docs).
    let lam: f64 = 1.0;
    let rate = (0.5 * lam).tan().powi(2);
    let mut prev: Option<(usize, f64)> = None;
    for n in [4usize, 8, 12, 16] {
        let pb = problem(r(1, 2), Some(r(1, 1)), sinusoid(r(1, 10)), r(0, 1), r(0, 1), r(0, 1), size_f(lam / PI));
        let opts = SolverOptions { nodes: Some(n), accept: 1.0, ..Default::default() };
        let s = solve_sliding_f64(&pb, &[0.0, 0.5, -0.8], &opts).unwrap();
        let s = s.primary();
        let pmax = 2.0 * PI * 0.1 * lam.sin();
        let err = s
            .pressure
            .iter()
            .map(|p| {
                let chi = PI * p.x;
                (p.p - 2.0 * PI * 0.1 * chi.cos() * (lam.sin().powi(2) - chi.sin().powi(2)).sqrt()).abs() / pmax
            })
            .fold(0.0, f64::max);
        if let Some((n0, e0)) = prev {
            // Observed rate per node within a factor 1.5 of the predicted one (in the exponent).
            let observed = (err / e0).ln() / (n - n0) as f64;
            assert!(
                observed < 0.67 * rate.ln() && observed > 1.5 * rate.ln(),
                "n {n}: observed {observed}, predicted {}",
                rate.ln()
            );
        }
        prev = Some((n, err));
    }
}

#[test]
fn sinusoid_past_the_load_maximum_is_not_physical() {
    // theta = 0.148: P2 = 0.40 pi E* D is reached twice (lambda ~ 0.80 and ~ 1.02); past the
    // maximum of P2(lambda) p < 0 at the leading end, so one solution is returned.
    let shape = sinusoid(r(1, 10));
    let pb = problem(r(1, 4), Some(r(1, 1)), shape, r(0, 1), r(0, 1), r(1, 1), load_f(0.40 * PI * 0.1));
    let prm = SlidingParamsF64::new(&pb).unwrap();
    assert_eq!(candidates(&prm, prm.target, &SolverOptions::default()).unwrap().len(), 2);
    let sols = solve_sliding_f64(&pb, &[0.0], &SolverOptions::default()).unwrap();
    assert_eq!(sols.solutions.len(), 1);
    let s = sols.primary();
    assert!((s.lambda - 0.80158).abs() < 1e-4, "{}", s.lambda);
    check_exact_reduction(&pb, s, TOL);
}

#[test]
fn small_load_with_adhesive_friction_drifts_to_minus_beta_tau0_over_e_k() {
    // docs/theory.md section 7: as P2 -> 0 with tau0 > 0, c -> -beta tau0/(E* k) (= -1/300 here).
    let pb = problem(r(1, 4), Some(r(1, 1)), parabola(r(1, 1)), r(1, 2), r(1, 100), r(0, 1), load(r(1, 100_000_000)));
    let s = solve_sliding_f64(&pb, &[], &SolverOptions::default()).unwrap();
    let s = s.primary();
    // c = -beta tau0/(E* k) + 2 theta l + O(l lambda^2) (single-punch rbar_s = 2 theta - T).
    let expected = -1.0 / 300.0 + 2.0 * s.theta * s.l;
    assert!((s.c - expected).abs() < 1e-6 * s.l, "{} vs {expected}", s.c);
    assert!(s.accuracy.max() < TOL);
}

#[test]
fn theta_near_one_half_single_punch() {
    // cW = 100, nu = 1/4: theta = 0.4936; l_s = a0/sqrt(1 - 4 theta^2) (docs/theory.md [3.10]).
    let pb = problem(r(1, 4), None, parabola(r(1, 1)), r(0, 1), r(0, 1), r(100, 1), load(r(1, 100)));
    let s = solve_sliding_f64(&pb, &[], &SolverOptions::default()).unwrap();
    let s = s.primary();
    let ls = SlidingParamsF64::new(&pb).unwrap().l_s(0.01);
    // Tolerance 1e-11: the weight 1/omega ~ (1-u)^{theta - 1/2} is nearly non-integrable.
    assert!(rel(s.l, ls, ls) < 1e-11, "{:e}", rel(s.l, ls, ls));
    assert!(rel(s.c / s.l, 2.0 * s.theta, 1.0) < 1e-11);
}

#[test]
fn errors_keep_their_kind_and_print_readable_numbers() {
    let pb = problem(r(1, 2), None, parabola(r(1, 1)), r(0, 1), r(0, 1), r(0, 1), load(r(1, 1)));
    let e: Error = solve_sliding_f64(&pb, &[1.0], &SolverOptions::default()).unwrap_err().into();
    assert_eq!(e.kind(), ErrorKind::Input);
    let pb = problem(r(1, 4), Some(r(1, 1)), parabola(r(1, 1)), r(0, 1), r(0, 1), r(4, 1), size(r(3, 10)));
    let e: Error = solve_sliding_f64(&pb, &[], &SolverOptions::default()).unwrap_err().into();
    assert_eq!(e.kind(), ErrorKind::NotPhysical);
    // theta = 0.148: the load 0.15 is above the largest physical load (about 0.426 pi E* D).
    let shape = sinusoid(r(1, 10));
    let pb = problem(r(1, 4), Some(r(1, 1)), shape, r(0, 1), r(0, 1), r(1, 1), load(r(3, 20)));
    let e: Error = solve_sliding_f64(&pb, &[], &SolverOptions::default()).unwrap_err().into();
    assert_eq!(e.kind(), ErrorKind::NoSolution);
    let text = e.to_string();
    assert!(text.starts_with("no solution: no contact carries normal_load = 3/20 at these parameters; physical contacts carry normal_load in (0, "), "{text}");
    assert!(!text.contains("no solution: no solution"), "{text}");
    let e: Error = SlidingF64Error::NoConvergence { reason: "x".into() }.into();
    assert_eq!(e.kind(), ErrorKind::NoConvergence);
}

#[test]
fn digits_per_quantity_follow_the_accuracy_rule() {
    // Periodic parabola with friction, wear and tau0: every quantity's digits are
    // f64_digits(|main - check|, value, scale) on the scales l, P2, k l P2, max p (the check run's
    // difference with its safety factor, or the round-off floor; issue 34).
    let pb = problem(r(1, 4), Some(r(1, 1)), parabola(r(1, 1)), r(1, 2), r(1, 7), r(2, 5), load(r(3, 20)));
    let s = solve_sliding_f64(&pb, &[0.0, 0.5], &SolverOptions::default()).unwrap();
    let s = s.primary();
    let d = s.digits();
    let (diff, sc) = (&s.accuracy.differences, &s.accuracy.scales);
    assert_eq!(sc.length, s.l);
    assert_eq!(sc.load, s.p2);
    assert_eq!(sc.f_def, 1.0 * s.l * s.p2);
    assert_eq!(sc.pressure, s.max_pressure);
    use crate::numerics::accuracy::f64_digits_nodes;
    let n = s.nodes;
    assert_eq!(d[Quantity::A], f64_digits_nodes(diff[Quantity::A], s.a, s.l, n));
    assert_eq!(d[Quantity::P1], f64_digits_nodes(diff[Quantity::P1], s.p1, s.p2, n));
    assert_eq!(d[Quantity::FDef], f64_digits_nodes(diff[Quantity::FDef], s.f_def, s.l * s.p2, n));
    assert_eq!(d[Quantity::Pressure], f64_digits_nodes(diff[Quantity::Pressure], s.max_pressure, s.max_pressure, n));
    // The relative fields are the same differences over the same scales.
    let geometry = diff[Quantity::A].max(diff[Quantity::B]).max(diff[Quantity::C]) / s.l;
    assert_eq!(s.accuracy.geometry, geometry);
    assert!(d.min() >= 11.0 && d.min() <= 13.3, "{d:?}");
}

/// One problem per kind of right-hand side of the collocation: the periodic parabola with
/// friction, the single parabola with friction, adhesive friction and wear, the sinusoid with
/// friction.
fn right_side_kinds() -> [SlidingProblem; 3] {
    [
        problem(r(3, 10), Some(r(1, 1)), parabola(r(1, 1)), r(3, 10), r(0, 1), r(0, 1), load(r(1, 100))),
        problem(r(1, 4), None, parabola(r(1, 1)), r(1, 5), r(1, 50), r(1, 10), load(r(1, 100))),
        problem(r(3, 10), Some(r(1, 1)), sinusoid(r(1, 20)), r(1, 2), r(0, 1), r(0, 1), load(r(1, 200))),
    ]
}

/// G at the operator's fixed samples from the precomputed weights (`interpolant::g_on_grid`) is
/// `g_at` there to the bit, for every kind of right-hand side (parabola periodic and single,
/// sinusoid, polynomial) and a node count whose Chebyshev-2 nodes (theta = 0, n + 1 = 67) fall on
/// the samples' Chebyshev–Lobatto points; and omega there is `omega(u, theta)`.
#[test]
fn g_on_the_fixed_samples_is_g_at_to_the_bit() {
    use super::candidates::state_of;
    use super::interpolant::{g_at, g_on_grid};
    use super::operator::{collocation, GridPoint};
    let mut cases = right_side_kinds().to_vec();
    cases.push(problem(r(0, 1), Some(r(1, 1)), parabola(r(1, 1)), r(0, 1), r(0, 1), r(0, 1), load(r(1, 100))));
    let mut on_node = 0;
    for (i, pb) in cases.iter().enumerate() {
        let prm = SlidingParamsF64::new(pb).unwrap();
        for (cand, n) in candidates(&prm, prm.target, &SolverOptions::default()).unwrap() {
            // The last case (theta = 0) at 66 nodes: its nodes are -cos(pi k/67) up to rounding.
            for n in [n, if i == 3 { 66 } else { n + 5 }] {
                let col = collocation(prm.theta, n).unwrap();
                let st = state_of(&prm, prm.target, cand, n, false).unwrap();
                let g = g_on_grid(&col, &st);
                assert_eq!(g.len(), 86);
                for (j, &u) in col.grid.u.iter().enumerate() {
                    let direct = g_at(&col, &st, u);
                    assert_eq!(g[j].to_bits(), direct.to_bits(), "case {i}, n = {n}, u = {u}: {} vs {direct}", g[j]);
                    assert_eq!(col.grid.omega[j].to_bits(), omega(u, prm.theta).to_bits());
                    on_node += matches!(col.grid.at[j], GridPoint::Node(_)) as usize;
                }
            }
        }
    }
    // At theta = 0 the rule is the closed-form Gauss–Chebyshev one, whose 66 nodes are the
    // samples' interior Chebyshev–Lobatto points to the bit: the node path is exercised.
    assert_eq!(on_node, 66);
}

/// G off the contact from the known divided differences (`interpolant::g_off_contact`, by
/// batches, 256-bit vectors where the processor has them) is the portable one-lane code to the
/// bit and the Nyström interpolant `g_at` (its F[u, x_r] by the arctangent form) to round-off,
/// on both sides of the contact, for the parabola (periodic and single) and the sinusoid.
#[test]
fn g_off_the_contact_is_g_at() {
    use super::candidates::state_of;
    use super::interpolant::{g_at, g_off_contact, g_off_contact_portable};
    use super::operator::collocation;
    for pb in &right_side_kinds() {
        let prm = SlidingParamsF64::new(pb).unwrap();
        for (cand, n) in candidates(&prm, prm.target, &SolverOptions::default()).unwrap() {
            let col = collocation(prm.theta, n).unwrap();
            let st = state_of(&prm, prm.target, cand, n, false).unwrap();
            for side in [1.0, -1.0] {
                // 21 points (two full batches and one partial) from the end to |u| = 21.
                let us: Vec<f64> = (0..21).map(|j| side * (1.0 + j as f64 + 1e-9)).collect();
                let r = if side > 0.0 { col.colloc.len() - 1 } else { 0 };
                let (xr, xi_r) = (col.colloc[r], st.map.offset(col.colloc[r]));
                let dds: Vec<f64> =
                    us.iter().map(|&u| st.rhs.off_contact(&st.map, st.c, u, st.map.offset(u), xr, xi_r).1).collect();
                let (mut fast, mut portable) = (vec![0.0; us.len()], vec![0.0; us.len()]);
                g_off_contact(&col, &st, r, &us, &dds, &mut fast);
                g_off_contact_portable(&col, &st, r, &us, &dds, &mut portable);
                let scale = st.g.iter().fold(0.0f64, |m, g| m.max(g.abs()));
                for ((u, f), p) in us.iter().zip(&fast).zip(&portable) {
                    assert_eq!(f.to_bits(), p.to_bits(), "u = {u}");
                    let direct = g_at(&col, &st, *u);
                    assert!((f - direct).abs() <= 1e-13 * scale, "u = {u}: {f} vs {direct} (scale {scale})");
                }
            }
        }
    }
}

/// `Collocation::solve` (the substitutions on the stored factors) gives nalgebra's `LU::solve`
/// of the same matrix to the bit, for both signs of theta, theta = 0 and several sizes.
#[test]
fn the_substitutions_are_nalgebras_to_the_bit() {
    use super::operator::Collocation;
    use nalgebra::{DMatrix, DVector};
    for (theta, n) in [(-0.0272, 16), (-0.0272, 24), (0.0, 9), (0.148, 40), (0.4, 67)] {
        let col = Collocation::new(theta, n).unwrap();
        let (rule, xs) = (&col.rule, &col.colloc);
        let m = DMatrix::<f64>::from_fn(n + 1, n + 1, |r, k| {
            if k == n {
                1.0
            } else {
                rule.weights[k] / (PI * (xs[r] - rule.nodes[k]))
            }
        });
        let lu = m.lu();
        for seed in 0..5 {
            let rhs: Vec<f64> = (0..=n).map(|i| ((i * 7 + seed * 13) as f64 * 0.37).sin() + 0.1 * i as f64).collect();
            let want = lu.solve(&DVector::from_vec(rhs.clone())).unwrap();
            let (g, k) = col.solve(&rhs).unwrap();
            for (a, b) in g.iter().chain([&k]).zip(want.iter()) {
                assert_eq!(a.to_bits(), b.to_bits(), "theta = {theta}, n = {n}: {a} vs {b}");
            }
        }
    }
}
