//! Quadrature and least squares for the spectral method (`spectral/mod.rs`), generic over [`Real`]:
//! composite tanh-sinh (double-exponential) rules on pieces graded toward near singularities, and
//! a Householder least-squares solver.
//!
//! Tanh-sinh (Takahasi and Mori 1974) on (0, 1): s(t) = 1/(1 + e^(-2 u)), u = (pi/2) sinh t, with
//! the complement 1 - s kept separately, so an integrand with algebraic end singularities is
//! evaluated at the distances to both ends without cancellation. Step h = pi^2/(2 B ln 2) for B
//! bits (error about exp(-pi^2/h) for an integrand analytic in the strip |Im t| < pi/2, squared
//! here for the safety of near singularities), truncated where the weight times the strongest end
//! singularity, distance^(`edge_power` - 1), falls below 2^-B.
//!
//! A singularity at distance d beyond an end of a piece (a kernel pole or the branch point of the
//! density next to it) narrows the strip; [`graded`] splits the piece into lengths d, 2 d, 4 d, ...
//! from that end, so every sub-piece sees it at least one own length away.

use super::real::Real;

/// A tanh-sinh rule on (0, 1): nodes s, complements 1 - s, weights.
#[derive(Debug, Clone)]
pub struct DoubleExp<T> {
    s: Vec<T>,
    c: Vec<T>,
    w: Vec<T>,
}

impl<T: Real> DoubleExp<T> {
    /// The rule at the precision of `one` (a 1 of the working type) for integrands whose end
    /// singularities are no stronger than distance^(edge_power - 1), 0 < edge_power <= 1.
    pub fn new(one: &T, edge_power: f64) -> DoubleExp<T> {
        let bits = one.bits() as f64;
        let ln2 = std::f64::consts::LN_2;
        let h = std::f64::consts::PI.powi(2) / (2.0 * (bits + 8.0) * ln2);
        // e^(-2 u) edge_power < 2^-(bits + 8); f64 keeps e^(2 u) finite
        let mut u_max = (bits + 8.0) * ln2 / (2.0 * edge_power.max(0.02));
        if one.bits() == 53 {
            u_max = u_max.min(340.0);
        }
        let t_max = (u_max * 2.0 / std::f64::consts::PI).asinh();
        let k_max = (t_max / h).ceil() as i64;
        let (hh, pi) = (one.lit(h), one.pi());
        let (mut s, mut c, mut w) = (Vec::new(), Vec::new(), Vec::new());
        for k in -k_max..=k_max {
            let t = one.lit(k as f64) * hh.clone();
            let et = t.exp();
            let sinh = (et.clone() - one.clone() / et.clone()) * one.lit(0.5);
            let cosh = (et.clone() + one.clone() / et) * one.lit(0.5);
            let u = pi.clone() * one.lit(0.5) * sinh;
            // e^(-2 |u|) <= 1: no overflow; s and 1 - s each from the side where it is small
            let e = (-(u.abs()) * one.lit(2.0)).exp();
            let (big, small) = (one.clone() / (one.clone() + e.clone()), e.clone() / (one.clone() + e));
            let (sk, ck) = if u > one.lit(0.0) { (big, small) } else { (small, big) };
            let wk = hh.clone() * pi.clone() * cosh * sk.clone() * ck.clone();
            if wk.partial_cmp(&one.lit(0.0)) != Some(std::cmp::Ordering::Greater) {
                continue; // underflow at the far tail (f64): the node adds nothing
            }
            s.push(sk);
            c.push(ck);
            w.push(wk);
        }
        DoubleExp { s, c, w }
    }

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.s.len()
    }

    /// Whether the rule has no nodes.
    pub fn is_empty(&self) -> bool {
        self.s.is_empty()
    }

    /// Calls `f(d_a, d_b, weight)` at every node of every piece (p, q) of a zone of length `len`:
    /// p, q are offsets from the zone's start a, d_a = x - a and d_b = b - x the node's distances
    /// to the zone's ends (exact at a piece that touches an end).
    pub fn sweep(&self, len: &T, pieces: &[(T, T)], mut f: impl FnMut(&T, &T, &T)) {
        // in place: one set of values reused for every node
        let mut l = len.clone();
        let (mut rest, mut d_a, mut d_b, mut w) = (len.clone(), len.clone(), len.clone(), len.clone());
        for (p, q) in pieces {
            l.set_sub(q, p);
            rest.set_sub(len, q);
            for k in 0..self.s.len() {
                d_a.set_mul_add(&l, &self.s[k], p);
                d_b.set_mul_add(&l, &self.c[k], &rest);
                w.set_mul(&l, &self.w[k]);
                f(&d_a, &d_b, &w);
            }
        }
    }
}

/// The pieces of (p, q): split at the middle, each half graded toward its end when a singularity
/// sits at distance `near_p` beyond p (or `near_q` beyond q) closer than the half's length.
pub fn graded<T: Real>(p: &T, q: &T, near_p: Option<&T>, near_q: Option<&T>) -> Vec<(T, T)> {
    let m = (p.clone() + q.clone()) * p.lit(0.5);
    let mut out = Vec::new();
    let half = m.clone() - p.clone();
    let two = p.lit(2.0);
    match near_p {
        Some(d) if *d < half => {
            let (mut s, mut len) = (p.clone(), d.clone());
            while m.clone() - s.clone() > two.clone() * len.clone() {
                out.push((s.clone(), s.clone() + len.clone()));
                s = s + len.clone();
                len = len * two.clone();
            }
            out.push((s, m.clone()));
        }
        _ => out.push((p.clone(), m.clone())),
    }
    match near_q {
        Some(d) if *d < half => {
            let (mut e, mut len) = (q.clone(), d.clone());
            while e.clone() - m.clone() > two.clone() * len.clone() {
                out.push((e.clone() - len.clone(), e.clone()));
                e = e - len.clone();
                len = len * two.clone();
            }
            out.push((m, e));
        }
        _ => out.push((m, q.clone())),
    }
    out
}

/// The least-squares solution of A x = b (A given by rows, at least as many rows as columns) by
/// Householder QR on unit-norm columns; None when a column is zero or R has a zero pivot.
pub fn least_squares<T: Real>(mut a: Vec<Vec<T>>, mut b: Vec<T>) -> Option<Vec<T>> {
    let (m, n) = (a.len(), a.first()?.len());
    if m < n {
        return None;
    }
    let zero = b[0].lit(0.0);
    let mut s = zero.clone();
    for (row, bi) in a.iter_mut().zip(b.iter_mut()) {
        s.set(&zero);
        for v in row.iter() {
            s.add_mul(v, v);
        }
        let s = s.sqrt();
        if s == zero {
            return None;
        }
        for v in row.iter_mut() {
            *v /= &s;
        }
        *bi /= &s;
    }
    let mut scale = Vec::with_capacity(n);
    for j in 0..n {
        s.set(&zero);
        for row in a.iter() {
            s.add_mul(&row[j], &row[j]);
        }
        let s = s.sqrt();
        if s == zero {
            return None;
        }
        for row in a.iter_mut() {
            row[j] /= &s;
        }
        scale.push(s);
    }
    let (mut dot, mut f) = (zero.clone(), zero.clone());
    for k in 0..n {
        let mut norm2 = zero.clone();
        for row in a.iter().skip(k) {
            norm2.add_mul(&row[k], &row[k]);
        }
        let norm = norm2.sqrt();
        if norm == zero {
            return None;
        }
        let alpha = if a[k][k] > zero { -norm } else { norm };
        let v0 = a[k][k].clone() - alpha.clone();
        let v: Vec<T> = (k..m).map(|i| if i == k { v0.clone() } else { a[i][k].clone() }).collect();
        let mut vtv = zero.clone();
        for x in &v {
            vtv.add_mul(x, x);
        }
        let two_over = b[0].lit(2.0) / vtv;
        for j in k + 1..n {
            dot.set(&zero);
            for (row, vi) in a[k..m].iter().zip(&v) {
                dot.add_mul(vi, &row[j]);
            }
            f.set_mul(&dot, &two_over);
            for (row, vi) in a[k..m].iter_mut().zip(&v) {
                row[j].sub_mul(&f, vi);
            }
        }
        dot.set(&zero);
        for (bi, vi) in b[k..m].iter().zip(&v) {
            dot.add_mul(vi, bi);
        }
        f.set_mul(&dot, &two_over);
        for (bi, vi) in b[k..m].iter_mut().zip(&v) {
            bi.sub_mul(&f, vi);
        }
        a[k][k] = alpha;
    }
    let mut x = vec![zero.clone(); n];
    for k in (0..n).rev() {
        let mut s = b[k].clone();
        for j in k + 1..n {
            s.sub_mul(&a[k][j], &x[j]);
        }
        if a[k][k] == zero {
            return None;
        }
        s /= &a[k][k];
        x[k] = s;
    }
    for (xi, s) in x.iter_mut().zip(&scale) {
        *xi /= s;
    }
    Some(x)
}
