//! Problem 1 at high precision: the exact reduction of docs/theory.md section 3 evaluated with MPFR (rug).
//!
//! The contact [-a, b] of a parabolic (g = k x^2), sinusoidal (g = D (1 - cos(2 pi x/L)) [2.16]),
//! polynomial (g = sum_j c_j x^j) or circular (g = R - sqrt(R^2 - x^2)) punch (docs/theory.md section 9),
//! periodic with period L or single (L = infinity), under the load P2 (inverse problem) or
//! for a given half-length l (direct problem). The canonical equation [2.8]
//!     kappa p + H\[p\] = (E*/2) g' + beta tau0,  theta = arctan(kappa)/pi,
//! reduces to one complex equation for (lambda, c) [2.14] ([`equation`]) and the pressure formula
//! [2.13] ([`pressure`]), both evaluated with Gauss–Jacobi rules at working precision
//! ([`crate::numerics::gauss_jacobi_mpfr`]).
//!
//! Entry points: [`solve_verified`] (digits requested, accuracy verified by a second run) and
//! [`solve_at`] (explicit precision and node rule). Both take the problem as given and return
//! loads, stresses, F_def and p(x) in its units; inside, the solver works in units of E*
//! ([`crate::params::sliding::SlidingParamsMpfr`], built once per precision by [`setup`]), so that
//! moduli and loads beyond the `f64` range reach its `f64` locating stage.
//!
//! Files: `setup` (the parameters of one solve, once per precision), `contact` (the map x(u) and
//! the slope basis), `equation` ([2.14] and the centre), `pressure` ([2.13], gap slope, integrals
//! of p), `physical` (p >= 0, gap >= 0), `solve` (locating and refining the contact), `scan`
//! (the sinusoid's load-curve scan of the locating stage), `verify`
//! (two runs), `solution`, `error`; for a polynomial or circular punch (docs/theory.md section 9)
//! `profile` (g', g'' evaluated directly), `centre` (the centre by Newton's method) and
//! `locate_profile`; `bracket` holds the locating stage's shared pieces.
//!
//! Conventions. By default the paper's (docs/theory.md's) convention is used; the problem's
//! [`crate::model::SlidingProblem::convention`] selects it. Two consequences found here
//! (derivations in [`Convention`] and [`physical`], numerical proofs in the tests
//! `paper_convention_gap_mismatch`, `outside_displacement_formula`):
//! - with tau0 > 0 the step of q1 at the contact ends puts a slope -2 beta tau0/E* into the gap just
//!   outside the leading edge, so the strict gap >= 0 fails there for every tau0 > 0, beta > 0; the
//!   physicality check leaves that term out;
//! - the surface does not close over a period: the gap gains M = (2/E*) beta P1 - cW P2 per period.
//!   The opt-in [`Convention::PeriodicSurface`] adds K = (kappa P2 - 2 beta l tau0)/L to the right
//!   side of [2.8], which closes it (M = 0, checked to 1e-20 by `paper_convention_gap_mismatch`).
//!   Under it the sinusoid's load curve with friction (tau0 = 0) has one physical solution beyond
//!   the paper convention's maximum load (test `periodic_surface_convention`), while under the
//!   paper's convention it is not monotone and loses physicality (gap, then p at the trailing end)
//!   before its maximum (test `non_monotone_sinusoid`). Both curves are charted by
//!   `cargo run --release --example reduction_mpfr_explore -- load-curve [--periodic-surface]`.
//!
//! Independent checks (tests): closed forms of docs/theory.md section 6 (Kuznetsov, Westergaard, Hertz)
//! to 30-40 digits; single-punch limit [3.10]; the returned p satisfies the original cot-kernel
//! equation [2.8] to 1e-30 relative to E* k l (direct tanh-sinh quadrature, no tangent map);
//! P2 = int p dx by a separate rule; direct vs inverse problem.

pub(crate) mod bracket;
mod branches;
pub mod centre;
pub mod contact;
pub mod equation;
pub mod error;
pub(crate) mod locate_profile;
mod nodes;
pub mod physical;
pub mod pressure;
pub mod profile;
pub(crate) mod scan;
pub mod setup;
pub mod solution;
pub mod solve;
pub mod verify;

pub use crate::model::Convention;
pub use error::SlidingError;
pub use solution::{Accuracy, PressurePoint, SlidingSolution, VerifiedSolution};
pub use solve::{physicality_at_contact, refusal_for, solve_at, Checks, NodeRule};
pub use verify::{precision_for, solve_verified};

#[cfg(test)]
mod tests;
