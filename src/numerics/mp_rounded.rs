//! ln x, (sin x, cos x) and (sinh x, cosh x) correctly rounded to nearest, i.e. the same bits as
//! MPFR's `ln`, `sin_cos` and `sinh_cosh` (which round correctly), in less of MPFR's time at
//! 100-130 bits: for the kernels of the loading law's edge integrals (`growing_contact::kernel`),
//! whose logarithm (by AGM), sines and hyperbolic functions were 38 % of its MPFR solve
//! (docs/performance.md "The loading law", round five).
//!
//! Method (Ziv's): the function at q >= p + [`GUARD`] bits ([`working`]: MPFR's fast paths end
//! at 127 and 191 bits) with a proven bound E on its error, then
//! the p-bit roundings to nearest of v - E (rounded down) and v + E (rounded up): when they agree,
//! every number in between, the exact value included, rounds to that one (rounding is monotone);
//! when they do not (v within E of a midpoint: about 2^-7 of the arguments for ln, fewer for the
//! sines), MPFR's own function answers. So the result never differs from MPFR's.
//! - ln x: `mp_elementary`'s table and series at q bits, within 2^13 ulp(q) of ln x: the
//!   table's and the product's roundings enter z = m e^(-j/1024) - 1 at 2^-q each, the sums add
//!   0.35 2^-q and 2^-q |ln x|, and |ln x| >= 2^-11 where j or e is not 0 (where both are, z =
//!   m - 1 is exact and only the series' few ulps remain); E = 2^14 ulp(q);
//! - sin x, cos x for |x| <= 8: x = j/64 + r (j the nearest integer to 64 x, r exact at q bits,
//!   |r| <= 2^-7), sin r and cos r by their Taylor series in r^2 (Horner, truncated below
//!   2^-(q+4) relative), then sin x = sin a cos r + cos a sin r, cos x = cos a cos r - sin a sin r
//!   with sin a, cos a (a = j/64) from a table made by MPFR at q bits. Errors: each table value
//!   and rounding 2^-q, so sin r within 4 2^-q relative, cos r within 3 2^-q, and for j != 0 both
//!   results within 7 2^-q absolute; E = 2^(-q+5) absolute (j != 0), 2^5 ulp(q) (j = 0, where
//!   sin x = sin r keeps its relative accuracy for tiny x). Beyond |x| = 8, MPFR's;
//! - sinh x, cosh x the same way (the series' terms all positive, the table's sinh and cosh of
//!   j/64, cosh a cosh r + sinh a sinh r), the absolute bounds scaled by cosh a: within
//!   7 2^-q cosh a, E = 2^(-q+5) 2^e with cosh a < 2^e.
//!
//! Tests: every function equals MPFR's bit for bit at 53-200 bits over arguments of all scales,
//! the loading law's among them, with the share that needed MPFR's fallback bounded.

use crate::numerics::mp_elementary;
use rug::ops::DivFrom;
use rug::{Assign, Float};
use std::cell::RefCell;
use std::sync::{Arc, Mutex, OnceLock};

/// The least guard bits of the working precision over the result's.
pub const GUARD: u32 = 18;

/// The working precision for `prec` bits: the end of MPFR's one-, two- or three-limb fast
/// paths (63, 127, 191 bits) when it leaves [`GUARD`] bits, else `prec` + 32.
pub fn working(prec: u32) -> u32 {
    [63, 127, 191].into_iter().find(|q| *q >= prec + GUARD).unwrap_or(prec + 32)
}

/// Steps 2^-STEP of the sines' table.
const STEP: i32 = 6;
/// The sines' table covers |j| <= RANGE, |x| <= RANGE 2^-STEP = 8.
const RANGE: i32 = 512;

/// sin and cos (or sinh and cosh) of j/64 and the Taylor coefficients at one working precision q.
struct Trig {
    q: u32,
    /// Whether these are sinh and cosh.
    hyperbolic: bool,
    /// (sin, cos) or (sinh, cosh) of j 2^-STEP, j = -RANGE..=RANGE (index j + RANGE), each made
    /// on its first use.
    table: Vec<OnceLock<(Float, Float)>>,
    /// (-1)^k/(2k + 1)!, k = 0..=K (1/(2k + 1)! for sinh).
    sin_coef: Vec<Float>,
    /// (-1)^k/(2k)!, k = 0..=K (1/(2k)! for cosh).
    cos_coef: Vec<Float>,
}

impl Trig {
    fn new(q: u32, hyperbolic: bool) -> Trig {
        let table = (-RANGE..=RANGE).map(|_| OnceLock::new()).collect();
        // |r|^2 <= 2^-13.9: the first omitted terms r2^(K+1)/(2K+2)! (cos) and r2^(K+1)/(2K+3)!
        // (sin over r) below 2^-(q+4).
        let mut k = 1usize;
        let bits = |k: usize| 13.9 * (k + 1) as f64 + (1..=2 * k + 2).map(|i| (i as f64).log2()).sum::<f64>();
        while bits(k) < (q + 4) as f64 {
            k += 1;
        }
        let (mut sin_coef, mut cos_coef) = (Vec::with_capacity(k + 1), Vec::with_capacity(k + 1));
        let mut fact = rug::Integer::from(1);
        for n in 0..=(2 * k + 1) {
            if n > 0 {
                fact *= n as u32;
            }
            let sign = if hyperbolic || (n / 2) % 2 == 0 { 1 } else { -1 };
            let c = Float::with_val(q, 1) / Float::with_val(q + 64, &fact) * sign;
            if n % 2 == 0 {
                cos_coef.push(c);
            } else {
                sin_coef.push(c);
            }
        }
        Trig { q, hyperbolic, table, sin_coef, cos_coef }
    }
}

/// The process's [`Trig`] tables, one per working precision.
static SHARED: Mutex<Vec<Arc<Trig>>> = Mutex::new(Vec::new());

thread_local! {
    /// The tables this thread has taken from [`SHARED`].
    static LOCAL: RefCell<Vec<Arc<Trig>>> = const { RefCell::new(Vec::new()) };
}

fn trig(q: u32, hyperbolic: bool) -> Arc<Trig> {
    mp_elementary::shared_table(
        &LOCAL,
        &SHARED,
        |x| x.q == q && x.hyperbolic == hyperbolic,
        || Trig::new(q, hyperbolic),
    )
}

/// The p-bit rounding to nearest of `v`, if every number within 2^`k` of v has the same one (no
/// midpoint of p-bit numbers within 2^k of v), and 2^k is at most 2^-3 ulp(p) of v; None
/// otherwise. From v's mantissa m (value m 2^(e - B), B its limbs' bits): the bits of m below the
/// top p, L, against the midpoint 2^(B - p - 1). Crossing a power of two needs no other case:
/// within 2^-3 ulp(p) of one, every number rounds to it on both sides.
fn rounded_within(v: &Float, k: i32, p: u32) -> Option<Float> {
    let (sig, exp) = (v.get_significand()?, v.get_exp()?);
    let limbs = sig.as_limbs();
    let bits = 64 * limbs.len() as i64;
    let low = bits - p as i64;
    let shift = k as i64 - exp as i64 + bits;
    if !(1..=127).contains(&low) || shift > low - 4 {
        return None;
    }
    let mut l = limbs[0] as u128;
    if limbs.len() > 1 {
        l |= (limbs[1] as u128) << 64;
    }
    if low < 128 {
        l &= (1u128 << low) - 1;
    }
    // |L - midpoint| > 2^shift (units of 2^(e - B)); below one unit, L off the midpoint suffices.
    let err = if shift < 0 { 0 } else { 1u128 << shift };
    (l.abs_diff(1u128 << (low - 1)) > err).then(|| Float::with_val(p, v))
}

/// ln x rounded to nearest at `prec` bits: MPFR's `Float::with_val(prec, x.ln_ref())`, bit for
/// bit (module doc).
pub fn ln(x: &Float, prec: u32) -> Float {
    let q = working(prec);
    if x.is_finite() && *x > 0 && *x != 1 && x.prec() <= q {
        let v = ln_q(x, &mp_elementary::tables(q));
        if let Some(out) = v.get_exp().and_then(|exp| rounded_within(&v, exp - q as i32 + 14, prec)) {
            return out;
        }
    }
    Float::with_val(prec, x.ln_ref())
}

/// ln x at q bits (x > 0 finite, of at most q bits) by `mp_elementary`'s reduction and tables:
/// x = 2^e m, 1/sqrt(2) <= m < sqrt(2), j the nearest 1024 ln m, z = m e^(-j/1024) - 1 (the
/// product rounded, the difference exact; z = m - 1 exact when j = 0),
/// ln x = e ln 2 + j/1024 + 2 atanh(z/(2 + z)), the series by Horner with separate products and
/// sums (no fused operation, whose exact product MPFR allocates). Within 2^13 ulp(q) (module doc).
fn ln_q(x: &Float, tb: &mp_elementary::Tables) -> Float {
    let q = tb.q;
    let mut e = x.get_exp().unwrap_or(0);
    let mut m = Float::with_val(q, x >> e);
    if m < std::f64::consts::FRAC_1_SQRT_2 {
        m <<= 1;
        e -= 1;
    }
    let step = mp_elementary::STEP;
    let range = mp_elementary::RANGE;
    let j = ((m.to_f64().ln() * (1 << step) as f64).round() as i32).clamp(-range, range);
    let mut z = m;
    if j != 0 {
        z *= &tb.exp_j[(range - j) as usize];
    }
    z -= 1u32;
    let mut out = Float::with_val(q, 0);
    if !z.is_zero() {
        let mut u = Float::with_val(q, &z + 2u32);
        u.div_from(&z);
        let u2 = Float::with_val(q, u.square_ref());
        let coef = &tb.inv_odd;
        out.assign(&coef[coef.len() - 1]);
        for c in coef[..coef.len() - 1].iter().rev() {
            out *= &u2;
            out += c;
        }
        out *= &u;
        out <<= 1;
    }
    if j != 0 {
        out += Float::with_val(q, j) >> step;
    }
    if e != 0 {
        out += Float::with_val(q + 40, &tb.ln2 * e);
    }
    out
}

/// (sin x, cos x) rounded to nearest at `prec` bits: MPFR's `sin_cos` of x at `prec` bits, bit
/// for bit (module doc).
pub fn sin_cos(x: &Float, prec: u32) -> (Float, Float) {
    pair(x, prec, false)
}

/// (sinh x, cosh x) rounded to nearest at `prec` bits: MPFR's `sinh_cosh` of x at `prec` bits,
/// bit for bit (module doc).
pub fn sinh_cosh(x: &Float, prec: u32) -> (Float, Float) {
    pair(x, prec, true)
}

/// [`sin_cos`] or, `hyperbolic`, [`sinh_cosh`]: from the table where its rounding is decided,
/// else MPFR's.
fn pair(x: &Float, prec: u32, hyperbolic: bool) -> (Float, Float) {
    let q = working(prec);
    if x.is_finite()
        && !x.is_zero()
        && x.prec() <= q
        && x.to_f64().abs() <= 8.0
        && let Some(pair) = sin_cos_q(x, &trig(q, hyperbolic), prec)
    {
        return pair;
    }
    let (mut s, mut c) = (Float::new(prec), Float::new(prec));
    if hyperbolic {
        (&mut s, &mut c).assign(x.sinh_cosh_ref());
    } else {
        (&mut s, &mut c).assign(x.sin_cos_ref());
    }
    (s, c)
}

/// [`sin_cos`] (or [`sinh_cosh`], by the table's kind) from the table, or None where either
/// rounding is not decided (module doc).
fn sin_cos_q(x: &Float, tb: &Trig, prec: u32) -> Option<(Float, Float)> {
    let q = tb.q;
    let j = (x.to_f64() * (1 << STEP) as f64).round() as i32;
    if j.abs() > RANGE {
        return None;
    }
    // r = x - j/64: exact at q bits (x has at most q bits; where j != 0, |x| >= 2^-7, so x and
    // j/64 are multiples of ulp(x) >= 2^(-7-q) and |r| <= 2^-7).
    let mut r = Float::with_val(q, x);
    if j != 0 {
        r -= Float::with_val(q, j) >> STEP;
    }
    let r2 = Float::with_val(q, r.square_ref());
    // Horner in r^2 with separate products and sums.
    let horner = |coef: &[Float], acc: &mut Float| {
        acc.assign(&coef[coef.len() - 1]);
        for c in coef[..coef.len() - 1].iter().rev() {
            *acc *= &r2;
            *acc += c;
        }
    };
    let (mut sin_r, mut cos_r) = (Float::new(q), Float::new(q));
    horner(&tb.sin_coef, &mut sin_r);
    sin_r *= &r;
    horner(&tb.cos_coef, &mut cos_r);
    let five = 5 - q as i32;
    if j == 0 {
        let s = rounded_within(&sin_r, sin_r.get_exp()? + five, prec)?;
        let c = rounded_within(&cos_r, five, prec)?;
        return Some((s, c));
    }
    let (sa, ca) = tb.table[(j + RANGE) as usize].get_or_init(|| {
        let a = Float::with_val(q, j) >> STEP;
        if tb.hyperbolic {
            a.sinh_cosh(Float::new(q))
        } else {
            a.sin_cos(Float::new(q))
        }
    });
    // sin a cos r + cos a sin r, cos a cos r -+ sin a sin r: two products and a sum each.
    let mut s = Float::with_val(q, sa * &cos_r);
    let mut t = Float::with_val(q, ca * &sin_r);
    s += &t;
    let mut c = Float::with_val(q, ca * &cos_r);
    t.assign(sa * &sin_r);
    if tb.hyperbolic {
        c += &t;
    } else {
        c -= &t;
    }
    // The bound 2^5 2^-q scaled by cosh a (up to cosh 8 < 2^11) for the hyperbolic functions.
    let bound = if tb.hyperbolic { five + ca.get_exp()? } else { five };
    Some((rounded_within(&s, bound, prec)?, rounded_within(&c, bound, prec)?))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Arguments of all scales in (0, 8] and their negatives: 2^k (1 + small), the multiples of
    /// 1/64 and their neighbours, near pi/2, pi and 1, and a dense pseudo-random sample.
    fn arguments(p: u32) -> Vec<Float> {
        let mut out = Vec::new();
        for k in -120..=3 {
            for f in [1.0, 1.37, 1.9999, 0.5001, 0.707, 1.414] {
                out.push(Float::with_val(p, f) << k);
            }
        }
        for j in 1..=512 {
            let a: Float = Float::with_val(p, j) >> 6;
            let ulp = Float::with_val(p, Float::i_exp(1, a.get_exp().unwrap() - p as i32));
            out.push(Float::with_val(p, &a + &ulp));
            out.push(Float::with_val(p, &a - &ulp));
            out.push(a);
        }
        let pi = Float::with_val(p, rug::float::Constant::Pi);
        for m in [Float::with_val(p, &pi / 2u32), pi.clone(), Float::with_val(p, 1)] {
            for d in [0.0, 1e-30, -1e-30, 1e-8, -1e-8] {
                out.push(Float::with_val(p, &m + d));
            }
        }
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        for _ in 0..4000 {
            let mut x = Float::with_val(p, 0);
            for _ in 0..p.div_ceil(53) {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                x += (state >> 11) as f64;
                x >>= 53;
            }
            out.push(x * 8u32);
        }
        let neg: Vec<Float> = out.iter().map(|x| -x.clone()).collect();
        out.extend(neg);
        out
    }

    /// The pair (sin, cos) or, `hyperbolic`, (sinh, cosh) of [`sin_cos`] / [`sinh_cosh`] equals
    /// MPFR's bit for bit (sign of zero included) at 53, 64, 107, 127, 128, 131 and 200 bits, over
    /// [`arguments`], beyond the table (|x| = 9, 100) and from an argument of fewer bits than the
    /// result; MPFR's fallback takes under 2 % of the arguments.
    fn pair_equals_mpfr_bit_for_bit(hyperbolic: bool) {
        let name = if hyperbolic { "sinh_cosh" } else { "sin_cos" };
        for p in [53u32, 64, 107, 127, 128, 131, 200] {
            let mut args = arguments(p);
            args.extend([9.0, -100.0, 1e-300].iter().map(|v| Float::with_val(p, *v)));
            args.push(Float::with_val(40, 0.3));
            let mut undecided = 0;
            for x in &args {
                let (s, c) = if hyperbolic { sinh_cosh(x, p) } else { sin_cos(x, p) };
                let (mut ws, mut wc) = (Float::new(p), Float::new(p));
                if hyperbolic {
                    (&mut ws, &mut wc).assign(x.sinh_cosh_ref());
                } else {
                    (&mut ws, &mut wc).assign(x.sin_cos_ref());
                }
                assert!(s == ws && s.is_sign_negative() == ws.is_sign_negative(), "{name} {x} at {p}: {s} vs {ws}");
                assert!(c == wc && c.is_sign_negative() == wc.is_sign_negative(), "{name} {x} at {p}: {c} vs {wc}");
                let q = working(p);
                if x.clone().abs() <= 8 && x.prec() <= q && sin_cos_q(x, &trig(q, hyperbolic), p).is_none() {
                    undecided += 1;
                }
            }
            eprintln!("{name} at {p} bits: {undecided} of {} arguments by MPFR", args.len());
            assert!(undecided * 50 < args.len(), "{undecided} of {}", args.len());
        }
    }

    /// sin and cos: [`pair_equals_mpfr_bit_for_bit`].
    #[test]
    fn sin_cos_equal_mpfr_bit_for_bit() {
        pair_equals_mpfr_bit_for_bit(false);
    }

    /// sinh and cosh: [`pair_equals_mpfr_bit_for_bit`].
    #[test]
    fn sinh_cosh_equal_mpfr_bit_for_bit() {
        pair_equals_mpfr_bit_for_bit(true);
    }

    /// ln equals MPFR's bit for bit at 53, 64, 107, 127, 128, 131 and 200 bits, over arguments
    /// from 2^-200 to 2^200, near 1 (1 +- 1e-40 .. 0.35) and the loading law's ratios
    /// sin d_far/sin d_near (pseudo-random in (1, 10^6)), and for 1, 0, -1 and a wider argument.
    #[test]
    fn ln_equals_mpfr_bit_for_bit() {
        for p in [53u32, 64, 107, 127, 128, 131, 200] {
            let mut args = Vec::new();
            for k in (-200..=200).step_by(3) {
                for f in [1.0, 1.37, 1.9999, 0.5001, 0.707, 1.414] {
                    args.push(Float::with_val(p, f) << k);
                }
            }
            for t in [1e-40, 1e-12, 3e-4, 9.7e-4, 1e-3, 0.01, 0.3, 0.3466, 0.35] {
                args.push(Float::with_val(p, 1) + Float::with_val(p, t));
                args.push(Float::with_val(p, 1) - Float::with_val(p, t));
            }
            for x in arguments(p).into_iter().filter(|x| *x > 0) {
                // 1 + x^3 2^17 spans (1, 1e6].
                args.push(Float::with_val(p, x.clone().square() * &x) * 2048u32 * 64u32 + 1u32);
            }
            args.extend([1.0, 0.0, -1.0].iter().map(|v| Float::with_val(p, *v)));
            args.push(Float::with_val(working(p) + 10, 3.7));
            for x in &args {
                let got = ln(x, p);
                let want = Float::with_val(p, x.ln_ref());
                assert!(
                    (got == want && got.is_sign_negative() == want.is_sign_negative())
                        || (got.is_nan() && want.is_nan()),
                    "ln {x} at {p}: {got} vs {want}"
                );
            }
        }
    }
}
