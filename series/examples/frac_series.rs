//! A fraction-field job (issue 14; its peers, python-flint's fmpz_mpoly fractions and SymPy's
//! field, in `bench/peers/series`): coefficients in Q(a, b).
//! f = 1 + x/(a + b) + a x^2/(a - b) + (1 + a b) x^3/(a^2 + b) + O(x^N); its inverse 1/f and its
//! logarithm log f through x^(N-1), each reduced to lowest terms. Prints one JSON line with the
//! best-of-`repeat` times and the text of the last coefficient of each (for the peer's check).
//!
//! `cargo run --release -p exact-series --example frac_series -- N [REPEAT]`
use exact_series::{Frac, Poly, Ring, Series};
use std::time::Instant;

fn main() {
    let mut args = std::env::args().skip(1);
    let n: usize = args.next().and_then(|s| s.parse().ok()).expect("usage: frac_series N [REPEAT]");
    let repeat: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(1);
    let a = Poly::var("a").expect("symbol");
    let b = Poly::var("b").expect("symbol");
    let coeffs = vec![
        Frac::one(),
        Frac::new(Poly::one(), a.add(&b)).expect("non-zero"),
        Frac::new(a.clone(), a.sub(&b)).expect("non-zero"),
        Frac::new(Poly::one().add(&a.mul(&b)), a.mul(&a).add(&b)).expect("non-zero"),
    ];
    let f = Series::new(coeffs, n);
    let best = |g: &dyn Fn() -> Series<Frac>| {
        let mut t = f64::INFINITY;
        let mut out = None;
        for _ in 0..repeat.max(1) {
            let t0 = Instant::now();
            let r = g();
            t = t.min(t0.elapsed().as_secs_f64());
            out = Some(r);
        }
        (t, out.expect("one run"))
    };
    let (t_inv, inv) = best(&|| f.inv().expect("f(0) = 1"));
    let (t_log, log) = best(&|| f.log().expect("f(0) = 1"));
    println!(
        "{{\"N\": {n}, \"inv_s\": {t_inv}, \"log_s\": {t_log}, \"inv_last\": \"{}\", \"log_last\": \"{}\"}}",
        inv.coeffs()[n - 1].text(),
        log.coeffs()[n - 1].text()
    );
}
