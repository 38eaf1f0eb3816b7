//! Numerical methods: quadrature rules, evaluation of exact objects in `f64` and MPFR.

pub mod accuracy;
pub mod evaluate;
pub mod exact;
pub mod gauss_jacobi_f64;
pub mod gauss_jacobi_mpfr;
pub mod precision;
pub mod roots;
