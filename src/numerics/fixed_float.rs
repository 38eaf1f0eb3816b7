//! Binary floating point with a mantissa of at most 64 L bits (L = 1..=4 limbs), rounded after
//! every operation to a precision p, 64 (L - 1) < p <= 64 L, to nearest with ties to even: the same value, bit for
//! bit, as MPFR's `MPFR_RNDN` at p bits (the rounding of `rug::Float` arithmetic), for the three
//! operations a long multiply-add loop needs (product, sum, difference) with no function call, no
//! heap, no special values to dispatch. For the inner loops of the MPFR solvers, whose results
//! must not move by one bit: the numbers are converted from and to `rug::Float` exactly
//! ([`Fixed::from_float`], [`Fixed::to_float`]). Correct rounding makes the result unique, so the
//! test of this module compares every operation with MPFR's on millions of operands, the
//! hard cases included (ties, cancellation, carries, exponent gaps around the precision).
//!
//! Representation: value = (-1)^neg 0.m 2^exp, the mantissa m (little-endian limbs) normalised
//! with its top bit set, bits below the precision zero (MPFR's convention, so the exponent is
//! `Float::get_exp`); zero is m = 0 with a sign. No infinities, NaN or exponent limits: the
//! operands of the loops this serves are finite and far from MPFR's exponent range (a product or
//! sum leaving i64's range would overflow an integer, caught in debug builds).

use rug::integer::Order;
use rug::ops::NegAssign;
use rug::{Assign, Float, Integer};

/// A number of at most 64 L significant bits (module doc).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Fixed<const L: usize> {
    m: [u64; L],
    exp: i64,
    neg: bool,
}

impl<const L: usize> Fixed<L> {
    /// Zero with the given sign.
    pub fn zero(neg: bool) -> Self {
        Fixed { m: [0; L], exp: 0, neg }
    }

    /// Whether the value is (signed) zero.
    #[inline(always)]
    pub fn is_zero(&self) -> bool {
        self.m[L - 1] == 0
    }

    /// The exact value of `x`, or None when `x` is not finite or has more than 64 L bits of
    /// precision.
    pub fn from_float(x: &Float) -> Option<Self> {
        if !(1..=L).contains(&x.prec().div_ceil(64).try_into().unwrap_or(usize::MAX)) {
            return None;
        }
        if x.is_zero() {
            return Some(Self::zero(x.is_sign_negative()));
        }
        let (sig, exp) = (x.get_significand()?, x.get_exp()?);
        let limbs = sig.as_limbs();
        let mut m = [0u64; L];
        m[L - limbs.len()..].copy_from_slice(limbs);
        Some(Fixed { m, exp: exp as i64, neg: x.is_sign_negative() })
    }

    /// The exact value as a `Float` of `prec` bits (at least this number's significant bits).
    pub fn to_float(&self, prec: u32) -> Float {
        if self.is_zero() {
            let z = Float::with_val(prec, 0);
            return if self.neg { -z } else { z };
        }
        let int = Integer::from_digits(&self.m, Order::Lsf);
        let shift = self.exp - 64 * L as i64;
        let mut f = Float::with_val(prec, int);
        f <<= shift as i32;
        if self.neg {
            -f
        } else {
            f
        }
    }

    /// Writes the exact value into `out` (whose precision must hold this number's significant
    /// bits), with `scratch` for the mantissa: no allocation once `scratch` holds 64 L bits
    /// ([`Self::to_float`] allocates).
    pub(crate) fn assign_to(&self, out: &mut Float, scratch: &mut Integer) {
        if self.is_zero() {
            out.assign(0);
        } else {
            scratch.assign_digits(&self.m, Order::Lsf);
            // Exact: at most prec(out) significant bits, then a power of two.
            out.assign(&*scratch);
            *out <<= (self.exp - 64 * L as i64) as i32;
        }
        if self.neg {
            out.neg_assign();
        }
    }

    /// -self.
    #[inline(always)]
    pub(crate) fn negated(mut self) -> Self {
        self.neg = !self.neg;
        self
    }

    /// 2^k self (exact).
    #[inline(always)]
    pub(crate) fn mul_2exp(mut self, k: i64) -> Self {
        if !self.is_zero() {
            self.exp += k;
        }
        self
    }

    /// |self| against |b|.
    pub(crate) fn cmp_abs(&self, b: &Self) -> std::cmp::Ordering {
        match (self.is_zero(), b.is_zero()) {
            (true, true) => std::cmp::Ordering::Equal,
            (true, false) => std::cmp::Ordering::Less,
            (false, true) => std::cmp::Ordering::Greater,
            (false, false) => self.exp.cmp(&b.exp).then_with(|| self.m.iter().rev().cmp(b.m.iter().rev())),
        }
    }

    /// self * b rounded to `p` bits (64 (L - 1) < p <= 64 L; both operands of at most p bits).
    #[inline(always)]
    pub fn mul(&self, b: &Self, p: u32) -> Self {
        let neg = self.neg != b.neg;
        if self.is_zero() || b.is_zero() {
            return Self::zero(neg);
        }
        // The 2 L limbs of the product, column by column (independent multiplications).
        let mut w = [0u64; 8];
        let mut acc: u128 = 0;
        let mut acc_hi: u64 = 0;
        for k in 0..2 * L - 1 {
            let lo = k.saturating_sub(L - 1);
            let hi = k.min(L - 1);
            for i in lo..=hi {
                let prod = self.m[i] as u128 * b.m[k - i] as u128;
                let (s, c) = acc.overflowing_add(prod);
                acc = s;
                acc_hi += c as u64;
            }
            w[k] = acc as u64;
            acc = (acc >> 64) | ((acc_hi as u128) << 64);
            acc_hi = 0;
        }
        w[2 * L - 1] = acc as u64;
        let mut exp = self.exp + b.exp;
        // The window: the top L limbs, one guard limb below, and whether any lower bit is set.
        let mut m = [0u64; L];
        m.copy_from_slice(&w[L..2 * L]);
        let mut guard = w[L - 1];
        let mut sticky = w[..L - 1].iter().any(|&x| x != 0);
        // Normalise: the top bit of the product is bit 128 L - 1 or 128 L - 2.
        if m[L - 1] >> 63 == 0 {
            for k in (1..L).rev() {
                m[k] = (m[k] << 1) | (m[k - 1] >> 63);
            }
            m[0] = (m[0] << 1) | (guard >> 63);
            let below = if L >= 2 { w[L - 2] } else { 0 };
            guard = (guard << 1) | (below >> 63);
            sticky = (below << 1) != 0 || w[..L.saturating_sub(2)].iter().any(|&x| x != 0);
            exp -= 1;
        }
        round_window(m, guard, sticky, p, exp, neg)
    }

    /// self + b rounded to `p` bits (64 (L - 1) < p <= 64 L; both operands of at most p bits).
    #[inline(always)]
    pub fn add(&self, b: &Self, p: u32) -> Self {
        add_signed(self, b, p)
    }

    /// self - b rounded to `p` bits.
    #[inline(always)]
    pub fn sub(&self, b: &Self, p: u32) -> Self {
        add_signed(self, &b.negated(), p)
    }
}

/// Rounds the normalised window (m: L limbs, top bit set; `guard`: the next 64 bits; `sticky`:
/// whether any bit below them is set) to the top `p` bits of m, to nearest, ties to even.
#[inline(always)]
fn round_window<const L: usize>(
    mut m: [u64; L],
    guard: u64,
    sticky: bool,
    p: u32,
    mut exp: i64,
    neg: bool,
) -> Fixed<L> {
    let low = 64 * L as u32 - p; // bits of m below the precision, 0..=63
    debug_assert!(low < 64, "precision {p} in {L} limbs");
    let (round, below) = if low == 0 {
        (guard >> 63, (guard << 1) != 0)
    } else {
        ((m[0] >> (low - 1)) & 1, (m[0] & ((1u64 << (low - 1)) - 1)) != 0 || guard != 0)
    };
    m[0] &= !0u64 << low;
    let lsb = (m[0] >> low) & 1;
    if round == 1 && (sticky || below || lsb == 1) {
        let (v, mut c) = m[0].overflowing_add(1u64 << low);
        m[0] = v;
        for x in m[1..].iter_mut() {
            let (v, c2) = x.overflowing_add(c as u64);
            *x = v;
            c = c2;
        }
        if c {
            m[L - 1] = 1 << 63;
            exp += 1;
        }
    }
    Fixed { m, exp, neg }
}

/// Limb k of the window (guard, m): 0 is the guard limb.
#[inline(always)]
fn limb<const L: usize>(m: &[u64; L], guard: u64, k: usize) -> u64 {
    if k == 0 {
        guard
    } else {
        m[k - 1]
    }
}

/// a + b rounded to p bits, signs included (MPFR RNDN: an exact zero sum is +0 unless both are -0).
#[inline(always)]
fn add_signed<const L: usize>(a: &Fixed<L>, b: &Fixed<L>, p: u32) -> Fixed<L> {
    if b.is_zero() {
        if a.is_zero() {
            return Fixed::zero(a.neg && b.neg);
        }
        return *a;
    }
    if a.is_zero() {
        return *b;
    }
    // |x| >= |y|.
    let a_bigger = a.exp > b.exp || (a.exp == b.exp && a.m.iter().rev().cmp(b.m.iter().rev()).is_ge());
    let (x, y) = if a_bigger { (a, b) } else { (b, a) };
    let d = (x.exp - y.exp) as u64;
    let subtract = x.neg != y.neg;
    // Window: x's L limbs and a guard limb below; y shifted right by d into it, the bits that
    // fall below summarised by `sticky`.
    if d >= 64 * (L as u64 + 1) {
        // |y| < 2^(exp_x - 64 L - 64) <= half an ulp of x (even below a power of two): x.
        return *x;
    }
    let (dq, dr) = ((d / 64) as usize, (d % 64) as u32);
    // y as L + 1 limbs (guard 0), shifted right by dq limbs and dr bits.
    let y_at = |k: usize| -> u64 { limb(&y.m, 0, k) };
    let mut ym = [0u64; L];
    let mut yg = 0u64;
    let mut sticky = false;
    if dq == 0 {
        // The usual case: a gap of less than a limb, nothing falls below the guard limb.
        if dr == 0 {
            ym = y.m;
        } else {
            yg = y.m[0] << (64 - dr);
            for k in 0..L {
                let hi = if k + 1 < L { y.m[k + 1] << (64 - dr) } else { 0 };
                ym[k] = (y.m[k] >> dr) | hi;
            }
        }
    } else {
        for k in 0..=L {
            let src = k + dq;
            let lo = if src <= L { y_at(src) >> dr } else { 0 };
            let hi = if dr > 0 && src < L { y_at(src + 1) << (64 - dr) } else { 0 };
            if k == 0 {
                yg = lo | hi;
            } else {
                ym[k - 1] = lo | hi;
            }
        }
        // Bits shifted out below the guard limb: limbs below dq (of y's window) and dr bits of
        // limb dq.
        for k in 0..dq.min(L + 1) {
            sticky |= y_at(k) != 0;
        }
        if dr > 0 && dq <= L {
            sticky |= (y_at(dq) << (64 - dr)) != 0;
        }
    }
    let mut m = x.m;
    let mut guard = 0u64;
    let mut exp = x.exp;
    if !subtract {
        let (g, mut c) = guard.overflowing_add(yg);
        guard = g;
        for k in 0..L {
            let (s1, c1) = m[k].overflowing_add(ym[k]);
            let (s2, c2) = s1.overflowing_add(c as u64);
            m[k] = s2;
            c = c1 || c2;
        }
        if c {
            sticky |= guard & 1 == 1;
            guard = (guard >> 1) | (m[0] << 63);
            for k in 0..L - 1 {
                m[k] = (m[k] >> 1) | (m[k + 1] << 63);
            }
            m[L - 1] = (m[L - 1] >> 1) | (1 << 63);
            exp += 1;
        }
    } else {
        // x - y, minus one unit of the window when y had bits below it: the exact difference
        // then lies strictly between w and w + 1 (units of the window's last bit), `sticky` set.
        let (g1, b1) = guard.overflowing_sub(yg);
        let (g2, b2) = g1.overflowing_sub(sticky as u64);
        guard = g2;
        let mut borrow = b1 || b2;
        for k in 0..L {
            let (s1, b1) = m[k].overflowing_sub(ym[k]);
            let (s2, b2) = s1.overflowing_sub(borrow as u64);
            m[k] = s2;
            borrow = b1 || b2;
        }
        debug_assert!(!borrow);
        // Normalise. With sticky set, d >= 64 and the shift is at most one bit: the bit shifted
        // in is unknown but lies 63 bits below the round bit, where only sticky matters.
        let mut lz = 0usize;
        let mut found = false;
        for k in (0..=L).rev() {
            let v = limb(&m, guard, k);
            if v != 0 {
                lz += v.leading_zeros() as usize;
                found = true;
                break;
            }
            lz += 64;
        }
        if !found {
            return Fixed::zero(false);
        }
        if lz > 0 && lz < 64 {
            // The usual case: a shift of less than a limb.
            let r = lz as u32;
            for k in (1..L).rev() {
                m[k] = (m[k] << r) | (m[k - 1] >> (64 - r));
            }
            m[0] = (m[0] << r) | (guard >> (64 - r));
            guard <<= r;
            exp -= lz as i64;
        } else if lz > 0 {
            let (q, r) = (lz / 64, (lz % 64) as u32);
            let mut out = [0u64; L];
            let mut og = 0u64;
            for k in (0..=L).rev() {
                let lo = if k >= q { limb(&m, guard, k - q) << r } else { 0 };
                let lo2 = if r > 0 && k > q { limb(&m, guard, k - q - 1) >> (64 - r) } else { 0 };
                if k == 0 {
                    og = lo | lo2;
                } else {
                    out[k - 1] = lo | lo2;
                }
            }
            m = out;
            guard = og;
            exp -= lz as i64;
        }
    }
    round_window(m, guard, sticky, p, exp, x.neg)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Assign;

    /// A deterministic generator (splitmix64).
    struct Rng(u64);
    impl Rng {
        fn next(&mut self) -> u64 {
            self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^ (z >> 31)
        }
    }

    /// A random p-bit number in one of several shapes: full random mantissa, runs of ones or
    /// zeros (carries, ties), a power of two, near another operand.
    fn operand(rng: &mut Rng, p: u32, near: Option<&Float>) -> Float {
        let kind = rng.next() % 8;
        let mut f = Float::new(p);
        let bits = p as usize;
        let mut int = Integer::new();
        match kind {
            0 => int.assign(Integer::from(1) << (bits - 1)),
            1 => int.assign((Integer::from(1) << bits) - 1),
            2 => {
                // ones then zeros then a random tail
                let k = (rng.next() % bits as u64) as usize;
                int.assign(((Integer::from(1) << bits) - 1) ^ ((Integer::from(1) << k) - 1));
                int |= Integer::from(rng.next() % 4);
                int |= Integer::from(1) << (bits - 1);
            }
            3 => {
                // 1 followed by zeros and a low one: ties in products and sums
                int.assign(
                    (Integer::from(1) << (bits - 1)) + (Integer::from(1) << (rng.next() % bits as u64) as usize),
                );
                if int.significant_bits() as usize > bits {
                    int >>= 1;
                }
            }
            _ => {
                for _ in 0..bits.div_ceil(64) {
                    int <<= 64;
                    int += rng.next();
                }
                int >>= int.significant_bits().saturating_sub(bits as u32);
                int |= Integer::from(1) << (bits - 1);
            }
        }
        f.assign(&int);
        let e = (rng.next() % 40) as i32 - 20;
        f >>= bits as i32 - e;
        if rng.next() % 2 == 0 {
            f = -f;
        }
        if let Some(n) = near {
            if rng.next() % 3 == 0 {
                // Within a few ulps of `n` (cancellation), or n's exponent shifted by ~p.
                let mut g = Float::with_val(p, n);
                let ulp = Float::with_val(p, Float::i_exp(1, n.get_exp().unwrap_or(0) - p as i32));
                let k = (rng.next() % 7) as i32 - 3;
                g += Float::with_val(p, &ulp * k);
                if rng.next() % 2 == 0 {
                    g = -g;
                }
                return g;
            }
            if rng.next() % 2 == 0 {
                // An exponent gap around 64 k and around the precision (alignment, sticky bits).
                let gaps = [0, 1, 2, 3, 62, 63, 64, 65, p - 1, p, p + 1, p + 2, p + 3, p + 63, p + 64, p + 65, p + 128];
                let gap = gaps[(rng.next() % gaps.len() as u64) as usize] as i32;
                let target = n.get_exp().unwrap_or(0) - gap;
                let cur = f.get_exp().unwrap_or(target);
                f <<= target - cur;
            }
        }
        if rng.next() % 50 == 0 {
            f = Float::with_val(p, 0);
            if rng.next() % 2 == 0 {
                f = -f;
            }
        }
        f
    }

    fn check<const L: usize>(p: u32, cases: usize, seed: u64) {
        let mut rng = Rng(seed);
        let mut digits = Integer::new();
        for case in 0..cases {
            let a = operand(&mut rng, p, None);
            let b = operand(&mut rng, p, Some(&a));
            let (fa, fb) = (Fixed::<L>::from_float(&a).unwrap(), Fixed::<L>::from_float(&b).unwrap());
            assert_eq!(fa.to_float(p), a);
            assert_eq!(fa.to_float(p).is_sign_negative(), a.is_sign_negative());
            let want = [
                Float::with_val(p, &a * &b),
                Float::with_val(p, &a + &b),
                Float::with_val(p, &a - &b),
                Float::with_val(p, &b - &a),
            ];
            assert_eq!(Some(fa.cmp_abs(&fb)), a.cmp_abs(&b), "p = {p}, case {case}: cmp_abs");
            let got = [fa.mul(&fb, p), fa.add(&fb, p), fa.sub(&fb, p), fb.sub(&fa, p)];
            for (k, (w, g)) in want.iter().zip(&got).enumerate() {
                let g = g.to_float(p);
                assert!(
                    g == *w && g.is_sign_negative() == w.is_sign_negative(),
                    "p = {p}, case {case}, op {k}: a = {a:?}, b = {b:?}: MPFR {w:?}, fixed {g:?}"
                );
                assert_eq!(Fixed::<L>::from_float(w).unwrap(), got[k], "p = {p}, case {case}, op {k}: representation");
                let mut out = Float::new(p);
                got[k].assign_to(&mut out, &mut digits);
                assert!(out == *w && out.is_sign_negative() == w.is_sign_negative(), "p = {p}, case {case}: assign_to");
            }
        }
    }

    #[test]
    fn fixed_float_rounds_as_mpfr_rndn() {
        // Every precision class: one limb, limb boundaries, and the report's working precisions
        // (107, 131, 140, 153, 164, 200 bits).
        for p in [2u32, 24, 53, 63, 64] {
            check::<1>(p, 20_000, p as u64);
        }
        for p in [65u32, 100, 107, 127, 128] {
            check::<2>(p, 20_000, p as u64);
        }
        for p in [129u32, 131, 140, 153, 164, 191, 192] {
            check::<3>(p, 20_000, p as u64);
        }
        for p in [193u32, 200, 255, 256] {
            check::<4>(p, 20_000, p as u64);
        }
    }

    #[test]
    fn fixed_float_conversions_refuse_what_does_not_fit() {
        assert!(Fixed::<2>::from_float(&Float::with_val(129, 1)).is_none());
        assert!(Fixed::<2>::from_float(&Float::with_val(128, f64::INFINITY)).is_none());
        assert!(Fixed::<2>::from_float(&Float::with_val(128, f64::NAN)).is_none());
        let x = Fixed::<2>::from_float(&Float::with_val(100, -2.5)).unwrap();
        assert_eq!(x.to_float(100), -2.5);
        assert_eq!(x.mul_2exp(3).to_float(100), -20.0);
        assert_eq!(x.negated().to_float(100), 2.5);
    }
}
