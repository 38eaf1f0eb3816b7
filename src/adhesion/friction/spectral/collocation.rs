//! The spectral method's collocation system (docs/theory.md section 17.7, (17.7); the row's
//! (17.10), section 17.8): the equations of (17.7) at `oversample` (2 n + 2) Chebyshev points of
//! each zone (both equations on the stick zone; 1 in MPFR, `F64_OVERSAMPLE` in `f64`: the basis
//! is a frame, stable in least squares only oversampled), the row's constant of the stick
//! condition and the normalisation int s2/(1 + tau^2 T^2) = 1 last: [`Spectral::system`], solved
//! by Householder QR in [`Spectral::solve`].
//!
//! The Cauchy integrals pi H\[s2\](x), pi H\[s1\](x) as rows over the 6 n coefficients (the
//! Hilbert rows) are exact up to the quadrature: the self-zone principal value by subtraction,
//! PV int f/(x - xi) = int (f(xi) - f(x))/(x - xi) + f(x) ln((x - a)/(b - x)), the slip zone and
//! its mirror (kernel 1/(x + eta)) apart, every integral by composite tanh-sinh graded toward
//! near singularities (`quadrature.rs`). One node's basis times the kernel goes into the rows of
//! a zone's families by one helper (`Node::add_stick`, `Node::add_slip`).
//!
//! Checked in `spectral_tests.rs` (`f64` against MPFR at one gamma: the rows' rounding with and
//! without the oversampling; the increment method at three friction ratios) and
//! `spectral_row_tests.rs` (the row's flat punch at beta = 0 in closed form, lambda -> 0).

use super::super::quadrature::graded;
use super::super::real::Real;
use super::basis::{Node, Zones};
use super::Spectral;

/// A collocation point: x with its distances to gamma (gamma - x, negative on the slip zone) and
/// to 1, each accurate on its own.
pub(super) struct Target<T> {
    pub(super) x: T,
    pub(super) to_gamma: T,
    pub(super) to_one: T,
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

impl<T: Real> Spectral<T> {
    /// pi H[s2](x) and pi H[s1](x) as rows over the 6 n coefficients.
    pub(super) fn hilbert_rows(&self, zn: &Zones<T>, gamma: &T, tg: &Target<T>) -> (Vec<T>, Vec<T>) {
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
    pub(super) fn targets(&self, gamma: &T) -> Vec<Target<T>> {
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
    pub(super) fn lateral_row(&self, zn: &Zones<T>, gamma: &T) -> Vec<T> {
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
}
