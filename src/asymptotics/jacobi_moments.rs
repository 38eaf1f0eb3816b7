//! The Jacobi moments J_n(theta) (docs/theory.md section 5; the paper's [3.5]):
//! J_n = int_{-1}^{1} y^n dy / omega(y) = (pi / cos(pi theta)) j_n(theta),
//! omega(y) = (1+y)^(1/2+theta) (1-y)^(1/2-theta), with
//! j_0 = 1, j_1 = -2 theta, (n+1) j_{n+1} = n j_{n-1} - 2 theta j_n, so j_n in Q\[theta\].

use exact_series::{Poly, Ring, Series, SeriesError, Symbol};

/// j_0(theta), ..., j_n(theta) by the three-term recurrence, exact in Q\[theta\], packed as the
/// coefficients of a "series" in the index (`coeff(n) = j_n`) so that it prints like the others.
pub fn jacobi_moments(n: usize) -> Result<Series<Poly>, SeriesError> {
    let theta = Poly::symbol(Symbol::new("theta")?);
    Ok(jacobi_moments_at(n, &theta))
}

/// j_0 .. j_n with an arbitrary polynomial in place of theta (e.g. `-theta` for the moments of
/// the weight omega itself: int y^n omega(y) dy = (pi / cos(pi theta)) (j_n(-theta) - j_{n+2}(-theta))).
pub(crate) fn jacobi_moments_at(n: usize, theta: &Poly) -> Series<Poly> {
    let two_theta = theta.mul_int(2);
    let mut j: Vec<Poly> = Vec::with_capacity(n + 1);
    j.push(Poly::one());
    if n >= 1 {
        j.push(two_theta.neg());
    }
    for m in 1..n {
        // (m+1) j_{m+1} = m j_{m-1} - 2 theta j_m
        let next = j[m - 1].mul_int(m as i64).sub(&two_theta.mul(&j[m])).div_int(m as i64 + 1);
        j.push(next);
    }
    Series::from_coeffs(j)
}

#[cfg(test)]
mod tests {
    use super::*;
    use exact_series::Q;

    /// The Beta-function sum: y^n = ((1+y) - 1)^n gives
    /// j_n = sum_k C(n,k) (-1)^(n-k) 2^k prod_{i<k} (i + 1/2 - theta) / k!
    /// (from int (1+y)^(k-1/2-theta) (1-y)^(-1/2+theta) dy = 2^k B(k+1/2-theta, 1/2+theta)).
    fn beta_sum(n: usize) -> Poly {
        let theta = Poly::var("theta").unwrap();
        let half = Poly::from_q(&Q::new(1.into(), 2.into()));
        let mut total = Poly::zero();
        let mut binom = Q::from_integer(1.into());
        for k in 0..=n {
            let mut rising = Poly::one();
            for i in 0..k {
                rising = rising.mul(&Poly::from_int(i as i64).add(&half).sub(&theta)).div_int(i as i64 + 1);
            }
            let sign = if (n - k) % 2 == 0 { 1 } else { -1 };
            let c = &binom * Q::from_integer((sign * (1i64 << k)).into());
            total = total.add(&rising.scale(&c));
            binom = binom * Q::new(((n - k) as i64).into(), ((k + 1) as i64).into());
        }
        total
    }

    #[test]
    fn recurrence_matches_beta_sum() {
        let j = jacobi_moments(40).unwrap();
        for n in 0..=40 {
            assert_eq!(j.coeff(n).unwrap(), &beta_sum(n), "j_{n}");
        }
    }

    #[test]
    fn theta_zero_is_chebyshev() {
        // At theta = 0, J_n = int y^n / sqrt(1-y^2) = pi (n-1)!!/n!! for even n, 0 for odd n.
        let j = jacobi_moments(12).unwrap();
        let t = Symbol::new("theta").unwrap();
        let zero = Q::from_integer(0.into());
        let mut expected = Q::from_integer(1.into());
        for n in 0..=12 {
            let v = j.coeff(n).unwrap().subs(t, &zero).as_q().unwrap();
            if n % 2 == 1 {
                assert_eq!(v, zero);
            } else {
                assert_eq!(v, expected, "n = {n}");
                expected = expected * Q::new(((n + 1) as i64).into(), ((n + 2) as i64).into());
            }
        }
    }
}
