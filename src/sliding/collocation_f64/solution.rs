//! Results of the f64 method: the solutions, their accuracy estimate (differences to the check
//! run on the scales of the accuracy rule) and the digits per quantity; and the solver's tunables.

use crate::numerics::accuracy::f64_digits_nodes;

/// Tunables of the f64 collocation solver.
#[derive(Debug, Clone, PartialEq)]
pub struct SolverOptions {
    /// Target size of the interpolation error used to choose the number of nodes (default 1e-14).
    pub target: f64,
    /// Largest number of nodes allowed (default 1200).
    pub max_nodes: usize,
    /// Force this number of nodes for the main run (the check run uses n + max(8, n/4));
    /// `None`: automatic.
    pub nodes: Option<usize>,
    /// Reject a solution whose estimated relative error exceeds this (default 1e-8).
    pub accept: f64,
}

impl Default for SolverOptions {
    fn default() -> Self {
        SolverOptions { target: 1e-14, max_nodes: 1200, nodes: None, accept: 1e-8 }
    }
}

/// Pressure at one requested point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressurePoint {
    /// xh = (x - c)/l in (-1, 1).
    pub xh: f64,
    /// x = c + l xh.
    pub x: f64,
    /// p(x).
    pub p: f64,
}

/// The check run's differences and the accuracy rule's scales (`verify.rs`): relative
/// differences per group (the acceptance test `options.accept` and the tests use them), the
/// absolute differences per quantity and the scales, from which
/// [`SlidingSolutionF64::digits`] states digits per quantity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AccuracyEstimate {
    /// max(|da|, |db|, |dc|)/l.
    pub geometry: f64,
    /// max |dp| / max p over the requested points and the 86 fixed samples in u of the
    /// physicality criterion's p >= 0 (`outputs.rs`).
    pub pressure: f64,
    /// max(|dP1|, |dP2|)/P2.
    pub load: f64,
    /// |dF_def|/(k l P2) (for the sinusoid k = 2 pi^2 D/L^2, the curvature of the osculating
    /// parabola).
    pub f_def: f64,
    /// Nodes of the check run: n + max(8, n/4).
    pub check_nodes: usize,
    /// |main - check| per quantity.
    pub differences: PerQuantity,
    /// The scale of each quantity.
    pub scales: Scales,
}

impl AccuracyEstimate {
    /// The largest of the four relative differences.
    pub fn max(&self) -> f64 {
        self.geometry.max(self.pressure).max(self.load).max(self.f_def)
    }
}

/// The outputs of Problem 1 that carry an accuracy, and the scale of each (issue 9, the one
/// table for the f64 method): l for lambda, l, a, b, c (and x); P2 for P1 and P2 (and the wear,
/// proportional to P2); k l P2 for F_def (k osculating,
/// [`crate::params::sliding::SlidingParamsF64::k`]); max p for p(x).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// lambda = pi l/L and l (they share their relative error).
    Size,
    /// a.
    A,
    /// b.
    B,
    /// c.
    C,
    /// P1.
    P1,
    /// P2.
    P2,
    /// F_def.
    FDef,
    /// p(x): the largest difference over the requested points and the 86 fixed samples in u
    /// (`outputs.rs`).
    Pressure,
}

impl Quantity {
    /// Every quantity, in the order of [`PerQuantity`].
    pub const ALL: [Quantity; 8] = [
        Quantity::Size,
        Quantity::A,
        Quantity::B,
        Quantity::C,
        Quantity::P1,
        Quantity::P2,
        Quantity::FDef,
        Quantity::Pressure,
    ];

    /// The scale of this quantity.
    pub fn scale(self, scales: &Scales) -> f64 {
        match self {
            Quantity::Size | Quantity::A | Quantity::B | Quantity::C => scales.length,
            Quantity::P1 | Quantity::P2 => scales.load,
            Quantity::FDef => scales.f_def,
            Quantity::Pressure => scales.pressure,
        }
    }
}

/// One number per [`Quantity`] (differences to the check run, or digits), indexed by it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PerQuantity(pub [f64; 8]);

impl std::ops::Index<Quantity> for PerQuantity {
    type Output = f64;
    fn index(&self, q: Quantity) -> &f64 {
        &self.0[q as usize]
    }
}

impl PerQuantity {
    /// The smallest entry (for digits: the headline).
    pub fn min(&self) -> f64 {
        self.0.into_iter().fold(f64::INFINITY, f64::min)
    }
}

/// Scales of the accuracy rule ([`Quantity::scale`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scales {
    /// l.
    pub length: f64,
    /// P2.
    pub load: f64,
    /// k l P2.
    pub f_def: f64,
    /// max p.
    pub pressure: f64,
}

/// One solution of Problem 1 in f64.
#[derive(Debug, Clone, PartialEq)]
pub struct SlidingSolutionF64 {
    /// theta = atan(kappa)/pi.
    pub theta: f64,
    /// kappa = E* cW/2 - beta mu.
    pub kappa: f64,
    /// lambda = pi l/L (0 for a single punch).
    pub lambda: f64,
    /// Half-length l = (a + b)/2.
    pub l: f64,
    /// Trailing edge at x = -a.
    pub a: f64,
    /// Leading edge at x = b.
    pub b: f64,
    /// Centre c = (b - a)/2.
    pub c: f64,
    /// Tangential load P1 = mu P2 + 2 l tau0.
    pub p1: f64,
    /// Normal load P2 = int p dx.
    pub p2: f64,
    /// Deformation component of the sliding resistance F_def = int p g' dx.
    pub f_def: f64,
    /// Mean wear per sliding distance cW P2/L (`None` for a single punch).
    pub wear_per_distance: Option<f64>,
    /// Mean wear rate cW V P2/L when the speed V is given (and L finite).
    pub wear_rate: Option<f64>,
    /// Worn area (volume per unit width) per unit sliding distance, cW P2, for each punch.
    pub worn_area_per_distance: f64,
    /// Largest pressure over the requested points and the 86 fixed samples in u of the
    /// physicality criterion's p >= 0, the MPFR method's samples of max p (`outputs.rs`).
    pub max_pressure: f64,
    /// What the shared physicality criterion reports beside the solution: the most negative gap
    /// (0 when none), the closure defect, the edge step and a warning in `paper`
    /// ([`crate::sliding::physicality::Assessment`]).
    pub physicality: crate::sliding::physicality::Assessment,
    /// p at the requested xh.
    pub pressure: Vec<PressurePoint>,
    /// Nodes of the main run.
    pub nodes: usize,
    /// Difference to the check run.
    pub accuracy: AccuracyEstimate,
}

impl SlidingSolutionF64 {
    /// Verified digits of each output under the project's accuracy rule: [`f64_digits_nodes`] of the
    /// difference to the check run on the quantity's scale ([`Quantity::scale`]), with the f64
    /// round-off floor. Index the result by [`Quantity`].
    pub fn digits(&self) -> PerQuantity {
        let (d, s) = (&self.accuracy.differences, &self.accuracy.scales);
        PerQuantity(Quantity::ALL.map(|q| f64_digits_nodes(d[q], self.value(q), q.scale(s), self.nodes)))
    }

    /// The value of quantity `q` (p: its scale, max p, whose round-off bounds every p's).
    pub fn value(&self, q: Quantity) -> f64 {
        match q {
            Quantity::Size => self.l,
            Quantity::A => self.a,
            Quantity::B => self.b,
            Quantity::C => self.c,
            Quantity::P1 => self.p1,
            Quantity::P2 => self.p2,
            Quantity::FDef => self.f_def,
            Quantity::Pressure => self.accuracy.scales.pressure,
        }
    }
}

/// All physical solutions, smallest contact first (several only for the sinusoid with theta != 0
/// or tau0 > 0).
#[derive(Debug, Clone, PartialEq)]
pub struct SlidingSolutionsF64 {
    /// Non-empty, sorted by l ascending.
    pub solutions: Vec<SlidingSolutionF64>,
}

impl SlidingSolutionsF64 {
    /// The solution with the smallest contact.
    pub fn primary(&self) -> &SlidingSolutionF64 {
        &self.solutions[0]
    }
}
