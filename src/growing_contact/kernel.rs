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
//! incremental method evaluates it. Many distances at one eta (both ends of a collocation's
//! increment, K with its log derivative and the tilted punch) share [`SizeFactors`]: the
//! functions of eta alone once, then one sin_cos per distance (addition formulas); the tests
//! check K against the quadrature of [1.8] through it and its log derivatives against central
//! differences.

use crate::numerics::mp_rounded;
use rug::{Assign, Complex, Float};

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
            Row::Periodic => mp_rounded::sin_cos(z, prec).0,
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
                let (sin, cos) = mp_rounded::sin_cos(&chi, prec);
                let (sinh, cosh) = mp_rounded::sinh_cosh(&b, prec);
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
/// (One evaluation of [`SizeFactors::kernel`]; callers with many distances at one eta build the
/// factors once.)
pub fn outside_kernel(row: Row, side: Side, d_near: &Float, eta: &Float, eps: &Float, prec: u32) -> Complex {
    let size = SizeFactors::new(row, eta, eps, prec);
    size.kernel(&size.point(side, d_near))
}

/// d ln K/d d_near of [`outside_kernel`] (the Jacobian of `crate::loading_law::jacobian`): with
/// chi = +-(d + eta), d_far = d + 2 eta,
///   right: -tan(chi - 2 i eps eta) + i eps (cot d_far - cot d) - (cot d + cot d_far)/2,
///   left:  +tan(chi - 2 i eps eta) - i eps (cot d_far - cot d) - (cot d + cot d_far)/2,
/// and for the single punch tan -> 0, cot z -> 1/z ([`SizeFactors::kernel_log_derivative`]).
pub fn outside_kernel_log_derivative(
    row: Row,
    side: Side,
    d_near: &Float,
    eta: &Float,
    eps: &Float,
    prec: u32,
) -> Complex {
    let size = SizeFactors::new(row, eta, eps, prec);
    size.kernel_log_derivative(&size.point(side, d_near))
}

/// The factors of the kernels outside a contact of half-length eta that depend on eta alone:
/// sin and cos of eta and 2 eta, sinh and cosh of b = 2 eps eta (the shift of cos(chi' - 2 i eps
/// eta)) and of 2 b (the tangent of the log derivative), computed once per eta for both ends,
/// for K, its log derivative and the tilted punch ([`TiltedPunch::outside_at`]). A distance's
/// own sin and cos then give sin d_far, cos d_far (d_far = d + 2 eta) and sin, cos of
/// chi' = d + eta by the addition formulas: one sin_cos per distance where K alone took three
/// sines, a sin_cos and a sinh_cosh. The single punch needs none of them (sin z -> z,
/// cos -> 1).
#[derive(Debug, Clone)]
pub struct SizeFactors {
    row: Row,
    prec: u32,
    eta: Float,
    eps: Float,
    sin_eta: Float,
    cos_eta: Float,
    sin_2eta: Float,
    cos_2eta: Float,
    sinh_b: Float,
    cosh_b: Float,
    sinh_2b: Float,
    cosh_2b: Float,
}

/// One point outside the contact of [`SizeFactors`], at distance d from its nearer end on `side`:
/// the sines and cosines of d, d_far and |chi'| = d + eta, and the singular factor
/// s (sin d_far/sin d_near)^(s i eps)/sqrt(sin d_near sin d_far) (s = +1 right, -1 left) that K
/// and the tilted punch share.
#[derive(Debug, Clone)]
pub struct OutsidePoint {
    side: Side,
    sin_near: Float,
    cos_near: Float,
    sin_far: Float,
    cos_far: Float,
    sin_chi: Float,
    cos_chi: Float,
    singular: Complex,
}

impl SizeFactors {
    /// The factors at half-length `eta` (`eps` of the material), `prec` bits.
    pub fn new(row: Row, eta: &Float, eps: &Float, prec: u32) -> Self {
        let zero = || Float::with_val(prec, 0);
        let one = || Float::with_val(prec, 1);
        let (mut sin_eta, mut cos_eta, mut sin_2eta, mut cos_2eta) = (zero(), one(), zero(), one());
        let (mut sinh_b, mut cosh_b, mut sinh_2b, mut cosh_2b) = (zero(), one(), zero(), one());
        if row == Row::Periodic {
            (sin_eta, cos_eta) = mp_rounded::sin_cos(&Float::with_val(prec, eta), prec);
            sin_2eta = Float::with_val(prec, &sin_eta * &cos_eta) * 2u32;
            cos_2eta = 1u32 - Float::with_val(prec, sin_eta.square_ref()) * 2u32;
            let b = Float::with_val(prec, eps * eta) * 2u32;
            (sinh_b, cosh_b) = mp_rounded::sinh_cosh(&b, prec);
            sinh_2b = Float::with_val(prec, &sinh_b * &cosh_b) * 2u32;
            cosh_2b = Float::with_val(prec, sinh_b.square_ref()) * 2u32 + 1u32;
        }
        SizeFactors {
            row,
            prec,
            eta: Float::with_val(prec, eta),
            eps: Float::with_val(prec, eps),
            sin_eta,
            cos_eta,
            sin_2eta,
            cos_2eta,
            sinh_b,
            cosh_b,
            sinh_2b,
            cosh_2b,
        }
    }

    /// exp(2 eps eta) = cosh b + sinh b.
    fn growth(&self) -> Float {
        Float::with_val(self.prec, &self.cosh_b + &self.sinh_b)
    }

    /// The point at distance `d_near` > 0 from the nearer end on `side`.
    pub fn point(&self, side: Side, d_near: &Float) -> OutsidePoint {
        let prec = self.prec;
        let (sin_near, cos_near, sin_far, cos_far, sin_chi, cos_chi) = match self.row {
            Row::Periodic => {
                let (sn, cn) = mp_rounded::sin_cos(&Float::with_val(prec, d_near), prec);
                // a x + b y (sign +1) or a x - b y, each product and the sum rounded once, with
                // one scratch value for the second product.
                let mut scratch = Float::new(prec);
                let mut combine = |a: &Float, x: &Float, b: &Float, y: &Float, plus: bool| {
                    let mut out = Float::with_val(prec, a * x);
                    scratch.assign(b * y);
                    if plus {
                        out += &scratch;
                    } else {
                        out -= &scratch;
                    }
                    out
                };
                let sin_far = combine(&sn, &self.cos_2eta, &cn, &self.sin_2eta, true);
                let cos_far = combine(&cn, &self.cos_2eta, &sn, &self.sin_2eta, false);
                let sin_chi = combine(&sn, &self.cos_eta, &cn, &self.sin_eta, true);
                let cos_chi = combine(&cn, &self.cos_eta, &sn, &self.sin_eta, false);
                (sn, cn, sin_far, cos_far, sin_chi, cos_chi)
            }
            Row::Single => {
                let far = Float::with_val(prec, d_near + &self.eta) + &self.eta;
                let one = Float::with_val(prec, 1);
                (Float::with_val(prec, d_near), one.clone(), far, one.clone(), Float::new(prec), one)
            }
        };
        // (sin d_far/sin d_near)^(+- i eps) = exp(+- i eps ln(ratio)).
        let mut theta = mp_rounded::ln(&Float::with_val(prec, &sin_far / &sin_near), prec);
        theta *= &self.eps;
        let mut mag = Float::with_val(prec, &sin_near * &sin_far);
        mag.sqrt_mut();
        mag.recip_mut();
        if side == Side::Left {
            theta = -theta;
            mag = -mag;
        }
        let (sin_t, cos_t) = mp_rounded::sin_cos(&theta, prec);
        let singular = Complex::with_val(prec, (cos_t, sin_t)) * mag;
        OutsidePoint { side, sin_near, cos_near, sin_far, cos_far, sin_chi, cos_chi, singular }
    }

    /// L K at `p` (module doc): cos(chi' - 2 i eps eta) times the singular factor, with
    /// cos(chi - i b) = cos chi cosh b + i sin chi sinh b and chi = +-|chi'|.
    pub fn kernel(&self, p: &OutsidePoint) -> Complex {
        let prec = self.prec;
        match self.row {
            Row::Periodic => {
                let mut sin = Float::with_val(prec, &p.sin_chi * &self.sinh_b);
                if p.side == Side::Left {
                    sin = -sin;
                }
                let cos = Complex::with_val(prec, (Float::with_val(prec, &p.cos_chi * &self.cosh_b), sin));
                cos * &p.singular
            }
            Row::Single => p.singular.clone(),
        }
    }

    /// d ln K/d d_near at `p` ([`outside_kernel_log_derivative`]): cot from the point's sines and
    /// cosines; tan(x + i y) = (sin 2x + i sinh 2y)/(cos 2x + cosh 2y) with x = chi, y = -b.
    pub fn kernel_log_derivative(&self, p: &OutsidePoint) -> Complex {
        let prec = self.prec;
        let (c_near, c_far) = match self.row {
            Row::Periodic => {
                (Float::with_val(prec, &p.cos_near / &p.sin_near), Float::with_val(prec, &p.cos_far / &p.sin_far))
            }
            Row::Single => {
                (Float::with_val(prec, p.sin_near.recip_ref()), Float::with_val(prec, p.sin_far.recip_ref()))
            }
        };
        let real = -(Float::with_val(prec, &c_near + &c_far) / 2u32);
        let imag = Float::with_val(prec, &c_far - &c_near) * &self.eps;
        let sign = if p.side == Side::Right { 1i32 } else { -1 };
        let mut out = Complex::with_val(prec, (real, imag * sign));
        if self.row == Row::Periodic {
            // sin 2x = sign 2 sin|chi| cos|chi|, cos 2x = 1 - 2 sin^2 chi, sinh 2y = -sinh 2b.
            let sin = Float::with_val(prec, &p.sin_chi * &p.cos_chi) * (2 * sign);
            let cos = 1u32 - Float::with_val(prec, p.sin_chi.square_ref()) * 2u32;
            let den = cos + &self.cosh_2b;
            let tan = Complex::with_val(
                prec,
                (Float::with_val(prec, &sin / &den), -Float::with_val(prec, &self.sinh_2b / &den)),
            );
            out -= tan * sign;
        }
        out
    }
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
    let theta = mp_rounded::ln(&Float::with_val(prec, &sp / &sm), prec) * eps;
    let cos = row.cos_shift(chi, eps, eta, prec);
    let (sin_t, cos_t) = mp_rounded::sin_cos(&theta, prec);
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
        let cos = Float::with_val(prec, eta.cos_ref());
        let grow = Float::with_val(prec, Float::with_val(prec, eps * eta) * 2u32).exp();
        Self::from_factors(f, p_over_l, &cos, &grow, cosh_pi_eps, prec)
    }

    /// [`Self::new`] from cos eta and `grow` = e^(2 eps eta).
    fn from_factors(
        f: &Complex,
        p_over_l: &Complex,
        cos: &Float,
        grow: &Float,
        cosh_pi_eps: &Float,
        prec: u32,
    ) -> Self {
        // Z(+-i) in closed form: i +- m = +-i e^(-+i eta)/cos eta (principal arguments
        // +-(pi/2 - eta) and +-(pi/2 + eta)) give Z(i) = -i cos(eta) e^(2 eps eta) and
        // Z(-i) = i cos(eta) e^(-2 eps eta) (checked against the principal branches in the tests).
        let i = Complex::with_val(prec, (0, 1));
        let ip = Complex::with_val(prec, &i * p_over_l);
        // A + iB = -ch (f + iP/L)/Z(i) = -i ch (f + iP/L) e^(-2 eps eta)/cos eta; A - iB likewise.
        let scale_plus = Float::with_val(prec, cosh_pi_eps / grow) / cos;
        let scale_minus = Float::with_val(prec, cosh_pi_eps * grow) / cos;
        let plus = Complex::with_val(prec, f + &ip) * &i * scale_plus * -1i32;
        let minus = Complex::with_val(prec, f - &ip) * &i * scale_minus;
        let a = Complex::with_val(prec, &plus + &minus) / 2u32;
        let b = Complex::with_val(prec, &plus - &minus) / Complex::with_val(prec, &i * 2u32);
        TiltedPunch { a, b }
    }

    /// [`Self::rotation`] from the factors of its half-length (periodic row).
    pub fn rotation_at(size: &SizeFactors, cosh_pi_eps: &Float) -> Self {
        let prec = size.prec;
        let one = Complex::with_val(prec, 1);
        Self::from_factors(&one, &Complex::new(prec), &size.cos_eta, &size.growth(), cosh_pi_eps, prec)
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
    /// nearer end on `side` ([`Self::outside_at`]).
    pub fn outside(
        &self,
        side: Side,
        d_near: &Float,
        eta: &Float,
        eps: &Float,
        cosh_pi_eps: &Float,
        prec: u32,
    ) -> Complex {
        let size = SizeFactors::new(Row::Periodic, eta, eps, prec);
        self.outside_at(&size, &size.point(side, d_near), cosh_pi_eps)
    }

    /// [`Self::outside`] at a point of [`SizeFactors`]: with t +- m = sin(eta +- chi')/(cos eta cos
    /// chi'), |t + m| and |t - m| are sin d_far/cc and sin d_near/cc on the right (mirrored on the
    /// left, where Z also takes the phase e^(i pi (-1/2 + i eps)) e^(i pi (-1/2 - i eps)) = -1),
    /// cc = cos eta cos chi', so Z = cc times K's singular factor and
    /// Z (A + B tan chi') = cos eta (A cos chi' + B sin chi') times it.
    pub fn outside_at(&self, size: &SizeFactors, p: &OutsidePoint, cosh_pi_eps: &Float) -> Complex {
        let prec = size.prec;
        let mut sin = Float::with_val(prec, &p.sin_chi * &size.cos_eta);
        if p.side == Side::Left {
            sin = -sin;
        }
        let cos = Float::with_val(prec, &p.cos_chi * &size.cos_eta);
        let linear = Complex::with_val(prec, &self.a * &cos) + Complex::with_val(prec, &self.b * &sin);
        linear * &p.singular / cosh_pi_eps
    }

    /// d ln/d d_near of [`Self::outside`] (the Jacobian of `crate::loading_law::jacobian`): with
    /// chi = +-(d + eta), the factor 1/(cos eta cos chi) of t +- m contributes +tan chi on the
    /// right and -tan chi on the left:
    ///   right: (-1/2 + i eps)(cot d_far + tan chi) + (-1/2 - i eps)(cot d + tan chi)
    ///          + B sec^2 chi/(A + B tan chi),
    ///   left:  (-1/2 + i eps)(cot d - tan chi) + (-1/2 - i eps)(cot d_far - tan chi)
    ///          - B sec^2 chi/(A + B tan chi).
    pub fn outside_log_derivative(&self, side: Side, d_near: &Float, eta: &Float, eps: &Float, prec: u32) -> Complex {
        let size = SizeFactors::new(Row::Periodic, eta, eps, prec);
        self.outside_log_derivative_at(&size, &size.point(side, d_near))
    }

    /// [`Self::outside_log_derivative`] at a point of [`SizeFactors`].
    pub fn outside_log_derivative_at(&self, size: &SizeFactors, p: &OutsidePoint) -> Complex {
        let prec = size.prec;
        let sign = if p.side == Side::Right { 1i32 } else { -1 };
        // tan |chi'| (= sign tan chi).
        let shift = Float::with_val(prec, &p.sin_chi / &p.cos_chi);
        let tan = Float::with_val(prec, &shift * sign);
        let sec2 = Float::with_val(prec, shift.square_ref()) + 1u32;
        let (c_near, c_far) =
            (Float::with_val(prec, &p.cos_near / &p.sin_near), Float::with_val(prec, &p.cos_far / &p.sin_far));
        let (first, second) = match p.side {
            Side::Right => (c_far + &shift, c_near + &shift),
            Side::Left => (c_near + &shift, c_far + &shift),
        };
        let e_plus = Complex::with_val(prec, (-0.5, &size.eps));
        let e_minus = Complex::with_val(prec, (-0.5, Float::with_val(prec, -&size.eps)));
        let linear = Complex::with_val(prec, &self.a + Complex::with_val(prec, &self.b * &tan));
        let tail = Complex::with_val(prec, &self.b * &sec2) / linear * sign;
        e_plus * first + e_minus * second + tail
    }
}

/// r^(-1/2 + sign i eps) for r > 0.
fn power(r: &Float, eps: &Float, sign: i32, prec: u32) -> Complex {
    let ln = mp_rounded::ln(r, prec);
    let mag = Float::with_val(prec, r.sqrt_ref()).recip();
    let theta = Float::with_val(prec, &ln * eps) * sign;
    let (sin, cos) = mp_rounded::sin_cos(&theta, prec);
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

    /// The log derivatives of K and of the tilted punch outside ([`SizeFactors::kernel_log_derivative`],
    /// [`TiltedPunch::outside_log_derivative_at`]) equal central differences of the functions
    /// (step 1e-20) to 1e-22, on both sides, in the periodic row and for the single punch (K
    /// only); measured: 3.6e-26 for K in the periodic row at d = 0.3 (160 bits).
    #[test]
    fn log_derivatives_equal_central_differences() {
        let (eta, e) = (f(0.6), eps());
        let ch = Float::with_val(PREC, Float::with_val(PREC, Constant::Pi) * &e).cosh();
        let h = f(1e-20);
        let rot = TiltedPunch::rotation(&eta, &e, &ch, PREC);
        for row in [Row::Periodic, Row::Single] {
            let size = SizeFactors::new(row, &eta, &e, PREC);
            for (side, d) in [(Side::Right, 0.3), (Side::Right, 0.01), (Side::Left, 0.2)] {
                let d = f(d);
                let (up, down) = (Float::with_val(PREC, &d + &h), Float::with_val(PREC, &d - &h));
                let log_difference = |g: &dyn Fn(&Float) -> Complex| {
                    Complex::with_val(PREC, g(&up) - g(&down)) / g(&d) / Float::with_val(PREC, &h * 2u32)
                };
                let k = |x: &Float| size.kernel(&size.point(side, x));
                let want = log_difference(&k);
                let got = size.kernel_log_derivative(&size.point(side, &d));
                let diff = Float::with_val(PREC, Complex::with_val(PREC, &got - &want).abs_ref()).to_f64();
                assert!(diff < 1e-22, "K {row:?} {side:?} d {d}: {got} vs {want}");
                if row == Row::Periodic {
                    let t = |x: &Float| rot.outside_at(&size, &size.point(side, x), &ch);
                    let want = log_difference(&t);
                    let got = rot.outside_log_derivative_at(&size, &size.point(side, &d));
                    let diff = Float::with_val(PREC, Complex::with_val(PREC, &got - &want).abs_ref()).to_f64();
                    assert!(diff < 1e-22, "tilt {side:?} d {d}: {got} vs {want}");
                }
            }
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
