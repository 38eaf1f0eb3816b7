//! One run of the analytic continuation (module doc of [`super`]): the tangent-variable series up to
//! t0 = tan eta0, then a Chebyshev collocation of the Volterra equation on [t_a, T1], T1 = tan lambda,
//! at one precision and one node count.
//!
//! The equation in t = tan eta (docs/theory.md section 5; [`crate::asymptotics::adhesion_numeric`]):
//! ```text
//!   Re int_0^T k(T, t) Phi(t) dt = pi arctan T,
//!   k(T, t) = (cosh(2 eps arctan t) + i T sinh(2 eps arctan t)) (T + t)^(-1/2+i eps) (T - t)^(-1/2-i eps),
//! ```
//! Phi(t) = cos(eta) P'(eta), P = int_0^T1 Phi(t) (1 + t^2)^(-1/2) dt (P2 = E* k (L/pi)^2 P).
//! - History: Phi = the series sum_k phi_k t^k on [0, t_a], t_a = [`OVERLAP`] t0, integrated by
//!   tanh-sinh (the collocation points T > t0 keep T - t >= t0 - t_a away from its end).
//! - Unknown: Phi = sum_(k<n) c_k T_k(y), y = (2 t - t_a - T1)/(T1 - t_a), on [t_a, T1]. At the n
//!   Chebyshev points t_i of that interval: t_i <= t0, Phi(t_i) = the series (the overlap pins
//!   the continuation to the analytic member); t_i > t0, the equation, with
//!   int_(t_a)^T k Phi dt = (T - t_a)^(1/2-i eps) int_0^1 (1 - u)^(-1/2-i eps) g(u) Phi(t(u)) du,
//!   g = (cosh + i T sinh)(T + t)^(-1/2+i eps), by the product rule of [`super::product`].
//! - The load: tanh-sinh on [0, t_a] (series), Clenshaw-Curtis (Fejer, first kind) on [t_a, T1].

use super::product::AbelRule;
use crate::asymptotics::adhesion_numeric::tangent_coefficients;
use crate::error::Error;
use crate::model::Material;
use crate::numerics::tanh_sinh::TanhSinh;
use crate::params::adhesion::eps as eps_const;
use rug::float::Constant;
use rug::{Assign, Complex, Float};

/// t_a = OVERLAP t0: the history's end below the first collocation point.
pub const OVERLAP: f64 = 0.85;

/// Extra bits of the series recurrence (its divisor Re M_(2j+1) is small near j = m*/2).
pub const SERIES_EXTRA_BITS: u32 = 64;

/// One run's result.
#[derive(Debug, Clone)]
pub struct Run {
    /// Working bits.
    pub prec: u32,
    /// Chebyshev nodes.
    pub nodes: usize,
    /// Series terms (powers of t through t^(2 terms - 1)).
    pub terms: usize,
    /// eta0 (the end of the series).
    pub eta0: f64,
    /// P(lambda) = int_0^lambda P'(eta) d eta.
    pub load: Float,
    /// |last two Chebyshev coefficients| relative to the largest (the interpolant's tail).
    pub tail: f64,
}

/// Phi by Horner in t^2 from the odd coefficients `odd` (phi_(2j+1) = odd[j]).
fn series_value(odd: &[Float], t: &Float, prec: u32) -> Float {
    let t2 = Float::with_val(prec, t.square_ref());
    let mut acc = Float::with_val(prec, 0);
    for c in odd.iter().rev() {
        acc *= &t2;
        acc += c;
    }
    acc * t
}

/// cosh and sinh of 2 eps arctan t.
fn hyperbolic(eps: &Float, t: &Float, prec: u32) -> (Float, Float) {
    let e = Float::with_val(prec, Float::with_val(prec, t.atan_ref()) * eps * 2u32).exp();
    let inv = Float::with_val(prec, e.recip_ref());
    (Float::with_val(prec, &e + &inv) / 2u32, Float::with_val(prec, &e - &inv) / 2u32)
}

/// Chebyshev values T_0..T_(n-1) at y.
fn chebyshev_values(y: &Float, n: usize, prec: u32) -> Vec<Float> {
    let mut v = Vec::with_capacity(n);
    v.push(Float::with_val(prec, 1u32));
    if n > 1 {
        v.push(y.clone());
    }
    for k in 2..n {
        let next = Float::with_val(prec, Float::with_val(prec, y * &v[k - 1]) * 2u32) - &v[k - 2];
        v.push(next);
    }
    v
}

/// Gaussian elimination with partial pivoting for several right sides.
fn solve_many(mut a: Vec<Vec<Float>>, mut rhs: Vec<Vec<Float>>, prec: u32) -> Result<Vec<Vec<Float>>, Error> {
    let n = a.len();
    let mut t = Float::new(prec);
    for k in 0..n {
        let p = (k..n).max_by(|&i, &j| a[i][k].cmp_abs(&a[j][k]).unwrap_or(std::cmp::Ordering::Equal)).unwrap_or(k);
        a.swap(k, p);
        for r in rhs.iter_mut() {
            r.swap(k, p);
        }
        if a[k][k].is_zero() {
            return Err(Error::NoConvergence {
                what: format!("analytic continuation: singular collocation matrix at column {k}"),
            });
        }
        let piv = a[k][k].clone();
        let (top, below) = a.split_at_mut(k + 1);
        let row_k = &top[k];
        for (off, row_i) in below.iter_mut().enumerate() {
            let m = Float::with_val(prec, &row_i[k] / &piv);
            if m.is_zero() {
                continue;
            }
            for (aij, akj) in row_i[k..].iter_mut().zip(&row_k[k..]) {
                t.assign(&m * akj);
                *aij -= &t;
            }
            for r in rhs.iter_mut() {
                t.assign(&m * &r[k]);
                r[k + 1 + off] -= &t;
            }
        }
    }
    Ok(rhs
        .into_iter()
        .map(|b| {
            let mut x = vec![Float::with_val(prec, 0); n];
            for k in (0..n).rev() {
                let mut acc = b[k].clone();
                for j in k + 1..n {
                    acc -= Float::with_val(prec, &a[k][j] * &x[j]);
                }
                x[k] = acc / &a[k][k];
            }
            x
        })
        .collect())
}

/// Highest power t^(2 J + 1) of the series computed: J = [`SERIES_POWERS`] (O(J^2) operations).
/// At nu = 0 the coefficients rise from O(1) at t^300 to 10^340 at t^1000 and 10^560 at t^2000
/// (the divisors Re M_(2j+1) shrinking towards j = 302), so the series sums to 10^-170 at
/// t0 = 0.4 only from about t^1900 on.
pub const SERIES_POWERS: usize = 1600;

/// Largest term of the series at t0 allowed, relative to its sum (bits of cancellation).
pub const MAX_CANCELLATION_BITS: u32 = 160;

/// The odd coefficients phi_(2j+1), j < J', of the series at `prec` bits and J', the number of terms
/// after which every term at t0 stays below 2^-(prec + 8) of the sum through
/// t^(2 SERIES_POWERS + 1) (first tried with a quarter of the terms); an error when the terms have not fallen that far, or when the largest
/// term exceeds the sum by more than [`MAX_CANCELLATION_BITS`] (the coefficients are computed with
/// [`SERIES_EXTRA_BITS`] + that many more bits).
pub fn series_to(material: &Material, t0: &Float, prec: u32) -> Result<(Vec<Float>, usize), Error> {
    // A quarter of the terms first (enough where the coefficients stay O(1)), then all.
    match series_with(material, t0, prec, SERIES_POWERS / 4) {
        Ok(s) => Ok(s),
        Err(_) => series_with(material, t0, prec, SERIES_POWERS),
    }
}

fn series_with(material: &Material, t0: &Float, prec: u32, powers: usize) -> Result<(Vec<Float>, usize), Error> {
    let wp = prec + SERIES_EXTRA_BITS + MAX_CANCELLATION_BITS;
    let coeffs = tangent_coefficients(material, powers, wp);
    let odd: Vec<Float> = (0..=powers).map(|j| coeffs.phi[2 * j + 1].clone()).collect();
    let sum = series_value(&odd, &Float::with_val(wp, t0), wp);
    let log_sum = Float::with_val(wp, sum.abs_ref()).log2().to_f64();
    let log_t0 = Float::with_val(wp, t0.log2_ref()).to_f64();
    let log_term = |j: usize| {
        if odd[j].is_zero() {
            f64::NEG_INFINITY
        } else {
            Float::with_val(wp, odd[j].abs_ref()).log2().to_f64() + (2 * j + 1) as f64 * log_t0 - log_sum
        }
    };
    let peak = (0..=powers).map(log_term).fold(f64::NEG_INFINITY, f64::max);
    let eta0 = Float::with_val(53, t0.atan_ref()).to_f64();
    if peak > MAX_CANCELLATION_BITS as f64 {
        return Err(Error::NoConvergence {
            what: format!(
                "analytic continuation: the series in tan eta cancels 10^{:.0} at eta0 = {eta0:.4} (more than \
                 2^{MAX_CANCELLATION_BITS})",
                peak * std::f64::consts::LOG10_2
            ),
        });
    }
    let floor = -(prec as f64) - 8.0;
    let terms = (0..=powers).rev().find(|&j| log_term(j) >= floor).map_or(0, |j| j + 1);
    // Converged within 7/8 of the terms, and still falling at the end (the coefficients' growth
    // slows with the order: falling terms stay falling).
    if terms + powers / 8 > powers || log_term(powers) >= log_term(powers - powers / 8) {
        return Err(Error::NoConvergence {
            what: format!(
                "analytic continuation: the series in tan eta has not converged to {prec} bits at eta0 = {eta0:.4} \
                 within t^{}",
                2 * powers + 1
            ),
        });
    }
    Ok((odd[..terms].iter().map(|c| Float::with_val(prec, c)).collect(), terms))
}

/// One run: series to eta0, collocation with `n` nodes from there to `lambda` at `prec` bits.
pub fn run(material: &Material, lambda: &Float, eta0: f64, prec: u32, n: usize) -> Result<Run, Error> {
    let eps = eps_const(material, prec);
    let t0 = Float::with_val(prec, eta0).tan();
    let ta = Float::with_val(prec, &t0 * OVERLAP);
    let t1 = Float::with_val(prec, lambda.tan_ref());
    let (odd, terms) = series_to(material, &t0, prec)?;
    let pi = Float::with_val(prec, Constant::Pi);
    // History nodes on [0, t_a].
    let ts = TanhSinh::new(prec, 1.5, prec);
    struct Node {
        t: Float,
        ch: Float,
        sh: Float,
        weighted_phi: Float,
    }
    let hist: Vec<Node> = (0..ts.len())
        .map(|j| {
            let t = Float::with_val(prec, &ts.s[j] * &ta);
            let (ch, sh) = hyperbolic(&eps, &t, prec);
            let weighted_phi = Float::with_val(prec, &ts.w[j] * &ta) * series_value(&odd, &t, prec);
            Node { t, ch, sh, weighted_phi }
        })
        .collect();
    let mid = Float::with_val(prec, &ta + &t1) / 2u32;
    let half = Float::with_val(prec, &t1 - &ta) / 2u32;
    let m = n + 20;
    let rule = AbelRule::new(&eps, m, prec);
    let mut a: Vec<Vec<Float>> = Vec::with_capacity(n);
    let mut b = Vec::with_capacity(n);
    for i in 0..n {
        let y = Float::with_val(prec, Float::with_val(prec, &pi * (2 * i + 1) as u32) / (2 * n) as u32).cos();
        let big_t = Float::with_val(prec, &mid + Float::with_val(prec, &half * &y));
        if big_t <= t0 {
            a.push(chebyshev_values(&y, n, prec));
            b.push(series_value(&odd, &big_t, prec));
            continue;
        }
        // History: Re sum_j w_j k(T, t_j) Phi(t_j).
        let mut h = Float::with_val(prec, 0);
        for nd in &hist {
            let plus = Float::with_val(prec, &big_t + &nd.t);
            let minus = Float::with_val(prec, &big_t - &nd.t);
            let modulus = Float::with_val(prec, Float::with_val(prec, &plus * &minus).sqrt()).recip();
            let phase = Float::with_val(prec, Float::with_val(prec, &plus / &minus).ln()) * &eps;
            let (s, c) = phase.sin_cos(Float::new(prec));
            // Re[(ch + i T sh)(c + i s)] = ch c - T sh s.
            let re = Float::with_val(prec, &nd.ch * &c) - Float::with_val(prec, &big_t * &nd.sh) * &s;
            h += re * modulus * &nd.weighted_phi;
        }
        // Unknown part: v_q = Re[(T - t_a)^(1/2 - i eps) w_q g(u_q)], row_k = sum_q v_q T_k(y_q).
        let span = Float::with_val(prec, &big_t - &ta);
        let ln_span = Float::with_val(prec, span.ln_ref());
        let pre = Complex::with_val(
            prec,
            (Float::with_val(prec, &ln_span / 2u32), Float::with_val(prec, -Float::with_val(prec, &ln_span * &eps))),
        )
        .exp();
        let mut row = vec![Float::with_val(prec, 0); n];
        for (u, w) in rule.u.iter().zip(&rule.w) {
            let t = Float::with_val(prec, &ta + Float::with_val(prec, &span * u));
            let (ch, sh) = hyperbolic(&eps, &t, prec);
            let plus = Float::with_val(prec, &big_t + &t);
            let ln_plus = Float::with_val(prec, plus.ln_ref());
            // (T + t)^(-1/2 + i eps) = exp(-ln/2 + i eps ln).
            let power = Complex::with_val(
                prec,
                (Float::with_val(prec, &ln_plus / -2i32), Float::with_val(prec, &ln_plus * &eps)),
            )
            .exp();
            let g = Complex::with_val(prec, (ch, Float::with_val(prec, &big_t * &sh))) * power;
            let v = Complex::with_val(prec, Complex::with_val(prec, &pre * w) * g);
            let v = v.real().clone();
            let yq = Float::with_val(prec, Float::with_val(prec, &t - &mid) / &half);
            let (mut tp, mut tc) = (Float::with_val(prec, 1u32), yq.clone());
            for (k, r) in row.iter_mut().enumerate() {
                if k == 0 {
                    *r += &v;
                    continue;
                }
                *r += Float::with_val(prec, &v * &tc);
                let next = Float::with_val(prec, Float::with_val(prec, &yq * &tc) * 2u32) - &tp;
                tp = std::mem::replace(&mut tc, next);
            }
        }
        a.push(row);
        let atan = Float::with_val(prec, big_t.atan_ref());
        b.push(Float::with_val(prec, &pi * &atan) - h);
    }
    let c = solve_many(a, vec![b], prec)?.pop().expect("one right side");
    // The load: series part on [0, t_a], Fejer on [t_a, T1].
    let mut load = Float::with_val(prec, 0);
    for nd in &hist {
        let r = Float::with_val(prec, Float::with_val(prec, nd.t.square_ref()) + 1u32).sqrt();
        load += Float::with_val(prec, &nd.weighted_phi / &r);
    }
    load += fejer_load(&c, &mid, &half, prec);
    let cmax = c.iter().map(|x| x.to_f64().abs()).fold(0.0, f64::max);
    let tail = c[n - 2..].iter().map(|x| x.to_f64().abs()).fold(0.0, f64::max) / cmax;
    Ok(Run { prec, nodes: n, terms, eta0, load, tail })
}

/// int_(t_a)^(T1) f(t) (1 + t^2)^(-1/2) dt for the Chebyshev series `c` by Fejer's first rule at
/// 2 n points.
fn fejer_load(c: &[Float], mid: &Float, half: &Float, prec: u32) -> Float {
    let m = 2 * c.len();
    let pi = Float::with_val(prec, Constant::Pi);
    let mut sc = Float::with_val(prec, 0);
    for q in 0..m {
        let theta = Float::with_val(prec, &pi * (2 * q + 1) as u32) / (2 * m) as u32;
        let y = Float::with_val(prec, theta.cos_ref());
        // Fejer weight on [-1, 1]: (2/m) (1 - 2 sum_(j=1)^(m/2) cos(2 j theta)/(4 j^2 - 1)).
        let tv = chebyshev_values(&y, m + 1, prec);
        let mut s = Float::with_val(prec, 0);
        for j in 1..=m / 2 {
            s += Float::with_val(prec, &tv[2 * j] / (4 * j * j - 1) as u32);
        }
        let w = Float::with_val(prec, 1u32 - Float::with_val(prec, &s * 2u32)) * 2u32 / m as u32;
        let t = Float::with_val(prec, mid + Float::with_val(prec, half * &y));
        let r = Float::with_val(prec, Float::with_val(prec, t.square_ref()) + 1u32).sqrt();
        let wr = Float::with_val(prec, &w / &r) * half;
        let mut f = Float::with_val(prec, 0);
        for (x, tk) in c.iter().zip(&tv) {
            f += Float::with_val(prec, x * tk);
        }
        sc += Float::with_val(prec, &wr * &f);
    }
    sc
}
