//! The increments of the asymmetric incremental method (docs/theory.md sections 4, 10) in `f64`, for
//! the marching method ([`super::march`]) and the loading-law collocation's chord Jacobian
//! (K's log derivative; [`crate::loading_law`]); written anew from the formulas (the MPFR kernel
//! [`super::kernel`] is not called), and checked against it in the tests.
//!
//! Variables as in [`super::kernel`]: chi' = chi - gamma, the earlier contact of half-length eta;
//! d_near, d_far the distances of an outside point to the nearer and farther end; d_left,
//! d_right those of a contact point to the trailing and leading end. With s = +1 right of the
//! contact, -1 left of it, and S(d) = sin d for the periodic row (S(d) = d, cos -> 1 for the
//! single punch, the limit L -> infinity at fixed x/L-scaled lengths):
//!   L K = s cos(chi' - 2 i eps eta) (S(d_far)/S(d_near))^(s i eps) / sqrt(S(d_near) S(d_far)),
//!   L sigma_flat = cosh(pi eps) cos(chi' - 2 i eps eta) (S(d_left)/S(d_right))^(i eps)
//!                  / sqrt(S(d_left) S(d_right)).
//! The tilted punch of the `periodic` convention (rotation f = 1, no load; [`super::kernel::
//! TiltedPunch`]): with t = tan chi', m = tan eta, A + i B = -i ch e^(-2 eps eta)/cos eta,
//! A - i B = i ch e^(2 eps eta)/cos eta,
//!   rho = (m + t)^(-1/2 + i eps) (m - t)^(-1/2 - i eps) (A + B t) on the contact,
//!   R = Z(t) (A + B t)/ch outside, Z = |t + m|^(-1/2 + i eps) |t - m|^(-1/2 - i eps), times -1 left.
//! It exists only for the periodic row (the term i beta dP/L vanishes as L -> infinity).

use crate::numerics::sin_cos_f64::sin_cos;
use nalgebra::Complex;

/// Complex `f64`.
pub type C64 = Complex<f64>;

/// The side of the earlier contact an outside point lies on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// Toward the leading end b (s = +1).
    Right,
    /// Toward the trailing end -a (s = -1).
    Left,
}

impl Side {
    /// s = +1 (right) or -1 (left).
    pub fn sign(self) -> f64 {
        match self {
            Side::Right => 1.0,
            Side::Left => -1.0,
        }
    }
}

/// The material constants and the geometry of the increments.
#[derive(Debug, Clone, Copy)]
pub struct KernelF64 {
    /// eps = ln(3 - 4 nu)/(2 pi).
    pub eps: f64,
    /// cosh(pi eps).
    pub cosh_pi_eps: f64,
    /// beta = tanh(pi eps).
    pub beta: f64,
    /// The single punch (S(d) = d, cos -> 1) instead of the periodic row.
    pub single: bool,
}

/// The factors of the increment's slope outside that depend on the earlier contact's half-length
/// eta alone ([`KernelF64::eta_factors`]; the march evaluates many distances at one eta): cosh
/// and sinh of -2 eps eta (cos(chi' - 2 i eps eta) = cos chi' cosh - i sin chi' sinh), cos eta and
/// the rotation's (A, B). The same operations as without them: the values are bit for bit those
/// of [`KernelF64::increment_outside`].
#[derive(Debug, Clone, Copy)]
pub(crate) struct EtaFactors {
    cosh: f64,
    sinh: f64,
    cos_eta: f64,
    tilt: (C64, C64),
}

/// [`EtaFactors`] with sin eta, sin 2 eta and cos 2 eta: the march's tables
/// ([`super::march`]) evaluate many distances at one eta, and with these each distance costs one
/// sin_cos for sin d_near, sin d_far, cos chi' and sin chi' (the addition formulas; `outside_with`
/// takes three sines and cosines), and the rotation's R shares K's power
/// ([`KernelF64::increment_outside_node`]). Its sines and cosines (of d_near and of the phase) are
/// [`crate::numerics::sin_cos_f64`]'s, within 1 ulp of the correctly rounded ones.
#[derive(Debug, Clone, Copy)]
pub(crate) struct NodeFactors {
    base: EtaFactors,
    sin_eta: f64,
    sin_2eta: f64,
    cos_2eta: f64,
}

/// r e^(i theta) by [`sin_cos`] (the march's node kernel).
#[inline]
fn polar(r: f64, theta: f64) -> C64 {
    let (s, c) = sin_cos(theta);
    C64::new(r * c, r * s)
}

/// r^(-1/2 + i e) for r > 0.
fn power(r: f64, e: f64) -> C64 {
    C64::from_polar(1.0 / r.sqrt(), e * r.ln())
}

impl KernelF64 {
    fn s(&self, d: f64) -> f64 {
        if self.single {
            d
        } else {
            d.sin()
        }
    }

    /// cos(chi' - 2 i eps eta) (1 for the single punch).
    fn cos_factor(&self, chi: f64, eta: f64) -> C64 {
        if self.single {
            C64::new(1.0, 0.0)
        } else {
            C64::new(chi, -2.0 * self.eps * eta).cos()
        }
    }

    /// The factors of eta alone ([`EtaFactors`]); the rotation's only with `tilt` on the
    /// periodic row.
    pub(crate) fn eta_factors(&self, eta: f64, tilt: bool) -> EtaFactors {
        let im = -2.0 * self.eps * eta;
        let zero = C64::new(0.0, 0.0);
        let tilt = if tilt && !self.single { self.tilt_coefficients(eta) } else { (zero, zero) };
        EtaFactors { cosh: im.cosh(), sinh: im.sinh(), cos_eta: eta.cos(), tilt }
    }

    /// The factors of eta alone with its sines ([`NodeFactors`]).
    pub(crate) fn node_factors(&self, eta: f64, tilt: bool) -> NodeFactors {
        let (sin_2eta, cos_2eta) = (2.0 * eta).sin_cos();
        NodeFactors { base: self.eta_factors(eta, tilt), sin_eta: eta.sin(), sin_2eta, cos_2eta }
    }

    /// sin d_near, sin d_far, cos chi' and sin chi' at distance `d_near` on `side` (periodic row):
    /// one sin_cos and the addition formulas with the sines of eta and 2 eta.
    fn node_geometry(f: &NodeFactors, side: Side, d_near: f64) -> (f64, f64, f64, f64, f64) {
        let (sn, cn) = sin_cos(d_near);
        let sf = sn * f.cos_2eta + cn * f.sin_2eta;
        let cos_chi = cn * f.base.cos_eta - sn * f.sin_eta;
        let sin_chi = side.sign() * (sn * f.base.cos_eta + cn * f.sin_eta);
        (sn, cn, sf, cos_chi, sin_chi)
    }

    /// [`Self::increment_outside`] from [`NodeFactors`] ([`Self::node_factors`] with the same
    /// `tilt`): K by [`Self::node_geometry`]; the rotation's slope R = Z (A + B t)/ch with
    /// Z = s |t + m|^(-1/2 + i eps) |t - m|^(-1/2 - i eps) is cos eta cos chi' times K's power
    /// (S(d_far)/S(d_near))^(s i eps)/sqrt(S(d_near) S(d_far)) (its two powers are
    /// (S(d)/(cos eta cos chi'))^(-1/2 -+ i eps), whose product is that), t = sin chi'/cos chi'.
    /// The same values as [`Self::increment_outside`] to rounding (test
    /// `node_kernel_equals_the_direct_one`); the single punch takes that one.
    pub(crate) fn increment_outside_node(
        &self,
        f: &NodeFactors,
        side: Side,
        d_near: f64,
        eta: f64,
        n: f64,
        tilt: bool,
    ) -> C64 {
        if self.single {
            return self.increment_outside_with(&f.base, side, d_near, eta, n, tilt);
        }
        let sg = side.sign();
        let (sn, _, sf, cos_chi, sin_chi) = Self::node_geometry(f, side, d_near);
        let phase = polar(sg / (sn * sf).sqrt(), sg * self.eps * (sf / sn).ln());
        let mut k = C64::new(cos_chi * f.base.cosh, -sin_chi * f.base.sinh) * phase;
        if tilt {
            k += self.node_tilt(f, phase, cos_chi, sin_chi) * C64::new(0.0, self.beta);
        }
        k * C64::new(1.0, n)
    }

    /// R from K's `phase` (see [`Self::increment_outside_node`]); NaN where cos eta cos chi' <= 0,
    /// as the direct powers of a negative ratio give.
    fn node_tilt(&self, f: &NodeFactors, phase: C64, cos_chi: f64, sin_chi: f64) -> C64 {
        let (a, b) = f.base.tilt;
        let cc = f.base.cos_eta * cos_chi;
        let cc = if cc > 0.0 { cc } else { f64::NAN };
        phase * cc * (a + b * (sin_chi / cos_chi)) / self.cosh_pi_eps
    }

    /// [`Self::increment_outside_node`] and its derivative in `d_near`, as
    /// [`Self::increment_with_derivative`] (the log derivatives' cotangents and tangents from
    /// [`Self::node_geometry`]: cot d_far = cos d_far/sin d_far, tan(chi' - 2 i eps eta) from
    /// cos chi', sin chi' and the cosh, sinh of 2 eps eta).
    pub(crate) fn increment_with_derivative_node(
        &self,
        f: &NodeFactors,
        side: Side,
        d_near: f64,
        eta: f64,
        n: f64,
        tilt: bool,
    ) -> (C64, C64) {
        if self.single {
            return self.increment_with_derivative_with(&f.base, side, d_near, eta, n, tilt);
        }
        let sg = side.sign();
        let (sn, cn, sf, cos_chi, sin_chi) = Self::node_geometry(f, side, d_near);
        let cf = cn * f.cos_2eta - sn * f.sin_2eta;
        let (c_near, c_far) = (cn / sn, cf / sf);
        let phase = polar(sg / (sn * sf).sqrt(), sg * self.eps * (sf / sn).ln());
        let (ch, sh) = (f.base.cosh, f.base.sinh);
        let cos_z = C64::new(cos_chi * ch, -sin_chi * sh);
        let sin_z = C64::new(sin_chi * ch, cos_chi * sh);
        let k = cos_z * phase;
        let log_k = C64::new(-(c_near + c_far) / 2.0, sg * self.eps * (c_far - c_near)) - sin_z / cos_z * sg;
        let (mut value, mut slope) = (k, k * log_k);
        if tilt {
            let r = self.node_tilt(f, phase, cos_chi, sin_chi) * C64::new(0.0, self.beta);
            let (a, b) = f.base.tilt;
            let t = sin_chi / cos_chi;
            let (near, far) = (c_near + sg * t, c_far + sg * t);
            let (tp, tm) = match side {
                Side::Right => (far, near),
                Side::Left => (near, far),
            };
            let log_r =
                C64::new(-0.5, self.eps) * tp + C64::new(-0.5, -self.eps) * tm + b * (sg * (1.0 + t * t)) / (a + b * t);
            value += r;
            slope += r * log_r;
        }
        let one_in = C64::new(1.0, n);
        (value * one_in, slope * one_in)
    }

    /// L K at distance `d_near` > 0 from the nearer end of a contact of half-length `eta`, on
    /// `side` (module doc).
    pub fn outside(&self, side: Side, d_near: f64, eta: f64) -> C64 {
        self.outside_with(side, d_near, eta, &self.eta_factors(eta, false))
    }

    /// [`Self::outside`] with the factors of eta given.
    fn outside_with(&self, side: Side, d_near: f64, eta: f64, f: &EtaFactors) -> C64 {
        let sg = side.sign();
        let d_far = d_near + 2.0 * eta;
        let (sn, sf) = (self.s(d_near), self.s(d_far));
        let chi = sg * (d_near + eta);
        let phase = C64::from_polar(sg / (sn * sf).sqrt(), sg * self.eps * (sf / sn).ln());
        let cos = if self.single { C64::new(1.0, 0.0) } else { C64::new(chi.cos() * f.cosh, -chi.sin() * f.sinh) };
        cos * phase
    }

    /// d ln(L K)/d d_near at the same point: with C(d) = cot d (1/d for the single punch),
    ///   -(C(d_near) + C(d_far))/2 + s i eps (C(d_far) - C(d_near)) - s tan(chi' - 2 i eps eta)
    /// (no tangent for the single punch), as [`super::kernel::outside_kernel_log_derivative`];
    /// for the chord Jacobian of the loading-law collocation ([`crate::loading_law`]).
    pub(crate) fn outside_log_derivative(&self, side: Side, d_near: f64, eta: f64) -> C64 {
        let sg = side.sign();
        let d_far = d_near + 2.0 * eta;
        let cot = |d: f64| if self.single { 1.0 / d } else { 1.0 / d.tan() };
        let (c_near, c_far) = (cot(d_near), cot(d_far));
        let out = C64::new(-(c_near + c_far) / 2.0, sg * self.eps * (c_far - c_near));
        if self.single {
            return out;
        }
        out - C64::new(sg * (d_near + eta), -2.0 * self.eps * eta).tan() * sg
    }

    /// L sigma_flat at the contact point with distances `d_left`, `d_right` to the trailing and
    /// leading ends (module doc).
    pub(crate) fn flat_stress(&self, d_left: f64, d_right: f64, eta: f64) -> C64 {
        let chi = 0.5 * (d_left - d_right);
        let (sl, sr) = (self.s(d_left), self.s(d_right));
        let phase = C64::from_polar(self.cosh_pi_eps / (sl * sr).sqrt(), self.eps * (sl / sr).ln());
        self.cos_factor(chi, eta) * phase
    }

    /// (A, B) of the rotation (module doc), periodic row only.
    fn tilt_coefficients(&self, eta: f64) -> (C64, C64) {
        let (ch, grow, cos) = (self.cosh_pi_eps, (2.0 * self.eps * eta).exp(), eta.cos());
        let plus = C64::new(0.0, -ch / (grow * cos));
        let minus = C64::new(0.0, ch * grow / cos);
        ((plus + minus) * 0.5, (plus - minus) / C64::new(0.0, 2.0))
    }

    /// The rotation's stress rho on the contact (module doc); zero for the single punch.
    pub(crate) fn tilt_stress(&self, d_left: f64, d_right: f64, eta: f64) -> C64 {
        if self.single {
            return C64::new(0.0, 0.0);
        }
        let (a, b) = self.tilt_coefficients(eta);
        let chi = 0.5 * (d_left - d_right);
        let cc = eta.cos() * chi.cos();
        let x = power(d_left.sin() / cc, self.eps) * power(d_right.sin() / cc, -self.eps);
        x * (a + b * chi.tan())
    }

    /// The rotation's slope R outside (module doc); zero for the single punch.
    pub(crate) fn tilt_outside(&self, side: Side, d_near: f64, eta: f64) -> C64 {
        self.tilt_outside_with(side, d_near, eta, &self.eta_factors(eta, true))
    }

    /// [`Self::tilt_outside`] with the factors of eta given.
    fn tilt_outside_with(&self, side: Side, d_near: f64, eta: f64, f: &EtaFactors) -> C64 {
        if self.single {
            return C64::new(0.0, 0.0);
        }
        let (a, b) = f.tilt;
        let d_far = d_near + 2.0 * eta;
        let chi = side.sign() * (d_near + eta);
        let cc = f.cos_eta * chi.cos();
        let (near, far) = (d_near.sin() / cc, d_far.sin() / cc);
        let (tp, tm) = match side {
            Side::Right => (far, near),
            Side::Left => (near, far),
        };
        let z = power(tp, self.eps) * power(tm, -self.eps) * side.sign();
        z * (a + b * chi.tan()) / self.cosh_pi_eps
    }

    /// The surface slope left outside by the increment dP = (1 + i n) dP2 of unit dP2 in the
    /// `periodic` convention or not: (1 + i n) (L K + i beta R) ([`crate::loading_law::collocation`]'s
    /// edge integrand; docs/theory.md section 8, Problem 2: the increment's i beta dP/L keeps v and
    /// u periodic).
    pub(crate) fn increment_outside(&self, side: Side, d_near: f64, eta: f64, n: f64, tilt: bool) -> C64 {
        self.increment_outside_with(&self.eta_factors(eta, tilt), side, d_near, eta, n, tilt)
    }

    /// [`Self::increment_outside`] with the factors of eta given ([`Self::eta_factors`] with
    /// the same `tilt`).
    pub(crate) fn increment_outside_with(
        &self,
        f: &EtaFactors,
        side: Side,
        d_near: f64,
        eta: f64,
        n: f64,
        tilt: bool,
    ) -> C64 {
        let mut k = self.outside_with(side, d_near, eta, f);
        if tilt {
            k += self.tilt_outside_with(side, d_near, eta, f) * C64::new(0.0, self.beta);
        }
        k * C64::new(1.0, n)
    }

    /// d ln R/d d_near of the rotation's slope outside (module doc), periodic row only, with the
    /// rotation's (A, B) at eta given: with t = tan chi' and near, far = S(d_near), S(d_far)
    /// over cos eta cos chi',
    ///   (-1/2 + i eps) d ln t_+ + (-1/2 - i eps) d ln t_- + s B (1 + t^2)/(A + B t),
    /// d ln near = cot d_near + s t, d ln far = cot d_far + s t (t_+ = far right, near left).
    fn tilt_outside_log_derivative_with(&self, side: Side, d_near: f64, eta: f64, (a, b): (C64, C64)) -> C64 {
        let sg = side.sign();
        let t = (sg * (d_near + eta)).tan();
        let (near, far) = (1.0 / d_near.tan() + sg * t, 1.0 / (d_near + 2.0 * eta).tan() + sg * t);
        let (tp, tm) = match side {
            Side::Right => (far, near),
            Side::Left => (near, far),
        };
        C64::new(-0.5, self.eps) * tp + C64::new(-0.5, -self.eps) * tm + b * (sg * (1.0 + t * t)) / (a + b * t)
    }

    /// [`Self::increment_outside`] and its derivative in `d_near` (the closed-form Jacobian of the
    /// march, [`super::march`]): (1 + i n) (L K D_K + i beta R D_R) with D_K, D_R the log
    /// derivatives of L K ([`Self::outside_log_derivative`]) and of R.
    #[cfg(test)]
    pub(crate) fn increment_with_derivative(
        &self,
        side: Side,
        d_near: f64,
        eta: f64,
        n: f64,
        tilt: bool,
    ) -> (C64, C64) {
        self.increment_with_derivative_with(&self.eta_factors(eta, tilt), side, d_near, eta, n, tilt)
    }

    /// [`Self::increment_with_derivative`] with the factors of eta given ([`Self::eta_factors`]
    /// with the same `tilt`): the same operations, bit for bit.
    pub(crate) fn increment_with_derivative_with(
        &self,
        f: &EtaFactors,
        side: Side,
        d_near: f64,
        eta: f64,
        n: f64,
        tilt: bool,
    ) -> (C64, C64) {
        let k = self.outside_with(side, d_near, eta, f);
        let mut value = k;
        let mut slope = k * self.outside_log_derivative(side, d_near, eta);
        if tilt && !self.single {
            let r = self.tilt_outside_with(side, d_near, eta, f) * C64::new(0.0, self.beta);
            value += r;
            slope += r * self.tilt_outside_log_derivative_with(side, d_near, eta, f.tilt);
        }
        let one_in = C64::new(1.0, n);
        (value * one_in, slope * one_in)
    }

    /// The stress of the same increment on the contact: (1 + i n) (L sigma_flat + i beta rho).
    pub(crate) fn increment_stress(&self, d_left: f64, d_right: f64, eta: f64, n: f64, tilt: bool) -> C64 {
        let mut s = self.flat_stress(d_left, d_right, eta);
        if tilt {
            s += self.tilt_stress(d_left, d_right, eta) * C64::new(0.0, self.beta);
        }
        s * C64::new(1.0, n)
    }
}

#[cfg(test)]
mod tests {
    use super::super::kernel::{self, TiltedPunch};
    use super::*;
    use rug::float::Constant;
    use rug::Float;

    const PREC: u32 = 120;

    /// Every f64 formula against the MPFR kernel (an independent transcription, itself checked
    /// against the direct cot-kernel quadrature) at nu = 0.3, to 1e-14 relative; and the single
    /// punch as the limit of the periodic row: lengths scaled by 1e-4 (K scales as 1/length).
    #[test]
    fn f64_kernel_matches_the_mpfr_kernel() {
        let pi = Float::with_val(PREC, Constant::Pi);
        let eps_m = Float::with_val(PREC, Float::with_val(PREC, 1.8).ln_ref()) / (pi.clone() * 2u32);
        let ch_m = Float::with_val(PREC, Float::with_val(PREC, &pi * &eps_m).cosh_ref());
        let eps = eps_m.to_f64();
        let k = KernelF64 { eps, cosh_pi_eps: ch_m.to_f64(), beta: (std::f64::consts::PI * eps).tanh(), single: false };
        let f = |v: f64| Float::with_val(PREC, v);
        let close = |a: C64, b: rug::Complex| {
            let (br, bi) = (b.real().to_f64(), b.imag().to_f64());
            let e = ((a.re - br).powi(2) + (a.im - bi).powi(2)).sqrt() / (br * br + bi * bi).sqrt();
            assert!(e < 1e-14, "{a} vs {br} {bi}: {e:e}");
        };
        let eta = 0.6;
        let tilt = TiltedPunch::rotation(&f(eta), &eps_m, &ch_m, PREC);
        for (side, ms) in [(Side::Right, kernel::Side::Right), (Side::Left, kernel::Side::Left)] {
            for d in [1e-9, 0.01, 0.3, 0.7] {
                close(
                    k.outside(side, d, eta),
                    kernel::outside_kernel(kernel::Row::Periodic, ms, &f(d), &f(eta), &eps_m, PREC),
                );
                close(k.tilt_outside(side, d, eta), tilt.outside(ms, &f(d), &f(eta), &eps_m, &ch_m, PREC));
                close(
                    k.outside_log_derivative(side, d, eta),
                    kernel::outside_kernel_log_derivative(kernel::Row::Periodic, ms, &f(d), &f(eta), &eps_m, PREC),
                );
            }
        }
        for (dl, dr) in [(1e-9, 1.2 - 1e-9), (0.3, 0.9), (1.1, 0.1), (0.6, 0.6)] {
            close(
                k.flat_stress(dl, dr, eta),
                kernel::flat_punch_stress(kernel::Row::Periodic, &f(dl), &f(dr), &f(eta), &eps_m, &ch_m, PREC),
            );
            close(k.tilt_stress(dl, dr, eta), tilt.stress(&f(dl), &f(dr), &f(eta), &eps_m, PREC));
        }
        let single = KernelF64 { single: true, ..k };
        let s = 1e-4;
        for side in [Side::Right, Side::Left] {
            let (a, b) = (single.outside(side, 0.3, 0.6), k.outside(side, 0.3 * s, 0.6 * s) * s);
            assert!((a - b).norm() < 1e-7 * a.norm(), "{a} vs {b}");
        }
        let (a, b) = (single.flat_stress(0.3, 0.9, 0.6), k.flat_stress(0.3 * s, 0.9 * s, 0.6 * s) * s);
        assert!((a - b).norm() < 1e-7 * a.norm(), "{a} vs {b}");
        // The single punch against the MPFR kernel's Row::Single.
        for (side, ms) in [(Side::Right, kernel::Side::Right), (Side::Left, kernel::Side::Left)] {
            close(
                single.outside(side, 0.3, 0.6),
                kernel::outside_kernel(kernel::Row::Single, ms, &f(0.3), &f(0.6), &eps_m, PREC),
            );
            close(
                single.outside_log_derivative(side, 0.3, 0.6),
                kernel::outside_kernel_log_derivative(kernel::Row::Single, ms, &f(0.3), &f(0.6), &eps_m, PREC),
            );
        }
        // The increment's derivative in d_near against central differences (step 1e-6: their
        // error about 1e-11 of the value), both rows, tilted or not, both sides.
        for (kern, tilt) in [(k, false), (k, true), (single, false)] {
            for side in [Side::Right, Side::Left] {
                for d in [0.01, 0.3, 0.7] {
                    let (v, dv) = kern.increment_with_derivative(side, d, eta, 0.2, tilt);
                    assert!((v - kern.increment_outside(side, d, eta, 0.2, tilt)).norm() <= 1e-15 * v.norm());
                    let h = 1e-6 * d;
                    let fd = (kern.increment_outside(side, d + h, eta, 0.2, tilt)
                        - kern.increment_outside(side, d - h, eta, 0.2, tilt))
                        / (2.0 * h);
                    assert!((dv - fd).norm() < 1e-8 * dv.norm(), "{side:?} {d} {tilt}: {dv} vs {fd}");
                }
            }
        }
        close(
            single.flat_stress(0.3, 0.9, 0.6),
            kernel::flat_punch_stress(kernel::Row::Single, &f(0.3), &f(0.9), &f(0.6), &eps_m, &ch_m, PREC),
        );
    }

    /// The march's node kernel ([`KernelF64::increment_outside_node`], by the addition formulas
    /// and the rotation's power shared with K) against the direct one, and its derivative
    /// against [`KernelF64::increment_with_derivative`], at nu = 0.3 (eps = ln 1.8/(2 pi)), both
    /// sides, tilted or not, eta = 0.05 .. 1, d_near = 1e-12 .. 0.9: equal to 2e-14 of the value
    /// (the derivative: of its own size), and NaN where the direct rotation is (cos chi' < 0);
    /// the single punch takes the direct formulas.
    #[test]
    fn node_kernel_equals_the_direct_one() {
        let eps = 1.8f64.ln() / (2.0 * std::f64::consts::PI);
        let pe = std::f64::consts::PI * eps;
        let k = KernelF64 { eps, cosh_pi_eps: pe.cosh(), beta: pe.tanh(), single: false };
        let mut worst: f64 = 0.0;
        for kern in [k, KernelF64 { single: true, ..k }] {
            for tilt in [false, true] {
                for eta in [0.05, 0.3, 0.6, 1.0] {
                    let f = kern.node_factors(eta, tilt);
                    for side in [Side::Right, Side::Left] {
                        for d in [1e-12, 1e-6, 0.01, 0.3, 0.9] {
                            let a = kern.increment_outside_node(&f, side, d, eta, 0.2, tilt);
                            let b = kern.increment_outside(side, d, eta, 0.2, tilt);
                            if b.re.is_nan() {
                                // The rotation's powers of a negative ratio (d_near + eta > pi/2).
                                assert!(tilt && d + eta > std::f64::consts::FRAC_PI_2 && a.re.is_nan(), "{a} vs {b}");
                                continue;
                            }
                            let e = (a - b).norm() / b.norm();
                            assert!(e < 2e-14, "{side:?} d {d} eta {eta} tilt {tilt}: {a} vs {b}");
                            let (va, da) = kern.increment_with_derivative_node(&f, side, d, eta, 0.2, tilt);
                            let (vb, db) = kern.increment_with_derivative(side, d, eta, 0.2, tilt);
                            assert!((va - a).norm() <= 1e-15 * a.norm(), "value {va} vs {a}");
                            assert!((vb - b).norm() <= 1e-15 * b.norm(), "value {vb} vs {b}");
                            let e2 = (da - db).norm() / db.norm();
                            assert!(e2 < 2e-14, "derivative {side:?} d {d} eta {eta} tilt {tilt}: {da} vs {db}");
                            worst = worst.max(e).max(e2);
                        }
                    }
                }
            }
        }
        assert!(worst > 0.0, "the node formulas differ from the direct ones in rounding somewhere");
    }
}
