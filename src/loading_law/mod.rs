//! Problem 2 with a loading law P1 = N(P2) (docs/theory.md section 10; issue 12): the contact
//! [-a, b] grows at both ends, in a periodic row or on a single punch ([`crate::growing_contact::kernel::Row`]):
//! - the kernels of the growing contact and the f64 march are one layer down, in
//!   [`crate::growing_contact`] (complete adhesion's f64 collocation uses them too);
//! - [`increment`]: the setting and the increment at one precision, shared by the residual and
//!   its Jacobian;
//! - [`collocation`]: the MPFR method for linear and polynomial laws in both conventions, the two
//!   moving-edge conditions as a nonlinear Volterra system (Chebyshev collocation, Newton with
//!   the closed-form Jacobian of `jacobian`, then chord steps with its `f64` twin);
//!   checked: n = 0 gives section 4's symmetric load (1.3e-34 with 32 nodes), nu = 1/2 decouples
//!   (centred contact, Kuznetsov's load);
//! - [`fields`]: psi (frozen at entry) and q2 + i q1 from the increments, checked by the
//!   independent residual test: the stresses put into the surface relations [1.8] (direct
//!   principal-value quadrature of the cot kernel) reproduce v' = g' and u' = psi on the
//!   asymmetric contact (n = 1/5, nu = 0.3) to 1e-16 in both conventions, and carry the load.
//! - [`verified`]: dimensional values (a, b, c, P1, P2, psi, phi, q1, q2) with digits from two
//!   runs, a given half-length or normal load, periodic row or single punch.
//! - [`ends`]: the stresses at the ends (sigma ~ C (d/l)^(1/2 -+ i eps)), the tension zones of
//!   the oscillating singularity and the friction complete adhesion needs against the distance;
//! - [`verified_f64`]: the second, independent method in `f64`, on the march of
//!   [`crate::growing_contact::march`]
//!   (block-by-block marching in lambda, its own kernels; two runs for the digits), reachable by
//!   `solve --method f64`; agrees with the MPFR method to 15-16 digits at nu = 0.3
//!   (tests/all/loading_law_agreement.rs); at small nu (below about 0.15) a given size is one block
//!   (the blocks' own error grows there until an end recedes), which agrees with the MPFR method
//!   at nu = 0, n = 1/5, l/L = 1/16 and 1/8 to 15.7-17 digits and refuses where the mode has
//!   grown. At small nu and larger n both methods meet the problem's homogeneous modes
//!   eta^mu* ([`crate::asymptotics::loading_law_modes`]: the history is fixed only up to C
//!   eta^mu*, and a discretisation's error at small sizes grows like (Lambda/eta)^mu*).

pub mod collocation;
pub mod ends;
pub mod fields;
pub mod increment;
mod jacobian;
pub mod verified;
pub mod verified_f64;
