//! The catalogue of derived series objects that the CLI (`periodic-contact series OBJECT`) and
//! the report print: each with its name, formula, equation number and expansion variable.

use super::polynomial::{
    polynomial_adhesion_expansion, polynomial_sliding_expansion_at, FixedValues, PolynomialProfile,
};
use super::sliding::{sliding_expansion, sliding_expansion_with, SlidingExpansion, SlidingShape};
use super::{jacobi_moments::jacobi_moments, kernel::kernel_series, weight::weight_series};
use crate::model::Convention;
use exact_series::{Frac, Poly, Ring, Series, SeriesError, Symbol, Q};

/// A derived object, ready to print.
#[derive(Debug, Clone)]
pub struct Derived {
    /// CLI name (`kernel`, `weight`, `jacobi`).
    pub object: &'static str,
    /// The formula in words.
    pub formula: &'static str,
    /// Where it comes from (docs/theory.md section, paper equation).
    pub source: &'static str,
    /// Expansion variable (or index, for sequences).
    pub variable: &'static str,
    /// The exact coefficients (polynomials or rational functions), symbols possibly substituted.
    pub series: Series<Frac>,
    /// Symbols that may occur in the coefficients.
    pub symbols: Vec<Symbol>,
    /// Definitions of the parameters (polynomial profiles: the coefficients, rho_j, T), printed
    /// after the source; empty for the other objects.
    pub notes: Vec<String>,
    /// Numerical values of the coefficients at a material, when asked for (Problem 2 with
    /// `--nu`): the parameter as text, and `(power, value to 30 digits)`.
    pub values: Option<(String, Vec<(usize, String)>)>,
}

/// The objects that need no physics (foundation issue).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SeriesObject {
    /// Z(z) = z cot z.
    Kernel,
    /// Y(xh; lambda).
    Weight,
    /// j_n(theta).
    Jacobi,
    /// Problem 1 expansions in Lambda (l/l_s, rbar - rbar_s, F_def/F_def,s, pi_j).
    Sliding(SlidingShape),
    /// Problem 2 expansions: c_n of the load [3.18] and A_n of the slope [3.16]-[3.17].
    Adhesion,
    /// Problem 1 expansions for the polynomial profile of [`Substitutions::profile`].
    PolynomialSliding,
    /// Problem 2 expansions for the even polynomial profile of [`Substitutions::profile`].
    PolynomialAdhesion,
}

/// Exact values substituted for symbols before printing.
#[derive(Debug, Clone, Default)]
pub struct Substitutions {
    /// theta, |theta| < 1/2.
    pub theta: Option<Q>,
    /// xh in [-1, 1].
    pub xh: Option<Q>,
    /// T = beta tau0 / (E* k l_s) (Problem 1).
    pub t: Option<Q>,
    /// Poisson's ratio, for numerical values of the Problem 2 coefficients.
    pub nu: Option<Q>,
    /// rbar_s, the single-punch centre over l_s (polynomial profiles, Problem 1).
    pub rbar_s: Option<Q>,
    /// The polynomial profile (the objects `PolynomialSliding`, `PolynomialAdhesion`).
    pub profile: Option<PolynomialProfile>,
}

/// Digits of the numerical values printed beside the exact Problem 2 coefficients.
pub const VALUE_DIGITS: usize = 30;

/// Applies the substitutions to a series and drops the substituted symbols from the list.
fn substitute(
    series: Series<Frac>,
    symbols: &mut Vec<Symbol>,
    subs: &Substitutions,
) -> Result<Series<Frac>, SeriesError> {
    let mut series = series;
    for (name, value) in [("theta", &subs.theta), ("xh", &subs.xh), ("T", &subs.t), ("rbar_s", &subs.rbar_s)] {
        if let Some(v) = value {
            let s = Symbol::new(name)?;
            let mapped: Option<Vec<Frac>> = series.coeffs().iter().map(|c| c.subs(s, v)).collect();
            let coeffs = mapped.ok_or_else(|| SeriesError::NotInvertible {
                operation: "substitution",
                value: format!("a denominator vanishes at {name} = {}", exact_series::q_text(v)),
            })?;
            series = Series::from_coeffs(coeffs);
            symbols.retain(|x| *x != s);
        }
    }
    Ok(series)
}

/// One part of a derived object before substitution: (object, formula, source, variable, series,
/// symbols).
type Part = (&'static str, &'static str, &'static str, &'static str, Series<Frac>, Vec<Symbol>);

/// The parts of the Problem 1 expansions `e` (either convention; docs/theory.md sections 5 and 8).
fn sliding_parts(e: &SlidingExpansion, order: usize, subs: &Substitutions) -> Result<Vec<Part>, SeriesError> {
    let theta = Symbol::new("theta")?;
    let xh = Symbol::new("xh")?;
    let t = Symbol::new("T")?;
    let frac = |s: Series<Poly>| s.map(|c| Frac::from_poly(c.clone()));
    let e = e.clone();
    if e.convention == Convention::PeriodicSurface {
        let (kappa, invpi) = (Symbol::new("kappa")?, Symbol::new("invpi")?);
        let mut v = vec![Poly::zero(); order + 1];
        for (j, pj) in e.pressure.iter().enumerate() {
            v[e.step * (j + 1)] = pj.clone();
        }
        let src =
            "docs/theory.md sections 5 and 8 (periodic convention: K = (kappa P2 - 2 beta l tau0)/L added to [2.8])";
        let syms = vec![theta, t, kappa, invpi];
        return Ok(vec![
            ("l_over_ls", "l/l_s at fixed P2, Lambda = pi l_s/L, periodic convention; kappa = tan(pi theta), invpi = 1/pi", src, "Lambda", frac(e.l_over_ls), syms.clone()),
            ("rbar_minus_rbar_s", "rbar - rbar_s, rbar = c/l, rbar_s = 2 theta - T, periodic convention", src, "Lambda", frac(e.rbar_minus_rbar_s), syms.clone()),
            ("F_def_scaled", "F_def/(pi E* k^2 l_s^3), periodic convention", src, "Lambda", frac(e.f_def_scaled), syms.clone()),
            ("pressure_pi", "p = E* k l cos(pi theta) omega(xh) (1 + sum_j Lambda^j pi_j(xh)), periodic convention; coefficient of Lambda^j is pi_j(xh)", src, "Lambda", frac(Series::from_coeffs(v)), vec![theta, t, kappa, invpi, xh]),
        ]);
    }
    let f0 = e.f_def_scaled.coeff(0).cloned().unwrap_or_else(Poly::zero);
    let xh_poly: Vec<Poly> = {
        let mut v = vec![Poly::zero(); order + 1];
        for (j, pj) in e.pressure.iter().enumerate() {
            v[e.step * (j + 1)] = pj.clone();
        }
        v
    };
    let pressure = Series::from_coeffs(xh_poly);
    let src = "docs/theory.md section 5, paper [3.7]-[3.12]";
    let mut parts = vec![
        ("l_over_ls", "l/l_s at fixed P2, Lambda = pi l_s/L; l_s = a0/sqrt(1 - 4 theta^2), a0 = sqrt(2 P2/(pi E* k)); Delta/l_s = l/l_s - 1 [3.11]", src, "Lambda", frac(e.l_over_ls), vec![theta, t]),
        ("rbar_minus_rbar_s", "rbar - rbar_s, rbar = c/l, rbar_s = 2 theta - T, T = beta tau0/(E* k l_s)", src, "Lambda", frac(e.rbar_minus_rbar_s), vec![theta, t]),
        ("F_def_scaled", "F_def/(pi E* k^2 l_s^3), F_def = int p g' dx", src, "Lambda", frac(e.f_def_scaled.clone()), vec![theta, t]),
        ("pressure_pi", "p = E* k l cos(pi theta) omega(xh) (1 + sum_j Lambda^(2j) pi_j(xh)); coefficient of Lambda^(2j) is pi_j(xh)", src, "Lambda", frac(pressure), vec![theta, t, xh]),
    ];
    // F_def/F_def,s, a rational function of theta and T (F_def,s = 0 when 8 theta/3 = T,
    // e.g. frictionless: then only F_def_scaled is defined).
    let f0_sub = substitute(Series::constant(Frac::from_poly(f0.clone()), 1), &mut vec![], subs)?;
    if !f0_sub.coeff(0).is_some_and(|c| c.is_zero()) {
        let ratio = Series::from_coeffs(
            e.f_def_scaled
                .coeffs()
                .iter()
                .map(|c| Frac::new(c.clone(), f0.clone()).expect("F_def,s is not the zero polynomial"))
                .collect(),
        );
        parts.insert(
            2,
            (
                "F_def_over_F_def_s",
                "F_def/F_def,s (deformation component of the sliding resistance)",
                src,
                "Lambda",
                ratio,
                vec![theta, t],
            ),
        );
    }
    Ok(parts)
}

/// The Problem 1 expansions in either surface convention through `order`, as derived parts
/// (`Convention::Paper` gives exactly [`SeriesObject::Sliding`]'s).
pub fn derive_sliding(
    shape: SlidingShape,
    convention: Convention,
    order: usize,
    subs: &Substitutions,
) -> Result<Vec<Derived>, SeriesError> {
    let e = sliding_expansion_with(shape, order, convention)?;
    sliding_parts(&e, order, subs)?
        .into_iter()
        .map(|(object, formula, source, variable, series, mut symbols)| {
            let series = substitute(series, &mut symbols, subs)?;
            Ok(Derived { object, formula, source, variable, series, symbols, notes: vec![], values: None })
        })
        .collect()
}

/// The symbols occurring in a series of rational functions, in name order.
fn symbols_of(series: &Series<Frac>) -> Vec<Symbol> {
    let mut v: Vec<Symbol> =
        series.coeffs().iter().flat_map(|c| c.numer().symbols().into_iter().chain(c.denom().symbols())).collect();
    v.sort();
    v.dedup();
    v
}

/// The profile's lines for the printed header.
fn profile_notes(profile: &PolynomialProfile) -> Vec<String> {
    let r = profile.reference_degree();
    let mut notes = vec![format!(
        "profile g = sum_j c_j x^j, coefficients {} (index j multiplies x^j; ? = symbolic), reference degree r = {r}",
        super::polynomial::profile::coefficients_text(profile)
    )];
    notes.extend(profile.ratio_definitions());
    notes
}

fn one_coefficient(p: &Poly) -> Series<Frac> {
    Series::from_coeffs(vec![Frac::from_poly(p.clone())])
}

/// Applies the substitutions and lists the symbols left.
fn finish(parts: Vec<Part>, notes: &[String], subs: &Substitutions) -> Result<Vec<Derived>, SeriesError> {
    parts
        .into_iter()
        .map(|(object, formula, source, variable, series, _)| {
            let series = substitute(series, &mut vec![], subs)?;
            let symbols = symbols_of(&series);
            Ok(Derived { object, formula, source, variable, series, symbols, notes: notes.to_vec(), values: None })
        })
        .collect()
}

/// The Problem 1 expansions of a polynomial punch in either surface convention through
/// `order` ([`polynomial_sliding_expansion`](super::polynomial::polynomial_sliding_expansion); docs/theory.md sections 5, 8, 9).
pub fn derive_polynomial_sliding(
    profile: &PolynomialProfile,
    convention: Convention,
    order: usize,
    subs: &Substitutions,
) -> Result<Vec<Derived>, SeriesError> {
    // theta, rbar_s, T fixed before the derivation: the same objects, much faster.
    let fixed = FixedValues { theta: subs.theta.clone(), rbar_s: subs.rbar_s.clone() };
    let e = polynomial_sliding_expansion_at(profile, order, convention, &fixed)?;
    let mut notes = profile_notes(profile);
    notes.push(
        "l_s: single-punch half-length at the same load P2; Lambda = pi l_s/L; rbar_s = c_s/l_s, the single punch's centre; T = beta tau0/(E* c_r l_s^(r-1)) = Tb_s - rho_1/2"
            .into(),
    );
    notes.push(match convention {
        Convention::Paper => "convention: paper (docs/theory.md section 3; even in Lambda)".into(),
        Convention::PeriodicSurface => {
            "convention: periodic (K of docs/theory.md section 8 added, T = Tb_s - rho_1/2 in it; kappa = tan(pi theta), invpi = 1/pi)".into()
        }
    });
    let src = "docs/theory.md sections 5, 8, 9; paper [2.13]-[2.14], [3.7]-[3.11]";
    let v = Vec::new;
    let parts: Vec<Part> = vec![
        ("Tb_single", "single punch: T + rho_1/2 = Tb_s(theta, rbar_s, rho_j), the solvability condition [2.14] at Lambda = 0 (it fixes rbar_s)", src, "Lambda", one_coefficient(&e.tbar_single), v()),
        ("m0s_single", "single punch load: P2 = pi E* c_r l_s^r (1/4 - theta^2) m0s; the coefficient is m0s", src, "Lambda", one_coefficient(&e.load_single), v()),
        ("Delta", "Delta = det of the single-punch Jacobian in (rbar, rho): every denominator below divides a power of Delta", src, "Lambda", one_coefficient(&e.jacobian), v()),
        ("l_over_ls", "l/l_s at fixed P2", src, "Lambda", e.l_over_ls, v()),
        ("rbar_minus_rbar_s", "rbar - rbar_s, rbar = c/l", src, "Lambda", e.rbar_minus_rbar_s, v()),
        ("F_def_scaled", "F_def/(pi E* c_r^2 l_s^(2r-1)), F_def = int p g' dx", src, "Lambda", e.f_def_scaled, v()),
        ("pressure_B", "p = E* c_r l^(r-1) cos(pi theta) omega(xh) B(xh); coefficient of Lambda^n is B_n(xh) (B_0: the single punch)", src, "Lambda", e.pressure, v()),
    ];
    finish(parts, &notes, subs)
}

/// The Problem 2 expansions of an even polynomial punch through `order`
/// ([`polynomial_adhesion_expansion`]; docs/theory.md sections 4, 5, 9).
pub fn derive_polynomial_adhesion(
    profile: &PolynomialProfile,
    order: usize,
    subs: &Substitutions,
) -> Result<Vec<Derived>, SeriesError> {
    let e = polynomial_adhesion_expansion(profile, order)?;
    let r = profile.reference_degree();
    let mut notes = vec![format!(
        "profile g = sum_j c_j x^j, coefficients {} (index j multiplies x^j; ? = symbolic), reference degree r = {r}",
        super::polynomial::profile::coefficients_text(profile)
    )];
    notes.extend(profile.period_ratio_definitions());
    notes.push("lambda = pi a/L, chi = pi x/L, L_pi = L/pi; B = pi/cosh(pi eps), S = S(eps)".into());
    let src = "docs/theory.md sections 4, 5, 9; paper [3.13]-[3.18]";
    let v = Vec::new;
    let parts: Vec<Part> = vec![
        (
            "load_P_over_pi",
            "P2 = E* c_r (L/pi)^r P(lambda), P(lambda)/pi = sum_j p_j lambda^(2j+2)/(2j+2) [3.18]",
            src,
            "lambda",
            e.load,
            v(),
        ),
        (
            "slope_A",
            "A_n: psi(x) = sum_n A_n |x|^n [3.16]; coefficient of chi^n is A_n/(c_r (pi/L)^(n+1-r)); even A_n vanish",
            src,
            "chi",
            e.slope,
            v(),
        ),
    ];
    finish(parts, &notes, subs)
}

fn missing_profile() -> SeriesError {
    SeriesError::NotInvertible {
        operation: "polynomial series",
        value: "no profile given (--coefficients or --degree)".into(),
    }
}

impl SeriesObject {
    /// [`SeriesObject::derive`] in the surface `convention` (docs/theory.md section 8): the
    /// Problem 1 expansions (`sliding`, the polynomial punch's) depend on it, the other objects do
    /// not. What `series OBJECT --convention C` and `api::derive` print.
    pub(crate) fn derive_in(
        self,
        convention: Convention,
        order: usize,
        subs: &Substitutions,
    ) -> Result<Vec<Derived>, SeriesError> {
        match self {
            SeriesObject::Sliding(shape) => derive_sliding(shape, convention, order, subs),
            SeriesObject::PolynomialSliding => {
                let profile = subs.profile.as_ref().ok_or_else(missing_profile)?;
                derive_polynomial_sliding(profile, convention, order, subs)
            }
            other => other.derive(order, subs),
        }
    }

    /// Derives the object through `order` (docs/theory.md section 5 order convention): one part for
    /// the foundation objects, several for the Problem 1 expansions.
    pub fn derive(self, order: usize, subs: &Substitutions) -> Result<Vec<Derived>, SeriesError> {
        match self {
            SeriesObject::PolynomialSliding => {
                let profile = subs.profile.as_ref().ok_or_else(missing_profile)?;
                return derive_polynomial_sliding(profile, Convention::Paper, order, subs);
            }
            SeriesObject::PolynomialAdhesion => {
                let profile = subs.profile.as_ref().ok_or_else(missing_profile)?;
                return derive_polynomial_adhesion(profile, order, subs);
            }
            _ => {}
        }
        let theta = Symbol::new("theta")?;
        let xh = Symbol::new("xh")?;
        let frac = |s: Series<Poly>| s.map(|c| Frac::from_poly(c.clone()));
        let parts: Vec<(&'static str, &'static str, &'static str, &'static str, Series<Frac>, Vec<Symbol>)> = match self {
            SeriesObject::Kernel => vec![(
                "kernel",
                "Z(z) = z cot z; (pi/L) cot(pi (x - xi)/L) = Z(lambda (xh - xih)) / (x - xi)",
                "docs/theory.md section 5, paper [3.2]",
                "z",
                frac(kernel_series(order).map(Poly::from_q)),
                vec![],
            )],
            SeriesObject::Weight => vec![(
                "weight",
                "Y(xh; lambda) = sinc(lambda (1 + xh))^(1/2 + theta) sinc(lambda (1 - xh))^(1/2 - theta)",
                "docs/theory.md section 5, paper [2.29], [3.1]",
                "lambda",
                frac(weight_series(order)?),
                vec![theta, xh],
            )],
            SeriesObject::Jacobi => vec![(
                "jacobi",
                "j_n(theta): J_n = int_{-1}^{1} y^n dy / omega(y) = (pi / cos(pi theta)) j_n(theta); coefficient n is j_n",
                "docs/theory.md section 5, paper [3.5]",
                "n",
                frac(jacobi_moments(order)?),
                vec![theta],
            )],
            SeriesObject::Adhesion => {
                let e = crate::asymptotics::adhesion::adhesion_expansion_with(order, false)?;
                let (eps, b, sy) = (Symbol::new("eps")?, Symbol::new("B")?, Symbol::new("S")?);
                let src = "docs/theory.md section 5, paper [3.13]-[3.19]";
                vec![
                    (
                        "C_P_over_pi",
                        "C_P/pi, P2 = C_P E* k a^2 (1 + c_2 lambda^2 + ...) for the single punch; C_P = pi/(2 (1 - 2 eps S))",
                        src,
                        "lambda",
                        Series::from_coeffs(vec![e.load_constant.clone()]),
                        vec![eps, sy],
                    ),
                    (
                        "load_c",
                        "c_n: P2(a) = C_P E* k a^2 (1 + c_2 lambda^2 + c_4 lambda^4 + ...), lambda = pi a/L [3.18]",
                        src,
                        "lambda",
                        e.load.clone(),
                        vec![eps, sy],
                    ),
                    (
                        "slope_A",
                        "A_n: psi(x) = sum_n A_n |x|^n [3.16]; coefficient of chi^n is A_n/(k (pi/L)^(n-1)), chi = pi x/L; even A_n vanish",
                        src,
                        "chi",
                        e.slope.clone(),
                        vec![eps, b, sy],
                    ),
                ]
            }
            SeriesObject::Sliding(shape) => sliding_parts(&sliding_expansion(shape, order)?, order, subs)?,
            SeriesObject::PolynomialSliding | SeriesObject::PolynomialAdhesion => unreachable!("handled above"),
        };
        let mut out: Vec<Derived> = parts
            .into_iter()
            .map(|(object, formula, source, variable, series, mut symbols)| {
                let series = substitute(series, &mut symbols, subs)?;
                Ok(Derived { object, formula, source, variable, series, symbols, notes: vec![], values: None })
            })
            .collect::<Result<_, SeriesError>>()?;
        if let (SeriesObject::Adhesion, Some(nu)) = (self, &subs.nu) {
            add_values(&mut out, nu)?;
        }
        Ok(out)
    }
}

/// The 30-digit values of the Problem 2 coefficients at Poisson's ratio `nu` (eps, B, S evaluated
/// in MPFR; S by its accelerated sum).
fn add_values(parts: &mut [Derived], nu: &Q) -> Result<(), SeriesError> {
    let prec = (VALUE_DIGITS as f64 * std::f64::consts::LOG2_10).ceil() as u32 + 16;
    let constants = crate::asymptotics::adhesion::series_constants(nu, prec)
        .map_err(|e| SeriesError::NotInvertible { operation: "evaluation at nu", value: e.to_string() })?;
    let values = crate::asymptotics::adhesion::symbol_values(&constants);
    let w = constants.prec;
    for d in parts.iter_mut() {
        let mut list = Vec::new();
        for (k, c) in d.series.coeffs().iter().enumerate() {
            if c.is_zero() {
                continue;
            }
            let n = crate::numerics::evaluate::poly_mpfr(c.numer(), &values, w);
            let m = crate::numerics::evaluate::poly_mpfr(c.denom(), &values, w);
            let (Ok(n), Ok(m)) = (n, m) else {
                return Err(SeriesError::NotInvertible { operation: "evaluation at nu", value: c.text() });
            };
            let v = rug::Float::with_val(prec, n / m);
            list.push((k, v.to_string_radix(10, Some(VALUE_DIGITS))));
        }
        d.values = Some((exact_series::q_text(nu), list));
    }
    Ok(())
}

impl Derived {
    /// Plain text: a header, then one line per non-zero coefficient, then the series.
    pub fn text(&self) -> String {
        let n = self.series.order().unwrap_or(0);
        let range = if self.object == "jacobi" {
            format!("index n, j_0 .. j_{n}")
        } else {
            format!("variable {v}, order {n} (every term through {v}^{n})", v = self.variable)
        };
        let mut s = format!("object: {}\nformula: {}\nsource: {}\n", self.object, self.formula, self.source);
        for n in &self.notes {
            s.push_str(&format!("note: {n}\n"));
        }
        s.push_str(&format!("{range}\n"));
        for (k, c) in self.series.coeffs().iter().enumerate() {
            if !c.is_zero() {
                let label = if self.object == "jacobi" { format!("j_{k}") } else { format!("[{}^{k}]", self.variable) };
                s.push_str(&format!("{label} {}\n", c.text()));
            }
        }
        if let Some((nu, vals)) = &self.values {
            s.push_str(&format!("values at nu = {nu} ({VALUE_DIGITS} digits):\n"));
            for (k, v) in vals {
                s.push_str(&format!("[{}^{k}] {v}\n", self.variable));
            }
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Q {
        Q::new(n.into(), d.into())
    }

    #[test]
    fn kernel_text_lists_bernoulli_coefficients() {
        let d = SeriesObject::Kernel.derive(4, &Substitutions::default()).unwrap().remove(0);
        assert!(d.text().contains("[z^2] -1/3\n[z^4] -1/45\n"), "{}", d.text());
    }

    #[test]
    fn weight_substitution_is_exact() {
        let subs = Substitutions { theta: Some(q(1, 10)), xh: Some(q(0, 1)), ..Substitutions::default() };
        let d = SeriesObject::Weight.derive(2, &subs).unwrap().remove(0);
        // At xh = 0: Y = sinc(lambda) = 1 - lambda^2/6 + ..., independent of theta.
        assert_eq!(d.series.coeff(2).unwrap().as_q(), Some(q(-1, 6)));
        assert!(d.symbols.is_empty());
    }
}

impl SeriesObject {
    /// CLI name.
    pub fn name(self) -> &'static str {
        match self {
            SeriesObject::Kernel => "kernel",
            SeriesObject::Weight => "weight",
            SeriesObject::Jacobi => "jacobi",
            SeriesObject::Sliding(_) => "sliding",
            SeriesObject::Adhesion | SeriesObject::PolynomialAdhesion => "adhesion",
            SeriesObject::PolynomialSliding => "sliding",
        }
    }
}
