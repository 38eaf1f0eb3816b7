//! Statement of the two contact problems (docs/theory.md sections 1, 3, 4): exact inputs only.
//!
//! Every number here is an exact rational read from its text (a decimal or a ratio), so that it
//! reaches MPFR rounded once at the working precision and never passes through `f64`.
//! Validation happens when a problem is built ([`ModelError`] names the parameter, its value and
//! the valid range); solvers may assume a validated problem.

pub mod adhesion;
pub mod error;
pub mod loading_law;
pub(crate) mod material;
pub(crate) mod punch;
pub(crate) mod row;
pub mod sliding;

pub use adhesion::{AdhesionProblem, AdhesionSize, FRICTION_RANGE};
pub use error::{readable, ModelError};
pub use loading_law::{LawSize, LoadingLaw, LoadingLawProblem};
pub use material::Material;
pub use punch::{Period, PunchShape};
pub use row::{OnPunchRow, PunchRow};
pub use sliding::{Convention, SlidingLoad, SlidingProblem, SlidingProblemBuilder};

/// Exact input number (a reduced rational).
pub type Exact = num_rational::BigRational;
