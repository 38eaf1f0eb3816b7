//! Problem 1 (steady sliding with friction, adhesive friction and wear; docs/theory.md sections 1-3):
//! two independent methods side by side, with parallel verbs (`solve`, `verify`, `physical`,
//! `solution`).
//!
//! - [`reduction_mpfr`]: the exact reduction [2.13]-[2.14] to one complex equation for
//!   (lambda, c), evaluated with MPFR at any precision, accuracy verified by a second run.
//!   Entry points [`solve_verified`] (digits requested) and [`solve_at`] (explicit precision).
//! - [`collocation_f64`]: Gauss–Jacobi collocation of the cot-kernel equation [2.8] in `f64`.
//! - [`series`]: the exact small-Lambda expansions [3.7]-[3.12] evaluated at the problem's
//!   parameters, with an estimated (not verified) error.
//!
//! Both read the derived parameters (kappa, theta, beta, k, l_s, units) from
//! [`crate::params::sliding`]. The entry points of the MPFR method are re-exported here.

pub mod collocation_f64;
pub mod physicality;
pub mod reduction_mpfr;
pub mod series;

pub use reduction_mpfr::{
    precision_for, solve_at, solve_verified, Accuracy, Checks, Convention, NodeRule, PressurePoint, SlidingError,
    SlidingSolution, VerifiedSolution,
};
