//! The collocation operator: Gauss–Jacobi rules and the LU-factored (n+1) x (n+1) matrix of
//! sum_k W_k G_k/(pi (x_r - t_k)) + K, which depend on (theta, n) only (module doc of
//! `collocation_f64`), cached per thread; and the number of nodes for a contact size.

use super::error::{Result, SlidingF64Error};
use super::solution::SolverOptions;
use crate::numerics::accuracy::readable_f64;
use crate::numerics::gauss_jacobi_f64::{sliding_rules, GaussRule};
use nalgebra::{DMatrix, DVector, Dyn, LU};
use std::cell::RefCell;
use std::collections::HashMap;
use std::f64::consts::PI;
use std::rc::Rc;

/// Gauss–Jacobi rules and the LU-factored collocation matrix for (theta, n).
pub struct Collocation {
    pub(super) theta: f64,
    /// Rule of omega: nodes t_k, weights W_k.
    pub(super) rule: GaussRule,
    /// Collocation points x_r (zeros of P_{n+1}^{(-alpha,-beta)}), ascending.
    pub(super) colloc: Vec<f64>,
    /// The matrix's kernel part W_k/(pi (x_r - t_k)), row r at [r n, (r + 1) n) (for the Nyström
    /// interpolant, `interpolant::g_at`).
    pub(super) kernel: Vec<f64>,
    /// 1/cos(pi theta).
    pub(super) sec_pi_theta: f64,
    lu: LU<f64, Dyn, Dyn>,
}

impl Collocation {
    /// Builds the rules and factors the matrix (O(n^2) rules, O(n^3) LU; not cached: see
    /// [`clear_cache`] for the cached path the solver uses).
    pub fn new(theta: f64, n: usize) -> Result<Self> {
        let (rule, conj) = sliding_rules(n, theta)?;
        let colloc = conj.nodes;
        let mut m = DMatrix::<f64>::zeros(n + 1, n + 1);
        let mut kernel = Vec::with_capacity((n + 1) * n);
        for (r, xr) in colloc.iter().enumerate() {
            for k in 0..n {
                m[(r, k)] = rule.weights[k] / (PI * (xr - rule.nodes[k]));
                kernel.push(m[(r, k)]);
            }
            m[(r, n)] = 1.0;
        }
        let sec_pi_theta = 1.0 / (PI * theta).cos();
        Ok(Collocation { theta, rule, colloc, kernel, sec_pi_theta, lu: m.lu() })
    }

    /// Number of nodes n.
    pub fn n(&self) -> usize {
        self.rule.nodes.len()
    }

    /// Solves sum_k W_k G_k/(pi (x_r - t_k)) + K = rhs_r; returns (G, K).
    pub(super) fn solve(&self, rhs: DVector<f64>) -> Result<(Vec<f64>, f64)> {
        let n = self.n();
        let sol = self.lu.solve(&rhs).ok_or_else(|| SlidingF64Error::NoConvergence {
            reason: format!("singular collocation matrix (theta = {}, n = {n})", readable_f64(self.theta)),
        })?;
        Ok((sol.as_slice()[..n].to_vec(), sol[n]))
    }

    /// sum_k W_k G_k h(t_k) over the rule of omega (a functional of p = omega G).
    pub(super) fn sum(&self, g: &[f64], h: impl Fn(f64) -> f64) -> f64 {
        let mut s = 0.0;
        for ((t, w), gk) in self.rule.nodes.iter().zip(&self.rule.weights).zip(g) {
            s += w * gk * h(*t);
        }
        s
    }
}

thread_local! {
    static CACHE: RefCell<HashMap<(u64, usize), Rc<Collocation>>> = RefCell::new(HashMap::new());
}

/// Empties this thread's cache of operators (for cold timings).
pub fn clear_cache() {
    CACHE.with(|c| c.borrow_mut().clear());
}

/// The collocation operator for (theta, n), cached per thread (at most 64 entries).
pub(super) fn collocation(theta: f64, n: usize) -> Result<Rc<Collocation>> {
    let key = (theta.to_bits(), n);
    if let Some(c) = CACHE.with(|c| c.borrow().get(&key).cloned()) {
        return Ok(c);
    }
    let c = Rc::new(Collocation::new(theta, n)?);
    CACHE.with(|cache| {
        let mut cache = cache.borrow_mut();
        if cache.len() >= 64 {
            cache.clear();
        }
        cache.insert(key, c.clone());
    });
    Ok(c)
}

/// Nodes for an error ~ `options.target` at relative size lambda: the quadrature and the Nyström
/// interpolant converge like rho^{-2n}, rho = cot(lambda/2) (Bernstein ellipse through the
/// singularities u = +-i/m of the data, docs/theory.md section 3), so n = ln(1/target)/(2 ln rho) + 8
/// (8: margin for the constant), clamped to [8, max_nodes]. Heuristic, checked by the convergence
/// tests for lambda <= 1.45.
pub fn collocation_nodes(lambda: f64, options: &SolverOptions) -> usize {
    let rate = -2.0 * (0.5 * lambda).tan().ln();
    let n = if rate > 0.0 { (-(options.target.ln()) / rate).ceil() + 8.0 } else { f64::INFINITY };
    if n.is_finite() {
        (n as usize).clamp(8, options.max_nodes)
    } else {
        options.max_nodes
    }
}
