//! Working precision: digits asked -> bits, and the guard bits, named once.
//!
//! Precision is an argument, never a global (STYLE.md habit 2): every MPFR routine takes `prec`
//! (bits) as its last argument. The guard bits below are the only ones in the project; each says
//! what it guards.

/// Guard bits of a solver's working precision over the bits of the requested digits: covers the
/// cancellation of the quadrature sums and of the root finding (measured: the verified digits of
/// both problems exceed the requested digits by 5-10 at every lambda of the stability maps).
pub const SOLVER_GUARD_BITS: u32 = 32;

/// Extra bits of a verification run over the first run (a second run must be more accurate than
/// the first for its difference to measure the first run's error).
pub const VERIFY_EXTRA_BITS: u32 = 32;

/// Guard bits of a closed-form constant evaluated once (eps, B, S(eps), M_m): a few operations,
/// each rounding once.
pub const CONSTANT_GUARD_BITS: u32 = 24;

/// Guard bits of the evaluation of a long exact series or recurrence at a point (hundreds of terms
/// with alternating signs: the cancellation grows with the order).
pub const SERIES_GUARD_BITS: u32 = 64;

/// Working precision in bits for `digits` decimal digits: ceil(digits log2 10) + [`SOLVER_GUARD_BITS`].
pub fn precision_for(digits: u32) -> u32 {
    bits_for_digits(digits) + SOLVER_GUARD_BITS
}

/// A working precision from `wanted` down to `least` bits that MPFR serves on fewer limbs: its
/// fast paths for n 64-bit limbs (`mpfr_mul_2`, `mpfr_add1sp2`, ...) take precisions below
/// 64 n, so the largest such precision in [`least`, `wanted`] when there is one below `wanted`'s
/// limb count, else `wanted` (the loading law's second run: 131 -> 127 bits at 20 digits).
pub(crate) fn below_limb_boundary(least: u32, wanted: u32) -> u32 {
    let fewer = (wanted.saturating_sub(1) / 64) * 64;
    if fewer > least {
        fewer - 1
    } else {
        wanted
    }
}

/// ceil(digits log2 10): the bits that hold `digits` decimal digits.
pub(crate) fn bits_for_digits(digits: u32) -> u32 {
    (digits as f64 * std::f64::consts::LOG2_10).ceil() as u32
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 131 bits (3 limbs) with 123 needed become 127 (2 limbs); 107 stays (already 2 limbs); 140
    /// with 140 needed stays; 64 (one limb) stays.
    #[test]
    fn precision_below_a_limb_boundary() {
        assert_eq!(below_limb_boundary(123, 131), 127);
        assert_eq!(below_limb_boundary(100, 107), 107);
        assert_eq!(below_limb_boundary(140, 140), 140);
        assert_eq!(below_limb_boundary(128, 131), 131);
        assert_eq!(below_limb_boundary(60, 64), 64);
    }

    #[test]
    fn bits_for_thirty_digits() {
        // 30 log2 10 = 99.66
        assert_eq!(bits_for_digits(30), 100);
        assert_eq!(precision_for(30), 132);
        assert_eq!(precision_for(0), SOLVER_GUARD_BITS);
    }
}
