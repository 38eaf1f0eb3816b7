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
//! (|error| <= eps = 10^-d s) shows every decimal place down to one place below the leading place
//! of eps (a guard digit, so that rounding adds at most eps/20), at most `requested` significant
//! digits (`solve`'s renderers ask one more than the digits requested: a text of exactly the
//! requested digits would hold fewer after its rounding). When |x| < 10 eps (the value is noise at this accuracy) it prints as `0`
//! ([`Printed::Zero`]), and its accuracy is still reported.
//!
//! A printed value holds the digits claimed for it ([`held_digits_mpfr`], issue 34): the claim
//! stated beside a printed text is `-log10(10^-d + |text - x|/s)`, at most `d`, so the rounding
//! of the text (and a cap of `requested` digits) is part of the claim, never hidden by it.

use rug::Float;

/// The digits an `f64` computation can see: 15 (2^-53 ~ 1.1e-16, minus one digit of round-off
/// accumulated by the solvers' dense linear algebra, measured in their tests).
pub const F64_DIGITS_CAP: f64 = 15.0;

/// The round-off floor of an `f64` solver's result, relative to max(|value|, |scale|): 256 eps
/// (5.7e-14, 13.2 digits). The check run with more nodes shares the main run's rounded inputs and
/// most of its arithmetic, so its difference does not see this part of the error. Measured by the
/// differential fuzzer (issue 34, docs/fuzzing.md): against verified MPFR the f64 methods' errors
/// reached 126 eps of the value (P2 and F_def of a polynomial punch with adhesive friction at
/// lambda = 1e-8), 70 eps at lambda = 1.8e-3 and 22 eps near full contact, where the check runs
/// differed by less than 1 eps; a heuristic bound, with a factor 2 over the largest error seen.
pub const F64_ROUNDOFF: f64 = 256.0 * f64::EPSILON;

/// The factor on a check run's difference before it is taken as the error of the main run: the
/// difference estimates the error, it does not bound it; the fuzzer saw the Problem 2 f64 method's
/// error reach 4 times the difference to its finer run (lambda = 3e-7). One digit of safety.
pub const CHECK_RUN_SAFETY: f64 = 10.0;

/// Digits of an `f64` result `value` on `scale` whose check run differs from it by `difference`:
/// [`verified_digits`] of max([`CHECK_RUN_SAFETY`] |difference|, [`F64_ROUNDOFF`]
/// max(|value|, |scale|)), at most [`F64_DIGITS_CAP`].
pub fn f64_digits(difference: f64, value: f64, scale: f64) -> f64 {
    f64_digits_nodes(difference, value, scale, 0)
}

/// [`f64_digits`] for a solver of `nodes` collocation nodes, whose round-off grows with them: the
/// floor is ([`F64_ROUNDOFF`] + 2 nodes eps) max(|value|, |scale|) (the fuzzer saw 375 eps of l in
/// a and b at lambda = 1.465, where the collocation has several hundred nodes).
pub fn f64_digits_nodes(difference: f64, value: f64, scale: f64, nodes: usize) -> f64 {
    let floor = (F64_ROUNDOFF + 2.0 * nodes as f64 * f64::EPSILON) * value.abs().max(scale.abs());
    let d = if difference.is_nan() { difference } else { (CHECK_RUN_SAFETY * difference.abs()).max(floor) };
    verified_digits(d, scale, F64_DIGITS_CAP)
}

/// The digits an `f64` is printed with at most: 17 tell every `f64` apart. The printing
/// rule's guard digit can ask for more than [`F64_DIGITS_CAP`] (a value well below its scale,
/// e.g. the centre c against l); the digits claimed for the printed text then say what it holds.
pub const F64_PRINT_DIGITS: u32 = 17;

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
    // log10 of the error bound eps = 10^-digits s; below 10 eps the value is noise.
    let eps = s - digits;
    if v < eps + 1.0 {
        return Printed::Zero;
    }
    // Places from the leading one of |x| down to one below the leading place of eps.
    let sig = v.floor() - (eps.floor() - 1.0) + 1.0;
    Printed::Significant((sig.max(1.0) as usize).min(requested))
}

/// The digits of the scale that the printed text `printed` of `value` holds when `value` is known
/// to `digits` digits of `scale`: `-log10(10^-digits + |printed - value|/|scale|)`, at most
/// `digits` and at least 0 (module doc). The text is read back exactly enough (at the value's
/// precision plus 64 bits), so a rounding the printing rule could not avoid (a cap of requested
/// digits, a logarithm misjudged at a power of 10) lowers the claim instead of falsifying it.
/// A zero or non-finite scale keeps `digits` (no relative statement to weaken); an unreadable
/// text holds nothing (0).
pub fn held_digits_mpfr(printed: &str, value: &Float, scale: &Float, digits: f64) -> f64 {
    let prec = value.prec().max(53) + 64;
    let Ok(parsed) = Float::parse(printed.trim()) else { return 0.0 };
    let text = Float::with_val(prec, parsed);
    let r = Float::with_val(prec, &text - value).abs();
    if r.is_zero() || !scale.is_normal() || digits.is_nan() {
        return digits.max(0.0);
    }
    if !r.is_finite() {
        return 0.0;
    }
    // log10(|s|) - log10(10^-d |s| + r), in MPFR (values beyond the f64 range).
    let s = Float::with_val(prec, scale.abs_ref());
    let bound = if digits.is_finite() {
        Float::with_val(prec, &s * Float::with_val(prec, Float::with_val(64, -digits).exp10()))
    } else {
        Float::new(prec)
    };
    let total = Float::with_val(prec, &bound + &r);
    let held = Float::with_val(64, s.log10_ref()).to_f64() - Float::with_val(64, total.log10_ref()).to_f64();
    held.clamp(0.0, digits.max(0.0))
}

/// [`held_digits_mpfr`] for an `f64` value and scale.
pub(crate) fn held_digits_f64(printed: &str, value: f64, scale: f64, digits: f64) -> f64 {
    if !value.is_finite() {
        return 0.0;
    }
    let scale = if scale.is_finite() { Float::with_val(53, scale) } else { Float::new(53) };
    held_digits_mpfr(printed, &Float::with_val(53, value), &scale, digits)
}

/// [`Printed`] for an `f64` value (module doc).
pub fn significant_digits(value: f64, scale: f64, digits: f64, requested: u32) -> Printed {
    let lv = (value != 0.0 && value.is_finite()).then(|| value.abs().log10());
    let ls = (scale != 0.0 && scale.is_finite()).then(|| scale.abs().log10());
    significant(lv, ls, digits, requested)
}

/// [`Printed`] for an MPFR value (module doc).
pub(crate) fn significant_digits_mpfr(value: &Float, scale: &Float, digits: f64, requested: u32) -> Printed {
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
pub(crate) fn print_f64(value: f64, scale: f64, digits: f64, requested: u32) -> String {
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

/// A digit count as printed everywhere (answers, messages, warnings, the report): one decimal,
/// rounded down, so that the text never claims more than the count (14.96 digits shown as "15.0"
/// would; issue 34). A count compared with a target is compared as printed ([`digits_floor`]).
/// Non-finite counts print as they are (`inf`).
pub fn digits_text(d: f64) -> String {
    format!("{:.1}", digits_floor(d))
}

/// A digit count rounded down to one decimal (what [`digits_text`] prints); non-finite counts
/// unchanged.
pub fn digits_floor(d: f64) -> f64 {
    if d.is_finite() {
        (d * 10.0).floor() / 10.0
    } else {
        d
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
pub(crate) fn readable_mpfr(value: &Float) -> String {
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
        // Places down to one below the error bound's: 1e-5 known to 1e-30 shows places 1e-5 .. 1e-31.
        assert_eq!(significant_digits(1e-5, 1.0, 30.0, 40), Printed::Significant(27));
        assert_eq!(significant_digits(1.0, 1.0, 30.4, 20), Printed::Significant(20));
        // 1e-4 known to 3.2e-6: places 1e-4 .. 1e-7; below 10 eps (3.2e-5) noise.
        assert_eq!(significant_digits(1e-4, 1.0, 5.5, 20), Printed::Significant(4));
        assert_eq!(significant_digits(1e-5, 1.0, 5.5, 20), Printed::Zero);
        // Noise: the frictionless F_def printed as 2.85e-44 at scale ~1e-3 and 30 digits.
        assert_eq!(print_f64(-1.32137139771671e-19, 2.3e-3, 14.0, 15), "0");
        let p = 128;
        let fdef = Float::with_val(p, 2.85470179000802031743799538663e-44);
        assert_eq!(print_mpfr(&fdef, &Float::with_val(p, 2.3e-3), 30.0, 30), "0");
        // 0.25 known to 3.2 digits of 1 (error bound 6.3e-4): places 1e-1 .. 1e-5.
        assert_eq!(print_mpfr(&Float::with_val(p, 0.25), &Float::with_val(p, 1.0), 3.2, 30), "2.5000e-1");
        assert_eq!(fmt_f64(0.25, 3), "2.50e-1");
        assert_eq!(print_f64(0.0, 1.0, 10.0, 10), "0");
    }

    #[test]
    fn printed_values_hold_their_claims() {
        // See: issue 34 (3). c = -4.3877912435965566e-3 on the scale l = 0.0794891890084214444 at
        // 15 digits: the former text "-4.387791243597e-3" held 14.18 digits; the text printed now
        // (a guard digit) holds 15 less its rounding, and says so.
        let (c, l) = (-4.3877912435965566e-3, 0.0794891890084214444);
        let old = held_digits_f64("-4.387791243597e-3", c, l, 15.0);
        assert!((old - 14.18).abs() < 0.01, "{old}");
        let text = print_f64(c, l, 15.0, F64_PRINT_DIGITS);
        assert_eq!(text, "-4.387791243596556e-3");
        let now = held_digits_f64(&text, c, l, 15.0);
        assert!(now > 14.99 && now <= 15.0, "{now}");
        // For every value and claim, the printed text holds at least the claim less log10(1.05)
        // (the guard digit's rounding adds at most eps/20), unless the requested digits cap it.
        for (x, s, d) in [(0.123456789123, 1.0, 9.3), (-7.77e-9, 3.0, 12.0), (9.999999e4, 1e5, 6.01), (5e-2, 1.0, 2.5)]
        {
            let held = held_digits_f64(&print_f64(x, s, d, 17), x, s, d);
            assert!(held >= d - 0.0212 && held <= d, "{x} {s} {d}: {held}");
        }
        // A cap of requested digits shows in the claim: 30 digits of 1/3 printed to 10.
        let third = Float::with_val(128, 1) / 3u32;
        let one = Float::with_val(128, 1);
        let text = print_mpfr(&third, &one, 30.0, 10);
        assert_eq!(text, "3.333333333e-1");
        let held = held_digits_mpfr(&text, &third, &one, 30.0);
        assert!((held - 10.48).abs() < 0.01, "{held}");
        // Noise printed as 0 holds what its size allows; an exact text holds the claim.
        assert!((held_digits_f64("0", 1e-20, 1.0, 19.0) - 18.96).abs() < 0.01);
        assert_eq!(held_digits_f64("2.5e-1", 0.25, 1.0, 14.0), 14.0);
        assert_eq!(held_digits_f64("nonsense", 0.25, 1.0, 14.0), 0.0);
    }

    #[test]
    fn f64_digits_carry_the_round_off_floor() {
        // A check run that agrees to the bit still leaves 256 eps of the larger of value and scale.
        let floor = -(256.0 * f64::EPSILON).log10();
        assert!((f64_digits(0.0, 1.0, 1.0) - floor).abs() < 1e-12);
        assert!((f64_digits(0.0, 1e4, 1.0) - (floor - 4.0)).abs() < 1e-12);
        // Otherwise ten times the difference.
        assert!((f64_digits(1e-10, 1.0, 1.0) - 9.0).abs() < 1e-12);
        assert_eq!(f64_digits(f64::NAN, 1.0, 1.0), 0.0);
    }

    #[test]
    fn digit_counts_print_rounded_down() {
        // See: issue 34. A count never prints above itself: 14.96 is "14.9", not "15.0".
        assert_eq!(digits_text(14.96), "14.9");
        assert_eq!(digits_text(3.6912), "3.6");
        assert_eq!(digits_text(15.0), "15.0");
        assert_eq!(digits_text(0.04), "0.0");
        assert_eq!(digits_text(f64::INFINITY), "inf");
        assert_eq!(digits_floor(11.96), 11.9);
        for d in [0.0, 0.05, 1.23456, 6.734, 9.999, 12.1, 13.249] {
            let printed: f64 = digits_text(d).parse().unwrap();
            assert!(printed <= d && d - printed < 0.1, "{d}: {printed}");
        }
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
