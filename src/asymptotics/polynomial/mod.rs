//! Exact series for polynomial punches g = sum_j c_j x^j (docs/theory.md section 9, issue 11): the
//! profile and its exact parameters ([`profile`]), Problem 1 in both conventions ([`sliding`]),
//! Problem 2 for even profiles ([`adhesion`]).

pub mod adhesion;
pub mod profile;
pub mod sliding;

pub use adhesion::{polynomial_adhesion_expansion, PolynomialAdhesionExpansion};
pub use profile::PolynomialProfile;
pub use sliding::{
    polynomial_sliding_expansion, polynomial_sliding_expansion_at, FixedValues, PolynomialSlidingExpansion,
};

#[cfg(test)]
mod tests;
