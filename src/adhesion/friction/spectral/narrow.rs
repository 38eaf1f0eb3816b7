//! The spectral method's option for narrow slip zones, [`Spectral::narrow`] (large mu,
//! docs/theory.md section 17.3 "Large mu"): the stick zone's collocation points Chebyshev in its
//! basis variable u (1 - x = 2/(1 + e^(v S)), S = ln((1 + gamma)/(1 - gamma)), with
//! gamma - x computed without cancellation) and its integrals graded toward +-gamma from the scale
//! 1 - gamma. The basis is unchanged.
//!
//! Checked in `spectral_tests.rs`: `narrow_method_matches_the_mpfr_table_at_nu0` (mu = 2 against
//! section 17.3's MPFR table) and, long tier, `growing_friction_rate_at_nu_0_3` (slip zones of
//! 1.6e-6 a at mu = 1024, two n agreeing).

use super::super::real::Real;
use super::basis::Zones;
use super::collocation::Target;
use super::Spectral;

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

impl<T: Real> Spectral<T> {
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
    pub(super) fn edge<'a>(&self, zn: &'a Zones<T>) -> Option<&'a T> {
        self.narrow.then_some(&zn.one_g)
    }

    /// `m` stick-zone points Chebyshev in the basis variable u = 2 v^2 - 1, v = artanh(x)/artanh(gamma)
    /// ([`Spectral::narrow`]): with S = ln((1 + gamma)/(1 - gamma)) and u = cos(th), v = cos(th/2),
    /// 1 - x = 2/(1 + e^(v S)), and gamma - x = 2 e^(v S) (e^((1 - v) S) - 1)/((1 + e^(v S))(1 + e^S))
    /// without cancellation (1 - v = 2 sin^2(th/4)).
    pub(super) fn narrow_stick_targets(&self, gamma: &T, m: usize) -> Vec<Target<T>> {
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
}
