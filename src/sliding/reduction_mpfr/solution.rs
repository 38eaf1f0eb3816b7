//! The result of the high-precision solution of Problem 1.

use rug::Float;

/// Pressure at one requested point.
#[derive(Debug, Clone)]
pub struct PressurePoint {
    /// xh = (x - c)/l in (-1, 1), as requested (rounded once).
    pub xh: Float,
    /// x = c + l xh.
    pub x: Float,
    /// p(x) [2.13].
    pub p: Float,
}

/// One solution of Problem 1 at working precision (docs/theory.md section 3). Returned by the solver
/// in the problem's units; inside the solver the same struct holds loads and stresses in units of
/// E* ([`SlidingSolution::in_units_of`] converts).
#[derive(Debug, Clone)]
pub struct SlidingSolution {
    /// theta = arctan(kappa)/pi.
    pub theta: Float,
    /// kappa = E* cW/2 - beta mu [2.8].
    pub kappa: Float,
    /// lambda = pi l/L [2.1] (None for a single punch).
    pub lambda: Option<Float>,
    /// Half-length l = (a + b)/2.
    pub l: Float,
    /// Trailing end: the contact is [-a, b].
    pub a: Float,
    /// Leading end.
    pub b: Float,
    /// Centre c = (b - a)/2.
    pub c: Float,
    /// Tangential load per punch P1 = mu P2 + 2 l tau0.
    pub p1: Float,
    /// Normal load per punch P2 (given, or from [2.14] in the direct problem).
    pub p2: Float,
    /// Deformation component of the sliding resistance F_def = int p g' dx.
    pub f_def: Float,
    /// Mean wear depth per sliding distance cW P2/L (None for a single punch, where the mean over
    /// an infinite period vanishes; see `worn_area_per_distance`).
    pub wear_per_distance: Option<Float>,
    /// Mean wear rate cW V P2/L when the speed V is given (periodic only).
    pub wear_rate: Option<Float>,
    /// Worn area (volume per unit width) per unit sliding distance, cW P2, for each punch.
    pub worn_area_per_distance: Float,
    /// Pressure at the requested points.
    pub pressure: Vec<PressurePoint>,
    /// Largest pressure over the dense samples of the physicality check (the scale of p(x)).
    pub max_pressure: Float,
    /// Curvature scale k of the punch (k, 2 pi^2 D/L^2, 1/(2 R), or a polynomial's mean curvature:
    /// [`crate::params::sliding::SlidingParamsMpfr::k`]): with l and P2 it gives the scale k l P2
    /// of F_def ([`crate::params::sliding::SlidingScale`]).
    pub k: Float,
    /// Number of Gauss–Jacobi nodes used.
    pub nodes: usize,
    /// Working precision in bits.
    pub prec: u32,
    /// What the shared physicality criterion reports beside the solution (most negative gap,
    /// closure defect, edge step, warning in `paper`; lengths, so the same in every unit); None
    /// when the run skipped the checks ([`super::Checks::Skip`]).
    pub physicality: Option<crate::sliding::physicality::Assessment>,
}

/// Verified digits of each quantity: -log10(|difference| / scale) between two runs.
#[derive(Debug, Clone, PartialEq)]
pub struct Accuracy {
    /// (quantity name, digits), e.g. ("a", 41.2).
    pub digits: Vec<(String, f64)>,
    /// The minimum over all quantities (the headline).
    pub digits_verified: f64,
}

/// A solution with its verified accuracy.
#[derive(Debug, Clone)]
pub struct VerifiedSolution {
    /// The solution of the first run.
    pub solution: SlidingSolution,
    /// Per-quantity agreement with the second run (more bits, 1.5x nodes).
    pub accuracy: Accuracy,
}

impl SlidingSolution {
    /// The solution with its loads and stresses (P1, P2, F_def, p(x), max p) multiplied by
    /// `unit`: from the solver's units of E* to the problem's when `unit` = E*
    /// ([`crate::params::sliding::SlidingParamsMpfr::unit`]). Lengths, lambda, theta, kappa and
    /// the wear quantities (cW P2, the same in both) are unchanged.
    pub fn in_units_of(mut self, unit: &Float) -> Self {
        self.p1 *= unit;
        self.p2 *= unit;
        self.f_def *= unit;
        self.max_pressure *= unit;
        for q in self.pressure.iter_mut() {
            q.p *= unit;
        }
        self
    }
}
