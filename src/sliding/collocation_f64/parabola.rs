//! The parabola g = k x^2 (periodic or single): the state at fixed contact size, with c explicit,
//! and the scalar equation P2(lambda) = P2 of the periodic inverse problem.

use super::closure::{closed, tau0_side};
use super::error::{root_error, Result, SlidingF64Error};
use super::interpolant::{basis, Rhs, State};
use super::operator::{collocation, Collocation};
use super::tangent_map::{Map, LAMBDA_MAX};
use crate::numerics::accuracy::readable_f64;
use crate::numerics::roots::{brent, Bracket};
use crate::params::sliding::SlidingParamsF64;
use std::cell::RefCell;
use std::f64::consts::PI;

/// Parabola at fixed lambda (or l): RHS E* k (x(u) - c); the constant E* k c is absorbed in K,
/// so G does not depend on c, and the solvability condition K_total = C0 - beta tau0 gives
/// c = C0[G] - K - beta tau0/(E* k) (docs/theory.md section 3: lambda does not depend on tau0, c explicit).
/// In the `periodic` convention beta tau0 -> beta tau0 + K (`closure.rs`): c moves by -K/(E* k).
pub(super) fn parabola_state(col: &Collocation, prm: &SlidingParamsF64, map: Map) -> Result<State> {
    let b = closed(prm, &map, basis(col, &map, |u| map.offset(u))?);
    let s = prm.e_star * prm.k;
    let c = b.cond - tau0_side(prm, &map) / s;
    Ok(State { map, c, g: b.g.iter().map(|v| v * s).collect(), p2: s * b.p2, rhs: Rhs::Offset { s } })
}

/// Starting value of lambda for the periodic parabola: Kuznetsov's cos(lambda) =
/// exp(-(pi a0/L)^2/2) [2.15] with a0 replaced by the single-punch l_s = a0/sqrt(1 - 4 theta^2)
/// [3.10] ([`SlidingParamsF64::l_s`]), written as lambda = 2 asin(sqrt(-expm1(-z)/2)) to keep
/// small z accurate.
pub(super) fn kuznetsov_guess(prm: &SlidingParamsF64, big_l: f64, p2: f64) -> f64 {
    let z = 0.5 * (PI * prm.l_s(p2) / big_l).powi(2);
    (2.0 * (0.5 * -(-z).exp_m1()).sqrt().asin()).min(LAMBDA_MAX - 1e-3).max(1e-300)
}

/// Parabola, given P2, periodic: solve P2(lambda) = P2 (monotone) with Brent; start from the
/// Kuznetsov relation cos(lambda) = exp(-(pi l_s/L)^2/2) with the single-punch l_s
/// (docs/theory.md sections 3.6, 6).
///
/// `near`: a lambda already solved at other nodes; the bracket then starts at +-1e-7 relative
/// around it (a few Brent steps instead of a dozen).
pub(super) fn parabola_lambda(prm: &SlidingParamsF64, big_l: f64, p2: f64, n: usize, near: Option<f64>) -> Result<f64> {
    let col = collocation(prm.theta, n)?;
    // Every state evaluated, by lambda: Brent returns one of them (`remember_root`).
    let seen = RefCell::new(Vec::new());
    let f = |lam: f64| -> Result<f64> {
        let st = parabola_state(&col, prm, Map::periodic(big_l, lam))?;
        let v = (st.p2 / p2).ln();
        seen.borrow_mut().push((lam.to_bits(), st));
        Ok(v)
    };
    let lam = bracket_and_solve(prm, big_l, p2, n, near, f)?;
    remember_root(prm, n, big_l, lam, seen.into_inner());
    Ok(lam)
}

/// The state at the root of the last [`parabola_lambda`] on this thread, with everything it
/// depends on (the parameters, n, L, lambda), so that [`periodic_parabola_state`] returns it
/// instead of solving the same system again.
struct RootState {
    prm: SlidingParamsF64,
    n: usize,
    big_l: u64,
    lambda: u64,
    state: State,
}

thread_local! {
    static ROOT: RefCell<Option<RootState>> = const { RefCell::new(None) };
}

fn remember_root(prm: &SlidingParamsF64, n: usize, big_l: f64, lam: f64, seen: Vec<(u64, State)>) {
    let state = seen.into_iter().rev().find(|(bits, _)| *bits == lam.to_bits()).map(|(_, st)| st);
    ROOT.with(|r| {
        *r.borrow_mut() =
            state.map(|state| RootState { prm: prm.clone(), n, big_l: big_l.to_bits(), lambda: lam.to_bits(), state })
    });
}

/// [`parabola_state`] of the periodic parabola at lambda with `col` = the operator of
/// (prm.theta, n): the remembered root state when it is this one (the same numbers: the same
/// function of the same inputs), else computed.
pub(super) fn periodic_parabola_state(
    col: &Collocation,
    prm: &SlidingParamsF64,
    big_l: f64,
    lam: f64,
) -> Result<State> {
    let hit = ROOT.with(|r| {
        r.borrow().as_ref().and_then(|m| {
            (m.n == col.n() && m.big_l == big_l.to_bits() && m.lambda == lam.to_bits() && m.prm == *prm)
                .then(|| m.state.clone())
        })
    });
    match hit {
        Some(st) => Ok(st),
        None => parabola_state(col, prm, Map::periodic(big_l, lam)),
    }
}

/// The bracket and Brent's method of [`parabola_lambda`] on f = ln(P2(lambda)/P2).
fn bracket_and_solve(
    prm: &SlidingParamsF64,
    big_l: f64,
    p2: f64,
    n: usize,
    near: Option<f64>,
    f: impl Fn(f64) -> Result<f64>,
) -> Result<f64> {
    let (guess, width) = match near {
        Some(l) => (l, 1e-7),
        None => (kuznetsov_guess(prm, big_l, p2), 0.05),
    };
    let mut step = width * guess;
    // Approach pi/2 geometrically: P2(lambda) at lambda ~ pi/2 needs more nodes than n.
    let up = |from: f64, step: f64| (guess + step).min(from + 0.5 * (LAMBDA_MAX - from)).max(from);
    let (mut lo, mut hi) = (guess - step, up(guess, step));
    let (mut flo, mut fhi) = (f(lo)?, f(hi)?);
    let mut it = 0;
    while flo > 0.0 {
        hi = lo;
        fhi = flo;
        step *= 8.0;
        lo = if guess - step > 0.0 { guess - step } else { 0.5 * lo };
        flo = f(lo)?;
        it += 1;
        if it > 400 {
            return Err(SlidingF64Error::NoConvergence { reason: "could not bracket lambda from below".into() });
        }
    }
    let fraction = || readable_f64(2.0 * LAMBDA_MAX / PI);
    while fhi < 0.0 {
        if hi >= LAMBDA_MAX * (1.0 - 1e-12) {
            return Err(SlidingF64Error::NoConvergence {
                reason: format!(
                    "the load P2 = {} needs a contact fraction above {} (or more than {n} nodes; for theta != 0 the contact may also leave the cell (-L/2, L/2))",
                    readable_f64(p2),
                    fraction()
                ),
            });
        }
        lo = hi;
        flo = fhi;
        step *= 8.0;
        let next = up(hi, step);
        if next <= hi {
            return Err(SlidingF64Error::NoConvergence {
                reason: format!(
                    "could not bracket lambda for P2 = {} below the contact fraction {}",
                    readable_f64(p2),
                    fraction()
                ),
            });
        }
        hi = next;
        fhi = f(hi)?;
    }
    brent(f, Bracket { a: lo, b: hi, fa: flo, fb: fhi }, 1e-16 * hi).map_err(root_error)
}
