//! Problem 2 with finite friction (docs/theory.md section 17): a central stick zone and Coulomb
//! slip at the ends of a growing contact, normal loading.
//!
//! Built so far: the single punch with the parabola ([`single_punch`]): the self-similar
//! solution's stick ratio c/a and load coefficient P/(E* k a^2) by two `f64` methods on the
//! shared graded [`mesh`]: [`increment_f64`] (the unit increment bounded at the stick edge, the load
//! from the slope at the moving edge) and [`state_f64`] (the current state, the stick edge from
//! the slip rate, the load by integration). Checked in `tests.rs`: Hertz's pi/2 at beta = 0 and as
//! mu -> 0, the uncoupled problem against K'(gamma)/K(gamma) = beta/mu, the boundary-element
//! c/a = 0.5219(1) at nu = 0, mu = 1/2, the two methods against each other, the approach to complete
//! adhesion's C_P as mu grows, and the inequalities of the state. [`fields`]: q1, q2, psi at
//! points, superposed from the unit increments, and the checks of the inequalities from the state.
//!
//! The spectral method ([`spectral`], generic over `f64` and MPFR through [`real`], with the
//! composite tanh-sinh rules and least squares of [`quadrature`]; driver [`spectral_punch`]) solves
//! the same increment with the exponents (17.3) in its basis: gamma and C_P with verified digits
//! (docs/theory.md section 17.7; checks in `spectral_tests.rs`); the increment's fields are
//! `spectral::fields`, and [`spectral_punch_fields`] superposes the single punch's q1, q2, psi
//! and its checks from them, in `f64` or MPFR (the two verified runs: verified digits).
//!
//! The periodic row ([`row_f64`]: the increment at (lambda, c) on the row's kernel, both
//! conventions; [`row_load_f64`]: the load marched in lambda on two discretisations), and by the
//! spectral method in the tangent variable ([`spectral_row`]: the increment and c/a in `f64` and
//! MPFR with verified digits; [`spectral_row_load`]: the load from the Volterra equation (17.11)
//! at high order, generic, and in MPFR with verified digits; [`spectral_row_slope`]: the outside
//! slope of one increment from a stored table; checks in `spectral_row_tests.rs`); [`row_fields`]:
//! the row's q1, q2, psi and the checks of its inequalities, superposed from the load's increments
//! (checks in `row_fields_tests.rs`).
//!
//! Scenes with `[adhesion] friction` reach these through `solve` (`src/solve/answer_friction.rs`,
//! `src/solve/answer_friction_row.rs`, docs/theory.md section 17.5): the single punch by f64 or by
//! the spectral method in MPFR (`--method mpfr`, the fields too), the row by the spectral method
//! in f64 and, given `half_width`, by its verified MPFR load (`spectral_row_load::verified_mpfr`;
//! with points its two runs' node increments solved to full stick-edge roots and the fields
//! superposed from each, `row_fields::verified_row_fields`).

pub mod fields;
pub mod increment_f64;
pub mod mesh;
pub mod quadrature;
pub mod real;
pub mod row_f64;
pub mod row_fields;
pub mod row_load_f64;
pub mod single_punch;
pub mod spectral;
pub mod spectral_punch;
pub mod spectral_punch_fields;
pub mod spectral_row;
pub mod spectral_row_load;
pub mod spectral_row_slope;
pub mod state_f64;

#[cfg(test)]
mod row_fields_tests;
#[cfg(test)]
mod spectral_row_tests;
#[cfg(test)]
mod spectral_tests;
#[cfg(test)]
mod tests;
