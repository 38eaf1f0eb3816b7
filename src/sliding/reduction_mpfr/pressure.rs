//! The pressure [2.13], the gap slope outside the contact, and the integrals of p.
//!
//! With F(u) = (E*/2) g'(x(u)) and the Gauss–Jacobi rule (u_j, w_j) for 1/omega (docs/theory.md section 3):
//!     p(u) = omega(u) cos^2(pi theta)/pi * D(u),   D(u) = int [F(u') - F(u)]/(u' - u) du'/omega(u'),
//! which is Psi+ - Psi- for the Psi of [`super::equation`], since X+ - X- = 2 i omega cos(pi theta).
//! p does not depend on tau0 or P2 [2.13]; sign(p) = sign(D) inside the contact.
//!
//! Outside the contact (real t = u(x), |t| > 1; q1 = 0 there) the same Psi gives \[reconstructed\]
//!     (E*/2) v'(x) = H\[p\](x) = F(t) + beta tau0 - X(t) cos(pi theta) D(t)/pi,
//!     X(t) = sign(t) |t - 1|^{1/2 - theta} |t + 1|^{1/2 + theta},
//! with F(t) the analytic continuation of F. (Check: Hertz, theta = 0: h' = 2 k sqrt(x^2 - a^2).)

use super::contact::Contact;
use super::profile::{is_general, profile_slope, row_slope};
use crate::numerics::gauss_jacobi_mpfr::GaussJacobiRule;
use crate::params::sliding::{ShapeMpfr, SlidingParamsMpfr};
use rug::ops::Pow;
use rug::{Assign, Float};

/// The pressure of one contact: the rule for 1/omega and F at its nodes.
pub struct Pressure<'a> {
    params: &'a SlidingParamsMpfr,
    contact: &'a Contact,
    rule: &'a GaussJacobiRule,
    f_nodes: Vec<Float>,
    /// The nodes rounded to `f64` (the distances that choose the working precision of [`Pressure::d`]).
    nodes_f64: Vec<f64>,
    /// F at the nodes at the raised precisions [`Pressure::d`] used so far (the same values as
    /// computed afresh; a point near a node raises the precision, and the points of one
    /// quadrature near the ends of the contact share a few precisions).
    f_raised: std::sync::Mutex<Vec<(u32, std::sync::Arc<Vec<Float>>)>>,
    /// cos^2(pi theta)/pi.
    factor: Float,
}

impl<'a> Pressure<'a> {
    /// Precomputes F(u_j) at the nodes of `rule` (weight 1/omega).
    pub fn new(params: &'a SlidingParamsMpfr, contact: &'a Contact, rule: &'a GaussJacobiRule) -> Self {
        let p = params.prec;
        let f_nodes = rule.nodes.iter().map(|u| contact.f(params, u, p)).collect();
        let nodes_f64 = rule.nodes.iter().map(Float::to_f64).collect();
        let factor = Float::with_val(p, params.cos_pi_theta.square_ref()) / &params.pi;
        Pressure { params, contact, rule, f_nodes, nodes_f64, f_raised: Default::default(), factor }
    }

    /// D(u) = sum_j w_j [F(u_j) - F(u)]/(u_j - u), for any real u (inside or outside [-1, 1]).
    ///
    /// A node closer to u than 2^(-prec/2) is replaced by F'(midpoint) (error O(|u_j - u|^2));
    /// when a node is closer than 2^-16 the whole sum is formed at a precision raised by the bits
    /// the difference quotient would lose.
    pub fn d(&self, u: &Float) -> Float {
        let p = self.params.prec;
        let uf = u.to_f64();
        let mut min_gap = f64::INFINITY;
        for &x in &self.nodes_f64 {
            let g = (x - uf).abs();
            if g < min_gap {
                min_gap = g;
            }
        }
        let lost = if min_gap < 1.0 / 65536.0 { ((-min_gap.max(1e-300).log2()).ceil() as u32).min(p) } else { 0 };
        let wp = p + lost;
        let fu = self.contact.f(self.params, u, wp);
        let near = Float::with_val(53, Float::i_exp(1, -(p as i32) / 2));
        // A node whose f64 distance exceeds `far` is not near (|x - u| > 2^(-p/2) whatever the
        // roundings of x, u and their f64 difference, each within 2^-52 of max(|x|, |u|)); only
        // the others are tested exactly (the test below), so that the common case allocates nothing.
        let near_f64 = near.to_f64();
        let far = if near_f64 > 0.0 { 2.0 * near_f64 } else { f64::INFINITY };
        let f_raised = (lost > 0).then(|| self.f_at_nodes(wp));
        let mut acc = Float::with_val(wp, 0);
        let mut t1 = Float::new(wp);
        let mut t2 = Float::new(wp);
        for (j, (x, w)) in self.rule.nodes.iter().zip(&self.rule.weights).enumerate() {
            t2.assign(x - u);
            let xf = self.nodes_f64[j];
            let surely_far = (xf - uf).abs() > far + (xf.abs() + uf.abs()) * f64::EPSILON;
            if !surely_far && Float::with_val(53, t2.abs_ref()) < near {
                let mid = Float::with_val(wp, x + u) / 2u32;
                t1 = self.contact.f_prime(self.params, &mid, wp);
            } else {
                if let Some(f) = &f_raised {
                    t1.assign(&f[j]);
                    t1 -= &fu;
                } else {
                    t1.assign(&self.f_nodes[j] - &fu);
                }
                t1 /= &t2;
            }
            t1 *= w;
            acc += &t1;
        }
        Float::with_val(p, acc)
    }

    /// F at every node at precision `wp`, computed once per precision.
    fn f_at_nodes(&self, wp: u32) -> std::sync::Arc<Vec<Float>> {
        let mut have = self.f_raised.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        if let Some((_, f)) = have.iter().find(|(q, _)| *q == wp) {
            return f.clone();
        }
        let f = std::sync::Arc::new(self.rule.nodes.iter().map(|x| self.contact.f(self.params, x, wp)).collect());
        have.push((wp, std::sync::Arc::clone(&f)));
        f
    }

    /// omega(u) = (1 + u)^{1/2 + theta} (1 - u)^{1/2 - theta}, u in [-1, 1].
    pub fn omega(&self, u: &Float) -> Float {
        let p = self.params.prec;
        let e1 = Float::with_val(p, &self.params.theta + 0.5f64);
        let e2 = Float::with_val(p, 0.5f64 - Float::with_val(p, &self.params.theta));
        let a = Float::with_val(p, u + 1u32).pow(&e1);
        let b = Float::with_val(p, 1u32 - Float::with_val(p, u)).pow(&e2);
        a * b
    }

    /// p(u) = omega(u) cos^2(pi theta) D(u)/pi [2.13], u in [-1, 1] (tangent variable).
    pub fn p(&self, u: &Float) -> Float {
        self.omega(u) * &self.factor * self.d(u)
    }

    /// p(u)/omega(u) = cos^2(pi theta) D(u)/pi (bounded, sign of p).
    pub fn p_over_omega(&self, u: &Float) -> Float {
        self.d(u) * &self.factor
    }

    /// Slope of the gap h' = g'(x) - v'(x) outside the contact, without the step -2 beta tau0/E*
    /// that the adhesive shear tau0 (discontinuous at the contact ends) adds to it everywhere
    /// outside (see [`super::physical`]): h' = g'(x) - g'_cont(x) + (2/E*) X(t) cos(pi theta) D(t)/pi,
    /// where g'_cont is the continuation used in F (differs from g' only for the periodic
    /// parabola beyond +-L/2). `x_minus_c` is x - c, t = u(x) with |t| > 1.
    pub fn gap_slope(&self, x_minus_c: &Float) -> Float {
        let s = self.params;
        let p = s.prec;
        let t = self.contact.size.u_of(s, x_minus_c, p);
        let e1 = Float::with_val(p, &s.theta + 0.5f64);
        let e2 = Float::with_val(p, 0.5f64 - Float::with_val(p, &s.theta));
        let tp = Float::with_val(p, &t + 1u32).abs().pow(&e1);
        let tm = Float::with_val(p, &t - 1u32).abs().pow(&e2);
        let mut xt = tp * tm;
        if t.is_sign_negative() {
            xt = -xt;
        }
        if is_general(&s.shape) {
            return self.general_gap_slope(x_minus_c, &t, &xt);
        }
        let mut h = xt * self.d(&t) * &s.cos_pi_theta / &s.pi * 2u32; // (2/E*) with E* = 1 (units of E*)
        if let (ShapeMpfr::Parabolic { k }, Some(big_l)) = (&s.shape, &s.period) {
            // True slope 2k (x - n L) vs the continuation 2k x(t), x(t) in (c - L/2, c + L/2).
            let x = Float::with_val(p, x_minus_c + &self.contact.c);
            let n = Float::with_val(p, &x / big_l).round();
            let x_true = Float::with_val(p, &x - Float::with_val(p, &n * big_l));
            let off = self.contact.size.offset(s, &t, p);
            let x_cont = Float::with_val(p, &off + &self.contact.c);
            h += Float::with_val(p, x_true - x_cont) * k * 2u32;
        }
        h
    }

    /// [`Pressure::gap_slope`] of a polynomial or circular punch (docs/theory.md section 9), with
    /// g'_row the slope of the punch row ([`super::profile::row_slope`]: reduced to the cell;
    /// +-infinity beyond the circle's |x| >= R, where no punch is):
    /// h' = g'_row(x) - g'(x(t)) + (2/E*) X(t) cos(pi theta) D(t)/pi while the analytic g' is
    /// defined at x(t) = c + (L/pi) arctan(m t) (always for a polynomial); otherwise (the circle
    /// beyond R, far from the contact) the unsubtracted form
    /// h' = g'_row(x) + (2/E*) X(t) cos(pi theta)/pi sum_j w_j F(u_j)/(u_j - t), which follows
    /// from D(t) = sum_j w_j F(u_j)/(u_j - t) - F(t) sum_j w_j/(u_j - t) and the exact
    /// int du/(omega (u - t)) = -pi/(cos(pi theta) X(t)).
    fn general_gap_slope(&self, x_minus_c: &Float, t: &Float, xt: &Float) -> Float {
        let s = self.params;
        let p = s.prec;
        let x = Float::with_val(p, x_minus_c + &self.contact.c);
        let row = row_slope(s, &x, p);
        if row.is_infinite() {
            return row;
        }
        let x_cont = Float::with_val(p, self.contact.size.offset(s, t, p) + &self.contact.c);
        let cont = profile_slope(&s.shape, &x_cont, p);
        let factor = Float::with_val(p, xt * &s.cos_pi_theta) / &s.pi * 2u32;
        if cont.is_finite() {
            return Float::with_val(p, &factor * self.d(t)) + Float::with_val(p, &row - &cont);
        }
        let mut sum = Float::with_val(p, 0);
        for ((u, w), f) in self.rule.nodes.iter().zip(&self.rule.weights).zip(&self.f_nodes) {
            sum += Float::with_val(p, w * f) / Float::with_val(p, u - t);
        }
        row + factor * sum
    }

    /// (P2, F_def) = (int p dx, int p g' dx) over the contact, by the n-point rule `rule_omega`
    /// for the weight omega: int p x'(u) du = cos^2(pi theta)/pi sum_i w_i D(u_i) x'(u_i).
    pub(crate) fn load_and_deformation_force(&self, rule_omega: &GaussJacobiRule) -> (Float, Float) {
        let s = self.params;
        let p = s.prec;
        let mut p2 = Float::with_val(p, 0);
        let mut fd = Float::with_val(p, 0);
        for (u, w) in rule_omega.nodes.iter().zip(&rule_omega.weights) {
            let v = self.d(u) * w * self.contact.size.jacobian(s, u, p);
            fd += Float::with_val(p, &v * self.contact.slope(s, u, p));
            p2 += v;
        }
        (p2 * &self.factor, fd * &self.factor)
    }
}
