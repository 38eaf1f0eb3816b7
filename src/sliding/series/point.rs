//! The evaluation point of the Problem 1 series: the values of its variables theta, T and
//! Lambda = pi l_s/L at a problem's parameters (docs/theory.md section 5, [3.10]), all read from
//! [`SlidingParamsMpfr`] (theta, T, l_s and the osculating k are computed there and nowhere else).

use crate::asymptotics::sliding::SlidingExpansion;
use crate::error::Error;
use crate::model::SlidingProblem;
use crate::numerics::accuracy::readable_mpfr;
use crate::numerics::evaluate;
use crate::params::sliding::{SlidingParamsMpfr, TargetMpfr};
use exact_series::{Poly, Series, Symbol};
use rug::Float;

/// The variables of the Problem 1 expansions at one problem, at working precision, in units of
/// E* (as [`SlidingParamsMpfr`]: lengths and theta, T, Lambda unchanged; loads divided by E*).
#[derive(Debug, Clone)]
pub struct SeriesPoint {
    /// theta = arctan(kappa)/pi.
    pub theta: Float,
    /// T = beta tau0/(E* k l_s) [3.10].
    pub t: Float,
    /// kappa = tan(pi theta) [2.8] (symbol `kappa` of the `periodic` expansions).
    pub kappa: Float,
    /// Lambda = pi l_s/L [3.10].
    pub big_lambda: Float,
    /// Single-punch half-length l_s = a0/sqrt(1 - 4 theta^2) [3.10].
    pub l_s: Float,
    /// Curvature k (osculating k = 2 pi^2 D/L^2 for the sinusoid [2.16]).
    pub k: Float,
    /// The load P2 / E*.
    pub p2: Float,
    /// The period L.
    pub period: Float,
    /// Working precision in bits.
    pub prec: u32,
}

impl SeriesPoint {
    /// The point of `params`. Input errors: a single punch (the series expands in pi l_s/L) and a
    /// given half-length (the series is at a given load).
    pub fn new(params: &SlidingParamsMpfr) -> Result<Self, Error> {
        let Some(period) = params.period.clone() else {
            return Err(Error::input(
                "punch.period",
                "inf",
                "the series method expands in Lambda = pi l_s/L and needs a finite period: give punch.period, \
                 or use --method mpfr (or f64) for a single punch",
            ));
        };
        let p2 = match &params.target {
            TargetMpfr::NormalLoad(p2) => p2.clone(),
            TargetMpfr::HalfLength(l) => {
                return Err(Error::input(
                    "sliding.half_length",
                    readable_mpfr(l),
                    "the series method expands at a given load, but sliding.half_length was given: \
                     give sliding.normal_load instead, or use --method mpfr (or f64) for a given half-length",
                ))
            }
        };
        let prec = params.prec;
        let l_s = params.l_s(&p2);
        let big_lambda = Float::with_val(prec, &params.pi * &l_s) / &period;
        Ok(SeriesPoint {
            theta: params.theta.clone(),
            t: params.t(&p2),
            kappa: params.kappa.clone(),
            big_lambda,
            l_s,
            k: params.k.clone(),
            p2,
            period,
            prec,
        })
    }

    /// The values of the symbols theta, T, kappa and invpi = 1/pi of the Problem 1 expansions
    /// (the last two occur only in the `periodic` convention's).
    pub fn bindings(&self) -> [(Symbol, Float); 4] {
        let invpi = Float::with_val(self.prec, rug::float::Constant::Pi).recip();
        [
            (Symbol::new("theta").expect("valid"), self.theta.clone()),
            (Symbol::new("T").expect("valid"), self.t.clone()),
            (Symbol::new("kappa").expect("valid"), self.kappa.clone()),
            (Symbol::new("invpi").expect("valid"), invpi),
        ]
    }

    /// A Lambda-series over Q[theta, T], truncated after Lambda^order, at this point.
    ///
    /// # Panics
    /// When `s` holds a symbol other than theta, T, kappa, invpi (a bug: the expansions' l/l_s,
    /// rbar - rbar_s and F_def series hold only these).
    pub(crate) fn eval(&self, s: &Series<Poly>, order: usize) -> Float {
        evaluate::series_mpfr(&s.truncate(order + 1), &self.big_lambda, &self.bindings(), self.prec)
            .expect("the expansions hold only theta, T, kappa and invpi")
    }

    /// The contact half-length l = l_s (l/l_s) and centre c = rbar l from the series truncated
    /// after Lambda^order, rbar = 2 theta - T + (rbar - rbar_s) [3.10].
    pub fn contact(&self, e: &SlidingExpansion, order: usize) -> (Float, Float) {
        let prec = self.prec;
        let l = Float::with_val(prec, &self.l_s * self.eval(&e.l_over_ls, order));
        let rbar = Float::with_val(prec, 2 * self.theta.clone() - &self.t) + self.eval(&e.rbar_minus_rbar_s, order);
        let c = Float::with_val(prec, &rbar * &l);
        (l, c)
    }
}

/// The series point of `problem` at `prec` bits (derives [`SlidingParamsMpfr`] first).
pub fn series_point(problem: &SlidingProblem, prec: u32) -> Result<SeriesPoint, Error> {
    SeriesPoint::new(&SlidingParamsMpfr::new(problem, prec)?)
}
