//! Gauss–Jacobi quadrature at MPFR precision.
//!
//! Rule for the weight $(1-u)^\alpha (1+u)^\beta$ on $(-1, 1)$, $\alpha, \beta > -1$:
//! $\int_{-1}^{1} f(u) (1-u)^\alpha (1+u)^\beta du \approx \sum_i w_i f(u_i)$, exact for
//! polynomials of degree $\le 2n - 1$.
//!
//! Method (Golub–Welsch for the start, Newton for the digits):
//! 1. the three-term recurrence of the orthonormal Jacobi polynomials
//!    $x p_k = b_{k+1} p_{k+1} + a_k p_k + b_k p_{k-1}$ with (DLMF 18.9.2, normalised)
//!    $a_k = (\beta^2-\alpha^2)/((2k+\alpha+\beta)(2k+\alpha+\beta+2))$,
//!    $b_k^2 = 4k(k+\alpha)(k+\beta)(k+\alpha+\beta)/((2k+\alpha+\beta)^2(2k+\alpha+\beta+1)(2k+\alpha+\beta-1))$,
//!    where the factor $(1+\alpha+\beta)$ is cancelled analytically in $b_1$ and $a_0 = (\beta-\alpha)/(\alpha+\beta+2)$
//!    (so that $\alpha + \beta = -1$ or $0$, the cases of docs/theory.md sections 3 and 5, are not 0/0);
//! 2. f64 eigenvalues of the Jacobi matrix (implicit QL) as initial guesses;
//! 3. Newton on $p_n$ evaluated by the recurrence at `prec + GUARD_BITS` bits, with precision
//!    doubling from the f64 start;
//! 4. Christoffel weights $w_i = \mu_0 / \sum_{k<n} p_k(u_i)^2$ ($p_0 = 1$), the sum taken from the
//!    last Newton pass by Christoffel–Darboux, $\sum_{k<n} p_k^2 = b_n p_n'(u_i) p_{n-1}(u_i)$ (DLMF 18.2.12),
//!    $\mu_0 = 2^{\alpha+\beta+1}\Gamma(\alpha+1)\Gamma(\beta+1)/\Gamma(\alpha+\beta+2)$.
//!
//! Nodes and weights are correct to about `prec` bits (tests check moments and orthogonality at
//! 64, 128 and 256 bits). Rules are cached per process, keyed exactly by
//! (alpha, beta, n, prec) (see [`gauss_jacobi`]); precision is always an argument.

use rug::ops::Pow;
use rug::{float::Constant, Assign, Float, Integer};
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

/// Extra bits carried while the nodes and weights are computed.
pub const GUARD_BITS: u32 = 32;

/// Largest number of nodes a rule may have (the f64 start and the O(n^2) Newton phase are
/// the limits; beyond this the caller should change method).
pub const MAX_NODES: usize = 4000;

/// Why a rule could not be built.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum QuadratureError {
    /// An exponent outside (-1, infinity).
    #[error("invalid Jacobi exponent {name} = {value}: must be > -1 (and finite)")]
    Exponent {
        /// "alpha" or "beta".
        name: &'static str,
        /// The value, printed.
        value: String,
    },
    /// n outside 1..=MAX_NODES.
    #[error("invalid number of nodes n = {n}: must lie in 1..={max}")]
    Nodes {
        /// Requested n.
        n: usize,
        /// MAX_NODES.
        max: usize,
    },
    /// The f64 eigenvalue start or the Newton refinement failed.
    #[error("Gauss-Jacobi rule (n = {n}) did not converge: {why}")]
    NoConvergence {
        /// Requested n.
        n: usize,
        /// What went wrong.
        why: String,
    },
}

/// A Gauss–Jacobi rule: nodes increasing in (-1, 1), positive weights, rounded to `prec` bits.
#[derive(Debug, Clone)]
pub struct GaussJacobiRule {
    /// Exponent of (1 - u).
    pub alpha: Float,
    /// Exponent of (1 + u).
    pub beta: Float,
    /// Nodes u_i, increasing.
    pub nodes: Vec<Float>,
    /// Weights w_i > 0.
    pub weights: Vec<Float>,
    /// Precision of the stored nodes and weights, in bits.
    pub prec: u32,
}

impl GaussJacobiRule {
    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }
    /// Whether the rule is empty (never, for a built rule).
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }
}

type Key = (Option<(Integer, i32)>, Option<(Integer, i32)>, usize, u32);

fn cache() -> &'static Mutex<HashMap<Key, Arc<GaussJacobiRule>>> {
    static CACHE: OnceLock<Mutex<HashMap<Key, Arc<GaussJacobiRule>>>> = OnceLock::new();
    CACHE.get_or_init(|| Mutex::new(HashMap::new()))
}

/// The n-point Gauss–Jacobi rule for $(1-u)^\alpha(1+u)^\beta$ at `prec` bits, from the process
/// cache when the same (alpha, beta, n, prec) was asked before (alpha and beta compared by their
/// exact binary values).
pub fn gauss_jacobi(alpha: &Float, beta: &Float, n: usize, prec: u32) -> Result<Arc<GaussJacobiRule>, QuadratureError> {
    let key: Key = (alpha.to_integer_exp(), beta.to_integer_exp(), n, prec);
    if let Some(r) = cache().lock().ok().and_then(|c| c.get(&key).cloned()) {
        return Ok(r);
    }
    let rule = Arc::new(gauss_jacobi_uncached(alpha, beta, n, prec)?);
    if let Ok(mut c) = cache().lock() {
        c.insert(key, rule.clone());
    }
    Ok(rule)
}

/// Empties the process cache of [`gauss_jacobi`] (it grows by one rule per distinct
/// (alpha, beta, n, prec), e.g. along a sweep in theta).
pub fn clear_cache() {
    if let Ok(mut c) = cache().lock() {
        c.clear();
    }
}

/// $\mu_0 = \int_{-1}^1 (1-u)^\alpha (1+u)^\beta du = 2^{\alpha+\beta+1}\Gamma(\alpha+1)\Gamma(\beta+1)/\Gamma(\alpha+\beta+2)$ (DLMF 5.12.1).
pub fn jacobi_mu0(alpha: &Float, beta: &Float, prec: u32) -> Float {
    let ap1 = Float::with_val(prec, alpha + 1u32);
    let bp1 = Float::with_val(prec, beta + 1u32);
    let abp2 = Float::with_val(prec, &ap1 + &bp1);
    let abp1 = Float::with_val(prec, &abp2 - 1u32);
    let two_pow = Float::with_val(prec, 2u32).pow(&abp1);
    let ga = ap1.gamma();
    let gb = bp1.gamma();
    let gab = abp2.gamma();
    two_pow * ga * gb / gab
}

/// Recurrence coefficients a_0..a_{n-1} and b_1..b_n (index k of `b` holds b_k; b_0 = 0) of the
/// orthonormal Jacobi polynomials, at `prec` bits.
fn recurrence(alpha: &Float, beta: &Float, n: usize, prec: u32) -> (Vec<Float>, Vec<Float>) {
    let ab = Float::with_val(prec, alpha + beta);
    let b2ma2 = Float::with_val(prec, beta * beta) - Float::with_val(prec, alpha * alpha);
    let mut a = Vec::with_capacity(n);
    let mut b = Vec::with_capacity(n + 1);
    b.push(Float::with_val(prec, 0));
    for k in 0..n {
        if k == 0 {
            a.push(Float::with_val(prec, beta - alpha) / Float::with_val(prec, &ab + 2u32));
        } else {
            let s = Float::with_val(prec, &ab + (2 * k) as u32);
            let d = Float::with_val(prec, &s * Float::with_val(prec, &s + 2u32));
            a.push(Float::with_val(prec, &b2ma2 / d));
        }
    }
    for k in 1..=n {
        let kf = Float::with_val(prec, k as u32);
        let s = Float::with_val(prec, &ab + (2 * k) as u32);
        let num_ab = Float::with_val(prec, alpha + &kf) * Float::with_val(prec, beta + &kf);
        let b2 = if k == 1 {
            // 4 (1+a)(1+b) / ((2+a+b)^2 (3+a+b)): the factor (1+a+b) cancelled.
            Float::with_val(prec, &num_ab * 4u32) / (Float::with_val(prec, &s * &s) * Float::with_val(prec, &s + 1u32))
        } else {
            let num = Float::with_val(prec, &num_ab * &kf) * Float::with_val(prec, &ab + &kf) * 4u32;
            let den =
                Float::with_val(prec, &s * &s) * Float::with_val(prec, &s + 1u32) * Float::with_val(prec, &s - 1u32);
            num / den
        };
        b.push(b2.sqrt());
    }
    (a, b)
}

/// Eigenvalues of the Jacobi matrix in f64 (the starting nodes), increasing; `None` if the QL
/// iteration fails or produces a non-finite value. Uses the f64 module's implicit QL.
fn tridiagonal_eigenvalues(mut d: Vec<f64>, off: &[f64]) -> Option<Vec<f64>> {
    let mut e = off.to_vec();
    e.resize(d.len(), 0.0);
    crate::numerics::gauss_jacobi_f64::tridiagonal_eigenvalues(&mut d, &mut e).ok()?;
    if d.iter().any(|x| !x.is_finite()) {
        return None;
    }
    d.sort_by(|x, y| x.partial_cmp(y).unwrap_or(std::cmp::Ordering::Equal));
    Some(d)
}

/// Scratch for the recurrence at one precision.
struct Eval {
    a: Vec<Float>,
    ib: Vec<Float>,
    b: Vec<Float>,
}

impl Eval {
    fn new(a: &[Float], b: &[Float], prec: u32) -> Self {
        Eval {
            a: a.iter().map(|x| Float::with_val(prec, x)).collect(),
            b: b.iter().map(|x| Float::with_val(prec, x)).collect(),
            ib: b
                .iter()
                .map(|x| {
                    if x.is_zero() {
                        Float::with_val(prec, 0)
                    } else {
                        Float::with_val(prec, 1u32) / Float::with_val(prec, x)
                    }
                })
                .collect(),
        }
    }

    /// p_n(x), p_n'(x), p_{n-1}(x) (p_0 = 1) and, if `want_sum`, sum_{k<n} p_k(x)^2.
    fn run(&self, x: &Float, n: usize, prec: u32, want_sum: bool) -> (Float, Float, Float, Float) {
        let mut pm = Float::with_val(prec, 0);
        let mut p = Float::with_val(prec, 1);
        let mut dpm = Float::with_val(prec, 0);
        let mut dp = Float::with_val(prec, 0);
        let mut sum = Float::with_val(prec, 0);
        let mut xa = Float::with_val(prec, 0);
        let mut t = Float::with_val(prec, 0);
        let mut dt = Float::with_val(prec, 0);
        for k in 0..n {
            if want_sum {
                sum += Float::with_val(prec, p.square_ref());
            }
            xa.assign(x - &self.a[k]);
            t.assign(&xa * &p - &self.b[k] * &pm);
            t *= &self.ib[k + 1];
            dt.assign(&xa * &dp - &self.b[k] * &dpm);
            dt += &p;
            dt *= &self.ib[k + 1];
            std::mem::swap(&mut pm, &mut p);
            std::mem::swap(&mut p, &mut t);
            std::mem::swap(&mut dpm, &mut dp);
            std::mem::swap(&mut dp, &mut dt);
        }
        (p, dp, pm, sum)
    }
}

/// The n-point rule computed afresh (no cache); see the module doc for the method.
pub fn gauss_jacobi_uncached(
    alpha: &Float,
    beta: &Float,
    n: usize,
    prec: u32,
) -> Result<GaussJacobiRule, QuadratureError> {
    for (name, v) in [("alpha", alpha), ("beta", beta)] {
        if !v.is_finite() || *v <= -1i32 {
            return Err(QuadratureError::Exponent { name, value: v.to_string() });
        }
    }
    if n == 0 || n > MAX_NODES {
        return Err(QuadratureError::Nodes { n, max: MAX_NODES });
    }
    if alpha == beta && (*alpha == 0.5f64 || *alpha == -0.5f64) {
        return Ok(chebyshev_rule(alpha, n, prec));
    }
    newton_rule(alpha, beta, n, prec)
}

/// The Gauss–Chebyshev rules in closed form (theta = 0: the weights 1/omega and omega of
/// docs/theory.md section 3), computed at `prec` + [`GUARD_BITS`] bits and rounded:
/// alpha = beta = -1/2, u_i = -cos((2i - 1) pi/(2n)), w_i = pi/n (DLMF 3.5.23); alpha = beta = 1/2,
/// u_i = -cos(i pi/(n + 1)), w_i = pi/(n + 1) sin^2(i pi/(n + 1)) (DLMF 3.5.24); i = 1..n. n cosines
/// instead of the O(n^2) Newton passes; the test `chebyshev_closed_forms_equal_newton` compares them.
fn chebyshev_rule(alpha: &Float, n: usize, prec: u32) -> GaussJacobiRule {
    let wp = prec + GUARD_BITS;
    let pi = pi(wp);
    let second_kind = *alpha > 0u32;
    let (mut nodes, mut weights) = (Vec::with_capacity(n), Vec::with_capacity(n));
    for i in 1..=n {
        let (t, w) = if second_kind {
            let t = Float::with_val(wp, &pi * i as u32) / (n + 1) as u32;
            let s2 = Float::with_val(wp, t.sin_ref()).square();
            (t, Float::with_val(wp, &pi * s2) / (n + 1) as u32)
        } else {
            let t = Float::with_val(wp, &pi * (2 * i - 1) as u32) / (2 * n) as u32;
            (t, Float::with_val(wp, &pi / n as u32))
        };
        nodes.push(Float::with_val(prec, -t.cos()));
        weights.push(Float::with_val(prec, &w));
    }
    GaussJacobiRule { alpha: alpha.clone(), beta: alpha.clone(), nodes, weights, prec }
}

/// The rule by Newton's method from the f64 eigenvalues (module doc), for any exponents.
fn newton_rule(alpha: &Float, beta: &Float, n: usize, prec: u32) -> Result<GaussJacobiRule, QuadratureError> {
    let wp = prec + GUARD_BITS + (usize::BITS - n.leading_zeros());
    let (a, b) = recurrence(alpha, beta, n, wp);
    let d64: Vec<f64> = a.iter().map(|x| x.to_f64()).collect();
    let e64: Vec<f64> = b[1..].iter().map(|x| x.to_f64()).collect();
    let start = tridiagonal_eigenvalues(d64, &e64).ok_or_else(|| QuadratureError::NoConvergence {
        n,
        why: "f64 eigenvalues (implicit QL) did not converge".into(),
    })?;

    // Precision ladder for Newton: each step roughly doubles the correct bits from ~50.
    let mut ladder = vec![];
    let mut bits = 100u32;
    while bits < wp {
        ladder.push(bits + 16);
        bits *= 2;
    }
    ladder.push(wp);
    ladder.push(wp);
    let evals: Vec<(u32, Eval)> = {
        let mut v: Vec<(u32, Eval)> = vec![];
        for &pb in &ladder {
            if !v.iter().any(|(q, _)| *q == pb) {
                v.push((pb, Eval::new(&a, &b, pb)));
            }
        }
        v
    };
    let get = |pb: u32| &evals.iter().find(|(q, _)| *q == pb).expect("ladder precision present").1;
    let mu0 = jacobi_mu0(alpha, beta, wp);
    let tol = Float::with_val(53, Float::i_exp(1, -(wp as i32) + 4));

    let mut nodes = Vec::with_capacity(n);
    let mut weights = Vec::with_capacity(n);
    for (i, &x0) in start.iter().enumerate() {
        let mut x = Float::with_val(wp, x0);
        let mut converged = false;
        // p_n' and p_{n-1} from the last full-precision pass, for the weight.
        let mut last: Option<(Float, Float)> = None;
        for (step, &pb) in ladder.iter().enumerate() {
            let xe = Float::with_val(pb, &x);
            let (p, dp, pm, _) = get(pb).run(&xe, n, pb, false);
            if dp.is_zero() || !dp.is_finite() {
                return Err(QuadratureError::NoConvergence { n, why: format!("zero derivative at node {i}") });
            }
            let dx = Float::with_val(pb, &p / &dp);
            x -= &dx;
            if step + 1 == ladder.len() {
                converged = dx.abs() <= tol;
                last = Some((dp, pm));
            }
        }
        // More steps at full precision if the last correction was not yet negligible.
        let mut extra = 0;
        while !converged && extra < 6 {
            let (p, dp, pm, _) = get(wp).run(&x, n, wp, false);
            let dx = Float::with_val(wp, &p / &dp);
            x -= &dx;
            converged = dx.abs() <= tol;
            last = Some((dp, pm));
            extra += 1;
        }
        if !converged {
            return Err(QuadratureError::NoConvergence { n, why: format!("Newton did not converge at node {i}") });
        }
        if (x.to_f64() - x0).abs() > 1e-6 + 1e-3 * (1.0 - x0 * x0) {
            return Err(QuadratureError::NoConvergence {
                n,
                why: format!("Newton drifted from its start at node {i}"),
            });
        }
        // Christoffel–Darboux at a root of p_n: sum_{k<n} p_k^2 = b_n p_n'(x) p_{n-1}(x) (evaluated
        // before the last, negligible, correction |dx| <= 2^(4 - wp)).
        let (dp, pm) = last.expect("at least one full-precision pass");
        let sum = Float::with_val(wp, &dp * &pm) * &b[n];
        if !(sum > 0u32) {
            return Err(QuadratureError::NoConvergence { n, why: format!("non-positive Christoffel sum at node {i}") });
        }
        let w = Float::with_val(wp, &mu0 / &sum);
        nodes.push(Float::with_val(prec, &x));
        weights.push(Float::with_val(prec, &w));
    }
    for i in 1..n {
        if nodes[i] <= nodes[i - 1] {
            return Err(QuadratureError::NoConvergence { n, why: format!("nodes {} and {i} not increasing", i - 1) });
        }
    }
    if nodes[0] <= -1i32 || nodes[n - 1] >= 1u32 {
        return Err(QuadratureError::NoConvergence { n, why: "a node left (-1, 1)".into() });
    }
    Ok(GaussJacobiRule { alpha: alpha.clone(), beta: beta.clone(), nodes, weights, prec })
}

/// pi at `prec` bits.
pub fn pi(prec: u32) -> Float {
    Float::with_val(prec, Constant::Pi)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Tolerance 2^(-prec + c): c = 12 covers the O(n) rounding errors of sums of n <= 100 terms
    /// of size <= 4 (|x|^k <= 1, weights sum to mu0 <= ~4).
    fn tol(prec: u32) -> Float {
        Float::with_val(prec, Float::i_exp(1, -(prec as i32) + 12))
    }

    /// J_k(theta) = int y^k / omega = pi/cos(pi theta) j_k, (n+1) j_{n+1} = n j_{n-1} - 2 theta j_n
    /// (docs/theory.md section 5), evaluated at `prec` bits.
    fn j_moments(theta: &Float, kmax: usize, prec: u32) -> Vec<Float> {
        let mut j = vec![Float::with_val(prec, 1), Float::with_val(prec, theta * -2i32)];
        for n in 1..kmax {
            let v = (Float::with_val(prec, &j[n - 1] * n as u32) - Float::with_val(prec, theta * 2u32) * &j[n])
                / (n as u32 + 1);
            j.push(v);
        }
        let c = Float::with_val(prec, pi(prec) * theta).cos();
        let f = pi(prec) / c;
        j.into_iter().map(|x| x * &f).collect()
    }

    #[test]
    fn moments_of_one_over_omega_at_several_precisions() {
        for prec in [64u32, 128, 256] {
            for (num, den) in [(0i32, 1u32), (1, 7), (-3, 10), (49, 100)] {
                let theta = Float::with_val(prec, num) / den;
                let alpha = Float::with_val(prec, &theta - 0.5f64);
                let beta = Float::with_val(prec, -Float::with_val(prec, &theta + 0.5f64));
                for n in [1usize, 5, 24] {
                    let rule = gauss_jacobi(&alpha, &beta, n, prec).unwrap();
                    let jm = j_moments(&theta, 2 * n, prec + 64);
                    for k in 0..2 * n {
                        let mut s = Float::with_val(prec + 64, 0);
                        for (x, w) in rule.nodes.iter().zip(&rule.weights) {
                            s += Float::with_val(prec + 64, (&*x).pow(k as u32)) * w;
                        }
                        let err = Float::with_val(prec, &s - &jm[k]).abs();
                        let scale = Float::with_val(prec, jm[0].abs_ref());
                        assert!(err <= tol(prec) * scale, "prec {prec} theta {num}/{den} n {n} k {k}: err {err}");
                    }
                }
            }
        }
    }

    #[test]
    fn chebyshev_closed_forms_equal_newton() {
        for prec in [64u32, 200] {
            for (a, n) in [(-0.5f64, 1usize), (-0.5, 33), (0.5, 33), (0.5, 128)] {
                let h = Float::with_val(prec, a);
                let fast = gauss_jacobi_uncached(&h, &h, n, prec).unwrap();
                let newton = newton_rule(&h, &h, n, prec).unwrap();
                for i in 0..n {
                    assert!(Float::with_val(prec, &fast.nodes[i] - &newton.nodes[i]).abs() <= tol(prec), "{a} {n} {i}");
                    let dw = Float::with_val(prec, &fast.weights[i] - &newton.weights[i]).abs();
                    assert!(dw <= Float::with_val(prec, tol(prec) * &newton.weights[i]), "{a} {n} weight {i}");
                }
            }
        }
    }

    #[test]
    fn chebyshev_closed_form() {
        // alpha = beta = -1/2: u_i = -cos((2i-1) pi/(2n)), w_i = pi/n (DLMF 3.5.23).
        for prec in [64u32, 128, 256] {
            let h = Float::with_val(prec, -0.5f64);
            let n = 17;
            let rule = gauss_jacobi(&h, &h, n, prec).unwrap();
            for i in 0..n {
                let x = -Float::with_val(prec, pi(prec) * (2 * i + 1) as u32 / (2 * n) as u32).cos();
                let w = pi(prec) / n as u32;
                assert!(Float::with_val(prec, &rule.nodes[i] - &x).abs() <= tol(prec));
                assert!(Float::with_val(prec, &rule.weights[i] - &w).abs() <= tol(prec));
            }
        }
    }

    #[test]
    fn orthonormality_for_general_exponents() {
        // sum_i w_i p_j(u_i) p_k(u_i) = mu0 delta_jk (p_0 = 1) for j + k <= 2n - 1.
        for prec in [64u32, 128, 256] {
            let alpha = Float::with_val(prec, 3u32) / 4u32;
            let beta = Float::with_val(prec, -2i32) / 3u32;
            let n = 12;
            let rule = gauss_jacobi(&alpha, &beta, n, prec).unwrap();
            let wp = prec + 64;
            let (a, b) = recurrence(&alpha, &beta, 2 * n, wp);
            let mu0 = jacobi_mu0(&alpha, &beta, wp);
            // p_k(u_i) for k < 2n.
            let vals: Vec<Vec<Float>> = rule
                .nodes
                .iter()
                .map(|x| {
                    let x = Float::with_val(wp, x);
                    let mut v = vec![Float::with_val(wp, 1)];
                    let mut pm = Float::with_val(wp, 0);
                    for k in 0..2 * n - 1 {
                        let next =
                            (Float::with_val(wp, &x - &a[k]) * &v[k] - Float::with_val(wp, &b[k] * &pm)) / &b[k + 1];
                        pm = v[k].clone();
                        v.push(next);
                    }
                    v
                })
                .collect();
            for j in 0..n {
                for k in j..(2 * n - j) {
                    let mut s = Float::with_val(wp, 0);
                    for (i, w) in rule.weights.iter().enumerate() {
                        s += Float::with_val(wp, &vals[i][j] * &vals[i][k]) * w;
                    }
                    let expect = if j == k { mu0.clone() } else { Float::with_val(wp, 0) };
                    let err = Float::with_val(prec, &s - &expect).abs();
                    assert!(err <= tol(prec) * 4u32, "prec {prec} j {j} k {k} err {err}");
                }
            }
        }
    }

    #[test]
    fn rejects_bad_input() {
        let m1 = Float::with_val(64, -1);
        let z = Float::with_val(64, 0);
        assert!(matches!(gauss_jacobi(&m1, &z, 4, 64), Err(QuadratureError::Exponent { name: "alpha", .. })));
        assert!(matches!(gauss_jacobi(&z, &z, 0, 64), Err(QuadratureError::Nodes { .. })));
    }

    #[test]
    fn cache_returns_same_rule() {
        let a = Float::with_val(128, 0.25f64);
        let r1 = gauss_jacobi(&a, &a, 9, 128).unwrap();
        let r2 = gauss_jacobi(&a, &a, 9, 128).unwrap();
        assert!(Arc::ptr_eq(&r1, &r2));
    }
}
