//! The load of the periodic row with finite friction from the edge-slope Volterra equation at high
//! order (docs/theory.md section 17.8, (17.11)), the increments by the spectral method of
//! [`super::spectral_row`], generic over `f64` and MPFR; [`verified_mpfr`]: P and c/a in MPFR with
//! verified digits.
//!
//! Units L = pi, E* = k = 1 (P2 = E* k (L/pi)^2 P). With W(chi, eta) the outside slope of the unit
//! increment at contact eta, the load P(lambda) solves
//!     int_0^chi W(chi, eta) P'(eta) d eta = chi,   0 < chi <= lambda.                      (17.11)
//! Discretisation: P'(eta) = tan(eta) F(eta), F the polynomial in v(eta) through its values at
//! the N Chebyshev points of v on (v(0), v(lambda)) (barycentric form), collocated at
//! chi_i = eta_i: N equations, solved by least squares (square). The factor tan(eta) carries the
//! pole of P' at full contact eta = pi/2 (Kuznetsov: F = pi). The variable ([`NodeRule`]): in
//! `paper` tau = tan(eta) enters (17.10) only as tau^2, so F and G cos(eta) below are even in
//! eta, and v = eta^2 keeps their singularities off the mirror side eta < 0 (measured at
//! lambda = 1.2, 128 bits: successive N differ by a factor 10^1.05 per node against 10^0.72 in
//! eta); in `periodic` the lateral strain b beta tau makes them neither even nor odd and v = eta
//! (10^0.7 per node, alternating in sign; v = eta^2 does not converge there). [`load`] keeps
//! v = eta; [`load_with`] takes the rule. The kernel is never needed at a new contact: in the tangent
//! variable W(chi, eta) = G(tan(chi)/tan(eta), eta)/tan(eta), G(T, eta) = H\[S2^eta\](T), whose
//! singular point T = 1 does not move with eta, so G is interpolated in v at fixed T from the
//! increments solved at the same N points (each at its own stick edge), as G cos(eta), which
//! has no pole at eta = pi/2 (Kuznetsov: G cos(eta) = 1/(pi sqrt(T^2 - 1)), independent of eta). The integral over eta is
//! tanh-sinh on (0, chi_i) ([`DoubleExp`], end singularity (chi - eta)^(-1/2 + theta0)), and
//! P(lambda) = int_0^lambda tan(eta) F(eta) d eta by the same rule; G of each increment comes from
//! its [`SlopeTable`] (its density stored once: N^2 times the rule's nodes slopes per load). The
//! increments with their tables, and the collocation rows, are computed on all CPUs
//! ([`crate::numerics::parallel::map`]).
//!
//! [`load_rate`]: the same load with F's values and the node increments kept ([`LoadRate`]:
//! P'(eta) at any eta, for the row's fields of `row_fields.rs`); [`loads_below`]: P at several
//! lambdas from one collocation (the report's map with friction).
//!
//! [`verified_mpfr`]: two runs, (N, n, B) from [`knobs`] (N = digits/0.7 + 2 nodes, in `paper`'s
//! eta^2 and `periodic`'s eta, n = digits + 4 polynomials per family,
//! B = 3.33 (digits + 4 + 1.2 n) + 16 bits as for c/a in [`super::spectral_row`]) and
//! (N + 3, n + 4, B + 24); the printed digits are where they agree (P relative, c/a on the scale
//! 1), P's at most those its finer run's F resolves ([`LoadRate::tail_error`], a second
//! bound on the node error, conservative: section 17.8, "The tail rule"). Each node's stick edge is a secant search from
//! the `f64` root stopped once its error is below 10^-(digits/2 + 3) ([`root_mpfr_stationary`],
//! three solves): the outside slope is stationary in the stick edge at its root
//! (`spectral_row_tests.rs`, `outside_slope_is_stationary_in_the_stick_edge`), so its error is
//! that squared. c/a at lambda is a full root ([`increment_mpfr`]). beta = 0 takes N = 2 and 4
//! (F constant). Cost (section 17.8): one MPFR increment solve is most of a node (profile: MPFR
//! arithmetic and its allocations in the collocation rows' quadrature).
//!
//! [`root_mpfr_stationary`]: super::spectral_punch::root_mpfr_stationary

use rug::Float;

use super::quadrature::{graded, least_squares, DoubleExp};
use super::real::{Mp, Real};
use super::spectral::{Spectral, SpectralIncrement};
use super::spectral_row::{increment_f64, increment_mpfr, increment_mpfr_root, physical_ratio};
use super::spectral_row_slope::SlopeTable;
use crate::growing_contact::error::AdhesionError;
use crate::numerics::accuracy::{agreement_mpfr, digits_cap_for_bits, verified_digits_mpfr};
use crate::numerics::parallel::map;

/// The increment at contact eta: the method and the solved increment at its stick edge.
pub type RowIncrement<T> = (Spectral<T>, SpectralIncrement<T>);

/// P(lambda) = P2/(E* k (L/pi)^2) on `nodes` Chebyshev points, the increments at contact eta
/// from `increment_at` (with the exponent theta0 = atan(beta mu)/pi for the quadrature). The
/// increments, their slope tables and the collocation rows are computed on all CPUs.
pub fn load<T: Real + Send + Sync>(
    lambda: &T,
    theta0: f64,
    nodes: usize,
    increment_at: impl Fn(&T) -> Result<RowIncrement<T>, AdhesionError> + Sync,
) -> Result<T, AdhesionError> {
    load_with(lambda, theta0, nodes, NodeRule::Eta, increment_at)
}

/// The variable v(eta) in which F (and G cos(eta)) are interpolated: Chebyshev points and the
/// barycentric formula in v on (v(0), v(lambda)) (module doc).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NodeRule {
    /// v = eta: `periodic` (b = 1: the lateral strain b beta tau makes F neither even nor odd).
    Eta,
    /// v = eta^2: `paper` (b = 0: tau = tan(eta) enters (17.10) only as tau^2, F is even in eta).
    EtaSquared,
}

impl NodeRule {
    /// The rule of a surface convention: [`NodeRule::EtaSquared`] in `paper`, [`NodeRule::Eta`]
    /// in `periodic`.
    pub fn of_convention(periodic: bool) -> NodeRule {
        if periodic {
            NodeRule::Eta
        } else {
            NodeRule::EtaSquared
        }
    }

    /// v(x).
    pub fn variable<T: Real>(self, x: &T) -> T {
        match self {
            NodeRule::Eta => x.clone(),
            NodeRule::EtaSquared => x.clone() * x.clone(),
        }
    }
}

/// As [`load`], F interpolated in the variable of `rule` ([`NodeRule::of_convention`] of the
/// increments' convention; any rule is exact at beta = 0, where F is constant).
pub fn load_with<T: Real + Send + Sync>(
    lambda: &T,
    theta0: f64,
    nodes: usize,
    node_rule: NodeRule,
    increment_at: impl Fn(&T) -> Result<RowIncrement<T>, AdhesionError> + Sync,
) -> Result<T, AdhesionError> {
    Ok(load_rate(lambda, theta0, nodes, node_rule, increment_at)?.load)
}

/// P at each of `lambdas` (each in (0, `lambda`]) from the one collocation of [`load`] on
/// (0, `lambda`): the Volterra equation (17.11) on (0, chi) involves F on (0, chi) only, so the F
/// solved up to `lambda` gives P(lambda') = int_0^lambda' tan(eta) F(eta) d eta below it too (how
/// accurately, against a load solved at lambda' itself: `crates/report/src/friction_map.rs`).
pub fn loads_below<T: Real + Send + Sync>(
    lambda: &T,
    lambdas: &[T],
    theta0: f64,
    nodes: usize,
    node_rule: NodeRule,
    increment_at: impl Fn(&T) -> Result<RowIncrement<T>, AdhesionError> + Sync,
) -> Result<Vec<T>, AdhesionError> {
    Ok(collocate(lambda, lambdas, theta0, nodes, node_rule, increment_at)?.0)
}

/// The solved load of [`load`] with what the row's fields need (`row_fields.rs`): F at the
/// Chebyshev nodes, so P'(eta) = tan(eta) F(eta) at any eta in (0, lambda), and the increments
/// there.
#[derive(Debug, Clone)]
pub struct LoadRate<T> {
    /// P(lambda).
    pub load: T,
    /// The Chebyshev nodes eta_j of (0, lambda).
    pub nodes: Vec<T>,
    /// Their barycentric weights.
    pub weights: Vec<T>,
    /// F(eta_j).
    pub values: Vec<T>,
    /// The increments at the nodes (each at its own stick edge).
    pub increments: Vec<RowIncrement<T>>,
    /// The variable of the interpolation.
    pub rule: NodeRule,
    /// The estimated error of `load` from F's unresolved part: (|c_(N-2)| + |c_(N-1)|)
    /// (-ln cos lambda), c_k the Chebyshev coefficients of F in the rule's variable through its
    /// N node values (k >= 1), -ln cos lambda = int_0^lambda tan (section 17.8, "The verified
    /// load's digits").
    pub tail_error: T,
}

impl<T: Real> LoadRate<T> {
    /// The polynomial in the rule's variable through `values` at the nodes, evaluated at `e`
    /// (barycentric form).
    pub fn interpolate(&self, values: &[T], e: &T) -> T {
        Self::interpolate_at(&self.terms(e), values)
    }

    /// The barycentric terms at `e`, w_j/(v(e) - v(eta_j)) and their sum, or `Err(j)` where `e`
    /// is the node eta_j: what [`LoadRate::interpolate_at`] needs for any values at `e`.
    pub fn terms(&self, e: &T) -> Result<(Vec<T>, T), usize> {
        if let Some(k) = self.nodes.iter().position(|x| x == e) {
            return Err(k);
        }
        let ve = self.rule.variable(e);
        let mut den = e.lit(0.0);
        let terms = self
            .nodes
            .iter()
            .zip(&self.weights)
            .map(|(x, w)| {
                let t = w.clone() / (ve.clone() - self.rule.variable(x));
                den = den.clone() + t.clone();
                t
            })
            .collect();
        Ok((terms, den))
    }

    /// The interpolant through `values` from the [`LoadRate::terms`] at a point.
    pub fn interpolate_at(terms: &Result<(Vec<T>, T), usize>, values: &[T]) -> T {
        match terms {
            Err(k) => values[*k].clone(),
            Ok((terms, den)) => {
                let num = terms.iter().zip(values).fold(den.lit(0.0), |num, (t, v)| num + t.clone() * v.clone());
                num / den.clone()
            }
        }
    }

    /// P'(eta) = tan(eta) F(eta).
    pub fn rate(&self, e: &T) -> T {
        e.sin() / e.cos() * self.interpolate(&self.values, e)
    }
}

/// [`load`] with F and the increments kept ([`LoadRate`]).
pub fn load_rate<T: Real + Send + Sync>(
    lambda: &T,
    theta0: f64,
    nodes: usize,
    node_rule: NodeRule,
    increment_at: impl Fn(&T) -> Result<RowIncrement<T>, AdhesionError> + Sync,
) -> Result<LoadRate<T>, AdhesionError> {
    Ok(collocate(lambda, &[], theta0, nodes, node_rule, increment_at)?.1)
}

/// The collocation of (17.11) on (0, `lambda`): P at each of `lambdas` and the [`LoadRate`].
fn collocate<T: Real + Send + Sync>(
    lambda: &T,
    lambdas: &[T],
    theta0: f64,
    nodes: usize,
    node_rule: NodeRule,
    increment_at: impl Fn(&T) -> Result<RowIncrement<T>, AdhesionError> + Sync,
) -> Result<(Vec<T>, LoadRate<T>), AdhesionError> {
    let one = lambda.lit(1.0);
    let zero = lambda.lit(0.0);
    if let Some(x) = lambdas.iter().find(|x| !(**x > zero && **x <= *lambda)) {
        return Err(AdhesionError::InvalidArgument {
            parameter: "lambdas",
            value: format!("{:e}", x.to_f64()),
            expected: format!("0 < lambda' <= {:e} (the collocation's interval)", lambda.to_f64()),
        });
    }
    let pi = lambda.pi();
    let nf = lambda.lit(nodes as f64);
    // Chebyshev points of the first kind on (0, lambda) and their barycentric weights
    let mut eta = Vec::with_capacity(nodes);
    let mut bary = Vec::with_capacity(nodes);
    let mut thetas = Vec::with_capacity(nodes);
    for j in 0..nodes {
        let th = pi.clone() * lambda.lit((2 * j + 1) as f64) / (lambda.lit(2.0) * nf.clone());
        let s = (th.clone() * lambda.lit(0.5)).sin();
        // v_j = v(lambda) (1 - cos th)/2: eta = lambda s^2 (v = eta), lambda s (v = eta^2)
        eta.push(match node_rule {
            NodeRule::Eta => lambda.clone() * s.clone() * s,
            NodeRule::EtaSquared => lambda.clone() * s,
        });
        let sign = if j % 2 == 0 { one.clone() } else { -one.clone() };
        bary.push(sign * th.sin());
        thetas.push(th);
    }
    let incs: Vec<(RowIncrement<T>, SlopeTable<T>)> = map(&eta, |_, e| {
        increment_at(e).map(|(sp, inc)| {
            let table = SlopeTable::new(&sp, &inc);
            ((sp, inc), table)
        })
    })
    .into_iter()
    .collect::<Result<_, _>>()?;
    let cosines: Vec<T> = eta.iter().map(|e| e.cos()).collect();
    let v_nodes: Vec<T> = eta.iter().map(|e| node_rule.variable(e)).collect();
    // the Lagrange basis at e
    let basis = |e: &T| -> Vec<T> {
        let v = node_rule.variable(e);
        if let Some(k) = v_nodes.iter().position(|x| *x == v) {
            return (0..nodes).map(|j| if j == k { one.clone() } else { zero.clone() }).collect();
        }
        let terms: Vec<T> = (0..nodes).map(|j| bary[j].clone() / (v.clone() - v_nodes[j].clone())).collect();
        let sum = terms.iter().fold(zero.clone(), |a, t| a + t.clone());
        terms.into_iter().map(|t| t / sum.clone()).collect()
    };
    let rule = DoubleExp::new(&one, 0.5 + theta0);
    let rows = map(&eta, |_, chi| {
        let mut row = vec![zero.clone(); nodes];
        rule.sweep(chi, &graded(&zero, chi, None, None), |d_a, d_b, w| {
            let e = d_a.clone();
            // T - 1 = sin(chi - eta)/(cos(chi) sin(eta)), without cancellation
            let beyond = d_b.sin() / (chi.cos() * e.sin());
            // eta underflowing to 0 (f64 tail nodes): W eta -> 0 there
            if !(beyond > zero && beyond < one.lit(1e300)) {
                return;
            }
            let l = basis(&e);
            let g = incs.iter().zip(&l).zip(&cosines).fold(zero.clone(), |acc, ((((sp, inc), table), lj), cj)| {
                let slope = table.slope(&beyond).unwrap_or_else(|| sp.outside_slope(inc, &beyond));
                acc + lj.clone() * cj.clone() * slope
            });
            // W tan(eta) = G = (G cos(eta))/cos(eta), P' = tan(eta) F
            let k = w.clone() * g / e.cos();
            for (r, lj) in row.iter_mut().zip(&l) {
                *r = r.clone() + k.clone() * lj.clone();
            }
        });
        row
    });
    let rhs = eta.clone();
    let f = least_squares(rows, rhs).ok_or_else(|| AdhesionError::NotConverged {
        what: "periodic-row load (spectral Volterra collocation)",
        reason: "the collocation system is singular".into(),
    })?;
    let at = |upper: &T| {
        let mut p = zero.clone();
        rule.sweep(upper, &graded(&zero, upper, None, None), |d_a, _, w| {
            let l = basis(d_a);
            let fe = l.iter().zip(&f).fold(zero.clone(), |a, (lj, fj)| a + lj.clone() * fj.clone());
            p = p.clone() + w.clone() * d_a.sin() / d_a.cos() * fe;
        });
        p
    };
    let below = lambdas.iter().map(at).collect();
    let p = at(lambda);
    // F's last two Chebyshev coefficients, c_k = (2/N) sum_j F_j cos(k theta_j) (T_k at the
    // nodes up to the sign (-1)^k, which the magnitudes drop)
    let mut tail = zero.clone();
    for k in nodes.saturating_sub(2).max(1)..nodes {
        let mut c = zero.clone();
        for (th, fj) in thetas.iter().zip(&f) {
            c = c + (th.clone() * lambda.lit(k as f64)).cos() * fj.clone();
        }
        tail = tail + (c * lambda.lit(2.0) / nf.clone()).abs();
    }
    let tail_error = tail * -(lambda.cos().ln());
    let increments = incs.into_iter().map(|(inc, _)| inc).collect();
    Ok((below, LoadRate { load: p, nodes: eta, weights: bary, values: f, increments, rule: node_rule, tail_error }))
}

/// The row's load P and stick ratio c/a at one lambda with verified digits ([`verified_mpfr`]).
#[derive(Debug, Clone)]
pub struct VerifiedRowLoad {
    /// P(lambda) = P2/(E* k (L/pi)^2) (the finer run).
    pub load: Float,
    /// Digits where the two runs agree on P (relative).
    pub load_digits: f64,
    /// c/a at lambda (the finer run).
    pub stick_ratio: Float,
    /// Digits where the two runs agree on c/a (scale 1).
    pub stick_digits: f64,
    /// The `f64` run of the same method: P on 12 nodes, c/a with n = 10.
    pub load_f64: f64,
    /// See [`VerifiedRowLoad::load_f64`].
    pub stick_ratio_f64: f64,
    /// (Chebyshev nodes in eta, polynomials per family, bits) of the two runs.
    pub runs: [(usize, usize, u32); 2],
    /// Wall-clock seconds of the two runs.
    pub seconds: [f64; 2],
}

/// The knobs (nodes, n, bits) of the coarser run for `digits` (module doc) in the convention's
/// node rule ([`NodeRule::of_convention`]); the finer run adds (3, 4, 24). beta = 0 needs 2 nodes
/// (F is the constant pi, section 17.8).
pub fn knobs(digits: u32, incompressible: bool, periodic: bool) -> (usize, usize, u32) {
    // measured at lambda = 1.2 (section 17.8): successive node counts differ by a factor of
    // about 10^0.7 per node in eta (`periodic`); in eta^2 (`paper`) P converges by 10^1.05 but
    // F's Chebyshev coefficients, whose tail bounds the claim, by 10^0.7 (heuristic rates: the
    // second run and the tail check them)
    let per_node = 0.7;
    let nodes = if incompressible { 2 } else { (digits as f64 / per_node).ceil() as usize + 2 };
    // `periodic`'s tail (`LoadRate::tail_error`) gains only about 0.5 digits per node: 8.2 digits
    // at 14 nodes, 18.1 at 34 (section 17.8, "The tail rule"), so 20 digits need a finer run of
    // about 38 nodes; 2 digits - 4 in the coarser run leaves the finer one a node's margin
    let nodes = if periodic && !incompressible { nodes.max((2 * digits as usize).saturating_sub(4)) } else { nodes };
    let n = digits as usize + 4;
    let bits = (3.33 * (digits as f64 + 4.0 + 1.2 * n as f64) + 16.0).ceil() as u32;
    (nodes, n, bits)
}

/// The knobs of the finer (second) run: [`knobs`] plus (3, 4, 24), (2, 4, 24) at beta = 0; the
/// inputs of [`verified_mpfr`] need at least its bits.
pub fn finer_knobs(digits: u32, incompressible: bool, periodic: bool) -> (usize, usize, u32) {
    let (nodes, n, bits) = knobs(digits, incompressible, periodic);
    (nodes + if incompressible { 2 } else { 3 }, n + 4, bits + 24)
}

/// P(lambda) and c/a of the row in MPFR with verified digits (module doc): two runs, the
/// knobs of [`knobs`] and [`finer_knobs`]; `beta`, `mu`, `lambda` exact values of
/// the problem at a precision of at least that of the finer run.
pub fn verified_mpfr(
    beta: &Float,
    mu: &Float,
    lambda: &Float,
    periodic: bool,
    digits: u32,
) -> Result<VerifiedRowLoad, AdhesionError> {
    Ok(verified_mpfr_runs(beta, mu, lambda, periodic, digits, false)?.0)
}

/// As [`verified_mpfr`], the two runs' [`LoadRate`]s kept (coarser, finer) for the row's fields
/// (`row_fields::verified_row_fields`); with `full_roots` every node's stick edge is a full root
/// to 10^-(`digits` + 4), as c/a's, not the stationary one: the fields are first order in it
/// (docs/theory.md section 17.8, "The row's fields in MPFR").
pub fn verified_mpfr_runs(
    beta: &Float,
    mu: &Float,
    lambda: &Float,
    periodic: bool,
    digits: u32,
    full_roots: bool,
) -> Result<(VerifiedRowLoad, [LoadRate<Mp>; 2]), AdhesionError> {
    let lam = lambda.to_f64();
    let (b, m) = (beta.to_f64(), mu.to_f64());
    let theta0 = (b * m).atan() / std::f64::consts::PI;
    // the f64 run; its increments start the MPFR roots
    let (_, at_lambda) = increment_f64(b, m, lam, 10, periodic)?;
    let stick_ratio_f64 = if beta.is_zero() { 1.0 } else { physical_ratio(&at_lambda.gamma, &lam) };
    let node_rule = NodeRule::of_convention(periodic);
    let load_f64 = load_with(&lam, theta0, 12, node_rule, |e: &f64| increment_f64(b, m, *e, 10, periodic))?;
    let run = |(nodes, n, bits): (usize, usize, u32)| -> Result<(LoadRate<Mp>, Float, f64), AdhesionError> {
        let t = std::time::Instant::now();
        let args = (beta, mu, lambda);
        let at_node = |e: &Mp| {
            let eta = Float::with_val(bits, &e.0);
            let start = if beta.is_zero() { 0.5 } else { increment_f64(b, m, eta.to_f64(), 10, periodic)?.1.gamma };
            // the outside slope is stationary in the stick edge: half the digits suffice there
            let tol = if full_roots { digits + 4 } else { digits / 2 + 3 };
            increment_mpfr_root((beta, mu, &eta), periodic, (n, bits, tol), start, !full_roots)
        };
        let p = load_rate(&Mp(Float::with_val(bits, lambda)), theta0, nodes, node_rule, at_node)?;
        if beta.is_zero() {
            return Ok((p, Float::with_val(bits, 1), t.elapsed().as_secs_f64()));
        }
        let (_, inc) = increment_mpfr(args, periodic, (n, bits, digits + 4), at_lambda.gamma)?;
        let ratio = physical_ratio(&inc.gamma, &Mp(Float::with_val(bits, lambda))).0;
        Ok((p, ratio, t.elapsed().as_secs_f64()))
    };
    let coarse = knobs(digits, beta.is_zero(), periodic);
    let fine = finer_knobs(digits, beta.is_zero(), periodic);
    let (p1, c1, s1) = run(coarse)?;
    let (p2, c2, s2) = run(fine)?;
    let cap = digits_cap_for_bits(coarse.2);
    let load = VerifiedRowLoad {
        // at most the digits F's unresolved part leaves (section 17.8, "The tail rule": a
        // second bound on the node error beside the two runs' agreement)
        load_digits: agreement_mpfr(&p1.load.0, &p2.load.0, &p2.load.0, cap).min(verified_digits_mpfr(
            &p2.tail_error.0,
            &p2.load.0,
            cap,
        )),
        stick_digits: agreement_mpfr(&c1, &c2, &Float::with_val(64, 1), cap),
        load: p2.load.0.clone(),
        stick_ratio: c2,
        load_f64,
        stick_ratio_f64,
        runs: [coarse, fine],
        seconds: [s1, s2],
    };
    Ok((load, [p1, p2]))
}
