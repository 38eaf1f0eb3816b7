//! The history of the edge integral ([`super`], "Quadrature"): the blocks before the current one
//! at a size lambda, by Gauss-Legendre graded toward lambda, as a table of nodes.
//!
//! While a block is solved its points lambda_j do not move and the earlier blocks are final, so
//! the nodes of each point's history, and at each node eta everything but gamma(lambda_j) (the
//! node's weight, gamma(eta), P'(eta), n and the kernel's factors of eta alone,
//! [`crate::growing_contact::kernel_f64::EtaFactors`]), are the same in every Newton step and in
//! the Jacobian's difference in gamma(lambda_j). [`HistoryNodes`] holds them once per point; each
//! evaluation then costs the kernel's factors of the distance
//!   d = (lambda - eta)(1 +- E),   E = (gamma(lambda) - gamma(eta))/(lambda - eta),
//! alone. The operations and their order are those of the direct sum (per block, the graded
//! segments' nodes in turn; then the blocks), so the values are bit for bit the same.

use super::{recedes, March};
use crate::growing_contact::error::AdhesionError;
use crate::growing_contact::kernel_f64::{EtaFactors, Side, C64};

/// One node of the history at one size.
#[derive(Debug, Clone)]
struct HistoryNode {
    eta: f64,
    /// Gauss weight times the segment's half-length.
    weight: f64,
    gamma: f64,
    p_prime: f64,
    ratio: f64,
    factors: EtaFactors,
}

/// The history's nodes at the size `lambda`, block by block.
#[derive(Debug, Clone)]
pub(super) struct HistoryNodes {
    lambda: f64,
    blocks: Vec<Vec<HistoryNode>>,
}

impl March {
    /// The nodes of the edge integral over the blocks before `upto` at the size `lambda`.
    pub(super) fn history_nodes(&self, lambda: f64, upto: usize) -> HistoryNodes {
        let tilt = self.setting.tilt;
        let blocks = self.blocks[..upto]
            .iter()
            .map(|b| {
                self.graded_nodes(b.start, b.end(), lambda)
                    .into_iter()
                    .map(|(eta, weight)| HistoryNode {
                        eta,
                        weight,
                        gamma: b.gamma(eta),
                        p_prime: b.p_prime(eta),
                        ratio: self.ratio_in(b, eta),
                        factors: self.setting.kernel.eta_factors(eta, tilt),
                    })
                    .collect()
            })
            .collect();
        HistoryNodes { lambda, blocks }
    }

    /// The edge integral over the nodes' blocks at their size with gamma(lambda) = `gl`.
    pub(super) fn history_at(&self, nodes: &HistoryNodes, side: Side, gl: f64) -> Result<C64, AdhesionError> {
        let (sg, lambda, tilt) = (side.sign(), nodes.lambda, self.setting.tilt);
        let kernel = &self.setting.kernel;
        let mut acc = C64::new(0.0, 0.0);
        for block in &nodes.blocks {
            let mut part = C64::new(0.0, 0.0);
            for n in block {
                let e = (gl - n.gamma) / (lambda - n.eta);
                let d = (lambda - n.eta) * (1.0 + sg * e);
                if d.is_nan() || d <= 0.0 {
                    return Err(recedes(side, lambda));
                }
                part += kernel.increment_outside_with(&n.factors, side, d, n.eta, n.ratio, tilt) * n.p_prime * n.weight;
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
