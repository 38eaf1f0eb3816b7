//! Problem 1 (sliding with friction, adhesive friction and wear): the small-lambda expansions
//! of docs/theory.md section 5 ([3.7]-[3.12]) to any order, exact, coefficients in Q[theta, T].
//!
//! Derivation \[reconstructed\]. In the linear variable xh = (x - c)/l the periodic kernel is
//! (1/L) cot(pi (x - xi)/L) dxi = (1/pi) Z(lambda (xh - xih)) dxih / (xh - xih), Z(z) = z cot z
//! = 1 + sum_k z_k z^(2k) [3.2], so the canonical equation [2.8] becomes the single-punch
//! (Cauchy) equation with a polynomial right-hand side:
//!
//!   kappa p + (1/pi) PV int p(xih)/(xh - xih) dxih = F(xh),
//!   F / (E* k l) = s(rbar + xh) + T/rho - sum_{k>=1} z_k lambda^(2k)
//!                   sum_{j=0}^{2k-1} C(2k-1, j) (-1)^j xh^(2k-1-j) mt_j,
//!
//! where rho = l/l_s, T = beta tau0/(E* k l_s), mt_j = int xih^j p dxih / (pi E* k l), and
//! s(y) = y for the parabola, s(y) = sin(2 lambda y)/(2 lambda) for the sinusoid (k = 2 pi^2 D/L^2,
//! the osculating parabola). For a polynomial F = sum F_i xh^i the bounded solution [2.13] is
//! p = E* k l cos(pi theta) omega(xh) B(xh), B = sum_i F_i sum_{r+s=i-1} xh^r j_s(theta),
//! with the solvability condition sum_i F_i j_i = 0 [2.14] (J_n = pi j_n / cos(pi theta), [3.5]).
//! The moments follow from int xh^n omega = (pi/cos(pi theta)) mu_n,
//! mu_n = j_n(-theta) - j_{n+2}(-theta) = (1/4 - theta^2) nu_n, so
//! mt_j = (1/4 - theta^2) sum_i F_i sum_{r+s=i-1} j_s nu_{j+r}, and the load
//! P2 = pi E* k l^2 mt_0 = pi E* k l_s^2 mt_0(single punch) fixes rho = (S_0/2)^(-1/2),
//! S_0 = mt_0 / (1/4 - theta^2). With lambda = Lambda rho, Lambda = pi l_s/L, the equations are
//! solved by a fixed-point iteration on truncated series; each sweep fixes one more power of
//! Lambda^2, and the iteration is run until two sweeps agree exactly.
//!
//! Outputs: l/l_s, rbar - rbar_s (rbar_s = 2 theta - T [3.10]), F_def/(pi E* k^2 l_s^3), the
//! pressure polynomials pi_j(xh) of p = E* k l cos(pi theta) omega(xh) (1 + sum Lambda^(2j) pi_j)
//! [3.9], and Delta/l_s = l/l_s - 1 [3.11].
//!
//! The `periodic` convention (docs/theory.md section 8): [2.8] gains the constant
//! K = (kappa P2 - 2 beta l tau0)/L beside beta tau0, so T/rho in F gains
//! K/(E* k l) = Lambda (kappa (1 - 4 theta^2)/(2 rho) - 2 T/pi)
//! (P2 = pi E* k l_s^2 (1 - 4 theta^2)/2 at every L, l_s/L = Lambda/pi, l = rho l_s). The expansions
//! then hold every power of Lambda, not only the even ones, and the fixed point fixes one power of
//! Lambda per sweep. Representation: kappa = tan(pi theta) and 1/pi are transcendental in theta and
//! over Q, so they enter as two independent symbols `kappa` and `invpi` beside theta and T
//! (coefficients in Q[theta, T, kappa, invpi]); a combined symbol (e.g. kappa/pi) would not do,
//! since kappa enters with 1/rho and 1/pi with T, in different monomials. Both appear only in odd
//! powers' coefficients and products thereof; at kappa = T = 0 the periodic expansions are the
//! paper's.

use super::jacobi_moments::jacobi_moments_at;
use super::kernel::kernel_series;
use crate::model::Convention;
use exact_series::{Poly, Ring, Series, SeriesError, Symbol, Q};

/// The punch shapes of Problem 1.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SlidingShape {
    /// g = k x^2.
    Parabolic,
    /// g = D (1 - cos(2 pi x/L)), expanded about its osculating parabola k = 2 pi^2 D/L^2.
    Sinusoidal,
}

/// The exact expansions in Lambda = pi l_s / L at fixed load (coefficients in Q[theta, T]).
#[derive(Debug, Clone)]
pub struct SlidingExpansion {
    /// The shape.
    pub shape: SlidingShape,
    /// The surface convention (docs/theory.md section 8).
    pub convention: Convention,
    /// l / l_s.
    pub l_over_ls: Series<Poly>,
    /// rbar - rbar_s, rbar = c/l, rbar_s = 2 theta - T.
    pub rbar_minus_rbar_s: Series<Poly>,
    /// F_def / (pi E* k^2 l_s^3); its Lambda^0 term is the single-punch value.
    pub f_def_scaled: Series<Poly>,
    /// pi_1(xh), pi_2(xh), ...: p = E* k l cos(pi theta) omega(xh) (1 + sum_j Lambda^(step j) pi_j(xh)).
    pub pressure: Vec<Poly>,
    /// The power of Lambda per pressure term: 2 in `paper` (even series), 1 in `periodic`.
    pub step: usize,
}

/// Polynomials in xh whose coefficients are Lambda-series: `c[i]` multiplies xh^i.
pub(super) type XPoly = Vec<Series<Poly>>;

/// `a[i] += s`, growing `a` as needed.
pub(super) fn xp_add(a: &mut XPoly, i: usize, s: &Series<Poly>) {
    let prec = s.prec();
    while a.len() <= i {
        a.push(Series::zero(prec));
    }
    a[i] = a[i].add(s);
}

/// The product of two polynomials in xh, each coefficient truncated to `prec`.
pub(super) fn xp_mul(a: &XPoly, b: &XPoly, prec: usize) -> XPoly {
    let mut out: XPoly = vec![Series::zero(prec); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] = out[i + j].add(&x.mul(y).truncate(prec));
        }
    }
    out
}

/// Pure data of the derivation that does not change between sweeps.
pub(super) struct Tables {
    pub(super) prec: usize,
    /// j_n(theta).
    pub(super) j: Vec<Poly>,
    /// nu_n = (j_n(-theta) - j_{n+2}(-theta)) / (1/4 - theta^2).
    pub(super) nu: Vec<Poly>,
    /// z_k, Z(z) = 1 + sum_k z_k z^(2k).
    pub(super) z: Vec<Q>,
    /// 1/4 - theta^2.
    pub(super) quarter: Poly,
}

impl Tables {
    /// Tables through Lambda^order for a right-hand side of degree at most `max(degree,
    /// order + 2)` in xh (the kernel correction alone has degree `2 (order/2) - 1`).
    pub(super) fn new(order: usize, theta: &Poly, degree: usize) -> Result<Tables, SeriesError> {
        let k_max = order / 2;
        let deg = (2 * k_max + 2).max(degree);
        let j = jacobi_moments_at(2 * deg + 2, theta).coeffs().to_vec();
        let jm = jacobi_moments_at(4 * deg + 6, &theta.neg()).coeffs().to_vec();
        let quarter = Poly::from_q(&Q::new(1.into(), 4.into())).sub(&theta.mul(theta));
        let nu = (0..4 * deg + 4)
            .map(|n| {
                jm[n].sub(&jm[n + 2]).div_exact(&quarter).ok_or_else(|| SeriesError::NotInvertible {
                    operation: "moment of omega divided by 1/4 - theta^2",
                    value: jm[n].sub(&jm[n + 2]).text(),
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        let zs = kernel_series(2 * k_max + 2);
        let z =
            (0..=k_max + 1).map(|k| zs.coeff(2 * k).cloned().unwrap_or_else(|| Q::from_integer(0.into()))).collect();
        Ok(Tables { prec: order + 1, j, nu, z, quarter })
    }

    /// sum_i F_i sum_{r+s=i-1} j_s w_{n+r}: the moment functional of the bounded solution.
    pub(super) fn moment(&self, f: &XPoly, w: &[Poly], n: usize) -> Series<Poly> {
        let mut acc = Series::zero(self.prec);
        for (i, fi) in f.iter().enumerate().skip(1) {
            let mut c = Poly::zero();
            for r in 0..i {
                c = c.add(&self.j[i - 1 - r].mul(&w[n + r]));
            }
            if !c.is_zero() {
                acc = acc.add(&fi.mul_scalar(&c));
            }
        }
        acc
    }
}

/// Derives the expansions through Lambda^order (every term through Lambda^order, docs/theory.md
/// section 5), symbolic in theta and T.
///
/// ```
/// use exact_series::Ring;
/// use periodic_contact::asymptotics::sliding::{sliding_expansion, SlidingShape};
/// let e = sliding_expansion(SlidingShape::Parabolic, 2).unwrap();
/// // Frictionless check (Kuznetsov): a = a0 (1 - Lambda^2/12 + ...) at theta = T = 0.
/// assert!(e.l_over_ls.coeff(2).unwrap().text().ends_with("- 1/12"));
/// ```
pub fn sliding_expansion(shape: SlidingShape, order: usize) -> Result<SlidingExpansion, SeriesError> {
    sliding_expansion_with(shape, order, Convention::Paper)
}

/// [`sliding_expansion`] in either surface convention (module doc): `Paper` gives the paper's
/// even series, `PeriodicSurface` adds K and the odd powers (symbols `kappa`, `invpi`).
pub fn sliding_expansion_with(
    shape: SlidingShape,
    order: usize,
    convention: Convention,
) -> Result<SlidingExpansion, SeriesError> {
    let periodic = convention == Convention::PeriodicSurface;
    let theta = Poly::symbol(Symbol::new("theta")?);
    let t = Poly::symbol(Symbol::new("T")?);
    let tab = Tables::new(order, &theta, 0)?;
    let prec = tab.prec;
    let k_max = order / 2;
    let half = Q::new(1.into(), 2.into());
    let step = if periodic { 1 } else { 2 };

    // Single punch: F = rbar + xh + T, u = rbar + T/rho = -j_1 = 2 theta, rho = 1.
    let mut rho = Series::<Poly>::one(1);
    let mut rbar = Series::constant(theta.mul_int(2).sub(&t), 1);
    let mut mt: Vec<Series<Poly>> = {
        let f: XPoly = vec![Series::zero(1), Series::one(1)];
        let mu: Vec<Poly> = tab.nu.iter().map(|n| n.mul(&tab.quarter)).collect();
        (0..2 * k_max + 3).map(|n| tab.moment(&f, &mu, n)).collect()
    };
    // K/(E* k l) = Lambda (kappa (1 - 4 theta^2)/2 (1/rho) - 2 T invpi) in `periodic` (module doc).
    let k_coeffs = if periodic {
        let kappa = Poly::symbol(Symbol::new("kappa")?);
        let invpi = Poly::symbol(Symbol::new("invpi")?);
        Some((kappa.mul(&tab.quarter).mul_int(2), t.mul(&invpi).mul_int(-2)))
    } else {
        None
    };
    let mut previous: Option<(Series<Poly>, Series<Poly>)> = None;
    let mut result = None;
    // Sweep s maps a state exact through Lambda^(step (s-1)) to one exact through Lambda^(step s)
    // (each unknown enters F multiplied by lambda^2, or by Lambda through K), so sweep s works at
    // precision min(prec, step s + 1) and only the last sweeps run at full order; the iteration is
    // run until two full-order sweeps agree (the truncated fixed point is unique, so the result
    // does not depend on the schedule).
    let sweeps = if periodic { order + 3 } else { k_max + 3 };
    for sweep in 1..=sweeps + 1 {
        let wprec = prec.min(step * sweep + 1);
        let pad = |s: &Series<Poly>| Series::new(s.coeffs().to_vec(), wprec);
        rho = pad(&rho);
        rbar = pad(&rbar);
        mt = mt.iter().map(pad).collect();
        let cst = |p: &Poly| Series::constant(p.clone(), wprec);
        let big_lambda = Series::<Poly>::var(wprec);
        let (k_rho, k_const) = match &k_coeffs {
            Some((a, b)) => (big_lambda.mul_scalar(a), big_lambda.mul_scalar(b)),
            None => (Series::zero(wprec), Series::zero(wprec)),
        };
        let lambda = big_lambda.mul(&rho).truncate(wprec);
        let lambda2 = lambda.mul(&lambda).truncate(wprec);
        // The shape term s(rbar + xh) as a polynomial in xh.
        let y: XPoly = vec![rbar.clone(), Series::one(wprec)];
        let mut shape_poly: XPoly = y.clone();
        if shape == SlidingShape::Sinusoidal {
            // s(rbar + xh) = sin(2 lambda (rbar + xh))/(2 lambda) by Taylor's formula in xh:
            // [xh^0] = rbar sinc(2 lambda rbar), [xh^m] = (2 lambda)^(m-1) sin^(m)(2 lambda rbar)/m!
            // (m >= 1; sin^(m) = cos, -sin, -cos, sin). Terms with m > 2 k_max + 1 are
            // O(lambda^(2 k_max + 2)), beyond the order. Exact: the same series as the power
            // expansion of sin in y, at a fraction of the cost.
            let two_lambda = lambda.scale(&Q::from_integer(2.into()));
            let z = two_lambda.mul(&rbar).truncate(wprec);
            let (sin_z, cos_z) = z.sin_cos()?;
            shape_poly = vec![rbar.mul(&z.sinc()?).truncate(wprec)];
            let mut lam_pow = Series::<Poly>::one(wprec);
            let mut fact = Q::from_integer(1.into());
            for m in 1..=2 * k_max + 1 {
                if m >= 2 {
                    lam_pow = lam_pow.mul(&two_lambda).truncate(wprec);
                }
                fact = fact * Q::from_integer((m as i64).into());
                let trig = match m % 4 {
                    1 => cos_z.clone(),
                    2 => sin_z.neg(),
                    3 => cos_z.neg(),
                    _ => sin_z.clone(),
                };
                shape_poly.push(trig.mul(&lam_pow).truncate(wprec).scale(&fact.recip()));
            }
        }
        // H = s(rbar + xh) - rbar + kernel correction: everything but u = rbar + T/rho.
        let mut h = shape_poly.clone();
        h[0] = h[0].sub(&rbar);
        let mut lam_pow = Series::<Poly>::one(wprec);
        for k in 1..=k_max {
            lam_pow = lam_pow.mul(&lambda2).truncate(wprec);
            let zk = &tab.z[k];
            let mut binom = Q::from_integer(1.into()); // C(2k-1, j)
            for j in 0..2 * k {
                let sign = if j % 2 == 0 { Q::from_integer(1.into()) } else { Q::from_integer((-1).into()) };
                let c = -(zk * &binom * sign);
                xp_add(&mut h, 2 * k - 1 - j, &mt[j].mul(&lam_pow).truncate(wprec).scale(&c));
                binom = binom * Q::new(((2 * k - 1 - j) as i64).into(), ((j + 1) as i64).into());
            }
        }
        // Solvability [2.14]: u + sum_i H_i j_i = 0.
        let mut u = Series::zero(wprec);
        for (i, hi) in h.iter().enumerate() {
            u = u.sub(&hi.mul_scalar(&tab.j[i]));
        }
        // The full right-hand side F = H + u, its moments, the load and the new rho.
        let mut f = h.clone();
        f[0] = f[0].add(&u);
        let mu: Vec<Poly> = tab.nu.iter().map(|n| n.mul(&tab.quarter)).collect();
        mt = (0..2 * k_max + 3).map(|n| tab.moment(&f, &mu, n).truncate(wprec)).collect();
        let s0_half = tab.moment(&f, &tab.nu, 0).scale(&half);
        let sqrt_s0_half = s0_half.pow_q(&half)?;
        rho = sqrt_s0_half.inv()?.truncate(wprec);
        // rbar = u - (T + K-term)/rho: the constant of F divided out of u.
        let c_rho = cst(&t).add(&k_rho);
        rbar = u.sub(&sqrt_s0_half.mul(&c_rho).truncate(wprec)).sub(&k_const).truncate(wprec);
        if wprec < prec {
            continue;
        }
        let fdef = {
            let mut acc = Series::zero(wprec);
            for (i, si) in shape_poly.iter().enumerate() {
                acc = acc.add(&si.mul(&mt[i]).truncate(wprec));
            }
            acc.mul(&rho.powi(3)?).truncate(wprec).scale(&Q::from_integer(2.into()))
        };
        // Pressure B(xh) = sum_i F_i sum_{r+s=i-1} xh^r j_s.
        let mut b: XPoly = vec![Series::zero(wprec)];
        for (i, fi) in f.iter().enumerate().skip(1) {
            for r in 0..i {
                xp_add(&mut b, r, &fi.mul_scalar(&tab.j[i - 1 - r]));
            }
        }
        let state = (rho.clone(), rbar.clone());
        if previous.as_ref() == Some(&state) {
            result = Some((fdef, b));
            break;
        }
        previous = Some(state);
        result = Some((fdef, b));
    }
    let (f_def_scaled, b) = result.expect("at least one sweep");
    if previous.as_ref() != Some(&(rho.clone(), rbar.clone())) {
        return Err(SeriesError::NotInvertible {
            operation: "sliding expansion fixed point",
            value: "did not settle".into(),
        });
    }
    let xh = Symbol::new("xh")?;
    let pressure = (1..=order / step)
        .map(|jj| {
            b.iter().enumerate().fold(Poly::zero(), |acc, (r, br)| {
                let c = br.coeff(step * jj).cloned().unwrap_or_else(Poly::zero);
                acc.add(&c.mul(&Poly::term(&Q::from_integer(1.into()), exact_series::Monomial::power(xh, r as u32))))
            })
        })
        .collect();
    let rbar_s = theta.mul_int(2).sub(&t);
    let cst = |p: &Poly| Series::constant(p.clone(), prec);
    Ok(SlidingExpansion {
        shape,
        convention,
        l_over_ls: rho,
        rbar_minus_rbar_s: rbar.sub(&cst(&rbar_s)),
        f_def_scaled,
        pressure,
        step,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(p: &Poly, theta: Q, t: Q) -> Q {
        let p = p.subs(Symbol::new("theta").unwrap(), &theta).subs(Symbol::new("T").unwrap(), &t);
        p.as_q().expect("no symbols left")
    }

    fn zero() -> Q {
        Q::from_integer(0.into())
    }

    #[test]
    fn kuznetsov_closed_form_for_the_frictionless_parabola() {
        // cos(lambda) = exp(-Lambda^2/2) [2.15] with l_s = a0 at theta = 0: 2 sin(lambda/2) = s,
        // s = sqrt(2 (1 - exp(-Lambda^2/2))), so lambda = 2 arcsin(s/2), l/l_s = lambda/Lambda.
        let order = 12;
        let prec = order + 2;
        let x = Series::<Q>::var(prec + 2);
        let e = x.mul(&x).scale(&Q::new((-1).into(), 2.into())).exp().unwrap();
        let two_v = Series::one(prec + 2).sub(&e).scale(&Q::from_integer(2.into()));
        let s = two_v.sqrt().unwrap(); // = Lambda (1 + ...)
        let arcsin = x.sin().unwrap().revert().unwrap();
        let lambda = arcsin.compose(&s.scale(&Q::new(1.into(), 2.into()))).unwrap().scale(&Q::from_integer(2.into()));
        let expected = lambda.div(&x).unwrap();
        let got = sliding_expansion(SlidingShape::Parabolic, order).unwrap();
        for k in 0..=order {
            assert_eq!(
                at(got.l_over_ls.coeff(k).unwrap(), zero(), zero()),
                expected.coeff(k).unwrap().clone(),
                "Lambda^{k}"
            );
            assert_eq!(at(got.rbar_minus_rbar_s.coeff(k).unwrap(), zero(), zero()), zero());
        }
    }

    #[test]
    fn westergaard_closed_form_for_the_frictionless_sinusoid() {
        // P2 = pi E* D sin^2(lambda) [2.17] gives sin(lambda) = lambda0: a/a0 = arcsin(lambda0)/lambda0.
        let order = 12;
        let x = Series::<Q>::var(order + 3);
        let expected = x.sin().unwrap().revert().unwrap().div(&x).unwrap();
        let got = sliding_expansion(SlidingShape::Sinusoidal, order).unwrap();
        for k in 0..=order {
            assert_eq!(
                at(got.l_over_ls.coeff(k).unwrap(), zero(), zero()),
                expected.coeff(k).unwrap().clone(),
                "Lambda^{k}"
            );
        }
        // Delta = a - a_s = -pi^2 a0^3/(12 L^2) for both shapes [3.11]: the Lambda^2 term of l/l_s
        // is 1/6 for the sinusoid, and the single bulge has 1/4: 1/6 - 1/4 = -1/12.
        assert_eq!(expected.coeff(2).unwrap(), &Q::new(1.into(), 6.into()));
    }

    #[test]
    fn single_punch_limit() {
        let e = sliding_expansion(SlidingShape::Parabolic, 4).unwrap();
        assert!(e.l_over_ls.coeff(0).unwrap().is_one());
        assert!(e.rbar_minus_rbar_s.coeff(0).unwrap().is_zero());
        // F_def,s / (pi E* k^2 l_s^3) = 2 (rbar_s mu_0 + mu_1) = (1/4 - theta^2)(32 theta/3 - 4 T).
        assert_eq!(e.f_def_scaled.coeff(0).unwrap().text(), "-32/3*theta^3 + 4*T*theta^2 + 8/3*theta - T");
        assert!(e.pressure.len() == 2);
    }

    #[test]
    fn periodic_parabola_keeps_l_and_shifts_the_centre_by_minus_k() {
        // docs/theory.md sections 3 and 8: for the parabola lambda does not depend on the constant of
        // [2.8], so l/l_s is the same in both conventions and rbar moves by exactly
        // -K/(E* k l) = -Lambda (kappa (1 - 4 theta^2)/(2 rho) - 2 T/pi), i.e. c_periodic - c_paper
        // = -K/(E* k), at the series level.
        let order = 12;
        let paper = sliding_expansion(SlidingShape::Parabolic, order).unwrap();
        let per = sliding_expansion_with(SlidingShape::Parabolic, order, Convention::PeriodicSurface).unwrap();
        assert_eq!(per.l_over_ls, paper.l_over_ls);
        let prec = order + 1;
        let theta = Poly::symbol(Symbol::new("theta").unwrap());
        let t = Poly::symbol(Symbol::new("T").unwrap());
        let kappa = Poly::symbol(Symbol::new("kappa").unwrap());
        let invpi = Poly::symbol(Symbol::new("invpi").unwrap());
        let lam = Series::<Poly>::var(prec);
        let one_minus = Poly::one().sub(&theta.mul(&theta).mul_int(4));
        let inv_rho = paper.l_over_ls.inv().unwrap();
        let k_over = lam
            .mul(&inv_rho.mul_scalar(&kappa.mul(&one_minus).scale(&Q::new(1.into(), 2.into()))))
            .truncate(prec)
            .sub(&lam.mul_scalar(&t.mul(&invpi).mul_int(2)));
        let shift = per.rbar_minus_rbar_s.sub(&paper.rbar_minus_rbar_s);
        assert_eq!(shift, k_over.neg());
        // c = rbar l: c_periodic - c_paper = -(K/(E* k l)) l.
        let dc = shift.mul(&paper.l_over_ls).truncate(prec);
        let expected = lam
            .mul_scalar(&kappa.mul(&one_minus).scale(&Q::new((-1).into(), 2.into())))
            .add(&lam.mul(&paper.l_over_ls).truncate(prec).mul_scalar(&t.mul(&invpi).mul_int(2)));
        assert_eq!(dc, expected);
        // F_def changes from Lambda^1 on: (F_def)_periodic - (F_def)_paper = 2 rho^3 mt_0 (rbar shift)
        // (mt_0 = 2 (1/4 - theta^2) at Lambda^0) for the parabola; its first term is 4 (1/4 - theta^2) (-kappa (1 - 4 theta^2)/2 + 2 T/pi).
        assert_eq!(per.f_def_scaled.coeff(0), paper.f_def_scaled.coeff(0));
        let d1 = per.f_def_scaled.coeff(1).unwrap().sub(paper.f_def_scaled.coeff(1).unwrap());
        let quarter = one_minus.scale(&Q::new(1.into(), 4.into()));
        let want = quarter
            .mul_int(4)
            .mul(&kappa.mul(&one_minus).scale(&Q::new((-1).into(), 2.into())).add(&t.mul(&invpi).mul_int(2)));
        assert_eq!(d1, want);
        assert!(paper.f_def_scaled.coeff(1).unwrap().is_zero());
    }

    #[test]
    fn periodic_equals_paper_without_kappa_and_t() {
        for shape in [SlidingShape::Parabolic, SlidingShape::Sinusoidal] {
            let paper = sliding_expansion(shape, 8).unwrap();
            let per = sliding_expansion_with(shape, 8, Convention::PeriodicSurface).unwrap();
            let z = |p: &Poly| p.subs(Symbol::new("kappa").unwrap(), &zero()).subs(Symbol::new("T").unwrap(), &zero());
            for k in 0..=8 {
                assert_eq!(z(per.l_over_ls.coeff(k).unwrap()), z(paper.l_over_ls.coeff(k).unwrap()), "{shape:?} l {k}");
                assert_eq!(
                    z(per.rbar_minus_rbar_s.coeff(k).unwrap()),
                    z(paper.rbar_minus_rbar_s.coeff(k).unwrap()),
                    "{shape:?} rbar {k}"
                );
            }
            // Odd powers of l/l_s of the sinusoid are nonzero in `periodic` (K couples through s).
            if shape == SlidingShape::Sinusoidal {
                assert!(!per.l_over_ls.coeff(3).unwrap().is_zero());
            }
        }
    }
}
