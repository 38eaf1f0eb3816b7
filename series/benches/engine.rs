//! Criterion benchmarks of the exact engine: the peer job (sinc power with a symbolic exponent and
//! the reversion of x times it), z cot z, and the weight-series building blocks.
//!
//! Run: `cargo bench -p exact-series`

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use exact_series::{Poly, Ring, Series, Q};

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

criterion_group!(benches, sinc_power, rational);
criterion_main!(benches);
