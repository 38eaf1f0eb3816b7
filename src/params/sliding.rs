//! Derived parameters of Problem 1, computed once from the exact problem (docs/theory.md sections 1, 3,
//! 5, 8): kappa, theta, beta, the osculating curvature k, the Hertz half-width a0 and the
//! single-punch half-length l_s, in `f64` ([`SlidingParamsF64`]) and in MPFR
//! ([`SlidingParamsMpfr`]). Every solver, series evaluation, report section and renderer reads
//! them from here; each formula below is written once per number type.
//!
//! Formulas:
//! - kappa = E* cW/2 - beta mu [2.8] (exact, [`SlidingProblem::kappa`]); theta = arctan(kappa)/pi;
//! - beta = (1 - 2 nu)/(2 (1 - nu)) (exact, `Material::beta`);
//! - curvature scale k: osculating g''(0)/2 for g = k x^2 (k), g = D (1 - cos(2 pi x/L)) [2.16]
//!   (2 pi^2 D/L^2) and the circle (1/(2R)); for a polynomial the mean curvature over its
//!   single-punch contact (see [`SlidingParamsMpfr::k`]);
//! - a0 = sqrt(2 P2/(pi E* k)) (Hertz half-width), l_s = a0/sqrt(1 - 4 theta^2) [3.10];
//! - T = beta tau0/(E* k l_s) [3.10].
//!
//! Units: the MPFR parameters also carry the problem in units of E* (E* -> 1, loads and stresses
//! / E*, tau0 / E*, cW E*; kappa, theta, T and lengths unchanged), so that moduli and loads beyond
//! the `f64` range reach the solvers' `f64` stages; [`SlidingParamsMpfr::unit`] converts back.

pub use super::profile::{
    check_profile_on_contact, polynomial_derivative, row_height_f64, row_rise_f64, ShapeF64, CIRCLE_SIZE_CAP,
    MAX_CONTACT_SLOPE,
};
use crate::error::Error;
use crate::model::OnPunchRow;
use crate::model::{Convention, Exact, ModelError, Period, PunchShape, SlidingLoad, SlidingProblem};
use crate::numerics::exact::{to_f64, to_float, SmallRational};
use rug::float::Constant;
use rug::Float;
use std::f64::consts::PI;

/// Smallest allowed distance of |theta| from 1/2: the end exponents 1/2 -+ theta of the pressure
/// reach 0 and the Gauss–Jacobi rules of 1/omega (exponents theta - 1/2, -theta - 1/2 > -1) need
/// ever more nodes (docs/theory.md section 7). |theta| <= 1/2 - 1e-6 means |kappa| <= about 3e5.
pub const THETA_MARGIN: f64 = 1e-6;

/// theta = arctan(kappa)/pi (docs/theory.md section 3), `f64`.
pub(crate) fn theta_f64(kappa: f64) -> f64 {
    kappa.atan() / PI
}

/// theta = arctan(kappa)/pi (docs/theory.md section 3), MPFR at the precision of `kappa`.
pub(crate) fn theta_mpfr(kappa: &Float) -> Float {
    let prec = kappa.prec();
    Float::with_val(prec, kappa.atan_ref()) / Float::with_val(prec, Constant::Pi)
}

/// Hertz half-width a0 = sqrt(2 P2/(pi E* k)) (docs/theory.md section 6), `f64`.
pub fn hertz_half_width_f64(p2: f64, e_star: f64, k: f64) -> f64 {
    (2.0 * p2 / (PI * e_star * k)).sqrt()
}

/// Hertz half-width a0 = sqrt(2 P2/(pi E* k)) (docs/theory.md section 6), MPFR.
pub(crate) fn hertz_half_width_mpfr(p2: &Float, e_star: &Float, k: &Float) -> Float {
    let prec = p2.prec();
    let pi = Float::with_val(prec, Constant::Pi);
    let den = Float::with_val(prec, &pi * e_star) * k;
    Float::with_val(prec, Float::with_val(prec, p2 * 2u32) / den).sqrt()
}

/// Single-punch half-length l_s = a0/sqrt(1 - 4 theta^2) [3.10], `f64`.
pub fn single_punch_half_length_f64(a0: f64, theta: f64) -> f64 {
    a0 / (1.0 - 4.0 * theta * theta).sqrt()
}

/// Single-punch half-length l_s = a0/sqrt(1 - 4 theta^2) [3.10], MPFR.
pub(crate) fn single_punch_half_length_mpfr(a0: &Float, theta: &Float) -> Float {
    let prec = a0.prec();
    let t2 = Float::with_val(prec, theta * theta) * 4u32;
    Float::with_val(prec, a0 / Float::with_val(prec, 1u32 - t2).sqrt())
}

/// Osculating curvature k = g''(0)/2 (docs/theory.md section 9), `f64`: k for g = k x^2,
/// 2 pi^2 D/L^2 for the sinusoid [2.16], c_2 for a polynomial, 1/(2 R) for the circle.
pub(crate) fn osculating_k_f64(shape: &ShapeF64, period: Option<f64>) -> f64 {
    match (shape, period) {
        (ShapeF64::Parabolic { k }, _) => *k,
        (ShapeF64::Sinusoidal { d }, Some(l)) => 2.0 * PI * PI * d / (l * l),
        (ShapeF64::Sinusoidal { .. }, None) => f64::NAN, // refused by the model: a sinusoid has a period
        (ShapeF64::Polynomial { curvature, .. }, _) => curvature.first().copied().unwrap_or(0.0) / 2.0,
        (ShapeF64::Circular { r }, _) => 0.5 / r,
    }
}

/// Osculating curvature k = g''(0)/2 (docs/theory.md section 9), MPFR: k for g = k x^2,
/// 2 pi^2 D/L^2 for the sinusoid [2.16], c_2 for a polynomial, 1/(2 R) for the circle.
pub(crate) fn osculating_k_mpfr(shape: &ShapeMpfr, period: Option<&Float>) -> Float {
    match (shape, period) {
        (ShapeMpfr::Parabolic { k }, _) => k.clone(),
        (ShapeMpfr::Sinusoidal { d }, Some(l)) => {
            let prec = d.prec();
            let pi = Float::with_val(prec, Constant::Pi);
            Float::with_val(prec, &pi * &pi) * d * 2u32 / Float::with_val(prec, l * l)
        }
        (ShapeMpfr::Sinusoidal { d }, None) => Float::with_val(d.prec(), rug::float::Special::Nan),
        (ShapeMpfr::Polynomial { slope, curvature }, _) => match curvature.first() {
            Some(c) => Float::with_val(c.prec(), c / 2u32),
            None => Float::with_val(slope[0].prec(), 0),
        },
        (ShapeMpfr::Circular { r }, _) => Float::with_val(r.prec(), 0.5f64 / r),
    }
}

/// P2/E* of a single punch (L = infinity) without friction for the EVEN part of the polynomial
/// g with slope coefficients `slope` (g' = sum_j slope\[j\] x^j), at half-width a: the power law
/// of docs/theory.md section 9, P2 = n pi E* A a^(2n) (2n-1)!!/(2n)!! for g = A x^(2n), summed over
/// the even terms (A = c_2n = slope[2n-1]/(2n)).
pub fn even_part_single_punch_load_mpfr(slope: &[Float], a: &Float) -> Float {
    let prec = a.prec();
    let mut total = Float::with_val(prec, 0);
    // ratio = (2n-1)!!/(2n)!!, a^(2n)
    let mut ratio = Float::with_val(prec, 1);
    let a2 = Float::with_val(prec, a.square_ref());
    let mut pow = Float::with_val(prec, 1);
    let mut n = 1u32;
    while ((2 * n - 1) as usize) < slope.len() {
        ratio *= 2 * n - 1;
        ratio /= 2 * n;
        pow *= &a2;
        // n pi c_2n = pi slope[2n-1]/2
        total += Float::with_val(prec, &slope[(2 * n - 1) as usize] * &pow) * &ratio / 2u32;
        n += 1;
    }
    total * Float::with_val(prec, Constant::Pi)
}

/// The curvature scale of a polynomial punch (the `k` of [`SlidingParamsMpfr`], see there): the
/// mean curvature (g'(l0) - g'(-l0))/(4 l0) over the centred contact of half-width l0, which is
/// the given half-length, or the single-punch frictionless half-width of the even part of g at
/// the given load P2/E* ([`even_part_single_punch_load_mpfr`], solved by bisection). Errors when
/// the even part of g carries no load (g is then not convex around 0).
pub fn polynomial_curvature_scale_mpfr(slope: &[Float], target: &TargetMpfr, prec: u32) -> Result<Float, Error> {
    let l0 = match target {
        TargetMpfr::HalfLength(l) => l.clone(),
        TargetMpfr::NormalLoad(p2) => {
            let f = |a: &Float| Float::with_val(prec, even_part_single_punch_load_mpfr(slope, a) - p2);
            let refuse = || {
                Error::Input(ModelError::new(
                    "coefficients",
                    "(polynomial)",
                    "the even part of g must carry the load (g(x) + g(-x) > 0 somewhere: a convex, curved punch)",
                ))
            };
            // Bracket [x, 2x] by doubling or halving from 1, then bisect to the precision.
            let mut x = Float::with_val(prec, 1);
            let up = f(&x) < 0u32;
            let mut steps = 0;
            loop {
                let next = if up { Float::with_val(prec, &x * 2u32) } else { Float::with_val(prec, &x / 2u32) };
                let fx = f(&next);
                steps += 1;
                if steps > 100_000 || !fx.is_finite() {
                    return Err(refuse());
                }
                let crossed = if up { fx >= 0u32 } else { fx < 0u32 };
                x = next;
                if crossed {
                    break;
                }
            }
            let (mut lo, mut hi) =
                if up { (Float::with_val(prec, &x / 2u32), x) } else { (x.clone(), Float::with_val(prec, &x * 2u32)) };
            for _ in 0..prec + 4 {
                let mid = Float::with_val(prec, &lo + &hi) / 2u32;
                if f(&mid) < 0u32 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            Float::with_val(prec, &lo + &hi) / 2u32
        }
    };
    let eval = |x: &Float| {
        let mut acc = Float::with_val(prec, 0);
        for c in slope.iter().rev() {
            acc *= x;
            acc += c;
        }
        acc
    };
    let minus = Float::with_val(prec, -&l0);
    let k = Float::with_val(prec, eval(&l0) - eval(&minus)) / Float::with_val(prec, &l0 * 4u32);
    if !(k.is_finite() && k > 0u32) {
        return Err(Error::Input(ModelError::new(
            "coefficients",
            "(polynomial)",
            format!(
                "g must be convex: its mean curvature over (-{0}, {0}) is {1}",
                crate::numerics::accuracy::readable_mpfr(&l0),
                crate::numerics::accuracy::readable_mpfr(&k)
            ),
        )));
    }
    Ok(k)
}

/// Punch shape in MPFR.
#[derive(Debug, Clone, PartialEq)]
pub enum ShapeMpfr {
    /// g = k x^2.
    Parabolic {
        /// k.
        k: Float,
    },
    /// g = D (1 - cos(2 pi x/L)) [2.16].
    Sinusoidal {
        /// D.
        d: Float,
    },
    /// g = sum_j c_j x^j (docs/theory.md section 9), by the coefficients of its derivatives, each
    /// formed exactly and rounded once (trailing zeros dropped).
    Polynomial {
        /// g' = sum_j slope\[j\] x^j, slope\[j\] = (j + 1) c_(j+1).
        slope: Vec<Float>,
        /// g'' = sum_j curvature\[j\] x^j, curvature\[j\] = (j + 2)(j + 1) c_(j+2).
        curvature: Vec<Float>,
    },
    /// g = R - sqrt(R^2 - x^2) (docs/theory.md section 9).
    Circular {
        /// R.
        r: Float,
    },
}

impl ShapeMpfr {
    /// The shape rounded to f64 (for checks evaluated in f64).
    pub fn to_f64(&self) -> ShapeF64 {
        let v = |c: &[Float]| c.iter().map(Float::to_f64).collect::<Vec<_>>();
        match self {
            ShapeMpfr::Parabolic { k } => ShapeF64::Parabolic { k: k.to_f64() },
            ShapeMpfr::Sinusoidal { d } => ShapeF64::Sinusoidal { d: d.to_f64() },
            ShapeMpfr::Polynomial { slope, curvature } => {
                ShapeF64::Polynomial { slope: v(slope), curvature: v(curvature) }
            }
            ShapeMpfr::Circular { r } => ShapeF64::Circular { r: r.to_f64() },
        }
    }
}

/// What fixes the contact, in `f64`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TargetF64 {
    /// Given P2.
    NormalLoad(f64),
    /// Given l.
    HalfLength(f64),
}

/// Problem 1 in `f64`: every input rounded once from its exact value, and the derived numbers.
#[derive(Debug, Clone, PartialEq)]
pub struct SlidingParamsF64 {
    /// E*.
    pub e_star: f64,
    /// beta (rounded once from its exact value).
    pub beta: f64,
    /// mu.
    pub mu: f64,
    /// tau0.
    pub tau0: f64,
    /// cW.
    pub wear: f64,
    /// V, if given.
    pub speed: Option<f64>,
    /// kappa (rounded once from its exact value).
    pub kappa: f64,
    /// theta = arctan(kappa)/pi.
    pub theta: f64,
    /// Period L (None: single punch).
    pub period: Option<f64>,
    /// Shape.
    pub shape: ShapeF64,
    /// Curvature scale k ([`SlidingParamsMpfr::k`]).
    pub k: f64,
    /// Load or size.
    pub target: TargetF64,
    /// Surface convention (docs/theory.md section 8).
    pub convention: Convention,
}

fn f64_of(q: &Exact, parameter: &str, allow_zero: bool) -> Result<f64, Error> {
    match to_f64(q) {
        Some(v) if v.is_finite() && (allow_zero || v != 0.0) => Ok(v),
        _ => Err(Error::Input(ModelError::new(
            parameter,
            crate::model::readable(q),
            "must be representable in f64 (about 1e-308 to 1e308 in magnitude) for the f64 method; the mpfr method takes any value",
        ))),
    }
}

/// The theta margin check, shared by both number types.
fn check_theta(theta_abs: f64, theta_text: String, problem: &SlidingProblem) -> Result<(), Error> {
    if !(0.5 - theta_abs >= THETA_MARGIN) {
        return Err(Error::Input(ModelError::new(
            "theta = arctan(kappa)/pi",
            format!("{theta_text} (kappa = E* cW/2 - beta mu = {})", crate::model::readable(&problem.kappa())),
            format!("|theta| must be <= 1/2 - {THETA_MARGIN:e}: friction or wear too large for the quadrature"),
        )));
    }
    Ok(())
}

/// beta = (1 - 2 nu)/(2 (1 - nu)) and kappa = E* cW/2 - beta mu rounded once to f64 from their
/// exact values ([`crate::model::Material::beta`], [`SlidingProblem::kappa`]), computed in i128
/// rationals ([`SmallRational`]) when the inputs' parts are small enough (every shipped scene):
/// the same exact values, so the same f64, at a tenth of the big-rational cost. `None` (an
/// overflow, or a value outside f64) leaves it to the big-rational path and its errors.
fn small_beta_kappa(problem: &SlidingProblem) -> Option<(f64, f64)> {
    let m = problem.material();
    let (one, two) = (SmallRational::integer(1), SmallRational::integer(2));
    let nu = SmallRational::of(m.poisson_ratio())?;
    let beta = one.sub(two.mul(nu)?)?.div(two.mul(one.sub(nu)?)?)?;
    let e_star = SmallRational::of(m.contact_modulus())?;
    let kappa = e_star
        .mul(SmallRational::of(problem.wear())?)?
        .div(two)?
        .sub(beta.mul(SmallRational::of(problem.friction())?)?)?;
    Some((beta.to_f64()?, kappa.to_f64()?))
}

impl SlidingParamsF64 {
    /// Rounds the exact inputs once to `f64` and derives kappa, theta and k. Errors when an input
    /// is outside the `f64` range or |theta| is within [`THETA_MARGIN`] of 1/2.
    pub fn new(problem: &SlidingProblem) -> Result<Self, Error> {
        let m = problem.material();
        let e_star = f64_of(m.contact_modulus(), "contact_modulus", false)?;
        let (beta, kappa) = match small_beta_kappa(problem) {
            Some(v) => v,
            None => (f64_of(&m.beta(), "beta", true)?, f64_of(&problem.kappa(), "kappa", true)?),
        };
        let mu = f64_of(problem.friction(), "friction", true)?;
        let tau0 = f64_of(problem.adhesive_friction(), "adhesive_friction", true)?;
        let wear = f64_of(problem.wear(), "wear", true)?;
        let speed = problem.speed().map(|v| f64_of(v, "speed", false)).transpose()?;
        let period = match problem.period() {
            Period::Finite(l) => Some(f64_of(l, "period", false)?),
            Period::Infinite => None,
        };
        let shape = match problem.shape() {
            PunchShape::Parabolic { k } => ShapeF64::Parabolic { k: f64_of(k, "k", false)? },
            PunchShape::Sinusoidal { amplitude } => ShapeF64::Sinusoidal { d: f64_of(amplitude, "amplitude", false)? },
            PunchShape::Polynomial { coefficients } => {
                let round =
                    |v: Vec<Exact>| v.iter().map(|c| f64_of(c, "coefficients", true)).collect::<Result<Vec<_>, _>>();
                ShapeF64::Polynomial {
                    slope: round(polynomial_derivative(coefficients, 1))?,
                    curvature: round(polynomial_derivative(coefficients, 2))?,
                }
            }
            PunchShape::Circular { radius } => ShapeF64::Circular { r: f64_of(radius, "radius", false)? },
        };
        let theta = theta_f64(kappa);
        check_theta(theta.abs(), crate::numerics::accuracy::readable_f64(theta), problem)?;
        let target = match problem.load() {
            SlidingLoad::NormalLoad(p) => TargetF64::NormalLoad(f64_of(p, "normal_load", false)?),
            SlidingLoad::HalfLength(l) => TargetF64::HalfLength(f64_of(l, "half_length", false)?),
        };
        let k = match problem.shape() {
            // The polynomial's curvature scale, formed in MPFR from the exact input and rounded once.
            PunchShape::Polynomial { .. } => SlidingParamsMpfr::new(problem, 64)?.k.to_f64(),
            _ => osculating_k_f64(&shape, period),
        };
        Ok(SlidingParamsF64 {
            e_star,
            beta,
            mu,
            tau0,
            wear,
            speed,
            kappa,
            theta,
            period,
            shape,
            k,
            target,
            convention: problem.convention(),
        })
    }

    /// Hertz half-width a0 at the load `p2` (osculating k for the sinusoid).
    pub fn a0(&self, p2: f64) -> f64 {
        hertz_half_width_f64(p2, self.e_star, self.k)
    }

    /// Single-punch half-length l_s at the load `p2` [3.10].
    pub fn l_s(&self, p2: f64) -> f64 {
        single_punch_half_length_f64(self.a0(p2), self.theta)
    }

    /// T = beta tau0/(E* k l_s) [3.10] at the load `p2`.
    pub fn t(&self, p2: f64) -> f64 {
        self.beta * self.tau0 / (self.e_star * self.k * self.l_s(p2))
    }
}

/// Problem 1 in MPFR at `prec` bits, in units of E* (module doc): every input rounded once from
/// its exact value, and the derived numbers.
#[derive(Debug, Clone, PartialEq)]
pub struct SlidingParamsMpfr {
    /// Working precision in bits.
    pub prec: u32,
    /// pi.
    pub pi: Float,
    /// E* of the problem as given: the unit of every load and stress below (the fields are in
    /// units of E*, so E* itself is 1 in them); multiply a load or stress by `unit` to return.
    pub unit: Float,
    /// beta.
    pub beta: Float,
    /// mu.
    pub mu: Float,
    /// tau0 / E*.
    pub tau0: Float,
    /// cW E*.
    pub wear: Float,
    /// V, if given.
    pub speed: Option<Float>,
    /// kappa (from its exact value; unchanged by the units).
    pub kappa: Float,
    /// theta = arctan(kappa)/pi.
    pub theta: Float,
    /// cos(pi theta).
    pub cos_pi_theta: Float,
    /// Period L (None: single punch).
    pub period: Option<Float>,
    /// Shape.
    pub shape: ShapeMpfr,
    /// Curvature scale k: the osculating g''(0)/2 for the parabola (k), the sinusoid
    /// (2 pi^2 D/L^2) and the circle (1/(2 R)); for a polynomial the mean curvature over the
    /// centred single-punch contact of its even part at the given load, or over the given
    /// half-length ([`polynomial_curvature_scale_mpfr`]; = k for g = k x^2, > 0 for g = A x^4
    /// whose osculating curvature is 0). Used for scales (F_def ~ k l P2, the gap's k l^2) and
    /// for the starting estimates a0, l_s of the locating stages.
    pub k: Float,
    /// Load P2 / E* (given) or half-length l (given).
    pub target: TargetMpfr,
    /// Surface convention (docs/theory.md section 8).
    pub convention: Convention,
}

/// What fixes the contact, in MPFR (load in units of E*).
#[derive(Debug, Clone, PartialEq)]
pub enum TargetMpfr {
    /// Given P2 / E*.
    NormalLoad(Float),
    /// Given l.
    HalfLength(Float),
}

impl SlidingParamsMpfr {
    /// Rounds the exact inputs once to `prec` bits (in units of E*) and derives kappa, theta,
    /// cos(pi theta) and k. Errors when |theta| is within [`THETA_MARGIN`] of 1/2.
    pub fn new(problem: &SlidingProblem, prec: u32) -> Result<Self, Error> {
        let m = problem.material();
        let e = m.contact_modulus();
        let pi = Float::with_val(prec, Constant::Pi);
        let kappa = to_float(&problem.kappa(), prec);
        let theta = theta_mpfr(&kappa);
        check_theta(
            Float::with_val(53, theta.abs_ref()).to_f64(),
            crate::numerics::accuracy::readable_mpfr(&theta),
            problem,
        )?;
        let cos_pi_theta = Float::with_val(prec, &pi * &theta).cos();
        let period = match problem.period() {
            Period::Finite(l) => Some(to_float(l, prec)),
            Period::Infinite => None,
        };
        let shape = match problem.shape() {
            PunchShape::Parabolic { k } => ShapeMpfr::Parabolic { k: to_float(k, prec) },
            PunchShape::Sinusoidal { amplitude } => ShapeMpfr::Sinusoidal { d: to_float(amplitude, prec) },
            PunchShape::Polynomial { coefficients } => {
                let round = |v: Vec<Exact>| v.iter().map(|c| to_float(c, prec)).collect::<Vec<_>>();
                ShapeMpfr::Polynomial {
                    slope: round(polynomial_derivative(coefficients, 1)),
                    curvature: round(polynomial_derivative(coefficients, 2)),
                }
            }
            PunchShape::Circular { radius } => ShapeMpfr::Circular { r: to_float(radius, prec) },
        };
        let target = match problem.load() {
            SlidingLoad::NormalLoad(p) => TargetMpfr::NormalLoad(to_float(&(p / e), prec)),
            SlidingLoad::HalfLength(l) => TargetMpfr::HalfLength(to_float(l, prec)),
        };
        let k = match &shape {
            ShapeMpfr::Polynomial { slope, .. } => polynomial_curvature_scale_mpfr(slope, &target, prec)?,
            _ => osculating_k_mpfr(&shape, period.as_ref()),
        };
        Ok(SlidingParamsMpfr {
            prec,
            unit: to_float(e, prec),
            beta: to_float(&m.beta(), prec),
            mu: to_float(problem.friction(), prec),
            tau0: to_float(&(problem.adhesive_friction() / e), prec),
            wear: to_float(&(problem.wear() * e), prec),
            speed: problem.speed().map(|v| to_float(v, prec)),
            kappa,
            theta,
            cos_pi_theta,
            period,
            shape,
            k,
            target,
            pi,
            convention: problem.convention(),
        })
    }

    /// Hertz half-width a0 at the load `p2` given in units of E* (osculating k for the sinusoid).
    pub fn a0(&self, p2_per_e_star: &Float) -> Float {
        hertz_half_width_mpfr(p2_per_e_star, &Float::with_val(self.prec, 1u32), &self.k)
    }

    /// Single-punch half-length l_s at the load `p2` given in units of E* [3.10].
    pub fn l_s(&self, p2_per_e_star: &Float) -> Float {
        single_punch_half_length_mpfr(&self.a0(p2_per_e_star), &self.theta)
    }

    /// T = beta tau0/(E* k l_s) [3.10] at the load `p2` given in units of E*.
    pub fn t(&self, p2_per_e_star: &Float) -> Float {
        let num = Float::with_val(self.prec, &self.beta * &self.tau0);
        num / Float::with_val(self.prec, &self.k * self.l_s(p2_per_e_star))
    }

    /// Exponents (alpha, beta) of the Jacobi weight 1/omega = (1-u)^{theta-1/2} (1+u)^{-theta-1/2}.
    pub fn inverse_weight_exponents(&self) -> (Float, Float) {
        let a = Float::with_val(self.prec, &self.theta - 0.5f64);
        let b = Float::with_val(self.prec, -Float::with_val(self.prec, &self.theta + 0.5f64));
        (a, b)
    }

    /// Exponents (alpha, beta) of omega = (1-u)^{1/2-theta} (1+u)^{1/2+theta} (docs/theory.md section 2).
    pub(crate) fn weight_exponents(&self) -> (Float, Float) {
        let a = Float::with_val(self.prec, 0.5f64 - Float::with_val(self.prec, &self.theta));
        let b = Float::with_val(self.prec, &self.theta + 0.5f64);
        (a, b)
    }
}

/// The scale of every Problem 1 output, the one table used by every method's accuracy and by the
/// renderer: digits of a, b, c, l, x are relative to l; of P1, P2 (and the wear outputs) to P2; of
/// F_def to k l P2 (k osculating: F_def = int p g' ~ p k l . l); of p(x) to max p.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SlidingScale {
    /// l: a, b, c, l, lambda (relative to itself), x.
    Length,
    /// P2: P1, P2, wear outputs (relative to themselves: each is a multiple of P2).
    Load,
    /// k l P2: F_def.
    DeformationForce,
    /// max p: p(x).
    Pressure,
}

impl SlidingScale {
    /// The scale in `f64` from the solution's l, P2, max p and the osculating k.
    pub fn f64(self, k: f64, l: f64, p2: f64, max_p: f64) -> f64 {
        match self {
            SlidingScale::Length => l,
            SlidingScale::Load => p2,
            SlidingScale::DeformationForce => k * l * p2,
            SlidingScale::Pressure => max_p,
        }
    }

    /// The scale in MPFR (at the precision of `l`).
    pub fn mpfr(self, k: &Float, l: &Float, p2: &Float, max_p: &Float) -> Float {
        let prec = l.prec();
        match self {
            SlidingScale::Length => l.clone(),
            SlidingScale::Load => p2.clone(),
            SlidingScale::DeformationForce => Float::with_val(prec, k * l) * p2,
            SlidingScale::Pressure => max_p.clone(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Material;

    fn q(s: &str) -> Exact {
        exact_series::parse_rational(s).unwrap()
    }

    fn problem(mu: &str, tau0: &str, cw: &str, e: &str) -> SlidingProblem {
        SlidingProblem::builder()
            .material(Material::from_contact_modulus(q("0.3"), q(e)).unwrap())
            .period(Period::finite(q("1")).unwrap())
            .shape(PunchShape::parabolic(q("1")).unwrap())
            .friction(q(mu))
            .adhesive_friction(q(tau0))
            .wear(q(cw))
            .normal_load(q("0.05"))
            .build()
            .unwrap()
    }

    /// The i128 path of beta and kappa gives the big-rational path's values to the bit, and
    /// declines (`None`) where a part overflows, leaving the same values to the big path.
    #[test]
    fn small_beta_and_kappa_are_the_exact_ones_rounded() {
        let big = |p: &SlidingProblem| (to_f64(&p.material().beta()).unwrap(), to_f64(&p.kappa()).unwrap());
        let bits = |(a, b): (f64, f64)| (a.to_bits(), b.to_bits());
        for (mu, tau0, cw, e) in [
            ("0.4", "0.01", "0.02", "2"),
            ("0.3", "0", "0", "1"),
            ("0", "0", "0.1234567890123", "210000"),
            ("1.23456789012345", "0", "7e-13", "3.3e11"),
            ("1/3", "0", "2/7", "22/7"),
        ] {
            let p = problem(mu, tau0, cw, e);
            assert_eq!(small_beta_kappa(&p).map(bits), Some(bits(big(&p))), "{mu} {cw} {e}");
        }
        // Parts beyond i128 (a 50-digit wear): the big-rational path, same parameters.
        let p = problem("0.3", "0", "0.00000000000000000000000000000000000000000000000001", "1");
        assert_eq!(small_beta_kappa(&p), None);
        let f = SlidingParamsF64::new(&p).unwrap();
        assert_eq!(bits((f.beta, f.kappa)), bits(big(&p)));
    }

    #[test]
    fn both_number_types_agree_on_every_derived_parameter() {
        let p = problem("0.4", "0.01", "0.02", "2");
        let f = SlidingParamsF64::new(&p).unwrap();
        let m = SlidingParamsMpfr::new(&p, 200).unwrap();
        // kappa = E* cW/2 - beta mu = 0.02 - (0.4/1.4) 0.4
        let kappa = 0.02 - 0.4 / 1.4 * 0.4;
        assert!((f.kappa - kappa).abs() < 1e-16);
        assert!((m.theta.to_f64() - f.theta).abs() < 1e-16);
        assert!((f.theta - kappa.atan() / PI).abs() < 1e-16);
        // l_s in units of E*: the MPFR target is P2/E*.
        let TargetMpfr::NormalLoad(p2) = &m.target else { panic!() };
        assert!((m.l_s(p2).to_f64() - f.l_s(0.05)).abs() < 1e-16);
        assert!((m.t(p2).to_f64() - f.t(0.05)).abs() < 1e-15);
        // Hertz: a0 = sqrt(2 P2/(pi E* k)) at P2 = 0.05, E* = 2, k = 1.
        assert!((f.a0(0.05) - (0.05 / PI).sqrt()).abs() < 1e-16);
    }

    #[test]
    fn osculating_curvature_of_the_sinusoid() {
        let k = osculating_k_f64(&ShapeF64::Sinusoidal { d: 0.01 }, Some(2.0));
        assert!((k - 2.0 * PI * PI * 0.01 / 4.0).abs() < 1e-17);
        let d = Float::with_val(100, 0.01f64);
        let km = osculating_k_mpfr(&ShapeMpfr::Sinusoidal { d }, Some(&Float::with_val(100, 2u32)));
        assert!((km.to_f64() - k).abs() < 1e-17);
    }

    #[test]
    fn theta_too_close_to_one_half_is_refused_by_both() {
        let p = problem("0", "0", "1000000", "1");
        let e = SlidingParamsF64::new(&p).unwrap_err();
        assert!(e.to_string().contains("theta"), "{e}");
        let e = SlidingParamsMpfr::new(&p, 100).unwrap_err();
        assert!(e.to_string().contains("theta"), "{e}");
    }
}
