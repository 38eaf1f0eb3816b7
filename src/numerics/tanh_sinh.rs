//! Tanh-sinh (double-exponential) quadrature on (0, 1), Takahasi and Mori (1974).
//!
//! s(t) = 1/(1 + e^{-pi sinh t}), ds/dt = pi cosh(t) s (1 - s); the nodes keep both s and its
//! complement 1 - s = 1/(1 + e^{pi sinh t}) to full relative precision, so endpoint factors such as
//! (1 - s)^{-1/2 - i eps} or y^{-2 i eps} are evaluated without cancellation. For an integrand
//! analytic in a strip of half-width d (in t) the error is O(exp(-2 pi d/h)); algebraic and
//! log-oscillatory endpoint singularities are absorbed by the double-exponential decay.
//! The step is heuristic (mpmath `TanhSinh` style): h = pi^2 gamma/(bits ln 2) with gamma = 1/2,
//! refined by `refine` > 1; the verification run uses a finer step, so a too-coarse step shows as
//! fewer verified digits, not as wrong digits.

use rug::ops::NegAssign;
use rug::Float;

/// Nodes of the rule in MPFR.
#[derive(Debug, Clone)]
pub struct TanhSinh {
    /// Nodes s_j in (0, 1).
    pub s: Vec<Float>,
    /// Complements 1 - s_j, accurate near s = 1.
    pub c: Vec<Float>,
    /// Weights h ds/dt.
    pub w: Vec<Float>,
    /// The arguments of [`TanhSinh::new`] that fix every node: (bits, refine's bits, prec).
    spec: (u32, u64, u32),
}

/// Step and half-length (in t) for `bits` of accuracy and a refinement factor.
fn step(bits: u32, refine: f64) -> (f64, f64) {
    let b = bits.max(20) as f64;
    let h = std::f64::consts::PI.powi(2) * 0.5 / (b * std::f64::consts::LN_2) / refine.max(0.25);
    // Truncate where sqrt(s (1 - s)) < 2^-(bits + 10), i.e. pi sinh T = 2 (bits + 10) ln 2: the
    // integrands have at worst inverse-square-root endpoint factors.
    let t_max = ((2.0 * (b + 10.0) * std::f64::consts::LN_2) / std::f64::consts::PI).asinh();
    (h, t_max)
}

impl TanhSinh {
    /// Rule accurate to about `bits` bits for well-behaved integrands, nodes in `prec`-bit MPFR.
    pub fn new(bits: u32, refine: f64, prec: u32) -> Self {
        let (h, t_max) = step(bits, refine);
        let n = (t_max / h).ceil() as i64;
        let hf = Float::with_val(prec, h);
        let pi = Float::with_val(prec, rug::float::Constant::Pi);
        let (mut s, mut c, mut w) = (Vec::new(), Vec::new(), Vec::new());
        for j in -n..=n {
            let t = Float::with_val(prec, &hf * j);
            let sh = Float::with_val(prec, t.sinh_ref()) * &pi;
            let ch = Float::with_val(prec, t.cosh_ref());
            let mut msh = sh.clone();
            msh.neg_assign();
            let sj = Float::with_val(prec, msh.exp() + 1u32).recip();
            let cj = Float::with_val(prec, sh.exp() + 1u32).recip();
            let wj = Float::with_val(prec, &sj * &cj) * &ch * &pi * &hf;
            s.push(sj);
            c.push(cj);
            w.push(wj);
        }
        TanhSinh { s, c, w, spec: (bits, refine.to_bits(), prec) }
    }

    /// (bits, refine as its bits, prec) as given to [`TanhSinh::new`]: equal specs, equal rules
    /// (a key for caches of values at the nodes).
    pub fn spec(&self) -> (u32, u64, u32) {
        self.spec
    }

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.s.len()
    }

    /// Whether the rule is empty (never, for a constructed rule).
    pub fn is_empty(&self) -> bool {
        self.s.is_empty()
    }
}

/// The same rule in `f64`: (s, 1 - s, weight) triples.
pub(crate) fn tanh_sinh_f64(bits: u32, refine: f64) -> Vec<(f64, f64, f64)> {
    tanh_sinh_f64_bounded(bits, refine).into_iter().map(|(s, c, w, _)| (s, c, w)).collect()
}

/// [`tanh_sinh_f64`] with a bound on the relative error of each of s, 1 - s and the weight
/// against the exact rule (the nodes of [`TanhSinh::new`] in exact arithmetic; h and t = h j
/// are exact there). With u = 2^-53 and every libm call (sinh, cosh, exp) within 2 ulp = 4 u of
/// its result: t = h j carries u, so sinh t carries (1 + |t|) u + 4 u (|t coth t| <= 1 + |t|)
/// and sh = pi sinh t (|t| + 7) u; exp(-+ sh) then |sh| (|t| + 7) u + 4 u, and s, 1 - s two
/// roundings more; the weight adds cosh t ((|t| + 4) u), pi and four products to both. The sum of
/// these first-order terms, with 1 % for the second order.
pub(crate) fn tanh_sinh_f64_bounded(bits: u32, refine: f64) -> Vec<(f64, f64, f64, f64)> {
    const U: f64 = f64::EPSILON / 2.0;
    let (h, t_max) = step(bits, refine);
    let n = (t_max / h).ceil() as i64;
    let pi = std::f64::consts::PI;
    (-n..=n)
        .map(|j| {
            let t = h * j as f64;
            let sh = pi * t.sinh();
            let s = 1.0 / (1.0 + (-sh).exp());
            let c = 1.0 / (1.0 + sh.exp());
            let e_s = sh.abs() * (t.abs() + 7.0) * U + 6.0 * U;
            let e_w = 2.0 * e_s + (t.abs() + 4.0) * U + 5.0 * U;
            (s, c, h * pi * t.cosh() * s * c, 1.01 * e_w)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tanh_sinh_endpoint_singularity() {
        // int_0^1 (1-s)^{-1/2} ds = 2; int_0^1 s^{-1/2} ln(1/(1-s))... keep it simple: also
        // int_0^1 s^2 ds = 1/3.
        let prec = 200;
        let r = TanhSinh::new(160, 1.0, prec);
        let mut a = Float::with_val(prec, 0);
        let mut b = Float::with_val(prec, 0);
        for j in 0..r.len() {
            a += Float::with_val(prec, &r.w[j] / r.c[j].clone().sqrt());
            b += Float::with_val(prec, &r.w[j] * &r.s[j]) * &r.s[j];
        }
        assert!(Float::with_val(prec, a - 2u32).abs().to_f64() < 1e-45);
        let third = Float::with_val(prec, 1u32) / 3u32;
        assert!(Float::with_val(prec, b - third).abs().to_f64() < 1e-45);
        let rf = tanh_sinh_f64(53, 1.0);
        let v: f64 = rf.iter().map(|(_, c, w)| w / c.sqrt()).sum();
        assert!((v - 2.0).abs() < 1e-14);
    }
}
