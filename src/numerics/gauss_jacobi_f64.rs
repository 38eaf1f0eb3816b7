//! Gauss–Jacobi quadrature in `f64` for the weight (1-u)^alpha (1+u)^beta on (-1, 1).
//!
//! Method (Golub & Welsch 1969, with the eigenvector step replaced by Christoffel sums):
//! 1. the nodes are the eigenvalues of the symmetric tridiagonal Jacobi matrix of the monic
//!    Jacobi recurrence (DLMF 18.9.2 rewritten for monic polynomials, Gautschi 2004, Table 1.1),
//!    found by the implicit QL method without eigenvectors (O(n^2));
//! 2. each node is polished by one Newton step on the orthonormal polynomial p_n;
//! 3. the weights are the Christoffel numbers W_k = 1 / sum_{j<n} p_j(u_k)^2 with the orthonormal
//!    p_j (Gautschi 2004, eq. (1.4.9)); unlike mu0 v_{0k}^2 from eigenvectors this keeps the
//!    relative accuracy of the tiny weights near the ends.
//!
//! The mass mu0 = int (1-u)^alpha (1+u)^beta du = 2^{alpha+beta+1} Gamma(alpha+1) Gamma(beta+1) /
//! Gamma(alpha+beta+2) is evaluated in closed form by the reflection formula when alpha + beta is
//! -1, 0 or 1 (the cases of docs/theory.md section 3: omega and 1/omega), otherwise by a Lanczos Gamma
//! (relative error ~ 1e-15).
//!
//! Companion rules for the singular integral equation of Problem 1 (docs/theory.md section 3):
//! with omega(u) = (1+u)^{1/2+theta} (1-u)^{1/2-theta} (Jacobi alpha = 1/2 - theta,
//! beta = 1/2 + theta) the dominant operator S\[f\] = tan(pi theta) f + (1/pi) PV int f(u')/(u - u') du'
//! maps omega P_n^{(alpha,beta)} onto a multiple of P_{n+1}^{(-alpha,-beta)} (Erdogan, Gupta & Cook
//! 1973; for n = 0 see [`omega_cauchy_exterior`]), so the collocation points are the n + 1 zeros of
//! P_{n+1}^{(-alpha,-beta)}: the nodes of the Gauss–Jacobi rule of the conjugate weight 1/omega.
//! [`sliding_rules`] returns both.

use std::f64::consts::PI;

/// A Gauss quadrature rule: `sum_k weights[k] f(nodes[k]) ~ int f(u) w(u) du`, nodes ascending.
#[derive(Debug, Clone, PartialEq)]
pub struct GaussRule {
    /// Nodes in (-1, 1), ascending.
    pub nodes: Vec<f64>,
    /// Positive weights, same order as `nodes`.
    pub weights: Vec<f64>,
}

/// Why a rule could not be built.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum QuadratureError {
    /// A Jacobi exponent outside (-1, infinity) or not finite.
    #[error("invalid Jacobi exponent {parameter} = {value}: must be finite and > -1")]
    InvalidExponent {
        /// "alpha" or "beta".
        parameter: &'static str,
        /// The value given.
        value: f64,
    },
    /// Zero nodes requested.
    #[error("invalid number of nodes n = 0: must be >= 1")]
    NoNodes,
    /// The QL iteration did not converge (not observed in practice).
    #[error("tridiagonal QL iteration did not converge for n = {n}")]
    NoConvergence {
        /// Number of nodes requested.
        n: usize,
    },
}

/// Monic Jacobi recurrence coefficients: p_{k+1} = (u - a_k) p_k - b_k p_{k-1}, k = 0..n-1,
/// b_0 = mu0 (Gautschi 2004, Table 1.1). Returns (a, b) with `b[0]` = mu0.
pub(crate) fn jacobi_recurrence(n: usize, alpha: f64, beta: f64) -> (Vec<f64>, Vec<f64>) {
    let s = alpha + beta;
    let mut a = Vec::with_capacity(n);
    let mut b = Vec::with_capacity(n);
    for k in 0..n {
        let kf = k as f64;
        let t = 2.0 * kf + s;
        // a_0 = (beta - alpha)/(s + 2): the general formula is 0/0 at s = 0.
        a.push(if k == 0 { (beta - alpha) / (s + 2.0) } else { (beta - alpha) * (beta + alpha) / (t * (t + 2.0)) });
        b.push(match k {
            0 => jacobi_mass(alpha, beta),
            // b_1 with the factor (1 + s) cancelled (0/0 at s = -1).
            1 => 4.0 * (1.0 + alpha) * (1.0 + beta) / ((2.0 + s) * (2.0 + s) * (3.0 + s)),
            _ => 4.0 * kf * (kf + alpha) * (kf + beta) * (kf + s) / (t * t * (t + 1.0) * (t - 1.0)),
        });
    }
    (a, b)
}

/// mu0 = int_{-1}^{1} (1-u)^alpha (1+u)^beta du = 2^{s+1} Gamma(alpha+1) Gamma(beta+1)/Gamma(s+2),
/// s = alpha + beta (DLMF 5.12.1 in the variable (1+u)/2).
///
/// Closed forms by the reflection formula Gamma(z) Gamma(1-z) = pi/sin(pi z) (DLMF 5.5.3):
/// s = 1: 2 pi alpha (1 - alpha)/sin(pi alpha); s = 0: 2 pi alpha / sin(pi alpha); s = -1: pi / sin(pi (alpha + 1)).
/// With alpha = 1/2 - theta, s = 1: mu0 = pi (1/2 - 2 theta^2)/cos(pi theta); s = -1 (1/omega):
/// mu0 = pi/cos(pi theta) = J_0 (docs/theory.md [3.5]).
pub(crate) fn jacobi_mass(alpha: f64, beta: f64) -> f64 {
    let s = alpha + beta;
    let sinc_pi = |z: f64| {
        if z == 0.0 {
            1.0
        } else {
            (PI * z).sin() / (PI * z)
        }
    };
    // alpha + beta formed in f64 (e.g. (1/2 - theta) + (1/2 + theta)) may miss the integer by an
    // ulp: accept 4 ulps.
    let near = |v: f64| (s - v).abs() <= 4.0 * f64::EPSILON;
    if near(1.0) {
        // 4 Gamma(1+alpha) Gamma(2-alpha)/Gamma(3) = 2 alpha (1-alpha) Gamma(alpha) Gamma(1-alpha)
        //   = 2 (1 - alpha) pi alpha / sin(pi alpha) = 2 (1 - alpha) / sinc_pi(alpha).
        2.0 * (1.0 - alpha) / sinc_pi(alpha)
    } else if near(0.0) {
        // 2 Gamma(1+alpha) Gamma(1-alpha) = 2 pi alpha / sin(pi alpha).
        2.0 / sinc_pi(alpha)
    } else if near(-1.0) {
        // Gamma(1+alpha) Gamma(-alpha) = Gamma(z) Gamma(1-z), z = 1 + alpha.
        PI / (PI * (1.0 + alpha)).sin()
    } else {
        (2f64.ln() * (s + 1.0) + ln_gamma(alpha + 1.0) + ln_gamma(beta + 1.0) - ln_gamma(s + 2.0)).exp()
    }
}

/// ln Gamma(x) for x > 0: Lanczos approximation g = 7, 9 terms (Numerical Recipes 3rd ed. 6.1),
/// relative error of Gamma about 1e-15.
fn ln_gamma(x: f64) -> f64 {
    const G: f64 = 7.0;
    const C: [f64; 9] = [
        0.999_999_999_999_809_93,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_13,
        -176.615_029_162_140_59,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_571_6e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if x < 0.5 {
        // Reflection (DLMF 5.5.3).
        return (PI / (PI * x).sin()).ln() - ln_gamma(1.0 - x);
    }
    let x = x - 1.0;
    let mut acc = C[0];
    for (i, c) in C.iter().enumerate().skip(1) {
        acc += c / (x + i as f64);
    }
    let t = x + G + 0.5;
    0.5 * (2.0 * PI).ln() + (x + 0.5) * t.ln() - t + acc.ln()
}

/// The n-point Gauss–Jacobi rule for (1-u)^alpha (1+u)^beta, alpha, beta > -1.
/// Exact for polynomials of degree <= 2n - 1.
pub fn gauss_jacobi(n: usize, alpha: f64, beta: f64) -> Result<GaussRule, QuadratureError> {
    if !(alpha.is_finite() && alpha > -1.0) {
        return Err(QuadratureError::InvalidExponent { parameter: "alpha", value: alpha });
    }
    if !(beta.is_finite() && beta > -1.0) {
        return Err(QuadratureError::InvalidExponent { parameter: "beta", value: beta });
    }
    if n == 0 {
        return Err(QuadratureError::NoNodes);
    }
    if alpha == beta && alpha.abs() == 0.5 {
        return Ok(chebyshev_rule(n, alpha > 0.0));
    }
    gauss_jacobi_general(n, alpha, beta)
}

/// The Gauss–Chebyshev rules in closed form (theta = 0 in docs/theory.md section 3: the weights
/// 1/omega and omega): alpha = beta = -1/2, u_i = -cos((2i - 1) pi/(2n)), W_i = pi/n (DLMF 3.5.23);
/// alpha = beta = 1/2, u_i = -cos(i pi/(n + 1)), W_i = pi/(n + 1) sin^2(i pi/(n + 1)) (DLMF 3.5.24),
/// i = 1..n, ascending. O(n) instead of the O(n^2) eigenvalue route; the test
/// `chebyshev_closed_forms_equal_the_general_route` compares the two.
fn chebyshev_rule(n: usize, second_kind: bool) -> GaussRule {
    let (mut nodes, mut weights) = (Vec::with_capacity(n), Vec::with_capacity(n));
    for i in 1..=n {
        if second_kind {
            let t = i as f64 * PI / (n + 1) as f64;
            nodes.push(-t.cos());
            weights.push(PI / (n + 1) as f64 * t.sin().powi(2));
        } else {
            nodes.push(-((2 * i - 1) as f64 * PI / (2 * n) as f64).cos());
            weights.push(PI / n as f64);
        }
    }
    GaussRule { nodes, weights }
}

/// [`gauss_jacobi`] by the eigenvalues of the Jacobi matrix (module doc), for any exponents.
fn gauss_jacobi_general(n: usize, alpha: f64, beta: f64) -> Result<GaussRule, QuadratureError> {
    let (a, b) = jacobi_recurrence(n, alpha, beta);
    let mut d = a.clone();
    let mut e: Vec<f64> = (0..n).map(|k| if k + 1 < n { b[k + 1].sqrt() } else { 0.0 }).collect();
    tridiagonal_eigenvalues(&mut d, &mut e).map_err(|_| QuadratureError::NoConvergence { n })?;
    d.sort_by(|x, y| x.total_cmp(y));
    let sq: Vec<f64> = b.iter().map(|v| v.sqrt()).collect();
    let mut weights = vec![0.0; n];
    // LANES nodes at a time (the last chunk padded with the last node): the recurrences of
    // different nodes are independent chains, each with the operations of `orthonormal_eval`
    // alone (the same bits: test `lanes_equal_one_node_at_a_time`).
    for c in (0..n).step_by(LANES) {
        let mut x: [f64; LANES] = std::array::from_fn(|l| d[(c + l).min(n - 1)]);
        // One Newton step on the orthonormal p_n (its zeros are the nodes).
        let values = orthonormal_eval_lanes(&a, &sq, x);
        for (xl, (pn, dpn, _)) in x.iter_mut().zip(values) {
            if dpn != 0.0 {
                let step = pn / dpn;
                if step.abs() < 1e-6 {
                    *xl -= step;
                }
            }
        }
        let sums = orthonormal_eval_lanes(&a, &sq, x);
        for l in 0..LANES.min(n - c) {
            d[c + l] = x[l];
            weights[c + l] = 1.0 / sums[l].2;
        }
    }
    Ok(GaussRule { nodes: d, weights })
}

/// Nodes evaluated side by side by [`orthonormal_eval_lanes`].
const LANES: usize = 4;

/// [`orthonormal_eval`] at LANES points at once, each lane with exactly its operations (the
/// core overlaps the independent divisions; the rules of several hundred nodes of the MPFR
/// solver's load scan spent a third of their time here, `perf record` of `solve
/// scenes/sinusoid_friction.toml --method mpfr`).
fn orthonormal_eval_lanes(a: &[f64], sq: &[f64], x: [f64; LANES]) -> [(f64, f64, f64); LANES] {
    let n = a.len();
    let (mut p_prev, mut p) = ([0.0; LANES], [1.0 / sq[0]; LANES]);
    let (mut d_prev, mut d) = ([0.0; LANES], [0.0; LANES]);
    let mut sum = [0.0; LANES];
    for j in 0..n {
        let bj = if j == 0 { 0.0 } else { sq[j] };
        let bnext = if j + 1 < n { sq[j + 1] } else { 1.0 };
        for l in 0..LANES {
            sum[l] += p[l] * p[l];
            let p_next = ((x[l] - a[j]) * p[l] - bj * p_prev[l]) / bnext;
            let d_next = (p[l] + (x[l] - a[j]) * d[l] - bj * d_prev[l]) / bnext;
            p_prev[l] = p[l];
            p[l] = p_next;
            d_prev[l] = d[l];
            d[l] = d_next;
        }
    }
    std::array::from_fn(|l| (p[l], d[l], sum[l]))
}

/// Evaluates the orthonormal p_n(x), p_n'(x) and sum_{j<n} p_j(x)^2 by the three-term
/// recurrence sqrt(b_{j+1}) p_{j+1} = (x - a_j) p_j - sqrt(b_j) p_{j-1}, p_0 = 1/sqrt(mu0): one
/// point (the reference of the test of [`orthonormal_eval_lanes`], which the rules use).
#[cfg(test)]
fn orthonormal_eval(a: &[f64], sq: &[f64], x: f64) -> (f64, f64, f64) {
    let n = a.len();
    let (mut p_prev, mut p) = (0.0, 1.0 / sq[0]);
    let (mut d_prev, mut d) = (0.0, 0.0);
    let mut sum = 0.0;
    for j in 0..n {
        sum += p * p;
        let bj = if j == 0 { 0.0 } else { sq[j] };
        // sqrt(b_{j+1}) for j = n - 1: use the next coefficient implied by the recurrence; only
        // the zero of p_n matters, so any positive normaliser works there.
        let bnext = if j + 1 < n { sq[j + 1] } else { 1.0 };
        let p_next = ((x - a[j]) * p - bj * p_prev) / bnext;
        let d_next = (p + (x - a[j]) * d - bj * d_prev) / bnext;
        p_prev = p;
        p = p_next;
        d_prev = d;
        d = d_next;
    }
    (p, d, sum)
}

/// Eigenvalues of the symmetric tridiagonal matrix with diagonal `d` and off-diagonal
/// `e[0..n-1]` (`e[n-1]` ignored): implicit QL with Wilkinson shifts (Numerical Recipes 11.4,
/// `tqli` without eigenvectors). The eigenvalues overwrite `d`, unsorted. Meant for Jacobi
/// matrices (entries of size <= 1): rotations use sqrt(f^2 + g^2), not hypot.
pub(crate) fn tridiagonal_eigenvalues(d: &mut [f64], e: &mut [f64]) -> Result<(), ()> {
    let n = d.len();
    if n == 0 {
        return Ok(());
    }
    e[n - 1] = 0.0;
    for l in 0..n {
        let mut iter = 0;
        loop {
            let mut m = l;
            while m + 1 < n {
                let dd = d[m].abs() + d[m + 1].abs();
                if e[m].abs() <= f64::EPSILON * 0.5 * dd {
                    break;
                }
                m += 1;
            }
            if m == l {
                break;
            }
            iter += 1;
            if iter > 100 {
                return Err(());
            }
            let mut g = (d[l + 1] - d[l]) / (2.0 * e[l]);
            // sqrt instead of hypot (hypot dominated the run time): the entries are O(1) here;
            // a huge g (tiny e[l]) overflows g*g to inf, which yields the correct limit below.
            let mut r = (g * g + 1.0).sqrt();
            g = d[m] - d[l] + e[l] / (g + r.copysign(g));
            let (mut s, mut c, mut p) = (1.0, 1.0, 0.0);
            let mut i = m;
            let mut deflated = false;
            while i > l {
                i -= 1;
                let f = s * e[i];
                let b = c * e[i];
                r = (f * f + g * g).sqrt();
                e[i + 1] = r;
                if r == 0.0 {
                    d[i + 1] -= p;
                    e[m] = 0.0;
                    deflated = true;
                    break;
                }
                s = f / r;
                c = g / r;
                g = d[i + 1] - p;
                r = (d[i] - g) * s + 2.0 * c * b;
                p = s * r;
                d[i + 1] = g + p;
                g = c * r - b;
            }
            if deflated {
                continue;
            }
            d[l] -= p;
            e[l] = g;
            e[m] = 0.0;
        }
    }
    Ok(())
}

/// The two rules of the Gauss–Jacobi collocation of Problem 1 (docs/theory.md section 3), for
/// omega(u) = (1+u)^{1/2+theta} (1-u)^{1/2-theta}, |theta| < 1/2:
/// `.0` the n-point rule of omega (alpha = 1/2 - theta, beta = 1/2 + theta; unknowns at its
/// nodes), `.1` the (n+1)-point rule of 1/omega (alpha = theta - 1/2, beta = -theta - 1/2); its
/// nodes, the zeros of P_{n+1}^{(-alpha,-beta)}, are the collocation points.
pub fn sliding_rules(n: usize, theta: f64) -> Result<(GaussRule, GaussRule), QuadratureError> {
    let alpha = 0.5 - theta;
    let beta = 0.5 + theta;
    Ok((gauss_jacobi(n, alpha, beta)?, gauss_jacobi(n + 1, -alpha, -beta)?))
}

/// (1/pi) int_{-1}^{1} omega(t)/(u - t) dt for real |u| > 1, omega as in [`sliding_rules`]:
/// (u + 2 theta - X(u)) / cos(pi theta), X(z) = (z-1)^{1/2-theta} (z+1)^{1/2+theta} (principal
/// branches, X ~ z + 2 theta at infinity; docs/theory.md section 3). For u < -1, X(u) =
/// -(1-u)^{1/2-theta} (-1-u)^{1/2+theta}. Derived from the Sokhotski–Plemelj formula applied to
/// X(z) - z - 2 theta = O(1/z), whose jump across (-1, 1) is 2 i cos(pi theta) omega.
/// On the cut the principal value is (u + 2 theta - omega(u) sin(pi theta))/cos(pi theta), so
/// tan(pi theta) omega + (1/pi) PV int omega/(u - t) = (u + 2 theta)/cos(pi theta): the case
/// n = 0 of the collocation identity (a multiple of P_1^{(-alpha,-beta)}, zero at u = -2 theta).
pub fn omega_cauchy_exterior(u: f64, theta: f64) -> f64 {
    let alpha = 0.5 - theta;
    let beta = 0.5 + theta;
    let x = if u > 0.0 {
        (u - 1.0).powf(alpha) * (u + 1.0).powf(beta)
    } else {
        -(1.0 - u).powf(alpha) * (-1.0 - u).powf(beta)
    };
    (u + 2.0 * theta - x) / (PI * theta).cos()
}

/// omega(u) = (1+u)^{1/2+theta} (1-u)^{1/2-theta} (docs/theory.md section 2), 0 outside [-1, 1].
pub fn omega(u: f64, theta: f64) -> f64 {
    if u <= -1.0 || u >= 1.0 {
        0.0
    } else {
        (1.0 + u).powf(0.5 + theta) * (1.0 - u).powf(0.5 - theta)
    }
}

/// The exterior weight X(u) of [`omega_cauchy_exterior`] for real |u| >= 1: X(u) =
/// sqrt((u - 1)(u + 1)) ((u + 1)/(u - 1))^theta = (u - 1)^{1/2-theta} (u + 1)^{1/2+theta} for
/// u >= 1, and -sqrt((u - 1)(u + 1)) ((-1 - u)/(1 - u))^theta = -(1 - u)^{1/2-theta}
/// (-1 - u)^{1/2+theta} for u <= -1 (omega's factors continued across each end, real on each
/// side, with the sign of u). The logarithms of the ratios are ln1p(2/(u - 1)) and
/// -ln1p(2/(-1 - u)) (the differences exact near the ends, no cancellation in 1 + x): one square
/// root, logarithm and exponential instead of two powers (test `omega_forms_agree`). Off the
/// contact of Problem 1 the gap's slope is this weight times the pressure factor's continuation
/// (`sliding::collocation_f64`'s `physical.rs`). At the ends u = +-1 it is 0, the limit for
/// |theta| < 1/2 (the form above would give 0 times infinity there for one sign of theta: issue
/// 34, a gap sample that the rounding of the contact's ends, far off the origin, put on the end).
pub fn omega_exterior(u: f64, theta: f64) -> f64 {
    let root = ((u - 1.0) * (u + 1.0)).sqrt();
    if root == 0.0 {
        return 0.0;
    }
    if u > 0.0 {
        root * (theta * (2.0 / (u - 1.0)).ln_1p()).exp()
    } else {
        -root * (-theta * (2.0 / (-1.0 - u)).ln_1p()).exp()
    }
}

/// Barycentric weights for interpolation in the nodes of a Gauss–Jacobi rule:
/// v_k = (-1)^k sqrt((1 - u_k^2) W_k) (Wang, Huybrechs & Vandewalle, Math. Comp. 83 (2014),
/// Theorem 3.1), nodes ascending; any common factor cancels in the second barycentric form.
pub fn barycentric_weights(rule: &GaussRule) -> Vec<f64> {
    rule.nodes
        .iter()
        .zip(&rule.weights)
        .enumerate()
        .map(|(k, (u, w))| {
            let v = ((1.0 - u * u) * w).sqrt();
            if k % 2 == 0 {
                v
            } else {
                -v
            }
        })
        .collect()
}

/// Evaluates at `x` the polynomial of degree < n with values `f` at `nodes`, by the second
/// (true) barycentric formula (Berrut & Trefethen, SIAM Rev. 46 (2004), eq. (4.2)).
pub fn barycentric_eval(nodes: &[f64], bary: &[f64], f: &[f64], x: f64) -> f64 {
    let mut num = 0.0;
    let mut den = 0.0;
    for k in 0..nodes.len() {
        let d = x - nodes[k];
        if d == 0.0 {
            return f[k];
        }
        let t = bary[k] / d;
        num += t * f[k];
        den += t;
    }
    num / den
}

#[cfg(test)]
mod tests {

    #[test]
    fn chebyshev_closed_forms_equal_the_general_route() {
        for (alpha, n) in [(-0.5, 1), (-0.5, 17), (0.5, 17), (-0.5, 200), (0.5, 200)] {
            let fast = gauss_jacobi(n, alpha, alpha).unwrap();
            let general = gauss_jacobi_general(n, alpha, alpha).unwrap();
            for i in 0..n {
                assert!((fast.nodes[i] - general.nodes[i]).abs() < 1e-14, "alpha {alpha} n {n} node {i}");
                // The general route's Christoffel sums carry ~1e-12 relative at n = 200 (pi/200:
                // 0.015707963267948967 in closed form, ...933313 by the general route).
                let w = general.weights[i];
                assert!(
                    (fast.weights[i] - w).abs() < 1e-11 * w.max(1e-300),
                    "alpha {alpha} n {n} weight {i}: {} vs {w}",
                    fast.weights[i]
                );
            }
        }
    }

    use super::*;

    /// J_n(theta) = int y^n / omega = (pi/cos(pi theta)) j_n, j_0 = 1, j_1 = -2 theta,
    /// (n+1) j_{n+1} = n j_{n-1} - 2 theta j_n (docs/theory.md [3.5]).
    fn j_moments(theta: f64, count: usize) -> Vec<f64> {
        let mut j = vec![1.0, -2.0 * theta];
        for n in 1..count {
            let nf = n as f64;
            let next = (nf * j[n - 1] - 2.0 * theta * j[n]) / (nf + 1.0);
            j.push(next);
        }
        let f = PI / (PI * theta).cos();
        j.iter().take(count).map(|v| v * f).collect()
    }

    #[test]
    fn omega_forms_agree() {
        for theta in [-0.49, -0.3, -0.027, 0.0, 0.1, 0.45] {
            let sec = 1.0 / (PI * theta).cos();
            for k in 0..=400 {
                for v in [1.0 + k as f64 / 200.0 + 1e-13, -(1.0 + k as f64 / 200.0 + 1e-13)] {
                    let d = (v + 2.0 * theta - omega_exterior(v, theta)) * sec;
                    let c = omega_cauchy_exterior(v, theta);
                    // Both forms cancel u + 2 theta against X(u) alike; compare on the scale of
                    // the terms, (|u| + 1) sec(pi theta).
                    let scale = (v.abs() + 1.0) * sec;
                    assert!((c - d).abs() <= 16.0 * f64::EPSILON * scale, "exterior theta {theta} u {v}: {c} vs {d}");
                }
            }
        }
    }

    /// At the ends X(+-1) = 0 for either sign of theta (the form's 0 times infinity for one of
    /// them gave NaN), and next to them X is finite and below 1 (|X| = d^(1/2 -+ theta) (2 +
    /// d)^(1/2 +- theta) at a distance d: 0.48 at d = 1e-12 and theta = 0.45).
    #[test]
    fn the_exterior_weight_vanishes_at_the_ends() {
        for theta in [-0.45, -0.05, 0.0, 0.05, 0.45] {
            for u in [1.0, -1.0] {
                assert_eq!(omega_exterior(u, theta), 0.0, "theta {theta} u {u}");
                let near = omega_exterior(u * (1.0 + 1e-12), theta);
                assert!(near.is_finite() && near.abs() < 1.0, "theta {theta} u {u}: {near}");
            }
        }
    }

    #[test]
    fn conjugate_weight_moments_match_recurrence() {
        for &theta in &[0.0, 0.1, -0.23, 0.37, -0.45, 0.49] {
            for &n in &[1usize, 5, 20, 60] {
                let rule = gauss_jacobi(n, theta - 0.5, -theta - 0.5).unwrap();
                let jm = j_moments(theta, 2 * n);
                for (m, exact) in jm.iter().enumerate() {
                    let q: f64 = rule.nodes.iter().zip(&rule.weights).map(|(u, w)| w * u.powi(m as i32)).sum();
                    // Tolerance: a few ulps of J_0 times the number of terms summed (C = 8).
                    let tol = 8.0 * f64::EPSILON * jm[0] * (n as f64).max(4.0);
                    assert!((q - exact).abs() <= tol, "theta {theta} n {n} m {m}: {q} vs {exact}");
                }
            }
        }
    }

    #[test]
    fn omega_moments_match_recurrence() {
        // omega_theta = (1 - y^2)/omega_{-theta}, so int y^m omega_theta = J_m(-theta) - J_{m+2}(-theta).
        for &theta in &[0.0, 0.17, -0.31, 0.44] {
            for &n in &[1usize, 7, 40] {
                let rule = gauss_jacobi(n, 0.5 - theta, 0.5 + theta).unwrap();
                let jm = j_moments(-theta, 2 * n + 2);
                for m in 0..2 * n {
                    let exact = jm[m] - jm[m + 2];
                    let q: f64 = rule.nodes.iter().zip(&rule.weights).map(|(u, w)| w * u.powi(m as i32)).sum();
                    let tol = 8.0 * f64::EPSILON * jm[0] * (n as f64).max(4.0);
                    assert!((q - exact).abs() <= tol, "theta {theta} n {n} m {m}: {q} vs {exact}");
                }
            }
        }
    }

    #[test]
    fn legendre_and_generic_exponents() {
        // Gauss–Legendre, n = 2: nodes +-1/sqrt(3), weights 1.
        let r = gauss_jacobi(2, 0.0, 0.0).unwrap();
        assert!((r.nodes[1] - 1.0 / 3f64.sqrt()).abs() < 4e-16);
        assert!((r.weights[0] - 1.0).abs() < 4e-16);
        // Generic exponents: int (1-u)^0.3 (1+u)^1.7 du = 2^3 Gamma(1.3) Gamma(2.7)/Gamma(4);
        // Gamma(1.3) = 0.8974706963062774, Gamma(2.7) = 1.5446858458505939 (Python math.gamma).
        let exact = 8.0 * 0.897_470_696_306_277_4 * 1.544_685_845_850_593_9 / 6.0;
        let r = gauss_jacobi(9, 0.3, 1.7).unwrap();
        let s: f64 = r.weights.iter().sum();
        assert!((s / exact - 1.0).abs() < 1e-14, "{s} vs {exact}");
    }

    #[test]
    fn collocation_points_are_zeros_of_the_dominant_image() {
        // n = 0 identity: S[omega] = (u + 2 theta)/cos(pi theta), whose zero -2 theta is the
        // single node of the 1-point rule of 1/omega (mean of 1/omega = J_1/J_0 = -2 theta).
        for &theta in &[0.0, 0.2, -0.4] {
            let conj = gauss_jacobi(1, theta - 0.5, -theta - 0.5).unwrap();
            assert!((conj.nodes[0] + 2.0 * theta).abs() < 1e-15);
        }
        // Exterior Cauchy transform vs. a direct quadrature at u = 1.5.
        let theta = 0.3;
        let r = gauss_jacobi(80, 0.5 - theta, 0.5 + theta).unwrap();
        let u = 1.5;
        let q: f64 = r.nodes.iter().zip(&r.weights).map(|(t, w)| w / (u - t)).sum::<f64>() / PI;
        assert!((q - omega_cauchy_exterior(u, theta)).abs() < 1e-14);
        let u = -2.5;
        let q: f64 = r.nodes.iter().zip(&r.weights).map(|(t, w)| w / (u - t)).sum::<f64>() / PI;
        assert!((q - omega_cauchy_exterior(u, theta)).abs() < 1e-14);
    }

    #[test]
    fn lanes_equal_one_node_at_a_time() {
        // The rule by lanes against the former loop, one node at a time: the same bits.
        for (n, alpha, beta) in [(1usize, -0.3, 0.2), (5, -0.545, -0.455), (7, 0.3, 1.7), (192, -0.545, -0.455)] {
            let rule = gauss_jacobi_general(n, alpha, beta).unwrap();
            let (a, b) = jacobi_recurrence(n, alpha, beta);
            let mut d = a.clone();
            let mut e: Vec<f64> = (0..n).map(|k| if k + 1 < n { b[k + 1].sqrt() } else { 0.0 }).collect();
            tridiagonal_eigenvalues(&mut d, &mut e).unwrap();
            d.sort_by(|x, y| x.total_cmp(y));
            let sq: Vec<f64> = b.iter().map(|v| v.sqrt()).collect();
            for (i, x) in d.iter_mut().enumerate() {
                let (pn, dpn, _) = orthonormal_eval(&a, &sq, *x);
                if dpn != 0.0 && (pn / dpn).abs() < 1e-6 {
                    *x -= pn / dpn;
                }
                let (_, _, sum_sq) = orthonormal_eval(&a, &sq, *x);
                assert_eq!(rule.nodes[i].to_bits(), x.to_bits(), "n {n} node {i}");
                assert_eq!(rule.weights[i].to_bits(), (1.0 / sum_sq).to_bits(), "n {n} weight {i}");
            }
        }
    }

    #[test]
    fn barycentric_interpolation_is_exact_for_polynomials() {
        let r = gauss_jacobi(12, 0.2, 0.8).unwrap();
        let v = barycentric_weights(&r);
        let poly = |x: f64| 1.0 - 2.0 * x + 0.5 * x.powi(5) - x.powi(11);
        let f: Vec<f64> = r.nodes.iter().map(|&x| poly(x)).collect();
        for &x in &[-1.0, -0.77, 0.0, 0.33, 1.0] {
            assert!((barycentric_eval(&r.nodes, &v, &f, x) - poly(x)).abs() < 1e-13);
        }
    }
}
