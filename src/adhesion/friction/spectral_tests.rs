//! Checks of the spectral method for the single punch (docs/theory.md section 17.7): the f64
//! methods of section 17.4 at beta/mu = 1, 0.3, 0.1 (independent discretisations), Hertz at
//! beta = 0, the uncoupled problem against K'(gamma)/K(gamma) = beta/mu by the AGM, f64 against
//! MPFR (one discretisation, and the `f64` root against the verified MPFR values), and (long tier) the verified digits at nu = 0, mu = 1/2;
//! narrow slip zones ([`Spectral::narrow`]): the MPFR table of docs/theory.md section 17.3 at
//! nu = 0, and (long tier) the rate in 1/mu at nu = 0.3 ((17.15)-(17.16)).

use rug::Float;

use super::real::{Mp, Real};
use super::single_punch::{solve, Method};
use super::spectral::{Spectral, F64_OVERSAMPLE};
use super::spectral_punch::{slip_width, stick_ratio_f64, verified};

/// K'(k)/K(k) = AGM(1, k')/AGM(1, k), k' = sqrt(1 - k^2) (K(k) = pi/(2 AGM(1, k'))).
fn elliptic_ratio<T: Real>(k: &T) -> T {
    let agm = |a0: T, b0: T| {
        let (mut a, mut b) = (a0, b0);
        for _ in 0..60 {
            let next = (a.clone() + b.clone()) * a.lit(0.5);
            b = (a * b).sqrt();
            a = next;
        }
        a
    };
    let one = k.lit(1.0);
    let kc = (one.clone() - k.clone() * k.clone()).sqrt();
    agm(one.clone(), kc) / agm(one, k.clone())
}

#[test]
fn matches_the_boundary_elements_and_the_f64_methods_at_nu0_mu_half() {
    // section 17.4: c/a = 0.521913 (1e-5), C_P = 1.800927 (3e-5); issue 32: 0.5219(1)
    let (g, p) = stick_ratio_f64(0.5, 0.5, 10, true).unwrap();
    assert!((g - 0.521913).abs() < 1e-5, "c/a = {g}");
    assert!((p - 1.800927).abs() < 3e-5, "C_P = {p}");
}

#[test]
fn agrees_with_the_increment_method_at_three_friction_ratios() {
    // beta/mu = 1, 0.3 at beta = 1/2: within 4 times the increment method's estimate plus the
    // spectral n = 10 vs 14 difference
    for mu in [0.5, 5.0 / 3.0] {
        let f = solve(0.5, mu, 40, Method::Increment).unwrap();
        let (g10, p10) = stick_ratio_f64(0.5, mu, 10, true).unwrap();
        let (g14, p14) = stick_ratio_f64(0.5, mu, 14, true).unwrap();
        let tol_g = 4.0 * f.gamma_error + (g14 - g10).abs();
        let tol_p = 4.0 * f.load_coefficient_error + (p14 - p10).abs();
        assert!((g14 - f.gamma).abs() < tol_g, "mu = {mu}: c/a {g14} vs {} ({tol_g:e})", f.gamma);
        assert!((p14 - f.load_coefficient).abs() < tol_p, "mu = {mu}: C_P {p14} vs {}", f.load_coefficient);
    }
    // beta/mu = 0.1 (theta0 = 0.38): the f64 spectral runs are off by about 1.1e-4 in c/a and 6e-4
    // in C_P (rounding; MPFR at n = 14 gives 0.9927170, 1.9472330, within the increment method's
    // 0.992723 (2e-5), 1.947208 (8e-5); docs/theory.md section 17.7); bounded at the measured size
    let f = solve(0.5, 5.0, 40, Method::Increment).unwrap();
    let (g, p) = stick_ratio_f64(0.5, 5.0, 14, true).unwrap();
    assert!((g - f.gamma).abs() < 3e-4 && (p - f.load_coefficient).abs() < 1.5e-3, "c/a {g}, C_P {p} vs {f:?}");
}

#[test]
fn incompressible_is_hertz_exactly() {
    let v = verified(&Float::with_val(128, 0), &Float::with_val(128, 0.5), 20).unwrap();
    assert_eq!(v.gamma, 1);
    let half_pi = Float::with_val(v.load_coefficient.prec(), rug::float::Constant::Pi) / 2u32;
    assert_eq!(v.load_coefficient, half_pi);
}

#[test]
fn uncoupled_is_spence_johnson_by_the_agm() {
    // beta/mu = 1 and 2: K'/K of the stick ratio, and C_P = pi/2 (s2 the flat punch)
    for (mu, ratio) in [(0.5, 1.0), (0.25, 2.0)] {
        let (g, p) = stick_ratio_f64(0.5, mu, 10, false).unwrap();
        assert!((elliptic_ratio(&g) - ratio).abs() < 1e-6, "mu = {mu}: K'/K = {}", elliptic_ratio(&g));
        assert!((p - std::f64::consts::FRAC_PI_2).abs() < 1e-8, "mu = {mu}: C_P = {p}");
    }
    // MPFR at beta/mu = 1: the root's distance from 1/sqrt(2), D(1/sqrt(2)) over the slope of D
    let sp = Spectral::new(Mp::new(128, 0.5), Mp::new(128, 0.5), 12, false);
    let exact = Mp::new(128, 0.5).sqrt();
    let d0 = sp.solve(&exact).unwrap().stick_edge_defect();
    let shifted = exact.clone() + exact.lit(1e-6);
    let d1 = sp.solve(&shifted).unwrap().stick_edge_defect();
    let err = (d0.clone() * exact.lit(1e-6) / (d1 - d0)).to_f64().abs();
    // measured 1.5e-13 by the secant root (the uncoupled basis converges more slowly)
    assert!(err < 1e-12, "root - 1/sqrt(2) = {err:e}");
}

/// The same discretisation (n = 10, the `f64` oversampling) in `f64` and MPFR at one gamma: the
/// `f64` rounding alone (measured 2.0e-12 in the defect and 4e-14 in C_P; 1.8e-9 and 6.9e-11
/// without the oversampling, docs/theory.md section 17.7).
#[test]
fn f64_and_mpfr_agree_at_one_stick_ratio() {
    let n = 10;
    let sp = Spectral::new(0.5f64, 0.5, n, true);
    let inc = sp.solve(&0.521913).unwrap();
    let (d, p) = (inc.stick_edge_defect(), sp.load_coefficient(&inc));
    let mp = Spectral::new(Mp::new(128, 0.5), Mp::new(128, 0.5), n, true).oversampled(F64_OVERSAMPLE);
    let inc_mp = mp.solve(&Mp::new(128, 0.521913)).unwrap();
    let (d_mp, p_mp) = (inc_mp.stick_edge_defect().to_f64(), mp.load_coefficient(&inc_mp).to_f64());
    // the defect's slope in gamma is about 0.26: 4e-11 in gamma
    assert!((d - d_mp).abs() < 1e-11, "defect {d:e} vs {d_mp:e}");
    assert!((p - p_mp).abs() < 1e-12 * p_mp, "C_P {p} vs {p_mp}");
}

/// Issue 32: the `f64` method against the MPFR values of `verified_digits_at_nu0_mu_half`
/// (c/a = 0.5219076749221461, 16.2 digits; C_P = 1.800911965200506302, 18.1 digits) at n = 14:
/// measured -8.0e-14 and -2.7e-15 (5.9e-13 and 6.4e-15 before issue 32 H80; 3.1e-12 and 1.2e-13 by a full scan: the root lands anywhere in
/// the defect's rounding band; 1.8e-8 and 3.4e-10 without the oversampling, docs/theory.md 17.7).
#[test]
fn f64_agrees_with_the_verified_mpfr_values() {
    let (g, p) = stick_ratio_f64(0.5, 0.5, 14, true).unwrap();
    let (gamma, load) = (0.521_907_674_922_146_1, 1.800_911_965_200_506_3);
    eprintln!("c/a {g} ({:.1e}), C_P {p} ({:.1e})", g - gamma, p - load);
    assert!((g - gamma).abs() < 1e-12, "c/a = {g}");
    assert!((p - load).abs() < 1e-12, "C_P = {p}");
}

#[test]
#[ignore = "long tier: 28 s alone in the test profile (opt-level 2), two MPFR root searches at n = 14 and 20 (scripts/test --long)"]
fn verified_digits_at_nu0_mu_half() {
    let half = Float::with_val(200, 0.5);
    let v = verified(&half, &half, 16).unwrap();
    eprintln!(
        "c/a = {:.25} ({:.1} digits), C_P = {:.25} ({:.1}), f64 {} {}",
        v.gamma, v.gamma_digits, v.load_coefficient, v.load_digits, v.gamma_f64, v.load_f64
    );
    assert!(v.gamma_digits >= 15.0 && v.load_digits >= 16.0);
    // the f64 run only starts the MPFR root search: about 8 digits (measured 1.06e-8 in c/a, the
    // collocation rows' rounding amplified by the least squares; docs/theory.md section 17.7)
    assert!((v.gamma.to_f64() - v.gamma_f64).abs() < 3e-8);
    assert!((v.load_coefficient.to_f64() - v.load_f64).abs() < 1e-9);
}

/// The narrow method (stick zone resolved on the scale of the slip zone, [`Spectral::narrow`];
/// `f64`, n = 10, root in ln(1 - c/a)) at nu = 0, mu = 2 against the MPFR table of
/// docs/theory.md section 17.3 (the default method at n = 10, 14, 128 and 160 bits:
/// 1 - c/a = 0.0230581 (3.9e-8 apart), C_P = 1.93631401 (3.6e-8 relative)). Measured: 2.3058108e-2,
/// 1.936314014 (n = 14: the same to 7e-12 and 2e-12).
#[test]
fn narrow_method_matches_the_mpfr_table_at_nu0() {
    let sp = Spectral::new(0.5, 2.0, 10, true).narrow();
    let (w, p) = slip_width(&sp, 0.02, 1e-12).unwrap();
    eprintln!("nu = 0, mu = 2: 1 - c/a = {w:.10e}, C_P = {p:.12}");
    assert!((w - 0.0230581).abs() < 1e-7, "1 - c/a = {w}");
    assert!((p - 1.93631401).abs() < 5e-8, "C_P = {p}");
}

/// mu -> infinity at nu = 0.3 (beta = 2/7, docs/theory.md section 17.3 "Large mu"): slip zones of
/// 1.6e-6 a, resolved by the narrow method (`f64`, n = 10 and 14). The two n agree (measured
/// 2.7e-5 relative in 1 - c/a and 1.6e-3 of the gap 1 - C_P/C_ca at mu = 1024); the logarithmic law (17.15) through mu = 64, 256,
/// 1024 predicts mu = 32 (measured 4.2e-5 relative: the O(mu^-3) left out), with
/// delta_inf/a = 1.599e-6, Phi_1 = eps Phi_1/eps = 0.500; the load's gap (17.16) levels off at
/// G_inf = kappa delta_inf/a with kappa = 1.000 (as at nu = 0), not at complete adhesion's 0.
#[test]
#[ignore = "long tier: ten f64 roots of narrow slip zones, about a minute (scripts/test --long)"]
fn growing_friction_rate_at_nu_0_3() {
    let (beta, eps) = (2.0 / 7.0, ((9.0f64 / 5.0).ln()) / (2.0 * std::f64::consts::PI));
    let c_ca = 1.674243188848;
    let mus = [32.0, 64.0, 256.0, 1024.0];
    let mut start = 2e-6;
    let mut width = Vec::new();
    let mut gap = Vec::new();
    for &mu in &mus {
        let run = |n: usize, start: f64| slip_width(&Spectral::new(beta, mu, n, true).narrow(), start, 1e-12).unwrap();
        let (w10, p10) = run(10, start);
        let (w, p) = run(14, w10);
        eprintln!(
            "mu {mu}: 1 - c/a = {w:.10e} (n = 10: {w10:.10e}), 1 - C_P/C_ca = {:.6e} (C_P {p:.13}, n = 10: {p10:.13})",
            1.0 - p / c_ca
        );
        assert!((w - w10).abs() < 1e-4 * w, "mu {mu}: n = 10, 14 differ: {w10} {w}");
        assert!((p - p10).abs() < 5e-3 * (1.0 - p / c_ca) * c_ca, "mu {mu}: C_P {p10} {p}");
        width.push(w);
        gap.push(1.0 - p / c_ca);
        start = w;
    }
    // the slip zone narrows and the load rises, ever more slowly
    assert!(width.windows(2).all(|w| w[1] < w[0]) && gap.windows(2).all(|g| g[1] < g[0]), "{width:?} {gap:?}");
    let ln_w: Vec<f64> = width.iter().map(|w| w.ln()).collect();
    let [l0, l1, l2] = super::tests::quadratic_in_inverse(&mus[1..], &ln_w[1..]);
    let at_32 = (l0 + l1 / 32.0 + l2 / 1024.0).exp();
    let (delta_inf, phi_1) = (l0.exp(), eps * l1);
    eprintln!(
        "(17.15): delta_inf/a = {delta_inf:.5e}, Phi_inf = {:.4}, Phi_1 = {phi_1:.4}; mu = 32: {at_32:.6e} vs {:.6e}",
        eps * l0,
        width[0]
    );
    assert!((at_32 - width[0]).abs() < 5e-4 * width[0], "(17.15) misses mu = 32: {at_32} vs {}", width[0]);
    assert!((delta_inf - 1.599e-6).abs() < 2e-9 && (phi_1 - 0.5).abs() < 5e-3, "{delta_inf} {phi_1}");
    let [g0, g1, _] = super::tests::quadratic_in_inverse(&mus[1..], &gap[1..]);
    eprintln!("(17.16): G_inf = {g0:.5e}, G_1 = {g1:.4e}, kappa = {:.4}", g0 / delta_inf);
    assert!(g1 > 0.0 && (g0 / delta_inf - 1.0).abs() < 2e-3, "G_inf {g0}, kappa {}", g0 / delta_inf);
}
