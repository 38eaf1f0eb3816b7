//! Numerical methods: quadrature rules (Gauss-Jacobi, tanh-sinh), Chebyshev interpolation, root
//! finding, evaluation of exact objects in `f64` and MPFR, the accuracy rule.

pub mod accuracy;
pub mod chebyshev;
pub mod complex_series;
pub(crate) mod elementary;
pub mod evaluate;
pub mod exact;
pub(crate) mod fixed_float;
pub mod gauss_jacobi_f64;
pub mod gauss_jacobi_mpfr;
pub(crate) mod mp_elementary;
pub(crate) mod mp_rounded;
pub mod pade;
pub mod parallel;
pub mod precision;
pub mod real_series;
pub mod roots;
pub(crate) mod sin_cos_f64;
pub mod tanh_sinh;
