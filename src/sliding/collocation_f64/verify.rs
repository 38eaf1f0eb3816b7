//! The accuracy estimate of the f64 method: a second ("check") run with n + max(8, n/4) nodes,
//! compared quantity by quantity with the main run on the scales of the accuracy rule.

use super::candidates::{state_of, Candidate};
use super::error::Result;
use super::operator::collocation;
use super::outputs::{outputs, Outputs};
use super::solution::{AccuracyEstimate, PerQuantity, Quantity, Scales};
use crate::params::sliding::SlidingScale;
use crate::params::sliding::{SlidingParamsF64, TargetF64};

/// Nodes of the check run: n + max(8, n/4). The error falls by tan(lambda/2)^{n/4} or more, so
/// the difference estimates the main run's error (cheaper than 1.5 n: the LU is O(n^3)).
pub(super) fn check_nodes(n: usize) -> usize {
    n + (n / 4).max(8)
}

/// Runs the check (re-solving the scalar equation in lambda at the check nodes when P2 is given)
/// and returns the differences to the main run `out` (at `n` nodes) on the scales l, P2, k l P2
/// and max p.
pub(super) fn check_run(
    prm: &SlidingParamsF64,
    target: TargetF64,
    cand: Candidate,
    out: &Outputs,
    n: usize,
    points: &[f64],
) -> Result<AccuracyEstimate> {
    let n2 = check_nodes(n);
    let col2 = collocation(prm.theta, n2)?;
    let cand2 = match cand {
        Candidate::Sinusoid { branch, .. } => Candidate::Sinusoid { lambda: out.lambda, branch },
        other => other,
    };
    let st2 = state_of(prm, target, cand2, n2, true)?;
    let out2 = outputs(&col2, prm, &st2, points);
    let l = out.l;
    let grid = out.grid_p.iter().zip(&out2.grid_p).map(|(p, q)| (p - q).abs());
    let p = out.pressure.iter().zip(&out2.pressure).map(|(p, q)| (p.p - q.p).abs()).chain(grid).fold(0.0f64, f64::max);
    // In the order of Quantity::ALL.
    let differences = PerQuantity(
        [
            out.l - out2.l,
            out.a - out2.a,
            out.b - out2.b,
            out.c - out2.c,
            out.p1 - out2.p1,
            out.p2 - out2.p2,
            out.f_def - out2.f_def,
            p,
        ]
        .map(f64::abs),
    );
    let scale = |q: SlidingScale| q.f64(prm.k, l, out.p2, out.max_p);
    let scales = Scales {
        length: scale(SlidingScale::Length),
        load: scale(SlidingScale::Load),
        f_def: scale(SlidingScale::DeformationForce),
        pressure: scale(SlidingScale::Pressure),
    };
    let d = |q: Quantity| differences[q];
    Ok(AccuracyEstimate {
        geometry: d(Quantity::A).max(d(Quantity::B)).max(d(Quantity::C)) / l,
        pressure: d(Quantity::Pressure) / out.max_p,
        load: d(Quantity::P2).max(d(Quantity::P1)) / out.p2,
        f_def: d(Quantity::FDef) / scales.f_def,
        check_nodes: n2,
        differences,
        scales,
    })
}
