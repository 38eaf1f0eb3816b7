//! Problem 2 with a loading law P1 = N(P2) (THEORY.md section 10; issue 12): the contact
//! [-a, b] grows at both ends. Built so far (not yet reachable from scenes or the CLI):
//! - [`kernel`]: the increments on an off-centre contact (the unit flat punch and its surface
//!   slopes on both sides; the left side checked against the direct cot-kernel quadrature) and
//!   the `periodic` convention's tilted punch (closed form in the tangent variable, checked the
//!   same way);
//! - [`collocation`]: the MPFR method for the linear law in both conventions, the two
//!   moving-edge conditions as a nonlinear Volterra system (Chebyshev collocation, chord Newton);
//!   checked: n = 0 gives section 4's symmetric load (1.3e-34 with 32 nodes), nu = 1/2 decouples
//!   (centred contact, Kuznetsov's load);
//! - [`fields`]: psi (frozen at entry) and q2 + i q1 from the increments, checked by the
//!   independent residual test: the stresses put into the surface relations [1.8] (direct
//!   principal-value quadrature of the cot kernel) reproduce v' = g' and u' = psi on the
//!   asymmetric contact (n = 1/5, nu = 0.3) to 1e-16 in both conventions, and carry the load.
//!
//! - [`kernel_f64`], [`marching`], [`verified_f64`]: the second, independent method in `f64`
//!   (block-by-block marching in lambda, its own kernels; two runs for the digits), reachable by
//!   `solve --method f64`; agrees with the MPFR method to 15-16 digits at nu = 0.3
//!   (tests/loading_law_agreement.rs); at nu <= 0.1 both methods fail (marching.rs, Stability).
//!
//! Still to come (issue 12): phi; polynomial laws and profiles; verified digits (two runs); the
//! given-load search; scenes, CLI, report; the asymptotic expansion.

pub mod chebyshev_f64;
pub mod collocation;
pub mod fields;
pub mod kernel;
pub mod kernel_f64;
pub mod marching;
pub mod verified;
pub mod verified_f64;
