//! The fraction-field job of bench/peers/series in FLINT's C fmpz_mpoly_q (Q(a, b), canonical
//! form after every operation), against exact-series' Frac; the same recurrences.
use exact_series::{Frac, Poly, Ring, Series};
use flint_sys::fmpz_mpoly::fmpz_mpoly_ctx_init;
use flint_sys::fmpz_mpoly_q::*;
use flint_sys::fmpz_types::fmpz_mpoly_q_struct as Fq;
use flint_sys::mpoly_types::{fmpz_mpoly_ctx_struct as Ctx, ordering_t_ORD_LEX};
use std::ffi::CString;
use std::mem::MaybeUninit;
use std::time::Instant;

struct F<'c> {
    v: Fq,
    ctx: &'c Ctx,
}
impl<'c> F<'c> {
    fn new(ctx: &'c Ctx) -> Self {
        unsafe {
            let mut v = MaybeUninit::uninit();
            fmpz_mpoly_q_init(v.as_mut_ptr(), ctx);
            F { v: v.assume_init(), ctx }
        }
    }
    fn parse(ctx: &'c Ctx, s: &str) -> Self {
        let mut f = F::new(ctx);
        let a = CString::new("a").unwrap();
        let b = CString::new("b").unwrap();
        let mut vars = [a.as_ptr(), b.as_ptr()];
        let c = CString::new(s.replace(' ', "")).unwrap();
        let r = unsafe {
            fmpz_mpoly_q_set_str_pretty(&mut f.v, c.as_ptr(), vars.as_mut_ptr(), ctx as *const Ctx as *mut Ctx)
        };
        assert_eq!(r, 0, "FLINT parses {s}");
        f
    }
}
impl Drop for F<'_> {
    fn drop(&mut self) {
        unsafe { fmpz_mpoly_q_clear(&mut self.v, self.ctx) }
    }
}

fn flint_job<'c>(ctx: &'c Ctx, f: &[F<'c>], n: usize) -> (Vec<F<'c>>, Vec<F<'c>>, f64, f64) {
    unsafe {
        let inverse = || {
            let mut b = vec![F::parse(ctx, "1")];
            let mut t = F::new(ctx);
            for m in 1..n {
                let mut acc = F::new(ctx);
                for k in 1..=m.min(f.len() - 1) {
                    fmpz_mpoly_q_mul(&mut t.v, &f[k].v, &b[m - k].v, ctx);
                    fmpz_mpoly_q_add(&mut acc.v, &acc.v, &t.v, ctx);
                }
                fmpz_mpoly_q_neg(&mut acc.v, &acc.v, ctx);
                b.push(acc);
            }
            b
        };
        let t0 = Instant::now();
        let inv = inverse();
        let ti = t0.elapsed().as_secs_f64();
        let t0 = Instant::now();
        let inv2 = inverse();
        let mut df = Vec::new();
        for k in 1..f.len() {
            let mut d = F::new(ctx);
            fmpz_mpoly_q_mul_si(&mut d.v, &f[k].v, k as i64, ctx);
            df.push(d);
        }
        let mut out = vec![F::new(ctx)];
        let mut t = F::new(ctx);
        for m in 1..n {
            let mut acc = F::new(ctx);
            for i in 0..m.min(df.len()) {
                fmpz_mpoly_q_mul(&mut t.v, &df[i].v, &inv2[m - 1 - i].v, ctx);
                fmpz_mpoly_q_add(&mut acc.v, &acc.v, &t.v, ctx);
            }
            fmpz_mpoly_q_div_si(&mut acc.v, &acc.v, m as i64, ctx);
            out.push(acc);
        }
        let tl = t0.elapsed().as_secs_f64();
        (inv, out, ti, tl)
    }
}

pub fn run(reps: usize) {
    let mut ctx = MaybeUninit::<Ctx>::uninit();
    unsafe { fmpz_mpoly_ctx_init(ctx.as_mut_ptr(), 2, ordering_t_ORD_LEX) };
    let ctx = unsafe { ctx.assume_init() };
    let f = vec![
        F::parse(&ctx, "1"),
        F::parse(&ctx, "1/(a+b)"),
        F::parse(&ctx, "a/(a-b)"),
        F::parse(&ctx, "(1+a*b)/(a^2+b)"),
    ];
    let a = Poly::var("a").unwrap();
    let b = Poly::var("b").unwrap();
    for n in [8usize, 12, 16, 20, 32] {
        let (mut ti, mut tl) = (f64::INFINITY, f64::INFINITY);
        let mut last = None;
        for _ in 0..reps {
            let (i, l, a1, a2) = flint_job(&ctx, &f, n);
            ti = ti.min(a1);
            tl = tl.min(a2);
            last = Some((i, l));
        }
        let (fi, fl) = last.unwrap();
        let coeffs = vec![
            Frac::one(),
            Frac::new(Poly::one(), a.add(&b)).unwrap(),
            Frac::new(a.clone(), a.sub(&b)).unwrap(),
            Frac::new(Poly::one().add(&a.mul(&b)), a.mul(&a).add(&b)).unwrap(),
        ];
        let s = Series::new(coeffs, n);
        let (mut oi, mut ol) = (f64::INFINITY, f64::INFINITY);
        let mut ours = None;
        for _ in 0..reps {
            let t0 = Instant::now();
            let i = s.inv().unwrap();
            oi = oi.min(t0.elapsed().as_secs_f64());
            let t0 = Instant::now();
            let l = s.log().unwrap();
            ol = ol.min(t0.elapsed().as_secs_f64());
            ours = Some((i, l));
        }
        let (i, l) = ours.unwrap();
        let eq = |x: &F, y: &Frac| unsafe { fmpz_mpoly_q_equal(&x.v, &F::parse(&ctx, &y.text()).v, &ctx) != 0 };
        let agree = eq(&fi[n - 1], &i.coeffs()[n - 1]) && eq(&fl[n - 1], &l.coeffs()[n - 1]);
        println!("frac N = {n:2}: 1/f FLINT {ti:.3e} ours {oi:.3e} ratio {:.2}; log f FLINT {tl:.3e} ours {ol:.3e} ratio {:.2}; last coefficients equal: {agree}", ti / oi, tl / ol);
    }
}
