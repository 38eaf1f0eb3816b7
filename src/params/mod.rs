//! Derived parameters, computed once per problem from the exact model at the precision asked
//! (`f64` or MPFR) and passed as data to every solver, series evaluation, report section and
//! renderer (STYLE.md habit 16): Problem 1 ([`sliding`]: kappa, theta, beta, k, a0, l_s, T, units)
//! and Problem 2 ([`adhesion`]: eps, cosh(pi eps), B, S(eps), the half-range moments).
//!
//! Layer: model -> numerics -> params -> asymptotics -> solvers. Each formula for a derived
//! quantity is written here once per number type.

pub mod adhesion;
pub mod profile;
pub mod sliding;
