//! Product integration against the Abel weight (1 - u)^a, a = -1/2 - i eps, on u in [0, 1]: the
//! weights w_q with int_0^1 (1 - u)^a f(u) du = sum_q w_q f(u_q) exactly for polynomials f of
//! degree < M, at the M Chebyshev points of the first kind u_q = (1 + x_q)/2,
//! x_q = cos(pi (q + 1/2)/M).
//!
//! With the interpolant f = sum_j' c_j T_j(x), c_j = (2/M) sum_q f(u_q) T_j(x_q) (the prime halves
//! j = 0), and the modified moments G_j = int_(-1)^1 (1 - x)^a T_j(x) dx,
//! int_0^1 (1 - u)^a f du = 2^(-a-1) sum_j' c_j G_j, so
//! w_q = 2^(-a-1) (2/M) (G_0/2 + sum_(j>=1) G_j T_j(x_q)).
//! The moments by Piessens' recurrence for the Jacobi weight (1 - x)^a (beta = 0):
//! (a + j + 2) G_(j+1) = -2 a G_j - (a - j + 2) G_(j-1), from G_0 = 2^(a+1)/(a+1) and
//! G_1 = G_0 - 2^(a+2)/(a+2) (x = 1 - (1 - x)). The recurrence is run with
//! [`GUARD_BITS`] more bits; the test checks the weights against tanh-sinh quadrature of
//! (1 - u)^a T_j at j = 0, 7 and M - 1.

use rug::float::Constant;
use rug::{Complex, Float};

/// Extra bits of the moment recurrence (its solutions grow at most algebraically in j).
pub const GUARD_BITS: u32 = 64;

/// A product rule of M nodes on [0, 1] for the weight (1 - u)^(-1/2 - i eps).
#[derive(Debug, Clone)]
pub struct AbelRule {
    /// Nodes u_q in (0, 1).
    pub u: Vec<Float>,
    /// Complex weights w_q.
    pub w: Vec<Complex>,
}

impl AbelRule {
    /// The rule with `m` nodes for `eps` at `prec` bits.
    pub fn new(eps: &Float, m: usize, prec: u32) -> Self {
        let wp = prec + GUARD_BITS;
        let a = Complex::with_val(wp, (-0.5f64, Float::with_val(wp, -eps)));
        let ln2 = Float::with_val(wp, Constant::Log2);
        // 2^(a+1) = exp((a+1) ln 2).
        let pow2 = |shift: i32| Complex::with_val(wp, Complex::with_val(wp, &a + shift) * &ln2).exp();
        let a1 = Complex::with_val(wp, &a + 1u32);
        let a2 = Complex::with_val(wp, &a + 2u32);
        let mut g: Vec<Complex> = Vec::with_capacity(m);
        g.push(Complex::with_val(wp, pow2(1) / &a1));
        if m > 1 {
            let t = Complex::with_val(wp, pow2(2) / &a2);
            g.push(Complex::with_val(wp, &g[0] - t));
        }
        for j in 1..m.saturating_sub(1) {
            // (a + j + 2) G_(j+1) = -2 a G_j - (a - j + 2) G_(j-1).
            let mut rhs = Complex::with_val(wp, &a * &g[j]) * (-2i32);
            rhs -= Complex::with_val(wp, Complex::with_val(wp, &a + (2 - j as i64)) * &g[j - 1]);
            g.push(rhs / Complex::with_val(wp, &a + (j as u64 + 2)));
        }
        // 2^(-a-1) (2/M).
        let pre = Complex::with_val(wp, Complex::with_val(wp, -Complex::with_val(wp, &a + 1u32)) * &ln2).exp()
            * Float::with_val(wp, 2u32)
            / m as u32;
        let pi = Float::with_val(wp, Constant::Pi);
        let mut u = Vec::with_capacity(m);
        let mut w = Vec::with_capacity(m);
        for q in 0..m {
            let x = Float::with_val(wp, Float::with_val(wp, &pi * (2 * q + 1) as u32) / (2 * m) as u32).cos();
            // sum_j' G_j T_j(x) by the three-term recurrence of T_j.
            let mut acc = Complex::with_val(wp, &g[0] / 2u32);
            let (mut t_prev, mut t_cur) = (Float::with_val(wp, 1u32), x.clone());
            for gj in g.iter().skip(1) {
                acc += Complex::with_val(wp, gj * &t_cur);
                let t_next = Float::with_val(wp, Float::with_val(wp, &x * &t_cur) * 2u32) - &t_prev;
                t_prev = t_cur;
                t_cur = t_next;
            }
            u.push(Float::with_val(prec, Float::with_val(wp, &x + 1u32) / 2u32));
            w.push(Complex::with_val(prec, acc * &pre));
        }
        AbelRule { u, w }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::tanh_sinh::TanhSinh;

    /// The product weights integrate (1 - u)^a T_j(2u - 1) as tanh-sinh does (which holds the
    /// endpoint factor through the exact complement), to 1e-60 at 256 bits.
    #[test]
    fn product_weights_match_tanh_sinh() {
        let prec = 256;
        let eps = Float::with_val(prec, 0.1748);
        let m = 40;
        let rule = AbelRule::new(&eps, m, prec);
        let ts = TanhSinh::new(prec, 2.0, prec);
        for j in [0usize, 7, m - 1] {
            let cheb = |u: &Float| {
                let x = Float::with_val(prec, u * 2u32) - 1u32;
                let ang = Float::with_val(prec, x.acos());
                Float::with_val(prec, ang * j as u32).cos()
            };
            let mut by_rule = Complex::with_val(prec, 0);
            for (u, w) in rule.u.iter().zip(&rule.w) {
                by_rule += Complex::with_val(prec, w * cheb(u));
            }
            let mut direct = Complex::with_val(prec, 0);
            for k in 0..ts.len() {
                // (1 - u)^(-1/2 - i eps) = exp((-1/2 - i eps) ln c).
                let lc = Float::with_val(prec, ts.c[k].ln_ref());
                let z =
                    Complex::with_val(prec, (Float::with_val(prec, &lc * -0.5f64), -Float::with_val(prec, &eps * &lc)))
                        .exp();
                direct += z * cheb(&ts.s[k]) * &ts.w[k];
            }
            let diff = Complex::with_val(prec, &by_rule - &direct);
            let err = diff.abs().real().to_f64();
            assert!(err < 1e-60, "j = {j}: product rule {by_rule} against tanh-sinh {direct}: {err:e}");
        }
    }
}
