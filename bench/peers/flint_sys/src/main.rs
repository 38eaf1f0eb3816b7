//! The candidate of issue 14, measured in one process: FLINT 3.5 (through flint-sys 0.9) against
//! exact-series on the peer jobs of `bench/peers/series`, best of several runs each:
//! - over Q: f = (sin x / x)^(5/6) = exp(5/6 log(sin x / x)) to N coefficients (FLINT's
//!   `fmpq_poly_log_series`, `fmpq_poly_exp_series`; ours `Series::<Q>::pow`) and the reversion
//!   of x f(x) (`fmpq_poly_revert_series`; ours `revert`), every coefficient compared;
//! - over Q(a, b) (argument `frac`): 1/f and log f of f = 1 + x/(a+b) + a x^2/(a-b) +
//!   (1+ab) x^3/(a^2+b) by the same recurrences, FLINT's `fmpz_mpoly_q` (canonical after every
//!   operation) against our `Frac`, the last coefficients compared.
//!
//! Prints FLINT's time, ours, and the ratio FLINT / ours (> 1: we are faster).
//! Run: `bench/peers/flint-sys` (builds FLINT from source first).
use exact_series::{Series, Q};
use flint_sys::flint::fmpq;
use flint_sys::fmpq::{fmpq_clear, fmpq_equal, fmpq_init, fmpq_set_str};
use flint_sys::fmpq_poly::*;
use flint_sys::fmpq_types::fmpq_poly_struct;
use std::ffi::CString;
use std::mem::MaybeUninit;
use std::time::Instant;
mod frac;

fn best(reps: usize, mut f: impl FnMut()) -> f64 {
    let mut b = f64::INFINITY;
    for _ in 0..reps {
        let t = Instant::now();
        f();
        b = b.min(t.elapsed().as_secs_f64());
    }
    b
}

struct P(fmpq_poly_struct);
impl P {
    fn new() -> Self {
        let mut p = MaybeUninit::uninit();
        // SAFETY: fmpq_poly_init initialises the struct it is given.
        unsafe {
            fmpq_poly_init(p.as_mut_ptr());
            P(p.assume_init())
        }
    }
}
impl Drop for P {
    fn drop(&mut self) {
        // SAFETY: initialised in `new`, cleared once.
        unsafe { fmpq_poly_clear(&mut self.0) }
    }
}

/// Every coefficient of FLINT's `r` equals ours (through x^(n-1)).
fn same(r: &P, ours: &Series<Q>, n: usize) -> bool {
    (0..n).all(|k| {
        let text = ours.coeff(k).map(|c| c.to_string()).unwrap_or_else(|| "0".into());
        let c = CString::new(text).expect("no NUL");
        // SAFETY: fmpq values initialised and cleared here; strings NUL-terminated.
        unsafe {
            let mut x = MaybeUninit::<fmpq>::uninit();
            let mut y = MaybeUninit::<fmpq>::uninit();
            fmpq_init(x.as_mut_ptr());
            fmpq_init(y.as_mut_ptr());
            let ok = fmpq_set_str(x.as_mut_ptr(), c.as_ptr(), 10) == 0;
            fmpq_poly_get_coeff_fmpq(y.as_mut_ptr(), &r.0, k as i64);
            let eq = ok && fmpq_equal(x.as_ptr(), y.as_ptr()) != 0;
            fmpq_clear(x.as_mut_ptr());
            fmpq_clear(y.as_mut_ptr());
            eq
        }
    })
}

fn main() {
    if std::env::args().nth(1).as_deref() == Some("frac") {
        frac::run(3);
        return;
    }
    let reps = 30;
    for n in [30usize, 60, 100, 200] {
        let (mut x, mut s, mut sinc, mut lg, mut f, mut y, mut r) =
            (P::new(), P::new(), P::new(), P::new(), P::new(), P::new(), P::new());
        let m = n as i64;
        // SAFETY: all polynomials initialised by P::new; FLINT allows aliasing of input and output.
        let (tf, tfr) = unsafe {
            fmpq_poly_set_coeff_si(&mut x.0, 1, 1);
            fmpq_poly_sin_series(&mut s.0, &x.0, m + 1);
            fmpq_poly_shift_right(&mut sinc.0, &s.0, 1);
            let tf = best(reps, || {
                fmpq_poly_log_series(&mut lg.0, &sinc.0, m);
                fmpq_poly_scalar_mul_si(&mut lg.0, &lg.0, 5);
                fmpq_poly_scalar_div_si(&mut lg.0, &lg.0, 6);
                fmpq_poly_exp_series(&mut f.0, &lg.0, m);
            });
            fmpq_poly_shift_left(&mut y.0, &f.0, 1);
            (tf, best(reps, || fmpq_poly_revert_series(&mut r.0, &y.0, m)))
        };
        let alpha = Q::new(5.into(), 6.into());
        let mut g = None;
        let to = best(reps, || g = Some(Series::<Q>::sinc_series(n).pow(&alpha).expect("sinc(0) = 1")));
        let g = g.expect("one run");
        let yo = g.shift(1).truncate(n);
        let mut rev = None;
        let tor = best(reps, || rev = Some(yo.revert().expect("y'(0) = 1")));
        let rev = rev.expect("one run");
        let agree = same(&f, &g, n) && same(&r, &rev, n);
        println!(
            "Q      N = {n:3}: series FLINT {tf:.3e} s, ours {to:.3e} s, FLINT/ours {:.2}; reversion FLINT {tfr:.3e} s, ours {tor:.3e} s, FLINT/ours {:.2}; all coefficients equal: {agree}",
            tf / to,
            tfr / tor
        );
    }
}
