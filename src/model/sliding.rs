//! Problem 1: steady sliding with Coulomb friction, adhesive friction and linear wear
//! (THEORY.md section 3; the paper's (1.3), (2.8)).

use super::{error::ModelError, Exact, Material, Period, PunchShape};
use num_traits::Signed;

/// What fixes the contact size.
#[derive(Debug, Clone, PartialEq)]
pub enum SlidingLoad {
    /// Given normal load per punch P2 > 0 (the inverse problem: find the contact).
    NormalLoad(Exact),
    /// Given contact half-length l = (a + b)/2 > 0 (the direct problem).
    HalfLength(Exact),
}

/// A validated statement of Problem 1.
#[derive(Debug, Clone, PartialEq)]
pub struct SlidingProblem {
    /// Half-plane material.
    pub material: Material,
    /// Period L, or a single punch.
    pub period: Period,
    /// Punch shape.
    pub shape: PunchShape,
    /// Coulomb friction coefficient mu >= 0.
    pub friction: Exact,
    /// Adhesive friction component tau0 >= 0.
    pub adhesive_friction: Exact,
    /// Linear wear coefficient cW >= 0.
    pub wear: Exact,
    /// Sliding speed V > 0, optional (only the wear rate needs it).
    pub speed: Option<Exact>,
    /// Load or contact size.
    pub load: SlidingLoad,
}

impl SlidingProblem {
    /// Validates the parameter ranges that do not need a solution (signs, the sinusoid's period).
    /// Conditions that depend on the solution (contact inside (-L/2, L/2), existence at this load)
    /// are checked by the solvers.
    pub fn new(
        material: Material,
        period: Period,
        shape: PunchShape,
        friction: Exact,
        adhesive_friction: Exact,
        wear: Exact,
        speed: Option<Exact>,
        load: SlidingLoad,
    ) -> Result<Self, ModelError> {
        if friction.is_negative() {
            return Err(ModelError::new("friction", &friction, "must be >= 0"));
        }
        if adhesive_friction.is_negative() {
            return Err(ModelError::new("adhesive_friction", &adhesive_friction, "must be >= 0"));
        }
        if wear.is_negative() {
            return Err(ModelError::new("wear", &wear, "must be >= 0"));
        }
        if let Some(v) = &speed {
            if !v.is_positive() {
                return Err(ModelError::new("speed", v, "must be > 0"));
            }
        }
        match &load {
            SlidingLoad::NormalLoad(p) if !p.is_positive() => {
                return Err(ModelError::new("normal_load", p, "must be > 0"))
            }
            SlidingLoad::HalfLength(l) if !l.is_positive() => {
                return Err(ModelError::new("half_length", l, "must be > 0"))
            }
            _ => {}
        }
        if let (PunchShape::Sinusoidal { .. }, Period::Infinite) = (&shape, &period) {
            return Err(ModelError::new("period", "inf", "a sinusoidal punch needs a finite period"));
        }
        if let (SlidingLoad::HalfLength(l), Period::Finite(big_l)) = (&load, &period) {
            if (l + l) >= *big_l {
                return Err(ModelError::new("half_length", l, format!("must satisfy 2 l < L = {big_l}")));
            }
        }
        Ok(SlidingProblem { material, period, shape, friction, adhesive_friction, wear, speed, load })
    }

    /// kappa = E* cW / 2 - beta mu (THEORY.md section 3, the paper's (2.8)), exact.
    pub fn kappa(&self) -> Exact {
        let two = Exact::from_integer(2.into());
        &self.material.contact_modulus * &self.wear / two - self.material.beta() * &self.friction
    }
}
