//! The frictionless load of an even punch profile in closed form (docs/theory.md section 9), computed
//! independently of the solvers: by its own evaluation of g' from the exact profile and its own
//! quadrature, so that a solver's load-size curve can be checked against it (report section
//! "Punch shapes", tests/all/profiles.rs, tests/all/adhesion_profiles.rs).
//!
//! Periodic row (period L), half-width a, lambda = pi a/L < pi/2:
//!     P2 = (E*/2) int_{-a}^{a} g'(x) sin(pi x/L) dx / sqrt(sin^2(pi a/L) - sin^2(pi x/L)).
//! With chi = pi x/L and sin chi = sin(lambda) sin(phi) the square-root singularities at the ends
//! disappear: dx / sqrt(...) = (L/pi) dphi / cos chi, so
//!     P2 = (E*/2) (L/pi) int_{-pi/2}^{pi/2} g'(x(phi)) tan(chi(phi)) dphi,
//! whose integrand f(phi) (g' odd for an even g, tan odd) is even and pi-periodic: the integral is
//! (1/2) int_0^pi f, and the trapezoid sum (pi/n) sum_{j<n} f(pi j/n) converges geometrically
//! (the integrand is analytic in a strip; Trefethen & Weideman, SIAM Review 56 (2014), thm 3.2):
//!     P2 ~ E* L/(2n) sum_{j<n} f(pi j/n).
//! Single punch (L = infinity): x = a sin(phi), f(phi) = g'(a sin phi) a sin phi,
//!     P2 ~ (E*/2) (pi/n) sum_{j<n} f(pi j/n)   (Hertz: g' = 2 k x gives pi E* k a^2/2).
//! The single-punch power law of the same section, g = A x^(2n):
//!     P2 = n pi E* A a^(2n) (2n-1)!!/(2n)!!,
//! is a separate, exact formula ([`single_punch_power_law_mpfr`]), summed over the even terms of a
//! polynomial (the load is linear in g).

use crate::error::Error;
use crate::model::{Exact, ModelError, PunchShape};
use crate::numerics::exact::to_float;
use num_traits::Zero;
use rug::float::Constant;
use rug::ops::Pow;
use rug::Float;

/// g' of an even profile at working precision, from the exact profile (not from the solvers'
/// parameters): the parabola g' = 2 k x, an even polynomial g' = sum_j j c_j x^(j-1), the
/// circle g' = x / sqrt(R^2 - x^2), the sinusoid g' = (2 pi D/L) sin(2 pi x/L).
#[derive(Debug, Clone)]
pub enum EvenSlope {
    /// g' = sum_i s_i x^i (s_i = (i+1) c_(i+1); only odd i are non-zero).
    Polynomial(Vec<Float>),
    /// g' = x / sqrt(R^2 - x^2); the radius R.
    Circular(Float),
    /// g' = (2 pi D/L) sin(2 pi x/L): amplitude D and period L.
    Sinusoidal(Float, Float),
}

impl EvenSlope {
    /// The slope of `shape` at `prec` bits. Errors (naming the parameter): a polynomial with a
    /// non-zero odd coefficient (the closed form needs an even g: the contact is then symmetric);
    /// a sinusoid without a period.
    pub fn new(shape: &PunchShape, period: Option<&Exact>, prec: u32) -> Result<Self, Error> {
        Ok(match shape {
            PunchShape::Parabolic { k } => {
                EvenSlope::Polynomial(vec![Float::with_val(prec, 0), Float::with_val(prec, to_float(k, prec) * 2u32)])
            }
            PunchShape::Polynomial { coefficients } => {
                if let Some((j, _)) = coefficients.iter().enumerate().find(|(j, c)| j % 2 == 1 && !c.is_zero()) {
                    let (name, value) = shape.parameters().remove(0);
                    return Err(Error::Input(ModelError::new(
                        name,
                        value,
                        format!(
                            "the closed-form load of docs/theory.md section 9 needs an even profile (coefficient of x^{j} \
                             must be 0)"
                        ),
                    )));
                }
                EvenSlope::Polynomial(
                    coefficients.iter().enumerate().skip(1).map(|(j, c)| to_float(c, prec) * j as u32).collect(),
                )
            }
            PunchShape::Circular { radius } => EvenSlope::Circular(to_float(radius, prec)),
            PunchShape::Sinusoidal { amplitude } => match period {
                Some(l) => EvenSlope::Sinusoidal(to_float(amplitude, prec), to_float(l, prec)),
                None => {
                    return Err(Error::Input(ModelError::new(
                        "period",
                        "inf",
                        "a finite period (the sinusoidal profile is defined by it)",
                    )))
                }
            },
        })
    }

    /// g'(x) at the precision of `x`.
    pub fn at(&self, x: &Float) -> Float {
        let prec = x.prec();
        match self {
            EvenSlope::Polynomial(s) => {
                let mut acc = Float::with_val(prec, 0);
                for c in s.iter().rev() {
                    acc *= x;
                    acc += c;
                }
                acc
            }
            EvenSlope::Circular(r) => {
                let d = Float::with_val(prec, r * r) - Float::with_val(prec, x * x);
                Float::with_val(prec, x / d.sqrt())
            }
            EvenSlope::Sinusoidal(d, l) => {
                let w = Float::with_val(prec, Constant::Pi) * 2u32 / l;
                Float::with_val(prec, &w * x).sin() * d * w
            }
        }
    }
}

/// A quadrature value with its error estimate.
#[derive(Debug, Clone)]
pub struct LoadEstimate {
    /// P2 (units of the contact modulus given).
    pub value: Float,
    /// |S_n - S_{n/2}|, the difference of the last two trapezoid sums: the error of the coarser
    /// one, an upper estimate of the finer one's under geometric convergence (a heuristic: it
    /// assumes the convergence has set in, which two sums agreeing to the target make likely).
    pub abs_err: Float,
    /// Points of the final trapezoid sum.
    pub points: u32,
}

impl LoadEstimate {
    /// Digits of the estimate relative to its value (the accuracy rule, capped at `cap`).
    pub fn digits(&self, cap: f64) -> f64 {
        crate::numerics::accuracy::verified_digits_mpfr(&self.abs_err, &self.value, cap)
    }
}

/// Largest trapezoid sum tried before giving up.
pub const MAX_POINTS: u32 = 1 << 16;

/// docs/theory.md section 9's frictionless load P2 at half-width `a` of the even profile `slope`,
/// period `period` (`None`: single punch), contact modulus `e_star`, by the trapezoid sums of the
/// module doc, doubled from 16 points until two agree to 2^-(prec - 16) relative (round-off of a
/// sum of up to [`MAX_POINTS`] terms stays below it). Errors: lambda = pi a/L >= pi/2 or a <= 0
/// (parameter `half_width`), no convergence by [`MAX_POINTS`].
pub fn frictionless_load_mpfr(
    slope: &EvenSlope,
    e_star: &Float,
    a: &Float,
    period: Option<&Float>,
    prec: u32,
) -> Result<LoadEstimate, Error> {
    let pi = Float::with_val(prec, Constant::Pi);
    if a.is_sign_negative() || a.is_zero() {
        return Err(Error::input("half_width", crate::numerics::accuracy::readable_mpfr(a), "must be > 0"));
    }
    let sin_lam = match period {
        Some(l) => {
            let lam = Float::with_val(prec, a * &pi) / l;
            if lam >= Float::with_val(prec, &pi / 2u32) {
                return Err(Error::input(
                    "half_width",
                    crate::numerics::accuracy::readable_mpfr(a),
                    "pi a/L < pi/2 (the contact inside the cell)",
                ));
            }
            Some(lam.sin())
        }
        None => None,
    };
    let integrand = |phi: &Float| -> Float {
        let sp = Float::with_val(prec, phi.sin_ref());
        match (period, &sin_lam) {
            (Some(l), Some(s)) => {
                let chi = Float::with_val(prec, &sp * s).asin();
                let x = Float::with_val(prec, &chi * l) / &pi;
                slope.at(&x) * chi.tan()
            }
            _ => {
                let x = Float::with_val(prec, a * &sp);
                slope.at(&x) * x
            }
        }
    };
    let sum = |n: u32| -> Float {
        let mut acc = Float::with_val(prec, 0);
        for j in 0..n {
            acc += integrand(&(Float::with_val(prec, &pi * j) / n));
        }
        match period {
            // E* L/(2n) sum
            Some(l) => acc * e_star * l / (2 * n),
            // (E*/2) (pi/n) sum
            None => acc * e_star * &pi / (2 * n),
        }
    };
    let tol = Float::with_val(prec, Float::i_exp(1, -(prec as i32 - 16)));
    let mut n = 16u32;
    let mut prev = sum(n);
    while n < MAX_POINTS {
        n *= 2;
        let next = sum(n);
        let diff = Float::with_val(prec, &next - &prev).abs();
        let done = diff <= Float::with_val(prec, next.abs_ref()) * &tol;
        prev = next;
        if done {
            return Ok(LoadEstimate { value: prev, abs_err: diff, points: n });
        }
    }
    Err(Error::NoConvergence {
        what: format!(
            "the closed-form load of docs/theory.md section 9 at half-width {}: trapezoid sums up to {MAX_POINTS} \
             points do not agree to {prec} bits",
            crate::numerics::accuracy::readable_mpfr(a)
        ),
    })
}

/// The single-punch power law of docs/theory.md section 9 summed over the even terms of a polynomial
/// g = sum_j c_j x^j (the load is linear in g): P2 = E* sum_n n pi c_2n a^(2n) (2n-1)!!/(2n)!!
/// (n = 1: Hertz, pi E* c_2 a^2/2). Odd terms are ignored (they carry no load of a centred
/// contact; the caller states whether g is even).
pub fn single_punch_power_law_mpfr(coefficients: &[Exact], e_star: &Float, a: &Float, prec: u32) -> Float {
    let pi = Float::with_val(prec, Constant::Pi);
    let mut total = Float::with_val(prec, 0);
    let mut ratio = Float::with_val(prec, 1);
    for n in 1..=(coefficients.len().saturating_sub(1) / 2) {
        let n32 = n as u32;
        ratio *= 2 * n32 - 1;
        ratio /= 2 * n32;
        let pow = Float::with_val(prec, a.pow(2 * n32));
        total += to_float(&coefficients[2 * n], prec) * pow * &ratio * n32;
    }
    total * pi * e_star
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(s: &str) -> Exact {
        exact_series::parse_rational(s).unwrap()
    }

    fn poly(c: &[&str]) -> PunchShape {
        PunchShape::polynomial(c.iter().map(|s| q(s)).collect()).unwrap()
    }

    fn rel(a: &Float, b: &Float) -> f64 {
        Float::with_val(a.prec(), Float::with_val(a.prec(), a - b) / b).abs().to_f64()
    }

    /// Kuznetsov [2.15] (docs/theory.md section 6) for the parabola g = k x^2:
    /// P2 = (E* k L^2/pi) ln sec(pi a/L), an independent closed form; at lambda = 0.2 .. 1.4.
    #[test]
    fn parabola_gives_kuznetsov() {
        let prec = 200;
        let slope = EvenSlope::new(&PunchShape::parabolic(q("3/2")).unwrap(), None, prec).unwrap();
        let (e, l) = (Float::with_val(prec, 2), Float::with_val(prec, 3));
        for lam in [0.2, 0.7, 1.1, 1.4] {
            let a = Float::with_val(prec, lam) * &l / Float::with_val(prec, Constant::Pi);
            let got = frictionless_load_mpfr(&slope, &e, &a, Some(&l), prec).unwrap();
            let pi = Float::with_val(prec, Constant::Pi);
            let want = Float::with_val(prec, 1.5) * &e * Float::with_val(prec, &l * &l) / &pi
                * Float::with_val(prec, lam).cos().recip().ln();
            assert!(rel(&got.value, &want) < 1e-55, "lambda {lam}: {} vs {}", got.value, want);
            assert!(got.digits(60.0) > 50.0, "{}", got.abs_err);
        }
    }

    /// Westergaard [2.17]: the sinusoid g = D (1 - cos(2 pi x/L)) carries P2 = pi E* D sin^2(pi a/L).
    #[test]
    fn sinusoid_gives_westergaard() {
        let prec = 200;
        let shape = PunchShape::sinusoidal(q("1/100")).unwrap();
        let slope = EvenSlope::new(&shape, Some(&q("2")), prec).unwrap();
        let (e, l) = (Float::with_val(prec, 1), Float::with_val(prec, 2));
        for lam in [0.3, 1.0, 1.4] {
            let a = Float::with_val(prec, lam) * &l / Float::with_val(prec, Constant::Pi);
            let got = frictionless_load_mpfr(&slope, &e, &a, Some(&l), prec).unwrap();
            let want = Float::with_val(prec, Constant::Pi) / 100u32 * Float::with_val(prec, lam).sin().square();
            assert!(rel(&got.value, &want) < 1e-55, "lambda {lam}: {} vs {}", got.value, want);
        }
    }

    /// Single punch: the quadrature and the power law agree for g = x^2/4 + x^4/2 + 3 x^6
    /// (the quadrature is exact for a trigonometric polynomial once n exceeds its degree).
    #[test]
    fn single_punch_quadrature_matches_the_power_law() {
        let prec = 160;
        let c = ["0", "0", "1/4", "0", "1/2", "0", "3"];
        let slope = EvenSlope::new(&poly(&c), None, prec).unwrap();
        let e = Float::with_val(prec, 7) / 10u32;
        let a = Float::with_val(prec, 3) / 10u32;
        let got = frictionless_load_mpfr(&slope, &e, &a, None, prec).unwrap();
        let coeffs: Vec<Exact> = c.iter().map(|s| q(s)).collect();
        let want = single_punch_power_law_mpfr(&coeffs, &e, &a, prec);
        assert!(rel(&got.value, &want) < 1e-45, "{} vs {}", got.value, want);
        // By hand: pi E* (c2 a^2/2 + (3/4) c4 a^4 + (15/16) c6 a^6).
        let a2 = Float::with_val(prec, &a * &a);
        let hand = Float::with_val(prec, Constant::Pi)
            * &e
            * (Float::with_val(prec, &a2 / 8u32)
                + Float::with_val(prec, (&a2).pow(2u32)) * 3u32 / 8u32
                + Float::with_val(prec, (&a2).pow(3u32)) * 45u32 / 16u32);
        assert!(rel(&want, &hand) < 1e-45, "{want} vs {hand}");
    }

    /// The circle against its own limit: a periodic row with a large period tends to the single
    /// punch (difference O(lambda^2)), and the single circular punch tends to Hertz with
    /// k = 1/(2R) as a/R -> 0 (relative difference O(a^2/R^2)).
    #[test]
    fn circle_limits() {
        let prec = 128;
        let slope = EvenSlope::new(&PunchShape::circular(q("1")).unwrap(), None, prec).unwrap();
        let e = Float::with_val(prec, 1);
        let a = Float::with_val(prec, 1) / 100u32;
        let single = frictionless_load_mpfr(&slope, &e, &a, None, prec).unwrap().value;
        let hertz = Float::with_val(prec, Constant::Pi) * Float::with_val(prec, &a * &a) / 4u32;
        let d = rel(&single, &hertz);
        assert!(d > 1e-6 && d < 1e-4, "{d}");
        let big_l = Float::with_val(prec, 1000);
        let row = frictionless_load_mpfr(&slope, &e, &a, Some(&big_l), prec).unwrap().value;
        assert!(rel(&row, &single) < 1e-9, "{row} vs {single}");
    }

    #[test]
    fn odd_profiles_and_bad_sizes_are_refused_naming_the_parameter() {
        let e = EvenSlope::new(&poly(&["0", "1/50", "1", "1/2"]), None, 64).unwrap_err();
        assert!(e.to_string().contains("coefficients") && e.to_string().contains("x^1"), "{e}");
        let e = EvenSlope::new(&PunchShape::sinusoidal(q("1")).unwrap(), None, 64).unwrap_err();
        assert!(e.to_string().contains("period"), "{e}");
        let slope = EvenSlope::new(&poly(&["0", "0", "1"]), None, 64).unwrap();
        let one = Float::with_val(64, 1);
        let e = frictionless_load_mpfr(&slope, &one, &Float::with_val(64, 0.6), Some(&one), 64).unwrap_err();
        assert!(e.to_string().contains("half_width"), "{e}");
        let e = frictionless_load_mpfr(&slope, &one, &Float::with_val(64, -0.1), None, 64).unwrap_err();
        assert!(e.to_string().contains("half_width"), "{e}");
    }
}
