//! Problem 2 (indentation with complete adhesion, periodic parabolic punches g = k x^2, b = a):
//! the small-lambda expansions of the paper's (3.16)-(3.19), exact, to any order.
//!
//! # Objects (docs/theory.md section 5)
//! With lambda = pi a/L, chi = pi x/L, xi = x/a (so chi = lambda xi):
//! - `psi(x) = phi'(x) = sum_n A_n |x|^n` [3.16], `A_{2J} = 0`, `A_{2J+1} = k (pi/L)^{2J} psi_J`;
//!   [`AdhesionExpansion::slope`] is `psi(x)/(k L/pi) = sum_J psi_J |chi|^{2J+1}` (a series in
//!   chi whose coefficient of chi^n is `A_n/(k (pi/L)^(n-1))`).
//! - `P2(a) = C_P E* k a^2 (1 + c_2 lambda^2 + c_4 lambda^4 + ...)` [3.18],
//!   `C_P = pi/(2 (1 - 2 eps S))`; [`AdhesionExpansion::load`] is the bracket.
//! - `q2 + i q1 = E* k a (pi/B) sum_N lambda^(2N) int_xi^1 (tau+xi)^(-1/2+i eps)
//!   (tau-xi)^(-1/2-i eps) h_N(xi, tau) dtau` for 0 <= xi <= 1 [3.19] (q2 even, q1 odd in x);
//!   [`AdhesionExpansion::stress`] holds the polynomials h_N(xi, tau) exactly.
//!
//! Coefficients are exact elements of Q(eps, B, S) (B = pi/cosh(pi eps), S = S(eps), both kept as
//! symbols: they are transcendental in eps), the stress kernels of Q(i)(eps, B, S)[xi, tau].
//!
//! # Derivation \[reconstructed\] (the paper prints only A1, A3 and c2; its formulas are lost)
//! Start from the incremental (Mossakovskii) form of docs/theory.md section 4: with
//! `P2 = E* k (L/pi)^2 P(lambda)`,
//! ```text
//!   (V)  Re I(chi) = pi chi,   I(chi) = int_0^chi K(chi, eta) P'(eta) deta,
//!   (Psi) psi(x) = -(2 k x/(pi chi)) Im I(chi) = -(2 k L/pi^2) Im I(chi),
//!   K(chi, eta) = cos(chi - 2 i eps eta) sin(chi+eta)^(-1/2+i eps) sin(chi-eta)^(-1/2-i eps).
//! ```
//! 1. Scaling eta = chi s, s in (0, 1) \[reconstructed\]: since sin z = z sinc z,
//!    `K(chi, chi s) chi = w(s) G(chi, s)` with the half-range weight
//!    `w(s) = (1+s)^(-1/2+i eps) (1-s)^(-1/2-i eps)` (docs/theory.md section 5, the weight of M_m) and
//!    `G(chi, s) = cos(chi (1 - 2 i eps s)) sinc(chi (1+s))^(-1/2+i eps) sinc(chi (1-s))^(-1/2-i eps)
//!     = sum_n G_n(s) chi^(2n)`,
//!    G_0 = 1, G_n a polynomial of degree 2n in s over Q(i)\[eps\] (even in chi: sinc and cos are
//!    even). Computed by the engine ([`kernel_factor`]).
//! 2. Ansatz `P'(eta) = pi sum_j p_j eta^(2j+1)` (P2 is even in lambda, docs/theory.md section 2)
//!    \[reconstructed\]. Then
//!    `I(chi) = pi sum_N chi^(2N+1) I_N`, `I_N = sum_{n+j=N} p_j T_{n,j}`,
//!    `T_{n,j} = int_0^1 w(s) G_n(s) s^(2j+1) ds = sum_m [s^m]G_n M_{m+2j+1}`,
//!    with the half-range moments M_m (docs/theory.md section 4): `M_0 = B/2 + i S`,
//!    `M_1 = 1 + 2 i eps M_0`, `(m+1) M_{m+1} = m M_{m-1} + 2 i eps M_m` — the only place where B
//!    and S enter. T_{0,j} = M_{2j+1}.
//! 3. The recurrence (equating powers of chi in (V)) \[reconstructed\]:
//!    ```text
//!      p_0 = 1/Re M_1,
//!      p_N Re M_{2N+1} = - Re sum_{n=1}^{N} p_{N-n} T_{n,N-n}      (N >= 1),
//!    ```
//!    triangular, p_N divides by D_N = Re M_{2N+1}; it is solved over polynomials with the
//!    common denominator D_0 ... D_N (`p_N = n_N/(D_0 ... D_N)`,
//!    `n_N = -Re sum_n n_{N-n} T_{n,N-n} D_{N-n+1} ... D_{N-1}`) and reduced once at the end.
//! 4. The slope (Psi): with chi = pi x/L, `psi = -(2 k L/pi^2) pi sum_J chi^(2J+1) Im I_J`
//!    gives, power by power, the recurrence's second half [3.17]
//!    `psi_J = -2 Im I_J = -2 Im sum_{j=0}^{J} p_j T_{J-j,j}` and `A_{2J+1} = k (pi/L)^(2J) psi_J`,
//!    `A_{2J} = 0`: psi is a fixed function of x (it is frozen when x enters the contact), so the
//!    A_n do not depend on lambda. `psi_0 = -2 Im M_1/Re M_1 = -2 eps B/(1 - 2 eps S)`: the
//!    single-punch slope, psi = A_1 |x| (checked against the fixed-a solvability condition of the
//!    single punch in the tests).
//! 5. The load: `P(lambda) = pi sum_j p_j lambda^(2j+2)/(2j+2)`, so `C_P = pi p_0/2 =
//!    pi/(2 (1 - 2 eps S))` (docs/theory.md section 5 check value) and
//!    `c_{2j} = p_j/((j+1) p_0)`.
//! 6. The stresses: `q2 + i q1 = int_{a'=|x|}^{a} sigma_flat(x; a') dP2(a')` (docs/theory.md section 4),
//!    sigma_flat = (ch/L) K(eta, chi) (the flat-punch stress is K with its arguments swapped),
//!    ch = cosh(pi eps) = pi/B. Scaling chi = lambda xi, eta = lambda tau \[reconstructed\]:
//!    `K(lambda tau, lambda xi) lambda = (tau+xi)^(-1/2+i eps) (tau-xi)^(-1/2-i eps) H(lambda; xi, tau)`,
//!    `H = cos(lambda (xi - 2 i eps tau)) sinc(lambda (tau+xi))^(-1/2+i eps)
//!    sinc(lambda (tau-xi))^(-1/2-i eps) = sum_n H_n(xi, tau) lambda^(2n)` (the same
//!    [`kernel_factor`] with (u, v) = (xi, tau) instead of (1, s)), and
//!    `h_N(xi, tau) = sum_{j=0}^{N} p_j tau^(2j+1) H_{N-j}(xi, tau)`.
//!    At eps = 0: h_0 = tau, and the integral is sqrt(1 - xi^2): Hertz.
//!
//! # Where B enters (proved, and checked in the tests)
//! G(chi, -s) = conj G(chi, s), so Re G_n is even and Im G_n odd in s; by the moment recurrence
//! (multiplication by i eps swaps real and imaginary parts) Re M_odd, Im M_even lie in Q[eps, S]
//! and Im M_odd, Re M_even in B Q\[eps\]. Hence Re T_{n,j} lies in Q[eps, S] and Im T_{n,j} in
//! B Q[eps, S]: the p_j, the c_n and C_P are free of B, and every A_{2J+1} is B times a rational
//! function of (eps, S). The stress kernels h_N = sum_j p_j tau^(2j+1) H_{N-j} (H over
//! Q(i)[eps, xi, tau]) are free of B too: in the stresses B enters only through the prefactor pi/B.
//!
//! # Printed form (for the CLI, `periodic-contact series adhesion --order N [--nu R]`)
//! Suggested JSON (strings for every number; exact forms as `Frac` text, `(num)/(den)`):
//! ```text
//! { "object": "adhesion", "order": N, "symbols": ["eps", "B", "S"],
//!   "C_P": "pi*(-1/4)/(S*eps - 1/2)",           // C_P = pi * load_constant
//!   "A": [ {"n": 1, "coefficient": "<psi_0>", "scale": "k"},
//!          {"n": 3, "coefficient": "<psi_1>", "scale": "k (pi/L)^2"}, ... ],   // A_n, n <= N+1
//!   "c": [ {"power": 0, "value": "1"}, {"power": 2, "value": "<c_2>"}, ... ],  // through lambda^N
//!   "values": { "nu": "R", "digits": 30, "eps": "...", "B": "...", "S": "...", "C_P": "...",
//!               "A": [...], "c": [...] } }        // only with --nu
//! ```
//! and as text one line per coefficient, `A_3 = k (pi/L)^2 * (...)`, `c_2 = (...)`, with the
//! 30-digit value appended when nu is given ([`AdhesionValues`]).
//!
//! # Cost
//! Order 12 (A_n through n = 13, c_n through lambda^12): about 12 s without the stress kernels,
//! 60 s with them (test profile, opt-level 2, 2 shared cores; `cargo test -p periodic-contact
//! --lib asymptotics::adhesion`). The time is in the reductions of the rational functions; the
//! engine's gcd certifies coprime pairs by univariate images (`exact_series::frac`), and the
//! known denominator factors D_i are cancelled by exact division before (`frac`).
//!
//! # Verification (tests, each against an independent computation)
//! - nu = 1/2: c_n equal the coefficients of ln sec(lambda)/(lambda^2/2) (Kuznetsov [2.15],
//!   computed from -log cos over Q) through lambda^12, psi = 0, h_0 = tau (Hertz).
//! - C_P and A_1 equal the single-punch check values of docs/theory.md section 5 exactly; A_1 also
//!   satisfies the fixed-a solvability condition of the single punch, int (2y - i A_1 |y|)
//!   dy/omega(y) = 0, evaluated by MPFR quadrature (no moments, no recurrence), to 2^-(prec-16).
//! - Signs stated in the paper's text: A_1 < 0, A_3 < 0 (delta_{1,3} > 0) and c_2 > 0 on [0, 1/2).
//! - p_j and psi_J agree to 1e-11 with method 2 of the adhesion solvers (f64, numerical Taylor
//!   coefficients of G at quadrature nodes) at nu = 0, 1/4, 9/20, 1/2 through order 12.
//! - Against method 1 of the adhesion solvers (full MPFR solution, 30 digits): the remainders of
//!   P2, psi and q2 + i q1 (x/a = 1/2) after m = 0..4 corrections have observed orders
//!   2m+2 +- 0.01 between lambda = pi/32 and pi/64, at nu = 0, 0.3, 0.45.
//!
//! # Convergence (observed, not proven)
//! The lambda^2-series of P2 has radius pi/2 at nu = 1/2 (ln sec); for nu < 1/2 the recurrence
//! divides by D_N = Re M_{2N+1}, which method 2 of the adhesion solvers observed to change sign near
//! N ~ 302 at nu = 0 (see the module doc of the adhesion series_f64 method; measured: the first
//! N with D_N <= 0 is 303, `adhesion_numeric::tests::sign_change_at_nu_zero`): the exact
//! coefficients then have a pole in nu. The numerical route ([`super::adhesion_numeric`]) gives the
//! coefficients at a given nu to order 1000; their ratio analysis ([`super::adhesion_singularity`])
//! finds no fixed singularity for nu < 1/2: the coefficients grow like the product of
//! 1/cos arg M_(2j+1).

use crate::model::Material;
use crate::numerics::evaluate::{poly_mpfr, UnboundSymbol};
use crate::numerics::precision::SERIES_GUARD_BITS;
use crate::numerics::tanh_sinh::TanhSinh;
use crate::params::adhesion::AdhesionParamsMpfr;
use exact_series::{Frac, Gaussian, Poly, Ring, Series, SeriesError, Symbol, Q};
use num_bigint::BigInt;
use rug::{Complex, Float};

/// Symbol eps = ln(3 - 4 nu)/(2 pi).
pub const EPS: &str = "eps";
/// Symbol B = pi/cosh(pi eps).
pub const B: &str = "B";
/// Symbol S = S(eps) = int_0^inf sin(2 eps y)/cosh y dy.
pub const S: &str = "S";
/// Symbol xi = x/a of the stress kernels.
pub const XI: &str = "xi";
/// Symbol tau = a'/a (integration variable of the stress kernels).
pub const TAU: &str = "tau";
/// Internal integration variable s = eta/chi (eliminated by the moments).
const SVAR: &str = "s_";

/// Gaussian polynomials: Q(i)[symbols].
type GPoly = Gaussian<Poly>;

/// The exact expansion of Problem 2 through lambda^order.
#[derive(Debug, Clone)]
pub struct AdhesionExpansion {
    /// Order N: every term through lambda^N (N even; an odd N is treated as N - 1 for the
    /// even series).
    pub order: usize,
    /// `C_P/pi = 1/(2 (1 - 2 eps S))` (the single-punch load constant over pi).
    pub load_constant: Frac,
    /// `1 + c_2 lambda^2 + ... ` through lambda^N: `P2 = C_P E* k a^2 * load(lambda)` [3.18].
    pub load: Series<Frac>,
    /// `psi(x)/(k L/pi) = sum_J psi_J |chi|^(2J+1)` through chi^(N+1): the coefficient of chi^n is
    /// `A_n/(k (pi/L)^(n-1))` [3.16]-[3.17] (zero for even n).
    pub slope: Series<Frac>,
    /// `p_j` of step 2 (`P'(eta) = pi sum_j p_j eta^(2j+1)`), j = 0..=N/2.
    pub volterra: Vec<Frac>,
    /// Stress kernels h_N(xi, tau) (coefficient of lambda^(2N) at index 2N; odd indices zero),
    /// over Q(i)(eps, B, S)[xi, tau] [3.19]; see the module doc for the integral. Empty
    /// (`prec() == 0`) when built without stresses ([`adhesion_expansion_with`]).
    pub stress: Series<Gaussian<Frac>>,
}

impl AdhesionExpansion {
    /// A_n / (k (pi/L)^(n-1)) for n >= 1 (`psi_{(n-1)/2}` for odd n, 0 for even n); `None`
    /// beyond the computed order.
    pub fn a_coefficient(&self, n: usize) -> Option<&Frac> {
        self.slope.coeff(n)
    }
    /// c_n (n even; c_0 = 1) of [3.18]; `None` beyond the computed order.
    pub fn c_coefficient(&self, n: usize) -> Option<&Frac> {
        self.load.coeff(n)
    }
}

fn symbol(name: &str) -> Result<Symbol, SeriesError> {
    Symbol::new(name)
}

/// `cos(z (u - 2 i eps v)) sinc(z (v+u))^(-1/2+i eps) sinc(z (v-u))^(-1/2-i eps)` as a series in
/// z to O(z^prec), coefficients in Q(i)[u, v, eps] [reconstructed, module doc steps 1 and 6].
/// With (u, v) = (1, s) it is G(chi, s); with (u, v) = (xi, tau) it is H(lambda; xi, tau).
pub fn kernel_factor(prec: usize, u: &Poly, v: &Poly) -> Result<Series<GPoly>, SeriesError> {
    let eps = Poly::symbol(symbol(EPS)?);
    let half = Poly::from_q(&Q::new(BigInt::from(-1), BigInt::from(2)));
    let alpha = GPoly::new(half.clone(), eps.clone());
    let alpha_bar = GPoly::new(half, eps.neg());
    let sinc = Series::<GPoly>::sinc_series(prec);
    let plus = sinc.rescale_var(&GPoly::real(v.add(u))).pow(&alpha)?;
    let minus = sinc.rescale_var(&GPoly::real(v.sub(u))).pow(&alpha_bar)?;
    let arg = Series::new(vec![GPoly::zero(), GPoly::new(u.clone(), eps.mul(v).mul_int(-2))], prec);
    Ok(arg.cos()?.mul(&plus).mul(&minus))
}

/// The half-range moments M_0..M_{count-1} over Q(i)[eps, B, S] (docs/theory.md sections 4, 5).
pub(crate) fn half_range_moments(count: usize) -> Result<Vec<GPoly>, SeriesError> {
    let eps = Poly::symbol(symbol(EPS)?);
    let b = Poly::symbol(symbol(B)?);
    let s = Poly::symbol(symbol(S)?);
    let two_i_eps = GPoly::new(Poly::zero(), eps.mul_int(2));
    let mut m: Vec<GPoly> = Vec::with_capacity(count);
    if count > 0 {
        m.push(GPoly::new(b.div_int(2), s));
    }
    if count > 1 {
        m.push(GPoly::one().add(&two_i_eps.mul(&m[0])));
    }
    for k in 1..count.saturating_sub(1) {
        let next = m[k - 1].mul_int(k as i64).add(&two_i_eps.mul(&m[k]));
        m.push(next.div_int(k as i64 + 1));
    }
    Ok(m)
}

/// `int_0^1 w(s) g(s) s^shift ds` for g in Q(i)[s, ...]: replaces s^m by M_{m+shift}.
fn moment_integral(g: &GPoly, shift: usize, s: Symbol, moments: &[GPoly]) -> GPoly {
    let mut out = GPoly::zero();
    for (part, is_im) in [(&g.re, false), (&g.im, true)] {
        for (mono, q) in part.terms() {
            let (rest, e) = mono.remove(s);
            let c = Poly::term(&q, rest);
            let c = if is_im { GPoly::new(Poly::zero(), c) } else { GPoly::real(c) };
            out = out.add(&c.mul(&moments[e as usize + shift]));
        }
    }
    out
}

fn product(ps: &[Poly]) -> Poly {
    ps.iter().fold(Poly::one(), |acc, p| acc.mul(p))
}

/// `num / (dens[0] dens[1] ...)`, reduced: the known factors D_i that divide `num` are cancelled
/// by exact division first, so that [`Frac::new`] meets (almost always) a coprime pair, which the
/// engine certifies cheaply.
pub(crate) fn frac(num: Poly, dens: &[Poly]) -> Frac {
    let mut num = num;
    let mut rest: Vec<Poly> = Vec::new();
    for d in dens {
        match num.div_exact(d) {
            Some(q) if d.as_q().is_none() => num = q,
            _ => rest.push(d.clone()),
        }
    }
    Frac::new(num, product(&rest)).expect("the denominators D_i = Re M_(2i+1) are non-zero polynomials")
}

/// The exact expansion through lambda^order (module doc, steps 1-6), stress kernels included.
/// Cost (test profile, 2 shared cores): order 8 about 1.3 s, order 10 about 12-18 s, order 12
/// about 60 s, three quarters of it in the stress kernels; see [`adhesion_expansion_with`].
///
/// ```
/// use periodic_contact::asymptotics::adhesion::adhesion_expansion;
/// use exact_series::Ring;
/// let e = adhesion_expansion(2).unwrap();
/// assert_eq!(e.load_constant.text(), "(-1/4)/(S*eps - 1/2)");
/// assert_eq!(e.a_coefficient(1).unwrap().text(), "(B*eps)/(S*eps - 1/2)");
/// ```
pub fn adhesion_expansion(order: usize) -> Result<AdhesionExpansion, SeriesError> {
    adhesion_expansion_with(order, true)
}

/// As [`adhesion_expansion`]; with `with_stress = false` the stress kernels are skipped
/// ([`AdhesionExpansion::stress`] is then the empty series, `prec() == 0`): what a table of A_n
/// and c_n needs (order 12 in about 12 s instead of 60 s; the MPFR values then take 10 ms).
pub fn adhesion_expansion_with(order: usize, with_stress: bool) -> Result<AdhesionExpansion, SeriesError> {
    let v = volterra_solution(order, &[Poly::one()])?;
    let (num, d) = (&v.num, &v.d);
    // Load: c_{2j} = n_j/((j+1) D_1 ... D_j).
    let mut load = vec![Frac::zero(); order + 1];
    for (j, nj) in num.iter().enumerate() {
        load[2 * j] = frac(nj.div_int(j as i64 + 1), &d[1..=j]);
    }
    Ok(AdhesionExpansion {
        order,
        load_constant: frac(Poly::one(), &[d[0].mul_int(2)]),
        load: Series::from_coeffs(load),
        slope: v.slope(order),
        volterra: v.volterra(),
        stress: v.stress(with_stress)?,
    })
}

/// The solved recurrence of steps 2-3 (module doc) for a general right side (docs/theory.md
/// section 9): `Re I(chi) = pi sum_N rhs_N chi^(2N+1)` (the parabola: rhs = [1]), i.e.
/// `p_N Re M_(2N+1) = rhs_N - Re sum_{n=1}^{N} p_(N-n) T_(n,N-n)`, kept as numerators over the
/// common denominator: `p_N = n_N/(D_0 ... D_N)`,
/// `n_N = rhs_N D_0 ... D_(N-1) - Re sum_n n_(N-n) T_(n,N-n) D_(N-n+1) ... D_(N-1)`.
pub(crate) struct VolterraSolution {
    /// J = order/2: p_0 .. p_J.
    pub(crate) jmax: usize,
    /// n_N.
    pub(crate) num: Vec<Poly>,
    /// D_N = Re M_(2N+1).
    pub(crate) d: Vec<Poly>,
    /// T_(n,j), n + j <= J.
    t: Vec<Vec<GPoly>>,
}

/// Solves the recurrence through p_(order/2) for the right side `rhs` (missing entries are 0).
pub(crate) fn volterra_solution(order: usize, rhs: &[Poly]) -> Result<VolterraSolution, SeriesError> {
    let jmax = order / 2;
    let prec = 2 * jmax + 1;
    let s_sym = symbol(SVAR)?;
    let s = Poly::symbol(s_sym);
    let g = kernel_factor(prec, &Poly::one(), &s)?;
    let moments = half_range_moments(2 * jmax + 2)?;
    // t[n][j] = T_{n,j}, n + j <= jmax.
    let t: Vec<Vec<GPoly>> = (0..=jmax)
        .map(|n| (0..=jmax - n).map(|j| moment_integral(&g.coeffs()[2 * n], 2 * j + 1, s_sym, &moments)).collect())
        .collect();
    let d: Vec<Poly> = (0..=jmax).map(|i| moments[2 * i + 1].re.clone()).collect();
    let rhs_at = |n: usize| rhs.get(n).cloned().unwrap_or_else(Poly::zero);
    // Numerators n_N of p_N = n_N/(D_0 ... D_N).
    let mut num: Vec<Poly> = vec![rhs_at(0)];
    for nn in 1..=jmax {
        let mut acc = Poly::zero();
        for (n, tn) in t.iter().enumerate().take(nn + 1).skip(1) {
            let j = nn - n;
            let f = num[j].mul(&product(&d[j + 1..nn]));
            acc = acc.add(&f.mul(&tn[j].re));
        }
        let r = rhs_at(nn);
        num.push(if r.is_zero() { acc.neg() } else { r.mul(&product(&d[..nn])).sub(&acc) });
    }
    Ok(VolterraSolution { jmax, num, d, t })
}

impl VolterraSolution {
    /// p_j = n_j/(D_0 ... D_j), reduced.
    pub(crate) fn volterra(&self) -> Vec<Frac> {
        (0..=self.jmax).map(|j| frac(self.num[j].clone(), &self.d[..=j])).collect()
    }

    /// The slope series of step 4: coefficient of chi^(2J+1) is
    /// psi_J = -2 [sum_j n_j Im T_(J-j,j) D_(j+1)...D_J]/(D_0...D_J), through chi^(order+1).
    pub(crate) fn slope(&self, order: usize) -> Series<Frac> {
        let (num, d, t) = (&self.num, &self.d, &self.t);
        let mut slope = vec![Frac::zero(); order + 2];
        for jj in 0..=self.jmax {
            let mut acc = Poly::zero();
            for (j, nj) in num.iter().enumerate().take(jj + 1) {
                acc = acc.add(&nj.mul(&t[jj - j][j].im).mul(&product(&d[j + 1..=jj])));
            }
            slope[2 * jj + 1] = frac(acc.mul_int(-2), &d[..=jj]);
        }
        Series::from_coeffs(slope)
    }

    /// The stress kernels of step 6, h_N = sum_j p_j tau^(2j+1) H_(N-j)(xi, tau), common
    /// denominator D_0...D_N; the empty series without stresses.
    pub(crate) fn stress(&self, with_stress: bool) -> Result<Series<Gaussian<Frac>>, SeriesError> {
        let (jmax, num, d) = (self.jmax, &self.num, &self.d);
        let prec = 2 * jmax + 1;
        let xi = Poly::symbol(symbol(XI)?);
        let tau = Poly::symbol(symbol(TAU)?);
        let h = kernel_factor(prec, &xi, &tau)?;
        let mut stress = vec![Gaussian::<Frac>::zero(); if with_stress { prec } else { 0 }];
        for nn in (0..=jmax).filter(|_| with_stress) {
            let mut acc = GPoly::zero();
            let mut tau_pow = tau.clone();
            for (j, nj) in num.iter().enumerate().take(nn + 1) {
                let f = GPoly::real(nj.mul(&product(&d[j + 1..=nn])).mul(&tau_pow));
                acc = acc.add(&f.mul(&h.coeffs()[2 * (nn - j)]));
                tau_pow = tau_pow.mul(&tau).mul(&tau);
            }
            stress[2 * nn] = Gaussian::new(frac(acc.re, &d[..=nn]), frac(acc.im, &d[..=nn]));
        }
        Ok(Series::from_coeffs(stress))
    }
}

/// Why an expansion could not be evaluated.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum AdhesionEvalError {
    /// nu outside [0, 1/2].
    #[error("Poisson's ratio {0} is outside [0, 1/2]")]
    PoissonRatio(String),
    /// A coefficient holds a symbol other than eps, B, S (xi, tau: use the stress evaluation).
    #[error(transparent)]
    Unbound(#[from] UnboundSymbol),
}

/// Guard bits of the evaluation: the rational functions are formed at `prec + GUARD_BITS` and
/// rounded once. The polynomials have coefficients of moderate size and eps, B, S = O(1), so the
/// cancellation is a few dozen bits at order 12 (measured in the tests by comparing precisions).
pub const GUARD_BITS: u32 = SERIES_GUARD_BITS;

/// The expansion's coefficients at a given nu, in MPFR.
#[derive(Debug, Clone)]
pub struct AdhesionValues {
    /// Precision in bits of every value.
    pub prec: u32,
    /// eps = ln(3 - 4 nu)/(2 pi).
    pub eps: Float,
    /// B = pi/cosh(pi eps).
    pub b: Float,
    /// S(eps).
    pub s: Float,
    /// C_P = pi/(2 (1 - 2 eps S)).
    pub load_constant: Float,
    /// c_n, n = 0..=order (index = power of lambda).
    pub load: Vec<Float>,
    /// A_n/(k (pi/L)^(n-1)), n = 0..=order+1.
    pub slope: Vec<Float>,
    /// p_j of the module doc (`P'(eta) = pi sum_j p_j eta^(2j+1)`).
    pub volterra: Vec<Float>,
}

/// A rational function of (eps, B, S) at the given values, at `w` bits.
fn frac_mpfr(f: &Frac, values: &[(Symbol, Float)], w: u32) -> Result<Float, UnboundSymbol> {
    let n = poly_mpfr(f.numer(), values, w)?;
    let d = poly_mpfr(f.denom(), values, w)?;
    Ok(n / d)
}

/// The derived constants of the material with Poisson's ratio `nu` (exact) at the working
/// precision `prec + GUARD_BITS` of an evaluation to `prec` bits: built once per evaluation
/// ([`AdhesionParamsMpfr`]: eps and B from the exact kappa = 3 - 4 nu, S by its accelerated sum).
pub fn series_constants(nu: &Q, prec: u32) -> Result<AdhesionParamsMpfr, AdhesionEvalError> {
    let material = Material::from_contact_modulus(nu.clone(), Q::from_integer(1.into()))
        .map_err(|_| AdhesionEvalError::PoissonRatio(nu.to_string()))?;
    Ok(AdhesionParamsMpfr::new(&material, prec + GUARD_BITS))
}

/// Bindings of the symbols (eps, B, S) to the values in `constants`, at their precision.
pub fn symbol_values(constants: &AdhesionParamsMpfr) -> Vec<(Symbol, Float)> {
    let sym = |n: &str| symbol(n).expect("valid symbol name");
    vec![(sym(EPS), constants.eps.clone()), (sym(B), constants.b.clone()), (sym(S), constants.s.clone())]
}

/// Every coefficient of `exp` at Poisson's ratio `nu` (exact), to `prec` bits.
pub fn adhesion_values(exp: &AdhesionExpansion, nu: &Q, prec: u32) -> Result<AdhesionValues, AdhesionEvalError> {
    let constants = series_constants(nu, prec)?;
    let w = constants.prec;
    let values = symbol_values(&constants);
    let round = |x: Float| Float::with_val(prec, x);
    let ev = |f: &Frac| frac_mpfr(f, &values, w).map(round);
    let pi = Float::with_val(w, rug::float::Constant::Pi);
    Ok(AdhesionValues {
        prec,
        eps: round(values[0].1.clone()),
        b: round(values[1].1.clone()),
        s: round(values[2].1.clone()),
        load_constant: round(frac_mpfr(&exp.load_constant, &values, w)? * pi),
        load: exp.load.coeffs().iter().map(ev).collect::<Result<_, _>>()?,
        slope: exp.slope.coeffs().iter().map(ev).collect::<Result<_, _>>()?,
        volterra: exp.volterra.iter().map(ev).collect::<Result<_, _>>()?,
    })
}

/// The stress coefficient `int_xi^1 (tau+xi)^(-1/2+i eps) (tau-xi)^(-1/2-i eps) h_N(xi, tau) dtau`
/// (the coefficient of `lambda^(2N)` in `(q2 + i q1) B/(pi E* k a)`, module doc step 6) at
/// `0 <= xi < 1` for the material of `constants` ([`series_constants`] at `prec`), by tanh-sinh
/// quadrature in MPFR (`tau = xi + (1 - xi) t`; the endpoint factor
/// `t^(-1/2 - i eps)` is absorbed by the double-exponential decay). Returns (Re, Im) = (q2, q1)
/// parts. The accuracy is that of the rule (`bits`), checked in the tests against two rules.
pub fn stress_coefficient_mpfr(
    exp: &AdhesionExpansion,
    n: usize,
    xi: &Float,
    constants: &AdhesionParamsMpfr,
    bits: u32,
    prec: u32,
) -> Result<Option<Complex>, AdhesionEvalError> {
    let Some(h) = exp.stress.coeff(2 * n) else {
        return Ok(None);
    };
    let w = constants.prec;
    let mut values = symbol_values(constants);
    let eps = &constants.eps;
    let rule = TanhSinh::new(bits, 1.0, w);
    let one_m_xi = Float::with_val(w, 1 - xi.clone());
    let sym = |n: &str| symbol(n).expect("valid symbol name");
    values.push((sym(XI), Float::with_val(w, xi)));
    values.push((sym(TAU), Float::with_val(w, 0)));
    let mut acc = Complex::with_val(w, 0);
    for k in 0..rule.len() {
        let t = &rule.s[k];
        let tau = Float::with_val(w, &one_m_xi * t) + xi;
        let plus = Float::with_val(w, &tau + xi);
        let minus = Float::with_val(w, &one_m_xi * t);
        // (tau+xi)^(-1/2+i eps) (tau-xi)^(-1/2-i eps) = exp(-ln(plus minus)/2 + i eps ln(plus/minus))
        let lp = Float::with_val(w, plus.ln_ref());
        let lm = Float::with_val(w, minus.ln_ref());
        let re = Float::with_val(w, &lp + &lm) / -2i32;
        let im = Float::with_val(w, &lp - &lm) * eps;
        let weight = Complex::with_val(w, (re, im)).exp();
        values[4].1 = tau;
        let hv = Complex::with_val(w, (frac_mpfr(&h.re, &values, w)?, frac_mpfr(&h.im, &values, w)?));
        acc += weight * hv * &rule.w[k];
    }
    Ok(Some(Complex::with_val(prec, acc * one_m_xi)))
}

#[cfg(test)]
mod tests;
