//! The homogeneous solution of section 4's symmetric Problem 2 (issue 13): why no method verifies
//! the incremental solution at small nu and larger lambda, and why none can.
//!
//! # The mode \[derived here\]
//! For the single punch the incremental equation int_0^chi Re K(chi, eta) P'(eta) d eta = pi chi
//! has the kernel K = (chi + eta)^(-1/2 + i eps) (chi - eta)^(-1/2 - i eps) (docs/theory.md
//! section 4 with sin -> identity, cos -> 1), homogeneous of degree -1, so a power P' = eta^m
//! gives chi^m Re M_m with the half-range moment M_m of section 5. Where Re M_m* = 0 for a real
//! m* > 1, P' + C eta^m* solves the same equation for every C: the incremental
//! complete-adhesion problem does not fix its solution. For the periodic row the kernel is
//! K(1 + O(eta^2)) and the mode continues as C H(eta), H = eta^m* (1 + O(eta^2)): the solution is
//! one-parameter family at every nu < 1/2 (at nu = 1/2, eps = 0, Re M_m > 0 for every m: unique).
//! The member analytic in lambda^2 (C = 0) is the series' ([`super::adhesion`],
//! [`super::adhesion_numeric`]): its coefficient of lambda^(2N) is divided by Re M_(2N+1), small
//! near m* (the "pole" near N = 302 at nu = 0 is this mode).
//!
//! m*(nu): the first sign change of Re M_m over odd m by the recurrence of section 4,
//! (m + 1) M_(m+1) = m M_(m-1) + 2 i eps M_m from M_0 = B/2 + i S, M_1 = 1 + 2 i eps M_0 (neutral:
//! both solutions ~ m^(-1/2)), interpolated linearly between the two odd m, then refined by the
//! secant method on Re M_x at real x (the two starting moments by quadrature, the recurrence
//! beyond: [`half_range_moment`]). nu = 0: 605.731090977683 (mpmath's root of
//! Re B(m+1, 1/2 - i eps) 2F1(1/2 - i eps, m+1; m+3/2 - i eps; -1) = 605.731090977680826547, run
//! once), nu = 1/10: 2284.482253534 (2284.48225353), nu = 1/5: 20001.69250179
//! (20001.6925017875), nu = 3/10: 1409212.5236 (1409212.523566145) (tests
//! `mode_exponent_against_mpmath`, `refined_mode_exponent_against_mpmath`). The loading
//! law's mode at n = 0 ([`super::loading_law_modes`]: 603.73, in F = P'/eta, the smaller zero of
//! det M = 2 M_f M_g) is the antisymmetric one (the centre moving); this one, 604.73 in F, is
//! M_f's: the two lie close together, as that module says.
//!
//! # What the solvers see (measured)
//! A small m* does not show at small sizes (C H is below any working precision), but the mode's
//! local growth rate d ln H/d ln eta falls as the contact grows (the kernel's phase rotates with
//! chi), so beyond some size two discretisations that each satisfy the equation to their full
//! precision differ by a multiple of H: the MPFR collocation at nu = 0, lambda = 1 with 60 and
//! 100 Chebyshev nodes (200 bits) has residuals below 1e-20 at points between the nodes, yet the
//! loads differ by 1.7e-4; with 120 and 150 nodes at 400 bits (residuals ~1e-40) the difference
//! F_120 - F_150 is at the 1e-39 floor for tau = (eta/lambda)^2 < 0.42 and grows steadily to
//! 5e-2 at tau = 1 (a growth rate d log10|D|/d tau of 150 at tau = 0.45, 18 at 1): a function the
//! equation does not see. With 60 and 120 nodes (300 bits), log10 |F_60 - F_120| at tau = 1 is
//! -14.5 at lambda = 0.8, -6.3 at 0.9, -2.1 at 1.0, and at the residual floor (-34, -26, -20) for
//! tau <= 0.5; at nu = 1/2 the same runs agree to 1e-51 (lambda = 1) and 1e-19 (1.45). More
//! nodes, more bits or another method (the f64 collocation in eta of
//! [`crate::adhesion::collocation_f64`] at nu = 0.15, lambda = 1.2: loads 1e-4 apart) do not
//! remove it: it is the problem's, not a discretisation's. At nu = 3/10 (m* = 1.4e6) the runs
//! agree to 1e-29 at lambda = 1.2; at 1.35 F differs by 1e-16 below tau = 0.9 and 1e-9 at tau = 1;
//! at 1.45 the collocation is not resolved (residuals 1e-6 to 1e-12, against 1e-22 to 1e-43 at
//! nu = 1/2) and the difference is largest at tau = 1: consistent with the mode grown near
//! eta = lambda, but there not separated from the slow convergence near full contact. `cargo run --release --example adhesion_charts --
//! homogeneous` prints these numbers; the test `two_discretisations_differ_by_a_homogeneous_solution`
//! (crate::adhesion::tests) asserts the nu = 0, lambda = 1 case and the nu = 1/2 control.
//!
//! So issue 13's dichotomy has a third answer: not a weak singularity to resolve, and not a size
//! lambda_s where well-posedness is lost, but a problem that is not unique at any size for
//! nu < 1/2, whose distinguished member (C = 0) cannot be told apart from the others by the
//! equation once H has grown to the digits asked. The solvers say so in their refusals and
//! warnings, naming m*.

/// m*(nu): the exponent of the symmetric homogeneous mode P' = eta^m* (Re M_m* = 0), from the
/// recurrence of M_m (module doc), with eps, B = pi/cosh(pi eps) and S(eps) as f64; `None` when
/// Re M_m keeps its sign up to `m_max` (eps = 0, or eps so small that m* > m_max).
pub fn symmetric_mode_exponent(eps: f64, b: f64, s: f64, m_max: usize) -> Option<f64> {
    // Complex numbers as (re, im) pairs: the recurrence needs only + and * by 2 i eps.
    let (mut prev, mut cur) = ((b / 2.0, s), (1.0 - 2.0 * eps * s, eps * b));
    let mut last_odd = cur.0;
    let mut m = 1usize;
    while m < m_max {
        let mf = m as f64;
        // (m + 1) M_(m+1) = m M_(m-1) + 2 i eps M_m.
        let next = ((mf * prev.0 - 2.0 * eps * cur.1) / (mf + 1.0), (mf * prev.1 + 2.0 * eps * cur.0) / (mf + 1.0));
        prev = cur;
        cur = next;
        m += 1;
        if m % 2 == 1 {
            if (cur.0 > 0.0) != (last_odd > 0.0) {
                let t = last_odd / (last_odd - cur.0);
                return Some((m - 2) as f64 + 2.0 * t);
            }
            last_odd = cur.0;
        }
    }
    None
}

/// M_x at a real x >= 1 (complex, as (re, im)): M_(x0 - 1) and M_x0, x0 = 1 + frac(x), by
/// tanh-sinh quadrature of the definition (the endpoint factor (1 - y)^(-1/2 - i eps) from
/// 1 - y held exactly by the rule), then the recurrence up to x (it holds at every real index
/// > 0: integrate d/dy [y^x (1 + y)^(1/2 + i eps) (1 - y)^(1/2 - i eps)] over (0, 1)).
pub fn half_range_moment(eps: f64, x: f64) -> (f64, f64) {
    let x0 = 1.0 + x.fract();
    let rule = crate::numerics::tanh_sinh::tanh_sinh_f64(53, 2.0);
    let moment = |m: f64| {
        let (mut re, mut im) = (0.0, 0.0);
        for &(y, c, w) in &rule {
            if y <= 0.0 || c <= 0.0 {
                continue;
            }
            // y^m (1 + y)^(-1/2) (1 - y)^(-1/2) e^(i eps (ln(1 + y) - ln(1 - y))).
            let modulus = (m * y.ln() - 0.5 * (y.ln_1p() + c.ln())).exp();
            let phase = eps * (y.ln_1p() - c.ln());
            re += w * modulus * phase.cos();
            im += w * modulus * phase.sin();
        }
        (re, im)
    };
    let (mut prev, mut cur) = (moment(x0 - 1.0), moment(x0));
    let mut k = x0;
    while k + 0.5 < x {
        // (k + 1) M_(k+1) = k M_(k-1) + 2 i eps M_k.
        let next = ((k * prev.0 - 2.0 * eps * cur.1) / (k + 1.0), (k * prev.1 + 2.0 * eps * cur.0) / (k + 1.0));
        prev = cur;
        cur = next;
        k += 1.0;
    }
    cur
}

/// m* refined: the secant method on Re M_x ([`half_range_moment`]) from the interpolated value
/// of [`symmetric_mode_exponent`] inside its bracket of odd integers.
pub fn symmetric_mode_exponent_refined(eps: f64, b: f64, s: f64, m_max: usize) -> Option<f64> {
    let guess = symmetric_mode_exponent(eps, b, s, m_max)?;
    let f = |x: f64| half_range_moment(eps, x).0;
    let (mut x0, mut x1) = (guess - 0.01, guess + 0.01);
    let (mut f0, mut f1) = (f(x0), f(x1));
    for _ in 0..40 {
        if f1 == f0 {
            break;
        }
        let x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
        if !x2.is_finite() {
            break;
        }
        (x0, f0) = (x1, f1);
        x1 = x2;
        f1 = f(x1);
        if (x1 - x0).abs() <= 1e-13 * x1 {
            break;
        }
    }
    Some(x1)
}

/// m* printed to 13 significant digits (the refined value agrees with mpmath to 13-14:
/// `refined_mode_exponent_against_mpmath`).
pub fn mode_text(m: f64) -> String {
    let int_digits = (m.abs().log10().floor() as i32 + 1).max(1);
    format!("{m:.*}", (13 - int_digits).max(0) as usize)
}

/// The sentence the solvers add where their runs disagree at nu < 1/2 (module doc), naming m*.
pub fn mode_sentence(eps: f64, b: f64, s: f64) -> String {
    let m = match symmetric_mode_exponent_refined(eps, b, s, 2_000_000) {
        Some(m) => format!("m* = {}", mode_text(m)),
        None => "m* > 2e6".into(),
    };
    format!(
        "below nu = 1/2 the incremental problem fixes P' only up to C H(eta), a homogeneous solution with \
         H ~ eta^m* ({m}, Re M_m* = 0; asymptotics::adhesion_mode): two discretisations pick different C, and \
         by this size their difference has grown to the digits lost; no precision or node count removes it"
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Exact, Material};
    use crate::params::adhesion::AdhesionParamsF64;

    fn at(nu: (i64, i64)) -> Option<f64> {
        let m = Material::from_contact_modulus(Exact::new(nu.0.into(), nu.1.into()), Exact::from_integer(1.into()))
            .unwrap();
        let c = AdhesionParamsF64::new(&m);
        symmetric_mode_exponent(c.eps, c.b, c.s, 400_000)
    }

    /// The mpmath roots quoted in the module doc (Re of B(m+1, 1/2 - i eps) times 2F1 at -1):
    /// 605.731090977680826547 (nu = 0), 2284.48225353 (1/10), 20001.6925017875 (1/5); the
    /// interpolation between odd m is good to a few hundredths.
    #[test]
    fn mode_exponent_against_mpmath() {
        for (nu, want) in [((0, 1), 605.731_090_977_680_8), ((1, 10), 2284.482_253_53), ((1, 5), 20_001.692_501_787_5)]
        {
            let m = at(nu).unwrap();
            assert!((m - want).abs() < 0.05, "nu {nu:?}: {m} vs {want}");
        }
        assert_eq!(at((3, 10)), None, "beyond 4e5 at nu = 0.3");
        assert_eq!(at((1, 2)), None, "eps = 0: Re M_m > 0");
    }

    /// Refined by the secant method on Re M_x: the mpmath roots (findroot on Re B 2F1, run once;
    /// nu = 3/10: 1409212.523566145) to 1e-9 relative (measured: 605.731090977683,
    /// 2284.482253534496, 20001.692501787606, 13 to 14 digits); M_x at a non-integer index from
    /// the recurrence equals the direct quadrature.
    #[test]
    fn refined_mode_exponent_against_mpmath() {
        // `cargo test --release --lib adhesion_mode -- --nocapture` prints the values.
        let params = |nu: (i64, i64)| {
            let m = Material::from_contact_modulus(Exact::new(nu.0.into(), nu.1.into()), Exact::from_integer(1.into()))
                .unwrap();
            AdhesionParamsF64::new(&m)
        };
        for (nu, want) in [
            ((0, 1), 605.731_090_977_680_8),
            ((1, 10), 2284.482_253_53),
            ((1, 5), 20_001.692_501_787_5),
            ((3, 10), 1_409_212.523_566_145),
        ] {
            let c = params(nu);
            let m = symmetric_mode_exponent_refined(c.eps, c.b, c.s, 2_000_000).unwrap();
            println!("nu {nu:?}: m* = {m:.12} (mpmath {want})");
            assert!((m - want).abs() < 1e-9 * want, "nu {nu:?}: {m} vs {want}");
        }
        // The recurrence from a fractional start (x0 = 1.3) against the direct quadrature at 7.3.
        let c = params((0, 1));
        let (re, im) = half_range_moment(c.eps, 7.3);
        let rule = crate::numerics::tanh_sinh::tanh_sinh_f64(53, 2.0);
        let (mut dr, mut di) = (0.0, 0.0);
        for &(y, one_minus, w) in &rule {
            if y > 0.0 && one_minus > 0.0 {
                let modulus = (7.3 * y.ln() - 0.5 * (y.ln_1p() + one_minus.ln())).exp();
                let phase = c.eps * (y.ln_1p() - one_minus.ln());
                dr += w * modulus * phase.cos();
                di += w * modulus * phase.sin();
            }
        }
        assert!((re - dr).abs() < 1e-14 && (im - di).abs() < 1e-14, "{re} {im} vs {dr} {di}");
    }

    /// The loading law's symbol at n = 0 (independent code: tanh-sinh quadrature of its kernel in
    /// MPFR): its f-column entry M_f(mu) = Re M_(mu+1) vanishes at mu = m* - 1 = 604.73 (this mode,
    /// the centre fixed) and changes sign there, while 603.73, the zero that module reports, is
    /// not M_f's (module doc).
    #[test]
    fn the_loading_law_symbol_has_this_zero_in_its_f_column() {
        use crate::asymptotics::loading_law_modes::Symbol;
        use crate::numerics::tanh_sinh::TanhSinh;
        use crate::params::adhesion::AdhesionParamsMpfr;
        use rug::Float;
        let prec = 160;
        let m = Material::from_contact_modulus(Exact::from_integer(0.into()), Exact::from_integer(1.into())).unwrap();
        let params = AdhesionParamsMpfr::new(&m, prec);
        let rule = TanhSinh::new(120, 1.0, prec);
        let sym = Symbol::new(&params, &Float::with_val(prec, 0), &rule, prec).unwrap();
        let mf = |mu: f64| sym.matrix(&Float::with_val(prec, mu))[0][0].to_f64();
        let star = at((0, 1)).unwrap() - 1.0;
        let (below, above) = (mf(star - 0.05), mf(star + 0.05));
        assert!(below * above < 0.0, "M_f changes sign across {star}: {below:e} {above:e}");
        let off = mf(603.731_091);
        assert!(off.abs() > 3.0 * below.abs().max(above.abs()), "M_f(603.73) = {off:e} is not small");
    }
}
