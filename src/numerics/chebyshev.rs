//! Chebyshev interpolation on tau in [0, 1] (x = 2 tau - 1) in MPFR: nodes of the first kind,
//! coefficients, Clenshaw evaluation, and the integral int_0^T. The coefficients' cosines are
//! computed once per (n, precision) in a process (`cosines`), and a [`Series`] sums in
//! `Fixed` arithmetic (`numerics::fixed_float`): both give the bits of the MPFR loops they replace (tests below).

use crate::numerics::fixed_float::Fixed;
use rug::{Assign, Float, Integer};
use std::sync::{Arc, Mutex};

/// Chebyshev points of the first kind mapped to (0, 1): tau_i = (1 + cos(pi (i + 1/2)/n))/2.
pub fn nodes(n: usize, prec: u32) -> Vec<Float> {
    let pi = Float::with_val(prec, rug::float::Constant::Pi);
    (0..n)
        .map(|i| {
            let ang = Float::with_val(prec, &pi * (2 * i + 1) as u32) / (2 * n) as u32;
            (ang.cos() + 1u32) / 2u32
        })
        .collect()
}

/// Coefficients c_j of the interpolant sum_j c_j T_j(2 tau - 1) through values at [`nodes`].
pub fn coefficients(values: &[Float], prec: u32) -> Vec<Float> {
    let n = values.len();
    let cos = cosines(n, prec);
    let mut product = Float::new(prec);
    (0..n)
        .map(|j| {
            let mut acc = Float::with_val(prec, 0);
            for (c, v) in cos[j * n..(j + 1) * n].iter().zip(values) {
                // The product rounded, then the sum (no fused multiply-add).
                product.assign(c * v);
                acc += &product;
            }
            let scale = if j == 0 { 1u32 } else { 2u32 };
            acc * scale / n as u32
        })
        .collect()
}

/// The largest n whose [`cosines`] are kept (n^2 numbers a precision).
const CACHED_COSINES: usize = 128;

/// Most mantissa bits the kept [`cosines`] hold together (2^28, 32 MiB): a sweep over many
/// precisions empties the tables when the next one would pass it.
const COSINES_BITS: usize = 1 << 28;

/// cos(a_ji), a_ji = pi j (2 i + 1)/(2 n) rounded as the product by pi then the quotient by 2 n
/// (each to `prec` bits), for j, i < n (row j at j n): the matrix of [`coefficients`], which the
/// loading law's residuals take at a few (n, prec) many times over (their 2 n^2 cosines were
/// 2.8 % of its MPFR solve, all on the main thread). Kept for the process up to n =
/// [`CACHED_COSINES`], emptied when [`COSINES_BITS`] would be passed: the same numbers as
/// computing them anew.
fn cosines(n: usize, prec: u32) -> Arc<Vec<Float>> {
    type Table = ((usize, u32), Arc<Vec<Float>>);
    static TABLES: Mutex<Vec<Table>> = Mutex::new(Vec::new());
    let compute = || {
        let pi = Float::with_val(prec, rug::float::Constant::Pi);
        let mut out = Vec::with_capacity(n * n);
        for j in 0..n {
            for i in 0..n {
                let ang = Float::with_val(prec, &pi * (j * (2 * i + 1)) as u32) / (2 * n) as u32;
                out.push(ang.cos());
            }
        }
        Arc::new(out)
    };
    if n > CACHED_COSINES {
        return compute();
    }
    let mut tables = TABLES.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    if let Some((_, t)) = tables.iter().find(|(key, _)| *key == (n, prec)) {
        return t.clone();
    }
    let t = compute();
    keep_within(&mut tables, ((n, prec), t.clone()), COSINES_BITS);
    t
}

/// Adds a table of [`cosines`] to `tables`, emptied first if their mantissa bits would pass `limit`.
fn keep_within<T>(tables: &mut Vec<((usize, u32), T)>, table: ((usize, u32), T), limit: usize) {
    let bits = |&((n, prec), _): &((usize, u32), T)| n * n * prec as usize;
    if tables.iter().map(bits).sum::<usize>() + bits(&table) > limit {
        tables.clear();
    }
    tables.push(table);
}

/// Clenshaw evaluation of sum_j c_j T_j(x).
pub fn evaluate(coeffs: &[Float], x: &Float, prec: u32) -> Float {
    let mut out = Float::new(prec);
    Clenshaw::new(prec).evaluate_into(coeffs, x, &mut out);
    out
}

/// Scratch of [`evaluate`] for many evaluations at one precision without allocating (the same
/// operations and roundings, so the same bits).
#[derive(Debug, Clone)]
pub struct Clenshaw {
    prec: u32,
    b0: Float,
    b1: Float,
    b2: Float,
    two_x: Float,
    /// The mantissa on the way back from [`Fixed`] ([`Series`]).
    digits: Integer,
}

impl Clenshaw {
    /// Scratch at `prec` bits.
    pub fn new(prec: u32) -> Self {
        let z = Float::new(prec);
        Clenshaw { prec, b0: z.clone(), b1: z.clone(), b2: z.clone(), two_x: z, digits: Integer::new() }
    }

    /// sum_j c_j T_j(x) into `out` (rounded to `prec` bits, the precision `out` is set to).
    pub(crate) fn evaluate_into(&mut self, coeffs: &[Float], x: &Float, out: &mut Float) {
        let prec = self.prec;
        let Clenshaw { b0, b1, b2, two_x, .. } = self;
        b1.assign(0);
        b2.assign(0);
        two_x.assign(x * 2u32);
        for c in coeffs.iter().skip(1).rev() {
            b0.assign(&*two_x * &*b1);
            *b0 -= &*b2;
            *b0 += c;
            // (b2, b1) <- (b1, b0); b0 is scratch again.
            std::mem::swap(b2, b1);
            std::mem::swap(b1, b0);
        }
        out.set_prec(prec);
        match coeffs.first() {
            Some(c0) => {
                out.assign(x * &*b1);
                *out -= &*b2;
                *out += c0;
            }
            None => out.assign(0),
        }
    }
}

/// A Chebyshev series for many [`Clenshaw`] sums at one precision: its coefficients converted
/// once to `Fixed` of L limbs (64 (L - 1) < prec <= 64 L <= 256), whose products and sums are
/// MPFR's roundings without MPFR's calls, so each sum gives the bits of `Clenshaw::evaluate_into`
/// (test below); beyond 256 bits, or where a coefficient is not a finite number of at most
/// `prec` bits, the MPFR loop. For the loading law's edge integrals, two sums per rule point.
#[derive(Debug, Clone)]
pub struct Series {
    prec: u32,
    coeffs: Vec<Float>,
    fixed: FixedCoefficients,
}

/// [`Series`]' coefficients in [`Fixed`], by limbs.
#[derive(Debug, Clone)]
enum FixedCoefficients {
    None,
    L1(Vec<Fixed<1>>),
    L2(Vec<Fixed<2>>),
    L3(Vec<Fixed<3>>),
    L4(Vec<Fixed<4>>),
}

impl Series {
    /// The series sum_j `coeffs`_j T_j at `prec` bits.
    pub fn new(coeffs: &[Float], prec: u32) -> Self {
        fn convert<const L: usize>(c: &[Float], prec: u32) -> Option<Vec<Fixed<L>>> {
            c.iter().map(|v| if v.prec() <= prec { Fixed::<L>::from_float(v) } else { None }).collect()
        }
        let fixed = match prec.div_ceil(64) {
            1 => convert::<1>(coeffs, prec).map(FixedCoefficients::L1),
            2 => convert::<2>(coeffs, prec).map(FixedCoefficients::L2),
            3 => convert::<3>(coeffs, prec).map(FixedCoefficients::L3),
            4 => convert::<4>(coeffs, prec).map(FixedCoefficients::L4),
            _ => None,
        };
        Series { prec, coeffs: coeffs.to_vec(), fixed: fixed.unwrap_or(FixedCoefficients::None) }
    }

    /// The sum at x into `out` (`prec` bits), `scratch` at the same precision: the bits of
    /// `scratch.evaluate_into(coeffs, x, out)`.
    pub fn evaluate_into(&self, x: &Float, out: &mut Float, scratch: &mut Clenshaw) {
        let done = match &self.fixed {
            FixedCoefficients::L1(c) => fixed_sum(c, x, self.prec, out, &mut scratch.digits),
            FixedCoefficients::L2(c) => fixed_sum(c, x, self.prec, out, &mut scratch.digits),
            FixedCoefficients::L3(c) => fixed_sum(c, x, self.prec, out, &mut scratch.digits),
            FixedCoefficients::L4(c) => fixed_sum(c, x, self.prec, out, &mut scratch.digits),
            FixedCoefficients::None => false,
        };
        if !done {
            scratch.evaluate_into(&self.coeffs, x, out);
        }
    }
}

/// [`Clenshaw::evaluate_into`]'s operations in [`Fixed`] (2 x exact in both); false, `out`
/// untouched, where x is not a finite number of at most `prec` bits.
fn fixed_sum<const L: usize>(c: &[Fixed<L>], x: &Float, prec: u32, out: &mut Float, digits: &mut Integer) -> bool {
    let Some(xf) = (if x.prec() <= prec { Fixed::<L>::from_float(x) } else { None }) else {
        return false;
    };
    let two_x = xf.mul_2exp(1);
    let (mut b1, mut b2) = (Fixed::<L>::zero(false), Fixed::<L>::zero(false));
    for ck in c.iter().skip(1).rev() {
        let b0 = two_x.mul(&b1, prec).sub(&b2, prec).add(ck, prec);
        b2 = b1;
        b1 = b0;
    }
    out.set_prec(prec);
    match c.first() {
        Some(c0) => xf.mul(&b1, prec).sub(&b2, prec).add(c0, prec).assign_to(out, digits),
        None => out.assign(0),
    }
    true
}

/// int_0^T sum_j c_j T_j(2 tau - 1) d tau for T in [0, 1].
pub fn integral(coeffs: &[Float], t_upper: &Float, prec: u32) -> Float {
    // Antiderivative in x of sum c_j T_j: coefficients d_k, then (1/2)(D(x_T) - D(-1)).
    let n = coeffs.len();
    let mut d = vec![Float::with_val(prec, 0); n + 2];
    for (j, c) in coeffs.iter().enumerate() {
        match j {
            0 => d[1] += c,
            1 => d[2] += Float::with_val(prec, c / 4u32),
            _ => {
                d[j + 1] += Float::with_val(prec, c / (2 * (j + 1)) as u32);
                d[j - 1] -= Float::with_val(prec, c / (2 * (j - 1)) as u32);
            }
        }
    }
    let x = Float::with_val(prec, t_upper * 2u32) - 1u32;
    let m1 = Float::with_val(prec, -1);
    (evaluate(&d, &x, prec) - evaluate(&d, &m1, prec)) / 2u32
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The coefficients as computed before the table of [`cosines`]: each cosine anew.
    fn coefficients_anew(values: &[Float], prec: u32) -> Vec<Float> {
        let n = values.len();
        let pi = Float::with_val(prec, rug::float::Constant::Pi);
        (0..n)
            .map(|j| {
                let mut acc = Float::with_val(prec, 0);
                for (i, v) in values.iter().enumerate() {
                    let ang = Float::with_val(prec, &pi * (j * (2 * i + 1)) as u32) / (2 * n) as u32;
                    acc += ang.cos() * v;
                }
                let scale = if j == 0 { 1u32 } else { 2u32 };
                acc * scale / n as u32
            })
            .collect()
    }

    /// A deterministic pseudo-random number in (-1, 1) with `prec` significant bits.
    fn random(state: &mut u64, prec: u32) -> Float {
        let mut x = Float::with_val(prec, 0);
        for _ in 0..prec.div_ceil(53) {
            *state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            x += (*state >> 11) as f64;
            x >>= 53;
        }
        if *state & 1 == 1 {
            x = -x;
        }
        x
    }

    /// The coefficients from the kept cosines equal those with every cosine computed anew, bit
    /// for bit, on the first call (table made) and the second (table read), and beyond the kept
    /// sizes (n = 130); 107, 127 and 300 bits.
    #[test]
    fn kept_cosines_are_emptied_before_passing_their_bound() {
        let mut tables = Vec::new();
        // 4 x 4 x 100 = 1600 bits a table: two fit under 4000, the third empties them
        for (k, prec) in [100u32, 100, 100].into_iter().enumerate() {
            keep_within(&mut tables, ((4, prec), k), 4000);
        }
        assert_eq!(tables.iter().map(|(_, k)| *k).collect::<Vec<_>>(), vec![2]);
        keep_within(&mut tables, ((4, 100), 3), 4000);
        assert_eq!(tables.len(), 2);
    }

    #[test]
    fn coefficients_from_kept_cosines_equal_fresh_ones() {
        let mut state = 7;
        for (n, prec) in [(27, 107), (27, 107), (35, 127), (9, 300), (130, 64)] {
            let values: Vec<Float> = (0..n).map(|_| random(&mut state, prec)).collect();
            assert_eq!(coefficients(&values, prec), coefficients_anew(&values, prec), "n {n}, {prec} bits");
        }
    }

    /// A [`Series`]' sums in [`Fixed`] equal the MPFR loop's bit for bit (sign of zero
    /// included) at one to four limbs and beyond (300 bits), the loading law's 64, 107 and 127
    /// bits among them, for series of 0 to 40 random terms (zeros among them) at random x in
    /// (-1, 1) and at -1, 0, 1; coefficients of more bits than the precision take the MPFR loop.
    #[test]
    fn fixed_series_equals_the_mpfr_loop() {
        let mut state = 11;
        for prec in [24u32, 53, 64, 65, 107, 127, 128, 131, 192, 200, 256, 300] {
            let mut scratch = Clenshaw::new(prec);
            for case in 0..300 {
                let len = case % 41;
                let mut coeffs: Vec<Float> = (0..len)
                    .map(|k| if k % 7 == 3 { Float::with_val(prec, 0) } else { random(&mut state, prec) })
                    .collect();
                if case % 50 == 7 {
                    coeffs.push(random(&mut state, prec + 70));
                }
                let x = match case % 10 {
                    0 => Float::with_val(prec, -1),
                    1 => Float::with_val(prec, 0),
                    2 => Float::with_val(prec, 1),
                    _ => random(&mut state, prec),
                };
                let (mut got, mut want) = (Float::new(8), Float::new(8));
                Series::new(&coeffs, prec).evaluate_into(&x, &mut got, &mut scratch);
                Clenshaw::new(prec).evaluate_into(&coeffs, &x, &mut want);
                assert!(
                    got == want && got.is_sign_negative() == want.is_sign_negative() && got.prec() == prec,
                    "{prec} bits, case {case}: {got:?} vs {want:?}"
                );
            }
        }
    }

    #[test]
    fn chebyshev_interpolates_and_integrates_exp() {
        let prec = 128;
        let t = nodes(30, prec);
        let v: Vec<Float> = t.iter().map(|x| x.clone().exp()).collect();
        let c = coefficients(&v, prec);
        let x = Float::with_val(prec, 0.3);
        let y = evaluate(&c, &(Float::with_val(prec, &x * 2u32) - 1u32), prec);
        assert!(Float::with_val(prec, y - x.clone().exp()).abs().to_f64() < 1e-35);
        let i = integral(&c, &x, prec);
        assert!(Float::with_val(prec, i - (x.exp() - 1u32)).abs().to_f64() < 1e-35);
    }
}
