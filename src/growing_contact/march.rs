//! The second method for Problem 2 under a loading law (docs/theory.md section 10; issue 12), in
//! `f64`: block-by-block marching in the loading parameter, built differently from the MPFR
//! collocation ([`crate::loading_law::collocation`], one global Chebyshev interpolant in t = eta/Lambda solved
//! all at once): here the loading [0, Lambda] is cut into blocks, each solved after the earlier
//! ones by its own small Newton iteration, with piecewise polynomials and a graded Gauss rule for
//! the history. Its kernels are [`super::kernel_f64`] (no MPFR code is called).
//!
//! Equations (dimensionless, chi = pi x/L, lambda = pi l/L, gamma = pi c/L, P2 = E* k (L/pi)^2 P,
//! dP1 = n dP2 with n = N'(P2)): at every size lambda both ends enter with the punch's slope,
//!   Re int_0^lambda P'(eta) [(1 + i n) L K(d; eta) - beta n R(d; eta)] d eta = G(chi_e),
//! chi_e = gamma(lambda) +- lambda (leading, trailing), d = chi_e's distance to the nearer end of
//! the contact of size eta: d = (lambda - eta)(1 +- E), E = (gamma(lambda) - gamma(eta))/(lambda -
//! eta); R (the tilted punch) only in the `periodic` convention of the periodic row. G(chi) is
//! the punch's slope pi^2 g'(L chi/pi)/(2 k L), a polynomial in chi (the parabola: pi chi).
//!
//! Discretisation. Block j covers [eta_j, eta_j + h_j]; in it F = P'(eta)/eta and Gm =
//! gamma(eta)/eta are polynomials of degree m - 1 in u in [-1, 1] (Chebyshev coefficients), fixed
//! by their values at the m right-Radau points (the zeros of (1 - u) P^(1,0)_(m-1)(u), u = 1
//! included: collocation of a first-kind Volterra equation with a weakly singular kernel is stable
//! with c_m = 1, Brunner 2004, section 6.2). At each of the m points both edge equations are
//! imposed: 2m equations for the 2m values, solved by Newton (the block's own part of the
//! Jacobian in closed form for the linear law, module `jacobian`, by differences in each value for a
//! polynomial one; the history enters only through gamma(lambda), by one difference per point;
//! its nodes tabled once a block, module `history`), started from the previous block's interpolant
//! continued. The load P(eta) and, for a polynomial law, n(eta)
//! follow from the exact integral of eta F in each block.
//! Quadrature of the edge integral at lambda in block k:
//! - the earlier blocks by Gauss-Legendre on segments graded toward lambda (each segment no
//!   longer than its distance to lambda, so the (lambda - eta)^(-1/2 -+ i eps) singularity just
//!   beyond a block end is resolved; error about (3 + sqrt 8)^(-2 q) per segment of q points);
//! - the current block's part (eta_k, lambda) by tanh-sinh in the complement lambda - eta
//!   (the endpoint singularity absorbed), E from the divided difference of Gm (accurate as
//!   eta -> lambda).
//!
//! Fields (the same definitions as [`crate::loading_law::fields`]): a point chi entered at eta_x
//! (gamma(eta_x) +- eta_x = chi); psi_hat(chi) = Im of its edge integral at lambda = eta_x;
//! sigma_hat(chi) = int_(eta_x)^Lambda P'(eta) [(1 + i n) L sigma_flat - beta n rho] d eta
//! (tanh-sinh from eta_x in its block, graded Gauss beyond); int_0^chi psi_hat = int_0^(eta_x)
//! psi_hat(chi(eta)) chi'(eta) d eta by Gauss per block.

use super::chebyshev_f64::{cheb, cheb_antiderivative, cheb_dd, cheb_derivative, cheb_times_x};
use super::kernel_f64::{KernelF64, Side, C64};
use crate::growing_contact::error::AdhesionError;
use crate::model::ModelError;
use crate::numerics::gauss_jacobi_f64::gauss_jacobi;
use crate::numerics::tanh_sinh::tanh_sinh_f64;
use std::f64::consts::PI;

mod fields;
mod history;
mod jacobian;
mod newton;

use history::{HistoryNodes, PartialNode};

/// Horner: sum_j p_j x^j (numpy order).
fn poly(p: &[f64], x: f64) -> f64 {
    p.iter().rev().fold(0.0, |acc, c| acc * x + c)
}

/// What the march needs besides its discretisation.
#[derive(Debug, Clone)]
pub struct MarchSetting {
    /// The increments' kernels (material and geometry).
    pub kernel: KernelF64,
    /// Whether each increment carries the `periodic` convention's tilted punch (periodic row only).
    pub tilt: bool,
    /// N'(P2) in powers of P2 (numpy order); one coefficient for the linear law.
    pub slope: Vec<f64>,
    /// P2 per unit P (E* k L^2/pi^2).
    pub p2_per_p: f64,
    /// G(chi) = sum_j profile_j chi^j, the punch's scaled slope (module doc; [0, pi] for the parabola).
    pub profile: Vec<f64>,
    /// First guess of P'(eta)/eta at eta = 0 (the symmetric single punch's 2 C_P).
    pub start: f64,
    /// The law's scene key and text, for the refusal N' < 0.
    pub law_key: &'static str,
    /// The law as the scene writes it.
    pub law_text: String,
}

impl MarchSetting {
    /// n = N'(P2) at P2 = p2_per_p `p`.
    pub fn ratio(&self, p: f64) -> f64 {
        poly(&self.slope, p * self.p2_per_p)
    }
    fn constant_ratio(&self) -> bool {
        self.slope.len() <= 1
    }
    /// No tangential load (N = 0) on an even punch (G odd): the contact stays centred, gamma = 0,
    /// and only the leading edge's equation is imposed (the trailing one is its mirror image).
    /// Then the march is a method for section 4's symmetric Problem 2 in its own right: with
    /// gamma free, its own error would move the centre at small nu (the asymmetric homogeneous
    /// modes of [`crate::asymptotics::loading_law_modes`]) although the exact centre stays put.
    pub fn symmetric(&self) -> bool {
        self.slope.iter().all(|c| *c == 0.0) && self.profile.iter().step_by(2).all(|c| *c == 0.0)
    }
}

/// The discretisation of the march.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MarchOptions {
    /// Collocation points per block (m).
    pub nodes: usize,
    /// Block length in lambda (the blocks are equal; the last one of a given load is cut).
    pub block: f64,
    /// Gauss points per history segment.
    pub gauss: usize,
    /// Bits of the tanh-sinh rule of the current block.
    pub bits: u32,
}

impl MarchOptions {
    /// The nominal discretisation: 10 points per block, blocks of 0.05, 14 Gauss points.
    pub const NOMINAL: MarchOptions = MarchOptions { nodes: 10, block: 0.05, gauss: 14, bits: 60 };
    /// The check run: a discretisation of its own, blocks twice as long (other block ends) with
    /// two more points each, and finer rules (two more Gauss points per segment, ten more bits of
    /// tanh-sinh). About 0.7 times the nominal run's work on the shipped scene, where the former
    /// check (blocks two thirds as long) took 2.7 times; docs/performance.md, "Round eight".
    pub fn check(&self) -> Self {
        MarchOptions { nodes: self.nodes + 2, block: self.block * 2.0, gauss: self.gauss + 2, bits: self.bits + 10 }
    }
}

/// Where the march stops.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MarchEnd {
    /// At the size Lambda.
    Size(f64),
    /// Where P reaches `load`, refused beyond `limit` in lambda.
    Load {
        /// Target P.
        load: f64,
        /// Largest lambda allowed.
        limit: f64,
    },
}

/// One block: F = P'/eta and Gm = gamma/eta as Chebyshev series in u = 2 (eta - start)/h - 1.
#[derive(Debug, Clone)]
pub struct Block {
    /// Left end.
    pub start: f64,
    /// Length.
    pub h: f64,
    f: Vec<f64>,
    g: Vec<f64>,
    dg: Vec<f64>,
    load: Vec<f64>,
}

impl Block {
    fn new(start: f64, h: f64, f: Vec<f64>, g: Vec<f64>, load_start: f64) -> Self {
        // P = P(start) + (h/2) int_(-1)^u eta(u') F(u') du', eta(u) = start + h/2 + (h/2) u.
        let xf = cheb_times_x(&f);
        let ef: Vec<f64> =
            (0..xf.len()).map(|j| (start + h / 2.0) * f.get(j).copied().unwrap_or(0.0) + h / 2.0 * xf[j]).collect();
        let mut load: Vec<f64> = cheb_antiderivative(&ef).into_iter().map(|v| v * h / 2.0).collect();
        load[0] += load_start;
        let dg = cheb_derivative(&g);
        Block { start, h, f, g, dg, load }
    }
    /// Right end.
    pub fn end(&self) -> f64 {
        self.start + self.h
    }
    fn u(&self, eta: f64) -> f64 {
        2.0 * (eta - self.start) / self.h - 1.0
    }
    fn p_prime(&self, eta: f64) -> f64 {
        eta * cheb(&self.f, self.u(eta))
    }
    fn gamma(&self, eta: f64) -> f64 {
        eta * cheb(&self.g, self.u(eta))
    }
    /// gamma'(eta) = Gm + eta Gm_u 2/h.
    fn gamma_slope(&self, eta: f64) -> f64 {
        let u = self.u(eta);
        cheb(&self.g, u) + eta * cheb(&self.dg, u) * 2.0 / self.h
    }
    fn load_at(&self, eta: f64) -> f64 {
        cheb(&self.load, self.u(eta))
    }
    /// (gamma(a) - gamma(b))/(a - b) for a, b in the block, accurate as b -> a.
    fn gamma_dd(&self, a: f64, b: f64) -> f64 {
        let ua = self.u(a);
        self.gamma_dd_at(ua, cheb(&self.g, ua), b)
    }
    /// [`Self::gamma_dd`] with a's u and Gm(u) = cheb(g, u) given (the same operations: the
    /// loops over one size's nodes evaluate Gm at the size once).
    fn gamma_dd_at(&self, ua: f64, gm_a: f64, b: f64) -> f64 {
        gm_a + b * cheb_dd(&self.g, ua, self.u(b)) * 2.0 / self.h
    }
}

/// The quadrature and interpolation rules of one discretisation.
#[derive(Debug, Clone)]
struct Rules {
    /// Right-Radau points in (-1, 1].
    radau: Vec<f64>,
    /// Values at `radau` -> Chebyshev coefficients.
    to_cheb: nalgebra::DMatrix<f64>,
    /// Gauss-Legendre on (-1, 1): (node, weight).
    gauss: Vec<(f64, f64)>,
    /// Tanh-sinh on (0, 1): (s, 1 - s, weight).
    ts: Vec<(f64, f64, f64)>,
    /// Gauss-Legendre rules of 0 ..= `gauss.len()` nodes for the history's far blocks (module
    /// `history`; empty: every block with `gauss`).
    far: Vec<Vec<(f64, f64)>>,
    /// The bits the far blocks' rules aim at (the tanh-sinh rule's).
    bits: u32,
}

impl Rules {
    fn new(o: &MarchOptions) -> Result<Self, AdhesionError> {
        let quad = |e: crate::numerics::gauss_jacobi_f64::QuadratureError| AdhesionError::NotConverged {
            what: "loading-law march rules",
            reason: e.to_string(),
        };
        let mut radau = gauss_jacobi(o.nodes - 1, 1.0, 0.0).map_err(quad)?.nodes;
        radau.push(1.0);
        let m = radau.len();
        let v = nalgebra::DMatrix::from_fn(m, m, |i, j| (j as f64 * radau[i].acos()).cos());
        let singular = || AdhesionError::NotConverged {
            what: "loading-law march rules",
            reason: "singular Chebyshev matrix".into(),
        };
        let to_cheb = v.try_inverse().ok_or_else(singular)?;

        let g = gauss_jacobi(o.gauss, 0.0, 0.0).map_err(quad)?;
        let gauss: Vec<(f64, f64)> = g.nodes.into_iter().zip(g.weights).collect();
        let mut far = Vec::with_capacity(o.gauss + 1);
        for n in 0..o.gauss {
            far.push(if n < FAR_MIN_NODES {
                Vec::new()
            } else {
                let g = gauss_jacobi(n, 0.0, 0.0).map_err(quad)?;
                g.nodes.into_iter().zip(g.weights).collect()
            });
        }
        far.push(gauss.clone());
        Ok(Rules { radau, to_cheb, gauss, ts: tanh_sinh_f64(o.bits, 1.0), far, bits: o.bits })
    }
    fn coefficients(&self, values: &[f64]) -> Vec<f64> {
        (&self.to_cheb * nalgebra::DVector::from_column_slice(values)).iter().copied().collect()
    }
}

/// A finished (or running) march: its blocks up to `end`.
#[derive(Debug, Clone)]
pub struct March {
    /// The setting.
    pub setting: MarchSetting,
    /// The discretisation.
    pub options: MarchOptions,
    /// The blocks; the last one may reach beyond `end` (a given load).
    pub blocks: Vec<Block>,
    /// The final size Lambda.
    pub end: f64,
    /// Newton steps taken over all blocks.
    pub steps: usize,
    rules: Rules,
    /// Per block, its history nodes on one Gauss segment, once it is final (module `history`).
    standard: Vec<history::BlockTables>,
    /// Per block, psi_hat at its points' leading and trailing ends as Chebyshev series in u (the
    /// converged Newton's last residual; not for the symmetric march), for phi.
    psi: Vec<Option<[Vec<f64>; 2]>>,
}

/// Largest number of collocation points (lambda ~ 1.52).
pub const MAX_POINTS: usize = 100;

/// Collocation points of the nominal run at `lambda` (one block: a global collocation in eta, [`single_block`]; the loading law at small nu and
/// complete adhesion beyond its series), or `None` beyond
/// [`MAX_POINTS`].
pub fn points_for(lambda: f64) -> Option<usize> {
    let u = PI / lambda.max(1e-3) - 1.0;
    let rho = u + (u * u - 1.0).max(0.0).sqrt();
    let m = (37.0 / rho.ln()).ceil() + 4.0;
    (m.is_finite() && m <= MAX_POINTS as f64).then_some((m as usize).max(8))
}

/// Fewest Gauss nodes on a far block of the history (module `history`).
const FAR_MIN_NODES: usize = 4;

/// A singular point closer than this fraction of a block to the block's end is integrated with
/// the neighbouring block in one tanh-sinh piece (the graded Gauss rule needs its distance).
const NEAR_END: f64 = 0.05;

fn recedes(side: Side, lambda: f64) -> AdhesionError {
    AdhesionError::NotConverged {
        what: "loading-law march",
        reason: format!(
            "the {} end recedes at lambda = {lambda:.4} (the contact must grow at both ends for complete adhesion; \
             at small nu this is the problem's homogeneous mode eta^mu* grown to this size (asymptotics::\
             loading_law_modes: the history is fixed only up to C eta^mu*, and the discretisation's own error \
             sets C), or with blocks of 0.05 their own growing error)",
            if side == Side::Right { "leading" } else { "trailing" }
        ),
    }
}

impl March {
    /// The block with start < eta <= end (eta = 0: the first).
    fn block_right(&self, eta: f64) -> usize {
        self.blocks.partition_point(|b| b.end() < eta).min(self.blocks.len() - 1)
    }
    /// The block with start <= eta < end.
    fn block_left(&self, eta: f64) -> usize {
        self.blocks.partition_point(|b| b.end() <= eta).min(self.blocks.len() - 1)
    }
    /// P'(eta).
    pub(crate) fn p_prime(&self, eta: f64) -> f64 {
        self.blocks[self.block_right(eta)].p_prime(eta)
    }
    /// gamma(eta) = pi c/L at size eta.
    pub fn gamma(&self, eta: f64) -> f64 {
        self.blocks[self.block_right(eta)].gamma(eta)
    }
    /// P(eta).
    pub fn load(&self, eta: f64) -> f64 {
        self.blocks[self.block_right(eta)].load_at(eta)
    }
    /// n = N'(P2(eta)).
    fn ratio_in(&self, block: &Block, eta: f64) -> f64 {
        if self.setting.constant_ratio() {
            self.setting.ratio(0.0)
        } else {
            self.setting.ratio(block.load_at(eta))
        }
    }

    /// Gauss-Legendre over [lo, hi] on segments graded toward `sing` outside it (module doc).
    fn graded(
        &self,
        lo: f64,
        hi: f64,
        sing: f64,
        f: &mut dyn FnMut(f64) -> Result<C64, AdhesionError>,
    ) -> Result<C64, AdhesionError> {
        let mut acc = C64::new(0.0, 0.0);
        for (eta, w) in self.graded_nodes(lo, hi, sing) {
            acc += f(eta)? * w;
        }
        Ok(acc)
    }

    /// The nodes and weights of [`Self::graded`], in its order of summation.
    fn graded_nodes(&self, lo: f64, hi: f64, sing: f64) -> Vec<(f64, f64)> {
        let toward_hi = sing >= hi;
        let (mut a, mut b) = (lo, hi);
        let mut out = Vec::new();
        let segment = |a: f64, b: f64, out: &mut Vec<(f64, f64)>| {
            let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
            out.extend(self.rules.gauss.iter().map(|&(x, w)| (mid + half * x, w * half)));
        };
        loop {
            let dist = if toward_hi { sing - b } else { a - sing };
            if b - a <= dist || dist <= 1e-13 * (hi - lo) {
                segment(a, b, &mut out);
                return out;
            }
            if toward_hi {
                segment(b - dist, b, &mut out);
                b -= dist;
            } else {
                segment(a, a + dist, &mut out);
                a += dist;
            }
        }
    }

    /// The edge integrand of the increment at eta (block `b`) for the end at distance d.
    fn edge_term(&self, b: &Block, side: Side, d: f64, eta: f64, lambda: f64) -> Result<C64, AdhesionError> {
        if d.is_nan() || d <= 0.0 {
            return Err(recedes(side, lambda));
        }
        let n = self.ratio_in(b, eta);
        Ok(self.setting.kernel.increment_outside(side, d, eta, n, self.setting.tilt) * b.p_prime(eta))
    }

    /// The edge integral over (start, lambda) of block `k` (tanh-sinh in lambda - eta).
    fn partial(&self, side: Side, lambda: f64, k: usize) -> Result<C64, AdhesionError> {
        let b = &self.blocks[k];
        let sg = side.sign();
        let span = lambda - b.start;
        let mut acc = C64::new(0.0, 0.0);
        let ul = b.u(lambda);
        let gm_l = cheb(&b.g, ul);
        for &(s, c, w) in &self.rules.ts {
            let gap = span * c;
            let eta = b.start + span * s;
            let e = b.gamma_dd_at(ul, gm_l, eta);
            acc += self.edge_term(b, side, gap * (1.0 + sg * e), eta, lambda)? * w;
        }
        Ok(acc * span)
    }

    /// int_0^lambda of the edge integrand at the leading (Right) or trailing (Left) end of the
    /// contact of size lambda <= end.
    pub fn edge(&self, side: Side, lambda: f64) -> Result<C64, AdhesionError> {
        let k = self.block_right(lambda);
        let b = &self.blocks[k];
        let gl = b.gamma(lambda);
        if k == 0 || lambda - b.start >= NEAR_END * b.h {
            return Ok(self.history(side, lambda, gl, k)? + self.partial(side, lambda, k)?);
        }
        // lambda just past a block start (a point entering there): the singular piece spans the
        // previous block too, whose polynomial gives E there (continued by < NEAR_END h).
        let prev = &self.blocks[k - 1];
        let sg = side.sign();
        let span = lambda - prev.start;
        let mut acc = C64::new(0.0, 0.0);
        for &(s, c, w) in &self.rules.ts {
            let eta = prev.start + span * s;
            let bj = if eta > prev.end() { b } else { prev };
            let e = bj.gamma_dd(lambda, eta);
            acc += self.edge_term(bj, side, span * c * (1.0 + sg * e), eta, lambda)? * w;
        }
        Ok(self.history(side, lambda, gl, k - 1)? + acc * span)
    }
}

/// One block on [0, `lambda`] holding F = P'/eta with the Chebyshev coefficients `f` (in
/// u = 2 eta/lambda - 1) and gamma = 0: the march's fields (load, psi, phi, stresses) for a
/// symmetric solution found by another solve ([`crate::adhesion::collocation_f64`], which solves
/// the same collocation equations of one block directly: they are linear in F when gamma = 0).
pub fn single_block(
    setting: &MarchSetting,
    options: &MarchOptions,
    lambda: f64,
    f: Vec<f64>,
) -> Result<March, AdhesionError> {
    let rules = Rules::new(options)?;
    let g = vec![0.0; f.len()];
    let blocks = vec![Block::new(0.0, lambda, f, g, 0.0)];
    let standard = vec![history::BlockTables::new(&rules)];
    Ok(March {
        setting: setting.clone(),
        options: *options,
        blocks,
        end: lambda,
        steps: 1,
        rules,
        standard,
        psi: vec![None],
    })
}

/// Marches from 0 to `end` (module doc).
pub fn march(setting: &MarchSetting, options: &MarchOptions, end: MarchEnd) -> Result<March, AdhesionError> {
    march_with(setting, options, end, Rules::new(options)?)
}

/// [`march`] with its rules.
fn march_with(
    setting: &MarchSetting,
    options: &MarchOptions,
    end: MarchEnd,
    rules: Rules,
) -> Result<March, AdhesionError> {
    let m = options.nodes;
    // Unknowns per block: the values of F, and of Gm unless the contact stays centred.
    let symmetric = setting.symmetric();
    let unknowns = if symmetric { m } else { 2 * m };
    let (h, count) = match end {
        MarchEnd::Size(lam) => {
            let count = (lam / options.block).ceil().max(1.0) as usize;
            (lam / count as f64, count)
        }
        MarchEnd::Load { limit, .. } => (options.block, (limit / options.block).ceil() as usize + 1),
    };
    let mut mar = March {
        setting: setting.clone(),
        options: *options,
        blocks: Vec::new(),
        end: 0.0,
        steps: 0,
        rules,
        standard: Vec::new(),
        psi: Vec::new(),
    };
    for k in 0..count {
        let start = k as f64 * h;
        let lambdas: Vec<f64> = mar.rules.radau.iter().map(|u| start + h * (1.0 + u) / 2.0).collect();
        let load_start = mar.blocks.last().map_or(0.0, |b| b.load_at(start));
        // The history's nodes at the block's points (the earlier blocks are final).
        let nodes: Vec<HistoryNodes> = lambdas.iter().map(|&l| mar.point_nodes(l, k, start)).collect();
        // First guess: the previous block continued, or the symmetric single punch.
        let x: Vec<f64> = match mar.blocks.last() {
            Some(b) => {
                let us: Vec<f64> = lambdas.iter().map(|l| b.u(*l)).collect();
                us.iter().map(|u| cheb(&b.f, *u)).chain(us.iter().map(|u| cheb(&b.g, *u))).take(unknowns).collect()
            }
            None => (0..unknowns).map(|i| if i < m { setting.start } else { 0.0 }).collect(),
        };
        let install = |mar: &mut March, x: &[f64]| {
            let g = if symmetric { vec![0.0; m] } else { mar.rules.coefficients(&x[m..]) };
            let blk = Block::new(start, h, mar.rules.coefficients(&x[..m]), g, load_start);
            if mar.blocks.len() == k + 1 {
                mar.blocks[k] = blk;
                mar.standard[k] = history::BlockTables::new(&mar.rules);
                mar.psi[k] = None;
            } else {
                mar.blocks.push(blk);
                mar.standard.push(history::BlockTables::new(&mar.rules));
                mar.psi.push(None);
            }
        };
        install(&mut mar, &x);
        // The closed-form Jacobian (linear law); where its Newton fails, the block is solved again
        // from the same start with the Jacobian by differences, as before the closed form (at
        // small nu, where the homogeneous mode has grown, the two iterations end differently:
        // nu = 0, n = 1/2, l/L = 1/8 stalls in 40 steps with the closed form, while the
        // differences let the trailing end recede, the refusal that names the mode).
        let closed = setting.constant_ratio();
        let converged = match newton::newton(&mut mar, x.clone(), &lambdas, &nodes, closed, &install) {
            Ok(true) => true,
            _ if closed => {
                install(&mut mar, &x);
                newton::newton(&mut mar, x.clone(), &lambdas, &nodes, false, &install)?
            }
            Ok(false) => false,
            Err(e) => return Err(e),
        };
        if !converged {
            return Err(not_converged(k, start, h));
        }
        let blk = &mar.blocks[k];
        for &lam in lambdas.iter().chain([start + 0.5 * h / m as f64].iter()) {
            let n = mar.ratio_in(blk, lam);
            if n < 0.0 {
                return Err(ModelError::new(
                    setting.law_key,
                    setting.law_text.clone(),
                    format!(
                        "N'(P2) >= 0 along the loading (P1 must not decrease as P2 grows), but N'({:.6e}) = {n:.6e}",
                        blk.load_at(lam) * setting.p2_per_p
                    ),
                )
                .into());
            }
            let slope = blk.gamma_slope(lam);
            if slope.is_nan() || slope.abs() >= 1.0 {
                return Err(recedes(if slope > 0.0 { Side::Left } else { Side::Right }, lam));
            }
        }
        match end {
            MarchEnd::Size(lam) if k + 1 == count => {
                mar.end = lam;
                return Ok(mar);
            }
            MarchEnd::Load { load, .. } if blk.load_at(blk.end()) >= load => {
                // P increases (P' > 0): bisection in the block.
                let (mut lo, mut hi) = (blk.start, blk.end());
                for _ in 0..200 {
                    let mid = 0.5 * (lo + hi);
                    if mid <= lo || mid >= hi {
                        break;
                    }
                    if blk.load_at(mid) < load {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                mar.end = 0.5 * (lo + hi);
                return Ok(mar);
            }
            _ => {}
        }
    }
    Err(AdhesionError::IllConditioned {
        method: "f64-loading-law",
        parameter: "normal_load",
        value: match end {
            MarchEnd::Load { load, .. } => format!("{:.6e}", load * setting.p2_per_p),
            MarchEnd::Size(l) => format!("lambda {l}"),
        },
        valid: "a load whose contact stays below lambda = pi l/L = 1.45".into(),
        reason: "the march reached its largest contact before the load".into(),
    })
}

fn not_converged(k: usize, start: f64, h: f64) -> AdhesionError {
    AdhesionError::NotConverged {
        what: "loading-law march Newton",
        reason: format!("block {k} (lambda in [{start:.4}, {:.4}]): 40 steps", start + h),
    }
}

#[cfg(test)]
mod tests {
    /// The tests' setting: nu = 0.3, n = 1/5 (the shipped scene's law), the parabola g = pi x^2 on the
    /// periodic row, `tilt` the punch's (`periodic` convention) or not (`paper`).
    pub(crate) fn test_setting(tilt: bool) -> MarchSetting {
        use crate::model::{Exact, Material};
        use crate::params::adhesion::AdhesionParamsF64;
        use std::f64::consts::PI;
        let m = Material::from_contact_modulus(Exact::new(3.into(), 10.into()), Exact::from_integer(1.into())).unwrap();
        let c = AdhesionParamsF64::new(&m);
        MarchSetting {
            kernel: KernelF64 { eps: c.eps, cosh_pi_eps: c.cosh_pi_eps, beta: c.beta, single: false },
            tilt,
            slope: vec![0.2],
            p2_per_p: 1.0 / (PI * PI),
            profile: vec![0.0, PI],
            start: 2.0 * c.load_constant,
            law_key: "tangential_ratio",
            law_text: "1/5".into(),
        }
    }

    use super::*;
    use crate::model::{Exact, Material};
    use crate::params::adhesion::AdhesionParamsF64;
    use std::f64::consts::PI;

    fn setting(nu: (i64, i64), n: f64, periodic: bool, single: bool) -> MarchSetting {
        let m = Material::from_contact_modulus(Exact::new(nu.0.into(), nu.1.into()), Exact::from_integer(1.into()))
            .unwrap();
        let c = AdhesionParamsF64::new(&m);
        MarchSetting {
            kernel: KernelF64 { eps: c.eps, cosh_pi_eps: c.cosh_pi_eps, beta: c.beta, single },
            tilt: periodic && !single,
            slope: vec![n],
            p2_per_p: 1.0 / (PI * PI),
            profile: vec![0.0, PI],
            start: 2.0 * c.load_constant,
            law_key: "tangential_ratio",
            law_text: format!("{n}"),
        }
    }

    /// The single punch (no period): the solution is self-similar, P'/eta and gamma/eta constant,
    /// so c/l and P/lambda^2 are the same at every size along one march (to 1e-13), here at
    /// nu = 0.3, n = 1/5, in the `paper` convention (no rotation for the single punch).
    #[test]
    fn single_punch_is_self_similar() {
        let s = setting((3, 10), 0.2, true, true);
        let m = march(&s, &MarchOptions::NOMINAL, MarchEnd::Size(1.0)).unwrap();
        let (r1, p1) = (m.gamma(1.0), m.load(1.0));
        for lam in [0.13, 0.37, 0.5, 0.81] {
            assert!((m.gamma(lam) / lam - r1).abs() < 1e-13, "c/l at {lam}: {} vs {r1}", m.gamma(lam) / lam);
            assert!((m.load(lam) / (lam * lam) - p1).abs() < 1e-13 * p1, "P at {lam}");
        }
        assert!(r1 < -0.01, "the contact shifts: {r1}");
    }

    /// The prototype case against the MPFR collocation's values at Lambda = pi/6, n = 1/5, nu = 0.3,
    /// paper (`cargo test --release --lib loading_law::collocation::tests::tangential -- --nocapture`:
    /// P = 0.48588839465251704, c/l = -0.04180946173701047), both discretisations.
    #[test]
    fn matches_the_collocation_values() {
        let s = setting((3, 10), 0.2, false, false);
        for o in [MarchOptions::NOMINAL, MarchOptions::NOMINAL.check()] {
            let m = march(&s, &o, MarchEnd::Size(PI / 6.0)).unwrap();
            let lam = m.end;
            assert!((m.load(lam) - 0.485_888_394_652_517_04).abs() < 2e-15, "{}", m.load(lam));
            assert!((m.gamma(lam) / lam + 0.041_809_461_737_010_47).abs() < 2e-15, "{}", m.gamma(lam) / lam);
        }
    }

    /// The history's far blocks with fewer Gauss nodes (module `history`) against every block
    /// with `gauss` nodes, on the march to Lambda = pi/6 (nu = 0.3, n = 1/5, both conventions,
    /// the nominal and the check discretisation): P and gamma at the end, psi_hat and sigma_hat at
    /// five points within 2e-15 of their largest values (measured 1.3e-16 .. 7.1e-16: where
    /// Newton stops, < 4e-15 of the values).
    #[test]
    fn far_blocks_with_fewer_nodes_change_nothing() {
        for periodic in [false, true] {
            let s = setting((3, 10), 0.2, periodic, false);
            for o in [MarchOptions::NOMINAL, MarchOptions::NOMINAL.check()] {
                let end = MarchEnd::Size(PI / 6.0);
                let a = march(&s, &o, end).unwrap();
                let mut rules = Rules::new(&o).unwrap();
                rules.far.clear();
                let b = march_with(&s, &o, end, rules).unwrap();
                let lam = a.end;
                let values = |m: &March| {
                    let mut v = vec![m.load(lam), m.gamma(lam)];
                    for h in [-0.9, -0.5, 0.0, 0.5, 0.9] {
                        let chi = m.gamma(lam) + lam * h;
                        let sigma = m.sigma_hat(chi).unwrap();
                        v.extend([m.psi_hat(chi).unwrap(), sigma.re, sigma.im]);
                    }
                    v
                };
                let (va, vb) = (values(&a), values(&b));
                let scale = vb.iter().fold(0f64, |m, x| m.max(x.abs()));
                let err = va.iter().zip(&vb).fold(0f64, |m, (x, y)| m.max((x - y).abs()));
                eprintln!("periodic {periodic} nodes {}: {err:e} of {scale:e}", o.nodes);
                assert!(err <= 2e-15 * scale, "periodic {periodic} nodes {}: {err:e} of {scale:e}", o.nodes);
            }
        }
    }
}
