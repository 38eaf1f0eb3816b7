//! # exact_series: exact truncated power series
//!
//! The exact engine of `periodic-contact`: truncated power series in one variable whose
//! truncation order is part of the value ([`Series`]), over exact coefficient rings:
//!
//! - [`Q`]: rationals (num-rational 0.4 / num-bigint 0.4); products, inverses, log, exp, powers and
//!   reversions of `Series<Q>` with at least 24 coefficients run in common-denominator form over GMP
//!   integers (Kronecker-substitution products, Newton iterations, baby-step giant-step Lagrange
//!   reversion: FLINT's `fmpq_poly` methods) and give the same reduced rationals; with the
//!   optional cargo feature `flint` they call FLINT 3.5 itself (compiled from source; see
//!   docs/development.md);
//! - [`Poly`]: multivariate polynomials over Q in named [`Symbol`]s (theta, T, xh, eps, B, S, ...),
//!   in common-denominator form;
//! - [`Gaussian`]: the extension `R[i]`, i^2 = -1, of any of these;
//! - [`Frac`]: the field of fractions of [`Poly`] (reduced by a multivariate gcd).
//!
//! Operations: + - * / (a typed [`SeriesError`], never a panic, when the constant term is not
//! invertible), scalar operations, derivative, integral, composition, reversion, exp, log, sqrt,
//! power with a symbolic exponent, sin, cos, tan, sinc, z cot z, exact substitution of rationals
//! for symbols; printing as text, LaTeX and JSON. The crate knows no physics and no floats:
//! evaluation at `f64` / MPFR lives in the main crate.
//!
//! ```
//! use exact_series::{Poly, Ring, Series, Q};
//! // (sin x / x)^(1/2 + theta) and the reversion of x times it (THEORY.md, foundation issue).
//! let n = 8;
//! let alpha = Poly::var("theta").unwrap().add(&Poly::from_q(&Q::new(1.into(), 2.into())));
//! let f = Series::<Poly>::sinc_series(n).pow(&alpha).unwrap();
//! let rev = f.shift(1).truncate(n).revert().unwrap();
//! assert_eq!(
//!     rev.coeff(7).unwrap().text(),
//!     "49/1296*theta^3 + 91/1440*theta^2 + 1277/36288*theta + 263/40320"
//! );
//! ```

mod arith;
mod compose;
mod dense_q;
mod elementary;
mod error;
#[cfg(feature = "flint")]
mod flint_q;
mod frac;
mod gaussian;
mod gmp;
mod pade;
mod poly;
mod print;
mod ring;
mod symbol;
mod truncated;

pub use error::SeriesError;
pub use frac::Frac;
pub use gaussian::Gaussian;
pub use pade::Pade;
pub use poly::{Monomial, Poly};
pub use ring::{parse_rational, q_latex, q_text, rational_sqrt, Ring, Q};
pub use symbol::Symbol;
pub use truncated::Series;
