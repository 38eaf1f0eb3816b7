//! Checks of the single punch's self-similar solution (docs/theory.md section 17): the limits,
//! the uncoupled problem against Spence and Johnson, the boundary-element value of issue 32, the
//! two methods against each other, the inequalities of the state.

use super::increment_f64::{increment, stick_edge_defect};
use super::single_punch::{solve, solve_once, Method, SinglePunchF64};
use super::state_f64::state;
use crate::model::Material;
use crate::params::adhesion::AdhesionParamsF64;
use exact_series::Q;
use std::f64::consts::FRAC_PI_2;

/// n = 40 stick elements (and 80 for the estimate), the meshes of every check below.
const N: usize = 40;

fn both(beta: f64, mu: f64) -> (SinglePunchF64, SinglePunchF64) {
    (solve(beta, mu, N, Method::Increment).unwrap(), solve(beta, mu, N, Method::State).unwrap())
}

/// The arithmetic-geometric mean (40 steps: converged quadratically long before).
fn agm(mut a: f64, mut b: f64) -> f64 {
    for _ in 0..40 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    a
}

/// K'(k)/K(k) = AGM(1, k')/AGM(1, k), from K(k) = pi/(2 AGM(1, k')) and K'(k) = pi/(2 AGM(1, k)).
fn elliptic_ratio(k: f64) -> f64 {
    agm(1.0, (1.0 - k * k).sqrt()) / agm(1.0, k)
}

/// The uncoupled stick ratio: the root of K'(gamma)/K(gamma) = beta/mu (decreasing in gamma).
fn spence_johnson(ratio: f64) -> f64 {
    let (mut lo, mut hi) = (1e-12, 1.0 - 1e-15);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if elliptic_ratio(mid) > ratio {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// nu = 1/2 (beta = 0): Hertz exactly, the whole contact sticks; as beta falls (nu -> 1/2) the
/// load coefficient falls toward pi/2 and the slip zones shrink (beta = 0.1: below 1e-4 a, refused
/// by the f64 mesh).
#[test]
fn incompressible_is_hertz() {
    assert_eq!(solve_once(0.0, 0.5, N, Method::Increment, true).unwrap(), (1.0, FRAC_PI_2));
    // beta = 0 by the equations (17.7): whatever the stick zone, s2 is the flat punch and C_P = pi/2
    // (to the n = 40 mesh's 4e-4, see `uncoupled_is_spence_johnson`)
    for (mu, gamma) in [(0.3, 0.2), (3.0, 0.7)] {
        let cp = super::increment_f64::load_coefficient(&increment(0.0, mu, gamma, N, true).unwrap());
        assert!((cp - FRAC_PI_2).abs() < 4e-4, "mu {mu}, gamma {gamma}: C_P {cp}");
    }
    let mut last = (f64::INFINITY, 0.0);
    for beta in [0.5, 0.4, 0.3] {
        let r = solve(beta, 0.5, N, Method::Increment).unwrap();
        let excess = r.load_coefficient - FRAC_PI_2;
        assert!(excess > 0.0 && excess < last.0 && r.gamma > last.1, "beta {beta}: {r:?}");
        last = (excess, r.gamma);
    }
    assert!(last.0 < 0.15, "C_P - pi/2 at beta = 0.3: {}", last.0);
}

/// mu -> 0: the load coefficient falls to Hertz's pi/2 (nu = 0) about linearly in mu, the stick
/// zone shrinks.
#[test]
fn vanishing_friction_is_hertz() {
    let mut excess = vec![];
    let mut last_gamma = 1.0;
    for mu in [0.4, 0.2, 0.1] {
        let r = solve(0.5, mu, N, Method::Increment).unwrap();
        assert!(r.gamma < last_gamma, "mu {mu}: {r:?}");
        last_gamma = r.gamma;
        excess.push(r.load_coefficient - FRAC_PI_2);
    }
    eprintln!("C_P - pi/2 at mu = 0.4, 0.2, 0.1: {excess:?}");
    assert!(excess[0] > excess[1] && excess[1] > excess[2] && excess[2] > 0.0);
    assert!(excess[2] < 0.6 * excess[1] && excess[1] < 0.6 * excess[0], "{excess:?}");
}

/// Without the shear's effect on v the stick ratio is Spence's and Johnson's
/// K'(gamma)/K(gamma) = beta/mu and the load Hertz's; where the answer is known, the error
/// estimate of [`solve`] bounds the true error.
#[test]
fn uncoupled_is_spence_johnson() {
    for (beta, mu) in [(0.5, 0.25), (0.5, 0.5), (0.4, 0.8)] {
        let (g1, p1) = solve_once(beta, mu, N, Method::Increment, false).unwrap();
        let (g2, p2) = solve_once(beta, mu, 2 * N, Method::Increment, false).unwrap();
        let exact = spence_johnson(beta / mu);
        // the flat punch's C_P on the n = 40 mesh: 1e-4 .. 3.5e-4 off, first order in 1/n
        assert!((g1 - exact).abs() < 5e-5, "beta/mu {}: {g1} against {exact}", beta / mu);
        assert!((p1 - FRAC_PI_2).abs() < 4e-4, "C_P {p1}");
        // the error estimate of `solve` (n against 2 n) bounds the true error of the 2 n result
        let (eg, ep) = ((g2 - exact).abs(), (p2 - FRAC_PI_2).abs());
        eprintln!(
            "beta/mu {}: gamma error {eg:.2e} of estimate {:.2e}, C_P {ep:.2e} of {:.2e}",
            beta / mu,
            (g2 - g1).abs(),
            (p2 - p1).abs()
        );
        assert!(eg < (g2 - g1).abs() && ep < (p2 - p1).abs(), "beta/mu {}", beta / mu);
    }
}

/// Issue 32's boundary-element value: c/a = 0.5219(1) at nu = 0, mu = 1/2, by both methods.
#[test]
fn boundary_element_stick_ratio() {
    let (inc, st) = both(0.5, 0.5);
    for r in [&inc, &st] {
        assert!((r.gamma - 0.5219).abs() < 2e-4, "{r:?}");
    }
}

/// The two methods agree within their estimates at beta/mu = 1, 0.3, 0.1 (nu = 0).
#[test]
fn the_two_methods_agree() {
    for mu in [0.5, 0.5 / 0.3, 5.0] {
        let (inc, st) = both(0.5, mu);
        let dg = (inc.gamma - st.gamma).abs();
        let dp = (inc.load_coefficient - st.load_coefficient).abs();
        eprintln!("mu {mu}: {inc:?} {st:?}");
        assert!(dg < 2.0 * (inc.gamma_error + st.gamma_error) + 1e-5, "mu {mu}: gamma {dg}");
        assert!(dp < 2.0 * (inc.load_coefficient_error + st.load_coefficient_error) + 1e-5, "mu {mu}: C_P {dp}");
    }
}

/// mu -> infinity (docs/theory.md section 17.3 "Large mu"): the slip zone does not close and C_P
/// levels off below complete adhesion's pi/(2 (1 - 2 eps S)) (1.95787 at nu = 0). The law
/// (17.15)-(17.16), X = X_inf + X_1/mu + X_2/mu^2, through mu = 64, 256, 1024 (the increment
/// method, n = 40 and 80) predicts mu = 16 to within 3e-5 (measured: 8.4e-6 in 1 - c/a, 3.6e-6 in 1 - C_P/C_ca), and its limits
/// are the MPFR spectral method's (1 - c/a, 1 - C_P/C_ca both 3.75e-3, fitted the same way to
/// mu = 8, 16, 64: `examples/mu_infinity.rs`), far from complete adhesion's 0 beside the estimates.
#[test]
fn growing_friction_levels_off_below_complete_adhesion() {
    let material = Material::from_contact_modulus(Q::from_integer(0.into()), Q::from_integer(1.into())).unwrap();
    let adhesion = AdhesionParamsF64::new(&material).load_constant;
    assert!((adhesion - 1.95787).abs() < 1e-5);
    let mus = [16.0, 64.0, 256.0, 1024.0];
    let runs: Vec<SinglePunchF64> = mus.iter().map(|&mu| solve(0.5, mu, N, Method::Increment).unwrap()).collect();
    // the slip-zone width and the load's gap, each with its n = 40 / 80 estimate
    let width: Vec<f64> = runs.iter().map(|r| 1.0 - r.gamma).collect();
    let gap: Vec<f64> = runs.iter().map(|r| 1.0 - r.load_coefficient / adhesion).collect();
    for (k, r) in runs.iter().enumerate() {
        eprintln!("mu {}: 1 - c/a = {:.6e}, 1 - C_P/C_ca = {:.6e} ({r:?})", mus[k], width[k], gap[k]);
        assert!(r.gamma_error < 5e-5 && r.load_coefficient_error < 1e-4, "mu {}: {r:?}", mus[k]);
        if k > 0 {
            // the slip zone narrows and the load rises, ever more slowly
            assert!(width[k] < width[k - 1] && gap[k] < gap[k - 1], "mu {}", mus[k]);
        }
    }
    for (name, x) in [("1 - c/a", &width), ("1 - C_P/C_ca", &gap)] {
        let [c0, c1, c2] = quadratic_in_inverse(&mus[1..], &x[1..]);
        let at_16 = c0 + c1 / 16.0 + c2 / 256.0;
        eprintln!("{name}: limit {c0:.5e}, 1/mu {c1:.4e}, 1/mu^2 {c2:.4e}; mu = 16: {at_16:.6e} vs {:.6e}", x[0]);
        assert!((at_16 - x[0]).abs() < 3e-5, "{name}: the law misses mu = 16: {at_16} vs {}", x[0]);
        assert!(c1 > 0.0, "{name}: the 1/mu term {c1}");
        // the MPFR limit 3.75e-3 within the f64 method's offsets (<= 5e-5 measured at mu = 64)
        assert!((c0 - 3.75e-3).abs() < 1.5e-4, "{name}: limit {c0}, not the MPFR 3.75e-3 (complete adhesion: 0)");
    }
}

/// (c0, c1, c2) with x = c0 + c1/mu + c2/mu^2 through three points.
pub(super) fn quadratic_in_inverse(mus: &[f64], x: &[f64]) -> [f64; 3] {
    let h: Vec<f64> = mus.iter().map(|m| 1.0 / m).collect();
    // Newton's divided differences in h
    let d01 = (x[1] - x[0]) / (h[1] - h[0]);
    let d12 = (x[2] - x[1]) / (h[2] - h[1]);
    let c2 = (d12 - d01) / (h[2] - h[0]);
    let c1 = d01 - c2 * (h[0] + h[1]);
    let c0 = x[0] - c1 * h[0] - c2 * h[0] * h[0];
    [c0, c1, c2]
}

/// The state at the self-similar gamma: q2 >= 0, |q1| <= mu q2 on the stick zone (up to the
/// discretisation next to its edge), and the slip zones slip inward, against q1 = mu q2. q2 >= 0
/// up to 1e-5 of its maximum: within 1e-7 a of the edge the state's boundedness condition leaves
/// a residual of the near-bounded mode (1 - x)^(-1/2 + theta0) (q2 = -6e-7 there at mu = 16); the
/// state superposed from the increments is positive there (measured, 2e-7 .. 8e-10).
#[test]
fn the_state_keeps_the_inequalities() {
    for mu in [0.5, 5.0, 16.0] {
        state_keeps_the_inequalities(0.5, mu);
    }
}

fn state_keeps_the_inequalities(beta: f64, mu: f64) {
    let r = solve(beta, mu, N, Method::State).unwrap();
    let s = state(beta, mu, r.gamma, 2 * N).unwrap();
    let top = s.q2.iter().cloned().fold(0.0, f64::max);
    for j in 0..s.q2.len() - 1 {
        assert!(s.q2[j] > -1e-5 * top, "mu {mu}: q2 = {} on element {j}", s.q2[j]);
    }
    for j in 0..s.mesh.stick {
        assert!(
            s.q1[j].abs() <= mu * s.q2[j] + 1e-4 * top,
            "mu {mu}: stick element {j}: {} > {}",
            s.q1[j],
            mu * s.q2[j]
        );
    }
    for j in s.mesh.stick + 1..s.q2.len() {
        assert!(s.slip_rate(j) < 1e-4 * top, "mu {mu}: slip element {j} slips outward: {}", s.slip_rate(j));
    }
    // and the increment's defect changes sign at the state's gamma (within its estimate)
    let d = |g: f64| stick_edge_defect(&increment(beta, mu, g, 2 * N, true).unwrap(), beta, mu);
    assert!(d(r.gamma - 5.0 * r.gamma_error - 1e-4) < 0.0 && d(r.gamma + 5.0 * r.gamma_error + 1e-4) > 0.0);
}
