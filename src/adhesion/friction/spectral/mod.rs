//! The spectral method for the single punch's unit increment (docs/theory.md section 17.7,
//! equations (17.7), (17.9)) and the periodic row's (section 17.8, (17.10)), generic over `f64`
//! and MPFR ([`Real`]): the problem's constants ([`Spectral`], built by [`Spectral::new`],
//! [`Spectral::row`] and the options [`Spectral::oversampled`], [`Spectral::narrow`]) and the
//! increment solved at one stick half-width ([`Spectral::solve`], [`SpectralIncrement`]) with
//! its stick-edge defect.
//!
//! With a = 1, E* k = 1, H\[f\](x) = (1/pi) PV int_-1^1 f(xi)/(x - xi) dxi, the increment
//! s = s2 + i s1 (s2 even, s1 odd) at stick half-width gamma solves the derivatives of (17.7),
//!     H\[s2\] - beta s1 = 0 on (0, 1),   H\[s1\] + beta s2 = 0 on (0, gamma),
//!     s1 = mu s2 on (gamma, 1),   int_-1^1 s2 = 1,
//! (the constants of (17.7) are the free descent v0 and, by oddness, zero), with the exponents
//! alpha = -1/2 - theta0, omega = -1/2 + theta0, tan(pi theta0) = beta mu of (17.2)/(17.3) in
//! its basis: 6 n unknowns, collocated and solved in the least-squares sense. The stick-edge
//! defect is the coefficient of |x - gamma|^alpha in r = s1 - mu s2 on the stick side,
//! sum S_k - mu sum Q_k (up to the positive factor (2 gamma)^alpha... of r's leading term); the
//! self-similar gamma is its zero (17.3: the increment bounded at gamma), found by the callers
//! (`spectral_punch.rs`, `spectral_row.rs`). `coupled = false` drops beta s1 from the first
//! equation (the uncoupled problem, theta0 = 0).
//!
//! The periodic row ([`Spectral::row`], section 17.8, (17.10)) is the same problem in the tangent
//! variable T = tan(chi)/tan(lambda): the stick condition gains the constant
//! (1/pi) int s1 tau^2 T/(1 + tau^2 T^2) and the right side b beta tau/pi, the normalisation the
//! weight 1/(1 + tau^2 T^2) (tau = tan(lambda)), and the slip zone's Chebyshev variable is
//! logarithmic in T + gamma.
//!
//! The parts, one concept a child module (each reads this module's private fields; none names a
//! sibling that names it):
//! - `basis.rs`: the basis (the stick and slip zones' families, their per-gamma constants, one
//!   node's values in reused storage);
//! - `collocation.rs`: the collocation points, the rows of the Cauchy integrals (the Hilbert
//!   rows), the row's constant and the normalisation: [`Spectral::system`];
//! - `narrow.rs`: the option for narrow slip zones (large mu, section 17.3 "Large mu");
//! - `density.rs`: s2 of a solved increment at many points ([`Density`]) and the load
//!   coefficient C_P of (17.9) ([`Spectral::load_coefficient`]);
//! - [`fields`]: the solved increment's fields (the densities at a point, the outside slope, the
//!   tangential strain).
//!
//! Checked in `spectral_tests.rs` (the single punch: the boundary elements and the two `f64`
//! methods of section 17.4, nu = 1/2 exactly Hertz, the uncoupled problem against Spence and
//! Johnson's K'/K, `f64` against MPFR and the verified values, the narrow option against the MPFR
//! table of section 17.3) and `spectral_row_tests.rs` (the row: the flat punch at beta = 0,
//! lambda -> 0 against the single punch, the march of `row_f64`).

use super::quadrature::{least_squares, DoubleExp};
use super::real::Real;

mod basis;
mod collocation;
mod density;
pub mod fields;
mod narrow;

use basis::Zones;
// the collocation point, named by the child `fields` as `super::Target`
use collocation::Target;
pub use density::Density;

/// Collocation points per zone in `f64`, in units of 2 n + 2 (the number of unknowns per
/// equation and zone, plus 2). The basis is a frame, not a basis: the smooth and the singular
/// family of one density (P and Q of s2 on the stick zone, A and B on the slip zone) are nearly
/// dependent (each family alone: condition number 2-10; the pair 1e8, 1e11, 1e14 at n = 6, 8,
/// 10), and such a least-squares problem is stable only when oversampled (docs/theory.md section
/// 17.7). MPFR keeps 1: its guard bits absorb the conditioning and its verified values stand.
pub const F64_OVERSAMPLE: usize = 3;

/// The increment at one gamma, solved.
#[derive(Debug, Clone)]
pub struct SpectralIncrement<T> {
    /// Stick half-width.
    pub gamma: T,
    /// Coefficients [P, Q, R, S, A, B], n each.
    pub coeffs: Vec<T>,
    n: usize,
    mu: T,
    alpha: T,
    omega: T,
    zones: Zones<T>,
}

/// The problem's constants at one precision.
#[derive(Debug, Clone)]
pub struct Spectral<T> {
    beta: T,
    beta_normal: T,
    mu: T,
    alpha: T,
    omega: T,
    n: usize,
    rule: DoubleExp<T>,
    /// tan(lambda) of the periodic row in the tangent variable (zero: the single punch).
    tau: T,
    /// The right side of the stick condition, b beta tau/pi (zero: the single punch, `paper`).
    lateral: T,
    /// The slip zone's Chebyshev variable logarithmic in x + gamma (the row) or linear.
    log_slip: bool,
    /// Collocation points per zone: `oversample` (2 n + 2).
    oversample: usize,
    /// The stick zone resolved on the scale 1 - gamma ([`Spectral::narrow`]).
    narrow: bool,
}

impl<T: Real> Spectral<T> {
    /// The method for Poisson parameter `beta`, friction `mu` (given at the working precision)
    /// with n polynomials per family.
    pub fn new(beta: T, mu: T, n: usize, coupled: bool) -> Spectral<T> {
        let beta_normal = if coupled { beta.clone() } else { beta.lit(0.0) };
        let theta0 = (beta_normal.clone() * mu.clone()).atan() / beta.pi();
        let half = beta.lit(0.5);
        let edge = (0.5 - theta0.to_f64()).min(1.0);
        let rule = DoubleExp::new(&beta.lit(1.0), edge);
        let (tau, lateral) = (beta.lit(0.0), beta.lit(0.0));
        let oversample = if beta.bits() == 53 { F64_OVERSAMPLE } else { 1 };
        Spectral {
            alpha: -half.clone() - theta0.clone(),
            omega: -half + theta0,
            beta,
            beta_normal,
            mu,
            n,
            rule,
            tau,
            lateral,
            log_slip: false,
            oversample,
            narrow: false,
        }
    }

    /// The same method collocated at `factor` (2 n + 2) points per zone (the default: 1 in MPFR,
    /// [`F64_OVERSAMPLE`] in `f64`).
    pub fn oversampled(mut self, factor: usize) -> Spectral<T> {
        self.oversample = factor.max(1);
        self
    }

    /// The same problem with `n` polynomials per family and 2 n + 2 points per zone: a cheap
    /// run whose stick-edge root brackets this one's (`spectral_punch::root_f64`).
    pub fn coarse(&self, n: usize) -> Spectral<T> {
        Spectral { n, oversample: 1, ..self.clone() }
    }

    /// The method for the periodic row at lambda = pi a/L in the tangent variable
    /// T = tan(chi)/tan(lambda) (docs/theory.md section 17.8, (17.10)): `tau` = tan(lambda),
    /// `periodic` the convention (b = 1).
    pub fn row(beta: T, mu: T, n: usize, tau: T, periodic: bool) -> Spectral<T> {
        let mut sp = Spectral::new(beta, mu, n, true);
        let b = sp.beta.lit(if periodic { 1.0 } else { 0.0 });
        sp.lateral = b * sp.beta.clone() * tau.clone() / tau.pi();
        sp.tau = tau;
        sp.log_slip = true;
        sp
    }

    /// Solves for the increment at stick half-width `gamma` in (0, 1); None when the
    /// least-squares system is singular.
    pub fn solve(&self, gamma: &T) -> Option<SpectralIncrement<T>> {
        let (rows, rhs) = self.system(gamma);
        let coeffs = least_squares(rows, rhs)?;
        Some(self.increment(gamma, coeffs))
    }

    /// The increment with given coefficients.
    pub fn increment(&self, gamma: &T, coeffs: Vec<T>) -> SpectralIncrement<T> {
        SpectralIncrement {
            gamma: gamma.clone(),
            coeffs,
            n: self.n,
            mu: self.mu.clone(),
            alpha: self.alpha.clone(),
            omega: self.omega.clone(),
            zones: Zones::new(gamma),
        }
    }

    /// The tanh-sinh rule of the method's integrals.
    pub fn rule(&self) -> &DoubleExp<T> {
        &self.rule
    }

    /// tan(lambda) of the row (zero: the single punch).
    pub fn tau(&self) -> T {
        self.tau.clone()
    }

    /// The Poisson parameter beta (the stick condition's; the normal equation drops it when
    /// uncoupled).
    pub fn beta(&self) -> T {
        self.beta.clone()
    }

    /// The friction coefficient mu.
    pub fn mu(&self) -> T {
        self.mu.clone()
    }

    /// The working precision (bits).
    pub fn bits(&self) -> u32 {
        self.beta.bits()
    }
}

impl<T: Real> SpectralIncrement<T> {
    /// The coefficient of w^alpha in r = s1 - mu s2 on the stick side at gamma (up to a positive
    /// factor): zero at the self-similar gamma.
    pub fn stick_edge_defect(&self) -> T {
        let n = self.n;
        let c = &self.coeffs;
        let zero = self.gamma.lit(0.0);
        let q = (0..n).fold(zero.clone(), |acc, k| acc + c[n + k].clone());
        let s = (0..n).fold(zero, |acc, k| acc + c[3 * n + k].clone());
        s - self.mu.clone() * q
    }

    /// Exponents (alpha, omega) of the basis.
    pub fn exponents(&self) -> (T, T) {
        (self.alpha.clone(), self.omega.clone())
    }
}
