//! Double-double arithmetic (hi + lo, about 106 bits in `f64` operations) for the Newton passes
//! of the MPFR Gauss–Jacobi rules ([`super`]'s module doc): the first rung of the precision
//! ladder, and the whole rule at up to 64 bits (`dd_rule` of [`super`]), four nodes side by side.

use super::recurrence_eval::Eval;
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
