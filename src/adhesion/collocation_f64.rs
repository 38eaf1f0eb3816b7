//! Method 2b (`f64`): section 4's symmetric Problem 2 by collocation in eta, the f64 method where
//! the lambda^2 series of [`super::series_f64`] stops (issue 13: it refuses lambda >= ~0.74 at
//! nu = 0 and ~1.2 at nu = 0.3, the radius it observes).
//!
//! The equation is the leading edge's condition of the incremental method (docs/theory.md
//! sections 4 and 10, chi = pi x/L, lambda = pi a/L, P2 = E* k (L/pi)^2 P):
//!   Re int_0^chi P'(eta) L K(chi - eta; eta) d eta = G(chi),   0 < chi <= lambda,
//! with the flat punch's outside slope L K of [`crate::growing_contact::kernel_f64`] and the punch's
//! scaled slope G(chi) = pi^2 g'(L chi/pi)/(2 k L) (the parabola: pi chi; an even polynomial
//! g = sum c_2m x^(2m): pi sum_m (m c_2m/k) (L/pi)^(2m-2) chi^(2m-1)). It is solved as one block
//! of the loading law's march ([`crate::growing_contact::march`] with N = 0, the contact centred,
//! gamma = 0): F = P'(eta)/eta a polynomial of degree m - 1 in eta on [0, lambda] (Chebyshev),
//! fixed by the equation at the m right-Radau points, the integral by tanh-sinh in chi - eta.
//! With gamma = 0 these equations are linear in F, so they are assembled and solved directly
//! (one m x m system; the march's Newton with a difference Jacobian reaches the same values at
//! about m times the cost: `solve --method f64` at nu = 0.3, lambda = 1.4, 58 points, 0.02 s CPU
//! against 2.35 s, whole process, loaded machine).
//! So nothing is shared with method 1 ([`super::volterra_mpfr`], MPFR, Chebyshev in tau =
//! (eta/lambda)^2 with the substitution eta = chi s and its own kernel) or with the series.
//! psi, phi and the stresses are the march's fields (their scalings: [`super::loading_law::
//! verified_f64`]).
//!
//! Size of the discretisation: F is analytic on [0, lambda] with its nearest singularities at
//! eta = +-pi/2 (full contact), so its Chebyshev coefficients in u = 2 eta/lambda - 1 fall like
//! rho^-j, rho = u* + sqrt(u*^2 - 1), u* = pi/lambda - 1; m = ceil(37/ln rho) + 4 points (about
//! 16 digits), the check run 8 more (and finer rules). Digits are estimated from the two runs as
//! for the series ([`super::series_f64::verify`]).
//!
//! What stops it is the problem, not the rule (docs/theory.md section 11, [`super::volterra_mpfr`],
//! Conditioning): below nu = 1/2 the incremental problem is solved only up to a homogeneous
//! solution, so two discretisations may pick different multiples of it and the estimate falls
//! (the default report's Problem 2 map: 3.7 estimated digits at nu = 0.3, lambda = 1.4; nu = 0
//! and 0.15 at 1.4 refused naming the mode). Agreement with method 1 (tests below, `cargo test
//! --release --lib adhesion::collocation_f64 -- --nocapture` prints it): nu = 0.3, lambda = 1.2
//! (where the series refuses) and nu = 0, lambda = 0.7, load and fields to >= 12 digits; the
//! quartic g = x^2/4 + x^4/2 at nu = 0.3, a/L = 3/10.
//!
//! The `periodic` convention (docs/theory.md section 8, Problem 2): each increment carries i beta
//! times the tilted punch of [`crate::growing_contact::kernel_f64`] (`MarchSetting::tilt`); this
//! route is derived apart from method 1's closed-form kernel, and the two agree to 15 digits at
//! nu = 0, lambda = 0.6 and 1.0 (`convention_tests.rs`).
//!
//! Punches: the parabola and even polynomials (G a polynomial in chi); the circle's slope is not
//! a polynomial, and it is refused here (the series serves it inside its radius).

use super::error::AdhesionError;
use super::profile::{check_profile_on_contact, half_width_search, HalfWidthSearch};
use super::scales::Digits;
use super::series_f64::solution::{AdhesionSolutionF64, F64Route, PointValuesF64};
use super::series_f64::verify::estimate;
use super::series_f64::RightSeries;
use crate::asymptotics::adhesion_mode::{mode_sentence, valid_sizes};
use crate::growing_contact::kernel_f64::{KernelF64, Side};
use crate::growing_contact::march::{points_for, single_block, March, MarchOptions, MarchSetting, MAX_POINTS};
use crate::model::OnPunchRow;
use crate::model::{readable, AdhesionProblem, AdhesionSize, Exact, Period, PunchShape};
use crate::numerics::accuracy::{digits_text, readable_f64};
use crate::numerics::exact::to_f64;
use crate::numerics::gauss_jacobi_f64::gauss_jacobi;
use crate::numerics::roots::increasing_root;
use crate::numerics::tanh_sinh::tanh_sinh_f64;
use crate::params::adhesion::AdhesionParamsF64;
use std::f64::consts::PI;

/// The nominal options for `lambda` and the check run's (8 more points, finer rules).
fn options(lambda: f64) -> Option<[MarchOptions; 2]> {
    let m = points_for(lambda)?;
    let nominal = MarchOptions { nodes: m, block: lambda, gauss: 40, bits: 60 };
    Some([nominal, MarchOptions { nodes: m + 8, block: lambda, gauss: 52, bits: 76 }])
}

/// The problem's data in f64 and the march's setting.
struct Setup {
    period: f64,
    k: f64,
    e_star: f64,
    setting: MarchSetting,
}

impl Setup {
    fn new(problem: &AdhesionProblem) -> Result<Self, AdhesionError> {
        let conv = |q: &Exact, name: &'static str| {
            to_f64(q).filter(|v| v.is_finite() && *v > 0.0).ok_or_else(|| AdhesionError::InvalidArgument {
                parameter: name,
                value: readable(q),
                expected: "a positive number that fits in f64".into(),
            })
        };
        let period = match problem.period() {
            Period::Finite(l) => conv(l, "period")?,
            Period::Infinite => {
                return Err(AdhesionError::InvalidArgument {
                    parameter: "period",
                    value: "inf".into(),
                    expected: "a finite period for the collocation in eta (the single punch is \
                               self-similar: the lambda^2 series gives it at lambda = 0)"
                        .into(),
                })
            }
        };
        if let PunchShape::Circular { radius } = problem.shape() {
            return Err(AdhesionError::InvalidArgument {
                parameter: "shape",
                value: format!("circular (radius {})", readable(radius)),
                expected: "the parabola or an even polynomial for the collocation in eta (the circle's slope is \
                           not a polynomial in x; the lambda^2 series serves it inside its radius)"
                    .into(),
            });
        }
        let k = conv(problem.curvature(), "k")?;
        let e_star = conv(problem.material().contact_modulus(), "contact_modulus")?;
        // G(chi) = pi sum_n r_n(L/pi) chi^(2n+1) (module doc; r_n(a) = w_n a^(2n)).
        let r = RightSeries::new(problem)?.coefficients(period / PI, usize::MAX);
        let mut profile = vec![0.0; 2 * r.len()];
        for (n, rn) in r.iter().enumerate() {
            profile[2 * n + 1] = PI * rn;
        }
        if profile.iter().any(|c| !c.is_finite()) {
            return Err(AdhesionError::InvalidArgument {
                parameter: "coefficients",
                value: "the punch's polynomial".into(),
                expected: "coefficients whose slope in units of the period fits in f64".into(),
            });
        }
        let c = AdhesionParamsF64::new(problem.material());
        let setting = MarchSetting {
            kernel: KernelF64 { eps: c.eps, cosh_pi_eps: c.cosh_pi_eps, beta: c.beta, single: false },
            // The `periodic` convention: each increment carries i beta times the tilted punch
            // (docs/theory.md section 8, Problem 2; the march's kernel).
            tilt: problem.periodic_surface(),
            slope: vec![0.0],
            p2_per_p: e_star * k * period * period / (PI * PI),
            profile,
            start: 2.0 * c.load_constant,
            law_key: "tangential_ratio",
            law_text: "0".into(),
        };
        Ok(Setup { period, k, e_star, setting })
    }

    fn lambda_of(&self, a: f64) -> f64 {
        PI * a / self.period
    }

    /// The solution at `lambda` with the nominal (`which` = 0) or the check run's options: the
    /// collocation equations of one block of the march (module doc), linear in F because gamma
    /// = 0, assembled and solved directly (the march's Newton with a difference Jacobian would
    /// reach the same values at m times the cost); the fields then come from the march's block.
    fn solve_at(&self, lambda: f64, which: usize) -> Result<March, AdhesionError> {
        let o = options(lambda).ok_or_else(|| too_large(lambda))?[which];
        let m = o.nodes;
        let rule_error = |e: crate::numerics::gauss_jacobi_f64::QuadratureError| AdhesionError::NotConverged {
            what: "collocation in eta: rules",
            reason: e.to_string(),
        };
        // Right-Radau points u in (-1, 1] (the march's collocation points) and tanh-sinh on (0, 1).
        let mut radau = gauss_jacobi(m - 1, 1.0, 0.0).map_err(rule_error)?.nodes;
        radau.push(1.0);
        let ts = tanh_sinh_f64(o.bits, 1.0);
        let k = &self.setting.kernel;
        let mut a = nalgebra::DMatrix::<f64>::zeros(m, m);
        let mut b = nalgebra::DVector::<f64>::zeros(m);
        let mut t = vec![0.0; m];
        for (i, u_i) in radau.iter().enumerate() {
            let chi = 0.5 * lambda * (1.0 + u_i);
            // Re int_0^chi K(chi - eta; eta) eta F(eta) d eta, eta = chi s, chi - eta = chi (1 - s).
            for &(s, c, w) in &ts {
                let eta = chi * s;
                let weight = k.increment_outside(Side::Right, chi * c, eta, 0.0, self.setting.tilt).re * eta * w * chi;
                let u = 2.0 * eta / lambda - 1.0;
                chebyshev_values(u, &mut t);
                for (j, tj) in t.iter().enumerate() {
                    a[(i, j)] += weight * tj;
                }
            }
            b[i] = self.setting.profile.iter().rev().fold(0.0, |acc, p| acc * chi + p);
        }
        let f = a.lu().solve(&b).ok_or(AdhesionError::NotConverged {
            what: "collocation in eta",
            reason: format!("singular collocation matrix at lambda = {}", readable_f64(lambda)),
        })?;
        single_block(&self.setting, &o, lambda, f.iter().copied().collect())
    }

    /// Dimensional values of the march `mar` at the points x/a.
    fn values(&self, mar: &March, points: &[f64]) -> Result<AdhesionSolutionF64, AdhesionError> {
        let lambda = mar.end;
        let (l_over_pi, pi2) = (self.period / PI, PI * PI);
        let psi_scale = 2.0 * self.k * self.period / pi2;
        let q_scale = self.e_star * self.k * self.period / pi2;
        let pts = points
            .iter()
            .map(|&s| {
                let chi = lambda * s;
                let sigma = mar.sigma_hat(chi)? * q_scale;
                Ok(PointValuesF64 {
                    x_over_a: s,
                    psi: -psi_scale * mar.psi_hat(chi)?,
                    phi: -psi_scale * l_over_pi * mar.psi_hat_integral(chi)?,
                    q1: sigma.im,
                    q2: sigma.re,
                })
            })
            .collect::<Result<Vec<_>, AdhesionError>>()?;
        Ok(AdhesionSolutionF64 {
            route: F64Route::Collocation,
            lambda,
            half_width: l_over_pi * lambda,
            normal_load: mar.load(lambda) * self.setting.p2_per_p,
            points: pts,
            terms: mar.options.nodes,
            digits_estimated: Digits::from_points(0.0, [], 0.0),
            warnings: Vec::new(),
        })
    }

    /// The size lambda carrying P2 = `target` (run `which`): Newton's method on P(lambda), which
    /// increases with dP/dlambda = P'(lambda), safeguarded by bisection in (0, `lambda_max`)
    /// ([`increasing_root`]).
    fn lambda_for_load(&self, target: f64, lambda_max: f64, which: usize) -> Result<March, AdhesionError> {
        let p = target / self.setting.p2_per_p;
        // First guess: Kuznetsov's parabola with C_P (P = 2 C_P ln sec lambda).
        let guess = crate::numerics::elementary::acos_exp_neg(p / self.setting.start);
        let root = increasing_root(
            |lam| {
                self.solve_at(lam, which).map(|mar| {
                    let (value, slope) = (mar.load(lam), mar.p_prime(lam));
                    (mar, value, slope)
                })
            },
            p,
            (0.0, lambda_max),
            guess,
            8.0 * f64::EPSILON,
            100,
        );
        if let Some((_, mar)) = root.found {
            return Ok(mar);
        }
        Err(root.last_error.unwrap_or(AdhesionError::IllConditioned {
            method: "f64-collocation",
            parameter: "normal_load",
            value: readable_f64(target),
            valid: format!("a load whose contact has lambda = pi a/L below {}", readable_f64(lambda_max)),
            reason: "the collocation in eta needs more than 100 points closer to full contact".into(),
        }))
    }
}

/// T_j(u), j < t.len(), by the three-term recurrence.
fn chebyshev_values(u: f64, t: &mut [f64]) {
    let n = t.len();
    if n > 0 {
        t[0] = 1.0;
    }
    if n > 1 {
        t[1] = u;
    }
    for j in 2..n {
        t[j] = 2.0 * u * t[j - 1] - t[j - 2];
    }
}

fn too_large(lambda: f64) -> AdhesionError {
    AdhesionError::IllConditioned {
        method: "f64-collocation",
        parameter: "lambda",
        value: readable_f64(lambda),
        valid: "lambda = pi a/L below about 1.52".into(),
        reason: format!(
            "F = P'/eta is singular at full contact lambda = pi/2; more than {MAX_POINTS} collocation points would be needed"
        ),
    }
}

/// Method 2b with estimated digits (module doc): the nominal run's values, digits from the check
/// run's difference (never more than [`crate::numerics::accuracy::F64_DIGITS_CAP`]).
pub(crate) fn solve_collocation_f64(
    problem: &AdhesionProblem,
    points: &[Exact],
) -> Result<AdhesionSolutionF64, AdhesionError> {
    super::points::check_points(points)?;
    let setup = Setup::new(problem)?;
    let xs: Vec<f64> = points.iter().map(|p| to_f64(p).unwrap_or(0.0)).collect();
    let run = |which: usize| -> Result<AdhesionSolutionF64, AdhesionError> {
        let mar = match problem.size() {
            AdhesionSize::HalfWidth(a) => {
                let a = to_f64(a).unwrap_or(f64::NAN);
                check_profile_on_contact(problem, a)?;
                setup.solve_at(setup.lambda_of(a), which)?
            }
            AdhesionSize::NormalLoad(p2) => {
                let lambda_max = match half_width_search(problem) {
                    HalfWidthSearch::Capped { a_max } => setup.lambda_of(a_max).min(1.52),
                    _ => 1.52,
                };
                let mar = setup.lambda_for_load(to_f64(p2).unwrap_or(f64::NAN), lambda_max, which)?;
                check_profile_on_contact(problem, mar.end * setup.period / PI)?;
                mar
            }
        };
        setup.values(&mar, &xs)
    };
    let mut sol = run(0)?;
    sol.digits_estimated = match run(1) {
        Ok(fine) => estimate(problem, &sol, &fine),
        Err(_) => Digits::from_points(0.0, sol.points.iter().map(|_| [0.0; 4]), 0.0),
    };
    let headline = sol.digits_estimated.headline;
    // The two runs disagree below nu = 1/2 where the homogeneous solution has grown (module doc).
    let c = AdhesionParamsF64::new(problem.material());
    // In `periodic` the mode is not excited (docs/theory.md section 8, Problem 2): full contact.
    let cause = || {
        if problem.periodic_surface() {
            "near full contact lambda -> pi/2 the collocation converges slowly (in the `periodic` convention the \
             homogeneous mode is not excited)"
                .into()
        } else if c.eps > 0.0 {
            mode_sentence(c.eps, c.b, c.s, SHORT_DIGITS)
        } else {
            "the collocation converges slowly".into()
        }
    };
    if headline < MIN_DIGITS {
        return Err(AdhesionError::IllConditioned {
            method: "f64-collocation",
            parameter: "lambda",
            value: readable_f64(sol.lambda),
            valid: if problem.periodic_surface() {
                "lambda below about 1.5 (`periodic`)".into()
            } else {
                valid_sizes(c.eps, c.b, c.s, SHORT_DIGITS)
            },
            reason: format!("two runs agree to only {} digits: {}", digits_text(headline), cause()),
        });
    }
    if headline < SHORT_DIGITS {
        sol.warnings.push(format!(
            "only {} digits estimated (lambda = {:.6}; {})",
            digits_text(headline),
            sol.lambda,
            cause()
        ));
    }
    Ok(sol)
}

/// Below this many estimated digits the collocation refuses (as method 1 does).
pub const MIN_DIGITS: f64 = 2.0;
/// Below this many estimated digits its answer carries a warning naming the cause.
pub const SHORT_DIGITS: f64 = 12.0;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::adhesion::volterra_mpfr::VolterraParams;
    use crate::adhesion::{solve_mpfr, solve_verified};
    use crate::model::{Material, PunchShape};

    fn q(n: i64, d: i64) -> Exact {
        Exact::new(n.into(), d.into())
    }

    fn problem(nu: Exact, size: AdhesionSize) -> AdhesionProblem {
        let m = Material::from_contact_modulus(nu, q(2, 1)).unwrap();
        AdhesionProblem::new(m, Period::finite(q(1, 1)).unwrap(), PunchShape::parabolic(q(3, 1)).unwrap(), size)
            .unwrap()
    }

    fn pts() -> Vec<Exact> {
        vec![q(0, 1), q(1, 2), q(9, 10), q(99, 100)]
    }

    /// |method 1 - this method| of (psi, phi, q1, q2) per point over their scales k a, k a^2,
    /// E* k a (`ka`, `eka`).
    fn field_errors(
        m: &crate::adhesion::AdhesionSolution,
        f: &AdhesionSolutionF64,
        ka: f64,
        eka: f64,
    ) -> Vec<[f64; 4]> {
        m.points
            .iter()
            .zip(&f.points)
            .map(|(u, w)| {
                [
                    (u.psi.to_f64() - w.psi).abs() / ka,
                    (u.phi.to_f64() - w.phi).abs() / (ka * f.half_width),
                    (u.q1.to_f64() - w.q1).abs() / eka,
                    (u.q2.to_f64() - w.q2).abs() / eka,
                ]
            })
            .collect()
    }

    /// The two issue-13 points where the series either refuses (nu = 0.3, lambda = 1.2) or is
    /// the other f64 method (nu = 0, lambda = 0.7): method 1 at 20 digits (verified >= 20) and
    /// this method agree to 1e-12 in the load and the fields (scales k a, k a^2, E* k a), and
    /// the estimate claims no more than the agreement shows.
    #[test]
    fn agrees_with_method_1_where_the_series_stops() {
        // a = lambda L/pi with lambda = 6/5 and 7/10 rounded to 20 digits (exact strings).
        for (nu, a) in [(q(3, 10), "0.38197186342054880584"), (q(0, 1), "0.22281692032865347008")] {
            let a = exact_series::parse_rational(a).unwrap();
            let pr = problem(nu.clone(), AdhesionSize::HalfWidth(a));
            let v = solve_verified(&pr, &pts(), 20).unwrap();
            assert!(v.digits_verified.size >= 20.0, "nu {nu}: {}", v.digits_verified.size);
            let m = &v.solution;
            let f = solve_collocation_f64(&pr, &pts()).unwrap();
            let (ka, eka) = (3.0 * f.half_width, 6.0 * f.half_width);
            let rel = (m.normal_load.to_f64() - f.normal_load).abs() / f.normal_load;
            println!(
                "nu {nu} lambda {:.3}: points {} load rel {rel:.1e}, estimated {:?}",
                f.lambda, f.terms, f.digits_estimated
            );
            assert!(rel < 1e-12, "nu {nu}: {} vs {}", m.normal_load, f.normal_load);
            for (w, e) in f.points.iter().zip(field_errors(m, &f, ka, eka)) {
                println!("  x/a {}: {:.1e} {:.1e} {:.1e} {:.1e}", w.x_over_a, e[0], e[1], e[2], e[3]);
                assert!(e.iter().all(|e| *e < 1e-12), "nu {nu} x/a {}: {e:?}", w.x_over_a);
            }
            let true_digits = -rel.log10();
            assert!(f.digits_estimated.size >= 12.0 && f.digits_estimated.size <= true_digits + 0.5);
        }
    }

    /// nu = 0, lambda = 1.2 (issue 13's hard point): the two runs disagree and the refusal names
    /// the homogeneous solution and its exponent, as method 1's does.
    #[test]
    fn small_nu_refusal_names_the_mode() {
        let a = exact_series::parse_rational("0.38197186342054880584").unwrap();
        let e = solve_collocation_f64(&problem(q(0, 1), AdhesionSize::HalfWidth(a)), &[]).unwrap_err();
        let text = e.to_string();
        assert!(text.contains("homogeneous solution") && text.contains("m* = 605.7"), "{text}");
    }

    /// An even polynomial punch, g = x^2/4 + x^4/2 (k = 1/4), nu = 0.3, a/L = 3/10 (lambda = 0.94):
    /// the load and the fields agree with method 1 to 1e-12 of their scales.
    #[test]
    fn even_polynomial_agrees_with_method_1() {
        let m = Material::from_contact_modulus(q(3, 10), q(2, 1)).unwrap();
        let shape = PunchShape::polynomial(vec![q(0, 1), q(0, 1), q(1, 4), q(0, 1), q(1, 2)]).unwrap();
        let pr = AdhesionProblem::new(m, Period::finite(q(1, 1)).unwrap(), shape, AdhesionSize::HalfWidth(q(3, 10)))
            .unwrap();
        let v = solve_mpfr(&pr, &pts(), VolterraParams::for_digits(20)).unwrap();
        let f = solve_collocation_f64(&pr, &pts()).unwrap();
        let rel = (v.normal_load.to_f64() - f.normal_load).abs() / f.normal_load;
        println!("quartic: load rel {rel:.1e}, estimated {:?}", f.digits_estimated);
        assert!(rel < 1e-12, "{} vs {}", v.normal_load, f.normal_load);
        let (ka, eka) = (0.25 * f.half_width, 0.5 * f.half_width);
        for (w, e) in f.points.iter().zip(field_errors(&v, &f, ka, eka)) {
            assert!(e.iter().all(|e| *e < 1e-12), "x/a {}: {e:?}", w.x_over_a);
        }
    }

    /// See: issue 34, fuzz seed 2026 case 5890. The stresses vanish at the contact's end x/a = 1
    /// exactly (the point enters with the final size); the bisection left its entry one ulp
    /// short and printed q2 = 1.1e-7 of a scale 3.1, the square root of that ulp. Both at
    /// nu = 1/2 (q2 alone) and nu = 3/10 (q1 too), while x/a = 0.99 keeps its value.
    #[test]
    fn stresses_vanish_at_the_end_of_the_contact() {
        for nu in [q(1, 2), q(3, 10)] {
            let pr = problem(nu.clone(), AdhesionSize::HalfWidth(q(3, 10)));
            let f = solve_collocation_f64(&pr, &[q(99, 100), q(1, 1)]).unwrap();
            let (near, end) = (&f.points[0], &f.points[1]);
            assert_eq!((end.q1, end.q2), (0.0, 0.0), "nu {nu}: {end:?}");
            assert!(near.q2.abs() > 1e-3, "nu {nu}: {near:?}");
        }
    }

    /// A given load: the half-width method 1 finds (nu = 0.3, lambda = 1.2) is found again.
    #[test]
    fn a_given_load_finds_the_half_width() {
        let a = exact_series::parse_rational("0.38197186342054880584").unwrap();
        let pr = problem(q(3, 10), AdhesionSize::HalfWidth(a));
        let m = solve_mpfr(&pr, &[], VolterraParams::for_digits(20)).unwrap();
        let p2 = exact_series::parse_rational(&format!("{:.20e}", m.normal_load.to_f64())).unwrap();
        let pl = problem(q(3, 10), AdhesionSize::NormalLoad(p2));
        let f = solve_collocation_f64(&pl, &[]).unwrap();
        assert!((f.half_width - 0.381_971_863_420_548_8).abs() < 1e-12, "{}", f.half_width);
        assert!(f.digits_estimated.size >= 11.0, "{:?}", f.digits_estimated);
    }

    /// The circle and the single punch are refused naming the parameter; lambda near pi/2 names
    /// the point count.
    #[test]
    fn refusals_name_the_parameter() {
        let m = Material::from_contact_modulus(q(3, 10), q(2, 1)).unwrap();
        let circle = AdhesionProblem::new(
            m.clone(),
            Period::finite(q(1, 1)).unwrap(),
            PunchShape::circular(q(2, 1)).unwrap(),
            AdhesionSize::HalfWidth(q(1, 4)),
        )
        .unwrap();
        let e = solve_collocation_f64(&circle, &[]).unwrap_err();
        assert!(matches!(e, AdhesionError::InvalidArgument { parameter: "shape", .. }), "{e}");
        let single = AdhesionProblem::new(
            m,
            Period::Infinite,
            PunchShape::parabolic(q(3, 1)).unwrap(),
            AdhesionSize::HalfWidth(q(1, 4)),
        )
        .unwrap();
        let e = solve_collocation_f64(&single, &[]).unwrap_err();
        assert!(matches!(e, AdhesionError::InvalidArgument { parameter: "period", .. }), "{e}");
        let near = problem(q(3, 10), AdhesionSize::HalfWidth(q(4999, 10000)));
        let e = solve_collocation_f64(&near, &[]).unwrap_err();
        assert!(matches!(e, AdhesionError::IllConditioned { parameter: "lambda", .. }), "{e}");
    }
}
