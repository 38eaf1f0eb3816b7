//! Method 1 (MPFR): Chebyshev collocation of the Volterra equation of the first kind of the
//! incremental method, docs/theory.md section 4 (Mossakovskii; the paper's (2.19) with a growing
//! contact).
//!
//! Writing P2 = E* k (L/pi)^2 P(lambda), P'(eta) = eta f(eta^2) and, at a given lambda,
//! F(tau) = f(lambda^2 tau) on tau in [0, 1], the equation
//! int_0^chi Re K(chi, eta) P'(eta) d eta = pi chi becomes, with eta = chi s and chi = lambda sigma
//! (see [`kernel`]),
//!   Re I(sigma) = pi,   I(sigma) = int_0^1 s w(s) G(lambda sigma, s) F(sigma^2 s^2) ds,
//! for sigma in (0, 1]. F is analytic on [0, 1] (its nearest singularity is at
//! tau = (pi/(2 lambda))^2, full contact; at eps = 0, f(t) = pi tan(sqrt t)/sqrt t), so a Chebyshev
//! interpolant in tau with n nodes converges like rho^-n, rho = z + sqrt(z^2 - 1),
//! z = 2 (pi/(2 lambda))^2 - 1. Collocation at the Chebyshev nodes tau_i = sigma_i^2, integrals by
//! tanh-sinh ([`crate::numerics::tanh_sinh`]), real n x n system by Gaussian elimination.
//! Then (docs/theory.md section 4):
//!   P2/(E* k a^2) = (1/2) int_0^1 F(tau) d tau,
//!   psi/(k a) = -(2 sigma/pi) Im I(sigma),
//!   phi/(k a^2) = -(1/pi) int_0^{sigma^2} Im I(sqrt tau) d tau,
//! and the stresses by [`kernel::stress_integrand`].
//! lambda = 0 is the single punch (G = 1, F = pi/Re M_1 constant: self-similar).
//! The `periodic` convention (docs/theory.md section 8, Problem 2) replaces the factor
//! cos(chi (1 - 2 i eps s)) of G by cos(chi (1 - 2 i eps s) + i pi eps)/cosh(pi eps)
//! ([`kernel::LateralShift`]); G is then not even in chi, and F is interpolated in sigma
//! (P'(eta) = eta F(eta/lambda), P2/(E* k a^2) = int_0^1 sigma F; [`volterra`]).
//! A general even profile (docs/theory.md section 9: even polynomial, circle) replaces the right side
//! pi by pi g'(x)/(2 k x), x = a sigma, k the reference curvature ([`right_side`]); the load, psi,
//! phi and the stresses follow from F by the same formulas. At nu = 1/2 its load equals THEORY 9's
//! closed form to ~1e-40 relative at 30 requested digits (quartic x^2/4 + x^4/2 and circle R = 2,
//! lambda = 0.2-1.1: `cargo test --test all adhesion_profiles:: -- --nocapture`).
//!
//! # Conditioning (measured; docs/theory.md section 7)
//! For nu = 1/2 (eps = 0) and nu >= 0.45 the method verifies 20+ digits up to lambda ~ 1.49.
//! For small nu it breaks down at a moderate contact size: verified digits of P2 at 20 requested
//! (`cargo run --release --example adhesion_charts -- conditioning`): nu = 0: 31 (lambda <= 0.47), 27 (0.63), 22 (0.79), 6 (0.94),
//! 2 (1.10), 0 beyond; nu = 0.3: >= 26 up to 1.26, 3 at 1.41, no convergence at 1.49.
//! Mechanism (a hypothesis supported by the following facts, not a proof): the kernel Re K is the
//! real part of an Abel kernel (chi - eta)^{-1/2 - i eps}, so on powers eta^{2n+1} the operator
//! acts, at lambda -> 0, by the factor Re M_{2n+1}; Re M_m changes sign at m ~ 605 for nu = 0
//! (m ~ 2285 for nu = 0.1, beyond 2e5 for nu = 0.3; computed from the recurrence for M_m), and the
//! phase of the near-diagonal coefficient cos(chi(1 - 2 i eps)) (sin 2 chi)^{i eps} grows with chi,
//! bringing the sign change down to low degrees as lambda grows: the first-kind equation then has
//! (near-)homogeneous solutions and the discrete problem loses digits without bound. The same
//! factor 1/Re M_{2n+1} enters the lambda^2 series (see [`crate::adhesion::series_f64`]).
//! A second chart (`cargo run --release --example adhesion_charts -- singularity`, 200-bit runs) reads
//! the decay rate of the Chebyshev coefficients of F on [0, lambda^2] and the real singularity it
//! would imply (nu = 0.3: eta_s ~ 1.43-1.45; nu = 0: 0.86-1.04, drifting with lambda). That reading
//! is not confirmed by the long series: the ratio analysis of 300 verified coefficients
//! ([`crate::asymptotics::adhesion_singularity`], docs/theory.md section 11) finds no fixed
//! singularity below nu = 1/2 (the local estimate drifts with the order and tracks the phase of
//! M_(2j+1)). The loss of digits is steady in lambda (nu = 0: 17.5 verified digits at lambda = 0.8,
//! 8.1 at 0.9, 4.7 at 1.0 with 20 asked), and more requested digits do not recover it (nu = 0,
//! lambda = 1: 4.4, 3.5, 3.4 at 20, 30, 40). The cause is settled in
//! [`crate::asymptotics::adhesion_mode`]: below nu = 1/2 the incremental problem has a homogeneous
//! solution H ~ eta^m* (Re M_m* = 0; m* = 605.73 at nu = 0), so the two runs, each satisfying the
//! equation to its precision, pick different multiples of H; no formulation removes that.
//! [`verify::solve_verified`] reports the loss (fewer verified digits, and a typed error below 2 digits).

//!
//! # Files
//! [`kernel`] (the regularised kernels), [`row_factors`] (their material-free factors on the
//! collocation rows, shared across solves), [`solve`](mod@solve) (discretisation and collocation solve at one
//! lambda), [`volterra`] (the dimensionless solution and its evaluations), [`solution`]
//! (dimensional results from the exact problem, the half-width for a given load), [`verify`] (two
//! runs, verified digits). The f64 method has the same files in [`crate::adhesion::series_f64`].

pub mod kernel;
pub mod right_side;
pub mod row_factors;
pub mod solution;
pub mod solve;
pub mod verify;
pub mod volterra;

pub use right_side::RightSide;
pub use solve::{
    chebyshev_size, chebyshev_size_in, solve, solve_rhs, solve_rhs_in, solve_with_nodes, solve_with_nodes_in,
    solve_with_nodes_rhs, VolterraParams, MAX_NODES,
};
pub use volterra::{lambda_of, VolterraSolution};
