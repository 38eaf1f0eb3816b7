//! Problem 1: steady sliding with Coulomb friction, adhesive friction and linear wear
//! (docs/theory.md section 3; the paper's (1.3), (2.8)).

use super::{error::readable, error::ModelError, Exact, Material, OnPunchRow, Period, PunchRow, PunchShape};
use num_traits::{Signed, Zero};

/// What fixes the contact size.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum SlidingLoad {
    /// Given normal load per punch P2 > 0 (the inverse problem: find the contact).
    NormalLoad(Exact),
    /// Given contact half-length l = (a + b)/2 > 0 (the direct problem).
    HalfLength(Exact),
}

/// The surface convention of Problem 1 (docs/theory.md section 8).
///
/// The paper's symmetric summation of Flamant's solutions [1.6]-[1.8] with the wear law
/// v' = g' - cW p leaves a surface that does not close over a period: the gap gains
/// M = (2/E*) beta P1 - cW P2 per period. Requiring a periodic surface adds the constant
///     K = (kappa P2 - 2 beta l tau0)/L   [reconstructed, docs/theory.md section 8]
/// to the right side of [2.8], i.e. beta tau0 -> beta tau0 + K in [2.14]. K -> 0 for a single
/// punch and vanishes when kappa = 0 and tau0 = 0; it is odd in lambda, so the paper's expansions
/// in even powers of lambda belong to [`Convention::Paper`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Convention {
    /// `paper`: sections 2-3 of docs/theory.md as they stand (no K). The default.
    #[default]
    Paper,
    /// `periodic`: K added; the surface closes over every period.
    PeriodicSurface,
}

impl Convention {
    /// The name used in scenes, on the command line and in JSON: `paper` or `periodic`.
    pub fn name(self) -> &'static str {
        match self {
            Convention::Paper => "paper",
            Convention::PeriodicSurface => "periodic",
        }
    }
}

/// A validated statement of Problem 1. Built by [`SlidingProblem::builder`]; validated once, when
/// built; read through its accessors.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct SlidingProblem {
    row: PunchRow,
    friction: Exact,
    adhesive_friction: Exact,
    wear: Exact,
    speed: Option<Exact>,
    load: SlidingLoad,
    convention: Convention,
}

/// Named-argument builder of a [`SlidingProblem`]: friction, adhesive friction and wear default
/// to 0, the convention to `paper`; material, period, shape and the load (or size) are required.
#[derive(Debug, Clone, Default)]
pub struct SlidingProblemBuilder {
    material: Option<Material>,
    period: Option<Period>,
    shape: Option<PunchShape>,
    friction: Option<Exact>,
    adhesive_friction: Option<Exact>,
    wear: Option<Exact>,
    speed: Option<Exact>,
    load: Option<SlidingLoad>,
    convention: Convention,
}

impl SlidingProblemBuilder {
    /// Half-plane material.
    pub fn material(mut self, m: Material) -> Self {
        self.material = Some(m);
        self
    }
    /// Period L, or a single punch.
    pub fn period(mut self, p: Period) -> Self {
        self.period = Some(p);
        self
    }
    /// Punch shape.
    pub fn shape(mut self, s: PunchShape) -> Self {
        self.shape = Some(s);
        self
    }
    /// Coulomb friction coefficient mu >= 0.
    pub fn friction(mut self, mu: Exact) -> Self {
        self.friction = Some(mu);
        self
    }
    /// Adhesive friction component tau0 >= 0.
    pub fn adhesive_friction(mut self, tau0: Exact) -> Self {
        self.adhesive_friction = Some(tau0);
        self
    }
    /// Linear wear coefficient cW >= 0.
    pub fn wear(mut self, cw: Exact) -> Self {
        self.wear = Some(cw);
        self
    }
    /// Sliding speed V > 0 (only the wear rate needs it).
    pub fn speed(mut self, v: Option<Exact>) -> Self {
        self.speed = v;
        self
    }
    /// Given normal load per punch P2 > 0 (find the contact).
    pub fn normal_load(mut self, p2: Exact) -> Self {
        self.load = Some(SlidingLoad::NormalLoad(p2));
        self
    }
    /// Given contact half-length l > 0 (find the load).
    pub fn half_length(mut self, l: Exact) -> Self {
        self.load = Some(SlidingLoad::HalfLength(l));
        self
    }
    /// Load or size.
    pub fn load(mut self, load: SlidingLoad) -> Self {
        self.load = Some(load);
        self
    }
    /// Surface convention (default `paper`).
    pub fn convention(mut self, c: Convention) -> Self {
        self.convention = c;
        self
    }

    /// Validates the parameter ranges that do not need a solution (signs, the sinusoid's period,
    /// 2 l < L). Conditions that depend on the solution (contact inside (-L/2, L/2), existence at
    /// this load) are checked by the solvers.
    pub fn build(self) -> Result<SlidingProblem, ModelError> {
        let missing = |name: &str| ModelError::new(name, "(missing)", "is required");
        let zero = || Exact::from_integer(0.into());
        let material = self.material.ok_or_else(|| missing("material"))?;
        let period = self.period.ok_or_else(|| missing("period"))?;
        let shape = self.shape.ok_or_else(|| missing("shape"))?;
        let load = self.load.ok_or_else(|| missing("normal_load or half_length"))?;
        let friction = self.friction.unwrap_or_else(zero);
        let adhesive_friction = self.adhesive_friction.unwrap_or_else(zero);
        let wear = self.wear.unwrap_or_else(zero);
        let speed = self.speed;
        let row = PunchRow::new(material, period, shape)?;
        if friction.is_negative() {
            return Err(ModelError::new("friction", readable(&friction), "must be >= 0"));
        }
        if adhesive_friction.is_negative() {
            return Err(ModelError::new("adhesive_friction", readable(&adhesive_friction), "must be >= 0"));
        }
        if wear.is_negative() {
            return Err(ModelError::new("wear", readable(&wear), "must be >= 0"));
        }
        if let Some(v) = &speed
            && !v.is_positive()
        {
            return Err(ModelError::new("speed", readable(v), "must be > 0"));
        }
        match &load {
            SlidingLoad::NormalLoad(p) if !p.is_positive() => {
                return Err(ModelError::new("normal_load", readable(p), "must be > 0"))
            }
            SlidingLoad::HalfLength(l) if !l.is_positive() => {
                return Err(ModelError::new("half_length", readable(l), "must be > 0"))
            }
            _ => {}
        }
        if let (SlidingLoad::HalfLength(l), Period::Finite(big_l)) = (&load, row.period())
            && (l + l) >= *big_l
        {
            return Err(ModelError::new(
                "half_length",
                readable(l),
                format!("must satisfy 2 l < L = {}", readable(big_l)),
            ));
        }
        Ok(SlidingProblem { row, friction, adhesive_friction, wear, speed, load, convention: self.convention })
    }
}

impl SlidingProblem {
    /// A builder with named arguments ([`SlidingProblemBuilder`]).
    pub fn builder() -> SlidingProblemBuilder {
        SlidingProblemBuilder::default()
    }

    /// A builder holding this problem's values (to change one and rebuild).
    pub fn to_builder(&self) -> SlidingProblemBuilder {
        SlidingProblemBuilder {
            material: Some(self.row.material().clone()),
            period: Some(self.row.period().clone()),
            shape: Some(self.row.shape().clone()),
            friction: Some(self.friction.clone()),
            adhesive_friction: Some(self.adhesive_friction.clone()),
            wear: Some(self.wear.clone()),
            speed: self.speed.clone(),
            load: Some(self.load.clone()),
            convention: self.convention,
        }
    }

    /// Coulomb friction coefficient mu >= 0.
    pub fn friction(&self) -> &Exact {
        &self.friction
    }
    /// Adhesive friction component tau0 >= 0.
    pub fn adhesive_friction(&self) -> &Exact {
        &self.adhesive_friction
    }
    /// Linear wear coefficient cW >= 0.
    pub fn wear(&self) -> &Exact {
        &self.wear
    }
    /// Sliding speed V > 0, if given.
    pub fn speed(&self) -> Option<&Exact> {
        self.speed.as_ref()
    }
    /// Load or contact size.
    pub fn load(&self) -> &SlidingLoad {
        &self.load
    }
    /// Surface convention.
    pub fn convention(&self) -> Convention {
        self.convention
    }

    /// kappa = 0 and tau0 = 0: the right side of [2.8] is (E*/2) g' alone (theta = 0, T = 0, the
    /// frictionless equation, whose closed forms apply), and K = (kappa P2 - 2 beta l tau0)/L
    /// vanishes, so the `paper` and `periodic` conventions coincide (docs/theory.md section 8).
    pub fn kappa_and_tau0_vanish(&self) -> bool {
        self.kappa().is_zero() && self.adhesive_friction.is_zero()
    }

    /// kappa = E* cW / 2 - beta mu (docs/theory.md section 3, the paper's (2.8)), exact.
    pub fn kappa(&self) -> Exact {
        let two = Exact::from_integer(2.into());
        self.row.material().contact_modulus() * &self.wear / two - self.row.material().beta() * &self.friction
    }
}
/// The punch row: material, period and shape.
impl OnPunchRow for SlidingProblem {
    fn row(&self) -> &PunchRow {
        &self.row
    }
}
