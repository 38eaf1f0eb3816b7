//! The growing contact of Problem 2, shared by complete adhesion ([`crate::adhesion`]) and the
//! loading law ([`crate::loading_law`]) (docs/theory.md sections 4 and 10):
//! - [`kernel`]: the increments on an off-centre contact in MPFR (the unit flat punch and its
//!   surface slopes on both sides, the left side checked against the direct cot-kernel
//!   quadrature) and the `periodic` convention's tilted punch (closed form in the tangent
//!   variable, checked the same way);
//! - [`kernel_f64`], [`chebyshev_f64`]: the same kernels written anew in `f64` (checked against
//!   [`kernel`]) and the Chebyshev series of the march;
//! - [`march`]: block-by-block marching in the contact size in `f64` (the loading law's second
//!   method; one block of it is complete adhesion's f64 collocation beyond its series);
//! - [`error`]: the one error type of the Problem 2 solvers.

pub mod chebyshev_f64;
pub mod error;
pub mod kernel;
pub mod kernel_f64;
pub mod march;
