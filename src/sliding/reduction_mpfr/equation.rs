//! The reduced equation [2.14] for (lambda, c): load and solvability in one complex equation.
//!
//! Derivation (docs/theory.md section 3; Muskhelishvili, Singular Integral Equations, sections 78-79).
//! With the tangent map, [2.8] becomes on u in (-1, 1)
//!     kappa p(u) + (1/pi) PV int p(u') du'/(u - u') = F(u) + beta tau0 - C0,   F = (E*/2) g'(x(u)).
//! Psi(z) = (1/(2 pi i)) int p(u') du'/(u' - z) satisfies (kappa - i) Psi+ - (kappa + i) Psi- = rhs;
//! X(z) = (z-1)^{1/2-theta} (z+1)^{1/2+theta} has X+ = omega i e^{-i pi theta}, X- = -omega i e^{i pi theta},
//! so X+/X- = (kappa + i)/(kappa - i) and (kappa - i) X+ = omega/cos(pi theta). The solution bounded at
//! both ends is
//!     Psi(z) = X(z) cos(pi theta)/(2 pi i) int rhs(u')/(omega(u') (u' - z)) du'
//! under the solvability condition int rhs/omega = 0. Partial fractions of 1/(1 + m^2 u^2) and of
//! u/(1 + m^2 u^2) give P2 = 2 L Re Psi(i/m) and C0 = -2 Im Psi(i/m); with
//! int du/(omega (u - z)) = -J0/X(z), J0 = pi/cos(pi theta), the C0 terms cancel and
//!     E* cos(pi theta) X(i/m)/(2 pi i) int g'(x(u)) du/(omega(u) (u - i/m)) = P2/L - i beta tau0.   [2.14]
//! Since X(i/m) = i e^{-2 i theta lambda}/sin(lambda) and 1/(u - i/m) = m (m u + i)/(1 + m^2 u^2), this is
//!     K int g'(x(u)) (m u + i)/((1 + m^2 u^2) omega(u)) du = P2/L - i beta tau0,
//!     K = E* cos(pi theta) e^{-2 i theta lambda}/(2 pi cos(lambda)),
//! free of cancellation as lambda -> 0. Single punch (the limit L -> infinity, L m -> pi l):
//!     P2 = (E* cos(pi theta) l/2) int g'(c + l u) (u + 2 theta)/omega du,
//!     (E* cos(pi theta)/(2 pi)) int g'(c + l u)/omega du = -beta tau0,
//! which for the parabola give l_s = a0/sqrt(1 - 4 theta^2) and rbar_s = 2 theta - T [3.10].
//!
//! Each integral is an n-point Gauss–Jacobi sum for the weight 1/omega; the integrands are analytic
//! with singularities at u = +-i/m, so the error behaves like tan(lambda/2)^{2n}.
//!
//! Units: evaluated in units of E* (E* = 1, P2 and tau0 divided by E*; [`SlidingParamsMpfr`]).

use super::contact::Size;
use crate::model::Convention;
use crate::numerics::gauss_jacobi_mpfr::GaussJacobiRule;
use crate::params::sliding::{ShapeMpfr, SlidingParamsMpfr};
use rug::{Assign, Float};

/// The equation split over the slope basis: P2 = sum_j q_j re_j and the solvability residual
/// S = sum_j q_j im_j + beta tau0 (S = 0 at a solution), q from [`super::contact::Contact`].
#[derive(Debug, Clone)]
pub struct EquationTerms {
    /// Load contributions (L Re of the left side of [2.14]).
    pub re: [Float; 2],
    /// Imaginary parts of the left side of [2.14].
    pub im: [Float; 2],
}

/// Evaluates the two basis integrals of [2.14] with the rule `rule` (weight 1/omega).
pub fn equation_terms(params: &SlidingParamsMpfr, size: &Size, rule: &GaussJacobiRule) -> EquationTerms {
    kernel_sums(params, size, rule, |u, p| size.basis(params, u, p))
}

/// The left side of [2.14] split into its load (`re`, times L) and imaginary (`im`) parts for two
/// integrands `values(u, prec)` evaluated at the nodes of `rule` (weight 1/omega) in place of
/// g'(x(u)): the slope basis of the parabola and the sinusoid, or (g', g'') of a general profile
/// at one centre ([`super::centre`]).
pub(crate) fn kernel_sums(
    params: &SlidingParamsMpfr,
    size: &Size,
    rule: &GaussJacobiRule,
    values: impl Fn(&Float, u32) -> [Float; 2],
) -> EquationTerms {
    let p = params.prec;
    let mut sr = [Float::with_val(p, 0), Float::with_val(p, 0)];
    let mut si = [Float::with_val(p, 0), Float::with_val(p, 0)];
    match (&size.m, &size.lambda, &params.period) {
        (Some(m), Some(lambda), Some(big_l)) => {
            // In place, each operation rounded to p as before (one allocation per temporary, not
            // per node).
            let (mut s, mut inv, mut wi, mut wr, mut t) =
                (Float::new(p), Float::new(p), Float::new(p), Float::new(p), Float::new(p));
            for (u, w) in rule.nodes.iter().zip(&rule.weights) {
                let b = values(u, p);
                s.assign(m * u);
                t.assign(s.square_ref());
                t += 1u32;
                inv.assign(1u32 / &t);
                wi.assign(w * &inv);
                wr.assign(&wi * &s);
                for j in 0..2 {
                    t.assign(&wr * &b[j]);
                    sr[j] += &t;
                    t.assign(&wi * &b[j]);
                    si[j] += &t;
                }
            }
            let kmag = Float::with_val(p, &params.cos_pi_theta)
                / (Float::with_val(p, &params.pi * 2u32) * Float::with_val(p, lambda.cos_ref()));
            let psi = Float::with_val(p, &params.theta * lambda) * 2u32;
            let (sn, cs) = psi.sin_cos(Float::new(p));
            let mut re = [Float::new(p), Float::new(p)];
            let mut im = [Float::new(p), Float::new(p)];
            for j in 0..2 {
                let r = Float::with_val(p, &cs * &sr[j]) + Float::with_val(p, &sn * &si[j]);
                let i = Float::with_val(p, &cs * &si[j]) - Float::with_val(p, &sn * &sr[j]);
                re[j] = r * &kmag * big_l;
                im[j] = i * &kmag;
            }
            EquationTerms { re, im }
        }
        _ => {
            let two_theta = Float::with_val(p, &params.theta * 2u32);
            for (u, w) in rule.nodes.iter().zip(&rule.weights) {
                let b = values(u, p);
                let wr = Float::with_val(p, w * Float::with_val(p, u + &two_theta));
                for j in 0..2 {
                    sr[j] += Float::with_val(p, &wr * &b[j]);
                    si[j] += Float::with_val(p, w * &b[j]);
                }
            }
            let ec = Float::with_val(p, &params.cos_pi_theta);
            let fr = Float::with_val(p, &ec * &size.l) / 2u32;
            let fi = Float::with_val(p, &ec / &params.pi) / 2u32;
            let [sr0, sr1] = sr;
            let [si0, si1] = si;
            EquationTerms { re: [sr0 * &fr, sr1 * &fr], im: [si0 * &fi, si1 * &fi] }
        }
    }
}

/// The convention's form of the solvability residual (see [`shift_solutions`]): with
/// [`Convention::PeriodicSurface`], im_j -> im_j + kappa re_j/L and beta tau0 -> beta tau0
/// (1 - 2 l/L); returns the adjusted terms and the constant beta tau0 (or its periodic form).
pub fn closed_terms(params: &SlidingParamsMpfr, size: &Size, terms: &EquationTerms) -> (EquationTerms, Float) {
    let p = params.prec;
    let mut bt = Float::with_val(p, &params.beta * &params.tau0);
    let mut terms = terms.clone();
    if let (Convention::PeriodicSurface, Some(big_l)) = (params.convention, &params.period) {
        for j in 0..2 {
            terms.im[j] += Float::with_val(p, &params.kappa * &terms.re[j]) / big_l;
        }
        let f = 1u32 - Float::with_val(p, &size.l * 2u32) / big_l;
        bt *= f;
    }
    (terms, bt)
}

/// A centre c solving the imaginary part of [2.14] at a given size, and the load it carries.
#[derive(Debug, Clone)]
pub struct ShiftSolution {
    /// Centre c of the contact.
    pub c: Float,
    /// Load P2 from the real part of [2.14].
    pub p2: Float,
}

/// All centres c (within one period) solving the imaginary part of [2.14] at this size.
///
/// Parabola: the residual is affine in c, c = -(2 k im1 + beta tau0)/(2 k im0) (one solution; c does
/// not enter P2 since im0 is the only c-term and re0 = 0 up to quadrature error; lambda does not
/// depend on tau0). Sinusoid: with phi = 2 pi c/L, A sin(phi) + B cos(phi) = -beta tau0,
/// A = Q im0, B = Q im1, Q = 2 pi D/L: phi = asin(-beta tau0/R) - psi or pi - asin(-beta tau0/R) - psi,
/// R = hypot(A, B), psi = atan2(B, A); the first (principal) branch continues the frictionless
/// phi = 0. Empty when R < beta tau0.
///
/// With [`Convention::PeriodicSurface`] the residual gains K = (kappa P2 - 2 beta l tau0)/L with
/// P2 = sum_j q_j re_j, i.e. im_j -> im_j + kappa re_j/L and beta tau0 -> beta tau0 (1 - 2 l/L).
pub fn shift_solutions(params: &SlidingParamsMpfr, size: &Size, terms: &EquationTerms) -> Vec<ShiftSolution> {
    let p = params.prec;
    let (terms, bt) = closed_terms(params, size, terms);
    let terms = &terms;
    match &params.shape {
        ShapeMpfr::Parabolic { k } => {
            let num = Float::with_val(p, k * &terms.im[1]) * 2u32 + &bt;
            let den = Float::with_val(p, k * &terms.im[0]) * 2u32;
            let c = -(num / den);
            let p2 = (Float::with_val(p, &c * &terms.re[0]) + &terms.re[1]) * k * 2u32;
            vec![ShiftSolution { c, p2 }]
        }
        ShapeMpfr::Sinusoidal { d } => {
            let big_l = params.period.as_ref().expect("sinusoid has a period");
            let q = Float::with_val(p, &params.pi * d) * 2u32 / big_l;
            let a = Float::with_val(p, &q * &terms.im[0]);
            let b = Float::with_val(p, &q * &terms.im[1]);
            let r = Float::with_val(p, a.hypot_ref(&b));
            if r < bt || r.is_zero() {
                return vec![];
            }
            let psi = Float::with_val(p, b.atan2_ref(&a));
            let asn = Float::with_val(p, &bt / &r).asin();
            let phis = [Float::with_val(p, -&asn) - &psi, Float::with_val(p, &params.pi + &asn) - &psi];
            let two_pi = Float::with_val(p, &params.pi * 2u32);
            phis.into_iter()
                .map(|mut phi| {
                    while phi > params.pi {
                        phi -= &two_pi;
                    }
                    while phi <= -Float::with_val(p, &params.pi) {
                        phi += &two_pi;
                    }
                    let (s, co) = phi.clone().sin_cos(Float::new(p));
                    let p2 = (Float::with_val(p, &s * &terms.re[0]) + Float::with_val(p, &co * &terms.re[1])) * &q;
                    let c = Float::with_val(p, &phi * big_l) / &two_pi;
                    ShiftSolution { c, p2 }
                })
                .collect()
        }
        ShapeMpfr::Polynomial { .. } | ShapeMpfr::Circular { .. } => {
            unreachable!("general profiles find their centre by Newton's method (the centre module)")
        }
    }
}
