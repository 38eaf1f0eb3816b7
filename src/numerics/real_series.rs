//! Truncated power series with real MPFR coefficients: the few operations the numerical route of
//! the Problem 2 coefficients needs (`crate::asymptotics::adhesion_numeric`): truncated products,
//! the reciprocal, composition, and the series of tan and sec.
//!
//! A series is a slice of coefficients c_0 .. c_(len-1) of sum_k c_k x^k + O(x^len) (FLINT
//! `_series` style: the terms from x^len on are unknown). Precision is the argument `prec`; every
//! product is accumulated by fused multiply-add (`Float += &a * &b`: one rounding per term, no
//! temporary allocation).
//! Formulas (power series identities, e.g. Knuth TAOCP vol. 2, 4.7):
//! - reciprocal: a_0 b_k = -sum_{j=1}^{k} a_j b_(k-j);
//! - composition f(g) with g_0 = 0 by Horner, h_m = f_m + g h_(m+1), where h_m is needed only to
//!   length len - m (g^m has valuation m): len^3/6 multiplications for len terms.

#![allow(clippy::needless_range_loop)] // index loops over coefficient tables read best here

use rug::Float;

/// `a b` truncated to `len` terms (missing coefficients of a shorter operand are unknown, so
/// `len` must not exceed either length).
pub(crate) fn mul_trunc(a: &[Float], b: &[Float], len: usize, prec: u32) -> Vec<Float> {
    assert!(len <= a.len() && len <= b.len(), "mul_trunc: {len} terms from operands of {} and {}", a.len(), b.len());
    (0..len)
        .map(|k| {
            let mut acc = Float::new(prec);
            for j in 0..=k {
                acc += &a[j] * &b[k - j];
            }
            acc
        })
        .collect()
}

/// 1/a to `a.len()` terms; `None` if a_0 = 0.
pub fn recip(a: &[Float], prec: u32) -> Option<Vec<Float>> {
    let a0 = a.first()?;
    if a0.is_zero() {
        return None;
    }
    let inv0 = Float::with_val(prec, a0.recip_ref());
    let mut b = vec![inv0.clone()];
    for k in 1..a.len() {
        let mut acc = Float::new(prec);
        for j in 1..=k {
            acc += &a[j] * &b[k - j];
        }
        acc *= &inv0;
        b.push(-acc);
    }
    Some(b)
}

/// f(g) = sum_m f_m g^m to `len` terms, for g with g_0 = 0 (`None` otherwise) and at least `len`
/// known terms of g; only f_0 .. f_(len-1) matter (module doc: Horner, h_m to length len - m).
pub fn compose(f: &[Float], g: &[Float], len: usize, prec: u32) -> Option<Vec<Float>> {
    if g.first().is_some_and(|c| !c.is_zero()) || g.len() < len {
        return None;
    }
    let top = f.len().min(len);
    if top == 0 {
        return Some(vec![Float::new(prec); len]);
    }
    // h = h_(top-1) = f_(top-1), then h_m = f_m + g h_(m+1) to length len - m.
    let mut h: Vec<Float> = vec![Float::with_val(prec, &f[top - 1])];
    for m in (0..top - 1).rev() {
        let n = len - m;
        let mut next: Vec<Float> = Vec::with_capacity(n);
        next.push(Float::with_val(prec, &f[m]));
        for k in 1..n {
            // [x^k] g h = sum_{i=1}^{k} g_i h_(k-i), h known to h.len() terms (= n - 1).
            let mut acc = Float::new(prec);
            for i in 1..=k.min(g.len() - 1) {
                if let Some(hv) = h.get(k - i) {
                    acc += &g[i] * hv;
                }
            }
            next.push(acc);
        }
        h = next;
    }
    h.resize(len, Float::new(prec));
    Some(h)
}

/// f(g) for several outer series f sharing one inner g (g_0 = 0, `None` otherwise or if g has
/// fewer than `len` terms), `len` terms each: the powers g^m (valuation m, so only len - m terms
/// each to form) are computed once, len^3/6 multiplications in all, and every f costs len^2/2
/// more, instead of len^3/6 per f by Horner ([`compose`]).
pub fn compose_several(fs: &[&[Float]], g: &[Float], len: usize, prec: u32) -> Option<Vec<Vec<Float>>> {
    if g.first().is_some_and(|c| !c.is_zero()) || g.len() < len {
        return None;
    }
    let mut out: Vec<Vec<Float>> = fs
        .iter()
        .map(|f| {
            let mut v = vec![Float::new(prec); len];
            if let (Some(f0), true) = (f.first(), len > 0) {
                v[0] = Float::with_val(prec, f0);
            }
            v
        })
        .collect();
    // power[k] = [x^k] g^m for k >= m (below m it is 0).
    let mut power: Vec<Float> = (0..len).map(|k| Float::with_val(prec, &g[k])).collect();
    for m in 1..len {
        for (f, o) in fs.iter().zip(out.iter_mut()) {
            if let Some(fm) = f.get(m) {
                for k in m..len {
                    o[k] += fm * &power[k];
                }
            }
        }
        if m + 1 < len {
            // g^(m+1) = g^m g: [x^k] = sum_{i=m}^{k-1} power[i] g[k-i], k >= m+1.
            let next: Vec<Float> = (0..len)
                .map(|k| {
                    let mut acc = Float::new(prec);
                    for i in m..k {
                        acc += &power[i] * &g[k - i];
                    }
                    acc
                })
                .collect();
            power = next;
        }
    }
    Some(out)
}

/// The coefficients of tan(z)/z and sec(z) as series in v = z^2, `len` terms each:
/// tan(z)/z = sinc(z)/cos(z), sec(z) = 1/cos(z), from (-1)^k/(2k+1)! and (-1)^k/(2k)!.
pub(crate) fn tan_sec_in_square(len: usize, prec: u32) -> (Vec<Float>, Vec<Float>) {
    let mut sinc = Vec::with_capacity(len);
    let mut cos = Vec::with_capacity(len);
    let mut term = Float::with_val(prec, 1);
    for k in 0..len as u32 {
        // term = (-1)^k/(2k)!
        if k > 0 {
            term /= (2 * k - 1) * (2 * k);
            term = -term;
        }
        cos.push(term.clone());
        sinc.push(Float::with_val(prec, &term / (2 * k + 1)));
    }
    let sec = recip(&cos, prec).expect("cos(0) = 1");
    let tan_over_z = mul_trunc(&sinc, &sec, len, prec);
    (tan_over_z, sec)
}

#[cfg(test)]
mod tests {
    use super::*;

    const PREC: u32 = 256;

    fn f(x: f64) -> Float {
        Float::with_val(PREC, x)
    }

    fn close(a: &Float, b: &Float, tol: f64) -> bool {
        Float::with_val(PREC, a - b).to_f64().abs() < tol
    }

    /// tan and sec summed at z^2 = 0.3 against MPFR's tan and sec; a (1/a) = 1.
    #[test]
    fn tan_sec_and_recip() {
        let n = 60;
        let (tan, sec) = tan_sec_in_square(n, PREC);
        let v = f(0.3);
        let z = Float::with_val(PREC, v.sqrt_ref());
        let sum = |c: &[Float]| c.iter().rev().fold(Float::new(PREC), |acc, c| acc * &v + c);
        let want_tan = Float::with_val(PREC, z.tan_ref()) / &z;
        let want_sec = Float::with_val(PREC, z.sec_ref());
        assert!(close(&sum(&tan), &want_tan, 1e-40), "{}", sum(&tan));
        assert!(close(&sum(&sec), &want_sec, 1e-40));
        // Bernoulli check: tan z = z + z^3/3 + 2 z^5/15 + 17 z^7/315.
        assert!(close(&tan[1], &Float::with_val(PREC, Float::with_val(PREC, 1) / 3u32), 1e-70));
        assert!(close(&tan[3], &Float::with_val(PREC, Float::with_val(PREC, 17) / 315u32), 1e-70));
        let a = vec![f(0.7), f(-1.3), f(0.25), f(3.0), f(1.0)];
        let one = mul_trunc(&a, &recip(&a, PREC).unwrap(), a.len(), PREC);
        for (k, c) in one.iter().enumerate() {
            assert!(close(c, &f(if k == 0 { 1.0 } else { 0.0 }), 1e-70), "{k}: {c}");
        }
        assert!(recip(&[f(0.0), f(1.0)], PREC).is_none());
    }

    /// exp(x + x^2) by composition of exp's coefficients equals the product exp(x) exp(x^2)
    /// (coefficients of both from 1/k!); arctan(tan x) = x by composition.
    #[test]
    fn composition() {
        let len = 12;
        let fact: Vec<Float> = (0..len as u32)
            .scan(f(1.0), |t, k| {
                if k > 0 {
                    *t /= k;
                }
                Some(t.clone())
            })
            .collect();
        let mut g = vec![f(0.0); len];
        g[1] = f(1.0);
        g[2] = f(1.0);
        let composed = compose(&fact, &g, len, PREC).unwrap();
        let mut exp_x2 = vec![f(0.0); len];
        for k in 0..len / 2 {
            exp_x2[2 * k] = fact[k].clone();
        }
        let direct = mul_trunc(&fact, &exp_x2, len, PREC);
        for k in 0..len {
            assert!(close(&composed[k], &direct[k], 1e-60), "{k}");
        }
        // arctan(t) = sum (-1)^j t^(2j+1)/(2j+1) composed with tan x = x tan_over(x^2).
        let len = 21;
        let (tan_sq, _) = tan_sec_in_square(len / 2 + 1, PREC);
        let mut tan = vec![f(0.0); len];
        for (j, c) in tan_sq.iter().enumerate() {
            if 2 * j + 1 < len {
                tan[2 * j + 1] = c.clone();
            }
        }
        let atan: Vec<Float> = (0..len)
            .map(|k| if k % 2 == 1 { f(if k % 4 == 1 { 1.0 } else { -1.0 }) / k as u32 } else { f(0.0) })
            .collect();
        let x = compose(&atan, &tan, len, PREC).unwrap();
        let both = compose_several(&[&atan, &fact], &tan, len, PREC).unwrap();
        let exp_tan = compose(&fact, &tan, len, PREC).unwrap();
        for k in 0..len {
            assert!(close(&both[0][k], &x[k], 1e-60), "several {k}");
            assert!(close(&both[1][k], &exp_tan[k], 1e-60), "several {k}");
        }
        assert!(compose_several(&[&atan], &[f(1.0), f(1.0)], 2, PREC).is_none());
        for (k, c) in x.iter().enumerate() {
            assert!(close(c, &f(if k == 1 { 1.0 } else { 0.0 }), 1e-60), "{k}: {c}");
        }
        assert!(compose(&atan, &[f(1.0), f(1.0)], 2, PREC).is_none());
    }
}
