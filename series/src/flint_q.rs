//! The optional FLINT backend of the dense Q series (cargo feature `flint`, off by default; issue
//! 33): the product, inverse, log, exp, power and reversion of a series held as integer numerators
//! over one positive denominator (`c_k = num[k]/den`, the form of `dense_q` and of FLINT's
//! `fmpq_poly`), computed by FLINT 3.5 through flint-sys:
//! `fmpq_poly_mullow`, `fmpq_poly_inv_series`, `fmpq_poly_log_series`, `fmpq_poly_exp_series`,
//! `f^(p/q) = exp((p/q) log f)` (FLINT's integer-exponent `pow_trunc` does not take a rational
//! exponent) and `fmpq_poly_revert_series`. FLINT picks its integer-polynomial product by size
//! (word-size schoolbook, Schönhage–Strassen, its small-prime FFT from length 100, bit-exact
//! Kronecker) and starts its exp with a basecase recurrence, where `dense_q` always makes one GMP
//! product by Kronecker substitution (docs/performance.md, "The profile, side by side with FLINT").
//!
//! The values are exact, so the coefficients are the same rationals as `dense_q`'s and the generic
//! recurrences' (tests in `dense_q.rs`, module `tests::flint`, run by `scripts/test-flint`). Every
//! result has exactly the requested number of coefficients (FLINT drops trailing zeros; they are
//! put back). Callers check the preconditions FLINT aborts on (a zero constant term for the
//! inverse, `f(0) != 1` for log, `f(0) != 0` for exp, `f(0) != 0` or `f'(0) = 0` for the
//! reversion) before calling, as they do for `dense_q`.

use flint_sys::deps::__mpz_struct;
use flint_sys::flint::fmpz;
use flint_sys::fmpq_poly::{
    _fmpq_poly_normalise, _fmpq_poly_set_length, fmpq_poly_canonicalise, fmpq_poly_clear, fmpq_poly_exp_series,
    fmpq_poly_fit_length, fmpq_poly_init, fmpq_poly_inv_series, fmpq_poly_length, fmpq_poly_log_series,
    fmpq_poly_mullow, fmpq_poly_revert_series, fmpq_poly_scalar_div_fmpz, fmpq_poly_scalar_mul_fmpz,
};
use flint_sys::fmpq_types::fmpq_poly_struct;
use flint_sys::fmpz::{fmpz_clear, fmpz_get_mpz, fmpz_set_mpz};
use rug::Integer;
use std::mem::MaybeUninit;

/// From this many coefficients on, the reversion goes to FLINT; the other operations go to FLINT
/// whenever `dense_q` runs (from its threshold of 24 coefficients on: FLINT's series is 2x
/// faster at N = 30, level at N = 100, 1.3x to 1.5x faster at N = 200, 1.1x to 1.2x slower near
/// N = 60).
/// Measured with `series/examples/sinc_power --q` built with and without the feature,
/// interleaved (docs/performance.md, "The optional FLINT backend"): FLINT's reversion is 1.4x to
/// 1.5x faster at N = 30 and 40, 1.1x to 1.25x slower at N = 50 to 70, as fast at N = 80 and
/// 1.5x to 1.7x faster at N = 200.
pub(crate) const REVERT_MIN: usize = 80;

/// A series as numerators over one denominator: the parts `dense_q` keeps.
pub(crate) type Parts = (Vec<Integer>, Integer);

/// An owned `fmpq_poly_t`, cleared on drop.
struct FmpqPoly(fmpq_poly_struct);

impl FmpqPoly {
    fn new() -> FmpqPoly {
        let mut p = MaybeUninit::uninit();
        // SAFETY: fmpq_poly_init initialises the struct it is given.
        unsafe {
            fmpq_poly_init(p.as_mut_ptr());
            FmpqPoly(p.assume_init())
        }
    }

    /// `sum_k num[k]/den x^k` in FLINT's canonical form (`den > 0` asserted by the callers'
    /// representation; the content is removed here).
    fn from_parts(num: &[Integer], den: &Integer) -> FmpqPoly {
        let mut p = FmpqPoly::new();
        let len = num.len() as i64;
        // SAFETY: fit_length allocates `len` zeroed coefficients; each one and the denominator are
        // set from initialised GMP integers (rug's mpz has the layout of __mpz_struct: both are
        // GMP's mpz_t); the length is then set and normalised as fmpq_poly requires.
        unsafe {
            fmpq_poly_fit_length(&mut p.0, len);
            for (k, c) in num.iter().enumerate() {
                fmpz_set_mpz(p.0.coeffs.add(k), c.as_raw().cast::<__mpz_struct>());
            }
            fmpz_set_mpz(p.0.den.as_mut_ptr(), den.as_raw().cast::<__mpz_struct>());
            _fmpq_poly_set_length(&mut p.0, len);
            _fmpq_poly_normalise(&mut p.0);
            fmpq_poly_canonicalise(&mut p.0);
        }
        p
    }

    /// The numerators (exactly `n` of them, zeros past FLINT's length) and the denominator.
    fn to_parts(&self, n: usize) -> Parts {
        let mut num = vec![Integer::new(); n];
        let mut den = Integer::new();
        // SAFETY: the coefficients below the polynomial's length and its denominator are
        // initialised fmpz values; fmpz_get_mpz writes into initialised GMP integers.
        unsafe {
            let len = (fmpq_poly_length(&self.0).max(0) as usize).min(n);
            for (k, c) in num.iter_mut().enumerate().take(len) {
                fmpz_get_mpz(c.as_raw_mut().cast::<__mpz_struct>(), self.0.coeffs.add(k));
            }
            fmpz_get_mpz(den.as_raw_mut().cast::<__mpz_struct>(), self.0.den.as_ptr());
        }
        (num, den)
    }
}

impl Drop for FmpqPoly {
    fn drop(&mut self) {
        // SAFETY: initialised in `new`, cleared once.
        unsafe { fmpq_poly_clear(&mut self.0) }
    }
}

/// An owned `fmpz`, cleared on drop.
struct Fmpz(fmpz);

impl Fmpz {
    fn from(i: &Integer) -> Fmpz {
        let mut z = Fmpz(0); // the fmpz 0 is a valid initialised value (fmpz_init sets 0)
                             // SAFETY: z is an initialised fmpz, i an initialised GMP integer of mpz_t layout.
        unsafe { fmpz_set_mpz(&mut z.0, i.as_raw().cast::<__mpz_struct>()) };
        z
    }
}

impl Drop for Fmpz {
    fn drop(&mut self) {
        // SAFETY: initialised in `from`, cleared once.
        unsafe { fmpz_clear(&mut self.0) }
    }
}

/// `a b` through `x^(n-1)`.
pub(crate) fn mullow(a: (&[Integer], &Integer), b: (&[Integer], &Integer), n: usize) -> Parts {
    let (fa, fb) = (FmpqPoly::from_parts(a.0, a.1), FmpqPoly::from_parts(b.0, b.1));
    let mut r = FmpqPoly::new();
    // SAFETY: all three initialised; FLINT allows any n >= 0.
    unsafe { fmpq_poly_mullow(&mut r.0, &fa.0, &fb.0, n as i64) };
    r.to_parts(n)
}

/// One of FLINT's series functions `op(res, f, n)` applied to `f` through `x^(n-1)`.
fn series_op(
    num: &[Integer],
    den: &Integer,
    n: usize,
    op: unsafe extern "C" fn(*mut fmpq_poly_struct, *const fmpq_poly_struct, i64),
) -> Parts {
    let f = FmpqPoly::from_parts(num, den);
    let mut r = FmpqPoly::new();
    // SAFETY: both initialised; `op` is one of the functions below, whose preconditions the
    // callers of those check.
    unsafe { op(&mut r.0, &f.0, n as i64) };
    r.to_parts(n)
}

/// `1/f` through `x^(n-1)`; the caller ensures `num[0] != 0` and `n >= 1`.
pub(crate) fn inv(num: &[Integer], den: &Integer, n: usize) -> Parts {
    series_op(num, den, n, fmpq_poly_inv_series)
}

/// `log f` through `x^(n-1)`; the caller ensures `f(0) = 1` and `n >= 1`.
pub(crate) fn log(num: &[Integer], den: &Integer, n: usize) -> Parts {
    series_op(num, den, n, fmpq_poly_log_series)
}

/// `exp f` through `x^(n-1)`; the caller ensures `f(0) = 0` and `n >= 1`.
pub(crate) fn exp(num: &[Integer], den: &Integer, n: usize) -> Parts {
    series_op(num, den, n, fmpq_poly_exp_series)
}

/// `f^(p/q) = exp((p/q) log f)` through `x^(n-1)`; the caller ensures `f(0) = 1`, `q > 0`, `n >= 1`.
pub(crate) fn pow(num: &[Integer], den: &Integer, p: &Integer, q: &Integer, n: usize) -> Parts {
    let f = FmpqPoly::from_parts(num, den);
    let (zp, zq) = (Fmpz::from(p), Fmpz::from(q));
    let mut l = FmpqPoly::new();
    let mut r = FmpqPoly::new();
    // SAFETY: initialised; f(0) = 1 and q != 0 checked by the caller; FLINT allows aliasing of
    // the input and the output of its scalar operations.
    unsafe {
        fmpq_poly_log_series(&mut l.0, &f.0, n as i64);
        let lp: *mut fmpq_poly_struct = &mut l.0;
        fmpq_poly_scalar_mul_fmpz(lp, lp, &zp.0);
        fmpq_poly_scalar_div_fmpz(lp, lp, &zq.0);
        fmpq_poly_exp_series(&mut r.0, &l.0, n as i64);
    }
    r.to_parts(n)
}

/// The compositional inverse with `num.len()` coefficients; the caller ensures `f(0) = 0` and,
/// from two coefficients on, `f'(0) != 0` (FLINT aborts the process otherwise).
pub(crate) fn revert(num: &[Integer], den: &Integer) -> Parts {
    let n = num.len();
    if n < 2 {
        return (vec![Integer::new(); n], Integer::from(1)); // O(x^n): no coefficient to invert
    }
    series_op(num, den, n, fmpq_poly_revert_series)
}
