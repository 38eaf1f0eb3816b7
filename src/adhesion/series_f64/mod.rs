//! Method 2 (`f64`): the Volterra equation of docs/theory.md section 4 solved as a power series in
//! lambda^2 ("collocation in lambda^2"), independent of the Chebyshev collocation of method 1.
//!
//! With P'(eta) = eta f(eta^2), f(t) = sum_n f_n t^n, and the Taylor expansion in chi^2 of the
//! regular kernel factor G(chi, s) = sum_m g_m(s) chi^{2m} ([`kernel`]; g_0 = 1), the
//! equation Re int_0^1 s w(s) G(chi, s) f(chi^2 s^2) ds = pi is triangular:
//!   sum_{j+m=n} f_j Re mu_{j,m} = pi delta_{n0},   mu_{j,m} = int_0^1 s^{2j+1} w(s) g_m(s) ds,
//! (mu_{j,0} = M_{2j+1}, the half-range moments of docs/theory.md section 5, so f_0 = pi/Re M_1 and
//! C_P = f_0/2). The g_m(s) are computed at each quadrature node as Taylor coefficients of
//! G(., s) (series log/exp/cos in f64 at that node, no expansion in powers of s, which would
//! cancel catastrophically), the mu by tanh-sinh. Then, with c_n = sum_{j+m=n} f_j mu_{j,m},
//!   P2/(E* k a^2) = (1/2) sum_n f_n lambda^{2n}/(n+1),
//!   psi/(k a) = -(2 sigma/pi) sum_n (lambda sigma)^{2n} Im c_n,
//!   phi/(k a^2) = -(1/pi) sum_n lambda^{2n} Im c_n sigma^{2n+2}/(n+1),
//! and the stresses by f64 tanh-sinh of the integral of [`kernel`] with this f.
//! At eps = 0 the series in lambda^2 converges for lambda < pi/2 (f = pi tan(sqrt t)/sqrt t).
//! For eps > 0 it does not have that radius: all f_n are positive but the ratios f_{n-1}/f_n keep
//! decreasing (nu = 0: 1.20 at n = 20, 0.99 at 40, 0.85 at 60, 0.69 at 89; nu = 0.3: 2.12, 2.08,
//! 2.05, 2.01; nu = 0.45: 2.4365 -> 2.4344; asserted by `series_ratios_quoted_in_the_module_doc`,
//! printed by `cargo run --release --example adhesion_charts -- series-ratios`), and the recursion divides by Re M_{2n+1}, which
//! changes sign at n ~ 302 for nu = 0: the series is at best slowly convergent, possibly only
//! asymptotic, at small nu. The method computes [`SERIES_TERMS`] coefficients, truncates where
//! the terms fall below 1e-18 of the largest, and returns `IllConditioned` when lambda^2 is not
//! well inside the observed ratio (lambda <= ~0.74 at nu = 0, ~1.2 at nu >= 0.3).
//!
//! A general even profile (docs/theory.md section 9) replaces the right side pi by
//! pi g'(x)/(2 k x) = pi sum_n r_n tau^n, tau = (x/a)^2 ([`right_side`]: a polynomial for an even
//! polynomial punch, the binomial series of the circle), and the recursion is solved directly in
//! tau for the contact at hand ([`solve::solve_rhs`]): F_n = f_n lambda^{2n},
//!   sum_{j+m=n} F_j lambda^{2m} Re mu_{j,m} = pi r_n,
//! which at lambda = 0 (single punch) is F_n = pi r_n/Re M_{2n+1}, THEORY 9's power law for
//! g = A x^(2n). The formulas above hold with f_n lambda^{2n} -> F_n, c_n lambda^{2n} -> C_n.

//!
//! # Files
//! [`kernel`] (the integrands in `f64`), [`series`] (the universal coefficients f_n, mu_{j,m},
//! once per material), [`right_side`] (a general even profile's right side as a series in
//! (x/a)^2, docs/theory.md section 9), [`solve`](mod@solve) (truncation at one lambda, dimensionless values), [`solution`]
//! (dimensional results from the exact problem), [`verify`] (the accuracy estimate by a second,
//! finer run). The MPFR method has the same files in [`crate::adhesion::volterra_mpfr`].

pub mod kernel;
pub mod right_side;
pub mod series;
pub mod solution;
pub mod solve;
pub mod verify;

pub use right_side::RightSeries;
pub use series::{universal_coefficients, SeriesParams, UniversalSeries, SERIES_TERMS};
pub use solve::{solve, solve_nominal, solve_rhs, SeriesSolution, SERIES_LAMBDA_MAX};
