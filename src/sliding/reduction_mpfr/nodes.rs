//! How many Gauss-Jacobi nodes the MPFR reduction uses at a contact size: the error model of
//! docs/theory.md section 3 (the quadrature error behaves like tan(lambda/2)^(2n)), its inverse
//! (the largest size a node count reaches) and the node counts rounded up to the rule cache's
//! buckets. Tested in `tests.rs` (`lambda_cap` against `nodes_for`).

/// Error model (docs/theory.md section 3): the quadrature error behaves like tan(lambda/2)^(2n), so
/// n = (digits + 4) ln 10 / (-2 ln tan(lambda/2)), at least 8 (a single punch, lambda = 0, needs few:
/// the integrands are polynomials for the parabola). Heuristic margin of 4 digits for the constant.
pub fn nodes_for(lambda: f64, digits: f64) -> usize {
    if lambda <= 0.0 {
        return 8;
    }
    let r = -(lambda / 2.0).tan().ln();
    if r <= 0.0 {
        return usize::MAX;
    }
    let n = ((digits + 4.0) * std::f64::consts::LN_10 / (2.0 * r)).ceil();
    if n > 1e9 {
        usize::MAX
    } else {
        (n as usize).max(8)
    }
}

/// Largest lambda for which `nodes_for(lambda, digits) <= nmax`.
pub(super) fn lambda_cap(digits: f64, nmax: usize) -> f64 {
    2.0 * (-(digits + 4.0) * std::f64::consts::LN_10 / (2.0 * nmax as f64)).exp().atan()
}

/// `n` rounded up to the next size of the rule cache (8, 16, 24, ..., 512, then multiples of 64).
pub(super) fn bucket(n: usize) -> usize {
    for b in [8usize, 16, 24, 32, 48, 64, 96, 128, 192, 256, 384, 512] {
        if n <= b {
            return b;
        }
    }
    n.div_ceil(64) * 64
}
