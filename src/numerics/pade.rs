//! Padé resummation of a series in one variable w (docs/theory.md section 11): the near-diagonal
//! approximants [L/M], L + M = N (every known coefficient used), built exactly by the engine
//! ([`exact_series::Pade`], extended Euclid over Q), evaluated at a point in MPFR, with the checks
//! that decide when a Padé value is refused.
//!
//! Coefficients: exact rationals when the parameters are rational (a frictionless punch: theta =
//! T = 0), else MPFR values, which are binary rationals and enter the exact algorithm as they are
//! ([`float_to_q`]): the approximant is then the exact one of the rounded coefficients, and the
//! caller states the effect of the rounding by a second run at more bits.
//!
//! For each candidate [L/M] (|L - M| <= [`SPREAD`], M >= 1):
//! - **estimated digits**: the agreement, on the quantity's scale, of its value with those of its
//!   two neighbours [L-1/M] and [L/M-1] (each one coefficient fewer; the smaller agreement). An
//!   estimate, not a verification: the tests compare it with the closed forms;
//! - **poles**: the zeros of the denominator (Aberth-Ehrlich in MPFR complex numbers). The value
//!   at w continues the sum analytically along the segment [0, w]; a pole within [`POLE_MARGIN`]
//!   |w| of that segment refuses the candidate, unless a zero of the numerator lies within
//!   [`DOUBLET_DISTANCE`] |z| of it (a Froissart doublet: a pole cancelled by a zero, which the
//!   approximant carries as noise; listed, not refused). Such a pole is either spurious or a real
//!   singularity between 0 and w (Problem 2 beyond eta_s), and in both cases the value at w is not
//!   the continuation. A disc |z| <= |w| (1 + margin) instead of the segment would refuse every
//!   resummation beyond the radius of convergence, whose poles model the true singularities off
//!   the path (log(1 + w)/w at w = 2: poles on (-inf, -1], 11 digits against 0 for the partial
//!   sum, test `log_resummed_beyond_its_radius_with_honest_digits`); poles inside that disc are
//!   listed (`poles`), and their effect on the value is what the neighbours' disagreement measures;
//! - a candidate is refused when its approximant does not exist (a degenerate block), when a
//!   pole refuses it, or when fewer than one digit is estimated.
//!
//! The chosen candidate is the most diagonal one not refused ([n/n], then [n+1/n-1], [n-1/n+1], ...),
//! with the digits its neighbours estimate.

use crate::numerics::accuracy::{readable_f64, verified_digits_mpfr};
use crate::numerics::exact::to_float;
use exact_series::{Pade, Series, Q};
use rug::{Complex, Float};

/// Candidates [L/M] with |L - M| <= SPREAD (near-diagonal).
pub const SPREAD: usize = 2;

/// A pole within POLE_MARGIN |w| of the segment [0, w] refuses an approximant (module doc).
pub const POLE_MARGIN: f64 = 0.05;

/// A pole and a zero closer than DOUBLET_DISTANCE |pole| form a Froissart doublet (module doc).
pub const DOUBLET_DISTANCE: f64 = 1e-4;

/// Bits of the root finder of poles and zeros (they are printed to 6 digits and compared with
/// the disc; the coefficients are exact).
const ROOT_BITS: u32 = 128;

/// An MPFR value as the exact binary rational it is; `None` for NaN or infinity.
pub fn float_to_q(x: &Float) -> Option<Q> {
    let r = x.to_rational()?;
    let (n, d) = r.into_numer_denom();
    let to_big = |z: rug::Integer| {
        let sign = if z < 0 { num_bigint::Sign::Minus } else { num_bigint::Sign::Plus };
        num_bigint::BigInt::from_biguint(
            sign,
            num_bigint::BigUint::from_bytes_le(&z.abs().to_digits::<u8>(rug::integer::Order::Lsf)),
        )
    };
    Some(Q::new(to_big(n), to_big(d)))
}

/// One approximant [L/M] evaluated at w.
#[derive(Debug, Clone)]
pub struct PadeValue {
    /// Numerator degree bound L.
    pub l: usize,
    /// Denominator degree bound M.
    pub m: usize,
    /// P(w)/Q(w) (NaN when the approximant does not exist or Q(w) = 0).
    pub value: Float,
    /// Estimated digits on the quantity's scale (agreement with [L-1/M] and [L/M-1]); 0 when
    /// refused.
    pub digits: f64,
    /// Zeros of the denominator (the approximant's poles in w).
    pub poles: Vec<Complex>,
    /// Poles matched by a zero of the numerator (Froissart doublets).
    pub doublets: Vec<Complex>,
    /// Why the value is refused, if it is.
    pub refusal: Option<String>,
}

/// The Padé candidates of one quantity at one point.
#[derive(Debug, Clone)]
pub struct Resummation {
    /// The point w.
    pub w: Float,
    /// Every candidate, diagonal first.
    pub candidates: Vec<PadeValue>,
    /// The index of the chosen candidate: the most diagonal one not refused.
    pub best: Option<usize>,
}

impl Resummation {
    /// The best candidate not refused.
    pub fn best(&self) -> Option<&PadeValue> {
        self.best.map(|i| &self.candidates[i])
    }
    /// One line per refused candidate: `[L/M]: reason`.
    pub fn refusals(&self) -> Vec<String> {
        self.candidates.iter().filter_map(|c| c.refusal.as_ref().map(|r| format!("[{}/{}]: {r}", c.l, c.m))).collect()
    }
}

/// A polynomial with exact coefficients (low to high) at w, `prec` bits (Horner).
fn horner(c: &[Q], w: &Float, prec: u32) -> Float {
    let mut acc = Float::with_val(prec, 0);
    for a in c.iter().rev() {
        acc *= w;
        acc += to_float(a, prec);
    }
    acc
}

fn value_of(p: &Pade<Q>, w: &Float, prec: u32) -> Float {
    Float::with_val(prec, horner(&p.numer, w, prec) / horner(&p.denom, w, prec))
}

/// The complex zeros of a polynomial with exact coefficients (low to high, the last non-zero),
/// by the Aberth-Ehrlich iteration at `ROOT_BITS` bits. Empty for a constant.
pub(crate) fn polynomial_roots(c: &[Q]) -> Vec<Complex> {
    let prec = ROOT_BITS;
    let mut c: Vec<Float> = c.iter().map(|a| to_float(a, prec)).collect();
    while c.last().is_some_and(|a| a.is_zero()) {
        c.pop();
    }
    let d = c.len().saturating_sub(1);
    if d == 0 {
        return vec![];
    }
    let lead = c[d].clone();
    let c: Vec<Float> = c.iter().map(|a| Float::with_val(prec, a / &lead)).collect();
    // Start on a circle of the Fujiwara bound's radius, off the real axis.
    let radius = (0..d).map(|k| 2.0 * c[k].to_f64().abs().powf(1.0 / (d - k) as f64)).fold(0.0f64, f64::max).max(1e-3);
    let mut z: Vec<Complex> = (0..d)
        .map(|k| {
            let t = 2.0 * std::f64::consts::PI * k as f64 / d as f64 + 0.4;
            Complex::with_val(prec, (radius * t.cos(), radius * t.sin()))
        })
        .collect();
    let tol = Float::with_val(prec, Float::i_exp(1, -(prec as i32) + 16));
    for _ in 0..500 {
        let mut moved = Float::with_val(prec, 0);
        for i in 0..d {
            let (mut p, mut dp) = (Complex::with_val(prec, (1, 0)), Complex::with_val(prec, (0, 0)));
            for a in c.iter().rev().skip(1) {
                dp = Complex::with_val(prec, &dp * &z[i]) + &p;
                p = Complex::with_val(prec, &p * &z[i]) + a;
            }
            if p.is_zero() {
                continue;
            }
            let ratio = Complex::with_val(prec, &p / &dp);
            let mut sum = Complex::with_val(prec, (0, 0));
            for (j, zj) in z.iter().enumerate() {
                if j != i {
                    sum += Complex::with_val(prec, Complex::with_val(prec, &z[i] - zj).recip_ref());
                }
            }
            let denom = Complex::with_val(prec, 1 - Complex::with_val(prec, &ratio * &sum));
            let step = Complex::with_val(prec, &ratio / &denom);
            let size = Float::with_val(prec, step.abs_ref())
                / Float::with_val(prec, z[i].abs_ref()).max(&Float::with_val(prec, 1));
            if size > moved {
                moved = size;
            }
            z[i] -= step;
        }
        if moved < tol {
            break;
        }
    }
    z.sort_by(|a, b| {
        let (x, y) = (Float::with_val(64, a.abs_ref()).to_f64(), Float::with_val(64, b.abs_ref()).to_f64());
        x.total_cmp(&y)
    });
    z
}

/// A complex number as `1.23456` or `1.23456 + 0.5i` (6 significant digits).
pub(crate) fn complex_text(z: &Complex) -> String {
    let (re, im) = (z.real().to_f64(), z.imag().to_f64());
    let scale = re.abs().max(im.abs());
    if im.abs() <= 1e-12 * scale {
        format!("{re:.6e}")
    } else {
        format!("{re:.6e} {} {:.6e}i", if im < 0.0 { "-" } else { "+" }, im.abs())
    }
}

fn modulus(z: &Complex) -> f64 {
    Float::with_val(64, z.abs_ref()).to_f64()
}

/// The distance of z from the real segment [0, w].
fn distance_to_segment(z: &Complex, w: f64) -> f64 {
    let (x, y) = (z.real().to_f64(), z.imag().to_f64());
    let (lo, hi) = if w >= 0.0 { (0.0, w) } else { (w, 0.0) };
    let dx = if x < lo {
        lo - x
    } else if x > hi {
        x - hi
    } else {
        0.0
    };
    dx.hypot(y)
}

/// The approximant [l/m] of `f` at w with its poles, doublets and pole refusal (no digits yet).
fn candidate(f: &Series<Q>, l: usize, m: usize, w: &Float, prec: u32) -> (Option<Pade<Q>>, PadeValue) {
    let nan = Float::with_val(prec, f64::NAN);
    let p = match Pade::new(f, l, m) {
        Ok(p) => p,
        Err(e) => {
            let v = PadeValue {
                l,
                m,
                value: nan,
                digits: 0.0,
                poles: vec![],
                doublets: vec![],
                refusal: Some(e.to_string()),
            };
            return (None, v);
        }
    };
    let poles = polynomial_roots(&p.denom);
    let zeros = polynomial_roots(&p.numer);
    let wf = w.to_f64();
    let reach = wf.abs() * POLE_MARGIN;
    let mut doublets = vec![];
    let mut refusal = None;
    for z in &poles {
        let r = modulus(z);
        let matched =
            zeros.iter().any(|y| modulus(&Complex::with_val(ROOT_BITS, y - z)) < DOUBLET_DISTANCE * r.max(1e-300));
        if matched {
            doublets.push(z.clone());
        } else if distance_to_segment(z, wf) <= reach && refusal.is_none() {
            refusal = Some(format!(
                "pole at w = {} within {} of the segment [0, {}] ({}% of |w|), not matched by a zero",
                complex_text(z),
                readable_f64(reach),
                readable_f64(wf),
                POLE_MARGIN * 100.0
            ));
        }
    }
    let value = value_of(&p, w, prec);
    (Some(p), PadeValue { l, m, value, digits: 0.0, poles, doublets, refusal })
}

/// The near-diagonal Padé approximants of `f` (all its coefficients: L + M = prec - 1) at w, with
/// estimated digits on `scale` capped at `cap`, refusals and the best candidate (module doc).
pub fn resum(f: &Series<Q>, w: &Float, scale: &Float, cap: f64, prec: u32) -> Resummation {
    let n = f.prec().saturating_sub(1);
    let mut pairs: Vec<(usize, usize)> =
        (1..=n).map(|m| (n - m, m)).filter(|(l, m)| l.abs_diff(*m) <= SPREAD).collect();
    pairs.sort_by_key(|(l, m)| (l.abs_diff(*m), std::cmp::Reverse(*l)));
    let mut candidates = vec![];
    // The neighbours' values, each computed once (adjacent candidates share one): None where the
    // approximant does not exist or its value is not finite. Only the value is used.
    let mut neighbours: std::collections::HashMap<(usize, usize), Option<Float>> = std::collections::HashMap::new();
    for (l, m) in pairs {
        let (_, mut v) = candidate(f, l, m, w, prec);
        if v.refusal.is_none() {
            let mut agreement: Option<f64> = None;
            let mut seen = vec![];
            for (nl, nm) in [(l.wrapping_sub(1), m), (l, m - 1)] {
                if nl == usize::MAX {
                    continue;
                }
                let value = neighbours.entry((nl, nm)).or_insert_with(|| {
                    let p = Pade::new(&f.truncate(nl + nm + 1), nl, nm).ok()?;
                    Some(value_of(&p, w, prec)).filter(|v| v.is_finite())
                });
                let Some(value) = value else { continue };
                let d = verified_digits_mpfr(&Float::with_val(prec, &v.value - &*value), scale, cap);
                seen.push(format!("[{nl}/{nm}]"));
                agreement = Some(agreement.map_or(d, |a: f64| a.min(d)));
            }
            match agreement {
                None => v.refusal = Some("no neighbouring approximant exists to estimate its digits".into()),
                Some(d) if d < 1.0 => {
                    v.refusal = Some(format!(
                        "its neighbours {} agree with it to {} digits (< 1)",
                        seen.join(", "),
                        readable_f64((d * 10.0).floor() / 10.0)
                    ))
                }
                Some(d) => v.digits = d,
            }
        }
        if !v.value.is_finite() && v.refusal.is_none() {
            v.refusal = Some("the denominator vanishes at w".into());
        }
        if v.refusal.is_some() {
            v.digits = 0.0;
        }
        candidates.push(v);
    }
    // The most diagonal candidate not refused (the candidates are in that order). Choosing by the
    // estimate instead favours a candidate whose neighbours happen to agree: Kuznetsov's l after
    // the conformal map at lambda = 1.2 (tests/all/pade.rs) would get [5/7] with 11.8 true digits
    // instead of the diagonal [6/6] with 13.7.
    let best = candidates.iter().position(|c| c.refusal.is_none());
    Resummation { w: w.clone(), candidates, best }
}

/// [`resum`] of MPFR coefficients (each taken as the binary rational it is, [`float_to_q`]);
/// `None` when a coefficient is not finite.
pub fn resum_mpfr(coeffs: &[Float], w: &Float, scale: &Float, cap: f64, prec: u32) -> Option<Resummation> {
    let c: Option<Vec<Q>> = coeffs.iter().map(float_to_q).collect();
    Some(resum(&Series::from_coeffs(c?), w, scale, cap, prec))
}

/// The shape of the cut plane of a known singularity of the sum, for [`Conformal`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cut {
    /// Branch points at w = +-i R with cuts to +-i infinity (Kuznetsov's l/l_s: R = 2 pi, where
    /// exp(-w/2) = -1): w = R 2z/(1 - z^2), z = u/(1 + sqrt(1 + u^2)), u = w/R.
    Imaginary,
    /// A branch point at w = R with the cut [R, infinity) (the sinusoid's a/a0 = arcsin(sqrt w)/sqrt w:
    /// R = 1): w = R 4z/(1 + z)^2, z = (1 - sqrt(1 - u))/(1 + sqrt(1 - u)).
    Real,
}

/// A conformal map of the plane cut at a known singularity onto the unit disc |z| < 1, z(0) = 0:
/// the sum, analytic on the cut plane, becomes a series in z that converges on the whole disc, and
/// the point w moves to z(w), nearer the origin relative to the radius (Kuznetsov at lambda = 1.2:
/// w/(2 pi) = 0.32, z = 0.16). The series in z is then resummed by [`resum`] as the series in w
/// is (poles on the segment [0, z]).
#[derive(Debug, Clone, PartialEq)]
pub struct Conformal {
    /// The shape of the cut.
    pub cut: Cut,
    /// The distance R of the branch point(s) from the origin.
    pub radius: Float,
}

impl Conformal {
    /// z(w); `None` when w lies on the cut (or beyond the branch point of a real cut).
    pub(crate) fn z_of(&self, w: &Float) -> Option<Float> {
        let prec = w.prec().max(self.radius.prec());
        let u = Float::with_val(prec, w / &self.radius);
        match self.cut {
            Cut::Imaginary => {
                let root = Float::with_val(prec, Float::with_val(prec, u.clone().square() + 1u32).sqrt() + 1u32);
                Some(Float::with_val(prec, &u / &root))
            }
            Cut::Real => {
                if u >= 1u32 {
                    return None;
                }
                let r = Float::with_val(prec, Float::with_val(prec, 1u32 - u).sqrt());
                Some(Float::with_val(prec, Float::with_val(prec, 1u32 - &r) / Float::with_val(prec, 1u32 + &r)))
            }
        }
    }

    /// The coefficients in z of f(w(z)) from those of f in w (as many as given), at `prec` bits.
    pub fn compose(&self, cw: &[Float], prec: u32) -> Vec<Float> {
        let n = cw.len();
        // w(z)/R: 2z/(1 - z^2) = 2 (z + z^3 + ...); 4z/(1 + z)^2 = 4 sum (-1)^(k-1) k z^k.
        let u: Vec<Float> = (0..n)
            .map(|k| match (self.cut, k) {
                (_, 0) => Float::with_val(prec, 0),
                (Cut::Imaginary, k) => Float::with_val(prec, if k % 2 == 1 { 2 } else { 0 }),
                (Cut::Real, k) => Float::with_val(prec, if k % 2 == 1 { 4 * k as i64 } else { -4 * k as i64 }),
            })
            .map(|x| Float::with_val(prec, &x * &self.radius))
            .collect();
        let mut out = vec![Float::with_val(prec, 0); n];
        let mut power = vec![Float::with_val(prec, 0); n];
        power[0] = Float::with_val(prec, 1);
        for c in cw {
            for (o, p) in out.iter_mut().zip(&power) {
                *o += Float::with_val(prec, c * p);
            }
            let mut next = vec![Float::with_val(prec, 0); n];
            for (i, p) in power.iter().enumerate() {
                if p.is_zero() {
                    continue;
                }
                for j in 1..n - i {
                    next[i + j] += Float::with_val(prec, p * &u[j]);
                }
            }
            power = next;
        }
        out
    }
}

/// [`resum_mpfr`] after the conformal map: the series in z of f(w(z)) resummed at z(w) (the
/// [`Resummation`]'s point is z). `None` when w lies on the cut or a coefficient is not finite.
pub fn resum_conformal(
    cw: &[Float],
    map: &Conformal,
    w: &Float,
    scale: &Float,
    cap: f64,
    prec: u32,
) -> Option<Resummation> {
    let z = map.z_of(w)?;
    resum_mpfr(&map.compose(cw, prec), &z, scale, cap, prec)
}

/// The coefficients in w of a series in x: w = x^2 for an even series (its odd coefficients
/// vanish), else w = x. Returns the coefficients and whether w = x^2.
pub fn in_w<T: Clone>(coeffs: &[T], is_zero: impl Fn(&T) -> bool) -> (Vec<T>, bool) {
    let even = coeffs.iter().skip(1).step_by(2).all(&is_zero);
    if even {
        (coeffs.iter().step_by(2).cloned().collect(), true)
    } else {
        (coeffs.to_vec(), false)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Q {
        Q::new(n.into(), d.into())
    }
    const P: u32 = 200;
    fn f(x: f64) -> Float {
        Float::with_val(P, x)
    }

    #[test]
    fn binary_rationals_are_exact() {
        let x = Float::with_val(P, 1) / 3;
        let r = float_to_q(&x).unwrap();
        assert_eq!(to_float(&r, P), x);
        assert_eq!(float_to_q(&f(-0.375)), Some(q(-3, 8)));
        assert_eq!(float_to_q(&f(f64::NAN)), None);
    }

    #[test]
    fn roots_of_a_known_polynomial() {
        // (1 - w/2)(1 + w^2/9) = 1 - w/2 + w^2/9 - w^3/18: zeros 2, 3i, -3i.
        let r = polynomial_roots(&[q(1, 1), q(-1, 2), q(1, 9), q(-1, 18)]);
        assert_eq!(r.len(), 3);
        assert!((r[0].real().to_f64() - 2.0).abs() < 1e-30 && r[0].imag().to_f64().abs() < 1e-30, "{r:?}");
        for z in &r[1..] {
            assert!(z.real().to_f64().abs() < 1e-30 && (z.imag().to_f64().abs() - 3.0).abs() < 1e-30, "{z:?}");
        }
    }

    #[test]
    #[ignore = "long tier: 10 s alone in the test profile (opt-level 2) on a loaded 2-core machine (scripts/test --long)"]
    fn log_resummed_beyond_its_radius_with_honest_digits() {
        // log(1 + w)/w, radius 1, at w = 2 (beyond it): the partial sums diverge, the Pade values
        // converge; the estimate never exceeds the true digits.
        let n = 21;
        let lg = Series::<Q>::var(n + 1).add(&Series::one(n + 1)).log().unwrap();
        let g = Series::from_coeffs(lg.coeffs()[1..].to_vec());
        let w = f(2.0);
        let truth = Float::with_val(P, 3).ln() / 2;
        let r = resum(&g, &w, &truth, 50.0, P);
        let best = r.best().unwrap();
        let true_digits = verified_digits_mpfr(&Float::with_val(P, &best.value - &truth), &truth, 50.0);
        assert!(best.digits >= 8.0, "{best:?}");
        assert!(best.digits <= true_digits + 0.5, "estimated {} true {true_digits}", best.digits);
        // Stieltjes function: every pole on the cut (-inf, -1], none refused.
        for p in &best.poles {
            assert!(p.real().to_f64() < -1.0 && p.imag().to_f64().abs() < 1e-20, "{p:?}");
        }
        let plain = crate::numerics::evaluate::series_q_mpfr(&g, &w, P);
        assert!(verified_digits_mpfr(&Float::with_val(P, &plain - &truth), &truth, 50.0) < 1.0);
    }

    #[test]
    fn a_spurious_pole_refuses_the_approximant() {
        // f = 1 + w/100 + w^2, a polynomial: [1/1] = (1 + (1/100 - 100) w)/(1 - 100 w) has its pole
        // at w = 1/100, on the segment [0, 1/2]: refused.
        let s = Series::<Q>::from_coeffs(vec![q(1, 1), q(1, 100), q(1, 1)]);
        let r = resum(&s, &f(0.5), &f(1.0), 30.0, P);
        let c = r.candidates.iter().find(|c| (c.l, c.m) == (1, 1)).unwrap();
        assert!(c.refusal.as_ref().unwrap().contains("pole at w = 1.000000e-2"), "{:?}", c.refusal);
        assert!(r.best().is_none_or(|b| (b.l, b.m) != (1, 1)));
        // The genuine pole of 1/(1 - 2w) refuses its exact approximant at w = 0.8 (past the pole).
        let g = Series::<Q>::one(8).sub(&Series::var(8).scale(&q(2, 1))).inv().unwrap();
        let r = resum(&g, &f(0.8), &f(1.0), 30.0, P);
        assert!(r.best.is_none(), "{:?}", r.candidates);
        assert!(r.refusals().iter().all(|x| x.contains("pole at w = 5.000000e-1")), "{:?}", r.refusals());
        // ... and not at w = 0.4 (inside its disc), where it is exact.
        let r = resum(&g, &f(0.4), &f(1.0), 30.0, P);
        let b = r.best().unwrap();
        assert!((b.value.to_f64() - 5.0).abs() < 1e-12 && b.digits == 30.0, "{b:?}");
    }

    #[test]
    fn conformal_maps_compose_and_invert() {
        use rug::ops::Pow;
        // f(w) = 1/(1 - w/3) under the real cut of radius 1: f(w(z)) = (1 + z)^2/((1 + z)^2 - 4z/3);
        // the composed series summed at z(w) gives f(w).
        let map = Conformal { cut: Cut::Real, radius: f(1.0) };
        let cw: Vec<Float> = (0..30).map(|k| Float::with_val(P, 3).pow(-(k as i32))).collect();
        let dz = map.compose(&cw, P);
        let w = f(0.5);
        let z = map.z_of(&w).unwrap();
        let sum = dz.iter().rev().fold(f(0.0), |acc, c| acc * &z + c);
        assert!((sum.to_f64() - 1.2).abs() < 1e-10, "{sum}");
        assert!(map.z_of(&f(1.5)).is_none());
        // The imaginary cuts: w(z) = 2R z/(1 - z^2) at z(w) is w again.
        let map = Conformal { cut: Cut::Imaginary, radius: f(2.0) };
        let z = map.z_of(&f(3.0)).unwrap().to_f64();
        assert!((4.0 * z / (1.0 - z * z) - 3.0).abs() < 1e-14, "{z}");
    }

    #[test]
    fn even_series_are_taken_in_x_squared() {
        let (w, even) = in_w(&[1, 0, 2, 0, 3], |x| *x == 0);
        assert_eq!((w, even), (vec![1, 2, 3], true));
        let (w, even) = in_w(&[1, 5, 2], |x| *x == 0);
        assert_eq!((w, even), (vec![1, 5, 2], false));
    }
}
