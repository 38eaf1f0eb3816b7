//! The load of the periodic row with finite friction: the march in lambda = pi a/L of the
//! edge-slope condition (docs/theory.md section 17.1, the Volterra condition of section 4 with the
//! friction increment), parabola g = k x^2, both conventions, `f64`.
//!
//! Units L = pi, E* = k = 1 (so P2 = E* k (L/pi)^2 P(lambda), as for complete adhesion in section
//! 4). With s^eta the unit increment at contact eta (its stick ratio c/a from boundedness at the stick
//! edge, [`super::row_f64`]) and W(chi, eta) = H\[s2^eta\](chi) its outside slope, the slope at the
//! moving edge accumulated over the loading is g'/2:
//!     int_0^lambda W(lambda, eta) P'(eta) d eta = lambda.
//! Discretisation: P'(eta) = eta F(eta), F constant on m equal intervals of (0, lambda_max),
//! collocated at their right ends (a lower-triangular system, solved by forward substitution). On
//! interval k the increment is the one at its midpoint eta_k, stretched to the contact eta
//! (s^eta(x) = (eta_k/eta) s^eta_k(x eta_k/eta)), whose outside slope is exact per element; the
//! integral over eta is 8-point Gauss-Legendre, graded as (1 - tau)^4 toward chi on the last
//! interval, where W is singular like (chi - eta)^(-1/2 + theta0). Error estimate: the difference
//! of (n, m) and (2 n, 2 m).

use super::increment_f64::Increment;
use super::mesh::Mesh;
use super::row_f64::{increment, outside_slope, row_stick_ratio};
use crate::growing_contact::error::AdhesionError;

/// 8-point Gauss-Legendre nodes and weights on (0, 1).
fn gauss8() -> [(f64, f64); 8] {
    const X: [f64; 4] =
        [0.183_434_642_495_649_8, 0.525_532_409_916_329, 0.796_666_477_413_626_7, 0.960_289_856_497_536_3];
    const W: [f64; 4] =
        [0.362_683_783_378_362, 0.313_706_645_877_887_3, 0.222_381_034_453_374_5, 0.101_228_536_290_376_3];
    let mut out = [(0.0, 0.0); 8];
    for i in 0..4 {
        out[2 * i] = (0.5 * (1.0 - X[i]), 0.5 * W[i]);
        out[2 * i + 1] = (0.5 * (1.0 + X[i]), 0.5 * W[i]);
    }
    out
}

/// One point of the march: lambda, the stick ratio c/a there, P(lambda) = P2/(E* k (L/pi)^2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RowPoint {
    /// lambda = pi a/L (the right end of an interval).
    pub lambda: f64,
    /// c/a at the interval's midpoint.
    pub stick_ratio: f64,
    /// P(lambda).
    pub load: f64,
}

/// The increment `inc` (solved at contact `from`) stretched to contact `to`.
fn stretched(inc: &Increment, from: f64, to: f64) -> Increment {
    let r = to / from;
    let mesh = Mesh { nodes: inc.mesh.nodes.iter().map(|x| x * r).collect(), stick: inc.mesh.stick };
    Increment { mesh, s2: inc.s2.iter().map(|v| v / r).collect(), s1: inc.s1.iter().map(|v| v / r).collect() }
}

/// The march to `lambda_max` on `m` intervals with `n` stick elements; `gamma` overrides the stick
/// ratio (a check at beta = 0, where any stick zone gives the frictionless increment).
pub fn march(
    beta: f64,
    mu: f64,
    lambda_max: f64,
    n: usize,
    m: usize,
    periodic: bool,
    gamma: Option<f64>,
) -> Result<Vec<RowPoint>, AdhesionError> {
    let h = lambda_max / m as f64;
    let mut incs = Vec::with_capacity(m);
    let mut ratios = Vec::with_capacity(m);
    for k in 0..m {
        let mid = (k as f64 + 0.5) * h;
        let g = match gamma {
            Some(g) => g,
            None => row_stick_ratio(beta, mu, mid, n, periodic)?,
        };
        incs.push(increment(beta, mu, mid, g, n, periodic)?);
        ratios.push(g);
    }
    let gauss = gauss8();
    // weight(i, k) = int over interval k of W(chi_i, eta) eta d eta
    let weight = |i: usize, k: usize| -> f64 {
        let chi = (i + 1) as f64 * h;
        let (lo, mid) = (k as f64 * h, (k as f64 + 0.5) * h);
        let mut sum = 0.0;
        for (t, w) in gauss {
            // eta = lo + h t, or graded toward chi on the last interval: eta = chi - h (1 - t)^4
            let (eta, jac) =
                if k == i { (chi - h * (1.0 - t).powi(4), 4.0 * h * (1.0 - t).powi(3)) } else { (lo + h * t, h) };
            if eta <= 0.0 || eta >= chi {
                continue;
            }
            sum += w * jac * eta * outside_slope(&stretched(&incs[k], mid, eta), chi);
        }
        sum
    };
    let mut f = vec![0.0; m];
    let mut out = Vec::with_capacity(m);
    let mut load = 0.0;
    for i in 0..m {
        let chi = (i + 1) as f64 * h;
        let known: f64 = (0..i).map(|k| weight(i, k) * f[k]).sum();
        f[i] = (chi - known) / weight(i, i);
        load += f[i] * 0.5 * (chi * chi - (i as f64 * h).powi(2));
        out.push(RowPoint { lambda: chi, stick_ratio: ratios[i], load });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::adhesion::friction::single_punch::{solve_once, Method};

    /// beta = 0: the increment is the frictionless flat punch whatever the stick zone, and the
    /// march gives Kuznetsov's P = -pi ln cos lambda (section 4: P' = pi tan eta); the difference of
    /// (n, m) = (10, 16) and (20, 32) bounds the true error of the finer (measured at lambda = 1.2:
    /// 3.2e-3 relative of which 2.6e-3 true).
    #[test]
    fn incompressible_march_is_kuznetsov() {
        let coarse = march(0.0, 0.5, 1.2, 10, 16, false, Some(0.5)).unwrap();
        let fine = march(0.0, 0.5, 1.2, 20, 32, false, Some(0.5)).unwrap();
        for (i, c) in coarse.iter().enumerate().skip(3).step_by(4) {
            let f = &fine[2 * i + 1];
            assert!((f.lambda - c.lambda).abs() < 1e-12);
            let exact = -std::f64::consts::PI * f.lambda.cos().ln();
            let (truth, estimate) = ((f.load / exact - 1.0).abs(), (f.load / c.load - 1.0).abs());
            eprintln!("lambda {}: P {} exact {exact}: error {truth:.2e}, estimate {estimate:.2e}", f.lambda, f.load);
            assert!(truth < estimate && truth < 3e-3, "lambda {}", f.lambda);
        }
    }

    /// Small lambda: P/lambda^2 tends to the single punch's C_P (nu = 0, mu = 1/2: 1.8011 on n = 20)
    /// in both conventions, and c/a to its 0.5219 in `paper` (in `periodic` c/a moves like
    /// 0.73 lambda, `row_f64`).
    #[test]
    fn small_lambda_load_is_the_single_punch() {
        let (gamma, cp) = solve_once(0.5, 0.5, 20, Method::Increment, true).unwrap();
        for periodic in [false, true] {
            let pts = march(0.5, 0.5, 0.1, 20, 16, periodic, None).unwrap();
            let p = pts[0];
            eprintln!("periodic {periodic}: {p:?}, P/lambda^2 {} single {cp}", p.load / p.lambda.powi(2));
            assert!((p.load / p.lambda.powi(2) - cp).abs() < 3e-4, "{p:?}");
            if !periodic {
                assert!((p.stick_ratio - gamma).abs() < 1e-4, "{p:?}");
            }
        }
    }

    /// nu = 0 (beta = 1/2), mu = 0.3 and 1, both conventions, up to lambda = 1.4: the two
    /// discretisations (10, 16) and (20, 32) differ in P(1.4) by about what they differ at nu = 1/2
    /// (Kuznetsov, 5e-3 at lambda = 1.2, first order), and c/a at 1.4 on n = 10, 20 by < 2e-3: no
    /// growth like complete adhesion's homogeneous mode in `paper` there (section 11).
    #[test]
    fn nu_zero_two_discretisations_agree_to_lambda_1_4() {
        for periodic in [false, true] {
            for mu in [0.3, 1.0] {
                let c = *march(0.5, mu, 1.4, 10, 16, periodic, None).unwrap().last().unwrap();
                let f = *march(0.5, mu, 1.4, 20, 32, periodic, None).unwrap().last().unwrap();
                let (g1, g2) = (
                    row_stick_ratio(0.5, mu, 1.4, 10, periodic).unwrap(),
                    row_stick_ratio(0.5, mu, 1.4, 20, periodic).unwrap(),
                );
                let (dp, dg) = ((f.load / c.load - 1.0).abs(), (g2 - g1).abs());
                eprintln!("periodic {periodic} mu {mu}: P(1.4) {} c/a {g2} (differences {dp:.1e}, {dg:.1e})", f.load);
                assert!(dp < 1.5e-2 && dg < 2e-3, "periodic {periodic} mu {mu}: {c:?} {f:?}");
            }
        }
    }
}
