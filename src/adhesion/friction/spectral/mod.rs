//! The spectral method for the single punch's unit increment (docs/theory.md section 17.7,
//! equations (17.7), (17.9)), generic over `f64` and MPFR ([`Real`]).
//!
//! With a = 1, E* k = 1, H\[f\](x) = (1/pi) PV int_-1^1 f(xi)/(x - xi) dxi, the increment
//! s = s2 + i s1 (s2 even, s1 odd) at stick half-width gamma solves the derivatives of (17.7),
//!     H\[s2\] - beta s1 = 0 on (0, 1),   H\[s1\] + beta s2 = 0 on (0, gamma),
//!     s1 = mu s2 on (gamma, 1),   int_-1^1 s2 = 1,
//! (the constants of (17.7) are the free descent v0 and, by oddness, zero). The basis carries the
//! exponents of (17.2)/(17.3) (section 17.7 derives which families occur): with
//! alpha = -1/2 - theta0, omega = -1/2 + theta0, tan(pi theta0) = beta mu,
//! - stick zone, z = x/gamma, w = 1 - z^2, u = 2 v^2 - 1 with v = artanh(x)/artanh(gamma):
//!   s2 = sum P_k T_k(u) + w^alpha sum Q_k T_k(u),   s1 = z (sum R_k T_k(u) + w^alpha sum S_k T_k(u));
//! - slip zone, zeta = (x - gamma)/(1 - gamma), y = 2 zeta - 1 (the single punch) or, for the
//!   row ([`Spectral::row`]), y = 2 s - 1 with s = ln(1 + (x - gamma)/(2 gamma))/ln(1 + (1 - gamma)/(2 gamma)):
//!   s2 = (1 - zeta)^omega (sum A_k T_k(y) + zeta^alpha sum B_k T_k(y)),
//!
//! T_k Chebyshev polynomials, k < n: 6 n unknowns. The equations are collocated at F (2 n + 2)
//! Chebyshev points of each zone (both on the stick zone) and solved with the normalisation in the
//! least-squares sense (Householder QR). The families are a frame (the smooth and the singular
//! family of one density nearly dependent), so `f64` oversamples, F = [`F64_OVERSAMPLE`] (about
//! 11 digits in gamma and 12-14 in C_P against MPFR instead of 7-8); MPFR keeps F = 1
//! ([`Spectral::oversampled`]). The Cauchy integrals are exact up to the quadrature: the
//! self-zone principal value by subtraction, PV int f/(x - xi) = int (f(xi) - f(x))/(x - xi) +
//! f(x) ln((x - a)/(b - x)), every integral by composite tanh-sinh graded toward near singularities
//! (`quadrature.rs`).
//!
//! The stick-edge defect is the coefficient of |x - gamma|^alpha in r = s1 - mu s2 on the stick
//! side, sum S_k - mu sum Q_k (up to the positive factor (2 gamma)^alpha... of r's leading term); the self-similar
//! gamma is its zero (17.3: the increment bounded at gamma). The load coefficient of the parabola
//! is C_P = 1/(2 I), I = (1/pi) int_0^1 s2 (-ln(1 - xi^2)/xi^2) dxi (17.9).
//!
//! `coupled = false` drops beta s1 from the first equation (the uncoupled problem, theta0 = 0).
//!
//! The periodic row ([`Spectral::row`], docs/theory.md section 17.8, (17.10)) is the same problem
//! in the tangent variable T = tan(chi)/tan(lambda): the stick condition gains the constant
//! (1/pi) int s1 tau^2 T/(1 + tau^2 T^2) and the right side b beta tau/pi, the normalisation the
//! weight 1/(1 + tau^2 T^2) (tau = tan(lambda)), and the slip zone's Chebyshev variable is
//! logarithmic in T + gamma.
//!
//! The solved increment's fields ([`fields`]): the densities at a point, the outside slope
//! H\[s2\] beyond the contact (the kernel of the row's load (17.11)) and the tangential strain.

use super::quadrature::{graded, least_squares, DoubleExp};
use super::real::Real;

pub mod fields;

/// Collocation points per zone in `f64`, in units of 2 n + 2 (the number of unknowns per
/// equation and zone, plus 2). The basis is a frame, not a basis: the smooth and the singular
/// family of one density (P and Q of s2 on the stick zone, A and B on the slip zone) are nearly
/// dependent (each family alone: condition number 2-10; the pair 1e8, 1e11, 1e14 at n = 6, 8,
/// 10), and such a least-squares problem is stable only when oversampled (docs/theory.md section
/// 17.7). MPFR keeps 1: its guard bits absorb the conditioning and its verified values stand.
pub const F64_OVERSAMPLE: usize = 3;

/// The increment at one gamma, solved.
#[derive(Debug, Clone)]
pub struct SpectralIncrement<T> {
    /// Stick half-width.
    pub gamma: T,
    /// Coefficients [P, Q, R, S, A, B], n each.
    pub coeffs: Vec<T>,
    n: usize,
    mu: T,
    alpha: T,
    omega: T,
    zones: Zones<T>,
}

/// The problem's constants at one precision.
#[derive(Debug, Clone)]
pub struct Spectral<T> {
    beta: T,
    beta_normal: T,
    mu: T,
    alpha: T,
    omega: T,
    n: usize,
    rule: DoubleExp<T>,
    /// tan(lambda) of the periodic row in the tangent variable (zero: the single punch).
    tau: T,
    /// The right side of the stick condition, b beta tau/pi (zero: the single punch, `paper`).
    lateral: T,
    /// The slip zone's Chebyshev variable logarithmic in x + gamma (the row) or linear.
    log_slip: bool,
    /// Collocation points per zone: `oversample` (2 n + 2).
    oversample: usize,
    /// The stick zone resolved on the scale 1 - gamma ([`Spectral::narrow`]).
    narrow: bool,
}

/// Constants of the basis at one gamma, computed once (not per quadrature node).
#[derive(Debug, Clone)]
struct Zones<T> {
    one: T,
    two: T,
    /// 2 gamma.
    two_g: T,
    /// gamma^2.
    gg: T,
    /// 1 - gamma (the slip zone's length).
    one_g: T,
    /// ln((1 + gamma)/(1 - gamma)): v = 1 at the stick edge.
    sigma_g: T,
    /// ln(1 + (1 - gamma)/(2 gamma)): s = 1 at the contact edge (the row's slip variable).
    slip_log: T,
}

impl<T: Real> Zones<T> {
    fn new(gamma: &T) -> Zones<T> {
        let (one, two) = (gamma.lit(1.0), gamma.lit(2.0));
        let two_g = two.clone() * gamma.clone();
        let one_g = one.clone() - gamma.clone();
        Zones {
            gg: gamma.clone() * gamma.clone(),
            sigma_g: ((one.clone() + gamma.clone()) / one_g.clone()).ln(),
            slip_log: (one_g.clone() / two_g.clone()).ln_1p(),
            one,
            two,
            two_g,
            one_g,
        }
    }
}

/// The basis at one quadrature node, in storage reused from node to node: the Chebyshev values
/// T_k and the families' factors (stick zone: w^alpha, z, z w^alpha; slip zone: (1 - zeta)^omega,
/// (1 - zeta)^omega zeta^alpha), so family f's k-th value is fac[f] T_k (the first stick family:
/// T_k).
struct Node<T> {
    t: Vec<T>,
    fac: [T; 3],
    a: T,
    b: T,
    c: T,
}

impl<T: Real> Node<T> {
    fn new(like: &T, n: usize) -> Node<T> {
        let z = like.lit(0.0);
        Node { t: vec![z.clone(); n], fac: [z.clone(), z.clone(), z.clone()], a: z.clone(), b: z.clone(), c: z }
    }

    /// T_k(u), k < n, into `t` (u in `a`; `b` scratch).
    fn chebyshev(&mut self, zn: &Zones<T>) {
        let n = self.t.len();
        self.t[0].set(&zn.one);
        if n > 1 {
            self.t[1].set(&self.a);
        }
        self.b.set_mul(&zn.two, &self.a);
        for k in 2..n {
            let (lo, hi) = self.t.split_at_mut(k);
            hi[0].set_mul_sub(&self.b, &lo[k - 1], &lo[k - 2]);
        }
    }

    /// Family `f`'s values as a vector (the first stick family's factor is one).
    fn family(&self, f: Option<usize>) -> impl Iterator<Item = T> + '_ {
        self.t.iter().map(move |v| match f {
            None => v.clone(),
            Some(i) => self.fac[i].clone() * v.clone(),
        })
    }
}

/// h\[j\] += (fac T_j - f_j) k for j < n (the principal value's subtraction, `f` the values at
/// the pole) or h\[j\] += (fac T_j) k (`f` None); fac None: one.
fn accumulate<T: Real>(h: &mut [T], k: &T, fac: Option<&T>, t: &[T], f: Option<&[T]>, tmp: &mut T) {
    for (j, (hj, tj)) in h.iter_mut().zip(t).enumerate() {
        match (fac, f) {
            (None, None) => tmp.set(tj),
            (Some(c), None) => tmp.set_mul(c, tj),
            (None, Some(f)) => tmp.set_sub(tj, &f[j]),
            (Some(c), Some(f)) => tmp.set_mul_sub(c, tj, &f[j]),
        }
        *tmp *= k;
        *hj += &*tmp;
    }
}

impl<T: Real> Node<T> {
    /// The stick zone's node times the kernel `k` into the rows of pi H\[s2\] over (P, Q) (`h2`,
    /// 2 n long) and pi H\[s1\] over (R, S) (`h1`), less the families' values at the pole
    /// (`pole` = (s2's, s1's), 2 n each: the principal value's subtraction) where given.
    fn add_stick(&self, h2: &mut [T], h1: &mut [T], k: &T, pole: Option<(&[T], &[T])>, tmp: &mut T) {
        self.add_pair(h2, k, [None, Some(&self.fac[0])], pole.map(|p| p.0), tmp);
        self.add_pair(h1, k, [Some(&self.fac[1]), Some(&self.fac[2])], pole.map(|p| p.1), tmp);
    }

    /// The slip zone's node times the kernel `k` into the rows over (A, B) (`h`, 2 n long), less
    /// the families' values at the pole (2 n) where given.
    fn add_slip(&self, h: &mut [T], k: &T, pole: Option<&[T]>, tmp: &mut T) {
        self.add_pair(h, k, [Some(&self.fac[0]), Some(&self.fac[1])], pole, tmp);
    }

    /// Two families (factors `fac`, None: one) into the two halves of `h`.
    fn add_pair(&self, h: &mut [T], k: &T, fac: [Option<&T>; 2], pole: Option<&[T]>, tmp: &mut T) {
        let n = self.t.len();
        let (lo, hi) = h.split_at_mut(n);
        accumulate(lo, k, fac[0], &self.t, pole.map(|f| &f[..n]), tmp);
        accumulate(hi, k, fac[1], &self.t, pole.map(|f| &f[n..]), tmp);
    }
}

/// e^y - 1 for y >= 0 without cancellation: the series below 1/2, else e^y - 1.
fn expm1<T: Real>(y: &T) -> T {
    if y.to_f64() >= 0.5 {
        return y.exp() - y.lit(1.0);
    }
    let tiny = y.lit(2f64.powi(-(y.bits() as i32) - 2));
    let (mut sum, mut term, mut k) = (y.clone(), y.clone(), 1.0);
    while term.abs() > tiny.clone() * sum.abs() {
        k += 1.0;
        term = term * y.clone() / y.lit(k);
        sum += &term;
    }
    sum
}

/// A collocation point: x with its distances to gamma (gamma - x, negative on the slip zone) and
/// to 1, each accurate on its own.
struct Target<T> {
    x: T,
    to_gamma: T,
    to_one: T,
}

impl<T: Real> Spectral<T> {
    /// The method for Poisson parameter `beta`, friction `mu` (given at the working precision)
    /// with n polynomials per family.
    pub fn new(beta: T, mu: T, n: usize, coupled: bool) -> Spectral<T> {
        let beta_normal = if coupled { beta.clone() } else { beta.lit(0.0) };
        let theta0 = (beta_normal.clone() * mu.clone()).atan() / beta.pi();
        let half = beta.lit(0.5);
        let edge = (0.5 - theta0.to_f64()).min(1.0);
        let rule = DoubleExp::new(&beta.lit(1.0), edge);
        let (tau, lateral) = (beta.lit(0.0), beta.lit(0.0));
        let oversample = if beta.bits() == 53 { F64_OVERSAMPLE } else { 1 };
        Spectral {
            alpha: -half.clone() - theta0.clone(),
            omega: -half + theta0,
            beta,
            beta_normal,
            mu,
            n,
            rule,
            tau,
            lateral,
            log_slip: false,
            oversample,
            narrow: false,
        }
    }

    /// The same method collocated at `factor` (2 n + 2) points per zone (the default: 1 in MPFR,
    /// [`F64_OVERSAMPLE`] in `f64`).
    pub fn oversampled(mut self, factor: usize) -> Spectral<T> {
        self.oversample = factor.max(1);
        self
    }

    /// The same method with the stick zone resolved on the scale delta = 1 - gamma, for narrow
    /// slip zones (large mu, docs/theory.md section 17.3 "Large mu"): the stick zone's
    /// collocation points Chebyshev in its basis variable u (not in x: the points in x come no
    /// nearer the stick edge than gamma (pi/(4 m))^2/2, 6e-4 at m = 22, blind to the increment's
    /// structure on the scale delta beside it) and its integrals graded toward +-gamma from the
    /// scale delta (the basis is analytic there but for the slip zones' edges +-1, delta beyond).
    /// The basis is unchanged.
    pub fn narrow(mut self) -> Spectral<T> {
        self.narrow = true;
        self
    }

    /// The grading toward the stick zone's ends: 1 - gamma where [`Spectral::narrow`], else none.
    fn edge<'a>(&self, zn: &'a Zones<T>) -> Option<&'a T> {
        self.narrow.then_some(&zn.one_g)
    }

    /// The same problem with `n` polynomials per family and 2 n + 2 points per zone: a cheap
    /// run whose stick-edge root brackets this one's (`spectral_punch::root_f64`).
    pub fn coarse(&self, n: usize) -> Spectral<T> {
        Spectral { n, oversample: 1, ..self.clone() }
    }

    /// The method for the periodic row at lambda = pi a/L in the tangent variable
    /// T = tan(chi)/tan(lambda) (docs/theory.md section 17.8, (17.10)): `tau` = tan(lambda),
    /// `periodic` the convention (b = 1).
    pub fn row(beta: T, mu: T, n: usize, tau: T, periodic: bool) -> Spectral<T> {
        let mut sp = Spectral::new(beta, mu, n, true);
        let b = sp.beta.lit(if periodic { 1.0 } else { 0.0 });
        sp.lateral = b * sp.beta.clone() * tau.clone() / tau.pi();
        sp.tau = tau;
        sp.log_slip = true;
        sp
    }

    /// The stick zone's basis at the point with distances d_a = x + gamma and d_b = gamma - x
    /// into `nd`: T_k(u) and the factors w^alpha, z, z w^alpha.
    fn stick_node(&self, zn: &Zones<T>, d_a: &T, d_b: &T, nd: &mut Node<T>) {
        // z = (d_a - d_b)/(2 gamma), w = d_a d_b/gamma^2
        nd.b.set_sub(d_a, d_b);
        nd.b /= &zn.two_g;
        nd.fac[1].set(&nd.b);
        nd.a.set_mul(d_a, d_b);
        nd.a /= &zn.gg;
        nd.fac[0] = nd.a.powr(&self.alpha);
        // v = artanh(x)/artanh(gamma): the slip zones' edge singularities at x = +-1 pushed to
        // infinity (section 17.7); u = 2 v^2 - 1
        nd.b.set(&zn.one_g);
        nd.b += d_a;
        nd.c.set(&zn.one_g);
        nd.c += d_b;
        nd.b /= &nd.c;
        let mut v = nd.b.ln();
        v /= &zn.sigma_g;
        nd.a.set_mul(&zn.two, &v);
        nd.a *= &v;
        nd.a -= &zn.one;
        let [wa, z, zwa] = &mut nd.fac;
        zwa.set_mul(z, wa);
        nd.chebyshev(zn);
    }

    /// The slip zone's basis at distances d_a = x - gamma, d_b = 1 - x into `nd`: T_k(y) and
    /// the factors (1 - zeta)^omega and (1 - zeta)^omega zeta^alpha.
    fn slip_node(&self, zn: &Zones<T>, d_a: &T, d_b: &T, nd: &mut Node<T>) {
        // zeta = d_a/(1 - gamma), 1 - zeta = d_b/(1 - gamma)
        nd.b.set(d_a);
        nd.b /= &zn.one_g;
        nd.c.set(d_b);
        nd.c /= &zn.one_g;
        nd.fac[0] = nd.c.powr(&self.omega);
        let [fo, fa, _] = &mut nd.fac;
        *fa = nd.b.powr(&self.alpha);
        *fa *= &*fo;
        if self.log_slip {
            // y = 2 s - 1, s = ln(1 + (x - gamma)/(2 gamma))/ln(1 + (1 - gamma)/(2 gamma)): the
            // other stick edge x = -gamma pushed to s = -infinity (the row, section 17.8)
            nd.a.set(d_a);
            nd.a /= &zn.two_g;
            let mut s = nd.a.ln_1p();
            s /= &zn.slip_log;
            nd.a.set_mul(&zn.two, &s);
            nd.a -= &zn.one;
        } else {
            nd.a.set_sub(d_a, d_b);
            nd.a /= &zn.one_g;
        }
        nd.chebyshev(zn);
    }

    /// s2 families (P, Q) and s1 families (R, S) of the stick zone at the point with distances
    /// d_a = x + gamma and d_b = gamma - x.
    fn stick_values(&self, zn: &Zones<T>, d_a: &T, d_b: &T) -> (Vec<T>, Vec<T>) {
        let mut nd = Node::new(d_a, self.n);
        self.stick_node(zn, d_a, d_b, &mut nd);
        let s2 = nd.family(None).chain(nd.family(Some(0))).collect();
        let s1 = nd.family(Some(1)).chain(nd.family(Some(2))).collect();
        (s2, s1)
    }

    /// s2 families (A, B) of the slip zone at distances d_a = x - gamma, d_b = 1 - x.
    fn slip_values(&self, zn: &Zones<T>, d_a: &T, d_b: &T) -> Vec<T> {
        let mut nd = Node::new(d_a, self.n);
        self.slip_node(zn, d_a, d_b, &mut nd);
        nd.family(Some(0)).chain(nd.family(Some(1))).collect()
    }

    /// pi H[s2](x) and pi H[s1](x) as rows over the 6 n coefficients.
    fn hilbert_rows(&self, zn: &Zones<T>, gamma: &T, tg: &Target<T>) -> (Vec<T>, Vec<T>) {
        let n = self.n;
        let zero = gamma.lit(0.0);
        let (mut h2, mut h1) = (vec![zero.clone(); 6 * n], vec![zero.clone(); 6 * n]);
        let in_stick = tg.to_gamma > zero;
        // one node's basis, the kernel and a scratch value, reused at every node
        let mut nd = Node::new(gamma, n);
        let (mut k, mut dx, mut tmp) = (zero.clone(), zero.clone(), zero.clone());
        // stick zone (-gamma, gamma), offsets from -gamma
        let len = gamma.lit(2.0) * gamma.clone();
        if in_stick {
            let xo = tg.x.clone() + gamma.clone();
            let (f2, f1) = self.stick_values(zn, &xo, &tg.to_gamma);
            let mut pieces = graded(&zero, &xo, self.edge(zn), Some(&tg.to_gamma));
            pieces.extend(graded(&xo, &len, Some(&xo), self.edge(zn)));
            self.rule.sweep(&len, &pieces, |d_a, d_b, w| {
                dx.set_sub(d_b, &tg.to_gamma);
                if dx == zero {
                    return;
                }
                k.set(w);
                k /= &dx;
                self.stick_node(zn, d_a, d_b, &mut nd);
                nd.add_stick(&mut h2[..2 * n], &mut h1[2 * n..4 * n], &k, Some((&f2, &f1)), &mut tmp);
            });
            let lg = (xo / tg.to_gamma.clone()).ln();
            for j in 0..2 * n {
                h2[j].add_mul(&lg, &f2[j]);
                h1[2 * n + j].add_mul(&lg, &f1[j]);
            }
        } else {
            let beyond = -tg.to_gamma.clone();
            let pieces = graded(&zero, &len, self.edge(zn), Some(&beyond));
            self.rule.sweep(&len, &pieces, |d_a, d_b, w| {
                dx.set(d_b);
                dx += &beyond;
                k.set(w);
                k /= &dx;
                self.stick_node(zn, d_a, d_b, &mut nd);
                nd.add_stick(&mut h2[..2 * n], &mut h1[2 * n..4 * n], &k, None, &mut tmp);
            });
        }
        // slip zones: (gamma, 1) with kernel 1/(x - eta) and its mirror with 1/(x + eta)
        let len = gamma.lit(1.0) - gamma.clone();
        let (mut minus, mut plus) = (vec![zero.clone(); 2 * n], vec![zero.clone(); 2 * n]);
        if in_stick {
            let pieces = graded(&zero, &len, Some(&tg.to_gamma), None);
            let from_gamma = -tg.to_gamma.clone();
            self.rule.sweep(&len, &pieces, |d_a, d_b, w| {
                // k = -w/(to_gamma + d_a)
                dx.set_sub(&from_gamma, d_a);
                k.set(w);
                k /= &dx;
                self.slip_node(zn, d_a, d_b, &mut nd);
                nd.add_slip(&mut minus, &k, None, &mut tmp);
            });
        } else {
            let xo = -tg.to_gamma.clone();
            let g = self.slip_values(zn, &xo, &tg.to_one);
            let mut pieces = graded(&zero, &xo, None, Some(&tg.to_one));
            pieces.extend(graded(&xo, &len, Some(&xo), None));
            // x - eta from the distances to the nearer end: from gamma (x - gamma - d_a) it carries
            // the rounding of d_a, about 1e-16 (1 - gamma), which at a point 1e-4 from the contact
            // edge is 1e-12 relative and, times the edge singularity's weight, had put 5e-11 into
            // the rows there and 1e-12 into the stick edge (`f64`; docs/theory.md section 17.8)
            let near_one = tg.to_one < xo;
            self.rule.sweep(&len, &pieces, |d_a, d_b, w| {
                if near_one {
                    dx.set_sub(d_b, &tg.to_one);
                } else {
                    dx.set_sub(&xo, d_a);
                }
                if dx == zero {
                    return;
                }
                k.set(w);
                k /= &dx;
                self.slip_node(zn, d_a, d_b, &mut nd);
                nd.add_slip(&mut minus, &k, Some(&g), &mut tmp);
            });
            let lg = (xo / tg.to_one.clone()).ln();
            for j in 0..2 * n {
                minus[j].add_mul(&lg, &g[j]);
            }
        }
        let mirror = tg.x.clone() + gamma.clone();
        let pieces = graded(&zero, &len, Some(&mirror), None);
        self.rule.sweep(&len, &pieces, |d_a, d_b, w| {
            dx.set(&mirror);
            dx += d_a;
            k.set(w);
            k /= &dx;
            self.slip_node(zn, d_a, d_b, &mut nd);
            nd.add_slip(&mut plus, &k, None, &mut tmp);
        });
        for j in 0..2 * n {
            h2[4 * n + j] = minus[j].clone() + plus[j].clone();
            h1[4 * n + j] = self.mu.clone() * (minus[j].clone() - plus[j].clone());
        }
        (h2, h1)
    }

    /// The collocation points: `oversample` (2 n + 2) on each zone.
    fn targets(&self, gamma: &T) -> Vec<Target<T>> {
        let m = self.oversample * (2 * self.n + 2);
        let pi = gamma.pi();
        let mut out = Vec::with_capacity(2 * m);
        if self.narrow {
            out.extend(self.narrow_stick_targets(gamma, m));
        }
        for i in (0..m).filter(|_| !self.narrow) {
            let th = pi.clone() * gamma.lit((2 * i + 1) as f64) / gamma.lit((4 * m) as f64);
            let sh = (th.clone() * gamma.lit(0.5)).sin();
            let x = gamma.clone() * th.cos();
            let to_gamma = gamma.lit(2.0) * gamma.clone() * sh.clone() * sh;
            let to_one = gamma.lit(1.0) - x.clone();
            out.push(Target { x, to_gamma, to_one });
        }
        let len = gamma.lit(1.0) - gamma.clone();
        for i in 0..m {
            let th = pi.clone() * gamma.lit((2 * i + 1) as f64) / gamma.lit((2 * m) as f64);
            let (c, s) = ((th.clone() * gamma.lit(0.5)).cos(), (th * gamma.lit(0.5)).sin());
            let from_gamma = len.clone() * c.clone() * c;
            let to_one = len.clone() * s.clone() * s;
            out.push(Target { x: gamma.clone() + from_gamma.clone(), to_gamma: -from_gamma, to_one });
        }
        out
    }

    /// `m` stick-zone points Chebyshev in the basis variable u = 2 v^2 - 1, v = artanh(x)/artanh(gamma)
    /// ([`Spectral::narrow`]): with S = ln((1 + gamma)/(1 - gamma)) and u = cos(th), v = cos(th/2),
    /// 1 - x = 2/(1 + e^(v S)), and gamma - x = 2 e^(v S) (e^((1 - v) S) - 1)/((1 + e^(v S))(1 + e^S))
    /// without cancellation (1 - v = 2 sin^2(th/4)).
    fn narrow_stick_targets(&self, gamma: &T, m: usize) -> Vec<Target<T>> {
        let zn = Zones::new(gamma);
        let (one, two) = (zn.one.clone(), zn.two.clone());
        let e_s = zn.sigma_g.exp();
        (0..m)
            .map(|i| {
                let th = gamma.pi() * gamma.lit((2 * i + 1) as f64) / gamma.lit((2 * m) as f64);
                let v = (th.clone() * gamma.lit(0.5)).cos();
                let sq = (th * gamma.lit(0.25)).sin();
                let rest = two.clone() * sq.clone() * sq * zn.sigma_g.clone();
                let e_v = (v * zn.sigma_g.clone()).exp();
                let to_gamma = two.clone() * e_v.clone() * expm1(&rest)
                    / ((one.clone() + e_v.clone()) * (one.clone() + e_s.clone()));
                let to_one = zn.one_g.clone() + to_gamma.clone();
                Target { x: gamma.clone() - to_gamma.clone(), to_gamma, to_one }
            })
            .collect()
    }

    /// Solves for the increment at stick half-width `gamma` in (0, 1); None when the
    /// least-squares system is singular.
    pub fn solve(&self, gamma: &T) -> Option<SpectralIncrement<T>> {
        let (rows, rhs) = self.system(gamma);
        let coeffs = least_squares(rows, rhs)?;
        Some(self.increment(gamma, coeffs))
    }

    /// The increment with given coefficients.
    pub fn increment(&self, gamma: &T, coeffs: Vec<T>) -> SpectralIncrement<T> {
        SpectralIncrement {
            gamma: gamma.clone(),
            coeffs,
            n: self.n,
            mu: self.mu.clone(),
            alpha: self.alpha.clone(),
            omega: self.omega.clone(),
            zones: Zones::new(gamma),
        }
    }

    /// The collocation rows and right side (the normalisation last).
    pub fn system(&self, gamma: &T) -> (Vec<Vec<T>>, Vec<T>) {
        let n = self.n;
        let zero = gamma.lit(0.0);
        let pi = gamma.pi();
        let mut rows = Vec::new();
        let mut rhs = Vec::new();
        let zn = Zones::new(gamma);
        let lateral_row = self.lateral_row(&zn, gamma);
        for tg in self.targets(gamma) {
            let (h2, h1) = self.hilbert_rows(&zn, gamma, &tg);
            let mut ra: Vec<T> = h2.into_iter().map(|v| v / pi.clone()).collect();
            if tg.to_gamma > zero {
                let xo = tg.x.clone() + gamma.clone();
                let (f2, f1) = self.stick_values(&zn, &xo, &tg.to_gamma);
                for j in 0..2 * n {
                    ra[2 * n + j] = ra[2 * n + j].clone() - self.beta_normal.clone() * f1[j].clone();
                }
                let mut rb: Vec<T> =
                    h1.into_iter().zip(&lateral_row).map(|(v, c)| v / pi.clone() + c.clone()).collect();
                for j in 0..2 * n {
                    rb[j] = rb[j].clone() + self.beta.clone() * f2[j].clone();
                }
                rows.push(rb);
                rhs.push(self.lateral.clone());
            } else {
                let g = self.slip_values(&zn, &-tg.to_gamma.clone(), &tg.to_one);
                for j in 0..2 * n {
                    ra[4 * n + j] = ra[4 * n + j].clone() - self.beta_normal.clone() * self.mu.clone() * g[j].clone();
                }
            }
            rows.push(ra);
            rhs.push(zero.clone());
        }
        // int_-1^1 s2/(1 + tau^2 T^2) = 1 (the unit load, (17.10))
        let mut norm = vec![zero.clone(); 6 * n];
        let one = gamma.lit(1.0);
        let weight = |t: &T| one.clone() / (one.clone() + self.tau.clone() * self.tau.clone() * t.clone() * t.clone());
        let len = gamma.lit(2.0) * gamma.clone();
        self.rule.sweep(&len, &graded(&zero, &len, self.edge(&zn), self.edge(&zn)), |d_a, d_b, w| {
            let (v2, _) = self.stick_values(&zn, d_a, d_b);
            let wt = w.clone() * weight(&(d_a.clone() - gamma.clone()));
            for j in 0..2 * n {
                norm[j] = norm[j].clone() + wt.clone() * v2[j].clone();
            }
        });
        let len = gamma.lit(1.0) - gamma.clone();
        self.rule.sweep(&len, &graded(&zero, &len, None, None), |d_a, d_b, w| {
            let v = self.slip_values(&zn, d_a, d_b);
            let wt = gamma.lit(2.0) * w.clone() * weight(&(gamma.clone() + d_a.clone()));
            for j in 0..2 * n {
                norm[4 * n + j] = norm[4 * n + j].clone() + wt.clone() * v[j].clone();
            }
        });
        rows.push(norm);
        rhs.push(gamma.lit(1.0));
        (rows, rhs)
    }

    /// The row's constant of the stick condition as a row over the coefficients:
    /// (1/pi) int_-1^1 s1(T) tau^2 T/(1 + tau^2 T^2) dT (17.10) (all zero for the single punch).
    fn lateral_row(&self, zn: &Zones<T>, gamma: &T) -> Vec<T> {
        let n = self.n;
        let zero = gamma.lit(0.0);
        let mut out = vec![zero.clone(); 6 * n];
        if self.tau == zero {
            return out;
        }
        let one = gamma.lit(1.0);
        let t2 = self.tau.clone() * self.tau.clone();
        let kern = |t: &T| t2.clone() * t.clone() / (one.clone() + t2.clone() * t.clone() * t.clone()) / gamma.pi();
        let len = gamma.lit(2.0) * gamma.clone();
        self.rule.sweep(&len, &graded(&zero, &len, self.edge(zn), self.edge(zn)), |d_a, d_b, w| {
            let (_, v1) = self.stick_values(zn, d_a, d_b);
            let k = w.clone() * kern(&(d_a.clone() - gamma.clone()));
            for j in 0..2 * n {
                out[2 * n + j] = out[2 * n + j].clone() + k.clone() * v1[j].clone();
            }
        });
        // s1 = mu s2 on (gamma, 1), odd: twice the right slip zone
        let len = one.clone() - gamma.clone();
        self.rule.sweep(&len, &graded(&zero, &len, None, None), |d_a, d_b, w| {
            let v = self.slip_values(zn, d_a, d_b);
            let k = gamma.lit(2.0) * self.mu.clone() * w.clone() * kern(&(gamma.clone() + d_a.clone()));
            for j in 0..2 * n {
                out[4 * n + j] = out[4 * n + j].clone() + k.clone() * v[j].clone();
            }
        });
        out
    }

    /// s2 of a solved increment at a point of the stick zone (`slip` false; d_a = x + gamma,
    /// d_b = gamma - x) or of the right slip zone (`slip` true; d_a = x - gamma, d_b = 1 - x).
    pub fn normal_density(&self, inc: &SpectralIncrement<T>, slip: bool, d_a: &T, d_b: &T) -> T {
        self.density(inc).at(slip, d_a, d_b)
    }

    /// [`Spectral::normal_density`] of `inc` at many points, its storage reused from point to
    /// point.
    pub fn density<'a>(&'a self, inc: &'a SpectralIncrement<T>) -> Density<'a, T> {
        Density { sp: self, inc, nd: Node::new(&inc.gamma, self.n), tmp: inc.gamma.lit(0.0) }
    }

    /// The tanh-sinh rule of the method's integrals.
    pub fn rule(&self) -> &DoubleExp<T> {
        &self.rule
    }

    /// tan(lambda) of the row (zero: the single punch).
    pub fn tau(&self) -> T {
        self.tau.clone()
    }

    /// The Poisson parameter beta (the stick condition's; the normal equation drops it when
    /// uncoupled).
    pub fn beta(&self) -> T {
        self.beta.clone()
    }

    /// The friction coefficient mu.
    pub fn mu(&self) -> T {
        self.mu.clone()
    }

    /// The working precision (bits).
    pub fn bits(&self) -> u32 {
        self.beta.bits()
    }

    /// C_P = 1/(2 I) of the parabola (17.9) from a solved increment.
    pub fn load_coefficient(&self, inc: &SpectralIncrement<T>) -> T {
        let gamma = &inc.gamma;
        let zero = gamma.lit(0.0);
        let one = gamma.lit(1.0);
        let mut dens = self.density(inc);
        let mut i_stick = zero.clone();
        let len = gamma.lit(2.0) * gamma.clone();
        let edge = self.edge(&inc.zones);
        self.rule.sweep(&len, &graded(&zero, &len, edge, edge), |d_a, d_b, w| {
            let xi = (d_a.clone() - d_b.clone()) * gamma.lit(0.5);
            let y = xi.clone() * xi;
            let kern = if y == zero { one.clone() } else { -(-y.clone()).ln_1p() / y };
            let s2 = dens.at(false, d_a, d_b);
            i_stick = i_stick.clone() + w.clone() * kern * s2;
        });
        let mut i_slip = zero.clone();
        let len = one.clone() - gamma.clone();
        self.rule.sweep(&len, &graded(&zero, &len, None, None), |d_a, d_b, w| {
            let eta = gamma.clone() + d_a.clone();
            let kern = -(d_b.ln() + (one.clone() + eta.clone()).ln()) / (eta.clone() * eta);
            let s2 = dens.at(true, d_a, d_b);
            i_slip = i_slip.clone() + w.clone() * kern * s2;
        });
        let i = (i_stick * gamma.lit(0.5) + i_slip) / gamma.pi();
        one / (gamma.lit(2.0) * i)
    }
}

/// s2 of one solved increment at many points ([`Spectral::density`]).
pub struct Density<'a, T> {
    sp: &'a Spectral<T>,
    inc: &'a SpectralIncrement<T>,
    nd: Node<T>,
    tmp: T,
}

impl<T: Real> Density<'_, T> {
    /// s2 at a point of the stick zone (`slip` false; d_a = x + gamma, d_b = gamma - x) or of
    /// the right slip zone (`slip` true; d_a = x - gamma, d_b = 1 - x).
    pub fn at(&mut self, slip: bool, d_a: &T, d_b: &T) -> T {
        let (n, zn) = (self.sp.n, &self.inc.zones);
        let c = if slip { &self.inc.coeffs[4 * n..6 * n] } else { &self.inc.coeffs[..2 * n] };
        let nd = &mut self.nd;
        let fac = if slip {
            self.sp.slip_node(zn, d_a, d_b, nd);
            [Some(&nd.fac[0]), Some(&nd.fac[1])]
        } else {
            self.sp.stick_node(zn, d_a, d_b, nd);
            [None, Some(&nd.fac[0])]
        };
        let mut acc = d_a.lit(0.0);
        for (f, cf) in fac.iter().zip(c.chunks(n)) {
            for (tj, cj) in nd.t.iter().zip(cf) {
                match f {
                    None => acc.add_mul(cj, tj),
                    Some(v) => {
                        self.tmp.set_mul(v, tj);
                        acc.add_mul(cj, &self.tmp);
                    }
                }
            }
        }
        acc
    }
}

impl<T: Real> SpectralIncrement<T> {
    /// The coefficient of w^alpha in r = s1 - mu s2 on the stick side at gamma (up to a positive
    /// factor): zero at the self-similar gamma.
    pub fn stick_edge_defect(&self) -> T {
        let n = self.n;
        let c = &self.coeffs;
        let zero = self.gamma.lit(0.0);
        let q = (0..n).fold(zero.clone(), |acc, k| acc + c[n + k].clone());
        let s = (0..n).fold(zero, |acc, k| acc + c[3 * n + k].clone());
        s - self.mu.clone() * q
    }

    /// Exponents (alpha, omega) of the basis.
    pub fn exponents(&self) -> (T, T) {
        (self.alpha.clone(), self.omega.clone())
    }
}
