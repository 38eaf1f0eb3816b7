//! The single punch's fields q1, q2, psi at points x/a and the checks of its inequalities by the
//! spectral method (docs/theory.md sections 17.3, 17.5, 17.7), generic over `f64` and MPFR:
//! [`point`] and [`checks`] of one solved run, [`verified`] the two runs of
//! [`super::spectral_punch::verified`] with their agreement as verified digits.
//!
//! With a = 1, E* k = 1 and the self-similar unit increment s = s2 + i s1 at gamma with its load
//! coefficient C_P (17.9), as `fields.rs` for the piecewise-constant increment (dP2 = 2 C_P a' da'):
//!     q(x) = q2 + i q1 = 2 C_P x int_x^1 s(y) y^-2 dy    (x > 0; q2(0) = 2 C_P s2(0), q1(0) = 0),
//!     psi(x)/(k a) = 4 C_P x J(max(x, gamma)),   J(X) = int_X^inf T(y) y^-2 dy,
//! T = -H\[s1\] - beta s2 + the constant of (17.10) (zero for the single punch; zero on the stick
//! zone, so psi is linear there). The order of J's integrals exchanged (s1 odd):
//!     J(X) = constant/X - beta int_X^1 s2 y^-2 dy - (1/pi) int_0^1 s1(xi) K(X, xi) d xi,
//!     K(X, xi) = PV int_X^inf (1/(y - xi) - 1/(y + xi)) y^-2 dy = ln((X + xi)/|X - xi|)/xi^2 - 2/(xi X),
//! a logarithmic singularity at xi = X, where the integral is split. Every integral is the
//! method's tanh-sinh rule on zones whose ends are the densities' edges (gamma, 1) and the point,
//! each node given its distances to both ends, graded toward the pole of y^-2 at 0 and the
//! densities' edges beyond a zone's end.
//!
//! Checks of one run (as the row's, `row_fields.rs`): `stick_ratio`, max of |q1|/(mu q2) at
//! x/c = j/10 (j = 1 .. 9) and 1 - 10^-k (k = 2 .. 6); `pressure_min`, min q2/max q2 at
//! x/a = j/16 (j = 0 .. 15) and the points; `outward_slip`, [`Spectral::outward_slip`] of the
//! increment (du/da up to a positive factor).
//!
//! Tests (below): the uncoupled problem's pressure is Hertz's sqrt(1 - x^2) at any mu; the
//! coupled fields at nu = 0, mu = 1/2 agree with the f64 fields of `fields.rs` within their
//! claim, psi is linear on the stick zone, q1 = mu q2 on the slip zone, and the MPFR run agrees
//! with the `f64` one.

use rug::Float;

use super::fields::{Check, Checks, PointFields};
use super::quadrature::graded;
use super::real::{Mp, Real};
use super::spectral::{Spectral, SpectralIncrement};
use super::spectral_punch::PunchRun;
use crate::numerics::accuracy::{agreement_mpfr, digits_cap_for_bits};

/// q1, q2 and (with `strain`) psi at x = x/a in [0, 1] (module doc), from the increment `inc` of
/// `sp` and its load coefficient `cp`; psi is zero without `strain`.
pub fn point<T: Real>(sp: &Spectral<T>, inc: &SpectralIncrement<T>, cp: &T, x: &T, strain: bool) -> PointFields<T> {
    let gamma = &inc.gamma;
    let (zero, one, two) = (x.lit(0.0), x.lit(1.0), x.lit(2.0));
    if *x <= zero {
        let s2 = sp.normal_density(inc, false, gamma, gamma);
        return PointFields { q1: zero.clone(), q2: two * cp.clone() * s2, psi: zero };
    }
    let (stick2, stick1) = if *x < *gamma { stick_moments(sp, inc, x) } else { (zero.clone(), zero.clone()) };
    // the contact's edge: q = 0, psi from J(1)
    let slip2 = if *x < one { slip_moment(sp, inc, x) } else { zero.clone() };
    let q2 = two.clone() * cp.clone() * x.clone() * (stick2 + slip2.clone());
    let q1 = two.clone() * cp.clone() * x.clone() * (stick1 + sp.mu() * slip2.clone());
    if !strain {
        return PointFields { q1, q2, psi: zero };
    }
    let big_x = if *x < *gamma { gamma.clone() } else { x.clone() };
    let from_big = if *x < *gamma { slip_moment(sp, inc, gamma) } else { slip2 };
    let j = sp.strain_constant(inc) / big_x.clone() - sp.beta() * from_big - odd_kernel(sp, inc, &big_x) / x.pi();
    PointFields { q1, q2, psi: two.clone() * two * cp.clone() * x.clone() * j }
}

/// (int_x^gamma s2 y^-2 dy, int_x^gamma s1 y^-2 dy) for 0 < x < gamma: the zone (x, gamma),
/// graded toward the pole at distance x before it.
fn stick_moments<T: Real>(sp: &Spectral<T>, inc: &SpectralIncrement<T>, x: &T) -> (T, T) {
    let gamma = &inc.gamma;
    let zero = x.lit(0.0);
    let len = gamma.clone() - x.clone();
    let base = x.clone() + gamma.clone();
    let (mut m2, mut m1) = (zero.clone(), zero.clone());
    let mut dens = sp.density(inc);
    sp.rule().sweep(&len, &graded(&zero, &len, Some(x), None), |d_a, d_b, w| {
        // stick coordinates: y + gamma = x + gamma + d_a, gamma - y = d_b
        let (s2, s1) = dens.pair(false, &(base.clone() + d_a.clone()), d_b);
        let y = x.clone() + d_a.clone();
        let k = w.clone() / (y.clone() * y);
        m2 += &(k.clone() * s2);
        m1 += &(k * s1);
    });
    (m2, m1)
}

/// int_max(x, gamma)^1 s2 y^-2 dy over the slip zone.
fn slip_moment<T: Real>(sp: &Spectral<T>, inc: &SpectralIncrement<T>, x: &T) -> T {
    let gamma = &inc.gamma;
    let (zero, one) = (x.lit(0.0), x.lit(1.0));
    let from = if *x > *gamma { x.clone() - gamma.clone() } else { zero.clone() };
    let len = one.clone() - gamma.clone() - from.clone();
    let mut m = zero.clone();
    let mut dens = sp.density(inc);
    let near = (from > zero).then(|| from.clone());
    sp.rule().sweep(&len, &graded(&zero, &len, near.as_ref(), None), |d_a, d_b, w| {
        // slip coordinates: y - gamma = from + d_a, 1 - y = d_b
        let s2 = dens.at(true, &(from.clone() + d_a.clone()), d_b);
        let y = gamma.clone() + from.clone() + d_a.clone();
        m += &(w.clone() * s2 / (y.clone() * y));
    });
    m
}

/// int_0^1 s1(xi) K(X, xi) d xi (module doc) for X in [gamma, 1): the stick zone (0, gamma) and
/// the slip zone split at X, where K is logarithmic.
fn odd_kernel<T: Real>(sp: &Spectral<T>, inc: &SpectralIncrement<T>, big_x: &T) -> T {
    let gamma = &inc.gamma;
    let (zero, one, two) = (big_x.lit(0.0), big_x.lit(1.0), big_x.lit(2.0));
    let kernel = |xi: &T, to_x: &T| {
        ((big_x.clone() + xi.clone()) / to_x.clone()).ln() / (xi.clone() * xi.clone())
            - two.clone() / (xi.clone() * big_x.clone())
    };
    let mut dens = sp.density(inc);
    let mut sum = zero.clone();
    // stick zone: xi = d_a, gamma - xi = d_b, X - xi = (X - gamma) + d_b
    let beyond = big_x.clone() - gamma.clone();
    let near = (beyond > zero).then(|| beyond.clone());
    sp.rule().sweep(gamma, &graded(&zero, gamma, None, near.as_ref()), |d_a, d_b, w| {
        if *d_a == zero {
            return; // s1 K ~ xi^2 at 0: an underflowed node adds nothing
        }
        let (_, s1) = dens.pair(false, &(gamma.clone() + d_a.clone()), d_b);
        sum += &(w.clone() * s1 * kernel(d_a, &(beyond.clone() + d_b.clone())));
    });
    // slip zone, s1 = mu s2: (gamma, X) as xi - gamma = d_a, X - xi = d_b ...
    let mut slip = zero.clone();
    let to_one = one.clone() - big_x.clone();
    if beyond > zero {
        let near = (to_one > zero).then(|| to_one.clone());
        sp.rule().sweep(&beyond, &graded(&zero, &beyond, None, near.as_ref()), |d_a, d_b, w| {
            let s2 = dens.at(true, d_a, &(to_one.clone() + d_b.clone()));
            slip += &(w.clone() * s2 * kernel(&(gamma.clone() + d_a.clone()), d_b));
        });
    }
    // ... and (X, 1) as xi - X = d_a, 1 - xi = d_b (none at X = 1)
    let near = (beyond > zero).then(|| beyond.clone());
    if to_one > zero {
        sp.rule().sweep(&to_one, &graded(&zero, &to_one, near.as_ref(), None), |d_a, d_b, w| {
            if *d_a == zero {
                return; // the logarithm's node at X underflowed (f64)
            }
            let s2 = dens.at(true, &(beyond.clone() + d_a.clone()), d_b);
            slip += &(w.clone() * s2 * kernel(&(big_x.clone() + d_a.clone()), d_a));
        });
    }
    sum + sp.mu() * slip
}

/// [stick ratio, pressure minimum, outward slip] of one run (module doc) at the points `xs`
/// (x/a), the slip rate's nodes within `edge_cut` of its zone's ends left out.
pub fn checks<T: Real>(sp: &Spectral<T>, inc: &SpectralIncrement<T>, cp: &T, xs: &[T], edge_cut: &T) -> [T; 3] {
    let gamma = &inc.gamma;
    let lit = |v: f64| gamma.lit(v);
    let mut stick = lit(0.0);
    let ratios = (1..10).map(|j| lit(j as f64 / 10.0)).chain((2..7).map(|k| lit(1.0) - lit(10f64.powi(-k))));
    let mut q2s = Vec::new();
    for r in ratios {
        let p = point(sp, inc, cp, &(gamma.clone() * r), false);
        let ratio = p.q1.abs() / (sp.mu() * p.q2.clone());
        if ratio > stick {
            stick = ratio;
        }
        q2s.push(p.q2);
    }
    for x in (0..16).map(|j| lit(j as f64 / 16.0)).chain(xs.iter().cloned()) {
        q2s.push(point(sp, inc, cp, &x, false).q2);
    }
    let (mut low, mut top) = (q2s[0].clone(), q2s[0].clone());
    for q in &q2s {
        if *q < low {
            low = q.clone();
        }
        if *q > top {
            top = q.clone();
        }
    }
    [stick, low / top, sp.outward_slip(inc, edge_cut)]
}

/// The fields of the two runs: the finer's values, digits where they agree.
#[derive(Debug, Clone)]
pub struct VerifiedFields {
    /// q1, q2 (scale E* k a) and psi (scale k a) at the points, the finer run.
    pub points: Vec<PointFields<Float>>,
    /// Per field, the least number of digits (on its scale) where the two runs agree over the
    /// points.
    pub digits: PointFields<f64>,
    /// The checks of the finer run, each with its difference from the coarser.
    pub checks: Checks,
}

/// The fields at `xs` (x/a in [0, 1], rounded to each run's precision) and the
/// checks of the two runs (coarser, finer) of [`super::spectral_punch::verified`]; the slip
/// rate's edge cut 10^-(2 `digits` + 4) (its error about 10^-(`digits` + 2)).
pub fn verified(runs: &[PunchRun; 2], xs: &[Float], digits: u32) -> VerifiedFields {
    let each = |(sp, inc, cp): &PunchRun| {
        let at = |v: f64| Mp::new(sp.bits(), v);
        let x: Vec<Mp> = xs.iter().map(|v| Mp(Float::with_val(sp.bits(), v))).collect();
        let points: Vec<PointFields<Mp>> = x.iter().map(|x| point(sp, inc, cp, x, true)).collect();
        let cut = at(10f64.powi(-(2 * digits as i32 + 4)));
        (points, checks(sp, inc, cp, &x, &cut))
    };
    let ((pc, cc), (pf, cf)) = (each(&runs[0]), each(&runs[1]));
    let cap = digits_cap_for_bits(runs[0].0.bits());
    let one = Float::with_val(64, 1);
    let agree = |get: fn(&PointFields<Mp>) -> &Mp| {
        pc.iter().zip(&pf).map(|(c, f)| agreement_mpfr(&get(c).0, &get(f).0, &one, cap)).fold(cap, f64::min)
    };
    let digits = PointFields { q1: agree(|p| &p.q1), q2: agree(|p| &p.q2), psi: agree(|p| &p.psi) };
    let check = |k: usize| Check { value: cf[k].to_f64(), error: (cf[k].to_f64() - cc[k].to_f64()).abs() };
    VerifiedFields {
        points: pf.into_iter().map(|p| PointFields { q1: p.q1.0, q2: p.q2.0, psi: p.psi.0 }).collect(),
        digits,
        checks: Checks { stick_ratio: check(0), pressure_min: check(1), outward_slip: check(2) },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::adhesion::friction::spectral_punch::root_f64;

    /// The uncoupled problem (docs/theory.md section 17.4: the shear does not move the surface
    /// normally) has Hertz's pressure sqrt(1 - x^2) (scale E* k a) at any mu, and C_P = pi/2:
    /// an independent closed form for the superposition of q2, in `f64` and MPFR.
    #[test]
    fn uncoupled_pressure_is_hertz() {
        let sp = Spectral::new(0.5, 0.5, 10, false);
        let inc = root_f64(&sp, "test").unwrap();
        let cp = sp.load_coefficient(&inc);
        for x in [0.0, 0.2, 0.5, inc.gamma, 0.9, 0.99] {
            let p = point(&sp, &inc, &cp, &x, true);
            let hertz = (1.0 - x * x).sqrt();
            assert!((p.q2 - hertz).abs() < 1e-9, "x = {x}: q2 {} against {hertz}", p.q2);
        }
        let bits = 160;
        let mp = |v: f64| Mp::new(bits, v);
        let sp = Spectral::new(mp(0.5), mp(0.5), 12, false);
        let inc = crate::adhesion::friction::spectral_punch::root_mpfr(&sp, inc.gamma, 30).unwrap();
        let cp = sp.load_coefficient(&inc);
        for x in [0.2, 0.5, 0.9] {
            let p = point(&sp, &inc, &cp, &mp(x), true);
            let hertz = Float::with_val(bits, 1.0 - Float::with_val(bits, x).square()).sqrt();
            let digits = agreement_mpfr(&p.q2.0, &hertz, &Float::with_val(64, 1), 48.0);
            // measured: 19.3 digits at x = 0.2 (n = 12 polynomials per family bound them)
            assert!(digits > 17.0, "x = {x}: {digits} digits");
        }
    }

    /// nu = 0, mu = 1/2 (the boundary-element case): the spectral fields agree with the f64
    /// fields of the piecewise-constant increments (`fields.rs`, n = 40 and 80) within twice
    /// their two-mesh difference, q1 = mu q2 on the slip zone, psi is linear on the stick zone,
    /// and the inequalities hold.
    #[test]
    fn agrees_with_the_piecewise_constant_fields() {
        use crate::adhesion::friction::single_punch::{solve_pair, Method};
        let (beta, mu) = (0.5, 0.5);
        let sp = Spectral::new(beta, mu, 10, true);
        let inc = root_f64(&sp, "test").unwrap();
        let cp = sp.load_coefficient(&inc);
        let xs = [0.0, 0.1, 0.2, 0.5, 0.9, 1.0];
        let pair = solve_pair(beta, mu, 40, Method::Increment).unwrap();
        let f = crate::adhesion::friction::fields::fields(beta, mu, pair, 40, &xs).unwrap();
        let ours: Vec<PointFields> = xs.iter().map(|x| point(&sp, &inc, &cp, x, true)).collect();
        eprintln!("spectral {ours:?}\npiecewise {:?}\nerrors {:?}", f.points, f.errors);
        for (o, p) in ours.iter().zip(&f.points) {
            assert!((o.q1 - p.q1).abs() < 8.0 * f.errors.q1 + 1e-6, "{o:?} {p:?}");
            assert!((o.q2 - p.q2).abs() < 8.0 * f.errors.q2 + 1e-6, "{o:?} {p:?}");
            assert!((o.psi - p.psi).abs() < 8.0 * f.errors.psi + 1e-6, "{o:?} {p:?}");
        }
        assert!((ours[4].q1 - mu * ours[4].q2).abs() < 1e-14);
        assert!(ours[5].q1 == 0.0 && ours[5].q2 == 0.0 && ours[5].psi < -0.5, "{ours:?}");
        assert!((ours[2].psi - 2.0 * ours[1].psi).abs() < 1e-12, "{ours:?}");
        let c = checks(&sp, &inc, &cp, &xs, &1e-15);
        eprintln!("checks {c:?}");
        assert!(c[0] <= 1.0 + 1e-6 && c[0] > 0.5 && c[1] >= 0.0 && c[2] <= 1e-12, "{c:?}");
    }
}
