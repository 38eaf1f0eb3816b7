//! The one accuracy rule of the project: digits from a difference and a scale, and the digits a
//! printed value may show.
//!
//! Every method (MPFR, f64, series) states the accuracy of each output as *digits relative to that
//! output's scale*: `d = -log10(|difference| / |scale|)`, where `difference` is the gap to a second
//! run (verified digits) or an error estimate (estimated digits). The scale of each output is fixed
//! in one table per problem (`crate::params`), not at the call site.
//!
//! Edge rule (the only one, [`verified_digits`]):
//! - a non-finite difference or scale verifies nothing: 0;
//! - a zero difference is capped, not infinite: `cap` (the digits the comparison could see, e.g.
//!   the second run's precision in digits);
//! - a zero scale with a non-zero difference verifies nothing: 0;
//! - otherwise `clamp(-log10(|difference| / |scale|), 0, cap)`.
//!
//! Printing ([`significant_digits`]): a value `x` known to `d` digits of the scale `s`
//! (|error| <= 10^-d s) has `floor(d - log10(s / |x|))` significant digits, at most `requested`.
//! When that is < 1 (|x| below s 10^-d: the value is noise at this accuracy), the value prints as
//! `0` ([`Printed::Zero`]), and its accuracy is still reported.

use rug::Float;

/// The digits an `f64` computation can see: 15 (2^-53 ~ 1.1e-16, minus one digit of round-off
/// accumulated by the solvers' dense linear algebra, measured in their tests).
pub const F64_DIGITS_CAP: f64 = 15.0;

/// The digits `bits` of working precision can see: bits log10 2.
pub fn digits_cap_for_bits(bits: u32) -> f64 {
    bits as f64 * std::f64::consts::LOG10_2
}

/// Digits of agreement `-log10(|difference| / |scale|)` under the edge rule of the module doc.
pub fn verified_digits(difference: f64, scale: f64, cap: f64) -> f64 {
    let (d, s) = (difference.abs(), scale.abs());
    if !d.is_finite() || !s.is_finite() {
        return 0.0;
    }
    if d == 0.0 {
        return cap.max(0.0);
    }
    if s == 0.0 {
        return 0.0;
    }
    // d / s may underflow or overflow in f64 even when both are finite: take logs separately.
    (s.log10() - d.log10()).clamp(0.0, cap.max(0.0))
}

/// [`verified_digits`] for MPFR numbers (no rounding to `f64` before the logarithm, so values
/// beyond the `f64` range are handled).
pub fn verified_digits_mpfr(difference: &Float, scale: &Float, cap: f64) -> f64 {
    if difference.is_nan() || scale.is_nan() || difference.is_infinite() || scale.is_infinite() {
        return 0.0;
    }
    if difference.is_zero() {
        return cap.max(0.0);
    }
    if scale.is_zero() {
        return 0.0;
    }
    let ld = Float::with_val(64, difference.abs_ref()).log10().to_f64();
    let ls = Float::with_val(64, scale.abs_ref()).log10().to_f64();
    (ls - ld).clamp(0.0, cap.max(0.0))
}

/// Digits of agreement between two MPFR values `x` and `y` relative to `scale`.
pub fn agreement_mpfr(x: &Float, y: &Float, scale: &Float, cap: f64) -> f64 {
    let diff = Float::with_val(x.prec().max(y.prec()), x - y);
    verified_digits_mpfr(&diff, scale, cap)
}

/// How many significant digits a value may show.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Printed {
    /// The value is below its scale times 10^-digits: it prints as `0`.
    Zero,
    /// Print with this many significant digits (>= 1).
    Significant(usize),
}

/// Significant digits of a value `|x| = value_abs_log10` (log10 |x|; `None` when x = 0) known to
/// `digits` digits of a scale with log10 |s| = `scale_log10`, at most `requested` (rule of the
/// module doc). Works on logarithms so that MPFR values beyond the `f64` range are handled.
fn significant(value_log10: Option<f64>, scale_log10: Option<f64>, digits: f64, requested: u32) -> Printed {
    let requested = (requested as usize).max(1);
    let Some(v) = value_log10 else { return Printed::Zero };
    if !digits.is_finite() {
        return Printed::Significant(requested);
    }
    let Some(s) = scale_log10 else {
        // A zero scale gives no relative information: only the digits themselves.
        return if digits >= 1.0 {
            Printed::Significant((digits.floor() as usize).clamp(1, requested))
        } else {
            Printed::Zero
        };
    };
    let sig = (digits - (s - v).max(0.0)).floor();
    if sig < 1.0 {
        Printed::Zero
    } else {
        Printed::Significant((sig as usize).min(requested))
    }
}

/// [`Printed`] for an `f64` value (module doc).
pub fn significant_digits(value: f64, scale: f64, digits: f64, requested: u32) -> Printed {
    let lv = (value != 0.0 && value.is_finite()).then(|| value.abs().log10());
    let ls = (scale != 0.0 && scale.is_finite()).then(|| scale.abs().log10());
    significant(lv, ls, digits, requested)
}

/// [`Printed`] for an MPFR value (module doc).
pub fn significant_digits_mpfr(value: &Float, scale: &Float, digits: f64, requested: u32) -> Printed {
    let log = |x: &Float| (x.is_normal()).then(|| Float::with_val(64, x.abs_ref()).log10().to_f64());
    significant(log(value), log(scale), digits, requested)
}

/// `value` printed with `sig` significant digits in scientific notation (`3.3333e-1`), `0` for 0.
pub fn fmt_mpfr(value: &Float, sig: usize) -> String {
    if value.is_zero() {
        return "0".to_string();
    }
    value.to_string_radix(10, Some(sig.max(1)))
}

/// An `f64` with `sig` significant digits (`3.3333e-1`), `0` for 0.
pub fn fmt_f64(value: f64, sig: usize) -> String {
    if value == 0.0 {
        return "0".to_string();
    }
    format!("{:.*e}", sig.max(1) - 1, value)
}

/// An `f64` value printed under the rule of the module doc.
pub fn print_f64(value: f64, scale: f64, digits: f64, requested: u32) -> String {
    match significant_digits(value, scale, digits, requested) {
        Printed::Zero => "0".to_string(),
        Printed::Significant(n) => fmt_f64(value, n),
    }
}

/// An MPFR value printed under the rule of the module doc.
pub fn print_mpfr(value: &Float, scale: &Float, digits: f64, requested: u32) -> String {
    match significant_digits_mpfr(value, scale, digits, requested) {
        Printed::Zero => "0".to_string(),
        Printed::Significant(n) => fmt_mpfr(value, n),
    }
}

/// A value for a human-readable message: at most 7 significant digits, plain decimals between
/// 1e-3 and 1e6 (`0.8`, not `0.7999999999999999`), scientific notation outside (`1.000000e-300`).
pub fn readable_f64(value: f64) -> String {
    if value == 0.0 || !value.is_finite() {
        return format!("{value}");
    }
    let a = value.abs();
    if (1e-3..1e6).contains(&a) {
        let decimals = (6 - a.log10().floor() as i32).max(0) as usize;
        let s = format!("{value:.decimals$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        format!("{value:.6e}")
    }
}

/// [`readable_f64`] for an MPFR value (values beyond the `f64` range in scientific notation).
pub fn readable_mpfr(value: &Float) -> String {
    let v = value.to_f64();
    if value.is_zero() || (v.is_finite() && v.abs() >= 1e-300) {
        readable_f64(v)
    } else {
        value.to_string_radix(10, Some(7))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edge_rule() {
        assert_eq!(verified_digits(0.0, 1.0, 15.0), 15.0);
        assert_eq!(verified_digits(0.0, 0.0, 15.0), 15.0);
        assert_eq!(verified_digits(1e-3, 0.0, 15.0), 0.0);
        assert_eq!(verified_digits(f64::NAN, 1.0, 15.0), 0.0);
        assert_eq!(verified_digits(1.0, f64::INFINITY, 15.0), 0.0);
        assert!((verified_digits(1e-10, 1.0, 15.0) - 10.0).abs() < 1e-12);
        assert!((verified_digits(-1e-10, -10.0, 15.0) - 11.0).abs() < 1e-12);
        assert_eq!(verified_digits(1e-30, 1.0, 15.0), 15.0);
        // An uncapped comparison (closed forms): a zero difference is infinitely many digits, as
        // in the MPFR variant.
        assert_eq!(verified_digits(0.0, 1.0, f64::INFINITY), f64::INFINITY);
        assert_eq!(
            verified_digits_mpfr(&Float::with_val(64, 0), &Float::with_val(64, 1), f64::INFINITY),
            f64::INFINITY
        );
        assert_eq!(verified_digits(2.0, 1.0, 15.0), 0.0);
        // No overflow of d/s for extreme but finite values.
        assert!((verified_digits(1e-300, 1e300, 1000.0) - 600.0).abs() < 1e-9);
        let p = 128;
        let f = |x: f64| Float::with_val(p, x);
        assert_eq!(verified_digits_mpfr(&f(0.0), &f(1.0), 30.0), 30.0);
        assert_eq!(verified_digits_mpfr(&f(1e-3), &f(0.0), 30.0), 0.0);
        assert!((verified_digits_mpfr(&f(1e-20), &f(1.0), 30.0) - 20.0).abs() < 1e-9);
        let big = Float::with_val(p, Float::i_exp(1, 4000));
        let tiny = Float::with_val(p, Float::i_exp(1, 3900));
        let want = 100.0 * std::f64::consts::LOG10_2;
        assert!((verified_digits_mpfr(&tiny, &big, 1e9) - want).abs() < 1e-9);
    }

    #[test]
    fn printed_digits_follow_the_scale() {
        assert_eq!(significant_digits(1e-5, 1.0, 30.0, 40), Printed::Significant(25));
        assert_eq!(significant_digits(1.0, 1.0, 30.4, 20), Printed::Significant(20));
        assert_eq!(significant_digits(1e-5, 1.0, 5.5, 20), Printed::Zero);
        // Noise: the frictionless F_def printed as 2.85e-44 at scale ~1e-3 and 30 digits.
        assert_eq!(print_f64(-1.32137139771671e-19, 2.3e-3, 14.0, 15), "0");
        let p = 128;
        let fdef = Float::with_val(p, 2.85470179000802031743799538663e-44);
        assert_eq!(print_mpfr(&fdef, &Float::with_val(p, 2.3e-3), 30.0, 30), "0");
        // 0.25 known to 3.2 digits of 1: floor(3.2 - log10(1/0.25)) = 2 significant digits.
        assert_eq!(print_mpfr(&Float::with_val(p, 0.25), &Float::with_val(p, 1.0), 3.2, 30), "2.5e-1");
        assert_eq!(fmt_f64(0.25, 3), "2.50e-1");
        assert_eq!(print_f64(0.0, 1.0, 10.0, 10), "0");
    }

    #[test]
    fn readable_values() {
        assert_eq!(readable_f64(0.7999999999999999), "0.8");
        assert_eq!(readable_f64(1e-400_f64.max(1e-300)), "1.000000e-300");
        assert_eq!(readable_f64(1.5676), "1.5676");
        assert_eq!(readable_f64(-0.0314159265), "-0.03141593");
        assert_eq!(readable_f64(12345678.0), "1.234568e7");
        let tiny = Float::with_val(64, Float::i_exp(1, -1400));
        assert_eq!(readable_mpfr(&tiny), "3.614149e-422");
    }
}
