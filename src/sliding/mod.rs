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
//! Files: `setup` (inputs at precision), `contact` (the map x(u) and the slope basis), `equation`
//! ([2.14] and the centre), `pressure` ([2.13], gap slope, integrals of p), `physical` (p >= 0,
//! gap >= 0), `solve` (locating and refining the contact), `verify` (two runs), `solution`, `error`.
//!
//! Conventions kept from THEORY.md (paper's symmetric summation). Two consequences found here and
//! documented in [`physical`]: with tau0 > 0 the step of q1 at the contact ends puts a slope
//! -2 beta tau0/E* into the gap just outside the leading edge (so the strict gap >= 0 fails for
//! every tau0 > 0 and beta > 0; the check leaves that term out), and v is not periodic (mean of
//! (E*/2) v' over a period is -beta P1/L; a periodic v would add (kappa P2 - 2 beta l tau0)/L to the
//! right side of [2.8], an odd-in-lambda change of c). See the report of the branch `sliding-mpfr`.

pub mod contact;
pub mod equation;
pub mod error;
pub mod physical;
pub mod pressure;
pub mod setup;
pub mod solution;
pub mod solve;
pub mod verify;

pub use error::SlidingError;
pub use solution::{Accuracy, PressurePoint, SlidingSolution, VerifiedSolution};
pub use solve::{solve_at, NodeRule};
pub use setup::Convention;
pub use verify::{precision_for, solve_verified, solve_verified_with};

#[cfg(test)]
mod tests;
