//! p_n, p_n' and p_(n-1) of the orthonormal Jacobi recurrence at one point in MPFR, the
//! derivative by the structure relation (the Newton step of the Gauss-Jacobi rules; [`super`]'s
//! module doc). Tested by `structure_relation_derivative` in the parent's tests.

use rug::{Assign, Float};

/// Scratch for the recurrence at one precision, with the constants of the structure relation.
pub(super) struct Eval {
    pub(super) a: Vec<Float>,
    pub(super) ib: Vec<Float>,
    pub(super) b: Vec<Float>,
    /// (alpha - beta)/(2n + alpha + beta).
    pub(super) shift: Float,
    /// (2n + alpha + beta + 1) b_n.
    pub(super) c2: Float,
}

impl Eval {
    pub(super) fn new(alpha: &Float, beta: &Float, a: &[Float], b: &[Float], prec: u32) -> Self {
        let n = a.len();
        let s = Float::with_val(prec, alpha + beta) + (2 * n) as u32;
        let shift = Float::with_val(prec, alpha - beta) / &s;
        let c2 = Float::with_val(prec, &s + 1u32) * &b[n];
        Eval {
            a: a.iter().map(|x| Float::with_val(prec, x)).collect(),
            b: b.iter().map(|x| Float::with_val(prec, x)).collect(),
            ib: b
                .iter()
                .map(|x| {
                    if x.is_zero() {
                        Float::with_val(prec, 0)
                    } else {
                        Float::with_val(prec, 1u32) / Float::with_val(prec, x)
                    }
                })
                .collect(),
            shift,
            c2,
        }
    }

    /// p_n(x), p_n'(x), p_{n-1}(x) (p_0 = 1; n = the length of the recurrence) for x in (-1, 1).
    ///
    /// The values by the recurrence; the derivative by the structure relation of the module doc,
    /// $(1-x^2) p_n' = c_1(x) p_n + c_2 p_{n-1}$: its leading terms give $c_1 = n (\text{shift} - x)$
    /// (with shift = (alpha - beta)/(2n + alpha + beta), DLMF 18.9.16 for the classical normalisation),
    /// and $c_2 = \langle (1-x^2) p_n', p_{n-1} \rangle - \langle c_1 p_n, p_{n-1} \rangle$ in the
    /// weight's inner product: by parts the first is $(n + \alpha + \beta + 1) b_n$, the second
    /// $-n b_n$ (from $\langle x p_n, p_{n-1} \rangle = b_n$ and $k_{n-1}/k_n = b_n$), so
    /// $c_2 = (2n + \alpha + \beta + 1) b_n$. The test `structure_relation_derivative` compares it
    /// with the derivative of the recurrence.
    pub(super) fn run(&self, x: &Float, prec: u32) -> (Float, Float, Float) {
        let n = self.a.len();
        let mut pm = Float::with_val(prec, 0);
        let mut p = Float::with_val(prec, 1);
        let mut xa = Float::with_val(prec, 0);
        let mut t = Float::with_val(prec, 0);
        for k in 0..n {
            xa.assign(x - &self.a[k]);
            t.assign(&xa * &p - &self.b[k] * &pm);
            t *= &self.ib[k + 1];
            std::mem::swap(&mut pm, &mut p);
            std::mem::swap(&mut p, &mut t);
        }
        let c1 = Float::with_val(prec, &self.shift - x) * n as u32;
        let num = Float::with_val(prec, &c1 * &p) + Float::with_val(prec, &self.c2 * &pm);
        let one_minus = Float::with_val(prec, 1u32 - x);
        let one_plus = Float::with_val(prec, x + 1u32);
        let dp = num / Float::with_val(prec, one_minus * one_plus);
        (p, dp, pm)
    }
}
