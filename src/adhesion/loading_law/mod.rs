//! Problem 2 with a loading law P1 = N(P2) (THEORY.md section 10; issue 12): the contact
//! [-a, b] grows at both ends. Built so far (not yet reachable from scenes or the CLI):
//! - [`kernel`]: the increments on an off-centre contact (the unit flat punch and its surface
//!   slopes on both sides; the left side checked against the direct cot-kernel quadrature);
//! - [`collocation`]: the MPFR method for the linear law in the `paper` convention, the two
//!   moving-edge conditions as a nonlinear Volterra system (Chebyshev collocation, chord Newton);
//!   checked: n = 0 gives section 4's symmetric load (1.3e-34 with 32 nodes), nu = 1/2 decouples
//!   (centred contact, Kuznetsov's load).
//!
//! Still to come (issue 12): psi, phi, q1, q2 from the increments; the `periodic` convention's
//! rotation increment; polynomial laws; the independent f64 method; the residual check in [1.8];
//! scenes, CLI, report.

pub mod collocation;
pub mod kernel;
