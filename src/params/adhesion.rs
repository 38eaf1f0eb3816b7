//! The material constants of Problem 2 (docs/theory.md sections 1, 4, 5): eps, cosh(pi eps),
//! B = pi/cosh(pi eps), S(eps) and the half-range moments M_m, in MPFR and in `f64`.
//!
//! With kappa = 3 - 4 nu (exact): eps = ln(kappa)/(2 pi), cosh(pi eps) = (kappa+1)/(2 sqrt(kappa)),
//! B = 2 pi sqrt(kappa)/(kappa+1) (docs/theory.md section 5; cosh(ln(kappa)/2) written out, so no
//! exponential of a rounded eps is formed).

use crate::model::Material;
use crate::numerics::exact::to_float;
use rug::float::Constant;
use rug::ops::Pow;
use rug::{Complex, Float};

use crate::numerics::precision::CONSTANT_GUARD_BITS;

/// The derived material constants of Problem 2 in MPFR, computed once per problem and precision:
/// every solver, series evaluation and renderer of Problem 2 reads them from here.
#[derive(Debug, Clone, PartialEq)]
pub struct AdhesionParamsMpfr {
    /// Working precision in bits.
    pub prec: u32,
    /// beta = (1 - 2 nu)/(2 (1 - nu)), rounded once from its exact value.
    pub beta: Float,
    /// eps = ln(3 - 4 nu)/(2 pi).
    pub eps: Float,
    /// cosh(pi eps) = (kappa + 1)/(2 sqrt(kappa)), kappa = 3 - 4 nu.
    pub cosh_pi_eps: Float,
    /// B = pi/cosh(pi eps).
    pub b: Float,
    /// S(eps) = int_0^inf sin(2 eps y)/cosh y dy.
    pub s: Float,
    /// The single-punch load constant C_P = pi/(2 (1 - 2 eps S)) ([`single_punch_load_constant`]).
    pub load_constant: Float,
}

impl AdhesionParamsMpfr {
    /// eps, cosh(pi eps), B, S(eps) and C_P of `material` at `prec` bits: eps, cosh(pi eps), B and
    /// C_P each to < 1 ulp (formed at `prec` + [`CONSTANT_GUARD_BITS`] and rounded once); S from the
    /// rounded eps by [`s_const`] (its proven bound 2^-prec plus the propagated rounding of eps:
    /// |dS/d eps| <= 2 int y/cosh y = 3.67, so a few ulp). These are exactly the values the solvers
    /// and the series evaluation formed before the parameters were gathered here.
    pub fn new(material: &Material, prec: u32) -> Self {
        let e = eps(material, prec);
        let s = s_const(&e, prec);
        AdhesionParamsMpfr {
            prec,
            beta: to_float(&material.beta(), prec),
            eps: e,
            cosh_pi_eps: cosh_pi_eps(material, prec),
            b: b_const(material, prec),
            s,
            load_constant: single_punch_load_constant(material, prec),
        }
    }

    /// The same constants rounded to `f64` (each rounded once from its MPFR value).
    pub fn to_f64(&self) -> AdhesionParamsF64 {
        AdhesionParamsF64 {
            beta: self.beta.to_f64(),
            eps: self.eps.to_f64(),
            cosh_pi_eps: self.cosh_pi_eps.to_f64(),
            b: self.b.to_f64(),
            s: self.s.to_f64(),
            load_constant: self.load_constant.to_f64(),
        }
    }
}

/// The derived material constants of Problem 2 in `f64` ([`AdhesionParamsMpfr::to_f64`], or
/// [`AdhesionParamsF64::new`] which rounds 64-bit values once).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AdhesionParamsF64 {
    /// beta.
    pub beta: f64,
    /// eps.
    pub eps: f64,
    /// cosh(pi eps).
    pub cosh_pi_eps: f64,
    /// B = pi/cosh(pi eps).
    pub b: f64,
    /// S(eps).
    pub s: f64,
    /// C_P = pi/(2 (1 - 2 eps S)).
    pub load_constant: f64,
}

impl AdhesionParamsF64 {
    /// The constants of `material`, computed in MPFR at 64 bits and rounded once to `f64`.
    pub fn new(material: &Material) -> Self {
        AdhesionParamsMpfr::new(material, 64).to_f64()
    }
}

/// eps = ln(3 - 4 nu)/(2 pi) [docs/theory.md section 1], rounded once from the exact kappa.
pub fn eps(material: &Material, prec: u32) -> Float {
    let w = prec + CONSTANT_GUARD_BITS;
    let kappa = to_float(&material.kolosov(), w);
    let pi = Float::with_val(w, Constant::Pi);
    Float::with_val(prec, kappa.ln() / (pi * 2u32))
}

/// cosh(pi eps) = (kappa + 1)/(2 sqrt(kappa)), kappa = 3 - 4 nu.
pub(crate) fn cosh_pi_eps(material: &Material, prec: u32) -> Float {
    let w = prec + CONSTANT_GUARD_BITS;
    let kappa = to_float(&material.kolosov(), w);
    let s = Float::with_val(w, kappa.sqrt_ref());
    Float::with_val(prec, (kappa + 1u32) / (s * 2u32))
}

/// B = pi/cosh(pi eps) [docs/theory.md section 5].
pub(crate) fn b_const(material: &Material, prec: u32) -> Float {
    let w = prec + CONSTANT_GUARD_BITS;
    let pi = Float::with_val(w, Constant::Pi);
    Float::with_val(prec, pi / cosh_pi_eps(material, w))
}

/// S(eps) = int_0^inf sin(2 eps y)/cosh(y) dy [docs/theory.md section 5], to `prec` bits.
///
/// Method: 1/cosh y = 2 sum_k (-1)^k e^{-(2k+1) y} gives S = 2 sum_{k>=0} (-1)^k a_k with
/// a_k = c/((2k+1)^2 + c^2), c = 2 eps. The alternating sum is accelerated by Algorithm 1 of
/// Cohen, Rodriguez Villegas and Zagier (Experiment. Math. 9 (2000) 3-12): a_k = int_0^1 x^k dmu,
/// dmu = sin(c y) e^{-y} dy with x = e^{-2y}, and the n-term result S_n satisfies
/// |sum - S_n| <= int |dmu| / d_n <= c / d_n, d_n >= (3 + sqrt 8)^n / 2 (proven bound; the
/// measure is signed, hence the total variation int |dmu| <= int c y e^{-y} dy = c).
/// So n = ceil((prec + 4) ln 2 / ln(3 + sqrt 8)) terms give |error| < 2^-prec; about 0.39 terms
/// per bit (130 terms for 100 digits).
pub fn s_const(eps: &Float, prec: u32) -> Float {
    let n = (((prec + 4) as f64) * std::f64::consts::LN_2 / (3.0 + 8f64.sqrt()).ln()).ceil() as u32 + 1;
    // The weights c_k reach d_n ~ 2^prec; a relative cancellation of at most n: guard bits.
    let w = prec + CONSTANT_GUARD_BITS + 2 * (32 - n.leading_zeros());
    let c = Float::with_val(w, eps * 2u32);
    Float::with_val(
        prec,
        alternating_sum_crvz(n, w, |k| {
            let t = Float::with_val(w, 2 * k + 1);
            let den = Float::with_val(w, &t * &t) + Float::with_val(w, &c * &c);
            Float::with_val(w, &c / den)
        }) * 2u32,
    )
}

/// Algorithm 1 of Cohen, Rodriguez Villegas, Zagier (2000): sum_{k>=0} (-1)^k a_k from n terms.
fn alternating_sum_crvz(n: u32, w: u32, a: impl Fn(u32) -> Float) -> Float {
    let r = Float::with_val(w, 8u32).sqrt() + 3u32;
    let d0 = Float::with_val(w, r.pow(n));
    let d = Float::with_val(w, &d0 + Float::with_val(w, d0.recip_ref())) / 2u32;
    let mut b = Float::with_val(w, -1);
    let mut c = Float::with_val(w, -&d);
    let mut s = Float::with_val(w, 0);
    for k in 0..n {
        c = Float::with_val(w, &b - &c);
        s += Float::with_val(w, &c * a(k));
        let (kk, nn) = (k as i64, n as i64);
        b *= (kk + nn) * (kk - nn);
        b /= Float::with_val(w, (2 * kk + 1) * (kk + 1)) / 2u32;
    }
    s / d
}

/// S(eps) in `f64` (same accelerated sum, 24 terms: bound c 2^-60).
pub fn s_const_f64(eps: f64) -> f64 {
    let c = 2.0 * eps;
    let n = 24u32;
    let r = 3.0 + 8f64.sqrt();
    let d0 = r.powi(n as i32);
    let d = (d0 + 1.0 / d0) / 2.0;
    let (mut b, mut cc, mut s) = (-1.0f64, -d, 0.0f64);
    for k in 0..n {
        cc = b - cc;
        let t = (2 * k + 1) as f64;
        s += cc * c / (t * t + c * c);
        let (kk, nn) = (k as f64, n as f64);
        b = (kk + nn) * (kk - nn) * b / ((kk + 0.5) * (kk + 1.0));
    }
    2.0 * s / d
}

/// Half-range moments M_m = int_0^1 y^m (1+y)^{-1/2+i eps} (1-y)^{-1/2-i eps} dy, m = 0..count-1
/// [docs/theory.md sections 4, 5]: M_0 = B/2 + i S, M_1 = 1 + 2 i eps M_0,
/// (m+1) M_{m+1} = m M_{m-1} + 2 i eps M_m. The recurrence is neutrally stable (both solutions
/// grow like m^{-1/2}); a few guard bits suffice for m up to thousands.
pub(crate) fn half_range_moments(material: &Material, count: usize, prec: u32) -> Vec<Complex> {
    let w = prec + CONSTANT_GUARD_BITS;
    let e = eps(material, w);
    let m0 = Complex::with_val(w, (b_const(material, w) / 2u32, s_const(&e, w)));
    let two_i_eps = Complex::with_val(w, (0, Float::with_val(w, &e * 2u32)));
    let mut out: Vec<Complex> = Vec::with_capacity(count);
    if count == 0 {
        return out;
    }
    out.push(m0.clone());
    if count > 1 {
        out.push(Complex::with_val(w, &two_i_eps * &m0) + 1u32);
    }
    for m in 1..count.saturating_sub(1) {
        let t = Complex::with_val(w, &two_i_eps * &out[m]) + Complex::with_val(w, &out[m - 1] * (m as u32));
        out.push(t / ((m + 1) as u32));
    }
    out.into_iter().map(|z| Complex::with_val(prec, z)).collect()
}

/// Single-punch load constant C_P = pi/(2 (1 - 2 eps S)) [docs/theory.md section 5; the paper's
/// (3.18) at lambda = 0]: P2 = C_P E* k a^2. Equals pi/(2 Re M_1).
pub fn single_punch_load_constant(material: &Material, prec: u32) -> Float {
    let w = prec + CONSTANT_GUARD_BITS;
    let e = eps(material, w);
    let s = s_const(&e, w);
    let pi = Float::with_val(w, Constant::Pi);
    let den = Float::with_val(w, 1u32) - Float::with_val(w, &e * &s) * 2u32;
    Float::with_val(prec, pi / (den * 2u32))
}

/// Single-punch slope of the tangential displacement, psi = A1 |x| with
/// A1 = -2 eps B k/(1 - 2 eps S) (from psi = -(2 k x/(pi chi)) Im int K P' as chi -> 0,
/// docs/theory.md section 4, with P' = eta pi/Re M_1 and Im M_1 = eps B). Returned per unit k.
pub fn single_punch_slope(material: &Material, prec: u32) -> Float {
    let w = prec + CONSTANT_GUARD_BITS;
    let e = eps(material, w);
    let s = s_const(&e, w);
    let b = b_const(material, w);
    let den = Float::with_val(w, 1u32) - Float::with_val(w, &e * &s) * 2u32;
    Float::with_val(prec, -(e * b * 2u32) / den)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Exact;

    fn material(nu: (i64, i64)) -> Material {
        Material::from_contact_modulus(Exact::new(nu.0.into(), nu.1.into()), Exact::from_integer(1.into())).unwrap()
    }
    fn parse(prec: u32, s: &str) -> Float {
        Float::with_val(prec, Float::parse(s).unwrap())
    }

    // Reference values: mpmath 1.3, mp.dps = 50, both quad(sin(2 eps y)/cosh y, [0, inf]) and
    // the independent closed form S = Im[digamma((3 - 2 i eps)/4) - digamma((1 - 2 i eps)/4)]/2,
    // which agree to all 50 digits.
    const S_REF: [((i64, i64), &str); 4] = [
        ((0, 1), "0.56534733229134773376738583842785622493210326752098"),
        ((3, 10), "0.33023942863136928937968104458985538125078216289360"),
        ((9, 20), "0.10593038231343169027759206881763348000082751482902"),
        ((1, 10), "0.50628815699106784092485628377823625183432602925283"),
    ];

    #[test]
    fn adhesion_s_matches_independent_digamma_form() {
        for prec in [64u32, 128, 166] {
            for (nu, s) in S_REF {
                let m = material(nu);
                let got = s_const(&eps(&m, prec + 10), prec);
                let want = parse(200, s);
                let err = Float::with_val(200, &got - &want).abs().to_f64();
                // Bound 2^-prec relative to |S| < 1, plus the reference's 1e-50.
                assert!(err < 4.0 * 2f64.powi(-(prec as i32)) + 1e-49, "nu {nu:?} prec {prec}: {err:e}");
            }
        }
        assert_eq!(s_const(&eps(&material((1, 2)), 100), 100), 0);
    }

    #[test]
    fn adhesion_s_f64_matches_mpfr() {
        for (nu, s) in S_REF {
            let e = eps(&material(nu), 53).to_f64();
            assert!((s_const_f64(e) - parse(60, s).to_f64()).abs() < 4e-16);
        }
    }

    #[test]
    fn adhesion_load_constant_single_punch() {
        // mpmath 1.3, dps 50: pi/(2 (1 - 2 eps S)) with S from quad.
        let refs = [
            ((0, 1), "1.957870161200987500354610296837901059468496248154"),
            ((3, 10), "1.6742431888479788202679004937760908174642073711431"),
            ((9, 20), "1.5805127560473433532244193760649162511204225735662"),
        ];
        for (nu, c) in refs {
            let got = single_punch_load_constant(&material(nu), 160);
            let err = Float::with_val(200, &got - &parse(200, c)).abs().to_f64();
            assert!(err < 1e-46, "{nu:?}: {err:e}");
        }
        let hertz = single_punch_load_constant(&material((1, 2)), 100);
        let half_pi = Float::with_val(100, Constant::Pi) / 2u32;
        assert_eq!(hertz, half_pi);
    }

    #[test]
    fn adhesion_moment_m0_matches_quadrature() {
        // mpmath 1.3, dps 50, quad of the weight over (0, 1) at nu = 0 (accurate to ~1e-27).
        let m = half_range_moments(&material((0, 1)), 4, 120);
        let re = parse(120, "1.3603495231756633879455586941354670140581072382616");
        let im = parse(120, "0.5653473322913477337673858387331208982547499253186");
        assert!(Float::with_val(120, m[0].real() - &re).abs().to_f64() < 1e-26);
        assert!(Float::with_val(120, m[0].imag() - &im).abs().to_f64() < 1e-26);
    }
}
