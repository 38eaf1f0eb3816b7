//! Double-double arithmetic (hi + lo, about 106 bits in `f64` operations) for the Newton passes
//! of the MPFR Gauss–Jacobi rules ([`super`]'s module doc): the first rung of the precision
//! ladder, and the whole rule at up to 64 bits ([`dd_rule`]), four nodes side by side.

use super::{checked_rule, Eval, GaussJacobiRule, QuadratureError};
use rug::Float;

/// Nodes whose Newton passes in double-double run side by side ([`EvalDd::run_lanes`]).
pub(super) const LANES: usize = 4;

/// A double-double number hi + lo (|lo| <= ulp(hi)/2): about 106 bits with `f64` operations, for
/// the first Newton pass of `newton_rule` (Dekker's products, no fused multiply-add needed).
#[derive(Debug, Clone, Copy)]
pub(super) struct Dd(pub(super) f64, pub(super) f64);

impl Dd {
    pub(super) fn of(x: &Float) -> Dd {
        let hi = x.to_f64();
        let lo = Float::with_val(x.prec(), x - hi).to_f64();
        Dd(hi, lo)
    }
    fn two_sum(a: f64, b: f64) -> Dd {
        let s = a + b;
        let bb = s - a;
        Dd(s, (a - (s - bb)) + (b - bb))
    }
    fn split(a: f64) -> (f64, f64) {
        let t = 134217729.0 * a; // 2^27 + 1
        let hi = t - (t - a);
        (hi, a - hi)
    }
    fn two_prod(a: f64, b: f64) -> Dd {
        let p = a * b;
        let (ah, al) = Dd::split(a);
        let (bh, bl) = Dd::split(b);
        Dd(p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
    }
    fn add(self, o: Dd) -> Dd {
        let s = Dd::two_sum(self.0, o.0);
        let t = Dd::two_sum(self.1, o.1);
        let s = Dd::two_sum(s.0, s.1 + t.0);
        Dd::two_sum(s.0, s.1 + t.1)
    }
    fn neg(self) -> Dd {
        Dd(-self.0, -self.1)
    }
    pub(super) fn sub(self, o: Dd) -> Dd {
        self.add(o.neg())
    }
    /// The exact product of two `f64` as a double-double by a fused multiply-add (the same value
    /// as [`Dd::two_prod`], which is exact too; only with the `fma` target feature enabled).
    #[inline(always)]
    fn two_prod_fma(a: f64, b: f64) -> Dd {
        let p = a * b;
        Dd(p, a.mul_add(b, -p))
    }
    /// [`Dd::mul`], with the exact product by [`Dd::two_prod_fma`] when `FMA` (the same bits).
    #[inline(always)]
    fn mul_g<const FMA: bool>(self, o: Dd) -> Dd {
        let p = if FMA { Dd::two_prod_fma(self.0, o.0) } else { Dd::two_prod(self.0, o.0) };
        Dd::two_sum(p.0, p.1 + (self.0 * o.1 + self.1 * o.0))
    }
    /// [`Dd::div`] with [`Dd::mul_g`].
    #[inline(always)]
    fn div_g<const FMA: bool>(self, o: Dd) -> Dd {
        let q1 = self.0 / o.0;
        let r = self.sub(o.mul_g::<FMA>(Dd(q1, 0.0)));
        let q2 = r.0 / o.0;
        let r = r.sub(o.mul_g::<FMA>(Dd(q2, 0.0)));
        let q3 = r.0 / o.0;
        Dd::two_sum(q1, q2).add(Dd(q3, 0.0))
    }
    /// The product with Dekker's exact product.
    pub(super) fn mul(self, o: Dd) -> Dd {
        self.mul_g::<false>(o)
    }
    /// The quotient with Dekker's exact product.
    pub(super) fn div(self, o: Dd) -> Dd {
        self.div_g::<false>(o)
    }
}

/// [`Eval`] in double-double: the first Newton pass (module doc), where ~100 bits suffice.
pub(super) struct EvalDd {
    a: Vec<Dd>,
    b: Vec<Dd>,
    ib: Vec<Dd>,
    shift: Dd,
    c2: Dd,
}

impl EvalDd {
    pub(super) fn new(e: &Eval) -> Self {
        let v = |x: &[Float]| x.iter().map(Dd::of).collect();
        EvalDd { a: v(&e.a), b: v(&e.b), ib: v(&e.ib), shift: Dd::of(&e.shift), c2: Dd::of(&e.c2) }
    }

    /// p_n(x), p_n'(x), p_{n-1}(x) as `Eval::run` computes them, in double-double, at [`LANES`]
    /// points at once (independent chains that the core overlaps; each lane's operations and
    /// bits are those of one point alone), with fused multiply-adds where the processor has them
    /// (the same bits: the exact products agree).
    pub(super) fn run_lanes(&self, x: &[Dd; LANES]) -> [(Dd, Dd, Dd); LANES] {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("fma") {
            // SAFETY: the processor has the `fma` feature (checked above).
            return unsafe { self.run_lanes_fma(x) };
        }
        self.run_lanes_with::<false>(x)
    }

    /// [`EvalDd::run_lanes_with`] compiled with fused multiply-adds.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "fma")]
    unsafe fn run_lanes_fma(&self, x: &[Dd; LANES]) -> [(Dd, Dd, Dd); LANES] {
        self.run_lanes_with::<true>(x)
    }

    #[inline(always)]
    pub(super) fn run_lanes_with<const FMA: bool>(&self, x: &[Dd; LANES]) -> [(Dd, Dd, Dd); LANES] {
        self.recurrence::<LANES, FMA>(x).map(|(p, num, den, pm)| (p, num.div_g::<FMA>(den), pm))
    }

    /// The three-term recurrence of `Eval::run` at K points side by side (each lane with the
    /// operations of one point alone): per point p_n, the numerator and the denominator of
    /// p_n' = num/den, and p_{n-1}.
    #[inline(always)]
    fn recurrence<const K: usize, const FMA: bool>(&self, x: &[Dd; K]) -> [(Dd, Dd, Dd, Dd); K] {
        let n = self.a.len();
        let (mut pm, mut p) = ([Dd(0.0, 0.0); K], [Dd(1.0, 0.0); K]);
        for k in 0..n {
            let (a, b, ib) = (self.a[k], self.b[k], self.ib[k + 1]);
            for l in 0..K {
                let t = x[l].sub(a).mul_g::<FMA>(p[l]).sub(b.mul_g::<FMA>(pm[l])).mul_g::<FMA>(ib);
                pm[l] = p[l];
                p[l] = t;
            }
        }
        std::array::from_fn(|l| {
            let c1 = self.shift.sub(x[l]).mul_g::<FMA>(Dd(n as f64, 0.0));
            let num = c1.mul_g::<FMA>(p[l]).add(self.c2.mul_g::<FMA>(pm[l]));
            let den = Dd(1.0, 0.0).sub(x[l]).mul_g::<FMA>(x[l].add(Dd(1.0, 0.0)));
            (p[l], num, den, pm[l])
        })
    }

    /// The Newton step p_n(x)/p_n'(x) = p_n den/num, as `Eval::run` computes it.
    pub(super) fn step(&self, x: Dd) -> Dd {
        let [(p, num, den, _)] = self.recurrence::<1, false>(&[x]);
        p.mul(den).div(num)
    }
}

/// The rule of `newton_rule` for `prec` <= `DD_ONLY_PREC`, every Newton pass in double-double
/// (about 100 correct bits, `wp` ~ 100-108 here) instead of the MPFR passes at `wp` bits: from the f64
/// start `start`, passes until the correction is below 2^-(prec + 28) (two, as the ladder at `wp`:
/// one to ~100 bits, one whose negligible correction yields p_n' and p_{n-1} for the weight), the
/// weight mu0 / (b_n p_n' p_{n-1}) as in the MPFR route; then each node and weight rounded to
/// `prec` bits. Both routes carry more than 30 bits beyond `prec`, so both round to the same
/// `prec`-bit numbers except when a value lies within about 2^-95 of a rounding boundary (test
/// `double_double_route_rounds_as_the_mpfr_route`: bit for bit, the locating stage's rules of
/// `sliding::reduction_mpfr` among them). A Newton pass in double-double costs about a quarter
/// of one in MPFR at 104 bits: the 192-node rule of the sinusoid's bracket refinement took 8.7 ms
/// of a 30 ms cold solve (`GJ` timing of each built rule, a temporary trace).
pub(super) fn dd_rule(
    alpha: &Float,
    beta: &Float,
    (a, b): (&[Float], &[Float]),
    start: &[f64],
    mu0: &Float,
    prec: u32,
    wp: u32,
) -> Result<GaussJacobiRule, QuadratureError> {
    let n = start.len();
    let dd = EvalDd::new(&Eval::new(alpha, beta, a, b, wp));
    let (mu0, bn) = (Dd::of(mu0), Dd::of(&b[n]));
    let tol = 2f64.powi(-(prec as i32) - 28);
    // hi + lo rounded once to `prec` bits (hi + lo is exact at 2 x 64 + 64 bits for |lo| <= ulp(hi)).
    let round = |v: Dd| {
        let mut f = Float::with_val(192, v.0);
        f += v.1;
        Float::with_val(prec, &f)
    };
    let mut nodes = Vec::with_capacity(n);
    let mut weights = Vec::with_capacity(n);
    // Newton in chunks of LANES nodes (the last chunk padded with its last node); a converged
    // node keeps its x and its (p_n', p_{n-1}).
    let mut found: Vec<(Dd, Dd, Dd)> = Vec::with_capacity(n);
    for chunk in start.chunks(LANES) {
        let at = |l: usize| chunk[l.min(chunk.len() - 1)];
        let mut x: [Dd; LANES] = std::array::from_fn(|l| Dd(at(l), 0.0));
        let mut last: [Option<(Dd, Dd)>; LANES] = [None; LANES];
        for pass in 0..8 {
            let values = dd.run_lanes(&x);
            for l in 0..LANES {
                if last[l].is_some() {
                    continue;
                }
                let (p, dp, pm) = values[l];
                let dx = p.div(dp);
                if !(dx.0.is_finite() && dx.1.is_finite()) || dp.0 == 0.0 {
                    let i = found.len() + l.min(chunk.len() - 1);
                    return Err(QuadratureError::NoConvergence { n, why: format!("zero derivative at node {i}") });
                }
                x[l] = x[l].sub(dx);
                if pass >= 1 && dx.0.abs() <= tol {
                    last[l] = Some((dp, pm));
                }
            }
            if last.iter().all(Option::is_some) {
                break;
            }
        }
        let base = found.len();
        for l in 0..chunk.len() {
            let Some((dp, pm)) = last[l] else {
                let i = base + l;
                return Err(QuadratureError::NoConvergence { n, why: format!("Newton did not converge at node {i}") });
            };
            found.push((x[l], dp, pm));
        }
    }
    for (i, (&x0, &(x, dp, pm))) in start.iter().zip(&found).enumerate() {
        if (x.0 - x0).abs() > 1e-6 + 1e-3 * (1.0 - x0 * x0) {
            return Err(QuadratureError::NoConvergence {
                n,
                why: format!("Newton drifted from its start at node {i}"),
            });
        }
        let sum = dp.mul(pm).mul(bn);
        if !(sum.0 > 0.0) {
            return Err(QuadratureError::NoConvergence { n, why: format!("non-positive Christoffel sum at node {i}") });
        }
        nodes.push(round(x));
        weights.push(round(mu0.div(sum)));
    }
    checked_rule(alpha, beta, nodes, weights, prec)
}
