//! The derived objects of THEORY.md section 5 against independent numerics: the truncated exact
//! series is evaluated in MPFR and compared with the function itself (computed directly in MPFR);
//! the remainder after the lambda^N term must scale like lambda^(N+2) (even series).

use exact_series::{Poly, Ring, Symbol, Q};
use periodic_contact::asymptotics::{kernel::kernel_series, weight::weight_series};
use periodic_contact::numerics::{evaluate, exact};
use rug::ops::Pow;
use rug::Float;

const PREC: u32 = 256;

/// Observed order of the remainder: log2(err(h) / err(h/2)).
fn observed_order(err: impl Fn(&Float) -> Float, h: f64) -> f64 {
    let h1 = Float::with_val(PREC, h);
    let h2 = Float::with_val(PREC, h / 2.0);
    let (e1, e2) = (err(&h1), err(&h2));
    Float::with_val(PREC, &e1 / &e2).log2().to_f64()
}

fn sinc(z: &Float) -> Float {
    Float::with_val(PREC, z.sin_ref()) / z
}

#[test]
fn weight_series_remainder_scales_like_next_even_power() {
    let full = weight_series(12).unwrap();
    let theta = Symbol::new("theta").unwrap();
    let xh = Symbol::new("xh").unwrap();
    for (t, x) in [((3, 10), (1, 3)), ((-2, 5), (-7, 10)), ((0, 1), (1, 2))] {
        let tq = Q::new(t.0.into(), t.1.into());
        let xq = Q::new(x.0.into(), x.1.into());
        let (tf, xf) = (exact::to_float(&tq, PREC), exact::to_float(&xq, PREC));
        let bindings = [(theta, tf.clone()), (xh, xf.clone())];
        let direct = |lam: &Float| {
            let one = Float::with_val(PREC, 1);
            let half = Float::with_val(PREC, 0.5);
            let a = Float::with_val(PREC, lam * Float::with_val(PREC, &one + &xf));
            let b = Float::with_val(PREC, lam * Float::with_val(PREC, &one - &xf));
            let pa = Float::with_val(PREC, &half + &tf);
            let pb = Float::with_val(PREC, &half - &tf);
            Float::with_val(PREC, sinc(&a).pow(&pa)) * Float::with_val(PREC, sinc(&b).pow(&pb))
        };
        for n in (0..=10).step_by(2) {
            let trunc = full.truncate(n + 1);
            let err = |lam: &Float| {
                let s = evaluate::series_mpfr(&trunc, lam, &bindings, PREC).unwrap();
                Float::with_val(PREC, s - direct(lam)).abs()
            };
            let p = observed_order(err, 0.02);
            assert!((p - (n as f64 + 2.0)).abs() < 0.1, "theta={tq} xh={xq} N={n}: order {p}");
        }
    }
}

#[test]
fn kernel_series_remainder_scales_like_next_even_power() {
    let z = kernel_series(30).map(Poly::from_q);
    for n in (0..=28).step_by(4) {
        let trunc = z.truncate(n + 1);
        let err = |x: &Float| {
            let s = evaluate::series_mpfr(&trunc, x, &[], PREC).unwrap();
            let direct = Float::with_val(PREC, x * Float::with_val(PREC, x.cot_ref()));
            Float::with_val(PREC, s - direct).abs()
        };
        let p = observed_order(err, 0.05);
        assert!((p - (n as f64 + 2.0)).abs() < 0.1, "N={n}: order {p}");
    }
}
