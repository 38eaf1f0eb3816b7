//! Fast `f64` solution of Problem 1 (steady sliding with friction, adhesive friction and wear) by
//! Gauss–Jacobi collocation of the cot-kernel singular integral equation.
//!
//! # Equation (docs/theory.md section 3, the paper's [2.8])
//! On the contact (-a, b), with H the periodic Hilbert operator of docs/theory.md section 2,
//!
//! ```text
//! kappa p + H[p] = (E*/2) g' + beta tau0,   kappa = E* cW/2 - beta mu,  theta = atan(kappa)/pi,
//! ```
//!
//! p bounded at both ends. In the `periodic` convention (docs/theory.md section 8; the problem's
//! [`crate::model::SlidingProblem::convention`]) beta tau0 is replaced by beta tau0 + K,
//! K = (kappa P2 - 2 beta l tau0)/L (`closure.rs`). The tangent map t = tan(pi (x - c)/L) = m u, m = tan(lambda), turns H
//! into the finite Cauchy operator in u plus the constant (docs/theory.md section 2)
//! C0\[p\] = (1/pi) int_{-1}^{1} p(u') m^2 u'/(1 + m^2 u'^2) du'. For a single punch
//! (L = infinity) u = (x - c)/l and C0 = 0 (`tangent_map.rs`).
//!
//! # Discretisation [reconstructed; independent of the exact reduction of docs/theory.md section 3]
//! p(u) = omega(u) G(u), omega = (1+u)^{1/2+theta} (1-u)^{1/2-theta}, G a polynomial of degree
//! n - 1 represented by its values G_k at the n nodes t_k of the Gauss–Jacobi rule of omega
//! (weights W_k). The constant part of the equation is an unknown K:
//!
//! ```text
//! kappa p(u) + (1/pi) PV int p(u')/(u - u') du' + K = F(u),   F = (E*/2) g'(x(u)) (shape part),
//! ```
//!
//! collocated at the n + 1 zeros x_r of P_{n+1}^{(-alpha,-beta)} (alpha = 1/2 - theta,
//! beta = 1/2 + theta), where the singular Gauss–Jacobi formula is exact for polynomial G of
//! degree <= 2n and the kappa-term cancels (Erdogan, Gupta & Cook 1973):
//!
//! ```text
//! sum_k W_k G_k / (pi (x_r - t_k)) + K = F(x_r),   r = 0..n.
//! ```
//!
//! The (n+1) x (n+1) matrix depends on (theta, n) only, never on (lambda, c): it is LU-factored
//! once and cached per thread (`operator.rs`). The two side conditions are then
//!
//! ```text
//! K = C0[p] - beta tau0      (solvability: the constant of the true equation),
//! P2 = int p dx = sum_k W_k G_k x'(t_k),   x'(u) = (L/pi) m/(1 + m^2 u^2)  (or l).
//! ```
//!
//! Since F is affine in c for the parabola (F = E* k (c + x(u) - c)) and linear in
//! (cos 2 pi c/L, sin 2 pi c/L) for the sinusoid, both conditions are solved for c in closed form
//! at fixed lambda, and only a scalar equation in lambda remains (Brent's method on a bracket,
//! [`crate::numerics::roots::brent`]); no 2D Newton iteration is needed. For the parabola lambda
//! does not depend on tau0 and c is explicit (docs/theory.md section 3; `parabola.rs`). For the sinusoid
//! the scalar equation is X(lambda)^2 + Y(lambda)^2 = 1, (X, Y) = (cos, sin)(2 pi c/L) from the
//! 2x2 linear system of the side conditions; all its roots are found by a scan and refined, which
//! handles the non-monotone P2(lambda) for theta != 0 (`sinusoid.rs`).
//!
//! # Accuracy
//! The quadrature error behaves like tan(lambda/2)^{2n} (docs/theory.md section 3). Between the nodes G
//! is evaluated by the Nyström interpolant of the collocation equation (`interpolant.rs`), not by
//! polynomial interpolation: its error follows the quadrature, tan(lambda/2)^{2n} (observed rate
//! asserted in the test `convergence_in_the_number_of_nodes`), where the degree n-1 interpolant
//! only gives tan(lambda/2)^n. The number of nodes is chosen from that rate
//! ([`collocation_nodes`]), and the result carries the difference to a second run with
//! n + max(8, n/4) nodes (`verify.rs`, [`AccuracyEstimate`]), stated as digits per quantity by
//! [`SlidingSolutionF64::digits`] under the project's one accuracy rule
//! ([`crate::numerics::accuracy::verified_digits`]).
//! Measured with `cargo run --release --example collocation_f64_charts -- convergence` (automatic
//! nodes, P2 given, lambda <= 1.3): a within 7e-16 of Kuznetsov and Westergaard (scale l), the
//! Westergaard p within 7e-15 (scale max p), error estimates 2e-15..8e-15; the single punch is
//! exact up to rounding (the data are linear in u, G is constant). The tests assert 1e-12 for the
//! same closed forms (`kuznetsov_periodic_parabola`, `westergaard_sinusoid`).
//!
//! # Findings (probed with `cargo run --release --example collocation_f64_charts -- all`)
//! - Sinusoid with theta != 0: P2(lambda) rises to a maximum and falls; a load below the maximum
//!   is reached twice, and on the branch past the maximum p < 0 at the leading end (theta > 0) or
//!   the trailing end (theta < 0) (`-- two-roots`, `-- load-curve`). So at most one physical
//!   solution was found in every case tried; above the largest physical load the refusal quotes
//!   the admissible range (`admissible.rs`, the shared [`crate::sliding::physicality`]; e.g.
//!   0.426 pi E* D at theta = 0.148, asserted between 0.40 and 0.45 by the test
//!   `sinusoid_with_wear_matches_exact_reduction_and_reports_maximum_load`).
//! - Gap: with the paper's convention (the default) v is not periodic, so the free surface does not close over a
//!   period: h(L - a) - h(b) = (2 beta/E*) P1 - cW P2 (measured by the shared criterion,
//!   `physicality.closure_defect`); with tau0 > 0, v' jumps by 2 beta tau0/E* at the ends (the
//!   criterion leaves that step out and reports it). In the `periodic` convention the surface
//!   closes (the defect is round-off).
//! - lambda -> pi/2 needs n ~ ln(1e14)/(2 ln cot(lambda/2)) nodes (381 at lambda = 1.5276,
//!   about 60 ms; `-- hard-cases`); beyond `max_nodes` the solver reports non-convergence.
//!   theta -> +-1/2 costs digits in the rules of 1/omega (estimate 2.5e-13 at theta = 0.4936,
//!   3e-11 at 0.4999; `-- hard-cases`; the test `theta_near_one_half_single_punch` asserts 1e-11).
//! - Small P2 with tau0 > 0: c -> -beta tau0/(E* k) + 2 theta l, as the single-punch limit says;
//!   no difficulty down to P2 = 1e-8 (test
//!   `small_load_with_adhesive_friction_drifts_to_minus_beta_tau0_over_e_k`).
//!
//! # Cost
//! `cargo run --release --example collocation_f64_charts -- convergence` (2 shared cores, load
//! ~4.5): n = 67 nodes at lambda = 1.3; per case, check run and physicality check included,
//! 0.2-0.7 ms with the rules and LU cached (a sweep), 0.4-2.5 ms from an empty cache (dominated by
//! the O(n^2) rules and the O(n^3) LU; `-- build-cost`).
//!
//! # Files
//! Inputs: [`crate::params::sliding::SlidingParamsF64`] (built once per solve and passed down);
//! `profile.rs` (g' of the periodic extension), `tangent_map.rs` (x(u), its Jacobian, the weight of
//! C0), `operator.rs` (rules, LU-factored matrix, cache, node count), `interpolant.rs` (unit bases,
//! discrete states, the Nyström interpolant), `parabola.rs` and `sinusoid.rs` (the scalar equation
//! in lambda per shape), `general.rs` (a polynomial or circular punch, docs/theory.md section 9: F(u) =
//! (E*/2) g'(x(u)) collocated directly, the centre by Newton's method in c with the g'' basis
//! giving the derivative, P2(size) = P2 by Brent), `candidates.rs` (every root at the main run's nodes), `outputs.rs` (l, a, b,
//! c, P1, P2, F_def, p of a state), `physical.rs` (p >= 0, gap), `admissible.rs` (the admissible range
//! its refusals quote), `verify.rs` (the check run), `solve.rs` (the driver), `solution.rs` (result
//! types), `error.rs`. The MPFR method of the same problem is [`crate::sliding`] (parallel verbs:
//! solve, verify, physical, solution).

mod admissible;
mod candidates;
mod closure;
mod error;
mod general;
mod interpolant;
mod operator;
mod outputs;
mod parabola;
mod physical;
mod profile;
mod sinusoid;
mod solution;
mod solve;
mod tangent_map;
mod verify;

pub use error::SlidingF64Error;
pub use operator::{clear_cache, collocation_nodes, Collocation};
pub use solution::{
    AccuracyEstimate, PerQuantity, PressurePoint, Quantity, Scales, SlidingSolutionF64, SlidingSolutionsF64,
    SolverOptions,
};
pub use solve::{candidate_roots, solve_sliding_f64, solve_sliding_f64_with, CandidateRoot};

#[cfg(test)]
mod tests;
