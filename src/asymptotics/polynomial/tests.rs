use super::*;
use crate::asymptotics::sliding::{sliding_expansion_with, SlidingShape};
use crate::model::Convention;
use exact_series::{Frac, Poly, Ring, Series, Symbol, Q};

fn q(n: i64, d: i64) -> Q {
    Q::new(n.into(), d.into())
}

fn c(n: i64) -> Option<Q> {
    Some(q(n, 1))
}

fn s(name: &str) -> Symbol {
    Symbol::new(name).unwrap()
}

fn frac_subs_poly(f: &Frac, sym: Symbol, v: &Poly) -> Frac {
    Frac::new(f.numer().subs_poly(sym, v), f.denom().subs_poly(sym, v)).unwrap()
}

fn frac_subs(f: &Frac, sym: Symbol, v: &Q) -> Frac {
    f.subs(sym, v).unwrap()
}

#[test]
fn parabola_reproduces_the_parabolic_expansions_exactly() {
    // g = k x^2 in both conventions: with rbar_s = 2 theta - T [3.10] every object equals the
    // parabola's derivation (asymptotics::sliding), coefficient by coefficient, as exact objects.
    let order = 8;
    let theta = Poly::symbol(s("theta"));
    let t = Poly::symbol(s("T"));
    let rbar_s = theta.mul_int(2).sub(&t);
    for k in [1, 3] {
        let g = PolynomialProfile::new(vec![c(0), c(0), c(k)]).unwrap();
        for conv in [Convention::Paper, Convention::PeriodicSurface] {
            let e = polynomial_sliding_expansion(&g, order, conv).unwrap();
            let p = sliding_expansion_with(SlidingShape::Parabolic, order, conv).unwrap();
            assert_eq!(e.tbar_single, theta.mul_int(2).sub(&Poly::symbol(s("rbar_s"))));
            let sub = |x: &Series<Frac>| x.map(|f| frac_subs_poly(f, s("rbar_s"), &rbar_s));
            let lift = |x: &Series<Poly>| x.map(|f| Frac::from_poly(f.clone()));
            assert_eq!(sub(&e.l_over_ls), lift(&p.l_over_ls), "{conv:?} l");
            assert_eq!(sub(&e.rbar_minus_rbar_s), lift(&p.rbar_minus_rbar_s), "{conv:?} rbar");
            assert_eq!(sub(&e.f_def_scaled), lift(&p.f_def_scaled), "{conv:?} F_def");
            let pr = sub(&e.pressure);
            assert!(pr.coeff(0).unwrap().as_q().is_some_and(|v| v == q(1, 1)));
            for (j, pj) in p.pressure.iter().enumerate() {
                assert_eq!(pr.coeff(p.step * (j + 1)).unwrap(), &Frac::from_poly(pj.clone()), "{conv:?} pi_{j}");
            }
        }
    }
}

#[test]
fn quartic_with_rho_zero_is_the_parabola() {
    let g = PolynomialProfile::new(vec![c(0), c(0), c(1), c(0), None]).unwrap();
    let par = PolynomialProfile::new(vec![c(0), c(0), c(1)]).unwrap();
    // Fixed exact theta, rbar_s, T (fully symbolic, order 6 takes minutes: FixedValues doc).
    let fixed = FixedValues { theta: Some(q(1, 10)), rbar_s: Some(q(1, 5)) };
    for conv in [Convention::Paper, Convention::PeriodicSurface] {
        let e = polynomial_sliding_expansion_at(&g, 6, conv, &fixed).unwrap();
        let p = polynomial_sliding_expansion_at(&par, 6, conv, &fixed).unwrap();
        let z = |x: &Series<Frac>| x.map(|f| frac_subs(f, s("rho_4"), &q(0, 1)));
        assert_eq!(z(&e.l_over_ls), p.l_over_ls);
        assert_eq!(z(&e.rbar_minus_rbar_s), p.rbar_minus_rbar_s);
        assert_eq!(z(&e.f_def_scaled), p.f_def_scaled);
        assert_eq!(z(&e.pressure), p.pressure);
    }
}

/// (2n-1)!!/(2n)!!
fn double_factorial_ratio(n: i64) -> Q {
    (1..=n).fold(q(1, 1), |acc, i| acc * q(2 * i - 1, 2 * i))
}

#[test]
fn single_punch_power_law() {
    // docs/theory.md section 9: g = A x^(2n) alone gives P2 = n pi E* A a^(2n) (2n-1)!!/(2n)!!; the
    // series' leading term is P2 = pi E* c_r l_s^r (1/4 - theta^2) m0s with r = 2n, so
    // m0s/4 = n (2n-1)!!/(2n)!! at theta = rbar_s = 0 (symmetric, frictionless).
    for n in 1..=4usize {
        let mut coeffs = vec![c(0); 2 * n + 1];
        coeffs[2 * n] = Some(q(7, 3));
        let g = PolynomialProfile::new(coeffs).unwrap();
        let e = polynomial_sliding_expansion(&g, 0, Convention::Paper).unwrap();
        let m0s = e.load_single.subs(s("theta"), &q(0, 1)).subs(s("rbar_s"), &q(0, 1));
        assert_eq!(m0s.as_q().unwrap() / q(4, 1), double_factorial_ratio(n as i64) * q(n as i64, 1), "n = {n}");
        // Symmetric: the single punch is centred when T + rho_1/2 = 0.
        assert!(e.tbar_single.subs(s("theta"), &q(0, 1)).subs(s("rbar_s"), &q(0, 1)).is_zero());
    }
}

#[test]
fn paper_expansions_are_even_and_periodic_ones_are_not() {
    let g = PolynomialProfile::new(vec![c(0), c(0), c(1), None]).unwrap();
    let e = polynomial_sliding_expansion(&g, 4, Convention::Paper).unwrap();
    assert!(e.l_over_ls.coeff(2).unwrap().numer().symbols().len() >= 3); // theta, rbar_s, rho_3
    assert!(e.l_over_ls.is_even() && e.rbar_minus_rbar_s.is_even() && e.f_def_scaled.is_even());
    let fixed = FixedValues { theta: Some(q(1, 10)), ..FixedValues::default() };
    let p = polynomial_sliding_expansion_at(&g, 3, Convention::PeriodicSurface, &fixed).unwrap();
    assert!(!p.l_over_ls.coeff(1).unwrap().is_zero());
}

/// int_{-1}^{1} p(s) ds / (pi sqrt(1 - s^2)) for p in Q[s, ...]: s^n -> (n-1)!!/n!! (n even).
fn chebyshev_mean(p: &Poly, sv: Symbol) -> Poly {
    let mut out = Poly::zero();
    for (mono, coef) in p.terms() {
        let (rest, e) = mono.remove(sv);
        if e % 2 == 0 {
            let w = double_factorial_ratio(e as i64 / 2);
            out = out.add(&Poly::term(&(coef * w), rest));
        }
    }
    out
}

/// docs/theory.md section 9's closed-form frictionless load for an even profile, as an identity in
/// Lambda: with x = a s, P2 = (E*/2) sum_j j c_j a^j Q_j(lambda),
/// Q_j = int s^j sinc(lambda s) [sinc(lambda (1+s)) sinc(lambda (1-s))]^(-1/2) ds/sqrt(1-s^2),
/// and P2 = pi E* c_r l_s^r m0s/4 at theta = 0, a = rho l_s, lambda = Lambda rho:
/// (1/(2 pi)) sum_j j rho_j rho^j Q_j(Lambda rho) = m0s/4. No Jacobi moments, no solvability
/// condition, no fixed point: an independent route to l/l_s.
fn closed_form_residual(g: &PolynomialProfile, order: usize) -> Series<Frac> {
    closed_form_residual_at(g, order, None)
}

/// [`closed_form_residual`] with one profile symbol (e.g. rho_4) set to a rational after the
/// derivation (the identity then has rational coefficients: fast at high order).
fn closed_form_residual_at(g: &PolynomialProfile, order: usize, at: Option<(&str, Q)>) -> Series<Frac> {
    let zero = q(0, 1);
    let fixed = FixedValues { theta: Some(zero.clone()), rbar_s: Some(zero.clone()) };
    let e = polynomial_sliding_expansion_at(g, order, Convention::Paper, &fixed).unwrap();
    let at0 = |f: &Frac| match &at {
        Some((name, v)) => frac_subs(f, s(name), v),
        None => f.clone(),
    };
    let rho = e.l_over_ls.map(at0);
    let m0s = match &at {
        Some((name, v)) => e.load_single.subs(s(name), v),
        None => e.load_single.clone(),
    };
    let ratios: Vec<Poly> = g
        .ratios()
        .unwrap()
        .iter()
        .map(|r| match &at {
            Some((name, v)) => r.subs(s(name), v),
            None => r.clone(),
        })
        .collect();
    let prec = order + 1;
    let (sv, sp, w) = closed_form_weight(prec);
    let lam = Series::<Frac>::var(prec).mul(&rho);
    let mut lhs = Series::<Frac>::zero(prec);
    let mut s_pow = Poly::one();
    for (j, rj) in ratios.iter().enumerate() {
        if j > 0 && !rj.is_zero() {
            let qj: Series<Frac> = w.map(|wk| Frac::from_poly(chebyshev_mean(&wk.mul(&s_pow), sv)));
            let term = qj.compose(&lam).unwrap().mul(&rho.powi(j as i64).unwrap());
            lhs = lhs.add(&term.mul_scalar(&Frac::from_poly(rj.scale(&q(j as i64, 2)))));
        }
        s_pow = s_pow.mul(&sp);
    }
    lhs.sub(&Series::constant(Frac::from_poly(m0s.scale(&q(1, 4))), prec))
}

#[test]
fn even_profiles_match_the_closed_form_load() {
    let profiles = [
        vec![c(0), c(0), c(0), c(0), c(5)],             // 5 x^4 (r = 4)
        vec![c(0), c(0), c(0), c(0), c(0), c(0), c(2)], // 2 x^6 (r = 6)
    ];
    for p in profiles {
        let g = PolynomialProfile::new(p).unwrap();
        let res = closed_form_residual(&g, 10);
        assert!(res.coeffs().iter().all(|c| c.is_zero()), "{res:?}");
    }
}

#[test]
fn adhesion_parabola_reproduces_the_parabolic_series() {
    // g = k x^2: sigma_2 = 1, the recurrence of asymptotics::adhesion exactly; the load
    // P/pi = sum_j p_j lambda^(2j+2)/(2j+2) = (C_P/pi) lambda^2 (1 + c_2 lambda^2 + ...).
    let g = PolynomialProfile::new(vec![c(0), c(0), c(3)]).unwrap();
    let e = polynomial_adhesion_expansion(&g, 8).unwrap();
    let p = crate::asymptotics::adhesion::adhesion_expansion_with(8, false).unwrap();
    assert_eq!(e.slope, p.slope);
    assert_eq!(e.volterra, p.volterra);
    for j in 0..=4 {
        assert_eq!(e.load.coeff(2 * j + 2).unwrap(), &p.load_constant.mul(p.load.coeff(2 * j).unwrap()), "j = {j}");
    }
}

#[test]
fn adhesion_at_half_is_the_frictionless_closed_form() {
    // nu = 1/2 (eps = S = 0): P2 = E* c_r (L/pi)^r P(lambda) must be docs/theory.md section 9's
    // closed form, P/pi = (1/2) sum_j j sigma_j lambda^j q_j(lambda), with q_j = Q_j/pi of
    // closed_form_residual (the frictionless load of the same profile, Problem 1).
    let order = 8;
    let g = PolynomialProfile::new(vec![c(0), c(0), c(1), c(0), None, c(0), None]).unwrap();
    let e = polynomial_adhesion_expansion(&g, order).unwrap();
    let zero = q(0, 1);
    let got = e.load.map(|f| frac_subs(&frac_subs(f, s("eps"), &zero), s("S"), &zero));
    let prec = got.prec();
    let (sv, sp, w) = closed_form_weight(prec);
    let mut want = Series::<Frac>::zero(prec);
    let mut s_pow = Poly::one();
    for (j, sj) in g.period_ratios().unwrap().iter().enumerate() {
        if j > 0 && !sj.is_zero() {
            let qj: Series<Frac> =
                w.map(|wk| Frac::from_poly(chebyshev_mean(&wk.mul(&s_pow), sv).mul(sj).scale(&q(j as i64, 2))));
            want = want.add(&qj.shift(j).truncate(prec));
        }
        s_pow = s_pow.mul(&sp);
    }
    assert_eq!(got, want);
}

#[test]
fn symbolic_quartic_matches_the_closed_form_load_through_order_12() {
    // The snapshot sliding_polynomial_quartic_frictionless_order12: l/l_s of g = x^2 + rho_4 x^4
    // (rho_4 symbolic) against docs/theory.md section 9's closed form, an identity in Lambda; checked
    // at several rho_4 (each coefficient is a rational function of degree < 24 in rho_4, so
    // these values test the snapshot's objects, not a proof of the identity in rho_4).
    let g = PolynomialProfile::new(vec![c(0), c(0), c(1), c(0), None]).unwrap();
    for v in [q(1, 10), q(3, 1), q(-1, 7)] {
        let res = closed_form_residual_at(&g, 12, Some(("rho_4", v.clone())));
        assert!(res.coeffs().iter().all(|c| c.is_zero()), "rho_4 = {v}: {res:?}");
    }
}

#[test]
fn periodic_quartic_at_rho_zero_is_the_periodic_parabola_with_exact_kappa() {
    // The snapshot sliding_periodic_polynomial_quartic_theta_1_4_order12 at rho_4 = 0 against
    // asymptotics::sliding's periodic parabola at theta = 1/4, T = 2 theta - rbar_s = 1/3 and
    // kappa = tan(pi/4) = 1 (odd powers included: order 7).
    let order = 7;
    let g = PolynomialProfile::new(vec![c(0), c(0), c(1), c(0), None]).unwrap();
    let fixed = FixedValues { theta: Some(q(1, 4)), rbar_s: Some(q(1, 6)) };
    let e = polynomial_sliding_expansion_at(&g, order, Convention::PeriodicSurface, &fixed).unwrap();
    let p = sliding_expansion_with(SlidingShape::Parabolic, order, Convention::PeriodicSurface).unwrap();
    let at = |x: &Series<Poly>| {
        x.map(|f| Frac::from_poly(f.subs(s("theta"), &q(1, 4)).subs(s("T"), &q(1, 3)).subs(s("kappa"), &q(1, 1))))
    };
    let z = |x: &Series<Frac>| x.map(|f| frac_subs(f, s("rho_4"), &q(0, 1)));
    assert!(e.l_over_ls.coeff(1).unwrap().numer().symbols().iter().all(|x| x.name() != "kappa"));
    assert_eq!(z(&e.l_over_ls), at(&p.l_over_ls));
    assert_eq!(z(&e.rbar_minus_rbar_s), at(&p.rbar_minus_rbar_s));
    assert_eq!(z(&e.f_def_scaled), at(&p.f_def_scaled));
}

/// The symbol s, its polynomial and the weight series w = sinc(s .) (sinc((1 + s) .)
/// sinc((1 - s) .))^(-1/2) through `prec`, shared by the closed-form checks of both problems.
fn closed_form_weight(prec: usize) -> (Symbol, Poly, Series<Poly>) {
    let sv = Symbol::new("s_cheb").unwrap();
    let sp = Poly::symbol(sv);
    let sinc = Series::<Poly>::sinc_series(prec);
    let half = Poly::from_q(&q(-1, 2));
    let w = sinc
        .rescale_var(&sp)
        .mul(&sinc.rescale_var(&Poly::one().add(&sp)).pow(&half).unwrap())
        .mul(&sinc.rescale_var(&Poly::one().sub(&sp)).pow(&half).unwrap());
    (sv, sp, w)
}
