//! The increments of the asymmetric incremental method (docs/theory.md section 10) in MPFR: the
//! unit-load adhesive flat punch on an off-centre contact and its surface slopes outside it.
//!
//! Variables: chi = pi x/L; the earlier contact has centre gamma = pi c/L and half-length
//! eta = pi l/L; chi' = chi - gamma. Inside (|chi'| < eta), the unit complex load gives
//!   sigma_flat = (cosh(pi eps)/L) cos(chi' - 2 i eps eta) (sin(eta + chi')/sin(eta - chi'))^(i eps)
//!                / sqrt(sin^2 eta - sin^2 chi')                                   (THEORY 4)
//! and a load dP = dP2 + i dP1 gives d sigma = dP sigma_flat (the operator H + i beta of [2.19]
//! is complex-linear). Outside (|chi'| > eta), (E*/2)(dv' - i du') = dP K/L with
//!   K = s cos(chi' - 2 i eps eta) (sin d_far/sin d_near)^(s i eps) / sqrt(sin d_near sin d_far),
//! s = +1 right of the contact (chi' > eta), -1 left of it; d_near = |chi'| - eta > 0 and
//! d_far = |chi'| + eta the distances to the nearer and farther end. For s = +1 this is THEORY
//! 4's K(chi', eta); the left side is its continuation, K(-chi') = -conj K(chi') (Re v' odd, u'
//! even), which THEORY 4 does not state: checked against the direct quadrature of the cot
//! kernel [1.8] in this module's test (and first in mpmath, 30 digits, session 4 notes).
//! Passing d_near (not chi') keeps the singular factor accurate next to the end, where the
//! incremental method evaluates it.

use rug::{Complex, Float};

/// The row: a periodic row (the kernels of the module doc, in chi = pi x/L), or the single punch
/// (L -> infinity): with the length unit U and chi = x/U the same formulas hold with L = pi U and
/// sin z -> z, cos(chi' - 2 i eps eta) -> 1 (the leading terms as pi U/L -> 0; docs/theory.md 10's
/// single-punch limit), so every caller keeps its scalings.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Row {
    /// Period L.
    Periodic,
    /// L = infinity.
    Single,
}

impl Row {
    /// sin z, or z for the single punch.
    fn sin(self, z: &Float, prec: u32) -> Float {
        match self {
            Row::Periodic => Float::with_val(prec, z.sin_ref()),
            Row::Single => Float::with_val(prec, z),
        }
    }
    /// cos(chi' - 2 i eps eta), or 1 for the single punch.
    fn cos_shift(self, chi: Float, eps: &Float, eta: &Float, prec: u32) -> Complex {
        match self {
            Row::Periodic => {
                // cos(chi - i b) = cos chi cosh b + i sin chi sinh b, b = 2 eps eta (one sin_cos
                // and one sinh_cosh: a third of the complex cosine's cost).
                let b = Float::with_val(prec, eps * eta) * 2u32;
                let (sin, cos) = chi.sin_cos(Float::new(prec));
                let (sinh, cosh) = b.sinh_cosh(Float::new(prec));
                Complex::with_val(prec, (cos * cosh, sin * sinh))
            }
            Row::Single => Complex::with_val(prec, 1),
        }
    }
}

/// Which side of the earlier contact the point lies on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// chi' > eta (toward the leading end b).
    Right,
    /// chi' < -eta (toward the trailing end -a).
    Left,
}

/// L K as a complex number (module doc) at distance `d_near` > 0 from the nearer end of a
/// contact of half-length `eta`, on `side`; `eps` of the material; `row` periodic or single.
pub fn outside_kernel(row: Row, side: Side, d_near: &Float, eta: &Float, eps: &Float, prec: u32) -> Complex {
    let d_far = Float::with_val(prec, d_near + eta) + eta;
    let chi = match side {
        Side::Right => Float::with_val(prec, d_near + eta),
        Side::Left => -Float::with_val(prec, d_near + eta),
    };
    let (s_near, s_far) = (row.sin(d_near, prec), row.sin(&d_far, prec));
    let cos = row.cos_shift(chi, eps, eta, prec);
    // (sin d_far/sin d_near)^(+- i eps) = exp(+- i eps ln(ratio)).
    let mut theta = Float::with_val(prec, Float::with_val(prec, &s_far / &s_near).ln_ref()) * eps;
    let mut mag = Float::with_val(prec, &s_near * &s_far).sqrt().recip();
    if side == Side::Left {
        theta = -theta;
        mag = -mag;
    }
    let (sin_t, cos_t) = theta.sin_cos(Float::new(prec));
    let phase = Complex::with_val(prec, (cos_t, sin_t));
    cos * phase * mag
}

/// d ln K/d d_near of [`outside_kernel`] (the Jacobian of `crate::loading_law::jacobian`): with
/// chi = +-(d + eta), d_far = d + 2 eta,
///   right: -tan(chi - 2 i eps eta) + i eps (cot d_far - cot d) - (cot d + cot d_far)/2,
///   left:  +tan(chi - 2 i eps eta) - i eps (cot d_far - cot d) - (cot d + cot d_far)/2,
/// and for the single punch tan -> 0, cot z -> 1/z.
pub fn outside_kernel_log_derivative(
    row: Row,
    side: Side,
    d_near: &Float,
    eta: &Float,
    eps: &Float,
    prec: u32,
) -> Complex {
    let d_far = Float::with_val(prec, d_near + eta) + eta;
    let cot = |z: &Float| match row {
        Row::Periodic => Float::with_val(prec, z.cot_ref()),
        Row::Single => Float::with_val(prec, z.recip_ref()),
    };
    let (c_near, c_far) = (cot(d_near), cot(&d_far));
    let real = -(Float::with_val(prec, &c_near + &c_far) / 2u32);
    let imag = Float::with_val(prec, &c_far - &c_near) * eps;
    let sign = if side == Side::Right { 1i32 } else { -1 };
    let mut out = Complex::with_val(prec, (real, imag * sign));
    if row == Row::Periodic {
        // tan(x + i y) = (sin 2x + i sinh 2y)/(cos 2x + cosh 2y), x = chi, y = -2 eps eta (real
        // functions: the complex tangent costs several times more).
        let two_x = Float::with_val(prec, d_near + eta) * (2 * sign);
        let two_y = Float::with_val(prec, eps * eta) * -4i32;
        let (sin, cos) = two_x.sin_cos(Float::new(prec));
        let (sinh, cosh) = two_y.sinh_cosh(Float::new(prec));
        let den = cos + cosh;
        let tan = Complex::with_val(prec, (Float::with_val(prec, &sin / &den), sinh / den));
        out -= tan * sign;
    }
    out
}

/// L sigma_flat (module doc) for the unit complex load at the point whose distances to the
/// trailing and leading ends are `d_left` = eta + chi' and `d_right` = eta - chi' (both > 0, given
/// separately so the end singularities keep their accuracy); `row` periodic or single.
pub fn flat_punch_stress(
    row: Row,
    d_left: &Float,
    d_right: &Float,
    eta: &Float,
    eps: &Float,
    cosh_pi_eps: &Float,
    prec: u32,
) -> Complex {
    let chi = Float::with_val(prec, d_left - d_right) / 2u32;
    let (sp, sm) = (row.sin(d_left, prec), row.sin(d_right, prec));
    // sin^2 eta - sin^2 chi' = sin(eta + chi') sin(eta - chi').
    let mag = Float::with_val(prec, &sp * &sm).sqrt().recip() * cosh_pi_eps;
    let theta = Float::with_val(prec, Float::with_val(prec, &sp / &sm).ln_ref()) * eps;
    let cos = row.cos_shift(chi, eps, eta, prec);
    let (sin_t, cos_t) = theta.sin_cos(Float::new(prec));
    let phase = Complex::with_val(prec, (cos_t, sin_t));
    cos * phase * mag
}

/// The tilted flat punch of the `periodic` convention (docs/theory.md section 8 applied to Problem 2):
/// with P1 != 0 the Flamant sum rotates the half-plane ((E*/2) mean v' = -beta P1/L), so in the
/// paper's frame a punch that does not rotate keeps (E*/2) v' = (E*/2) g' - beta P1/L on its
/// contact, and an increment dP brings, besides dP sigma_flat, the solution sigma_rot of
///   (H + i beta) sigma_rot = 1 on the contact,  int sigma_rot = 0,
/// times -beta dP1/L. Derivation (session 4): with t = tan chi', m = tan eta (THEORY 2's tangent
/// map: H = C + C0, C the Cauchy operator in t, C0 = (1/pi) int rho t'/(1 + t'^2) dt'), every
/// solution bounded at neither end is rho = X(t)(A + B t), X = (m + t)^(-1/2 + i eps)
/// (m - t)^(-1/2 - i eps); with Z(z) = (z + m)^(-1/2 + i eps) (z - m)^(-1/2 - i eps) (cut on
/// (-m, m), Z ~ 1/z) the Plemelj formulas give (C + i beta) rho = -B/cosh(pi eps) on the contact
/// (beta = tanh(pi eps)), and residues at z = +-i give C0 and the load, so that
///   Z(i)(A + i B) = -cosh(pi eps)(f + i P/L),  Z(-i)(A - i B) = -cosh(pi eps)(f - i P/L)
/// for (H + i beta) rho = f with load P; outside, H\[rho\](t) = Z(t)(A + B t)/cosh(pi eps) + f.
/// The rotation is f = 1, P = 0. (The same formulas with f = 0, P = 1 reproduce sigma_flat and K:
/// checked in the tests.)
#[derive(Debug, Clone)]
pub struct TiltedPunch {
    a: Complex,
    b: Complex,
}

/// (z + m)^(-1/2 + i eps) (z - m)^(-1/2 - i eps), principal branches (the tests' check of the
/// closed forms of Z(+-i)).
#[cfg(test)]
fn z_function(z: &Complex, m: &Float, eps: &Float, prec: u32) -> Complex {
    let e1 = Complex::with_val(prec, (-0.5, eps));
    let e2 = Complex::with_val(prec, (-0.5, Float::with_val(prec, -eps)));
    let zp = Complex::with_val(prec, z + m);
    let zm = Complex::with_val(prec, z - m);
    Complex::with_val(prec, zp.ln() * e1).exp() * Complex::with_val(prec, zm.ln() * e2).exp()
}

impl TiltedPunch {
    /// The solution rho = X (A + B t) of (H + i beta) rho = `f` with load `p_over_l` = P/L on the
    /// contact of half-length `eta` (doc above).
    pub fn new(f: &Complex, p_over_l: &Complex, eta: &Float, eps: &Float, cosh_pi_eps: &Float, prec: u32) -> Self {
        // Z(+-i) in closed form: i +- m = +-i e^(-+i eta)/cos eta (principal arguments
        // +-(pi/2 - eta) and +-(pi/2 + eta)) give Z(i) = -i cos(eta) e^(2 eps eta) and
        // Z(-i) = i cos(eta) e^(-2 eps eta) (checked against the principal branches in the tests).
        let i = Complex::with_val(prec, (0, 1));
        let cos = Float::with_val(prec, eta.cos_ref());
        let grow = Float::with_val(prec, Float::with_val(prec, eps * eta) * 2u32).exp();
        let ip = Complex::with_val(prec, &i * p_over_l);
        // A + iB = -ch (f + iP/L)/Z(i) = -i ch (f + iP/L) e^(-2 eps eta)/cos eta; A - iB likewise.
        let scale_plus = Float::with_val(prec, cosh_pi_eps / &grow) / &cos;
        let scale_minus = Float::with_val(prec, cosh_pi_eps * &grow) / &cos;
        let plus = Complex::with_val(prec, f + &ip) * &i * scale_plus * -1i32;
        let minus = Complex::with_val(prec, f - &ip) * &i * scale_minus;
        let a = Complex::with_val(prec, &plus + &minus) / 2u32;
        let b = Complex::with_val(prec, &plus - &minus) / Complex::with_val(prec, &i * 2u32);
        TiltedPunch { a, b }
    }

    /// The rotation of the doc above (f = 1, P = 0).
    pub fn rotation(eta: &Float, eps: &Float, cosh_pi_eps: &Float, prec: u32) -> Self {
        TiltedPunch::new(&Complex::with_val(prec, 1), &Complex::new(prec), eta, eps, cosh_pi_eps, prec)
    }

    /// rho on the contact at the point with distances `d_left`, `d_right` to its ends (as in
    /// [`flat_punch_stress`]): t +- m = sin(eta +- chi')/(cos eta cos chi').
    pub fn stress(&self, d_left: &Float, d_right: &Float, eta: &Float, eps: &Float, prec: u32) -> Complex {
        let chi = Float::with_val(prec, d_left - d_right) / 2u32;
        let cc = Float::with_val(prec, eta.cos_ref()) * Float::with_val(prec, chi.cos_ref());
        let tp = Float::with_val(prec, d_left.sin_ref()) / &cc; // m + t
        let tm = Float::with_val(prec, d_right.sin_ref()) / &cc; // m - t
        let x = power(&tp, eps, 1, prec) * power(&tm, eps, -1, prec);
        let t = Float::with_val(prec, chi.tan_ref());
        x * Complex::with_val(prec, &self.a + Complex::with_val(prec, &self.b * &t))
    }

    /// Z(t)(A + B t)/cosh(pi eps) outside the contact (H\[rho\] - f), at distance `d_near` from the
    /// nearer end on `side`.
    pub fn outside(
        &self,
        side: Side,
        d_near: &Float,
        eta: &Float,
        eps: &Float,
        cosh_pi_eps: &Float,
        prec: u32,
    ) -> Complex {
        let d_far = Float::with_val(prec, d_near + eta) + eta;
        let chi = match side {
            Side::Right => Float::with_val(prec, d_near + eta),
            Side::Left => -Float::with_val(prec, d_near + eta),
        };
        let cc = Float::with_val(prec, eta.cos_ref()) * Float::with_val(prec, chi.cos_ref());
        let (s_near, s_far) = (Float::with_val(prec, d_near.sin_ref()), Float::with_val(prec, d_far.sin_ref()));
        // |t + m| and |t - m|: on the right t + m = far, t - m = near; on the left mirrored.
        let (tp, tm) = match side {
            Side::Right => (s_far / &cc, s_near / &cc),
            Side::Left => (s_near / &cc, s_far / &cc),
        };
        let mut z = power(&tp, eps, 1, prec) * power(&tm, eps, -1, prec);
        if side == Side::Left {
            z = -z; // the phase e^(i pi (-1/2 + i eps)) e^(i pi (-1/2 - i eps)) = -1 of Z there.
        }
        let t = Float::with_val(prec, chi.tan_ref());
        z * Complex::with_val(prec, &self.a + Complex::with_val(prec, &self.b * &t)) / cosh_pi_eps
    }

    /// d ln/d d_near of [`Self::outside`] (the Jacobian of `crate::loading_law::jacobian`): with
    /// chi = +-(d + eta), the factor 1/(cos eta cos chi) of t +- m contributes +tan chi on the
    /// right and -tan chi on the left:
    ///   right: (-1/2 + i eps)(cot d_far + tan chi) + (-1/2 - i eps)(cot d + tan chi)
    ///          + B sec^2 chi/(A + B tan chi),
    ///   left:  (-1/2 + i eps)(cot d - tan chi) + (-1/2 - i eps)(cot d_far - tan chi)
    ///          - B sec^2 chi/(A + B tan chi).
    pub fn outside_log_derivative(&self, side: Side, d_near: &Float, eta: &Float, eps: &Float, prec: u32) -> Complex {
        let d_far = Float::with_val(prec, d_near + eta) + eta;
        let sign = if side == Side::Right { 1i32 } else { -1 };
        let chi = Float::with_val(prec, d_near + eta) * sign;
        let tan = Float::with_val(prec, chi.tan_ref());
        let sec2 = Float::with_val(prec, tan.square_ref()) + 1u32;
        let (c_near, c_far) = (Float::with_val(prec, d_near.cot_ref()), Float::with_val(prec, d_far.cot_ref()));
        let shift = Float::with_val(prec, &tan * sign);
        let (first, second) = match side {
            Side::Right => (c_far + &shift, c_near + &shift),
            Side::Left => (c_near + &shift, c_far + &shift),
        };
        let e_plus = Complex::with_val(prec, (-0.5, eps));
        let e_minus = Complex::with_val(prec, (-0.5, Float::with_val(prec, -eps)));
        let linear = Complex::with_val(prec, &self.a + Complex::with_val(prec, &self.b * &tan));
        let tail = Complex::with_val(prec, &self.b * &sec2) / linear * sign;
        e_plus * first + e_minus * second + tail
    }
}

/// r^(-1/2 + sign i eps) for r > 0.
fn power(r: &Float, eps: &Float, sign: i32, prec: u32) -> Complex {
    let ln = Float::with_val(prec, r.ln_ref());
    let mag = Float::with_val(prec, r.sqrt_ref()).recip();
    let theta = Float::with_val(prec, &ln * eps) * sign;
    let (sin, cos) = theta.sin_cos(Float::new(prec));
    Complex::with_val(prec, (cos, sin)) * mag
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::tanh_sinh::TanhSinh;
    use rug::float::Constant;

    const PREC: u32 = 160;

    fn f(v: f64) -> Float {
        Float::with_val(PREC, v)
    }

    /// eps of nu = 0.3: ln(3 - 4 nu)/(2 pi).
    fn eps() -> Float {
        let pi = Float::with_val(PREC, Constant::Pi);
        Float::with_val(PREC, Float::with_val(PREC, 1.8).ln_ref()) / (pi * 2u32)
    }

    /// int over the contact (-eta, eta) of L sigma_flat(xi) w(xi) by tanh-sinh on each half
    /// (the ends are inverse-square-root singular), with chi' = eta (1 - 2 u) mapping.
    fn integrate(eta: &Float, w: impl Fn(&Float) -> Complex) -> Complex {
        let e = eps();
        let ch = Float::with_val(PREC, Float::with_val(PREC, Constant::Pi) * &e).cosh();
        let rule = TanhSinh::new(150, 3.0, PREC);
        let mut acc = Complex::new(PREC);
        // Right half chi' = eta c (c = 1 - s): d_right = eta s, d_left = eta (1 + c); the left
        // half mirrored. s -> 0 is the end, s -> 1 the centre.
        for q in 0..rule.s.len() {
            let near = Float::with_val(PREC, eta * &rule.s[q]);
            let far = Float::with_val(PREC, Float::with_val(PREC, &rule.c[q] + 1u32) * eta);
            for (d_left, d_right, sign) in [(&far, &near, 1i32), (&near, &far, -1)] {
                let chi = Float::with_val(PREC, eta * &rule.c[q]) * sign;
                let sigma = flat_punch_stress(Row::Periodic, d_left, d_right, eta, &e, &ch, PREC);
                acc += sigma * w(&chi) * Float::with_val(PREC, &rule.w[q] * eta);
            }
        }
        acc
    }

    /// The flat punch carries the unit load, and outside it the direct quadrature of the cot
    /// kernel [1.8], H[sigma_flat](x) = (1/L) int sigma_flat(xi) cot(pi (x - xi)/L) d xi (here
    /// L = pi), equals K/L on both sides (sigma = 0 there, so (E*/2)(v' - i u') = H[sigma]),
    /// near an end (d = 0.01) and far from it, to 1e-40 (a tanh-sinh step 3 times finer than
    /// nominal: the cot factor is nearly singular at d = 0.01).
    #[test]
    fn outside_kernel_equals_direct_quadrature_on_both_sides() {
        let eta = f(0.6);
        // L = pi, so x = chi and int sigma dx = (1/pi) int (L sigma) d chi'.
        let load = integrate(&eta, |_| Complex::with_val(PREC, 1)) / Float::with_val(PREC, Constant::Pi);
        assert!(Float::with_val(PREC, load.real() - 1u32).abs() < 1e-40, "load {load}");
        assert!(load.imag().clone().abs() < 1e-40, "load {load}");
        let e = eps();
        for (side, d) in [(Side::Right, 0.3), (Side::Right, 0.01), (Side::Left, 0.3), (Side::Left, 0.7)] {
            let d = f(d);
            let chi = match side {
                Side::Right => Float::with_val(PREC, &d + &eta),
                Side::Left => -Float::with_val(PREC, &d + &eta),
            };
            // H = (1/L) int sigma(xi) cot(x - xi) d xi = (1/pi^2) int (L sigma) cot d chi' (L = pi).
            let pi = Float::with_val(PREC, Constant::Pi);
            let h = integrate(&eta, |xi| {
                let z = Float::with_val(PREC, &chi - xi);
                Complex::with_val(PREC, Float::with_val(PREC, z.tan_ref()).recip())
            }) / Float::with_val(PREC, &pi * &pi);
            let k = outside_kernel(Row::Periodic, side, &d, &eta, &e, PREC) / &pi;
            let diff = Float::with_val(PREC, Complex::with_val(PREC, &h - &k).abs_ref());
            assert!(diff < 1e-40, "{side:?} d {d}: {h} vs {k}");
        }
    }

    /// The tilted punch's closed form against the direct quadrature: f = 0, P = 1 reproduces
    /// sigma_flat and K (two derivations); the rotation (f = 1, P = 0) carries no load, satisfies
    /// (H + i beta) rho = 1 at a contact point (principal value) and H[rho] = outside + 1 on both
    /// sides. L = pi.
    #[test]
    fn tilted_punch_closed_form_against_quadrature() {
        let eta = f(0.6);
        let e = eps();
        let pi = Float::with_val(PREC, Constant::Pi);
        let ch = Float::with_val(PREC, Float::with_val(PREC, &pi * &e).cosh_ref());
        // f = 0, P/L = 1/pi: L rho = pi rho must equal L sigma_flat.
        let flat =
            TiltedPunch::new(&Complex::new(PREC), &Complex::with_val(PREC, pi.clone().recip()), &eta, &e, &ch, PREC);
        for (dl, dr) in [(0.3, 0.9), (1.1, 0.1), (0.6, 0.6)] {
            let (dl, dr) = (f(dl), f(dr));
            let a = flat.stress(&dl, &dr, &eta, &e, PREC) * &pi;
            let b = flat_punch_stress(Row::Periodic, &dl, &dr, &eta, &e, &ch, PREC);
            let d = Float::with_val(PREC, Complex::with_val(PREC, &a - &b).abs_ref()).to_f64();
            assert!(d < 1e-40, "flat: {a} vs {b}");
        }
        for (side, d) in [(Side::Right, 0.3), (Side::Left, 0.2)] {
            let d = f(d);
            let a = flat.outside(side, &d, &eta, &e, &ch, PREC) * &pi;
            let b = outside_kernel(Row::Periodic, side, &d, &eta, &e, PREC);
            let diff = Float::with_val(PREC, Complex::with_val(PREC, &a - &b).abs_ref()).to_f64();
            assert!(diff < 1e-40, "K {side:?}: {a} vs {b}");
        }
        // Z(+-i) closed forms against the principal branches.
        let m = Float::with_val(PREC, eta.tan_ref());
        let cos = Float::with_val(PREC, eta.cos_ref());
        let grow = Float::with_val(PREC, Float::with_val(PREC, &e * &eta) * 2u32).exp();
        let zi = z_function(&Complex::with_val(PREC, (0, 1)), &m, &e, PREC);
        let want = Complex::with_val(PREC, (0, -Float::with_val(PREC, &cos * &grow)));
        assert!(Float::with_val(PREC, Complex::with_val(PREC, &zi - &want).abs_ref()).to_f64() < 1e-45, "{zi}");
        let zmi = z_function(&Complex::with_val(PREC, (0, -1)), &m, &e, PREC);
        let want = Complex::with_val(PREC, (0, Float::with_val(PREC, &cos / &grow)));
        assert!(Float::with_val(PREC, Complex::with_val(PREC, &zmi - &want).abs_ref()).to_f64() < 1e-45, "{zmi}");
        // The rotation.
        let rot = TiltedPunch::rotation(&eta, &e, &ch, PREC);
        let rule = TanhSinh::new(150, 3.0, PREC);
        let integrate = |w: &dyn Fn(&Float) -> Complex| {
            let mut acc = Complex::new(PREC);
            for q in 0..rule.s.len() {
                let near = Float::with_val(PREC, &eta * &rule.s[q]);
                let far = Float::with_val(PREC, Float::with_val(PREC, &rule.c[q] + 1u32) * &eta);
                for (d_left, d_right, sign) in [(&far, &near, 1i32), (&near, &far, -1)] {
                    let chi = Float::with_val(PREC, &eta * &rule.c[q]) * sign;
                    acc += rot.stress(d_left, d_right, &eta, &e, PREC)
                        * w(&chi)
                        * Float::with_val(PREC, &rule.w[q] * &eta);
                }
            }
            acc
        };
        let load = integrate(&|_| Complex::with_val(PREC, 1));
        assert!(Float::with_val(PREC, load.abs_ref()).to_f64() < 1e-40, "rotation load {load}");
        // On the contact at chi0 = 0.2: (1/pi) PV int rho cot(chi0 - chi') d chi' + i beta rho(chi0) = 1,
        // PV = int (rho - rho0) cot + rho0 ln|sin(chi0 + eta)/sin(chi0 - eta)|.
        let chi0 = f(0.2);
        let (dl0, dr0) = (Float::with_val(PREC, &eta + &chi0), Float::with_val(PREC, &eta - &chi0));
        let rho0 = rot.stress(&dl0, &dr0, &eta, &e, PREC);
        let mut pv = Complex::new(PREC);
        for q in 0..rule.s.len() {
            let near = Float::with_val(PREC, &eta * &rule.s[q]);
            let far = Float::with_val(PREC, Float::with_val(PREC, &rule.c[q] + 1u32) * &eta);
            for (d_left, d_right, sign) in [(&far, &near, 1i32), (&near, &far, -1)] {
                let chi = Float::with_val(PREC, &eta * &rule.c[q]) * sign;
                let z = Float::with_val(PREC, &chi0 - &chi);
                if z.is_zero() {
                    continue;
                }
                let cot = Float::with_val(PREC, z.tan_ref()).recip();
                let diff = Complex::with_val(PREC, rot.stress(d_left, d_right, &eta, &e, PREC) - &rho0);
                pv += diff * cot * Float::with_val(PREC, &rule.w[q] * &eta);
            }
        }
        let log =
            Float::with_val(PREC, Float::with_val(PREC, dl0.sin_ref()) / Float::with_val(PREC, dr0.sin_ref())).ln();
        let beta = Float::with_val(PREC, Float::with_val(PREC, &pi * &e).tanh_ref());
        let lhs = (pv + Complex::with_val(PREC, &rho0 * &log)) / &pi + Complex::with_val(PREC, (0, &beta)) * &rho0;
        let diff = Float::with_val(PREC, Complex::with_val(PREC, &lhs - 1u32).abs_ref()).to_f64();
        assert!(diff < 1e-30, "rotation on the contact: {lhs}");
        for (side, d) in [(Side::Right, 0.3), (Side::Left, 0.3), (Side::Left, 0.05)] {
            let d = f(d);
            let chi = match side {
                Side::Right => Float::with_val(PREC, &d + &eta),
                Side::Left => -Float::with_val(PREC, &d + &eta),
            };
            // H[rho] = (1/L) int rho cot d xi = (1/pi) int rho cot d chi' (L = pi, d xi = d chi').
            let h = integrate(&|xi| {
                let z = Float::with_val(PREC, &chi - xi);
                Complex::with_val(PREC, Float::with_val(PREC, z.tan_ref()).recip())
            }) / &pi;
            let want = rot.outside(side, &d, &eta, &e, &ch, PREC) + 1u32;
            let diff = Float::with_val(PREC, Complex::with_val(PREC, &h - &want).abs_ref()).to_f64();
            assert!(diff < 1e-38, "rotation outside {side:?} d {d}: {h} vs {want}");
        }
    }
}
