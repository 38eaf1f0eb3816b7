//! Problem 2 coefficients to any order at a given nu, in MPFR (issue 13, "coefficients to any
//! order"): the numerical twin of [`super::adhesion`], whose exact coefficients in Q(eps, B, S) cost
//! seconds at order 24 and grow without bound. Same objects, same normalisation: c_n of the load
//! [3.18], A_n/(k (pi/L)^(n-1)) of the slope [3.16]-[3.17], C_P/pi, and p_j of
//! `P'(eta) = pi sum_j p_j eta^(2j+1)`.
//!
//! # The recurrence in tangent variables \[reconstructed\]
//! With T = tan chi and t = tan eta (0 < eta < chi < pi/2), sin(chi +- eta) = cos chi cos eta (T +- t)
//! and cos(chi - 2 i eps eta) = cos chi (cosh(2 eps eta) + i T sinh(2 eps eta)), so the kernel of
//! (V) (module doc of [`super::adhesion`]) is
//! ```text
//!   K(chi, eta) = (cosh(2 eps eta) + i T sinh(2 eps eta)) sec(eta) (T + t)^(-1/2+i eps) (T - t)^(-1/2-i eps).
//! ```
//! With Phi(t) = cos(eta) P'(eta) (eta = arctan t, d eta = cos^2 eta dt) and t = T s,
//! `(T + t)^(...) (T - t)^(...) dt = w(s) ds`, the weight of the half-range moments M_m: the
//! Abel factor becomes *exactly* the moment weight, with no kernel factor G_n(s) left over:
//! ```text
//!   I(chi) = int_0^1 w(s) (A(T s) + i T B(T s)) ds = sum_k T^k (a_k M_k + i b_(k-1) M_(k-1)),
//!   A(t) = cosh(2 eps arctan t) Phi(t) = sum a_k t^k,  B(t) = sinh(2 eps arctan t) Phi(t) = sum b_k t^k.
//! ```
//! Phi is odd (P' is), A odd, B even. cosh and sinh of 2 eps arctan t are the even and odd parts
//! of E(t) = exp(2 eps arctan t) = sum e_k t^k, whose coefficients follow from
//! (1 + t^2) E' = 2 eps E: `(k+1) e_(k+1) = 2 eps e_k - (k-1) e_(k-1)`, e_0 = 1, e_1 = 2 eps.
//! Equating powers of T in Re I = pi chi = pi arctan T gives, for j = 0, 1, ...:
//! ```text
//!   D_j a_(2j+1) - Im M_(2j) b_(2j) = pi (-1)^j/(2j+1),   D_j = Re M_(2j+1),
//!   a_(2j+1) = phi_(2j+1) + sum_{l>=1} e_(2l) phi_(2j+1-2l),   b_(2j) = sum_{l>=0} e_(2l+1) phi_(2j-1-2l),
//! ```
//! triangular in the coefficients phi_(2j+1) of Phi, O(j) operations each: O(N^2) for order 2N
//! instead of the O(N^3) kernel moments T_(n,j) of the exact route (the same divisors D_j = Re
//! M_(2j+1) appear: the same poles in nu). The slope (Psi) needs
//! `Im I(chi) = Y(T) = sum_j T^(2j+1) (Im M_(2j+1) a_(2j+1) + Re M_(2j) b_(2j))`.
//! Back to the paper's variables by composition with tan (v = eta^2 or chi^2, tan z = z tau(v),
//! sec z = sigma(v)):
//! ```text
//!   P'(eta) = sec(eta) Phi(tan eta):  p_j = [v^j] sigma(v) tau(v) phi~(v tau(v)^2)/pi,  phi~(u) = sum_j phi_(2j+1) u^j,
//!   psi_J = [v^J] -(2/pi) tau(v) y~(v tau(v)^2),  y~(u) = sum_j y_j u^j,
//! ```
//! then `c_(2j) = p_j/((j+1) p_0)`, `C_P/pi = p_0/2`, and the coefficient of chi^(2J+1) of the slope
//! is psi_J (module doc of [`super::adhesion`], steps 4-5). The compositions are the cost:
//! the powers of v tau(v)^2, (N+1)^3/6 multiplications, shared by both
//! ([`crate::numerics::real_series::compose_several`]).
//!
//! # Precision
//! Phi has radius 1 in t (singular at t = +-i, the image of eta = +-i infinity; at nu = 1/2,
//! Phi = pi t/sqrt(1 + t^2)), while P'(eta) has radius eta_s <= pi/2: the composition with tan sums
//! terms of size (4/pi)^k (the majorant 1/(1 - tan z) has radius pi/4) into a coefficient of size
//! eta_s^(-k), k = 2N+1, a cancellation of at most 2^(2N+1). So each run works at
//! `bits(digits) + SERIES_GUARD_BITS + 2N + 1` bits ([`working_bits`]); the second run has
//! [`VERIFY_EXTRA_BITS`] more, and every coefficient's digits are its agreement with the second run
//! relative to its own magnitude (`crate::numerics::accuracy`).
//!
//! # The pole of the exact coefficients (Re M_(2N+1) = 0)
//! M_m ~ 2^(-1/2+i eps) Gamma(1/2 - i eps) m^(-1/2+i eps) for large m: its phase grows like
//! eps ln m and D_N = Re M_(2N+1) > 0 for small N changes sign once, where the phase passes pi/2
//! (by this asymptotic form at m ~ exp(pi/(2 eps) - ln 2 - arg Gamma(1/2 - i eps)/eps), about 560 at
//! nu = 0 and 2 10^3 at nu = 0.1; measured exactly by [`AdhesionRun::sign_change`]: 2N+1 = 607 at
//! nu = 0, none through 2N+1 = 1001 at nu = 1/10, tested). For N at and beyond the first
//! N* with D_N(nu) <= 0, D_N has a zero at some nu' between nu and 1/2 (D_N > 0 at nu = 1/2, where
//! the moments are real), so the exact p_N, c_(2N), A_(2N+1) have a pole in nu there, and at the given
//! nu p_(N*) is divided by a small D_(N*) and every later coefficient carries it. The numerical
//! route prints the coefficients below N* only, and says where N* is and how small D_N is there
//! (|D_N|/|M_(2N+1)|).
//!
//! # Verification (tests)
//! - Through order 12 at nu = 0, 3/10, 9/20 against the exact coefficients of [`super::adhesion`]
//!   substituted at nu (`adhesion_values`), to 1e-40.
//! - nu = 1/2: c_n are the coefficients of ln sec(lambda)/(lambda^2/2) (Kuznetsov) through
//!   lambda^200, A_n = 0.
//! - Two precisions agree to the digits claimed; the sign change at nu = 0 lies near N ~ 300.

use super::print::VerifiedPart;
use crate::error::Error;
use crate::model::Material;
use crate::numerics::accuracy::{digits_cap_for_bits, verified_digits_mpfr};
use crate::numerics::precision::{bits_for_digits, SERIES_GUARD_BITS, VERIFY_EXTRA_BITS};
use crate::numerics::real_series::{compose_several, mul_trunc, tan_sec_in_square};
use crate::params::adhesion::{eps as eps_const, half_range_moments};
use num_traits::Signed;
use rug::float::Constant;
use rug::Float;

type Q = num_rational::BigRational;

/// Largest order (power of lambda) of the numerical route: order 1000 runs at 1165 and 1197 bits,
/// 2.1 10^7 multiplications each, 18 s in all (release, `/usr/bin/time periodic-contact series
/// adhesion --order 1000 --nu 3/10`; order 200: 0.06 s).
pub const MAX_ORDER: usize = 1000;

/// Largest number of digits asked of the numerical route.
pub const MAX_DIGITS: u32 = 1000;

/// Working bits of a run for `digits` digits through lambda^(2 jmax): the cancellation of the
/// composition with tan (module doc, "Precision") is at most 2^(2 jmax + 1).
pub fn working_bits(digits: u32, jmax: usize) -> u32 {
    bits_for_digits(digits) + SERIES_GUARD_BITS + 2 * jmax as u32 + 1
}

/// One run of the recurrence at one precision.
#[derive(Debug, Clone)]
pub struct AdhesionRun {
    /// Working precision (bits).
    pub prec: u32,
    /// p_j, j = 0..=jmax (`P'(eta) = pi sum_j p_j eta^(2j+1)`).
    pub p: Vec<Float>,
    /// psi_J, J = 0..=jmax: the coefficient of chi^(2J+1) of psi/(k L/pi), i.e.
    /// A_(2J+1)/(k (pi/L)^(2J)).
    pub psi: Vec<Float>,
    /// D_N = Re M_(2N+1), N = 0..=jmax.
    pub d: Vec<Float>,
    /// |M_(2N+1)|, N = 0..=jmax.
    pub m_abs: Vec<Float>,
}

impl AdhesionRun {
    /// The first N with D_N <= 0 (module doc, "The pole"), if any through jmax.
    pub fn sign_change(&self) -> Option<usize> {
        self.d.iter().position(|d| !d.is_sign_positive() || d.is_zero())
    }
    /// c_(2j) = p_j/((j+1) p_0), j = 0..=jmax.
    pub fn load(&self) -> Vec<Float> {
        let p0 = &self.p[0];
        self.p.iter().enumerate().map(|(j, pj)| Float::with_val(self.prec, pj / p0) / (j as u32 + 1)).collect()
    }
    /// C_P/pi = p_0/2.
    pub(crate) fn load_constant_over_pi(&self) -> Float {
        Float::with_val(self.prec, &self.p[0] / 2u32)
    }
}

/// The tangent-variable coefficients of one run (module doc): phi_k of Phi(t) = cos(eta) P'(eta)
/// (index k = power of t; the even ones 0), y_j of Y(T) = Im I, D_j = Re M_(2j+1), |M_(2j+1)|.
#[derive(Debug, Clone)]
pub struct TangentRun {
    /// phi_k, k = 0..=2 jmax + 1 (odd k only non-zero).
    pub phi: Vec<Float>,
    /// y_j, j = 0..=jmax.
    pub y: Vec<Float>,
    /// D_j = Re M_(2j+1), j = 0..=jmax.
    pub d: Vec<Float>,
    /// |M_(2j+1)|, j = 0..=jmax.
    pub m_abs: Vec<Float>,
}

/// The recurrence of the module doc in t = tan eta through t^(2 jmax + 1), at `prec` bits: O(jmax^2)
/// operations. Phi(t) = sum_k phi_k t^k converges for |t| < 1 (module doc, "Precision").
pub fn tangent_coefficients(material: &Material, jmax: usize, prec: u32) -> TangentRun {
    let kmax = 2 * jmax + 1; // highest power of t
    let moments = half_range_moments(material, kmax + 1, prec);
    let eps = eps_const(material, prec);
    let two_eps = Float::with_val(prec, &eps * 2u32);
    // E(t) = exp(2 eps arctan t): (k+1) e_(k+1) = 2 eps e_k - (k-1) e_(k-1).
    let mut e: Vec<Float> = vec![Float::with_val(prec, 1), two_eps.clone()];
    for k in 1..kmax {
        let mut next = Float::with_val(prec, &two_eps * &e[k]);
        next -= Float::with_val(prec, &e[k - 1] * (k as u32 - 1));
        next /= k as u32 + 1;
        e.push(next);
    }
    let pi = Float::with_val(prec, Constant::Pi);
    let mut phi = vec![Float::new(prec); kmax + 1];
    let mut y = Vec::with_capacity(jmax + 1);
    let mut d = Vec::with_capacity(jmax + 1);
    let mut m_abs = Vec::with_capacity(jmax + 1);
    for j in 0..=jmax {
        let k = 2 * j + 1;
        // b_(2j) = sum_{l odd, 1 <= l <= 2j-1} e_l phi_(2j-l); rest = sum_{l even, 2 <= l <= 2j} e_l phi_(k-l).
        let mut b = Float::new(prec);
        for l in (1..2 * j).step_by(2) {
            b += &e[l] * &phi[2 * j - l];
        }
        let mut rest = Float::new(prec);
        for l in (2..=2 * j).step_by(2) {
            rest += &e[l] * &phi[k - l];
        }
        let (re_k, im_k) = (moments[k].real(), moments[k].imag());
        let (re_2j, im_2j) = (moments[2 * j].real(), moments[2 * j].imag());
        let mut rhs = Float::with_val(prec, &pi / k as u32);
        if j % 2 == 1 {
            rhs = -rhs;
        }
        rhs += im_2j * &b;
        let a = Float::with_val(prec, &rhs / re_k);
        phi[k] = Float::with_val(prec, &a - &rest);
        // y_j = Im M_k a_k + Re M_(2j) b_(2j).
        let mut yj = Float::with_val(prec, im_k * &a);
        yj += re_2j * &b;
        y.push(yj);
        d.push(re_k.clone());
        m_abs.push(Float::with_val(prec, moments[k].abs_ref()));
    }
    TangentRun { phi, y, d, m_abs }
}

/// The recurrence of the module doc through p_jmax and psi_jmax for `material`, at `prec` bits.
pub fn adhesion_run(material: &Material, jmax: usize, prec: u32) -> AdhesionRun {
    let TangentRun { phi, y, d, m_abs } = tangent_coefficients(material, jmax, prec);
    let pi = Float::with_val(prec, Constant::Pi);
    // Back to eta and chi by composition with tan (v = z^2).
    let len = jmax + 1;
    let (tau, sigma) = tan_sec_in_square(len, prec);
    let tau_sq = mul_trunc(&tau, &tau, len, prec);
    let mut inner = vec![Float::new(prec); len];
    inner[1..].clone_from_slice(&tau_sq[..len - 1]);
    let phi_t: Vec<Float> = (0..len).map(|j| phi[2 * j + 1].clone()).collect();
    let [h, hy]: [Vec<Float>; 2] = compose_several(&[&phi_t, &y], &inner, len, prec)
        .expect("inner series starts with 0")
        .try_into()
        .expect("two outer series");
    let p = mul_trunc(&mul_trunc(&sigma, &tau, len, prec), &h, len, prec).into_iter().map(|x| x / &pi).collect();
    let psi = mul_trunc(&tau, &hy, len, prec).into_iter().map(|x| Float::with_val(prec, x * -2i32) / &pi).collect();
    AdhesionRun { prec, p, psi, d, m_abs }
}

/// One coefficient: power, value (first run), digits verified by the second run.
pub type Coefficient = (usize, Float, f64);

/// Where the exact coefficients stop being meaningful (module doc, "The pole").
#[derive(Debug, Clone)]
pub struct SignChange {
    /// The first N with D_N = Re M_(2N+1) <= 0.
    pub n: usize,
    /// |D_N|/|M_(2N+1)| at N - 1 and N.
    pub ratio: [f64; 2],
}

/// The verified numerical coefficients ([`adhesion_numeric`]).
#[derive(Debug, Clone)]
pub struct AdhesionNumeric {
    /// Poisson's ratio (exact).
    pub nu: Q,
    /// Order asked (every term through lambda^order; an odd order is treated as order - 1).
    pub order: usize,
    /// Digits requested.
    pub digits: u32,
    /// eps, B, S at the first run's precision.
    pub constants: [Float; 3],
    /// C_P/pi with its digits.
    pub load_constant: Coefficient,
    /// c_(2j) (power 2j) through the printed order.
    pub load: Vec<Coefficient>,
    /// psi_J (power 2J+1 of chi) through the printed order.
    pub slope: Vec<Coefficient>,
    /// p_j (index j) through the printed order.
    pub volterra: Vec<Coefficient>,
    /// The sign change of D_N, when it lies within the order asked.
    pub pole: Option<SignChange>,
    /// Working bits of the two runs.
    pub bits: [u32; 2],
}

fn verify(a: &[Float], b: &[Float], cap: f64, power: impl Fn(usize) -> usize) -> Vec<Coefficient> {
    a.iter()
        .zip(b)
        .enumerate()
        .map(|(i, (x, y))| {
            let diff = Float::with_val(y.prec(), x - y);
            let scale = Float::with_val(x.prec(), x.abs_ref());
            (power(i), x.clone(), verified_digits_mpfr(&diff, &scale, cap))
        })
        .collect()
}

/// The Problem 2 coefficients at Poisson's ratio `nu` (exact, in [0, 1/2]) through lambda^`order`
/// (`order` <= [`MAX_ORDER`]), to `digits` digits (1..=[`MAX_DIGITS`]): two runs of
/// [`adhesion_run`], at [`working_bits`] and [`VERIFY_EXTRA_BITS`] more; each coefficient's digits
/// are its agreement with the second run relative to its magnitude. Coefficients from the first
/// sign change of D_N on are left out ([`AdhesionNumeric::pole`]).
pub fn adhesion_numeric(nu: &Q, order: usize, digits: u32) -> Result<AdhesionNumeric, Error> {
    let half = Q::new(1.into(), 2.into());
    if nu.is_negative() || *nu > half {
        return Err(Error::input("nu", nu, "must lie in [0, 1/2]"));
    }
    if order > MAX_ORDER {
        return Err(Error::input("order", order, format!("must be an integer in [0, {MAX_ORDER}]")));
    }
    if !(1..=MAX_DIGITS).contains(&digits) {
        return Err(Error::input("digits", digits, format!("must be an integer in [1, {MAX_DIGITS}]")));
    }
    let material = Material::from_contact_modulus(nu.clone(), Q::from_integer(1.into()))
        .map_err(|e| Error::Input(crate::model::ModelError { parameter: "nu".into(), ..e }))?;
    let jmax = order / 2;
    let bits = working_bits(digits, jmax);
    let first = adhesion_run(&material, jmax, bits);
    let second = adhesion_run(&material, jmax, bits + VERIFY_EXTRA_BITS);
    let pole = first.sign_change().map(|n| {
        let r = |i: usize| Float::with_val(64, &first.d[i] / &first.m_abs[i]).abs().to_f64();
        SignChange { n, ratio: [if n > 0 { r(n - 1) } else { f64::NAN }, r(n)] }
    });
    let keep = pole.as_ref().map_or(jmax + 1, |s| s.n);
    let cap = digits_cap_for_bits(bits);
    let lc = verify(&[first.load_constant_over_pi()], &[second.load_constant_over_pi()], cap, |_| 0).remove(0);
    let load = verify(&first.load()[..keep], &second.load()[..keep], cap, |j| 2 * j);
    let slope = verify(&first.psi[..keep], &second.psi[..keep], cap, |j| 2 * j + 1);
    let volterra = verify(&first.p[..keep], &second.p[..keep], cap, |j| j);
    let params = crate::params::adhesion::AdhesionParamsMpfr::new(&material, bits);
    Ok(AdhesionNumeric {
        nu: nu.clone(),
        order: 2 * jmax,
        digits,
        constants: [params.eps, params.b, params.s],
        load_constant: lc,
        load,
        slope,
        volterra,
        pole,
        bits: [bits, bits + VERIFY_EXTRA_BITS],
    })
}

/// The printed parts: (name, formula, variable, coefficients).
type Part<'a> = (&'static str, &'static str, &'static str, &'a [Coefficient]);

impl AdhesionNumeric {
    /// Least verified digits over the printed coefficients.
    pub(crate) fn min_digits(&self) -> f64 {
        std::iter::once(&self.load_constant)
            .chain(&self.load)
            .chain(&self.slope)
            .map(|c| c.2)
            .fold(f64::INFINITY, f64::min)
    }

    /// The printed coefficients whose verified digits fall below the digits asked.
    pub fn short(&self) -> Vec<(&'static str, usize, f64)> {
        self.parts()
            .iter()
            .flat_map(|(name, _, _, cs)| cs.iter().filter(|c| c.2 < self.digits as f64).map(|c| (*name, c.0, c.2)))
            .collect()
    }

    fn parts(&self) -> Vec<Part<'_>> {
        vec![
            ("C_P_over_pi", "C_P/pi, P2 = C_P E* k a^2 (1 + c_2 lambda^2 + ...) for the single punch; C_P = pi/(2 (1 - 2 eps S))", "lambda", std::slice::from_ref(&self.load_constant)),
            ("load_c", "c_n: P2(a) = C_P E* k a^2 (1 + c_2 lambda^2 + c_4 lambda^4 + ...), lambda = pi a/L [3.18]", "lambda", &self.load),
            ("slope_A", "A_n: psi(x) = sum_n A_n |x|^n [3.16]; coefficient of chi^n is A_n/(k (pi/L)^(n-1)), chi = pi x/L; even A_n vanish", "chi", &self.slope),
        ]
    }

    /// The highest power of lambda printed (below the sign change, if any).
    pub fn printed_order(&self) -> usize {
        self.load.last().map_or(0, |c| c.0)
    }

    /// The sentence on the sign change of D_N (module doc, "The pole"), or on its absence.
    pub(crate) fn pole_text(&self) -> String {
        match &self.pole {
            None => format!(
                "no pole: D_N = Re M_(2N+1) > 0 for every N <= {} (the exact coefficients have no pole in nu between this nu and 1/2 through this order)",
                self.order / 2
            ),
            Some(s) => format!(
                "pole: D_N = Re M_(2N+1) changes sign at N = {} (|D_N|/|M_(2N+1)| = {:.1e} at N = {}, {:.1e} at N = {}): the exact p_N, c_(2N), A_(2N+1) have a pole in nu between this nu and 1/2 from N = {} on, and at this nu every later coefficient carries the division by the small D_N; printed through lambda^{} only (coefficients from lambda^{} on are not meaningful)",
                s.n,
                s.ratio[0],
                s.n.saturating_sub(1),
                s.ratio[1],
                s.n,
                s.n,
                2 * s.n.saturating_sub(1),
                2 * s.n
            ),
        }
    }

    /// lambda_h(nu, digits) as printed ([`super::adhesion_mode::horizon`], 3 decimals rounded
    /// down): the size up to which the incremental solution keeps the digits asked here (issue 31:
    /// the horizon from a command, `series adhesion --nu R --digits D`).
    pub fn lambda_h(&self) -> String {
        let (eps, b, s) = self.f64_constants();
        super::adhesion_mode::horizon_text(super::adhesion_mode::horizon(eps, b, s, self.digits as f64))
    }

    fn horizon_sentence(&self) -> String {
        let (eps, b, s) = self.f64_constants();
        super::adhesion_mode::horizon_sentence(eps, b, s, self.digits as f64)
    }

    fn f64_constants(&self) -> (f64, f64, f64) {
        let [eps, b, s] = &self.constants;
        (eps.to_f64(), b.to_f64(), s.to_f64())
    }

    fn header(&self) -> Vec<String> {
        let [eps, b, s] = &self.constants;
        let mut h = vec![
            "object: adhesion (numerical route)".to_string(),
            "source: docs/theory.md section 5, paper [3.13]-[3.19]; the recurrence in tangent variables (asymptotics::adhesion_numeric), MPFR at the given nu".into(),
            format!(
                "nu = {} (eps = {}, B = {}, S = {}), order {} (every term through lambda^{}; A_n through chi^{})",
                exact_series::q_text(&self.nu),
                eps.to_string_radix(10, Some(self.digits.min(30) as usize)),
                b.to_string_radix(10, Some(self.digits.min(30) as usize)),
                s.to_string_radix(10, Some(self.digits.min(30) as usize)),
                self.order,
                self.order,
                self.order + 1
            ),
            format!(
                "values to {} digits, verified by a second run ({} and {} bits): every printed coefficient to >= {} digits of its own magnitude",
                self.digits,
                self.bits[0],
                self.bits[1],
                crate::numerics::accuracy::digits_text(self.min_digits())
            ),
            self.pole_text(),
            format!("horizon: lambda_h = {} ({})", self.lambda_h(), self.horizon_sentence()),
        ];
        let short = self.short();
        if let Some(worst) = short.iter().min_by(|a, b| a.2.total_cmp(&b.2)) {
            h.push(format!(
                "warning: {} coefficients verified to fewer than the {} digits asked (least: {} power {}, {} digits); each is printed with its verified digits only",
                short.len(),
                self.digits,
                worst.0,
                worst.1,
                crate::numerics::accuracy::digits_text(worst.2)
            ));
        }
        h.push("stress kernels: not printed by the numerical route (h_N is a polynomial of degree 2N+1 in (xi, tau) with complex coefficients: hundreds of lines per order); the exact kernels through order 24 are `asymptotics::adhesion::adhesion_expansion`'s `stress`".into());
        h
    }

    /// Plain text: the header, then per part its name, formula and one line per coefficient.
    pub fn text(&self) -> String {
        let mut s = self.header().join("\n");
        s.push('\n');
        for (object, formula, variable, coefficients) in self.parts() {
            s.push_str(&VerifiedPart { object, formula, variable, coefficients }.text(self.digits));
        }
        s
    }

    /// JSON: {"object": "adhesion", "route": "numeric", "nu", "order", "printed_order", "digits",
    /// "verified_digits", "bits", "eps", "B", "S", "pole": null | {"n", "power", "ratio", "text"},
    /// "short": [...], "parts": [{"object", "formula", "variable", "coefficients": [{"power",
    /// "value", "digits"}]}]} (values as strings, digits to 0.1).
    pub fn json(&self) -> serde_json::Value {
        let round = |d: f64| (d * 10.0).round() / 10.0;
        let [eps, b, s] = &self.constants;
        let c = |x: &Float| x.to_string_radix(10, Some(self.digits as usize));
        serde_json::json!({
            "object": "adhesion",
            "route": "numeric",
            "nu": exact_series::q_text(&self.nu),
            "order": self.order,
            "printed_order": self.printed_order(),
            "digits": self.digits,
            "verified_digits": round(self.min_digits()),
            "bits": self.bits,
            "eps": c(eps),
            "B": c(b),
            "S": c(s),
            "lambda_h": self.lambda_h(),
            "pole": self.pole.as_ref().map(|p| serde_json::json!({
                "n": p.n,
                "power": 2 * p.n,
                "ratio": [format!("{:.2e}", p.ratio[0]), format!("{:.2e}", p.ratio[1])],
                "text": self.pole_text(),
            })),
            "short": self.short().iter().map(|(o, k, d)| serde_json::json!({"object": o, "power": k, "digits": round(*d)})).collect::<Vec<_>>(),
            "parts": self.parts().into_iter().map(|(object, formula, variable, coefficients)| {
                VerifiedPart { object, formula, variable, coefficients }.json(self.digits)
            }).collect::<Vec<_>>(),
        })
    }
}

#[cfg(test)]
mod tests;
