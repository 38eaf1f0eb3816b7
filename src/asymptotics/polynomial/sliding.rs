//! Problem 1 for a polynomial punch g = sum_j c_j x^j (docs/theory.md section 9): the small-lambda
//! expansions of section 5 ([3.7]-[3.12]) exact in the profile's ratios rho_j, in both surface
//! conventions, to any order.
//!
//! # Equations \[reconstructed\]
//! With xh = (x - c)/l, y = rbar + xh, rho = l/l_s, Lambda = pi l_s/L, lambda = Lambda rho and the
//! ratios rho_j of [`super::profile`] (reference degree r), [2.8] divided by E* c_r l^(r-1) reads
//! (as for the parabola, [`crate::asymptotics::sliding`])
//!
//!   kappa p + (1/pi) PV int p Z(lambda (xh - xih))/(xh - xih) dxih = F(xh),
//!   F = G + Tb rho^(1-r) [+ K-term] - sum_{k>=1} z_k lambda^(2k) sum_j C(2k-1, j) (-1)^j xh^(2k-1-j) mt_j,
//!   G = sum_{j>=2} (j/2) rho_j rho^(j-r) y^(j-1),     Tb = T + rho_1/2,
//!   K-term = Lambda (kappa (1/4 - theta^2) m0s rho^(1-r) - 2 T invpi rho^(2-r))   (`periodic` only),
//!
//! T = beta tau0/(E* c_r l_s^(r-1)), mt_j = int xih^j p dxih/(pi E* c_r l^(r-1)); the K-term is
//! K/(E* c_r l^(r-1)) with K = (kappa P2 - 2 beta l tau0)/L (docs/theory.md section 8) and
//! P2 = pi E* c_r l_s^r (1/4 - theta^2) m0s. For a polynomial F the bounded solution is
//! p = E* c_r l^(r-1) cos(pi theta) omega(xh) B(xh), B = sum_i F_i sum_{s+t=i-1} xh^s j_t(theta),
//! with the solvability condition S(F) = sum_i F_i j_i = 0 [2.14], and
//! mt_n = (1/4 - theta^2) m_n(F), m_n(F) = sum_i F_i sum_{s+t=i-1} j_t nu_(n+s) (the tables of
//! the parabola's derivation). The load at fixed P2 is rho^r m_0(F) = m0s.
//!
//! # Parameters: why the single-punch centre rbar_s, not T
//! For the parabola the single punch has rbar_s = 2 theta - T [3.10]. For a profile with a term
//! of degree >= 3 the single-punch solvability condition is a polynomial equation of degree
//! D - 1 in rbar_s: with T as the parameter rbar_s would be algebraic, not rational. It is linear
//! in Tb = T + rho_1/2 (the constant of F), so the exact parameters are (theta, rbar_s, rho_j):
//!
//!   Tb = Tb_s(theta, rbar_s, rho_j) = -S(G_s),   G_s = G at rho = 1, rbar = rbar_s
//!
//! ([`PolynomialSlidingExpansion::tbar_single`]); the parabola's relation is Tb_s = 2 theta - rbar_s.
//! Given T and the tilt, rbar_s is the root of Tb_s = T + rho_1/2 that continues the physical
//! single punch (rbar_s = 0 for an even profile at theta = T = 0). T itself is then no parameter
//! of its own: T = Tb_s - rho_1/2. `periodic`, where T enters K apart from the tilt, uses exactly
//! that polynomial (a symbol T beside rbar_s would be a second, redundant parameter that could
//! contradict the first), beside the symbols kappa = tan(pi theta) and invpi = 1/pi. With theta
//! fixed to a rational, kappa is rational only at theta = 0, +-1/4 (Niven: tan of a rational
//! multiple of pi is rational only when it is 0 or +-1), where it is replaced by 0, +-1;
//! otherwise it stays a symbol.
//!
//! # Why the coefficients are rational, and how they are kept exact
//! Around the single punch, (rbar, rho) solve two equations Phi = (S(F), rho^r m_0(F) - m0s) = 0
//! whose Jacobian J at Lambda = 0 is a polynomial matrix:
//! J = [[S(dG/drbar), S(dF/drho)], [m_0(dG/drbar), r m0s + m_0(dF/drho)]] (dF/drho includes
//! (1 - r) Tb_s). Every Taylor coefficient divides by Delta = det J: by the implicit function
//! theorem the coefficient of Lambda^n has a denominator dividing Delta^(2n-1) (with Lambda^2 as
//! the variable in `paper`, whose expansions are even: Delta^(n-1)). So the derivation runs in
//! mu, Lambda = Delta^a mu (a = 1 `paper`, a = 2 `periodic`, a = 0 when Delta is a rational),
//! where every coefficient is a polynomial, and solves order by order:
//! x_n = -adj(J) Phi_n(x_0..x_{n-1})/Delta, an exact polynomial division (checked: a remainder
//! would be a bug and is reported as an error). The mt_n are updated with the same linear
//! terms, and each order is computed at working precision n + 1 only. At the end the
//! coefficient of Lambda^n is that of mu^n over Delta^(a n), reduced ([`Frac`]).
//! For the parabola Delta = 4 and the objects are exactly those of
//! [`crate::asymptotics::sliding`] with rbar_s = 2 theta - T (tested).
//!
//! # Outputs
//! l/l_s, rbar - rbar_s, F_def/(pi E* c_r^2 l_s^(2r-1)) = 2 rho^(2r-1) sum_i G_i mt_i
//! + rho_1 (1/4 - theta^2) m0s (the tilt's share c_1 P2 separated: F_def = int p g' dx), and the
//! pressure B(xh) (its Lambda^0 term B_s is the single punch's; for the parabola B_s = 1).

use super::profile::PolynomialProfile;
use crate::asymptotics::sliding::{xp_add, xp_mul, Tables, XPoly};
use crate::model::Convention;
use exact_series::{Frac, Monomial, Poly, Ring, Series, SeriesError, Symbol, Q};

/// The exact expansions in Lambda = pi l_s/L at fixed load for a polynomial punch
/// (coefficients in Q(theta, rbar_s, rho_j, l_s) [+ kappa, invpi in `periodic`]).
#[derive(Debug, Clone)]
pub struct PolynomialSlidingExpansion {
    /// The profile.
    pub profile: PolynomialProfile,
    /// The surface convention (docs/theory.md section 8).
    pub convention: Convention,
    /// Delta = det J, the single-punch Jacobian (module doc): every denominator divides a power.
    pub jacobian: Poly,
    /// Tb_s: the single punch has T + rho_1/2 = Tb_s(theta, rbar_s, rho_j).
    pub tbar_single: Poly,
    /// m0s: P2 = pi E* c_r l_s^r (1/4 - theta^2) m0s (the single-punch load law).
    pub load_single: Poly,
    /// l / l_s.
    pub l_over_ls: Series<Frac>,
    /// rbar - rbar_s.
    pub rbar_minus_rbar_s: Series<Frac>,
    /// F_def / (pi E* c_r^2 l_s^(2r-1)).
    pub f_def_scaled: Series<Frac>,
    /// B(xh): p = E* c_r l^(r-1) cos(pi theta) omega(xh) B(xh); coefficient of Lambda^n.
    pub pressure: Series<Frac>,
}

fn sym(name: &str) -> Result<Poly, SeriesError> {
    Ok(Poly::symbol(Symbol::new(name)?))
}

fn q(n: i64, d: i64) -> Q {
    Q::new(n.into(), d.into())
}

/// tan(pi theta) when it is rational (theta = 0, +-1/4 for |theta| < 1/2, by Niven's theorem).
fn rational_tan_pi(theta: &Q) -> Option<Q> {
    [(q(0, 1), q(0, 1)), (q(1, 4), q(1, 1)), (q(-1, 4), q(-1, 1))].into_iter().find(|(t, _)| t == theta).map(|(_, k)| k)
}

/// S(F) = sum_i F_i j_i: the solvability functional [2.14].
fn solvability(f: &[Poly], j: &[Poly]) -> Poly {
    f.iter().zip(j).fold(Poly::zero(), |acc, (fi, ji)| acc.add(&fi.mul(ji)))
}

/// sum_i F_i sum_{s+t=i-1} j_t w_(n+s) for coefficient lists (the constant F_0 drops out).
fn moment_poly(f: &[Poly], tab: &Tables, w: &[Poly], n: usize) -> Poly {
    let mut acc = Poly::zero();
    for (i, fi) in f.iter().enumerate().skip(1) {
        for s in 0..i {
            acc = acc.add(&fi.mul(&tab.j[i - 1 - s]).mul(&w[n + s]));
        }
    }
    acc
}

/// (rbar_s + xh)^m as coefficient lists in xh, m = 0..=max.
fn shifted_powers(rs: &Poly, max: usize) -> Vec<Vec<Poly>> {
    let mut out = vec![vec![Poly::one()]];
    for m in 1..=max {
        let prev = &out[m - 1];
        let mut next = vec![Poly::zero(); m + 1];
        for (i, c) in prev.iter().enumerate() {
            next[i] = next[i].add(&c.mul(rs));
            next[i + 1] = next[i + 1].add(c);
        }
        out.push(next);
    }
    out
}

fn add_into(acc: &mut Vec<Poly>, p: &[Poly], c: &Poly) {
    if acc.len() < p.len() {
        acc.resize(p.len(), Poly::zero());
    }
    for (a, x) in acc.iter_mut().zip(p) {
        *a = a.add(&x.mul(c));
    }
}

fn pow(p: &Poly, e: usize) -> Poly {
    (0..e).fold(Poly::one(), |acc, _| acc.mul(p))
}

/// G = sum_{j>=2} (j/2) rho_j rho^(j-r) y^(j-1), y = rbar + xh, as a polynomial in xh.
fn profile_term(
    ratios: &[Poly],
    r: usize,
    rbar: &Series<Poly>,
    rho: &Series<Poly>,
    prec: usize,
) -> Result<XPoly, SeriesError> {
    let inv_rho = rho.inv()?;
    let y: XPoly = vec![rbar.clone(), Series::one(prec)];
    let mut y_pow: XPoly = vec![Series::one(prec)];
    let mut out: XPoly = vec![Series::zero(prec)];
    for (j, rj) in ratios.iter().enumerate().skip(2) {
        y_pow = xp_mul(&y_pow, &y, prec);
        if rj.is_zero() {
            continue;
        }
        let e = j as i64 - r as i64;
        let rho_pow = if e >= 0 { rho.powi(e)? } else { inv_rho.powi(-e)? }.truncate(prec);
        let c = rho_pow.mul_scalar(&rj.scale(&q(j as i64, 2)));
        for (i, yi) in y_pow.iter().enumerate() {
            xp_add(&mut out, i, &yi.mul(&c).truncate(prec));
        }
    }
    Ok(out)
}

/// The exact pieces that do not change from order to order.
struct Setup {
    tab: Tables,
    ratios: Vec<Poly>,
    r: usize,
    k_max: usize,
    tbar_s: Poly,
    m0s: Poly,
    /// (kappa (1/4 - theta^2) m0s, -2 T invpi) in `periodic`, T = Tb_s - rho_1/2.
    k_coeffs: Option<(Poly, Poly)>,
    /// Delta^a: Lambda = scale * mu.
    scale: Poly,
    moments: usize,
}

impl Setup {
    /// F at working precision `prec` (module doc), mu-series coefficients.
    fn rhs(
        &self,
        rbar: &Series<Poly>,
        rho: &Series<Poly>,
        mt: &[Series<Poly>],
        prec: usize,
    ) -> Result<XPoly, SeriesError> {
        let mut f = profile_term(&self.ratios, self.r, rbar, rho, prec)?;
        let inv_rho = rho.inv()?;
        let rho_1mr = inv_rho.powi(self.r as i64 - 1)?.truncate(prec);
        xp_add(&mut f, 0, &rho_1mr.mul_scalar(&self.tbar_s));
        let big_lambda = Series::new(vec![Poly::zero(), self.scale.clone()], prec);
        if let Some((a, b)) = &self.k_coeffs {
            let rho_2mr = if self.r >= 2 { inv_rho.powi(self.r as i64 - 2)? } else { rho.clone() }.truncate(prec);
            let k = rho_1mr.mul_scalar(a).add(&rho_2mr.mul_scalar(b));
            xp_add(&mut f, 0, &big_lambda.mul(&k).truncate(prec));
        }
        let lambda = big_lambda.mul(rho).truncate(prec);
        let lambda2 = lambda.mul(&lambda).truncate(prec);
        let mut lam_pow = Series::<Poly>::one(prec);
        for k in 1..=self.k_max {
            lam_pow = lam_pow.mul(&lambda2).truncate(prec);
            let zk = &self.tab.z[k];
            let mut binom = Q::from_integer(1.into()); // C(2k-1, j)
            for j in 0..2 * k {
                let sign = if j % 2 == 0 { Q::from_integer(1.into()) } else { Q::from_integer((-1).into()) };
                let c = -(zk * &binom * sign);
                xp_add(&mut f, 2 * k - 1 - j, &mt[j].mul(&lam_pow).truncate(prec).scale(&c));
                binom = binom * Q::new(((2 * k - 1 - j) as i64).into(), ((j + 1) as i64).into());
            }
        }
        Ok(f.into_iter().map(|s| s.truncate(prec)).collect())
    }

    fn mt(&self, f: &XPoly, prec: usize) -> Vec<Series<Poly>> {
        let mu: Vec<Poly> = self.tab.nu.iter().map(|n| n.mul(&self.tab.quarter)).collect();
        (0..self.moments).map(|n| self.tab.moment(f, &mu, n).truncate(prec)).collect()
    }
}

/// Exact values fixed before the derivation (each `None` stays a symbol): the same result as
/// substituting afterwards (kappa aside: module doc), much faster. The coefficients are rational
/// functions of every symbol kept and their size grows with each: for g = x^2 + rho_4 x^4 in
/// `paper`, order 12 at fixed theta, rbar_s takes under a second, while order 8 with theta,
/// rbar_s and rho_4 all symbolic prints 1.8 MB in about a minute (debug build,
/// `series sliding --shape polynomial --coefficients 0,0,1,0,? --order 8`).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct FixedValues {
    /// theta, |theta| < 1/2.
    pub theta: Option<Q>,
    /// rbar_s, the single punch's centre over l_s. It fixes T = beta tau0/(E* c_r l_s^(r-1)):
    /// T = Tb_s(theta, rbar_s, rho_j) - rho_1/2 (module doc), so T is not a parameter here.
    pub rbar_s: Option<Q>,
}

/// Derives the expansions of the polynomial punch through Lambda^order (module doc), every
/// parameter symbolic.
///
/// ```
/// use exact_series::{Q, Ring};
/// use periodic_contact::asymptotics::polynomial::{polynomial_sliding_expansion, PolynomialProfile};
/// use periodic_contact::model::Convention;
/// let zero = Some(Q::from_integer(0.into()));
/// let one = Some(Q::from_integer(1.into()));
/// let g = PolynomialProfile::new(vec![zero.clone(), zero, one]).unwrap(); // g = x^2
/// let e = polynomial_sliding_expansion(&g, 2, Convention::Paper).unwrap();
/// assert_eq!(e.tbar_single.text(), "2*theta - rbar_s"); // rbar_s = 2 theta - T [3.10]
/// ```
pub fn polynomial_sliding_expansion(
    profile: &PolynomialProfile,
    order: usize,
    convention: Convention,
) -> Result<PolynomialSlidingExpansion, SeriesError> {
    polynomial_sliding_expansion_at(profile, order, convention, &FixedValues::default())
}

/// [`polynomial_sliding_expansion`] with some parameters fixed to exact values first.
pub fn polynomial_sliding_expansion_at(
    profile: &PolynomialProfile,
    order: usize,
    convention: Convention,
    fixed: &FixedValues,
) -> Result<PolynomialSlidingExpansion, SeriesError> {
    let periodic = convention == Convention::PeriodicSurface;
    let value = |v: &Option<Q>, name: &str| match v {
        Some(x) => Ok(Poly::from_q(x)),
        None => sym(name),
    };
    let theta = value(&fixed.theta, "theta")?;
    let rs = value(&fixed.rbar_s, "rbar_s")?;
    let ratios = profile.ratios()?;
    let r = profile.reference_degree();
    let d = profile.degree();
    let k_max = order / 2;
    let tab = Tables::new(order, &theta, d + 1)?;
    let quarter = tab.quarter.clone();

    // The single punch and the Jacobian (module doc).
    let pw = shifted_powers(&rs, d);
    let mut g_s = Vec::new();
    let mut dg_rbar = Vec::new();
    let mut df_rho = Vec::new();
    for (j, rj) in ratios.iter().enumerate().skip(2) {
        let jj = j as i64;
        add_into(&mut g_s, &pw[j - 1], &rj.scale(&q(jj, 2)));
        add_into(&mut dg_rbar, &pw[j - 2], &rj.scale(&q(jj * (jj - 1), 2)));
        add_into(&mut df_rho, &pw[j - 1], &rj.scale(&q(jj * (jj - r as i64), 2)));
    }
    let tbar_s = solvability(&g_s, &tab.j).neg();
    add_into(&mut df_rho, &[Poly::one()], &tbar_s.mul_int(1 - r as i64));
    let m0s = moment_poly(&g_s, &tab, &tab.nu, 0);
    let j11 = solvability(&dg_rbar, &tab.j);
    let j12 = solvability(&df_rho, &tab.j);
    let j21 = moment_poly(&dg_rbar, &tab, &tab.nu, 0);
    let j22 = m0s.mul_int(r as i64).add(&moment_poly(&df_rho, &tab, &tab.nu, 0));
    let delta = j11.mul(&j22).sub(&j12.mul(&j21));
    if delta.is_zero() {
        return Err(SeriesError::NotInvertible {
            operation: "single-punch Jacobian of the polynomial profile",
            value: "0".into(),
        });
    }
    let delta_q = delta.as_q();
    let a = if delta_q.is_some() {
        0
    } else if periodic {
        2
    } else {
        1
    };
    let k_coeffs = if periodic {
        // kappa = tan(pi theta) (rational at theta = 0, +-1/4 only); T = Tb_s - rho_1/2.
        let kappa = match fixed.theta.as_ref().and_then(rational_tan_pi) {
            Some(k) => Poly::from_q(&k),
            None => sym("kappa")?,
        };
        let invpi = sym("invpi")?;
        let t = tbar_s.sub(&ratios[1].scale(&q(1, 2)));
        Some((kappa.mul(&quarter).mul(&m0s), t.mul(&invpi).mul_int(-2)))
    } else {
        None
    };
    let moments = (2 * k_max).max(d) + 1;
    let setup = Setup { tab, ratios, r, k_max, tbar_s, m0s, k_coeffs, scale: pow(&delta, a), moments };
    let divide = |n: Poly| -> Result<Poly, SeriesError> {
        match &delta_q {
            Some(dq) => Ok(n.scale(&dq.recip())),
            None => n.div_exact(&delta).ok_or_else(|| SeriesError::NotInvertible {
                operation: "exact division by the single-punch Jacobian (a remainder is a bug)",
                value: delta.text(),
            }),
        }
    };

    let mut rho = Series::<Poly>::one(1);
    let mut rbar = Series::constant(rs.clone(), 1);
    let g0: XPoly = g_s.iter().map(|c| Series::constant(c.clone(), 1)).collect();
    let mut mt = setup.mt(&g0, 1);
    let mut f = setup.rhs(&rbar, &rho, &mt, 1)?;
    for k in 1..=order {
        let wprec = k + 1;
        let pad = |s: &Series<Poly>| Series::new(s.coeffs().to_vec(), wprec);
        rho = pad(&rho);
        rbar = pad(&rbar);
        mt = mt.iter().map(pad).collect();
        f = setup.rhs(&rbar, &rho, &mt, wprec)?;
        let coeff = |s: &Series<Poly>| s.coeff(k).cloned().unwrap_or_else(Poly::zero);
        let mut phi1 = Poly::zero();
        for (fi, ji) in f.iter().zip(&setup.tab.j) {
            phi1 = phi1.add(&coeff(fi).mul(ji));
        }
        let m0 = setup.tab.moment(&f, &setup.tab.nu, 0);
        let phi2 = coeff(&rho.powi(r as i64)?.mul(&m0));
        let x_rbar = divide(j22.mul(&phi1).sub(&j12.mul(&phi2)).neg())?;
        let x_rho = divide(j11.mul(&phi2).sub(&j21.mul(&phi1)).neg())?;
        let at_k = |c: &Poly| Series::from_fn(wprec, |m| if m == k { c.clone() } else { Poly::zero() });
        rbar = rbar.add(&at_k(&x_rbar));
        rho = rho.add(&at_k(&x_rho));
        for (i, c) in dg_rbar.iter().enumerate() {
            xp_add(&mut f, i, &at_k(&c.mul(&x_rbar)));
        }
        for (i, c) in df_rho.iter().enumerate() {
            xp_add(&mut f, i, &at_k(&c.mul(&x_rho)));
        }
        mt = setup.mt(&f, wprec);
    }

    let prec = order + 1;
    let to_frac = |p: &Poly, k: usize| -> Frac {
        match &delta_q {
            Some(_) => Frac::from_poly(p.clone()),
            None => Frac::over_power(p.clone(), &delta, (a * k) as u32).expect("Delta is not zero"),
        }
    };
    let lambda_series = |s: &Series<Poly>| Series::from_fn(prec, |k| to_frac(s.coeff(k).unwrap_or(&Poly::zero()), k));
    let g = profile_term(&setup.ratios, r, &rbar, &rho, prec)?;
    let mut fdef = Series::constant(setup.ratios[1].mul(&quarter).mul(&setup.m0s), prec);
    let rho_pow = rho.powi(2 * r as i64 - 1)?;
    for (i, gi) in g.iter().enumerate() {
        fdef = fdef.add(&gi.mul(&mt[i]).mul(&rho_pow).truncate(prec).scale(&q(2, 1)));
    }
    let xh = Symbol::new("xh")?;
    let mut b: Vec<Poly> = vec![Poly::zero(); prec];
    for (i, fi) in f.iter().enumerate().skip(1) {
        for s in 0..i {
            let mono = Poly::term(&Q::from_integer(1.into()), Monomial::power(xh, s as u32));
            let c = setup.tab.j[i - 1 - s].mul(&mono);
            for (k, bk) in b.iter_mut().enumerate() {
                if let Some(fik) = fi.coeff(k) {
                    *bk = bk.add(&fik.mul(&c));
                }
            }
        }
    }
    Ok(PolynomialSlidingExpansion {
        profile: profile.clone(),
        convention,
        jacobian: delta.clone(),
        tbar_single: setup.tbar_s.clone(),
        load_single: setup.m0s.clone(),
        l_over_ls: lambda_series(&rho),
        rbar_minus_rbar_s: lambda_series(&rbar.sub(&Series::constant(rs, prec))),
        f_def_scaled: lambda_series(&fdef),
        pressure: Series::from_fn(prec, |k| to_frac(&b[k], k)),
    })
}
