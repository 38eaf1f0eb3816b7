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
//! Scenes with `[adhesion] friction` reach [`single_punch`] through `solve`
//! (`src/solve/answer_friction.rs`, docs/theory.md section 17.5). Not built (issue 32): the MPFR
//! method with verified digits, the periodic row.

pub mod fields;
pub mod increment_f64;
pub mod mesh;
pub mod row_f64;
pub mod row_load_f64;
pub mod single_punch;
pub mod state_f64;

#[cfg(test)]
mod tests;
