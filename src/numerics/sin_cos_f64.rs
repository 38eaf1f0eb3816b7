//! sin x and cos x together in `f64`, inlined, for the f64 march's kernel
//! ([`crate::growing_contact::kernel_f64`]: two per distance), where glibc's `sincos` spent a
//! quarter of the f64 loading law's time, much of it saving and restoring the rounding mode.
//!
//! The method of musl (FreeBSD's msun, Sun's fdlibm): x = n pi/2 + r, |r| <= pi/4 (about), by
//! Cody-Waite with pi/2 in three parts of 33, 33 and 53 bits (n < 2^19, so n times a part is
//! exact), r kept as r_0 + r_1; then the kernels' minimax polynomials on [-pi/4, pi/4] (sin
//! to degree 13, cos to degree 14, with r_1's first-order term), and the quadrant n mod 4.
//! Their error is below 1 ulp in fdlibm's analysis; test `within_one_ulp_of_mpfr`: against
//! MPFR's correctly rounded values at 200 bits over 200000 arguments in (-20, 20), the points
//! near multiples of pi/2 and small ones, every result within 1 ulp (most exact). Outside
//! |x| < 2^19 pi/2 (and for NaN, infinity) std's `sin_cos` answers.

// fdlibm's constants as published (each decimal rounds to the intended f64).
#![allow(clippy::excessive_precision)]

const INV_PIO2: f64 = std::f64::consts::FRAC_2_PI; // fdlibm's invpio2, 0x3FE45F306DC9C883
const PIO2_1: f64 = 1.570_796_326_734_125_614_17; // first 33 bits of pi/2
const PIO2_1T: f64 = 6.077_100_506_506_192_249_32e-11; // pi/2 - PIO2_1
const PIO2_2: f64 = 6.077_100_506_303_965_976_60e-11; // second 33 bits of pi/2
const PIO2_2T: f64 = 2.022_266_248_795_950_631_54e-21; // pi/2 - (PIO2_1 + PIO2_2)
const PIO2_3: f64 = 2.022_266_248_711_166_455_80e-21; // third 33 bits of pi/2
const PIO2_3T: f64 = 8.478_427_660_368_899_569_97e-32; // pi/2 - (PIO2_1 + PIO2_2 + PIO2_3)

/// sin(r_0 + r_1), |r_0 + r_1| <= pi/4 (fdlibm's __kernel_sin).
#[inline(always)]
fn kernel_sin(x: f64, y: f64) -> f64 {
    const S1: f64 = -1.666_666_666_666_663_243_48e-01;
    const S2: f64 = 8.333_333_333_322_489_461_24e-03;
    const S3: f64 = -1.984_126_982_985_794_931_34e-04;
    const S4: f64 = 2.755_731_370_707_006_767_89e-06;
    const S5: f64 = -2.505_076_025_340_686_341_95e-08;
    const S6: f64 = 1.589_690_995_211_550_102_21e-10;
    let z = x * x;
    let w = z * z;
    let r = S2 + z * (S3 + z * S4) + z * w * (S5 + z * S6);
    let v = z * x;
    if y == 0.0 {
        x + v * (S1 + z * r)
    } else {
        x - ((z * (0.5 * y - v * r) - y) - v * S1)
    }
}

/// cos(r_0 + r_1), |r_0 + r_1| <= pi/4 (fdlibm's __kernel_cos).
#[inline(always)]
fn kernel_cos(x: f64, y: f64) -> f64 {
    const C1: f64 = 4.166_666_666_666_660_190_37e-02;
    const C2: f64 = -1.388_888_888_887_410_957_49e-03;
    const C3: f64 = 2.480_158_728_947_672_941_78e-05;
    const C4: f64 = -2.755_731_435_139_066_330_35e-07;
    const C5: f64 = 2.087_572_321_298_174_827_90e-09;
    const C6: f64 = -1.135_964_755_778_819_482_65e-11;
    let z = x * x;
    let w = z * z;
    let r = z * (C1 + z * (C2 + z * C3)) + w * w * (C4 + z * (C5 + z * C6));
    let hz = 0.5 * z;
    let w = 1.0 - hz;
    w + (((1.0 - w) - hz) + (z * r - x * y))
}

/// (sin x, cos x) (module doc).
#[inline]
pub(crate) fn sin_cos(x: f64) -> (f64, f64) {
    if x.abs() <= std::f64::consts::FRAC_PI_4 {
        return (kernel_sin(x, 0.0), kernel_cos(x, 0.0));
    }
    if x.is_nan() || x.abs() >= 823_550.0 {
        return x.sin_cos();
    }
    // musl's __rem_pio2 medium case: n = round(x 2/pi), then one, two or three parts of pi/2
    // as the cancellation needs (the exponent of r_0 against x's).
    let n = (x * INV_PIO2).round();
    let ex = (x.to_bits() >> 52) & 0x7ff;
    let mut r = x - n * PIO2_1;
    let mut w = n * PIO2_1T;
    let mut y0 = r - w;
    if ex as i64 - ((y0.to_bits() >> 52) & 0x7ff) as i64 > 16 {
        let t = r;
        w = n * PIO2_2;
        r = t - w;
        w = n * PIO2_2T - ((t - r) - w);
        y0 = r - w;
        if ex as i64 - ((y0.to_bits() >> 52) & 0x7ff) as i64 > 49 {
            let t = r;
            w = n * PIO2_3;
            r = t - w;
            w = n * PIO2_3T - ((t - r) - w);
            y0 = r - w;
        }
    }
    let y1 = (r - y0) - w;
    let (s, c) = (kernel_sin(y0, y1), kernel_cos(y0, y1));
    match (n as i64) & 3 {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Float;

    /// Distance in ulps of `got` from MPFR's correctly rounded `f(x)` at 200 bits.
    fn ulps(got: f64, exact: &Float) -> f64 {
        let want = exact.to_f64();
        if want == 0.0 {
            return if got == 0.0 { 0.0 } else { f64::INFINITY };
        }
        let ulp = f64::from_bits(want.abs().to_bits() + 1) - want.abs();
        (got - want).abs() / ulp
    }

    /// Within 1 ulp of the correctly rounded sin and cos (module doc), and std's answer
    /// outside the reduction's range.
    #[test]
    fn within_one_ulp_of_mpfr() {
        let mut xs: Vec<f64> = Vec::new();
        let mut state: u64 = 0x2545_f491_4f6c_dd1d;
        for _ in 0..200_000 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            xs.push(((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 40.0);
        }
        for k in 1..=12 {
            let m = k as f64 * std::f64::consts::FRAC_PI_2;
            for d in [0.0, 1e-300, 1e-16, 1e-12, 1e-8, 1e-4] {
                xs.extend([m + d, m - d, -m + d, -m - d, d, -d]);
            }
            let b = m.to_bits();
            xs.extend([f64::from_bits(b - 1), f64::from_bits(b + 1), -m]);
        }
        xs.extend([std::f64::consts::FRAC_PI_4, -std::f64::consts::FRAC_PI_4, 0.785_398_163_397_448_4, 1e5, -3e5]);
        let (mut worst_s, mut worst_c, mut exact) = (0f64, 0f64, 0usize);
        for &x in &xs {
            let (s, c) = sin_cos(x);
            let xf = Float::with_val(200, x);
            let (es, ec) = (ulps(s, &Float::with_val(200, xf.sin_ref())), ulps(c, &Float::with_val(200, xf.cos_ref())));
            assert!(es <= 1.0 && ec <= 1.0, "x = {x:e}: sin {es} ulp, cos {ec} ulp");
            worst_s = worst_s.max(es);
            worst_c = worst_c.max(ec);
            exact += usize::from(es == 0.0 && ec == 0.0);
        }
        assert!(exact * 10 > xs.len() * 8, "{exact} of {} exact", xs.len());
        for x in [1e6, -2e7, f64::INFINITY, f64::NAN] {
            let (a, b) = (sin_cos(x), x.sin_cos());
            assert!(a.0.to_bits() == b.0.to_bits() && a.1.to_bits() == b.1.to_bits(), "{x}");
        }
        eprintln!("sin_cos: worst {worst_s} ulp (sin), {worst_c} ulp (cos); {exact} of {} both exact", xs.len());
    }
}
