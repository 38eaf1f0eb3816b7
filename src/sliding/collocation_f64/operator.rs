//! The collocation operator: Gauss–Jacobi rules and the LU-factored (n+1) x (n+1) matrix of
//! sum_k W_k G_k/(pi (x_r - t_k)) + K, which depend on (theta, n) only (module doc of
//! `collocation_f64`), cached per thread; and the number of nodes for a contact size.

use super::error::{Result, SlidingF64Error};
use super::solution::SolverOptions;
use crate::numerics::accuracy::readable_f64;
use crate::numerics::gauss_jacobi_f64::{self, sliding_rules, GaussRule};
use crate::sliding::physicality::pressure_points;
use nalgebra::{DMatrix, DVector};
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
    /// The samples of p at fixed u ([`SampleGrid`]).
    pub(super) grid: SampleGrid,
    /// nalgebra's LU factors of the (n+1) x (n+1) matrix, column-major (unit lower L below the
    /// diagonal, U on and above), and its row permutation as a gather (`perm[i]` = the row of the
    /// right-hand side that lands in row i), for [`Self::solve`].
    factors: Vec<f64>,
    perm: Vec<usize>,
}

/// The fixed samples of p in the tangent variable: the physicality criterion's pressure points
/// ([`pressure_points`]: 68 Chebyshev–Lobatto points and 18 next to the ends, in that order),
/// where the outputs take max p and the check run's pressure difference and the criterion tests
/// p >= 0. At a fixed u the Nyström interpolant ([`super::interpolant::g_at`]) is
/// G(u) = (F[u, x_r] + sum_k q_k G_k)/(sec(pi theta) + sum_k q_k), q_k = W_k/(pi (x_r - t_k)
/// (u - t_k)), whose weights q_k and denominator depend on (theta, n) only: they are computed
/// here once per operator (as in `g_at`, term by term in the same order, so G on the grid is
/// the same to the bit as `g_at`), and a state's G there costs n multiply-adds and one F[u, x_r]
/// per point (`interpolant::g_on_grid`), omega(u) none.
pub(super) struct SampleGrid {
    /// The points u, in the order of [`pressure_points`].
    pub(super) u: Vec<f64>,
    /// omega(u) = (1 + u)^(1/2 + theta) (1 - u)^(1/2 - theta).
    pub(super) omega: Vec<f64>,
    /// Per point: the collocation point x_r of the interpolant, or the node u falls on.
    pub(super) at: Vec<GridPoint>,
    /// q_k by node: row k holds q_k of every point in the points' order (zero for a point on
    /// a node), so that a state's sums over k run for all points side by side.
    pub(super) q: Vec<f64>,
    /// sec(pi theta) + sum_k q_k per point.
    pub(super) den: Vec<f64>,
}

/// How G is obtained at a point of the [`SampleGrid`].
#[derive(Debug, Clone, Copy)]
pub(super) enum GridPoint {
    /// By the interpolant with the collocation point x_r, r = this index.
    Row(usize),
    /// u is the node t_k, k = this index: G = G_k.
    Node(usize),
}

impl SampleGrid {
    fn new(rule: &GaussRule, colloc: &[f64], kernel: &[f64], sec_pi_theta: f64, theta: f64) -> Self {
        let n = rule.nodes.len();
        let u = pressure_points();
        let omega = u.iter().map(|&v| gauss_jacobi_f64::omega(v, theta)).collect();
        let points = u.len();
        let (mut at, mut q, mut den) = (Vec::with_capacity(points), vec![0.0; points * n], Vec::new());
        for (i, &v) in u.iter().enumerate() {
            if let Some(k) = rule.nodes.iter().position(|t| *t == v) {
                at.push(GridPoint::Node(k));
                den.push(1.0);
                continue;
            }
            let r = nearest_collocation_point(colloc, v);
            let row = &kernel[r * n..(r + 1) * n];
            let mut d = sec_pi_theta;
            for (k, (w, t)) in row.iter().zip(&rule.nodes).enumerate() {
                let qk = w / (v - t);
                q[k * points + i] = qk;
                d += qk;
            }
            at.push(GridPoint::Row(r));
            den.push(d);
        }
        SampleGrid { u, omega, at, q, den }
    }
}

/// The index r of the collocation point x_r nearest to u (`xs` ascending; the lower one on a
/// tie), as the Nyström interpolant uses it.
pub(super) fn nearest_collocation_point(xs: &[f64], u: f64) -> usize {
    let i = xs.partition_point(|x| *x < u).min(xs.len() - 1);
    if i > 0 && (u - xs[i - 1]).abs() < (xs[i] - u).abs() {
        i - 1
    } else {
        i
    }
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
        let grid = SampleGrid::new(&rule, &colloc, &kernel, sec_pi_theta, theta);
        let lu = m.lu();
        // The permutation applied to the row indices gives the gather.
        let mut rows = DVector::<f64>::from_fn(n + 1, |i, _| i as f64);
        lu.p().permute_rows(&mut rows);
        let perm = rows.iter().map(|&i| i as usize).collect();
        let factors = lu.lu_internal().as_slice().to_vec();
        Ok(Collocation { theta, rule, colloc, kernel, sec_pi_theta, grid, factors, perm })
    }

    /// Number of nodes n.
    pub fn n(&self) -> usize {
        self.rule.nodes.len()
    }

    /// Solves sum_k W_k G_k/(pi (x_r - t_k)) + K = rhs_r; returns (G, K). The substitutions
    /// of nalgebra's `LU::solve` written out on the stored factors, operation for operation
    /// (the permutation; b_j -= b_i L_ji column by column; then from the last row b_i /= U_ii,
    /// b_j -= b_i U_ji), so the same bits without its copies and generic indexing (test
    /// `the_substitutions_are_nalgebras_to_the_bit`).
    pub(super) fn solve(&self, rhs: &[f64]) -> Result<(Vec<f64>, f64)> {
        let (n, dim) = (self.n(), self.n() + 1);
        let f = &self.factors;
        let mut b: Vec<f64> = self.perm.iter().map(|&i| rhs[i]).collect();
        for i in 0..dim - 1 {
            let c = b[i];
            for (bj, l) in b[i + 1..].iter_mut().zip(&f[i * dim + i + 1..(i + 1) * dim]) {
                *bj -= c * l;
            }
        }
        for i in (0..dim).rev() {
            let d = f[i * dim + i];
            if d == 0.0 {
                return Err(SlidingF64Error::NoConvergence {
                    reason: format!("singular collocation matrix (theta = {}, n = {n})", readable_f64(self.theta)),
                });
            }
            let c = b[i] / d;
            b[i] = c;
            for (bj, u) in b[..i].iter_mut().zip(&f[i * dim..i * dim + i]) {
                *bj -= c * u;
            }
        }
        let k = b[n];
        b.truncate(n);
        Ok((b, k))
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
