//! The history of the edge integral ([`super`], "Quadrature"): the blocks before the current one
//! at a size lambda, by Gauss-Legendre graded toward lambda, as a table of nodes; and the current
//! block's tanh-sinh nodes at that size.
//!
//! While a block is solved its points lambda_j do not move and the earlier blocks are final, so
//! the nodes of each point's history, and at each node eta everything but gamma(lambda_j) (the
//! node's weight, gamma(eta), P'(eta), n and the kernel's factors of eta alone,
//! [`crate::growing_contact::kernel_f64::NodeFactors`]), are the same in every Newton step and in
//! the Jacobian's difference in gamma(lambda_j). [`HistoryNodes`] holds them once per point; each
//! evaluation then costs the kernel's factors of the distance
//!   d = (lambda - eta)(1 +- E),   E = (gamma(lambda) - gamma(eta))/(lambda - eta),
//! alone. The current block's tanh-sinh nodes (eta, the gap lambda - eta, the weight and eta's
//! kernel factors) are tabled too ([`PartialNode`]); its polynomials change with the Newton steps
//! and are evaluated anew.
//!
//! A finished block of length h whose end lies dist >= h before lambda is one Gauss segment
//! (graded segments only nearer). Its integrand is analytic but for the edge singularity at
//! eta = lambda, a distance 2 dist/h past the end of the block's [-1, 1]: Gauss-Legendre with n
//! nodes errs by about rho^(-2n), rho = x + sqrt(x^2 - 1), x = 1 + 2 dist/h (the Bernstein
//! ellipse through the singularity). Such a block takes the fewest n with rho^(-2n) <= 2^-bits
//! (the tanh-sinh rule's bits, 60 and 76 in the two runs), one more, at least 4, at most the
//! `gauss` of the options ([`March::far_order`]; dist = h: 13 and 16 nodes, 2 h: 11 and 13,
//! 10 h: 7 and 9, where every block took 14 and 18): the history's far blocks are most of its
//! nodes. Against every block with `gauss` nodes: within 2e-15 of the values (test
//! `far_blocks_with_fewer_nodes_change_nothing`). Each block's table of n nodes is made once per
//! march ([`March::standard_nodes`]) and shared by every later point and every edge integral of
//! the fields. The sums run in the order of the direct sum (per block, the graded segments' nodes
//! in turn; then the blocks).

use super::{recedes, March};
use crate::growing_contact::error::AdhesionError;
use crate::growing_contact::kernel_f64::{NodeFactors, Side, C64};
use std::sync::{Arc, OnceLock};

/// Per order n, a finished block's history nodes on one Gauss segment of n nodes
/// ([`March::standard_nodes`]).
#[derive(Debug, Clone)]
pub(super) struct BlockTables(Vec<OnceLock<Arc<[HistoryNode]>>>);

impl BlockTables {
    pub(super) fn new(rules: &super::Rules) -> Self {
        BlockTables((0..rules.far.len().max(rules.gauss.len() + 1)).map(|_| OnceLock::new()).collect())
    }
}

/// One node of the history at one size.
#[derive(Debug, Clone)]
pub(super) struct HistoryNode {
    eta: f64,
    /// Gauss weight times the segment's half-length.
    weight: f64,
    gamma: f64,
    p_prime: f64,
    ratio: f64,
    factors: NodeFactors,
}

/// One tanh-sinh node of the current block's part at one size: eta = start + span s, the gap
/// span (1 - s), the rule's weight and eta's kernel factors.
#[derive(Debug, Clone)]
pub(super) struct PartialNode {
    pub(super) eta: f64,
    pub(super) gap: f64,
    pub(super) weight: f64,
    pub(super) factors: NodeFactors,
}

/// The history's nodes at the size `lambda`, block by block, and the current block's nodes.
#[derive(Debug, Clone)]
pub(super) struct HistoryNodes {
    lambda: f64,
    blocks: Vec<Arc<[HistoryNode]>>,
    /// The current block's tanh-sinh nodes (empty where the caller sums them itself).
    pub(super) partial: Vec<PartialNode>,
}

impl March {
    /// The nodes of block `k` on the single Gauss segment of `n` nodes over the whole block (as
    /// [`March::graded_nodes`] gives it for a singular point at least a block length away, with
    /// `gauss` nodes), computed once per march; block `k` must be final.
    fn standard_nodes(&self, k: usize, n: usize) -> Arc<[HistoryNode]> {
        let b = &self.blocks[k];
        self.standard[k].0[n]
            .get_or_init(|| {
                let (mid, half) = (0.5 * (b.start + b.end()), 0.5 * (b.end() - b.start));
                let rule = if n == self.rules.gauss.len() { &self.rules.gauss } else { &self.rules.far[n] };
                let nodes = rule.iter().map(|&(x, w)| (mid + half * x, w * half));
                self.history_node_table(b, nodes)
            })
            .clone()
    }

    /// Gauss nodes for a far block of length `h` whose end is `dist` >= h from the singular
    /// point (module doc): the fewest n with rho^(-2 n) <= 2^-bits, one more, within
    /// [FAR_MIN_NODES, gauss]; `gauss` where the rules keep no far orders.
    fn far_order(&self, h: f64, dist: f64) -> usize {
        let gauss = self.rules.gauss.len();
        if self.rules.far.len() <= gauss {
            return gauss;
        }
        let x = 1.0 + 2.0 * dist / h;
        let rho = x + (x * x - 1.0).sqrt();
        let n = (self.rules.bits as f64 * std::f64::consts::LN_2 / (2.0 * rho.ln())).ceil() + 1.0;
        if n.is_finite() {
            (n as usize).clamp(super::FAR_MIN_NODES.min(gauss), gauss)
        } else {
            gauss
        }
    }

    fn history_node_table(&self, b: &super::Block, nodes: impl Iterator<Item = (f64, f64)>) -> Arc<[HistoryNode]> {
        let tilt = self.setting.tilt;
        nodes
            .map(|(eta, weight)| HistoryNode {
                eta,
                weight,
                gamma: b.gamma(eta),
                p_prime: b.p_prime(eta),
                ratio: self.ratio_in(b, eta),
                factors: self.setting.kernel.node_factors(eta, tilt),
            })
            .collect()
    }

    /// The nodes of the edge integral over the blocks before `upto` at the size `lambda`.
    pub(super) fn history_nodes(&self, lambda: f64, upto: usize) -> HistoryNodes {
        let blocks = self.blocks[..upto]
            .iter()
            .enumerate()
            .map(|(k, b)| {
                // graded_nodes' first test: one segment over the whole block.
                let (lo, hi) = (b.start, b.end());
                let dist = lambda - hi;
                if lambda >= hi && hi - lo <= dist {
                    self.standard_nodes(k, self.far_order(hi - lo, dist))
                } else if lambda >= hi && dist <= 1e-13 * (hi - lo) {
                    self.standard_nodes(k, self.rules.gauss.len())
                } else {
                    self.history_node_table(b, self.graded_nodes(lo, hi, lambda).into_iter())
                }
            })
            .collect();
        HistoryNodes { lambda, blocks, partial: Vec::new() }
    }

    /// [`Self::history_nodes`] with the tanh-sinh nodes of the block starting at `start`
    /// (the current one, the `upto`-th) at the same size.
    pub(super) fn point_nodes(&self, lambda: f64, upto: usize, start: f64) -> HistoryNodes {
        let mut nodes = self.history_nodes(lambda, upto);
        let span = lambda - start;
        let tilt = self.setting.tilt;
        nodes.partial = self
            .rules
            .ts
            .iter()
            .map(|&(s, c, w)| {
                let eta = start + span * s;
                PartialNode { eta, gap: span * c, weight: w, factors: self.setting.kernel.node_factors(eta, tilt) }
            })
            .collect();
        nodes
    }

    /// The edge integral over the nodes' blocks at their size with gamma(lambda) = `gl`.
    pub(super) fn history_at(&self, nodes: &HistoryNodes, side: Side, gl: f64) -> Result<C64, AdhesionError> {
        let (sg, lambda, tilt) = (side.sign(), nodes.lambda, self.setting.tilt);
        let kernel = &self.setting.kernel;
        let mut acc = C64::new(0.0, 0.0);
        for block in &nodes.blocks {
            let mut part = C64::new(0.0, 0.0);
            for n in block.iter() {
                let e = (gl - n.gamma) / (lambda - n.eta);
                let d = (lambda - n.eta) * (1.0 + sg * e);
                if d.is_nan() || d <= 0.0 {
                    return Err(recedes(side, lambda));
                }
                part += kernel.increment_outside_node(&n.factors, side, d, n.eta, n.ratio, tilt) * n.p_prime * n.weight;
            }
            acc += part;
        }
        Ok(acc)
    }

    /// The edge integral over the blocks before `upto` at the size lambda with gamma(lambda) = `gl`.
    pub(super) fn history(&self, side: Side, lambda: f64, gl: f64, upto: usize) -> Result<C64, AdhesionError> {
        self.history_at(&self.history_nodes(lambda, upto), side, gl)
    }
}
