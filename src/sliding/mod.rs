//! Problem 1 (steady sliding with friction, adhesive friction and wear) at high precision:
//! the exact reduction of THEORY.md section 3 evaluated with MPFR (rug).
//!
//! The contact [-a, b] of a parabolic (g = k x^2) or sinusoidal (g = D (1 - cos(2 pi x/L)) [2.16])
//! punch, periodic with period L or single (L = infinity), under the load P2 (inverse problem) or
//! for a given half-length l (direct problem). The canonical equation [2.8]
//!     kappa p + H[p] = (E*/2) g' + beta tau0,  theta = arctan(kappa)/pi,
//! reduces to one complex equation for (lambda, c) [2.14] ([`equation`]) and the pressure formula
//! [2.13] ([`pressure`]), both evaluated with Gauss–Jacobi rules at working precision
//! ([`crate::numerics::gauss_jacobi_mpfr`]).
//!
//! Entry points: [`solve_verified`] (digits requested, accuracy verified by a second run) and
//! [`solve_at`] (explicit precision and node rule).
//!
//! The fast f64 method, an independent Gauss–Jacobi collocation of the cot-kernel equation, is
//! [`collocation_f64`].
//!
//! Files: `setup` (inputs at precision), `contact` (the map x(u) and the slope basis), `equation`
//! ([2.14] and the centre), `pressure` ([2.13], gap slope, integrals of p), `physical` (p >= 0,
//! gap >= 0), `solve` (locating and refining the contact), `verify` (two runs), `solution`, `error`.
//!
//! Conventions. By default the paper's (THEORY.md's) convention is used. Two consequences found
//! here (derivations in [`setup::Convention`] and [`physical`], numerical proofs in the tests
//! `paper_convention_gap_mismatch`, `outside_displacement_formula`):
//! - with tau0 > 0 the step of q1 at the contact ends puts a slope -2 beta tau0/E* into the gap just
//!   outside the leading edge, so the strict gap >= 0 fails there for every tau0 > 0, beta > 0; the
//!   physicality check leaves that term out;
//! - the surface does not close over a period: the gap gains M = (2/E*) beta P1 - cW P2 per period.
//!   The opt-in [`Convention::PeriodicSurface`] adds K = (kappa P2 - 2 beta l tau0)/L to the right
//!   side of [2.8], which closes it (M = 0, checked to 1e-20). Under it the sinusoid's load curve
//!   with friction or wear (tau0 = 0) is monotone and physical up to lambda ~ 1.52 (charted), while
//!   under the paper's convention it is not monotone and loses physicality (gap, then p at the
//!   trailing end) before its maximum.
//!
//! Independent checks (tests): closed forms of THEORY.md section 6 (Kuznetsov, Westergaard, Hertz)
//! to 30-40 digits; single-punch limit [3.10]; the returned p satisfies the original cot-kernel
//! equation [2.8] to ~1e-35 (direct tanh-sinh quadrature, no tangent map); P2 = int p dx by a
//! separate rule; direct vs inverse problem.

pub mod collocation_f64;
pub mod contact;
pub mod equation;
pub mod error;
pub mod physical;
pub mod pressure;
pub mod setup;
pub mod solution;
pub mod solve;
pub mod verify;
pub mod series;

pub use error::SlidingError;
pub use setup::Convention;
pub use solution::{Accuracy, PressurePoint, SlidingSolution, VerifiedSolution};
pub use solve::{solve_at, NodeRule};
pub use verify::{precision_for, solve_verified, solve_verified_with};

#[cfg(test)]
mod tests;
