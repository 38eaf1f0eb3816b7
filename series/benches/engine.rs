//! Criterion benchmarks of the exact engine: the peer job (sinc power with a symbolic exponent and
//! the reversion of x times it), z cot z, the weight-series building blocks, and the
//! fraction-field job of `examples/frac_series.rs` (inverse and log of a series over Q(a, b) whose
//! denominators share factors; its peer side is `bench/peers/series`).
//!
//! Run: `cargo bench -p exact-series`

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use exact_series::{Frac, Poly, Ring, Series, Q};

fn alpha() -> Poly {
    Poly::var("theta").unwrap().add(&Poly::from_q(&Q::new(1.into(), 2.into())))
}

fn sinc_power(c: &mut Criterion) {
    let mut g = c.benchmark_group("sinc_power_symbolic");
    g.sample_size(10);
    for n in [30usize, 60] {
        g.bench_with_input(BenchmarkId::new("series", n), &n, |b, &n| {
            b.iter(|| Series::<Poly>::sinc_series(black_box(n)).pow(&alpha()).unwrap())
        });
        let f = Series::<Poly>::sinc_series(n).pow(&alpha()).unwrap().shift(1).truncate(n);
        g.bench_with_input(BenchmarkId::new("reversion", n), &f, |b, f| b.iter(|| f.revert().unwrap()));
    }
    g.finish();
}

fn rational(c: &mut Criterion) {
    let mut g = c.benchmark_group("rational");
    g.sample_size(10);
    for n in [30usize, 100] {
        g.bench_with_input(BenchmarkId::new("zcot", n), &n, |b, &n| b.iter(|| Series::<Q>::zcot_series(black_box(n))));
        let x = Series::<Q>::var(n);
        g.bench_with_input(BenchmarkId::new("tan_revert", n), &x, |b, x| b.iter(|| x.tan().unwrap().revert().unwrap()));
        // The peer job at theta = 1/3 over Q (the common-denominator GMP route, src/dense_q.rs).
        let a = Q::new(5.into(), 6.into());
        g.bench_with_input(BenchmarkId::new("sinc_power_q", n), &n, |b, &n| {
            b.iter(|| Series::<Q>::sinc_series(black_box(n)).pow(&a).unwrap())
        });
        let f = Series::<Q>::sinc_series(n).pow(&a).unwrap().shift(1).truncate(n);
        g.bench_with_input(BenchmarkId::new("sinc_power_q_reversion", n), &f, |b, f| b.iter(|| f.revert().unwrap()));
    }
    g.finish();
}

/// f = 1 + x/(a + b) + a x^2/(a - b) + (1 + a b) x^3/(a^2 + b) + O(x^N) (the frac job).
fn frac_input(n: usize) -> Series<Frac> {
    let a = Poly::var("a").unwrap();
    let b = Poly::var("b").unwrap();
    let coeffs = vec![
        Frac::one(),
        Frac::new(Poly::one(), a.add(&b)).unwrap(),
        Frac::new(a.clone(), a.sub(&b)).unwrap(),
        Frac::new(Poly::one().add(&a.mul(&b)), a.mul(&a).add(&b)).unwrap(),
    ];
    Series::new(coeffs, n)
}

fn fraction_field(c: &mut Criterion) {
    let mut g = c.benchmark_group("frac_job");
    g.sample_size(10);
    for n in [8usize, 12] {
        let f = frac_input(n);
        g.bench_with_input(BenchmarkId::new("inv", n), &n, |b, _| b.iter(|| black_box(&f).inv().unwrap()));
        g.bench_with_input(BenchmarkId::new("log", n), &n, |b, _| b.iter(|| black_box(&f).log().unwrap()));
    }
    g.finish();
}

criterion_group!(benches, sinc_power, rational, fraction_field);
criterion_main!(benches);
