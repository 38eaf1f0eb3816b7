//! Numerical methods: quadrature rules, evaluation of exact objects in `f64` and MPFR.
pub mod exact;
pub mod gauss_jacobi_mpfr;
