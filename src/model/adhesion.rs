//! Problem 2: monotone indentation of periodic punches with complete adhesion
//! (docs/theory.md section 4; the paper's (1.4), (2.18)-(2.26)).

use super::{
    error::readable, error::ModelError, Convention, Exact, Material, OnPunchRow, Period, PunchRow, PunchShape,
};
use num_traits::{Signed, Zero};

/// What fixes the state of the monotone indentation.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum AdhesionSize {
    /// Given contact half-width a > 0 (the direct problem).
    HalfWidth(Exact),
    /// Given normal load per punch P2 > 0 (find a).
    NormalLoad(Exact),
}

/// A validated statement of Problem 2 (symmetric case, b = a, P1 = 0).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct AdhesionProblem {
    row: PunchRow,
    size: AdhesionSize,
    reference_curvature: Exact,
    convention: Convention,
    friction: Option<Exact>,
}

impl AdhesionProblem {
    /// Validates the statement: a parabolic, even polynomial or circular punch (Problem 2 here
    /// is symmetric: a polynomial with a non-zero odd coefficient is refused, naming
    /// `coefficients`), positive sizes, 2a < L for a given a. (For a given load every P2 > 0 has
    /// a solution with 2a < L, since P2(a) -> infinity as 2a -> L; the single punch's half-width
    /// under a given load is searched by the solvers for every profile.) Convexity and the circle's |x| < R on the contact are
    /// checked by the solvers once a is known ([`crate::adhesion::profile`]).
    pub fn new(material: Material, period: Period, shape: PunchShape, size: AdhesionSize) -> Result<Self, ModelError> {
        match &shape {
            PunchShape::Parabolic { .. } | PunchShape::Circular { .. } => {}
            PunchShape::Polynomial { coefficients } => {
                if let Some((j, c)) = coefficients.iter().enumerate().find(|(j, c)| j % 2 == 1 && !c.is_zero()) {
                    return Err(ModelError::new(
                        "coefficients",
                        shape.parameters().remove(0).1,
                        format!(
                            "the adhesion problem is symmetric (g even): every odd coefficient must be 0, but coefficients[{j}] = c_{j} = {}",
                            readable(c)
                        ),
                    ));
                }
            }
            PunchShape::Sinusoidal { .. } => {
                return Err(ModelError::new(
                    "shape",
                    shape.name(),
                    "the adhesion problem supports the parabolic, even polynomial and circular punches",
                ))
            }
        }
        let row = PunchRow::new(material, period, shape)?;
        let (period, shape) = (row.period(), row.shape());
        match &size {
            AdhesionSize::HalfWidth(a) if !a.is_positive() => {
                return Err(ModelError::new("half_width", readable(a), "must be > 0"))
            }
            AdhesionSize::NormalLoad(p) if !p.is_positive() => {
                return Err(ModelError::new("normal_load", readable(p), "must be > 0"))
            }
            _ => {}
        }
        if let (AdhesionSize::HalfWidth(a), Period::Finite(l)) = (&size, period)
            && (a + a) >= *l
        {
            return Err(ModelError::new("half_width", readable(a), format!("must satisfy 2 a < L = {}", readable(l))));
        }
        let reference_curvature = reference_curvature(shape, period, &size, row.material().contact_modulus());
        Ok(AdhesionProblem { row, size, reference_curvature, convention: Convention::Paper, friction: None })
    }

    /// Half-width or load.
    pub fn size(&self) -> &AdhesionSize {
        &self.size
    }
    /// The surface convention (docs/theory.md section 8): `paper` (the default) keeps the Flamant
    /// far field sigma_xx = -P2/L (u not periodic, each punch translates with the surface under
    /// it), `periodic` makes u periodic (a laterally rigid row, zero mean lateral strain). The
    /// single punch is the same in both.
    pub fn convention(&self) -> Convention {
        self.convention
    }
    /// The same problem in the convention `c`.
    pub fn with_convention(mut self, c: Convention) -> Self {
        self.convention = c;
        self
    }
    /// The Coulomb friction coefficient mu of finite friction (docs/theory.md section 17: a central
    /// stick zone, slip |q1| = mu q2 at the ends); None: complete adhesion (mu -> infinity).
    pub fn friction(&self) -> Option<&Exact> {
        self.friction.as_ref()
    }
    /// The same problem with finite friction mu; mu must be > 0 (mu = 0 is the frictionless
    /// contact, not an adhesion problem), refused naming `friction`.
    pub fn with_friction(mut self, mu: Exact) -> Result<Self, ModelError> {
        if !mu.is_positive() {
            return Err(ModelError::new("friction", readable(&mu), FRICTION_RANGE));
        }
        self.friction = Some(mu);
        Ok(self)
    }
    /// Whether the `periodic` convention's lateral term applies: the `periodic` convention on a
    /// finite period (the term beta P2/L vanishes for the single punch).
    pub(crate) fn periodic_surface(&self) -> bool {
        self.convention == Convention::PeriodicSurface && matches!(self.row.period(), Period::Finite(_))
    }

    /// The reference curvature k of the scalings P2 = E* k (L/pi)^2 P, psi ~ k a, phi ~ k a^2,
    /// q ~ E* k a (exact): the parabola's k; for the circle 1/(2R) (its osculating parabola);
    /// for an even polynomial the secant curvature g'(l)/(2 l) = sum_m m c_2m l^(2m-2) at l = a
    /// (given half-width), l = L/4 (given load, finite period) or, for the single punch under a
    /// given load, l = (P2/(E* |c_2m|))^(1/(2m)) of the first non-zero c_2m (a length that scales
    /// with the problem, so the digits' scales follow its scaling laws; issue 34's fuzz case 815
    /// found l = 1 there, which did not). Any positive value is a valid
    /// scale: it only sets the units of F and of the digits' scales. A polynomial g = k x^2 gives
    /// the parabola's k exactly.
    pub fn curvature(&self) -> &Exact {
        &self.reference_curvature
    }
}

/// Range text of `[adhesion] friction` (the key table's and the model's message).
pub const FRICTION_RANGE: &str = "an exact number > 0 (a Coulomb friction coefficient mu; absent: complete adhesion)";

/// The punch row: material, period and shape (parabolic, even polynomial or circular).
impl OnPunchRow for AdhesionProblem {
    fn row(&self) -> &PunchRow {
        &self.row
    }
}

/// See [`AdhesionProblem::curvature`]. A non-positive secant curvature (a non-convex
/// polynomial) falls back to |c_j| of the first non-zero j >= 2 so the scale stays positive; the
/// solver then refuses the profile as not convex.
fn reference_curvature(shape: &PunchShape, period: &Period, size: &AdhesionSize, e_star: &Exact) -> Exact {
    let one = Exact::from_integer(1.into());
    match shape {
        PunchShape::Parabolic { k } => k.clone(),
        PunchShape::Circular { radius } => one / (radius * Exact::from_integer(2.into())),
        PunchShape::Sinusoidal { amplitude } => amplitude.clone(),
        PunchShape::Polynomial { coefficients } => {
            let l = match (size, period) {
                (AdhesionSize::HalfWidth(a), _) => a.clone(),
                (AdhesionSize::NormalLoad(_), Period::Finite(l)) => l / Exact::from_integer(4.into()),
                (AdhesionSize::NormalLoad(p2), Period::Infinite) => load_length(coefficients, p2, e_star),
            };
            let l2 = &l * &l;
            let mut pow = one.clone();
            let mut sum = Exact::zero();
            for (j, c) in coefficients.iter().enumerate().skip(2).step_by(2) {
                sum += c * Exact::from_integer(((j / 2) as i64).into()) * &pow;
                pow *= &l2;
            }
            if sum.is_positive() {
                sum
            } else {
                coefficients.iter().skip(2).find(|c| !c.is_zero()).map(|c| c.abs()).unwrap_or(one)
            }
        }
    }
}

/// The single punch's length for a given load P2 on g = sum c_j x^j: l = (P2/(E* |c_2m|))^(1/(2m))
/// with c_2m the first non-zero even coefficient (j >= 2), rounded once from f64 to an exact
/// rational (it only sets a scale); 1 when there is none or f64 cannot carry it.
fn load_length(coefficients: &[Exact], p2: &Exact, e_star: &Exact) -> Exact {
    let one = Exact::from_integer(1.into());
    let Some((j, c)) = coefficients.iter().enumerate().skip(2).step_by(2).find(|(_, c)| !c.is_zero()) else {
        return one;
    };
    let ratio = p2 / (e_star * c.abs());
    let l = num_traits::ToPrimitive::to_f64(&ratio).map(|r| r.powf(1.0 / j as f64));
    l.filter(|l| l.is_finite() && *l > 0.0).and_then(Exact::from_float).unwrap_or(one)
}

#[cfg(test)]
mod tests {
    use super::*;
    fn q(n: i64, d: i64) -> Exact {
        Exact::new(n.into(), d.into())
    }
    fn mat() -> Material {
        Material::from_contact_modulus(q(3, 10), q(1, 1)).unwrap()
    }

    #[test]
    fn adhesion_problem_validation() {
        let k = PunchShape::parabolic(q(1, 1)).unwrap();
        let l = Period::finite(q(1, 1)).unwrap();
        assert!(AdhesionProblem::new(mat(), l.clone(), k.clone(), AdhesionSize::HalfWidth(q(1, 4))).is_ok());
        let e = AdhesionProblem::new(mat(), l.clone(), k.clone(), AdhesionSize::HalfWidth(q(1, 2))).unwrap_err();
        assert_eq!(e.parameter, "half_width");
        let e = AdhesionProblem::new(mat(), l.clone(), k.clone(), AdhesionSize::NormalLoad(q(0, 1))).unwrap_err();
        assert_eq!(e.parameter, "normal_load");
        let s = PunchShape::sinusoidal(q(1, 1)).unwrap();
        let e = AdhesionProblem::new(mat(), l, s, AdhesionSize::HalfWidth(q(1, 4))).unwrap_err();
        assert_eq!(e.parameter, "shape");
        let single = AdhesionProblem::new(mat(), Period::Infinite, k, AdhesionSize::HalfWidth(q(7, 1))).unwrap();
        assert_eq!(single.friction(), None);
        assert_eq!(single.clone().with_friction(q(1, 2)).unwrap().friction(), Some(&q(1, 2)));
        for bad in [q(0, 1), q(-1, 2)] {
            let e = single.clone().with_friction(bad).unwrap_err();
            assert_eq!(e.parameter, "friction");
            assert!(e.expected.contains("> 0"), "{e}");
        }
    }

    #[test]
    fn adhesion_even_profiles_accepted_odd_terms_refused() {
        let l = Period::finite(q(1, 1)).unwrap();
        let quartic = PunchShape::polynomial(vec![q(0, 1), q(0, 1), q(1, 4), q(0, 1), q(1, 2)]).unwrap();
        let p = AdhesionProblem::new(mat(), l.clone(), quartic, AdhesionSize::HalfWidth(q(1, 5))).unwrap();
        // g'(a)/(2a) = c_2 + 2 c_4 a^2 = 1/4 + 1/25.
        assert_eq!(p.curvature(), &q(29, 100));
        let parabola = PunchShape::polynomial(vec![q(0, 1), q(0, 1), q(3, 7)]).unwrap();
        let p = AdhesionProblem::new(mat(), l.clone(), parabola, AdhesionSize::NormalLoad(q(1, 1))).unwrap();
        assert_eq!(p.curvature(), &q(3, 7));
        let circle = PunchShape::circular(q(2, 1)).unwrap();
        let p = AdhesionProblem::new(mat(), l.clone(), circle.clone(), AdhesionSize::HalfWidth(q(1, 5))).unwrap();
        assert_eq!(p.curvature(), &q(1, 4));
        let cubic = PunchShape::polynomial(vec![q(0, 1), q(0, 1), q(1, 1), q(1, 10)]).unwrap();
        let e = AdhesionProblem::new(mat(), l, cubic, AdhesionSize::HalfWidth(q(1, 5))).unwrap_err();
        assert_eq!(e.parameter, "coefficients");
        assert!(e.expected.contains("coefficients[3] = c_3 = 1/10") && e.value.contains("\"1/10\""), "{e}");
        // A single punch under a given load: every even profile (the solvers search the half-width).
        let p = AdhesionProblem::new(mat(), Period::Infinite, circle, AdhesionSize::NormalLoad(q(1, 1))).unwrap();
        assert_eq!(p.curvature(), &q(1, 4));
    }

    /// Issue 34, fuzz case 815: the single polynomial punch under a given load has a reference
    /// curvature that follows the scaling laws: lengths x s, stresses x t (c_j x s^(1-j), P2 x t s,
    /// E* x t) divide it by s, so every printed digit's scale scales as the problem does.
    #[test]
    fn single_punch_reference_curvature_follows_the_scaling() {
        let poly = |c2: Exact, c4: Exact| PunchShape::polynomial(vec![q(0, 1), q(0, 1), c2, q(0, 1), c4]).unwrap();
        let solve = |e: Exact, c2: Exact, c4: Exact, p: Exact| {
            let m = Material::from_contact_modulus(q(1, 2), e).unwrap();
            let k = AdhesionProblem::new(m, Period::Infinite, poly(c2, c4), AdhesionSize::NormalLoad(p)).unwrap();
            num_traits::ToPrimitive::to_f64(k.curvature()).unwrap()
        };
        let (s, t) = (q(1, 1000), q(1, 100));
        let base = solve(q(1, 1), q(28, 5), q(2688, 625), q(3, 100));
        let s3 = &s * &s * &s;
        let twin = solve(t.clone(), q(28, 5) / &s, q(2688, 625) / s3, q(3, 100) * &t * &s);
        assert!((twin * 1e-3 / base - 1.0).abs() < 1e-12, "{base} {twin}");
        // The length is (P2/(E* c_2))^(1/2) = (3/100 / (28/5))^(1/2); k = c_2 + 2 c_4 l^2.
        let l2 = 0.03 / 5.6;
        assert!((base - (5.6 + 2.0 * 2688.0 / 625.0 * l2)).abs() < 1e-12 * base, "{base}");
    }
}
