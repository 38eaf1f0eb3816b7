//! The kernel series Z(z) = z cot z (docs/theory.md section 5; the paper's [3.2]).
//!
//! (pi/L) cot(pi (x - xi)/L) = Z(lambda (xh - xih)) / (x - xi), so the periodic kernel is the
//! Cauchy kernel times Z, an even series whose coefficients are
//! (-1)^k 2^(2k) B_(2k) / (2k)! (DLMF 4.19.6).

use exact_series::{Series, Q};

/// Z(z) = z cot z through z^order (`order + 1` coefficients), exact over Q.
pub fn kernel_series(order: usize) -> Series<Q> {
    Series::zcot_series(order + 1)
}
