//! e^x, ln x, ln(1 + x) and x^a of MPFR numbers, within one unit in the last place of the
//! result's precision p (not correctly rounded), faster than MPFR's own (a table and a short
//! series in place of MPFR's AGM logarithm and generic power): for the inner loops of the spectral friction method (`adhesion::friction`),
//! where three of these per quadrature node had taken 40% of a solve (docs/theory.md section
//! 17.8, "Where the time goes now").
//!
//! Method: tables at the working precision q = p + [`GUARD`] bits, built once per process and q
//! with MPFR (shared by the threads: `numerics::parallel` starts new ones for every map): T_j =
//! e^(j/1024), |j| <= 360, ln 2, 1/k!, 1/(2 k + 1).
//! - e^x = 2^k T_j e^r', x = k ln 2 + j/1024 + r' (|r'| <= 2^-11), e^r' by its Taylor series
//!   (Horner);
//! - ln x = e ln 2 + j/1024 + ln(1 + z), x = 2^e m with 1/sqrt(2) <= m < sqrt(2), j the nearest
//!   1024 ln m (from `f64`), z = m T_-j - 1 (|z| <~ 2^-11; exact when j = 0, so ln x keeps its
//!   relative accuracy near x = 1), ln(1 + z) = 2 atanh(z/(2 + z)) by its series;
//! - ln(1 + x) = the series of ln(1 + z) at z = x where 1024 ln(1 + x) rounds to 0 (no 1 + x
//!   formed), else ln of 1 + x formed at q bits;
//! - x^a = e^(a ln x) with ln x kept at q bits.
//!
//! The rounding errors of the q-bit arithmetic stay below 2^(11 + 9) ulp(q) (the cancellation in
//! z loses at most 11 bits; |a ln x| < 2^9 in x^a), i.e. 2^-12 ulp(p), so the result is within
//! 1/2 + 2^-12 ulp(p) of the exact value. Outside the tables' range (|x| >= 2^20 in e^x,
//! |a ln x| >= 2^9 in x^a, non-finite or non-positive arguments) MPFR's functions
//! answer. Test: every function against MPFR at 53 .. 1000 bits over arguments of all scales.

use std::cell::RefCell;
use std::sync::{Arc, Mutex};

use rug::float::Constant;
use rug::{Assign, Float};

/// Guard bits of the working precision over the result's.
pub const GUARD: u32 = 32;
/// Table step 2^-STEP of the reduced argument.
pub(crate) const STEP: i32 = 10;
/// Table half-range: |j| <= RANGE covers |j 2^-STEP| <= 0.3516 >= ln(2)/2 + 2^-STEP.
pub(crate) const RANGE: i32 = 360;

/// The tables of one working precision q.
pub(crate) struct Tables {
    pub(crate) q: u32,
    /// e^(j/1024) for j = -RANGE ..= RANGE (index j + RANGE).
    pub(crate) exp_j: Vec<Float>,
    /// ln 2 at q + 40 bits (exponents up to 2^30 times it).
    pub(crate) ln2: Float,
    /// 1/k!, k = 0 ..= taylor terms.
    inv_fact: Vec<Float>,
    /// 1/(2 k + 1), k = 0 ..= atanh terms.
    pub(crate) inv_odd: Vec<Float>,
}

impl Tables {
    fn new(q: u32) -> Tables {
        let exp_j = (-RANGE..=RANGE).map(|j| Float::with_val(q, Float::with_val(q, j) >> STEP).exp()).collect();
        // e^r', |r'| <= 2^-11 (1 + 2^-40): the first omitted term r'^(N+1)/(N+1)! below 2^-(q+2)
        let mut n = 1u32;
        let mut log2_term = -11.0f64;
        while log2_term > -(q as f64) - 2.0 {
            n += 1;
            log2_term += -11.0 - (n as f64).log2();
        }
        let mut inv_fact = vec![Float::with_val(q, 1)];
        for k in 1..=n {
            let prev = inv_fact[k as usize - 1].clone();
            inv_fact.push(prev / k);
        }
        // 2 atanh(u) = 2 (u + u^3/3 + ...), |u| <= 2^-11.9: terms up to u^(2K+1) with u^(2K+2) < 2^-(q+2)
        let k_max = (q + 2).div_ceil(23) as usize;
        let inv_odd = (0..=k_max).map(|k| Float::with_val(q, 1) / (2 * k as u32 + 1)).collect();
        Tables { q, exp_j, ln2: Float::with_val(q + 40, Constant::Log2), inv_fact, inv_odd }
    }
}

/// The tables of the process, one per working precision.
static SHARED: Mutex<Vec<Arc<Tables>>> = Mutex::new(Vec::new());

thread_local! {
    /// The tables this thread has taken from [`SHARED`] (no lock after the first use).
    static TABLES: RefCell<Vec<Arc<Tables>>> = const { RefCell::new(Vec::new()) };
}

/// The tables of working precision q.
pub(crate) fn tables(q: u32) -> Arc<Tables> {
    shared_table(&TABLES, &SHARED, |t| t.q == q, || Tables::new(q))
}

/// The entry of a process-wide table list for which `is` holds, made by `make` on the process's
/// first use and kept by each thread in `local` (no lock after a thread's first use; the threads
/// of `numerics::parallel` are new for every map, so a per-thread table alone would be rebuilt
/// per map). Serves these tables and `mp_rounded`'s sines.
pub(crate) fn shared_table<T>(
    local: &'static std::thread::LocalKey<RefCell<Vec<Arc<T>>>>,
    shared: &Mutex<Vec<Arc<T>>>,
    is: impl Fn(&T) -> bool,
    make: impl FnOnce() -> T,
) -> Arc<T> {
    local.with(|t| {
        let mut t = t.borrow_mut();
        if let Some(found) = t.iter().find(|x| is(x)) {
            return found.clone();
        }
        let made = {
            let mut shared = shared.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
            match shared.iter().find(|x| is(x)) {
                Some(found) => found.clone(),
                None => {
                    let made = Arc::new(make());
                    shared.push(made.clone());
                    made
                }
            }
        };
        t.push(made.clone());
        made
    })
}

/// e^x at q bits (x finite, |x| < 2^20).
fn exp_q(x: &Float, tb: &Tables) -> Float {
    let q = tb.q;
    let k = (x.to_f64() / std::f64::consts::LN_2).round();
    let mut r = Float::with_val(q + 40, &tb.ln2 * k);
    r = Float::with_val(q, x - &r);
    let j = ((r.to_f64() * (1 << STEP) as f64).round() as i32).clamp(-RANGE, RANGE);
    // r' = r - j/1024 is exact (both multiples of ulp(r), |r'| <= 2^-11)
    r -= Float::with_val(q, j) >> STEP;
    let coef = &tb.inv_fact;
    let mut acc = coef[coef.len() - 1].clone();
    for c in coef[..coef.len() - 1].iter().rev() {
        acc.mul_add_mut(&r, c);
    }
    acc *= &tb.exp_j[(j + RANGE) as usize];
    acc << k as i32
}

/// ln(1 + z) at q bits for |z| <~ 2^-11 by 2 atanh(z/(2 + z)).
fn ln1p_series(z: &Float, tb: &Tables) -> Float {
    if z.is_zero() {
        return Float::with_val(tb.q, 0);
    }
    let mut u = Float::with_val(tb.q, z + 2u32);
    u = Float::with_val(tb.q, z / &u);
    let u2 = Float::with_val(tb.q, u.square_ref());
    let coef = &tb.inv_odd;
    let mut acc = coef[coef.len() - 1].clone();
    for c in coef[..coef.len() - 1].iter().rev() {
        acc.mul_add_mut(&u2, c);
    }
    acc *= &u;
    acc << 1
}

/// ln x at q bits for x > 0 finite.
fn ln_q(x: &Float, tb: &Tables) -> Float {
    let q = tb.q;
    let mut e = x.get_exp().unwrap_or(0);
    let mut m = Float::with_val(q, x >> e);
    if m < 0.707_106_781_186_547_5 {
        m <<= 1;
        e -= 1;
    }
    let j = ((m.to_f64().ln() * (1 << STEP) as f64).round() as i32).clamp(-RANGE, RANGE);
    // z = m e^(-j/1024) - 1: one rounding, exact for j = 0
    let mut z = Float::new(q);
    z.assign(&m * &tb.exp_j[(RANGE - j) as usize] - &tb.exp_j[RANGE as usize]);
    let mut out = ln1p_series(&z, tb);
    if j != 0 {
        out += Float::with_val(q, j) >> STEP;
    }
    if e != 0 {
        out += Float::with_val(q + 40, &tb.ln2 * e);
    }
    out
}

/// Whether x is a finite number the tables of e^x serve.
fn exp_in_range(x: &Float) -> bool {
    x.is_finite() && x.to_f64().abs() < (1u32 << 20) as f64
}

/// e^x to within 1/2 + 2^-12 ulp of x's precision (module doc).
pub fn exp(x: &Float) -> Float {
    if !exp_in_range(x) {
        return x.clone().exp();
    }
    let tb = tables(x.prec() + GUARD);
    Float::with_val(x.prec(), exp_q(x, &tb))
}

/// ln x to within 1/2 + 2^-12 ulp of x's precision (module doc).
pub fn ln(x: &Float) -> Float {
    if !x.is_finite() || *x <= 0 {
        return x.clone().ln();
    }
    let tb = tables(x.prec() + GUARD);
    Float::with_val(x.prec(), ln_q(x, &tb))
}

/// ln(1 + x) to within 1/2 + 2^-12 ulp of x's precision, accurate for small x (module doc).
pub fn ln_1p(x: &Float) -> Float {
    if !x.is_finite() || *x <= -1 {
        return x.clone().ln_1p();
    }
    let tb = tables(x.prec() + GUARD);
    let y0 = x.to_f64().ln_1p();
    let out = if (y0 * (1 << STEP) as f64).round() == 0.0 {
        ln1p_series(&Float::with_val(tb.q, x), &tb)
    } else {
        ln_q(&Float::with_val(tb.q, x + 1u32), &tb)
    };
    Float::with_val(x.prec(), out)
}

/// x^a for x > 0 to within 1/2 + 2^-12 ulp of x's precision while |a ln x| < 2^9 (module doc);
/// MPFR's power elsewhere.
pub fn pow(x: &Float, a: &Float) -> Float {
    if !x.is_finite() || *x <= 0 || !a.is_finite() {
        return Float::with_val(x.prec(), rug::ops::Pow::pow(x, a));
    }
    let tb = tables(x.prec() + GUARD);
    let mut l = ln_q(x, &tb);
    l *= a;
    if l.to_f64().abs() >= 512.0 {
        return Float::with_val(x.prec(), rug::ops::Pow::pow(x, a));
    }
    Float::with_val(x.prec(), exp_q(&l, &tb))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::ops::Pow;

    /// |got - want| in units of the last place of want at precision p.
    fn ulps(got: &Float, want: &Float, p: u32) -> f64 {
        if want.is_zero() {
            return if got.is_zero() { 0.0 } else { f64::INFINITY };
        }
        let diff = Float::with_val(p + 64, got - want).abs();
        let ulp = Float::with_val(64, 1) << (want.get_exp().unwrap() - p as i32);
        Float::with_val(64, diff / ulp).to_f64()
    }

    /// Arguments of all scales: +-2^k (1 + small), k = -200 .. 200, and near 1.
    fn arguments(p: u32) -> Vec<Float> {
        let mut out = Vec::new();
        for k in (-200..=200).step_by(7) {
            for f in [1.0, 1.37, 1.9999, 0.5001, 0.707, 1.414] {
                out.push(Float::with_val(p, f) << k);
            }
        }
        for t in [1e-40, 1e-12, 3e-4, 9.7e-4, 1e-3, 0.01, 0.3, 0.3466, 0.35] {
            out.push(Float::with_val(p, 1) + Float::with_val(p, t));
            out.push(Float::with_val(p, 1) - Float::with_val(p, t));
        }
        out
    }

    #[test]
    fn agree_with_mpfr_to_one_ulp() {
        for p in [53u32, 100, 160, 200, 232, 300, 521, 1000] {
            let mut worst = [0.0f64; 4];
            let a = Float::with_val(p, -0.578_123_456_789);
            for x in arguments(p) {
                if x > 0 {
                    worst[1] = worst[1].max(ulps(&ln(&x), &x.clone().ln(), p));
                    let pw = x.clone().pow(&a);
                    if (Float::with_val(64, x.ln_ref()) * &a).to_f64().abs() < 500.0 {
                        worst[3] = worst[3].max(ulps(&pow(&x, &a), &pw, p));
                    }
                }
                for s in [1i32, -1] {
                    let y = Float::with_val(p, &x * s);
                    if y.to_f64().abs() < 1e4 {
                        worst[0] = worst[0].max(ulps(&exp(&y), &y.clone().exp(), p));
                    }
                    if y > -1 {
                        worst[2] = worst[2].max(ulps(&ln_1p(&y), &y.clone().ln_1p(), p));
                    }
                }
            }
            for (name, w) in ["exp", "ln", "ln_1p", "pow"].iter().zip(worst) {
                assert!(w <= 1.0, "{name} at {p} bits: {w} ulp");
            }
        }
    }

    #[test]
    fn special_arguments_are_mpfr_s() {
        let p = 160;
        assert_eq!(exp(&Float::with_val(p, 0)), 1);
        assert!(ln(&Float::with_val(p, 1)).is_zero());
        assert!(ln_1p(&Float::with_val(p, 0)).is_zero());
        assert!(ln(&Float::with_val(p, 0)).is_infinite());
        assert!(ln(&Float::with_val(p, -1)).is_nan());
        let tiny = Float::with_val(p, 1) >> 300;
        assert_eq!(ulps(&ln_1p(&tiny), &tiny.clone().ln_1p(), p), 0.0);
    }
}
