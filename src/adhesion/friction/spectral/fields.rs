//! The fields of a solved increment of the spectral method (docs/theory.md sections 17.7, 17.8,
//! the row's fields (17.12)-(17.14)), generic over `f64` and MPFR: the densities (s2, s1) at a
//! point ([`Spectral::densities`], [`Density::pair`]), the outside slope H\[s2\] beyond the
//! contact ([`Spectral::outside_slope`], the kernel of the row's load (17.11)), and the
//! tangential strain of the increment, tau (E*/2) du'/dP = -(H\[s1\] + beta s2) + the constant of
//! (17.10) ([`Spectral::strain_constant`]), on the slip zone ([`Spectral::slip_zone_strain`]) and
//! beyond the contact ([`Spectral::outside_strain`]); zero on the stick zone by the stick
//! condition.
//!
//! A child of `spectral` so that it reads the basis (`Zones`, `Node`), the collocation target and
//! the Hilbert rows of its parent without making them public. The storage of one increment's
//! basis is reused from point to point ([`Density`]): the quadratures over the increment (the
//! outside Cauchy integrals here, the superpositions of `row_fields.rs`) evaluate it at every
//! node. Checked in `spectral_row_tests.rs` (the outside slope against the slope table and the
//! frictionless closed form) and `row_fields_tests.rs` (the densities of an interpolated
//! increment, the row's fields at nu = 1/2).

use super::super::quadrature::graded;
use super::super::real::Real;
use super::{Density, Spectral, SpectralIncrement, Target};

impl<T: Real> Density<'_, T> {
    /// (s2, s1) at a point of the stick zone (`slip` false; d_a = x + gamma, d_b = gamma - x) or
    /// of the right slip zone (`slip` true; d_a = x - gamma, d_b = 1 - x; s1 = mu s2 there), the
    /// basis evaluated once for both.
    pub fn pair(&mut self, slip: bool, d_a: &T, d_b: &T) -> (T, T) {
        let s2 = self.at(slip, d_a, d_b);
        if slip {
            let s1 = self.sp.mu.clone() * s2.clone();
            return (s2, s1);
        }
        // `at` left the stick node in `nd`: s1 = z (sum R_k T_k + w^alpha sum S_k T_k)
        let n = self.sp.n;
        let c = &self.inc.coeffs[2 * n..4 * n];
        let mut s1 = d_a.lit(0.0);
        for (f, cf) in [&self.nd.fac[1], &self.nd.fac[2]].into_iter().zip(c.chunks(n)) {
            for (tj, cj) in self.nd.t.iter().zip(cf) {
                self.tmp.set_mul(f, tj);
                s1.add_mul(cj, &self.tmp);
            }
        }
        (s2, s1)
    }
}

impl<T: Real> Spectral<T> {
    /// (1/pi) int_-1^1 s2(T')/(t - T') dT' at t > 1, given by `beyond` = t - 1 (> 0): the outside
    /// slope H\[s2\](t) of a solved increment (the row's W of (17.11) up to the factor 1/tau).
    pub fn outside_slope(&self, inc: &SpectralIncrement<T>, beyond: &T) -> T {
        self.outside_cauchy(inc, beyond, false)
    }

    /// (1/pi) int_-1^1 s(T')/(t - T') dT' at t = 1 + `beyond` (> 0) for s = s2 (`odd` false) or
    /// s = s1 (`odd`: the slip zones' s1 = +-mu s2).
    fn outside_cauchy(&self, inc: &SpectralIncrement<T>, beyond: &T, odd: bool) -> T {
        let gamma = &inc.gamma;
        let zero = gamma.lit(0.0);
        let one = gamma.lit(1.0);
        let t = one.clone() + beyond.clone();
        let mut sum = zero.clone();
        let mut dens = self.density(inc);
        let len = gamma.lit(2.0) * gamma.clone();
        let near = one.clone() - gamma.clone() + beyond.clone();
        self.rule.sweep(&len, &graded(&zero, &len, self.edge(&inc.zones), Some(&near)), |d_a, d_b, w| {
            let s = if odd { dens.pair(false, d_a, d_b).1 } else { dens.at(false, d_a, d_b) };
            sum = sum.clone() + w.clone() * s / (near.clone() + d_b.clone());
        });
        let len = one.clone() - gamma.clone();
        let (factor, mirror) = if odd { (self.mu.clone(), -one.clone()) } else { (one.clone(), one.clone()) };
        self.rule.sweep(&len, &graded(&zero, &len, None, Some(beyond)), |d_a, d_b, w| {
            if *d_b == zero || *w == zero {
                return; // a tail node underflowed (f64, beyond below 1e-20): it adds nothing
            }
            let s2 = dens.at(true, d_a, d_b);
            let eta = gamma.clone() + d_a.clone();
            let k = one.clone() / (beyond.clone() + d_b.clone()) + mirror.clone() / (t.clone() + eta);
            sum = sum.clone() + w.clone() * factor.clone() * s2 * k;
        });
        sum / gamma.pi()
    }

    /// (s2, s1) of a solved increment at a point of the stick zone (`slip` false; d_a = x + gamma,
    /// d_b = gamma - x) or of the right slip zone (`slip` true; d_a = x - gamma, d_b = 1 - x;
    /// s1 = mu s2 there): the densities the row's fields superpose (`row_fields.rs`). At many
    /// points of one increment, [`Density::pair`] reuses the storage.
    pub fn densities(&self, inc: &SpectralIncrement<T>, slip: bool, d_a: &T, d_b: &T) -> (T, T) {
        self.density(inc).pair(slip, d_a, d_b)
    }

    /// The constant part of tau (E*/2) du'/dP of a solved increment, b beta tau/pi minus the
    /// row's constant (1/pi) int s1 tau^2 T/(1 + tau^2 T^2) dT of (17.10) (zero for the single
    /// punch in `paper`): the argument `constant` of [`Spectral::slip_zone_strain`] and
    /// [`Spectral::outside_strain`].
    pub fn strain_constant(&self, inc: &SpectralIncrement<T>) -> T {
        let row = self.lateral_row(&inc.zones, &inc.gamma);
        let zero = inc.gamma.lit(0.0);
        self.lateral.clone() - row.iter().zip(&inc.coeffs).fold(zero, |acc, (r, k)| acc + r.clone() * k.clone())
    }

    /// tau (E*/2) du'/dP of the unit increment, -(H\[s1\] + beta s2) + `constant` (the stick
    /// condition of (17.10), left minus right side: zero on the stick zone), at a point of the
    /// right slip zone given as (d_a, d_b) = (x - gamma, 1 - x) (docs/theory.md section 17.8,
    /// the fields).
    pub fn slip_zone_strain(&self, inc: &SpectralIncrement<T>, constant: &T, d_a: &T, d_b: &T) -> T {
        let (gamma, c) = (&inc.gamma, &inc.coeffs);
        let zero = gamma.lit(0.0);
        let tg = Target { x: gamma.clone() + d_a.clone(), to_gamma: -d_a.clone(), to_one: d_b.clone() };
        let (_, h1) = self.hilbert_rows(&inc.zones, gamma, &tg);
        let h = h1.iter().zip(c).fold(zero, |acc, (r, k)| acc + r.clone() * k.clone());
        let s2 = self.normal_density(inc, true, d_a, d_b);
        constant.clone() - h / gamma.pi() - self.beta.clone() * s2
    }

    /// The largest slip rate of the increment's slip zone over its largest magnitude (<= 0: every
    /// point of the slip zone slips inward, against q1 = mu q2; docs/theory.md (17.14)): with
    /// dchi = tau dT/(1 + tau^2 T^2), du/dP at T is 2 int_gamma^T D(T') dT'/(1 + tau^2 T'^2),
    /// D the strain of [`Spectral::slip_zone_strain`] (tau = 0: the single punch, du/da up to a
    /// positive factor), the stuck points not moving. The quadrature's nodes within `edge_cut`
    /// of the zone's ends are left out (D ~ distance^(-1/2 + theta0) there: the rate moves by at
    /// most about `edge_cut`^(1/2 + theta0)); zero without nodes.
    pub fn outward_slip(&self, inc: &SpectralIncrement<T>, edge_cut: &T) -> T {
        let gamma = &inc.gamma;
        let (zero, one) = (gamma.lit(0.0), gamma.lit(1.0));
        let len = one.clone() - gamma.clone();
        let tau = self.tau.clone();
        let constant = self.strain_constant(inc);
        let mut nodes = Vec::new();
        self.rule.sweep(&len, &graded(&zero, &len, None, None), |d_a, d_b, w| {
            if *d_b > *edge_cut && *d_a > *edge_cut && *w > zero {
                let t = gamma.clone() + d_a.clone();
                let d = self.slip_zone_strain(inc, &constant, d_a, d_b);
                let weight = one.clone() + tau.clone() * tau.clone() * t.clone() * t;
                nodes.push((d_a.clone(), w.clone() * d / weight));
            }
        });
        nodes.sort_by(|a, b| a.0.partial_cmp(&b.0).unwrap_or(std::cmp::Ordering::Equal));
        let mut rate = zero.clone();
        let (mut top, mut size): (Option<T>, T) = (None, zero.clone());
        for (_, v) in nodes {
            rate += &v;
            top = Some(match top {
                Some(t) if t >= rate => t,
                _ => rate.clone(),
            });
            if rate.abs() > size {
                size = rate.abs();
            }
        }
        match top {
            Some(t) if size > zero => t / size,
            _ => zero,
        }
    }

    /// As [`Spectral::slip_zone_strain`] outside the contact, at x = 1 + `beyond` (> 0), where
    /// s2 = 0: `constant` - H\[s1\](x), the stick zone's s1 and the slip zones' s1 = +-mu s2.
    pub fn outside_strain(&self, inc: &SpectralIncrement<T>, constant: &T, beyond: &T) -> T {
        constant.clone() - self.outside_cauchy(inc, beyond, true)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`Density::pair`] is the sum over the stick zone's families of `stick_values` (the
    /// evaluation `densities` made before it reused storage), equal to the last bit in `f64`,
    /// and s1 = mu s2 on the slip zone: nu = 0, mu = 1/2, the row at lambda = 1.2.
    #[test]
    fn pair_is_the_families_sum_bit_for_bit() {
        let sp = Spectral::row(0.5, 0.5, 8, 1.2f64.tan(), true);
        let inc = sp.solve(&0.3).unwrap();
        let n = 8;
        let mut dens = sp.density(&inc);
        for x in [-0.29, -0.1, 0.0, 0.05, 0.2999] {
            let (d_a, d_b) = (x + inc.gamma, inc.gamma - x);
            let (v2, v1) = sp.stick_values(&inc.zones, &d_a, &d_b);
            let s2 = (0..2 * n).fold(0.0, |acc, j| acc + inc.coeffs[j] * v2[j]);
            let s1 = (0..2 * n).fold(0.0, |acc, j| acc + inc.coeffs[2 * n + j] * v1[j]);
            assert_eq!(dens.pair(false, &d_a, &d_b), (s2, s1), "x = {x}");
        }
        let (s2, s1) = dens.pair(true, &0.2, &0.5);
        assert_eq!((s2, s1), (dens.at(true, &0.2, &0.5), 0.5 * s2));
    }
}
