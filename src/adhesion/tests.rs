//! Tests of Problem 2 across the methods: closed forms (Hertz, Kuznetsov, Sadowsky, C_P), the
//! boundary conditions by an independent evaluation of the surface relations [1.6]-[1.8], load
//! balance, MPFR vs f64, convergence with nodes, errors.

use super::series_f64::{self, kernel::flat_punch_stress};
use super::volterra_mpfr::{self, VolterraParams};
use super::{solve_f64, solve_mpfr, solve_verified, AdhesionError, F64Route};
use crate::model::OnPunchRow;
use crate::model::{AdhesionProblem, AdhesionSize, Exact, Material, Period, PunchShape};
use crate::numerics::exact::to_f64;
use crate::numerics::tanh_sinh::tanh_sinh_f64;
use crate::params::adhesion::{self as constants, AdhesionParamsF64, AdhesionParamsMpfr};
use rug::float::Constant;
use rug::ops::Pow;
use rug::Float;

fn q(n: i64, d: i64) -> Exact {
    Exact::new(n.into(), d.into())
}
fn material(nu: Exact) -> Material {
    Material::from_contact_modulus(nu, q(2, 1)).unwrap()
}
fn problem(nu: Exact, period: Option<Exact>, size: AdhesionSize) -> AdhesionProblem {
    let p = match period {
        Some(l) => Period::finite(l).unwrap(),
        None => Period::Infinite,
    };
    AdhesionProblem::new(material(nu), p, PunchShape::parabolic(q(3, 1)).unwrap(), size).unwrap()
}
fn pts() -> Vec<Exact> {
    vec![q(0, 1), q(1, 1000), q(1, 10), q(1, 4), q(1, 2), q(9, 10), q(99, 100), q(1, 1)]
}
fn relerr(a: &Float, b: &Float) -> f64 {
    Float::with_val(64, Float::with_val(a.prec().max(b.prec()), a - b) / b).abs().to_f64()
}

#[test]
fn adhesion_kuznetsov_load_nu_half() {
    // nu = 1/2: P2 = (E* k L^2/pi) ln sec(pi a/L) [2.15], docs/theory.md section 6.
    for (a, l) in [(q(1, 10), q(1, 1)), (q(3, 20), q(1, 1)), (q(1, 3), q(1, 1))] {
        let pr = problem(q(1, 2), Some(l.clone()), AdhesionSize::HalfWidth(a.clone()));
        let v = solve_verified(&pr, &pts(), 25).unwrap();
        let prec = v.solution.prec;
        let lam = volterra_mpfr::lambda_of(&a, &l, prec);
        let sec = Float::with_val(prec, lam.cos_ref()).recip().ln();
        let lf = crate::numerics::exact::to_float(&l, prec);
        let want = sec * 2u32 * 3u32 * &lf * &lf / Float::with_val(prec, Constant::Pi);
        let e = relerr(&v.solution.normal_load, &want);
        assert!(e < 1e-25, "a/L {a}: {e:e}");
        assert!(v.digits_verified.headline >= 25.0, "{:?}", v.digits_verified);
        for p in &v.solution.points {
            assert!(p.psi.is_zero() || p.psi.clone().abs().to_f64() < 1e-30);
            assert!(p.q1.clone().abs().to_f64() < 1e-30);
        }
    }
}

#[test]
fn adhesion_hertz_single_punch_nu_half() {
    // P2 = (pi/2) E* k a^2, q2 = E* k sqrt(a^2 - x^2), q1 = psi = 0 (docs/theory.md section 6).
    let pr = problem(q(1, 2), None, AdhesionSize::HalfWidth(q(1, 5)));
    let s = solve_mpfr(&pr, &pts(), VolterraParams::for_digits(30)).unwrap();
    let prec = s.prec;
    let pi = Float::with_val(prec, Constant::Pi);
    let want = pi / 2u32 * 2u32 * 3u32 / 25u32;
    assert!(relerr(&s.normal_load, &want) < 1e-30);
    for p in &s.points {
        let x = crate::numerics::exact::to_float(&p.x_over_a, prec) / 5u32;
        let w =
            Float::with_val(prec, Float::with_val(prec, 1u32) / 25u32 - Float::with_val(prec, &x * &x)).sqrt() * 6u32;
        let err = Float::with_val(prec, &p.q2 - w).abs().to_f64();
        assert!(err < 1e-29, "x/a {}: {err:e}", p.x_over_a);
        assert!(p.q1.clone().abs().to_f64() < 1e-30 && p.psi.clone().abs().to_f64() < 1e-30);
    }
}

#[test]
fn adhesion_single_punch_load_constant_and_slope() {
    // C_P = pi/(2 (1 - 2 eps S)), psi = A1 |x|, A1 = -2 eps B k/(1 - 2 eps S): self-similar.
    for nu in [q(0, 1), q(3, 10), q(9, 20)] {
        let pr = problem(nu.clone(), None, AdhesionSize::HalfWidth(q(1, 2)));
        let s = solve_mpfr(&pr, &pts(), VolterraParams::for_digits(30)).unwrap();
        let prec = s.prec;
        let cp = constants::single_punch_load_constant(pr.material(), prec);
        let want = cp * 2u32 * 3u32 / 4u32;
        assert!(relerr(&s.normal_load, &want) < 1e-30, "nu {nu}");
        let a1 = constants::single_punch_slope(pr.material(), prec) * 3u32;
        for p in &s.points[1..] {
            let x = crate::numerics::exact::to_float(&p.x_over_a, prec) / 2u32;
            let w = Float::with_val(prec, &a1 * &x);
            assert!(relerr(&p.psi, &w) < 1e-29, "nu {nu} x/a {}", p.x_over_a);
            let phi = Float::with_val(prec, &w * &x) / 2u32;
            assert!(relerr(&p.phi, &phi) < 1e-29);
        }
    }
}

#[test]
fn adhesion_flat_punch_sadowsky_and_unit_load() {
    // eps = 0: Sadowsky, L sigma = cos chi/sqrt(sin^2 lambda - sin^2 chi); every eps: int = 1.
    let lam: f64 = 0.7;
    let (re, im) = flat_punch_stress(0.3, lam + 0.3, lam - 0.3, lam, 0.0, 1.0);
    let want = 0.3f64.cos() / (lam.sin().powi(2) - 0.3f64.sin().powi(2)).sqrt();
    assert!((re - want).abs() < 1e-14 && im == 0.0);
    for eps in [0.0, 0.05, 0.1748] {
        // (1/L) int_{-a}^{a} L sigma dx = (1/pi) int_{-lambda}^{lambda} L sigma d chi, chi = lambda (2 s - 1).
        let rule = tanh_sinh_f64(53, 1.5);
        let (mut sr, mut si) = (0.0, 0.0);
        for &(s, c, w) in &rule {
            let chi = lam * (s - c);
            let (r, i) =
                flat_punch_stress(chi, 2.0 * lam * s, 2.0 * lam * c, lam, eps, (std::f64::consts::PI * eps).cosh());
            sr += w * r * 2.0 * lam / std::f64::consts::PI;
            si += w * i * 2.0 * lam / std::f64::consts::PI;
        }
        assert!((sr - 1.0).abs() < 1e-12 && si.abs() < 1e-12, "eps {eps}: {sr} {si}");
    }
}

/// (H[q2~] - beta q1~, -H[q1~] - beta q2~)(sigma0) in units E* k a, from the f64 stresses
/// (surface relations [1.6]-[1.8], docs/theory.md section 2, with the periodic cot kernel).
fn surface_relations(sol: &series_f64::SeriesSolution, beta: f64, sigma0: f64) -> (f64, f64) {
    let lam = sol.lambda;
    let pi = std::f64::consts::PI;
    let stress = |s: f64| -> (f64, f64) {
        let (q2, q1) = sol.stress_ratio(s.abs());
        (q2, if s < 0.0 { -q1 } else { q1 })
    };
    let kern = |d: f64| if lam == 0.0 { 1.0 / (pi * d) } else { lam / pi / (lam * d).tan() };
    let (q20, q10) = stress(sigma0);
    let rule = tanh_sinh_f64(53, 1.0);
    let (mut h2, mut h1) = (0.0, 0.0);
    // Break at 0 too: q1 ~ x ln|x| there (the kink of psi = A1 |x| + ...).
    for (lo, hi) in [(-1.0, 0.0), (0.0, sigma0), (sigma0, 1.0)] {
        for &(s, c, w) in &rule {
            // Node in (lo, hi) from the nearer end, so distances to sigma0 stay accurate.
            let xx = if s < 0.5 { lo + (hi - lo) * s } else { hi - (hi - lo) * c };
            let d = if hi == sigma0 && s >= 0.5 {
                (hi - lo) * c
            } else if lo == sigma0 && s < 0.5 {
                -(hi - lo) * s
            } else {
                sigma0 - xx
            };
            if d == 0.0 {
                continue; // bounded integrand times a vanishing weight
            }
            let (q2, q1) = stress(xx);
            let kv = kern(d);
            h2 += w * (hi - lo) * (q2 - q20) * kv;
            h1 += w * (hi - lo) * (q1 - q10) * kv;
        }
    }
    let log = if lam == 0.0 {
        ((1.0 + sigma0) / (1.0 - sigma0)).ln() / pi
    } else {
        ((lam * (1.0 + sigma0)).sin() / (lam * (1.0 - sigma0)).sin()).ln() / pi
    };
    h2 += q20 * log;
    h1 += q10 * log;
    (h2 - beta * q10, -h1 - beta * q20)
}

#[test]
fn adhesion_boundary_conditions_hold_inside() {
    // (E*/2) v' = (E*/2) g' = E* k x and (E*/2) u' = (E*/2) psi inside the contact: in units
    // E* k a, sigma0 and psi~/2. An evaluation independent of the incremental construction.
    for (nu, lam) in [(q(0, 1), 0.0), (q(0, 1), 0.6), (q(3, 10), 0.9), (q(9, 20), 0.3)] {
        let m = material(nu.clone());
        let beta = to_f64(&m.beta()).unwrap();
        let sol = series_f64::solve_nominal(&m, lam).unwrap();
        for sigma0 in [0.2, 0.55, 0.8] {
            let (v, u) = surface_relations(&sol, beta, sigma0);
            assert!((v - sigma0).abs() < 2e-11, "nu {nu} lam {lam} x/a {sigma0}: v' {v}");
            let psi_half = 0.5 * sol.psi_ratio(sigma0);
            assert!((u - psi_half).abs() < 2e-11, "nu {nu} lam {lam}: u' {u} vs {psi_half}");
        }
    }
}

#[test]
fn adhesion_load_balance() {
    // int_{-a}^{a} q2 dx = P2 [1.9], f64.
    for (nu, lam) in [(q(0, 1), 0.5), (q(3, 10), 1.0)] {
        let m = material(nu);
        let sol = series_f64::solve_nominal(&m, lam).unwrap();
        let rule = tanh_sinh_f64(53, 1.0);
        let total: f64 = rule.iter().map(|&(s, _, w)| 2.0 * w * sol.stress_ratio(s).0).sum();
        assert!((total - sol.load_ratio()).abs() < 1e-13 * sol.load_ratio(), "{total} {}", sol.load_ratio());
    }
}

#[test]
fn adhesion_mpfr_and_f64_agree() {
    for nu in [q(0, 1), q(3, 10), q(9, 20), q(1, 2)] {
        // lambda = 0.31, 0.52, 0.79 (the last outside the f64 series' range at nu = 0: there the
        // collocation in eta answers), single.
        for (a, l) in [(q(1, 10), Some(q(1, 1))), (q(1, 6), Some(q(1, 1))), (q(1, 4), Some(q(1, 1))), (q(1, 2), None)] {
            let pr = problem(nu.clone(), l, AdhesionSize::HalfWidth(a.clone()));
            let m = solve_mpfr(&pr, &pts(), VolterraParams::for_digits(20)).unwrap();
            let f = solve_f64(&pr, &pts()).unwrap();
            let beyond_series = nu == q(0, 1) && a == q(1, 4);
            assert_eq!(f.route, if beyond_series { F64Route::Collocation } else { F64Route::Series }, "nu {nu} a {a}");
            let ka = 3.0 * m.half_width.to_f64();
            let tol = 1e-12;
            assert!(
                (m.normal_load.to_f64() - f.normal_load).abs() < tol * f.normal_load,
                "nu {nu} lam {}: {} vs {}",
                f.lambda,
                m.normal_load,
                f.normal_load
            );
            for (u, v) in m.points.iter().zip(&f.points) {
                assert!((u.psi.to_f64() - v.psi).abs() < tol * ka, "nu {nu} psi {} {}", u.psi, v.psi);
                assert!((u.phi.to_f64() - v.phi).abs() < tol * ka);
                assert!((u.q2.to_f64() - v.q2).abs() < tol * 2.0 * ka, "q2 {} {}", u.q2, v.q2);
                assert!((u.q1.to_f64() - v.q1).abs() < tol * 2.0 * ka, "q1 {} {}", u.q1, v.q1);
            }
        }
    }
}

#[test]
#[ignore = "long tier: 7 s alone in the test profile (opt-level 2) on a loaded 2-core machine (scripts/test --long)"]
fn adhesion_converges_with_nodes() {
    // Load at nu = 0, lambda = pi/5: the error against a 60-digit run falls with the target.
    let pr = problem(q(0, 1), Some(q(1, 1)), AdhesionSize::HalfWidth(q(1, 5)));
    let reference = solve_mpfr(&pr, &[], VolterraParams::for_digits(60)).unwrap().normal_load;
    let mut last = 1.0;
    for d in [10u32, 20, 30, 40] {
        let s = solve_mpfr(&pr, &[], VolterraParams::for_digits(d)).unwrap();
        let e = relerr(&s.normal_load, &reference);
        assert!(e < 10f64.powi(-(d as i32)) && e <= last, "digits {d}: {e:e}");
        last = e;
    }
}

#[test]
fn adhesion_load_given_finds_half_width() {
    for (nu, l) in [(q(3, 10), Some(q(1, 1))), (q(0, 1), None), (q(1, 2), Some(q(1, 1)))] {
        let pa = problem(nu.clone(), l.clone(), AdhesionSize::HalfWidth(q(1, 5)));
        let s = solve_mpfr(&pa, &[], VolterraParams::for_digits(30)).unwrap();
        let p2 = s.normal_load.to_rational().unwrap();
        let p2 = Exact::new(
            num_bigint::BigInt::parse_bytes(p2.numer().to_string().as_bytes(), 10).unwrap(),
            num_bigint::BigInt::parse_bytes(p2.denom().to_string().as_bytes(), 10).unwrap(),
        );
        let pl = problem(nu, l, AdhesionSize::NormalLoad(p2));
        let v = solve_verified(&pl, &pts(), 25).unwrap();
        let a = v.solution.half_width.to_f64();
        assert!((a - 0.2).abs() < 1e-24 * 0.2 + 1e-30, "{a}");
        assert!(v.digits_verified.size >= 25.0);
        let f = solve_f64(&pl, &pts()).unwrap();
        assert!((f.half_width - 0.2).abs() < 1e-13);
    }
}

#[test]
fn adhesion_errors_are_typed() {
    let pr = problem(q(3, 10), Some(q(1, 1)), AdhesionSize::HalfWidth(q(1, 5)));
    let e = solve_mpfr(&pr, &[q(11, 10)], VolterraParams::for_digits(20)).unwrap_err();
    assert!(matches!(e, AdhesionError::InvalidArgument { parameter: "points", .. }));
    let e = solve_verified(&pr, &[], 2).unwrap_err();
    assert!(matches!(e, AdhesionError::InvalidArgument { parameter: "digits", .. }));
    let near = problem(q(3, 10), Some(q(1, 1)), AdhesionSize::HalfWidth(q(4999, 10000)));
    let e = solve_mpfr(&near, &[], VolterraParams::for_digits(20)).unwrap_err();
    assert!(matches!(e, AdhesionError::IllConditioned { parameter: "lambda", .. }), "{e}");
    let e = solve_f64(&near, &[]).unwrap_err();
    assert!(matches!(e, AdhesionError::IllConditioned { parameter: "lambda", .. }));
    // nu = 0 at lambda = 0.4 pi: the two runs do not agree (module doc, Conditioning).
    let bad = problem(q(0, 1), Some(q(1, 1)), AdhesionSize::HalfWidth(q(2, 5)));
    let e = solve_verified(&bad, &[q(1, 2)], 20).unwrap_err();
    assert!(matches!(e, AdhesionError::IllConditioned { parameter: "lambda", .. }), "{e}");
}

#[test]
fn adhesion_tension_zone_near_edge() {
    // nu = 0: q2 < 0 in a thin zone at the edge; check q2 < 0 at its middle, none at nu = 1/2.
    let pr = problem(q(0, 1), Some(q(1, 1)), AdhesionSize::HalfWidth(q(1, 5)));
    let s = solve_mpfr(&pr, &[], VolterraParams::for_digits(20)).unwrap();
    assert!(!s.tension.zones.is_empty());
    let z = &s.tension.zones[0];
    assert!(z.from_x_over_a < z.to_x_over_a && z.to_x_over_a < 1);
    // Middle of the zone (geometric mean of its 1 - x/a ends) in tension; outside it, pressure.
    let mid = Float::with_val(64, &z.delta_inner * &z.delta_outer).sqrt().to_f64();
    let mid = Exact::new(((1.0 - mid) * 1e15).round().to_string().parse().unwrap(), 1_000_000_000_000_000i64.into());
    let outer = Float::with_val(64, &z.delta_outer * 10u32).to_f64();
    let outer =
        Exact::new(((1.0 - outer) * 1e15).round().to_string().parse().unwrap(), 1_000_000_000_000_000i64.into());
    let s = solve_mpfr(&pr, &[mid, outer], VolterraParams::for_digits(20)).unwrap();
    assert!(s.points[0].q2 < 0 && s.points[1].q2 > 0, "{} {}", s.points[0].q2, s.points[1].q2);
    assert_eq!(s.tension.at_points, vec![0]);
    let pr2 = problem(q(1, 2), Some(q(1, 1)), AdhesionSize::HalfWidth(q(1, 5)));
    assert!(solve_mpfr(&pr2, &[], VolterraParams::for_digits(20)).unwrap().tension.zones.is_empty());
}

#[test]
fn adhesion_edge_factor_matches_stress_near_edge() {
    // (q2 + i q1)/(E* k a) = C delta^{1/2 - i eps} (1 + O(delta)) at delta = 1 - x/a -> 0.
    let m = material(q(0, 1));
    let prec = 100;
    let lam = Float::with_val(prec, 0.6);
    let params = VolterraParams::for_digits(20);
    let sol = volterra_mpfr::solve(&AdhesionParamsMpfr::new(&m, params.prec), &lam, params).unwrap();
    let c = sol.edge_stress_factor();
    for d in [1e-6, 1e-9] {
        let delta = Float::with_val(prec, d);
        let (q2, q1) = sol.stress_ratio_near_edge(&delta);
        let expo = rug::Complex::with_val(prec, (0.5f64, Float::with_val(prec, -&sol.eps)));
        let want = rug::Complex::with_val(prec, &c * rug::Complex::with_val(prec, delta.clone()).pow(&expo));
        let err = ((q2.to_f64() - want.real().to_f64()).powi(2) + (q1.to_f64() - want.imag().to_f64()).powi(2)).sqrt();
        let size = want.clone().abs().real().to_f64();
        assert!(err < 10.0 * d * size, "delta {d}: {err:e} vs {size:e}");
    }
}

#[test]
fn adhesion_flat_punch_is_adhesive_and_k_is_its_outside_slope() {
    // (H + i beta) sigma_flat = 0 inside; H[sigma_flat] = K(chi, lambda) outside (docs/theory.md 4).
    let pi = std::f64::consts::PI;
    for nu in [q(0, 1), q(9, 20)] {
        let m = material(nu.clone());
        let beta = to_f64(&m.beta()).unwrap();
        let eps = AdhesionParamsF64::new(&m).eps;
        let lam = 0.6f64;
        let rule = tanh_sinh_f64(53, 1.0);
        // sigma(chi) over chi in (-lam, lam): L sigma; H[sigma](x) = (1/pi) int L sigma(chi') cot(chi - chi') dchi'
        let ch = (pi * eps).cosh();
        let sig = |chi: f64, lp: f64, lm: f64| flat_punch_stress(chi, lp, lm, lam, eps, ch);
        // Outside: chi0 = 0.9
        for chi0 in [0.9f64, 1.2] {
            let (mut hr, mut hi) = (0.0, 0.0);
            for &(s, c, w) in &rule {
                let chi = lam * (s - c);
                let (r, i) = sig(chi, 2.0 * lam * s, 2.0 * lam * c);
                let k = 1.0 / (chi0 - chi).tan() / pi * 2.0 * lam * w;
                hr += r * k;
                hi += i * k;
            }
            // K formula
            let (sp, sm) = ((chi0 + lam).sin(), (chi0 - lam).sin());
            let mag = 1.0 / (sp * sm).sqrt();
            let th = eps * (sp.ln() - sm.ln());
            let (cr, ci) = (chi0.cos() * (2.0 * eps * lam).cosh(), chi0.sin() * (2.0 * eps * lam).sinh());
            let (st, ct) = th.sin_cos();
            let (kr, ki) = (mag * (ct * cr - st * ci), mag * (ct * ci + st * cr));
            assert!(
                (hr - kr).abs() < 1e-13 && (hi - ki).abs() < 1e-13,
                "nu {nu} chi {chi0}: ({hr}, {hi}) vs ({kr}, {ki})"
            );
        }
        // Inside: (H + i beta) sigma at chi0 = 0.3: PV by subtraction.
        let chi0 = 0.3f64;
        let (s0r, s0i) = sig(chi0, lam + chi0, lam - chi0);
        let (mut hr, mut hi) = (0.0, 0.0);
        for (lo, hi_) in [(-lam, chi0), (chi0, lam)] {
            for &(s, c, w) in &rule {
                let (x, lp, lm) = if s < 0.5 {
                    let x = lo + (hi_ - lo) * s;
                    (x, lam + x, lam - x)
                } else {
                    let x = hi_ - (hi_ - lo) * c;
                    (x, lam + x, lam - x)
                };
                let (lp, lm) = if lo == -lam && s < 0.5 {
                    ((hi_ - lo) * s, lm)
                } else if hi_ == lam && s >= 0.5 {
                    (lp, (hi_ - lo) * c)
                } else {
                    (lp, lm)
                };
                let d = chi0 - x;
                if d == 0.0 {
                    continue;
                }
                let (r, i) = sig(x, lp, lm);
                let k = (hi_ - lo) * w / d.tan() / pi;
                hr += (r - s0r) * k;
                hi += (i - s0i) * k;
            }
        }
        let lg = ((lam + chi0).sin() / (lam - chi0).sin()).ln() / pi;
        hr += s0r * lg;
        hi += s0i * lg;
        assert!((hr - beta * s0i).abs() < 1e-13 && (hi + beta * s0r).abs() < 1e-13, "nu {nu}: inside");
    }
}

#[test]
fn adhesion_robust_over_inputs() {
    // No panic, no NaN, digits delivered, for tiny and moderate contacts and points at the edge.
    let points = vec![
        q(0, 1),
        q(1, 3),
        Exact::new(1.into(), 1.into()) - Exact::new(1.into(), num_bigint::BigInt::from(10).pow(20)),
        q(1, 1),
    ];
    for nu in [q(0, 1), q(1, 4), q(1, 2)] {
        for (a, l) in [
            (Exact::new(1.into(), num_bigint::BigInt::from(10).pow(6)), Some(q(1, 1))),
            (q(1, 10), Some(q(1, 1))),
            (q(7, 3), None),
        ] {
            let pr = problem(nu.clone(), l, AdhesionSize::HalfWidth(a.clone()));
            let v = solve_verified(&pr, &points, 10).unwrap();
            assert!(v.digits_verified.headline >= 10.0, "nu {nu} a {a}: {:?}", v.digits_verified);
            for p in &v.solution.points {
                for x in [&p.psi, &p.phi, &p.q1, &p.q2] {
                    assert!(x.is_finite());
                }
            }
            assert!(v.solution.normal_load.is_finite() && v.solution.normal_load > 0);
        }
    }
}

#[test]
fn f64_estimate_never_overclaims() {
    // The f64 method's estimated digits (a second, finer run) never exceed its true digits
    // against method 1 (20 digits) by more than 0.3, per quantity, over a grid of (nu, lambda).
    use crate::numerics::accuracy::{verified_digits, F64_DIGITS_CAP};
    let cap = F64_DIGITS_CAP;
    let cases = [
        (q(0, 1), Some(q(1, 1)), q(1, 20)),
        (q(0, 1), Some(q(1, 1)), q(1, 6)),
        (q(0, 1), None, q(1, 2)),
        (q(3, 10), Some(q(1, 1)), q(1, 10)),
        (q(3, 10), Some(q(1, 1)), q(1, 4)),
        (q(3, 10), Some(q(1, 1)), q(7, 20)),
        (q(0, 1), Some(q(1, 1)), q(11, 50)),
        (q(1, 10), Some(q(1, 1)), q(6, 25)),
        (q(3, 10), Some(q(1, 1)), q(37, 100)),
        (q(9, 20), Some(q(1, 1)), q(1, 5)),
        (q(9, 20), Some(q(1, 1)), q(3, 10)),
        (q(1, 2), Some(q(1, 1)), q(1, 4)),
    ];
    for (nu, l, a) in cases {
        let pr = problem(nu.clone(), l, AdhesionSize::HalfWidth(a.clone()));
        let f = solve_f64(&pr, &pts()).unwrap();
        let m = super::solve_mpfr_with(&pr, &pts(), VolterraParams::for_digits(20), super::TensionZones::Skip).unwrap();
        let s = super::ScalesF64::new(&pr, f.half_width, f.normal_load);
        let d = |x: f64, y: &Float, scale: f64| verified_digits(x - y.to_f64(), scale, cap);
        let truth = super::Digits::from_points(
            d(f.normal_load, &m.normal_load, s.load),
            f.points.iter().zip(&m.points).map(|(u, v)| {
                [d(u.psi, &v.psi, s.psi), d(u.phi, &v.phi, s.phi), d(u.q1, &v.q1, s.stress), d(u.q2, &v.q2, s.stress)]
            }),
            cap,
        );
        let e = f.digits_estimated;
        for (name, est, tru) in [
            ("size", e.size, truth.size),
            ("psi", e.psi, truth.psi),
            ("phi", e.phi, truth.phi),
            ("q1", e.q1, truth.q1),
            ("q2", e.q2, truth.q2),
        ] {
            eprintln!("nu {nu} a/L {a} {name}: estimated {est:.2} true {tru:.2}");
            assert!(est <= tru + 0.3, "nu {nu} a/L {a} {name}: estimated {est:.2} > true {tru:.2} + 0.3");
        }
        assert!(e.headline >= 8.0, "nu {nu} a/L {a}: {e:?}");
    }
}

/// See: issue 13 ("a warning blaming near full contact; the cause is the small-nu conditioning").
/// nu = 0, lambda = 1 (L = 1, a = 1/pi to 12 digits): fewer digits verified than asked, and the
/// warning names the homogeneous solution and its exponent (asymptotics::adhesion_mode), not
/// full contact.
#[test]
fn small_nu_shortfall_names_the_homogeneous_solution() {
    let a = Exact::new(318309886184i64.into(), 1000000000000i64.into());
    let pr = problem(q(0, 1), Some(q(1, 1)), AdhesionSize::HalfWidth(a));
    let v = solve_verified(&pr, &[], 20).unwrap();
    assert!(v.digits_verified.headline < 20.0, "{}", v.digits_verified.headline);
    let w = v.warnings.iter().find(|w| w.contains("requested digits verified")).expect("a shortfall warning");
    assert!(w.contains("homogeneous solution") && w.contains("m* = 605.7") && !w.contains("full contact"), "{w}");
}

/// The homogeneous solution of the symmetric problem (asymptotics::adhesion_mode): at nu = 0,
/// lambda = 1 two MPFR collocations (60 and 100 Chebyshev nodes, 200 bits) each satisfy the
/// equation to better than 1e-20 between their nodes, agree on F = P'/eta to 1e-15 for
/// tau = (eta/lambda)^2 <= 0.3, and yet differ by more than 1e-6 at tau = 1 and in the load
/// (measured 1.7e-4): a function the equation does not see. At nu = 1/2 (eps = 0, unique) the
/// same runs agree to 1e-40.
#[test]
#[ignore = "long tier: 8 s alone in the test profile (opt-level 2) on a loaded 2-core machine (scripts/test --long)"]
fn two_discretisations_differ_by_a_homogeneous_solution() {
    let p = VolterraParams { prec: 200, target_bits: 160, refine: 1.3 };
    let pi = Float::with_val(p.prec, Constant::Pi);
    for (nu, unique) in [(q(0, 1), false), (q(1, 2), true)] {
        let c = AdhesionParamsMpfr::new(&material(nu.clone()), p.prec);
        let lam = Float::with_val(p.prec, 1);
        let runs: Vec<_> =
            [60, 100].iter().map(|&n| volterra_mpfr::solve_with_nodes(&c, &lam, p, n).unwrap()).collect();
        for r in &runs {
            for k in 1..12 {
                let sigma = Float::with_val(p.prec, k as f64 / 12.0 + 0.01);
                let (re, _) = r.integral_i(&sigma);
                let res = Float::with_val(p.prec, &re - &pi).abs().to_f64();
                assert!(res < 1e-20, "nu {nu}: residual {res:e} at sigma {sigma}");
            }
        }
        let diff = |tau: f64| {
            let t = Float::with_val(p.prec, tau);
            Float::with_val(p.prec, runs[0].f_at(&t) - runs[1].f_at(&t)).abs().to_f64()
        };
        let load = Float::with_val(p.prec, runs[0].load_ratio() - runs[1].load_ratio()).abs().to_f64();
        if unique {
            assert!(diff(1.0) < 1e-40 && load < 1e-40, "nu 1/2: {:e} {load:e}", diff(1.0));
        } else {
            for tau in [0.1, 0.2, 0.3] {
                assert!(diff(tau) < 1e-15, "nu 0: F differs by {:e} at tau {tau}", diff(tau));
            }
            assert!(diff(1.0) > 1e-6 && load > 1e-6, "nu 0: {:e} {load:e}", diff(1.0));
        }
    }
}

/// docs/theory.md section 11 (issue 31): the digits the incremental solution keeps at nu < 1/2 are
/// the decades the homogeneous mode still has to grow from lambda to full contact (by the frozen
/// symbol, `asymptotics::adhesion_mode::digits_kept`, margin included), whatever the digits asked:
/// the verified MPFR solver at 20 digits, at (nu, lambda) = (0, 0.9), (1/10, 1.05), (1/5, 1.2),
/// (3/10, 1.35), keeps at least the predicted digits and at most 3 more (measured - predicted:
/// 0.7 to 2.1; at 30 digits the same digits are kept).
#[test]
#[ignore = "long tier: 16 s alone in the test profile (opt-level 2) on a loaded 2-core machine (scripts/test --long)"]
fn the_horizon_bounds_the_measured_spread() {
    use crate::asymptotics::adhesion_mode::digits_kept;
    for (nu, lam) in [(q(0, 1), 0.9), (q(1, 10), 1.05), (q(1, 5), 1.2), (q(3, 10), 1.35)] {
        let a = q((lam / std::f64::consts::PI * 1e6).round() as i64, 1_000_000);
        let lam = std::f64::consts::PI * to_f64(&a).unwrap();
        let pr = problem(nu.clone(), Some(q(1, 1)), AdhesionSize::HalfWidth(a));
        let v = solve_verified(&pr, &[q(0, 1)], 20).unwrap();
        let c = AdhesionParamsF64::new(&material(nu.clone()));
        let predicted = digits_kept(c.eps, c.b, c.s, lam);
        // The runs' own agreement (the claim, digits_verified, is at most the prediction).
        let measured = v.runs_agree.headline;
        assert!(v.digits_verified.headline <= predicted, "{:?}", v.digits_verified);
        println!("nu {nu}, lambda {lam:.4}: measured {measured:.2}, predicted {predicted:.2}");
        assert!(
            predicted <= measured && measured <= predicted + 3.0,
            "nu {nu}, lambda {lam}: {measured} vs {predicted}"
        );
    }
}
