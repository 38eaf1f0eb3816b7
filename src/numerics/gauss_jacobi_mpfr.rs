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
//! 3. Newton on $p_n$ evaluated by the recurrence (values only) at `prec + GUARD_BITS` bits, with
//!    precision doubling from the f64 start: a first pass in double-double arithmetic (about 100
//!    bits, `Dd`), then MPFR; the derivative from $p_n$ and $p_{n-1}$ by the structure relation
//!    $(1-x^2) p_n'(x) = n\,((\alpha-\beta)/(2n+\alpha+\beta) - x)\, p_n(x) + (2n+\alpha+\beta+1)\, b_n\, p_{n-1}(x)$
//!    (derived in `Eval::run`; half the operations of differentiating the recurrence, issue 14);
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

/// Largest first rung of the Newton ladder done in double-double arithmetic (`Dd`, 106 bits, of
/// which the recurrence's rounding leaves about 100).
const DD_BITS: u32 = 116;

/// Largest precision whose rules are computed wholly in double-double (`double_double::dd_rule`); the
/// locating stage of `sliding::reduction_mpfr` works at 64 bits.
const DD_ONLY_PREC: u32 = 64;

mod double_double;
mod recurrence_eval;
use double_double::{Dd, EvalDd, LANES};
use recurrence_eval::Eval;

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

/// (alpha, beta) by their exact binary values, n, prec, and whether the rule is the f64 one lifted
/// ([`gauss_jacobi_f64_lifted`]) rather than computed at `prec` ([`gauss_jacobi`]).
type Key = (Option<(Integer, i32)>, Option<(Integer, i32)>, usize, u32, bool);

/// The process cache of rules: thread-safe (one mutex, held only to look up and insert: two
/// threads asking one new rule may both build it, the same bits, and one copy is kept) and bounded
/// by [`CACHE_BITS`] (issue 34): a long run over many distinct (alpha, beta), such as a sweep in
/// theta or the differential fuzzer, empties it when the next rule would pass the bound.
struct Cache {
    rules: HashMap<Key, Arc<GaussJacobiRule>>,
    /// Mantissa bits held: sum over the rules of 2 n prec.
    bits: u64,
}

/// Most mantissa bits the cache holds: 2^30 (128 MiB), e.g. 120 rules of 3000 nodes at 1500 bits,
/// or every rule of a verified 30-digit solve many times over.
pub const CACHE_BITS: u64 = 1 << 30;

fn cache() -> &'static Mutex<Cache> {
    static CACHE: OnceLock<Mutex<Cache>> = OnceLock::new();
    CACHE.get_or_init(|| Mutex::new(Cache { rules: HashMap::new(), bits: 0 }))
}

/// The mantissa bits of a rule (nodes and weights).
fn rule_bits(r: &GaussJacobiRule) -> u64 {
    2 * r.nodes.len() as u64 * u64::from(r.prec)
}

/// Rules and mantissa bits the process cache holds now (for tests of its bound).
pub fn cache_size() -> (usize, u64) {
    cache().lock().map_or((0, 0), |c| (c.rules.len(), c.bits))
}

/// The n-point Gauss–Jacobi rule for $(1-u)^\alpha(1+u)^\beta$ at `prec` bits, from the process
/// cache when the same (alpha, beta, n, prec) was asked before (alpha and beta compared by their
/// exact binary values).
///
/// When the cache holds the lifted f64 rule of the same key ([`gauss_jacobi_f64_lifted`], e.g. the
/// sinusoid's load scan at the locating precision), its nodes start Newton's method instead of the
/// QL eigenvalues (both about 16 digits; the same rule, bit for bit: test
/// `f64_rule_start_gives_the_same_rule`); this saves the 192-node QL of a cold solve of
/// `scenes/sinusoid_friction.toml`.
pub fn gauss_jacobi(alpha: &Float, beta: &Float, n: usize, prec: u32) -> Result<Arc<GaussJacobiRule>, QuadratureError> {
    let (ka, kb) = (alpha.to_integer_exp(), beta.to_integer_exp());
    let lifted = (ka.clone(), kb.clone(), n, prec, true);
    cached((ka, kb, n, prec, false), || {
        let start = cache().lock().ok().and_then(|c| c.rules.get(&lifted).cloned());
        uncached_from(alpha, beta, n, prec, start.map(|r| r.nodes.iter().map(Float::to_f64).collect()))
    })
}

/// The n-point rule of [`crate::numerics::gauss_jacobi_f64::gauss_jacobi`] (alpha and beta rounded
/// to f64; about 15 correct digits) with its nodes and weights rounded to `prec` bits, from the
/// same process cache as [`gauss_jacobi`] (so [`clear_cache`] empties both): for computations
/// that need only signs, where the MPFR rule's O(n^2) Newton passes would dominate (the sinusoid's
/// load-curve scan, `sliding::reduction_mpfr`).
pub fn gauss_jacobi_f64_lifted(
    alpha: &Float,
    beta: &Float,
    n: usize,
    prec: u32,
) -> Result<Arc<GaussJacobiRule>, crate::numerics::gauss_jacobi_f64::QuadratureError> {
    cached((alpha.to_integer_exp(), beta.to_integer_exp(), n, prec, true), || {
        let r = crate::numerics::gauss_jacobi_f64::gauss_jacobi(n, alpha.to_f64(), beta.to_f64())?;
        let lift = |v: &[f64]| v.iter().map(|x| Float::with_val(prec, *x)).collect();
        Ok(GaussJacobiRule {
            alpha: alpha.clone(),
            beta: beta.clone(),
            nodes: lift(&r.nodes),
            weights: lift(&r.weights),
            prec,
        })
    })
}

/// The rule of `key` from the process cache, built by `build` (and kept) the first time.
fn cached<E>(key: Key, build: impl FnOnce() -> Result<GaussJacobiRule, E>) -> Result<Arc<GaussJacobiRule>, E> {
    if let Some(r) = cache().lock().ok().and_then(|c| c.rules.get(&key).cloned()) {
        return Ok(r);
    }
    let rule = Arc::new(build()?);
    if let Ok(mut c) = cache().lock() {
        c.insert(key, rule.clone(), CACHE_BITS);
    }
    Ok(rule)
}

impl Cache {
    /// Keeps `rule` under `key`, first emptying the cache when it would pass `bound` bits (a rule
    /// larger than the bound alone is not kept).
    fn insert(&mut self, key: Key, rule: Arc<GaussJacobiRule>, bound: u64) {
        let bits = rule_bits(&rule);
        if self.bits + bits > bound {
            self.rules.clear();
            self.bits = 0;
        }
        if bits <= bound {
            if let Some(old) = self.rules.insert(key, rule) {
                self.bits -= rule_bits(&old);
            }
            self.bits += bits;
        }
    }
}

/// Empties the process cache of [`gauss_jacobi`] and [`gauss_jacobi_f64_lifted`] (it grows by one
/// rule per distinct (alpha, beta, n, prec), e.g. along a sweep in theta).
pub fn clear_cache() {
    if let Ok(mut c) = cache().lock() {
        c.rules.clear();
        c.bits = 0;
    }
}

/// $\mu_0 = \int_{-1}^1 (1-u)^\alpha (1+u)^\beta du = 2^{\alpha+\beta+1}\Gamma(\alpha+1)\Gamma(\beta+1)/\Gamma(\alpha+\beta+2)$ (DLMF 5.12.1).
pub(crate) fn jacobi_mu0(alpha: &Float, beta: &Float, prec: u32) -> Float {
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

/// The n-point rule computed afresh (no cache); see the module doc for the method.
pub fn gauss_jacobi_uncached(
    alpha: &Float,
    beta: &Float,
    n: usize,
    prec: u32,
) -> Result<GaussJacobiRule, QuadratureError> {
    uncached_from(alpha, beta, n, prec, None)
}

/// [`gauss_jacobi_uncached`] with Newton's method started from `start` (n increasing f64 nodes)
/// when given, from the QL eigenvalues otherwise.
fn uncached_from(
    alpha: &Float,
    beta: &Float,
    n: usize,
    prec: u32,
    start: Option<Vec<f64>>,
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
    newton_rule(alpha, beta, n, prec, prec <= DD_ONLY_PREC, start.filter(|v| v.len() == n))
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
/// `start`: the f64 nodes Newton's method starts from (None: the QL eigenvalues). `dd_only`
/// (chosen as `prec` <= [`DD_ONLY_PREC`] by [`uncached_from`]): every pass in
/// double-double ([`dd_rule`]); otherwise the precision ladder (a double-double first rung, MPFR
/// passes up to the working precision).
fn newton_rule(
    alpha: &Float,
    beta: &Float,
    n: usize,
    prec: u32,
    dd_only: bool,
    start: Option<Vec<f64>>,
) -> Result<GaussJacobiRule, QuadratureError> {
    let wp = prec + GUARD_BITS + (usize::BITS - n.leading_zeros());
    let (a, b) = recurrence(alpha, beta, n, wp);
    let start = match start {
        Some(v) => v,
        None => {
            let d64: Vec<f64> = a.iter().map(|x| x.to_f64()).collect();
            let e64: Vec<f64> = b[1..].iter().map(|x| x.to_f64()).collect();
            tridiagonal_eigenvalues(d64, &e64).ok_or_else(|| QuadratureError::NoConvergence {
                n,
                why: "f64 eigenvalues (implicit QL) did not converge".into(),
            })?
        }
    };

    let mu0 = jacobi_mu0(alpha, beta, wp);
    if dd_only {
        return dd_rule(alpha, beta, (&a, &b), &start, &mu0, prec, wp);
    }

    // Precision ladder for Newton: each step roughly doubles the correct bits from ~50. A first
    // rung of at most DD_BITS bits is a double-double pass.
    let mut ladder = vec![];
    let mut bits = 100u32;
    while bits < wp {
        ladder.push(bits + 16);
        bits *= 2;
    }
    ladder.push(wp);
    ladder.push(wp);
    let dd_first = ladder[0] <= DD_BITS && ladder.len() > 2;
    let evals: Vec<(u32, Eval)> = {
        let mut v: Vec<(u32, Eval)> = vec![];
        for (step, &pb) in ladder.iter().enumerate() {
            if !(dd_first && step == 0) && !v.iter().any(|(q, _)| *q == pb) {
                v.push((pb, Eval::new(alpha, beta, &a, &b, pb)));
            }
        }
        v
    };
    let get = |pb: u32| &evals.iter().find(|(q, _)| *q == pb).expect("ladder precision present").1;
    let dd = dd_first.then(|| EvalDd::new(get(wp)));
    let tol = Float::with_val(53, Float::i_exp(1, -(wp as i32) + 4));

    let mut nodes = Vec::with_capacity(n);
    let mut weights = Vec::with_capacity(n);
    for (i, &x0) in start.iter().enumerate() {
        let mut x = Float::with_val(wp, x0);
        let mut converged = false;
        // p_n' and p_{n-1} from the last full-precision pass, for the weight.
        let mut last: Option<(Float, Float)> = None;
        for (step, &pb) in ladder.iter().enumerate() {
            if let (Some(dd), 0) = (&dd, step) {
                let xd = Dd(x0, 0.0);
                let dx = dd.step(xd);
                if !(dx.0.is_finite() && dx.1.is_finite()) {
                    return Err(QuadratureError::NoConvergence { n, why: format!("zero derivative at node {i}") });
                }
                let next = xd.sub(dx);
                x.assign(next.0);
                x += next.1;
                continue;
            }
            let xe = Float::with_val(pb, &x);
            let (p, dp, pm) = get(pb).run(&xe, pb);
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
            let (p, dp, pm) = get(wp).run(&x, wp);
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
    checked_rule(alpha, beta, nodes, weights, prec)
}

/// The rule of `newton_rule` for `prec` <= `DD_ONLY_PREC`, every Newton pass in double-double
/// (about 100 correct bits, `wp` ~ 100-108 here) instead of the MPFR passes at `wp` bits: from the f64
/// start `start`, passes until the correction is below 2^-(prec + 28) (two, as the ladder at `wp`:
/// one to ~100 bits, one whose negligible correction yields p_n' and p_{n-1} for the weight), the
/// weight mu0 / (b_n p_n' p_{n-1}) as in the MPFR route; then each node and weight rounded to
/// `prec` bits. Both routes carry more than 30 bits beyond `prec`, so both round to the same
/// `prec`-bit numbers except when a value lies within about 2^-95 of a rounding boundary (test
/// `double_double_route_rounds_as_the_mpfr_route`: bit for bit, the locating stage's rules of
/// `sliding::reduction_mpfr` among them). A Newton pass in double-double costs about a quarter
/// of one in MPFR at 104 bits: the 192-node rule of the sinusoid's bracket refinement took 8.7 ms
/// of a 30 ms cold solve (`GJ` timing of each built rule, a temporary trace).
fn dd_rule(
    alpha: &Float,
    beta: &Float,
    (a, b): (&[Float], &[Float]),
    start: &[f64],
    mu0: &Float,
    prec: u32,
    wp: u32,
) -> Result<GaussJacobiRule, QuadratureError> {
    let n = start.len();
    let dd = EvalDd::new(&Eval::new(alpha, beta, a, b, wp));
    let (mu0, bn) = (Dd::of(mu0), Dd::of(&b[n]));
    let tol = 2f64.powi(-(prec as i32) - 28);
    // hi + lo rounded once to `prec` bits (hi + lo is exact at 2 x 64 + 64 bits for |lo| <= ulp(hi)).
    let round = |v: Dd| {
        let mut f = Float::with_val(192, v.0);
        f += v.1;
        Float::with_val(prec, &f)
    };
    let mut nodes = Vec::with_capacity(n);
    let mut weights = Vec::with_capacity(n);
    // Newton in chunks of LANES nodes (the last chunk padded with its last node); a converged
    // node keeps its x and its (p_n', p_{n-1}).
    let mut found: Vec<(Dd, Dd, Dd)> = Vec::with_capacity(n);
    for chunk in start.chunks(LANES) {
        let at = |l: usize| chunk[l.min(chunk.len() - 1)];
        let mut x: [Dd; LANES] = std::array::from_fn(|l| Dd(at(l), 0.0));
        let mut last: [Option<(Dd, Dd)>; LANES] = [None; LANES];
        for pass in 0..8 {
            let values = dd.run_lanes(&x);
            for l in 0..LANES {
                if last[l].is_some() {
                    continue;
                }
                let (p, dp, pm) = values[l];
                let dx = p.div(dp);
                if !(dx.0.is_finite() && dx.1.is_finite()) || dp.0 == 0.0 {
                    let i = found.len() + l.min(chunk.len() - 1);
                    return Err(QuadratureError::NoConvergence { n, why: format!("zero derivative at node {i}") });
                }
                x[l] = x[l].sub(dx);
                if pass >= 1 && dx.0.abs() <= tol {
                    last[l] = Some((dp, pm));
                }
            }
            if last.iter().all(Option::is_some) {
                break;
            }
        }
        let base = found.len();
        for l in 0..chunk.len() {
            let Some((dp, pm)) = last[l] else {
                let i = base + l;
                return Err(QuadratureError::NoConvergence { n, why: format!("Newton did not converge at node {i}") });
            };
            found.push((x[l], dp, pm));
        }
    }
    for (i, (&x0, &(x, dp, pm))) in start.iter().zip(&found).enumerate() {
        if (x.0 - x0).abs() > 1e-6 + 1e-3 * (1.0 - x0 * x0) {
            return Err(QuadratureError::NoConvergence {
                n,
                why: format!("Newton drifted from its start at node {i}"),
            });
        }
        let sum = dp.mul(pm).mul(bn);
        if !(sum.0 > 0.0) {
            return Err(QuadratureError::NoConvergence { n, why: format!("non-positive Christoffel sum at node {i}") });
        }
        nodes.push(round(x));
        weights.push(round(mu0.div(sum)));
    }
    checked_rule(alpha, beta, nodes, weights, prec)
}

/// The rule from its nodes and weights, after the checks both Newton routes end with: nodes
/// strictly increasing inside (-1, 1).
fn checked_rule(
    alpha: &Float,
    beta: &Float,
    nodes: Vec<Float>,
    weights: Vec<Float>,
    prec: u32,
) -> Result<GaussJacobiRule, QuadratureError> {
    let n = nodes.len();
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
    use super::double_double::LANES;
    use super::*;

    /// See: issue 34 (4). The process cache is bounded: a rule that would pass the bound empties
    /// it first, the count of bits held is the sum over the rules kept, and a rule larger than the
    /// bound is returned but not kept.
    #[test]
    fn the_cache_is_bounded() {
        let (a, b) = (Float::with_val(64, -0.5), Float::with_val(64, 0.5));
        let rule = |n: usize, prec: u32| Arc::new(uncached_from(&a, &b, n, prec, None).unwrap());
        let key = |n: usize, prec: u32| (a.to_integer_exp(), b.to_integer_exp(), n, prec, false);
        let mut c = Cache { rules: HashMap::new(), bits: 0 };
        let bound = 2 * 16 * 128 * 2; // two 16-node rules at 128 bits
        for n in [16usize, 16, 17, 18] {
            let r = rule(n.min(16), 128);
            c.insert(key(n, 128), r, bound);
            let held: u64 = c.rules.values().map(|r| rule_bits(r)).sum();
            assert_eq!(c.bits, held);
            assert!(c.bits <= bound, "{} > {bound}", c.bits);
        }
        // The fourth distinct key passed the bound: the cache was emptied and holds it alone.
        assert_eq!(c.rules.len(), 1);
        c.insert(key(64, 512), rule(64, 512), bound);
        assert!(c.rules.is_empty() && c.bits == 0);
    }

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
                let newton = newton_rule(&h, &h, n, prec, prec <= DD_ONLY_PREC, None).unwrap();
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
    fn structure_relation_derivative() {
        // p_n' of Eval::run (structure relation) against the derivative of the recurrence,
        // d/dx: b_{k+1} p_{k+1}' = (x - a_k) p_k' + p_k - b_k p_{k-1}', at 256 bits.
        let prec = 256;
        for (al, be) in [(-0.9f64, -0.1f64), (0.1, 0.9), (0.0, 0.0), (2.5, -0.75), (-0.5, 0.5)] {
            let (alpha, beta) = (Float::with_val(prec, al), Float::with_val(prec, be));
            for n in [1usize, 2, 7, 40] {
                let (a, b) = recurrence(&alpha, &beta, n, prec);
                let e = Eval::new(&alpha, &beta, &a, &b, prec);
                for xv in [-0.999f64, -0.6, 0.0, 0.31, 0.97] {
                    let x = Float::with_val(prec, xv);
                    let (p, dp, pm) = e.run(&x, prec);
                    let (mut q, mut dq) = (Float::with_val(prec, 1), Float::with_val(prec, 0));
                    let (mut qm, mut dqm) = (Float::with_val(prec, 0), Float::with_val(prec, 0));
                    for k in 0..n {
                        let xa = Float::with_val(prec, &x - &a[k]);
                        let next = (Float::with_val(prec, &xa * &q) - Float::with_val(prec, &b[k] * &qm)) / &b[k + 1];
                        let dnext =
                            (Float::with_val(prec, &xa * &dq) + &q - Float::with_val(prec, &b[k] * &dqm)) / &b[k + 1];
                        (qm, q, dqm, dq) = (q, next, dq, dnext);
                    }
                    let close = |u: &Float, v: &Float| {
                        let scale = Float::with_val(prec, u.abs_ref()).max(&Float::with_val(prec, 1));
                        Float::with_val(prec, u - v).abs() <= Float::with_val(prec, Float::i_exp(1, -230)) * scale
                    };
                    assert!(close(&p, &q) && close(&pm, &qm), "values: {al} {be} n {n} x {xv}");
                    assert!(close(&dp, &dq), "derivative: {al} {be} n {n} x {xv}: {dp} vs {dq}");
                }
            }
        }
    }

    #[test]
    fn double_double_start_gives_the_rule_of_a_higher_precision() {
        // Rules whose Newton ladder is the double-double pass and two passes at the working
        // precision (wp <= 200 bits) against the same rule at 96 more bits (a longer ladder, whose
        // MPFR passes correct any error of the start): every node and weight within 2 ulps.
        for (al, be, n, prec) in [(-0.9f64, -0.1f64, 300usize, 132u32), (0.7, 0.3, 64, 64), (0.25, -0.6, 97, 164)] {
            let (alpha, beta) = (Float::with_val(prec, al), Float::with_val(prec, be));
            let r = gauss_jacobi_uncached(&alpha, &beta, n, prec).unwrap();
            let hi = gauss_jacobi_uncached(&alpha, &beta, n, prec + 96).unwrap();
            let ulp = |x: &Float| Float::with_val(prec, Float::i_exp(1, x.get_exp().unwrap_or(0) - prec as i32));
            for i in 0..n {
                let dx = Float::with_val(prec + 96, &r.nodes[i] - &hi.nodes[i]).abs();
                assert!(dx <= Float::with_val(prec, ulp(&r.nodes[i]) * 2u32), "{al} {be} {n} {prec} node {i}");
                let dw = Float::with_val(prec + 96, &r.weights[i] - &hi.weights[i]).abs();
                assert!(dw <= Float::with_val(prec, ulp(&r.weights[i]) * 2u32), "{al} {be} {n} {prec} weight {i}");
            }
        }
    }

    #[test]
    fn double_double_route_rounds_as_the_mpfr_route() {
        // Bit for bit at 64 bits (and below): the locating stage's exponents of the shipped
        // sinusoid scenes (theta = -0.04517 for sinusoid_friction, 0 handled in closed form),
        // both weights 1/omega and omega, generic and extreme exponents, n up to 1024.
        let theta = -0.045_167_235_300_866_55_f64;
        let cases = [
            (theta - 0.5, -theta - 0.5),
            (0.5 - theta, 0.5 + theta),
            (-0.9, -0.1),
            (0.7, 0.3),
            (2.5, -0.75),
            (-0.99, 0.4),
            (0.123, 0.456),
        ];
        let mut checked = 0;
        for (al, be) in cases {
            for (n, prec) in
                [(1usize, 64u32), (2, 64), (8, 64), (16, 64), (40, 53), (97, 64), (192, 64), (384, 64), (1024, 64)]
            {
                if n == 1024 && al != theta - 0.5 {
                    continue;
                }
                let (alpha, beta) = (Float::with_val(prec, al), Float::with_val(prec, be));
                let dd = newton_rule(&alpha, &beta, n, prec, true, None).unwrap();
                let mp = newton_rule(&alpha, &beta, n, prec, false, None).unwrap();
                for i in 0..n {
                    assert_eq!(dd.nodes[i], mp.nodes[i], "{al} {be} n {n} node {i}");
                    assert_eq!(dd.weights[i], mp.weights[i], "{al} {be} n {n} weight {i}");
                    checked += 2;
                }
            }
        }
        assert!(checked > 10_000, "{checked}");
    }

    #[test]
    fn double_double_lanes_are_bit_identical_with_and_without_fma() {
        // Dekker's and the fused exact products are both exact: every lane's (p_n, p_n', p_{n-1})
        // the same bits either way (on a processor without `fma` both sides take Dekker's).
        let prec = 104;
        let (alpha, beta) =
            (Float::with_val(prec, -0.545_167_235_300_866_5_f64), Float::with_val(prec, -0.454_832_764_7_f64));
        let (a, b) = recurrence(&alpha, &beta, 192, prec);
        let dd = EvalDd::new(&Eval::new(&alpha, &beta, &a, &b, prec));
        for j in 0..50 {
            let x: [Dd; LANES] = std::array::from_fn(|l| {
                let v = -0.999 + 1.998 * ((j * LANES + l) as f64 / (50 * LANES) as f64);
                Dd(v, v * 1e-17)
            });
            let (plain, fast) = (dd.run_lanes_with::<false>(&x), dd.run_lanes(&x));
            for l in 0..LANES {
                let bits = |t: (Dd, Dd, Dd)| [t.0 .0, t.0 .1, t.1 .0, t.1 .1, t.2 .0, t.2 .1].map(f64::to_bits);
                assert_eq!(bits(plain[l]), bits(fast[l]), "x = {:?}", x[l]);
            }
        }
    }

    #[test]
    fn f64_rule_start_gives_the_same_rule() {
        // Newton from the f64 rule's nodes (the lifted rule of the sinusoid's scan) against Newton
        // from the QL eigenvalues: the same bits, at the locating precision (double-double route)
        // and at working precisions (MPFR ladder).
        let theta = -0.045_167_235_300_866_55_f64;
        for (al, be) in [(theta - 0.5, -theta - 0.5), (0.7, 0.3), (-0.9, -0.1)] {
            for (n, prec) in [(16usize, 64u32), (96, 64), (192, 64), (384, 64), (28, 132), (40, 164)] {
                let (alpha, beta) = (Float::with_val(prec, al), Float::with_val(prec, be));
                let f = crate::numerics::gauss_jacobi_f64::gauss_jacobi(n, alpha.to_f64(), beta.to_f64()).unwrap();
                let from_f64 = uncached_from(&alpha, &beta, n, prec, Some(f.nodes)).unwrap();
                let from_ql = gauss_jacobi_uncached(&alpha, &beta, n, prec).unwrap();
                assert_eq!(from_f64.nodes, from_ql.nodes, "{al} {be} n {n} prec {prec}");
                assert_eq!(from_f64.weights, from_ql.weights, "{al} {be} n {n} prec {prec}");
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

    #[test]
    fn lifted_f64_rule_is_the_f64_rule_cached_apart_from_the_mpfr_one() {
        let (a, b) = (Float::with_val(96, -0.527f64), Float::with_val(96, -0.473f64));
        let lifted = gauss_jacobi_f64_lifted(&a, &b, 11, 96).unwrap();
        let f = crate::numerics::gauss_jacobi_f64::gauss_jacobi(11, -0.527, -0.473).unwrap();
        for (x, y) in lifted.nodes.iter().zip(&f.nodes).chain(lifted.weights.iter().zip(&f.weights)) {
            assert_eq!(x.to_f64(), *y);
        }
        assert!(Arc::ptr_eq(&lifted, &gauss_jacobi_f64_lifted(&a, &b, 11, 96).unwrap()));
        let mpfr = gauss_jacobi(&a, &b, 11, 96).unwrap();
        assert!(!Arc::ptr_eq(&lifted, &mpfr));
        // The MPFR rule is the more accurate one: the two differ at f64's last digits, not beyond.
        let gap = lifted.nodes.iter().zip(&mpfr.nodes).map(|(x, y)| Float::with_val(96, x - y).abs().to_f64());
        assert!(gap.fold(0.0, f64::max) < 1e-13);
    }
}
