//! Method 2 in dimensional form: the solution of the exact problem (given a or P2, period or
//! single punch) at the requested points x/a. Scalings: [`crate::adhesion::scales`].

use super::right_side::RightSeries;
use super::series::{UniversalSeries, SERIES_TERMS};
use super::solve::{solve_rhs, SeriesSolution, SERIES_LAMBDA_MAX};
use crate::adhesion::profile::{check_profile_on_contact, circle_cap_error, half_width_search, HalfWidthSearch};
use crate::adhesion::scales::Digits;
use crate::growing_contact::error::AdhesionError;
use crate::model::OnPunchRow;
use crate::model::{readable, AdhesionProblem, AdhesionSize, Exact, Period};
use crate::numerics::exact::to_f64;
use crate::numerics::roots::increasing_root;

/// f64 values at one point (method 2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointValuesF64 {
    /// x/a.
    pub x_over_a: f64,
    /// psi.
    pub psi: f64,
    /// phi.
    pub phi: f64,
    /// q1.
    pub q1: f64,
    /// q2.
    pub q2: f64,
}

/// Which f64 method produced an [`AdhesionSolutionF64`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum F64Route {
    /// The power series in lambda^2 (this module).
    Series,
    /// The collocation in eta ([`crate::adhesion::collocation_f64`]), where the series stops.
    Collocation,
}

impl F64Route {
    /// The name printed in the JSON (`route`).
    pub fn name(self) -> &'static str {
        match self {
            F64Route::Series => "lambda^2 series",
            F64Route::Collocation => "collocation in eta",
        }
    }
}

/// Method 2 solution (f64).
#[derive(Debug, Clone, PartialEq)]
pub struct AdhesionSolutionF64 {
    /// The method that produced it.
    pub route: F64Route,
    /// lambda.
    pub lambda: f64,
    /// a.
    pub half_width: f64,
    /// P2.
    pub normal_load: f64,
    /// Points.
    pub points: Vec<PointValuesF64>,
    /// Series terms used (the collocation: points).
    pub terms: usize,
    /// Digits per quantity estimated by a second, finer run ([`super::verify`]); never more than
    /// the true digits (tested against method 1).
    pub digits_estimated: Digits,
    /// Why digits are short, if they are (the collocation at small nu; empty otherwise).
    pub warnings: Vec<String>,
}

/// One run of method 2 (f64 power series in lambda^2) on the universal series of the problem's
/// material; `digits_estimated` is left at 0 (the estimate compares two runs: [`super::verify`]).
/// A profile other than the parabola enters through its right side ([`RightSeries`]) and is
/// checked on the contact found ([`check_profile_on_contact`]).
pub(super) fn solve_run(
    problem: &AdhesionProblem,
    points: &[Exact],
    universal: &UniversalSeries,
) -> Result<AdhesionSolutionF64, AdhesionError> {
    let conv = |q: &Exact, name: &'static str| {
        to_f64(q).ok_or(AdhesionError::InvalidArgument {
            parameter: name,
            value: readable(q),
            expected: "must fit in f64".into(),
        })
    };
    let e_star = conv(problem.material().contact_modulus(), "contact_modulus")?;
    let k = conv(problem.curvature(), "k")?;
    let pi = std::f64::consts::PI;
    let right = RightSeries::new(problem)?;
    let period = match problem.period() {
        Period::Finite(l) => Some(conv(l, "period")?),
        Period::Infinite => None,
    };
    let lambda_of = |a: f64| period.map_or(0.0, |l| pi * a / l);
    let at = |a: f64| solve_rhs(universal, lambda_of(a), &right.coefficients(a, SERIES_TERMS));
    let (a, sol) = match problem.size() {
        AdhesionSize::HalfWidth(a) => {
            let a = conv(a, "half_width")?;
            check_profile_on_contact(problem, a)?;
            (a, at(a)?)
        }
        AdhesionSize::NormalLoad(p2) => {
            let target = conv(p2, "normal_load")?;
            let (a, sol) = half_width_for_load(problem, universal, &at, target, e_star * k, period)?;
            check_profile_on_contact(problem, a)?;
            (a, sol)
        }
    };
    let lambda = lambda_of(a);
    let load = sol.load_ratio() * e_star * k * a * a;
    let pts = points
        .iter()
        .map(|p| {
            let s = to_f64(p).unwrap_or(0.0);
            let (q2, q1) = sol.stress_ratio(s);
            PointValuesF64 {
                x_over_a: s,
                psi: sol.psi_ratio(s) * k * a,
                phi: sol.phi_ratio(s) * k * a * a,
                q1: q1 * e_star * k * a,
                q2: q2 * e_star * k * a,
            }
        })
        .collect();
    Ok(AdhesionSolutionF64 {
        route: F64Route::Series,
        lambda,
        half_width: a,
        normal_load: load,
        points: pts,
        terms: sol.f.len(),
        digits_estimated: Digits::from_points(0.0, [], 0.0),
        warnings: Vec::new(),
    })
}

/// The half-width of the given load P2 (`target`), by Newton's method safeguarded by bisection
/// on a in (0, a_max): P2(a) = E* k a^2 P~(a) increases with a, and dP2/da = E* k a F(1)
/// (f does not depend on the contact size, docs/theory.md section 4: P(lambda) = (1/2) int_0^(lambda^2) f,
/// the same for the single punch in the limit L -> infinity). a_max: the series' range
/// lambda <= [`SERIES_LAMBDA_MAX`] and the profile's search bound ([`half_width_search`]: the
/// circle's cap; a polynomial's single punch doubles its first bracket until the load is reached).
/// A solve that fails inside the bracket (the series too
/// close to its radius) shrinks the bracket from above; a load beyond the last solvable contact is
/// refused with the reason of that contact. `ek` = E* k. The parabola's single punch is
/// self-similar (P~ constant) and needs no iteration.
fn half_width_for_load(
    problem: &AdhesionProblem,
    universal: &UniversalSeries,
    at: &dyn Fn(f64) -> Result<SeriesSolution, AdhesionError>,
    target: f64,
    ek: f64,
    period: Option<f64>,
) -> Result<(f64, SeriesSolution), AdhesionError> {
    let pi = std::f64::consts::PI;
    let search = half_width_search(problem);
    if period.is_none() && search == HalfWidthSearch::Parabola {
        let sol = at(1.0)?;
        return Ok(((target / (sol.load_ratio() * ek)).sqrt(), sol));
    }
    let load_at = |a: f64| at(a).map(|sol| ek * a * a * sol.load_ratio());
    let profile_cap = match search {
        HalfWidthSearch::Capped { a_max } => Some(a_max),
        // A polynomial's single punch: double the first bracket until it holds the load (P2 grows
        // at least like a^2); with a period, the series' range bounds the search.
        HalfWidthSearch::Unbounded { start } if period.is_none() => {
            let mut hi = start;
            for _ in 0..64 {
                if load_at(hi)? >= target {
                    break;
                }
                hi *= 2.0;
            }
            Some(hi)
        }
        _ => None,
    };
    let series_cap = period.map(|l| SERIES_LAMBDA_MAX * l / pi);
    let a_max = match (series_cap, profile_cap) {
        (Some(s), Some(c)) => s.min(c),
        (Some(s), None) => s,
        (None, Some(c)) => c,
        (None, None) => f64::INFINITY,
    };
    // First guess: the parabola with curvature k (Kuznetsov-like P ~ 2 C_P ln sec lambda for a
    // period, P2 ~ 2 C_P E* k a^2 for the single punch), inside the bracket.
    let cp = universal.constants.load_constant;
    let guess = match period {
        Some(l) => {
            let t = target * pi * pi / (ek * l * l);
            crate::numerics::elementary::acos_exp_neg(t / (2.0 * cp)) * l / pi
        }
        None => (target / (cp * ek)).sqrt(),
    };
    let root = increasing_root(
        |a| {
            at(a).map(|sol| {
                let (p, d) = (ek * a * a * sol.load_ratio(), ek * a * sol.f_at(1.0));
                (sol, p, d)
            })
        },
        target,
        (0.0, a_max),
        guess,
        4.0 * f64::EPSILON,
        200,
    );
    if let Some(found) = root.found {
        return Ok(found);
    }
    let (hi, last_err) = (root.hi, root.last_error);
    if hi < a_max * (1.0 - 1e-12)
        && let Some(e) = last_err
    {
        return Err(e);
    }
    let size = readable(match problem.size() {
        AdhesionSize::NormalLoad(p) => p,
        AdhesionSize::HalfWidth(a) => a,
    });
    if let (HalfWidthSearch::Capped { a_max: cap }, AdhesionSize::NormalLoad(p2)) = (search, problem.size())
        && cap <= a_max
    {
        return Err(circle_cap_error(p2, cap, None));
    }
    Err(last_err.unwrap_or(AdhesionError::IllConditioned {
        method: "f64-series",
        parameter: "normal_load",
        value: size,
        valid: format!("a load whose contact has lambda = pi a/L <= {SERIES_LAMBDA_MAX}"),
        reason: "the lambda^2 series converges too slowly near its radius".into(),
    }))
}
