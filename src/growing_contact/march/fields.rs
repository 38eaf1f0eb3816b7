//! The march's fields (module doc of [`super`], "Fields"): the entry size of a point of the final
//! contact, psi_hat and its integral, and the stresses sigma_hat, from the blocks of a finished
//! march.
//!
//! phi's integrand psi_hat(chi(eta)) = Im of the edge integral at the size eta is, at a block's
//! m points, the imaginary part of the residual's edge integral: Newton's last residual (at the
//! iterate before its last correction, < 4e-15 of the values) keeps them per side, and their
//! Chebyshev interpolant of degree m - 1 on the block gives psi_hat at the Gauss nodes (an edge
//! integral each before: a fifth of the f64 loading law's time). Against the edge integrals at
//! every node: within 1e-15 of the largest |phi| (test `interpolated_phi_equals_the_edge_integrals`,
//! both runs, both conventions). The symmetric march (no trailing equation) and
//! [`super::single_block`] keep the edge integrals.

use super::{Block, March, NEAR_END};
use crate::growing_contact::chebyshev_f64::cheb;
use crate::growing_contact::error::AdhesionError;
use crate::growing_contact::kernel_f64::{Side, C64};

impl March {
    /// The side and the entry size eta_x of the point chi of the final contact: gamma(eta) +- eta
    /// = chi, by bisection (monotone: both ends advance). A point at the final end (or past it by
    /// rounding) entered with the final size: eta_x = end exactly, where the stresses vanish (issue
    /// 34, fuzz seed 2026 case 5890: x/a = 1 bisected to one ulp below the end printed q2 =
    /// 1.1e-7 of a scale 3.1, the square root of that ulp, where the truth is 0).
    pub fn entry(&self, chi: f64) -> (Side, f64) {
        let (side, sg) = if chi >= 0.0 { (Side::Right, 1.0) } else { (Side::Left, -1.0) };
        if sg * (self.gamma(self.end) + sg * self.end - chi) <= 0.0 {
            return (side, self.end);
        }
        let (mut lo, mut hi) = (0.0, self.end);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if sg * (self.gamma(mid) + sg * mid - chi) < 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        (side, 0.5 * (lo + hi))
    }

    /// psi_hat(chi) = Im of the edge integral at the point's entry (module doc).
    pub fn psi_hat(&self, chi: f64) -> Result<f64, AdhesionError> {
        let (side, eta_x) = self.entry(chi);
        if eta_x <= 0.0 {
            return Ok(0.0);
        }
        Ok(self.edge(side, eta_x)?.im)
    }

    /// int_0^chi psi_hat(chi') d chi' = int_0^(eta_x) psi_hat(chi(eta)) (gamma'(eta) +- 1) d eta,
    /// Gauss-Legendre on each block's part (module doc).
    pub(crate) fn psi_hat_integral(&self, chi: f64) -> Result<f64, AdhesionError> {
        Ok(self.psi_hat_integrals(&[chi])?[0])
    }

    /// [`Self::psi_hat_integral`] at each of `chis`: the terms of a block the point's entry
    /// passed whole (the same Gauss nodes for every point entered through the same end) are
    /// computed once per side and summed in the same order, so each value is the one
    /// `psi_hat_integral` gives alone, bit for bit.
    pub(crate) fn psi_hat_integrals(&self, chis: &[f64]) -> Result<Vec<f64>, AdhesionError> {
        self.psi_hat_integrals_with(chis, true)
    }

    /// [`Self::psi_hat_integrals`], psi_hat at the Gauss nodes from the block's interpolant
    /// where the march kept one and `interpolated`, else by its edge integral.
    fn psi_hat_integrals_with(&self, chis: &[f64], interpolated: bool) -> Result<Vec<f64>, AdhesionError> {
        let mut whole: [Vec<Option<Vec<f64>>>; 2] = [vec![None; self.blocks.len()], vec![None; self.blocks.len()]];
        let mut out = Vec::with_capacity(chis.len());
        for &chi in chis {
            let (side, eta_x) = self.entry(chi);
            let sg = side.sign();
            let terms = |k: usize, b: &super::Block, lo: f64, hi: f64| -> Result<Vec<f64>, AdhesionError> {
                let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
                self.rules
                    .gauss
                    .iter()
                    .map(|&(x, w)| {
                        let eta = mid + half * x;
                        let psi = match &self.psi[k] {
                            Some(sides) if interpolated => cheb(&sides[usize::from(side == Side::Left)], b.u(eta)),
                            _ => self.edge(side, eta)?.im,
                        };
                        Ok(w * half * psi * (b.gamma_slope(eta) + sg))
                    })
                    .collect()
            };
            let cache = &mut whole[usize::from(side == Side::Left)];
            let mut acc = 0.0;
            for (k, b) in self.blocks.iter().enumerate() {
                let (lo, hi) = (b.start, b.end().min(eta_x));
                if hi <= lo {
                    break;
                }
                if hi == b.end() {
                    if cache[k].is_none() {
                        cache[k] = Some(terms(k, b, lo, hi)?);
                    }
                    for t in cache[k].iter().flatten() {
                        acc += t;
                    }
                } else {
                    for t in terms(k, b, lo, hi)? {
                        acc += t;
                    }
                }
            }
            out.push(acc);
        }
        Ok(out)
    }

    /// The stress integrand at eta (block `b`) for the point at distance `near` from the end
    /// that passed it.
    fn stress_term(&self, b: &Block, side: Side, near: f64, eta: f64) -> C64 {
        let far = 2.0 * eta - near;
        let (d_left, d_right) = if side == Side::Right { (far, near) } else { (near, far) };
        let n = self.ratio_in(b, eta);
        self.setting.kernel.increment_stress(d_left, d_right, eta, n, self.setting.tilt) * b.p_prime(eta)
    }

    /// sigma_hat(chi) = int_(eta_x)^Lambda of the increments' stresses at chi (module doc).
    pub(crate) fn sigma_hat(&self, chi: f64) -> Result<C64, AdhesionError> {
        let (side, eta_x) = self.entry(chi);
        let sg = side.sign();
        let k = self.block_left(eta_x);
        let mut acc = C64::new(0.0, 0.0);
        // The singular piece from eta_x: tanh-sinh in eta - eta_x over the rest of its block, or
        // over the next block too when eta_x lies within NEAR_END h of the block's end; the slope
        // of gamma by the divided difference of the polynomial of each node's block.
        let b = &self.blocks[k];
        let two = b.end() - eta_x < NEAR_END * b.h && k + 1 < self.blocks.len() && b.end() < self.end;
        let last = if two { k + 1 } else { k };
        let span = self.blocks[last].end().min(self.end) - eta_x;
        if span > 0.0 {
            for &(s, _, w) in &self.rules.ts {
                let gap = span * s;
                let eta = eta_x + gap;
                let bj = if eta < b.end() { b } else { &self.blocks[last] };
                let e = bj.gamma_dd(eta, eta_x);
                acc += self.stress_term(bj, side, gap * (1.0 + sg * e), eta) * (w * span);
            }
        }
        let gx = self.gamma(eta_x);
        for b in self.blocks.iter().skip(last + 1) {
            let hi = b.end().min(self.end);
            if hi <= b.start {
                break;
            }
            acc += self.graded(b.start, hi, eta_x, &mut |eta| {
                let e = (b.gamma(eta) - gx) / (eta - eta_x);
                Ok(self.stress_term(b, side, (eta - eta_x) * (1.0 + sg * e), eta))
            })?;
        }
        Ok(acc)
    }
}

#[cfg(test)]
mod tests {
    use super::super::{march, MarchEnd, MarchOptions};
    use std::f64::consts::PI;

    /// phi from the blocks' interpolants of psi_hat against phi from an edge integral at every
    /// Gauss node (module doc), at the shipped scene's size and points (nu = 0.3, n = 1/5,
    /// Lambda = pi/6, xh = -0.9 .. 0.9), the nominal and the check run, `paper` and `periodic`
    /// conventions: within 1e-15 of the largest |phi| (measured 0.8e-16 .. 1.9e-16).
    #[test]
    fn interpolated_phi_equals_the_edge_integrals() {
        for tilt in [false, true] {
            let s = super::super::tests::test_setting(tilt);
            for o in [MarchOptions::NOMINAL, MarchOptions::NOMINAL.check()] {
                let mar = march(&s, &o, MarchEnd::Size(PI / 6.0)).unwrap();
                assert!(mar.psi.iter().all(Option::is_some), "every block keeps its psi_hat");
                let (lam, g) = (mar.end, mar.gamma(mar.end));
                let chis: Vec<f64> = [-0.9, -0.5, 0.0, 0.5, 0.9].iter().map(|h| g + lam * h).collect();
                let a = mar.psi_hat_integrals_with(&chis, true).unwrap();
                let b = mar.psi_hat_integrals_with(&chis, false).unwrap();
                let scale = b.iter().fold(0f64, |m, v| m.max(v.abs()));
                let err = a.iter().zip(&b).fold(0f64, |m, (x, y)| m.max((x - y).abs()));
                eprintln!("tilt {tilt} nodes {}: {err:e} of {scale:e}", o.nodes);
                assert!(err < 1e-15 * scale, "tilt {tilt} nodes {}: {err:e} of {scale:e}", o.nodes);
            }
        }
    }
}
