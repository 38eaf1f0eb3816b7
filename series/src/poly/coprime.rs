//! A certificate that two polynomials of Q[symbols] are coprime, computed modulo the prime
//! 2^61 - 1 (the cheap first step of [`super::gcd`] and of the heuristic gcd of [`super::heu`]):
//! for each common symbol, the univariate images at random residues of the others have a gcd of
//! degree 0. Sound (never claims coprime for a common factor), inconclusive otherwise; tested by
//! `certificate_is_sound` in `gcd.rs`.

use super::Poly;
use crate::Symbol;
use num_bigint::BigInt;

/// The prime of the coprimality certificate, 2^61 - 1.
const P: u64 = (1 << 61) - 1;

/// `x mod P` for any `x < 2^128`, by the Mersenne folding 2^61 = 1 (mod P): no division.
fn reduce(x: u128) -> u64 {
    let p = P as u128;
    let r = (x & p) + (x >> 61); // < 2^61 + 2^67
    let r = ((r & p) + (r >> 61)) as u64; // < 2^61 + 2^6
    if r >= P {
        r - P
    } else {
        r
    }
}

fn mul_mod(a: u64, b: u64) -> u64 {
    reduce(a as u128 * b as u128)
}

fn pow_mod(mut a: u64, mut e: u64) -> u64 {
    let mut r = 1;
    while e > 0 {
        if e & 1 == 1 {
            r = mul_mod(r, a);
        }
        a = mul_mod(a, a);
        e >>= 1;
    }
    r
}

/// `n mod P` in `[0, P)`.
fn big_mod(n: &BigInt) -> u64 {
    // 2^64 = 8 (mod P): acc 2^64 + d = 8 acc + d.
    let r = n.magnitude().iter_u64_digits().rev().fold(0u64, |acc, d| reduce(8 * acc as u128 + d as u128));
    if num_traits::Signed::is_negative(n) && r != 0 {
        P - r
    } else {
        r
    }
}

/// The image mod P of `den p` (an integer polynomial) in `x` alone, the other symbols set to
/// `point` (dense, index = exponent).
fn image_mod(p: &Poly, x: Symbol, point: &[(Symbol, u64)]) -> Vec<u64> {
    let mut out = vec![0u64; p.degree_in(x) as usize + 1];
    // Powers of each point coordinate, extended on demand.
    let mut powers: Vec<Vec<u64>> = point.iter().map(|&(_, v)| vec![1, v]).collect();
    for (m, n) in &p.terms {
        let mut c = big_mod(n);
        let mut e_x = 0;
        for &(s, e) in m.factors() {
            if s == x {
                e_x = e;
            } else if let Some(k) = point.iter().position(|(t, _)| *t == s) {
                let pw = &mut powers[k];
                while pw.len() <= e as usize {
                    let next = mul_mod(pw[pw.len() - 1], pw[1]);
                    pw.push(next);
                }
                c = mul_mod(c, pw[e as usize]);
            }
        }
        let slot = &mut out[e_x as usize];
        *slot = (*slot + c) % P;
    }
    out
}

/// Degree of the gcd of two univariate polynomials mod P (dense, non-zero leading coefficients):
/// Euclid with monic remainders.
fn univariate_gcd_degree_mod(a: Vec<u64>, b: Vec<u64>) -> usize {
    let (mut a, mut b) = if a.len() >= b.len() { (a, b) } else { (b, a) };
    loop {
        while b.last() == Some(&0) {
            b.pop();
        }
        if b.is_empty() {
            return a.len().saturating_sub(1);
        }
        let lb = pow_mod(*b.last().expect("non-empty"), P - 2);
        b.iter_mut().for_each(|c| *c = mul_mod(*c, lb));
        // a mod b (b monic).
        while a.len() >= b.len() {
            let lead = a.pop().expect("non-empty");
            let off = a.len() + 1 - b.len();
            for (k, c) in b[..b.len() - 1].iter().enumerate() {
                a[off + k] = (a[off + k] + P - mul_mod(lead, *c)) % P;
            }
            while a.last() == Some(&0) {
                a.pop();
            }
        }
        std::mem::swap(&mut a, &mut b);
    }
}

/// A proof that `gcd(a, b)` is a constant, or `false` (inconclusive). For each symbol `x` of
/// both, the integer polynomials `den a`, `den b` are reduced mod the prime P = 2^61 - 1 and the
/// other symbols set to fixed residues at which neither leading coefficient in `x` vanishes mod P.
/// A non-constant common factor `g` involving `x` (primitive, in Z[symbols] by Gauss's lemma)
/// would survive there with its full degree in `x` (the degrees of the images of `a = g h` add up
/// to `deg_x a`, so neither factor loses degree) and divide both images, so a constant gcd of the
/// images mod P excludes every factor involving `x`. Cheap (univariate Euclid over 61-bit
/// residues), it spares the primitive PRS of [`gcd`] on the coprime pairs that dominate fraction
/// arithmetic; an unlucky prime or point only makes it inconclusive.
pub(super) fn coprime_certificate(a: &Poly, b: &Poly) -> bool {
    let (sa, sb) = (a.symbols(), b.symbols());
    let common: Vec<Symbol> = sa.iter().copied().filter(|s| sb.contains(s)).collect();
    let mut others: Vec<Symbol> = sa.clone();
    others.extend(sb.iter().copied());
    others.sort();
    others.dedup();
    'vars: for &x in &common {
        let (da, db) = (a.degree_in(x) as usize, b.degree_in(x) as usize);
        for attempt in 0..4u64 {
            let point: Vec<(Symbol, u64)> = others
                .iter()
                .filter(|&&y| y != x)
                .enumerate()
                .map(|(k, &y)| (y, 1_000_003 * (k as u64 + 1) + 7_919 * attempt + 3))
                .collect();
            let (ia, ib) = (image_mod(a, x, &point), image_mod(b, x, &point));
            if ia[da] == 0 || ib[db] == 0 {
                continue; // a leading coefficient vanished there: try another point
            }
            if univariate_gcd_degree_mod(ia, ib) == 0 {
                continue 'vars;
            }
            return false;
        }
        return false;
    }
    true
}
