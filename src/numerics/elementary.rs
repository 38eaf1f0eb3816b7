//! Elementary functions in the forms that keep their digits where the textbook form cancels.

/// `acos(exp(-t))` for `t >= 0` without cancellation: with `cos(y) = 1 - 2 sin^2(y/2)`,
/// `y = 2 asin(sqrt(-expm1(-t)/2))`. The textbook form is `acos(1) = 0` once `t < 2^-53`, and loses
/// half its digits well above that (issue 34: Kuznetsov's first guess cos(lambda) = exp(-t) [2.15]
/// at P2 = 1e-20 gave lambda = 0). NaN for a negative or NaN `t`; pi/2 (to round-off) for `t = inf`.
pub(crate) fn acos_exp_neg(t: f64) -> f64 {
    if t.is_nan() || t < 0.0 {
        return f64::NAN;
    }
    2.0 * (-(-t).exp_m1() / 2.0).sqrt().asin()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn acos_exp_neg_keeps_its_digits() {
        // Small t: acos(exp(-t)) = sqrt(2 t) (1 - t/6 + O(t^2)).
        for t in [1e-40_f64, 1e-20, 1e-12] {
            let want = (2.0 * t).sqrt() * (1.0 - t / 6.0);
            assert!((acos_exp_neg(t) - want).abs() <= 4.0 * f64::EPSILON * want, "t = {t}");
        }
        // Where the textbook form is accurate, the same to round-off.
        for t in [0.1_f64, 1.0, 5.0, 40.0] {
            let direct = (-t).exp().acos();
            assert!((acos_exp_neg(t) - direct).abs() <= 4.0 * f64::EPSILON * direct, "t = {t}");
        }
        assert_eq!(acos_exp_neg(0.0), 0.0);
        assert!((acos_exp_neg(f64::INFINITY) - std::f64::consts::FRAC_PI_2).abs() <= 2.0 * f64::EPSILON);
        assert!(acos_exp_neg(-1.0).is_nan());
    }
}
