//! Chebyshev series on u in [-1, 1] in `f64` for the marching method ([`super::march`]) and the
//! loading-law collocation's f64 chord Jacobian ([`crate::loading_law`]):
//! Clenshaw evaluation, the divided difference (accurate as the two points meet), derivative,
//! antiderivative from -1 and multiplication by x (the identities of Mason and Handscomb,
//! "Chebyshev Polynomials", 2003, sections 2.4.4-2.4.5).

/// Clenshaw: sum_j c_j T_j(x).
pub(crate) fn cheb(c: &[f64], x: f64) -> f64 {
    let (mut b1, mut b2) = (0.0, 0.0);
    for &cj in c.iter().skip(1).rev() {
        let b0 = 2.0 * x * b1 - b2 + cj;
        b2 = b1;
        b1 = b0;
    }
    c.first().map_or(0.0, |c0| x * b1 - b2 + c0)
}

/// sum_j c_j [T_j(x) - T_j(y)]/(x - y), by d_(j+1) = 2 x d_j + 2 T_j(y) - d_(j-1) (d_0 = 0,
/// d_1 = 1): accurate as y -> x.
pub(crate) fn cheb_dd(c: &[f64], x: f64, y: f64) -> f64 {
    let (mut acc, mut d_prev, mut d, mut t_prev, mut t) = (0.0, 0.0, 1.0, 1.0, y);
    for &cj in c.iter().skip(1) {
        acc += cj * d;
        let d_next = 2.0 * x * d + 2.0 * t - d_prev;
        let t_next = 2.0 * y * t - t_prev;
        d_prev = std::mem::replace(&mut d, d_next);
        t_prev = std::mem::replace(&mut t, t_next);
    }
    acc
}

/// Coefficients of d/dx sum_j c_j T_j.
pub(super) fn cheb_derivative(c: &[f64]) -> Vec<f64> {
    let n = c.len();
    if n <= 1 {
        return vec![0.0];
    }
    let mut d = vec![0.0; n + 1];
    for k in (1..n).rev() {
        d[k - 1] = d[k + 1] + 2.0 * k as f64 * c[k];
    }
    d[0] /= 2.0;
    d.truncate(n - 1);
    d
}

/// Coefficients of the antiderivative of sum_j c_j T_j vanishing at x = -1
/// (D_1 = c_0 - c_2/2, D_k = (c_(k-1) - c_(k+1))/(2k)).
pub(crate) fn cheb_antiderivative(c: &[f64]) -> Vec<f64> {
    let n = c.len();
    let at = |j: usize| c.get(j).copied().unwrap_or(0.0);
    let mut d = vec![0.0; n + 1];
    for (k, dk) in d.iter_mut().enumerate().skip(1) {
        *dk = if k == 1 { at(0) - at(2) / 2.0 } else { (at(k - 1) - at(k + 1)) / (2.0 * k as f64) };
    }
    d[0] = -(1..=n).map(|k| if k % 2 == 1 { -d[k] } else { d[k] }).sum::<f64>();
    d
}

/// Coefficients of x sum_j c_j T_j (x T_0 = T_1, x T_j = (T_(j+1) + T_(j-1))/2).
pub(crate) fn cheb_times_x(c: &[f64]) -> Vec<f64> {
    let mut out = vec![0.0; c.len() + 1];
    for (j, &cj) in c.iter().enumerate() {
        if j == 0 {
            out[1] += cj;
        } else {
            out[j + 1] += cj / 2.0;
            out[j - 1] += cj / 2.0;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Chebyshev helpers: derivative, antiderivative from -1, x times, divided difference.
    #[test]
    fn chebyshev_helpers() {
        let c = [0.3, -1.2, 0.7, 0.25];
        let (x, y) = (0.4, 0.4 + 1e-9);
        let d = cheb_derivative(&c);
        assert!((cheb(&d, x) - (cheb(&c, y) - cheb(&c, x)) / 1e-9).abs() < 1e-6);
        let a = cheb_antiderivative(&c);
        assert!(cheb(&a, -1.0).abs() < 1e-15);
        assert!((cheb(&cheb_derivative(&a), x) - cheb(&c, x)).abs() < 1e-14);
        assert!((cheb(&cheb_times_x(&c), x) - x * cheb(&c, x)).abs() < 1e-15);
        let (u, v) = (0.3, -0.55);
        assert!((cheb_dd(&c, u, v) - (cheb(&c, u) - cheb(&c, v)) / (u - v)).abs() < 1e-14);
        assert!((cheb_dd(&c, x, x) - cheb(&d, x)).abs() < 1e-13);
    }
}
