//! The spectral method's basis (docs/theory.md section 17.7, the exponents of (17.2)/(17.3);
//! the row's slip variable, section 17.8): with alpha = -1/2 - theta0, omega = -1/2 + theta0,
//! tan(pi theta0) = beta mu,
//! - stick zone, z = x/gamma, w = 1 - z^2, u = 2 v^2 - 1 with v = artanh(x)/artanh(gamma) (the
//!   slip zones' edge singularities at x = +-1 pushed to infinity):
//!   s2 = sum P_k T_k(u) + w^alpha sum Q_k T_k(u),   s1 = z (sum R_k T_k(u) + w^alpha sum S_k T_k(u));
//! - slip zone, zeta = (x - gamma)/(1 - gamma), y = 2 zeta - 1 (the single punch) or, for the
//!   row, y = 2 s - 1 with s = ln(1 + (x - gamma)/(2 gamma))/ln(1 + (1 - gamma)/(2 gamma)) (the
//!   other stick edge pushed to s = -infinity):
//!   s2 = (1 - zeta)^omega (sum A_k T_k(y) + zeta^alpha sum B_k T_k(y)),   s1 = mu s2;
//!
//! T_k Chebyshev polynomials, k < n: 6 n coefficients [P, Q, R, S, A, B]. A point is given by its
//! distances to its zone's two ends, each accurate on its own (no cancellation near an edge).
//! `Zones` holds the per-gamma constants (computed once per solve, not per quadrature node),
//! `Node` one point's T_k and the families' factors in storage reused from node to node.
//!
//! Checked through the method (`spectral_tests.rs`: nu = 1/2 exactly Hertz, the uncoupled
//! problem's stick ratio to 1e-12 against the AGM) and, the families' values against the
//! reused-storage evaluation, by `pair_is_the_families_sum_bit_for_bit` (`fields.rs`).

use super::super::real::Real;
use super::Spectral;

/// Constants of the basis at one gamma, computed once (not per quadrature node).
#[derive(Debug, Clone)]
pub(super) struct Zones<T> {
    pub(super) one: T,
    pub(super) two: T,
    /// 2 gamma.
    two_g: T,
    /// gamma^2.
    gg: T,
    /// 1 - gamma (the slip zone's length).
    pub(super) one_g: T,
    /// ln((1 + gamma)/(1 - gamma)): v = 1 at the stick edge.
    pub(super) sigma_g: T,
    /// ln(1 + (1 - gamma)/(2 gamma)): s = 1 at the contact edge (the row's slip variable).
    slip_log: T,
}

impl<T: Real> Zones<T> {
    pub(super) fn new(gamma: &T) -> Zones<T> {
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
pub(super) struct Node<T> {
    pub(super) t: Vec<T>,
    pub(super) fac: [T; 3],
    a: T,
    b: T,
    c: T,
}

impl<T: Real> Node<T> {
    pub(super) fn new(like: &T, n: usize) -> Node<T> {
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

impl<T: Real> Spectral<T> {
    /// The stick zone's basis at the point with distances d_a = x + gamma and d_b = gamma - x
    /// into `nd`: T_k(u) and the factors w^alpha, z, z w^alpha.
    pub(super) fn stick_node(&self, zn: &Zones<T>, d_a: &T, d_b: &T, nd: &mut Node<T>) {
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
    pub(super) fn slip_node(&self, zn: &Zones<T>, d_a: &T, d_b: &T, nd: &mut Node<T>) {
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
    pub(super) fn stick_values(&self, zn: &Zones<T>, d_a: &T, d_b: &T) -> (Vec<T>, Vec<T>) {
        let mut nd = Node::new(d_a, self.n);
        self.stick_node(zn, d_a, d_b, &mut nd);
        let s2 = nd.family(None).chain(nd.family(Some(0))).collect();
        let s1 = nd.family(Some(1)).chain(nd.family(Some(2))).collect();
        (s2, s1)
    }

    /// s2 families (A, B) of the slip zone at distances d_a = x - gamma, d_b = 1 - x.
    pub(super) fn slip_values(&self, zn: &Zones<T>, d_a: &T, d_b: &T) -> Vec<T> {
        let mut nd = Node::new(d_a, self.n);
        self.slip_node(zn, d_a, d_b, &mut nd);
        nd.family(Some(0)).chain(nd.family(Some(1))).collect()
    }
}
