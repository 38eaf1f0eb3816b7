//! The catalogue of derived series objects that the CLI (`periodic-contact series OBJECT`) and
//! the report print: each with its name, formula, equation number and expansion variable.

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
    /// Where it comes from (THEORY.md section, paper equation).
    pub source: &'static str,
    /// Expansion variable (or index, for sequences).
    pub variable: &'static str,
    /// The exact coefficients (polynomials or rational functions), symbols possibly substituted.
    pub series: Series<Frac>,
    /// Symbols that may occur in the coefficients.
    pub symbols: Vec<Symbol>,
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
    for (name, value) in [("theta", &subs.theta), ("xh", &subs.xh), ("T", &subs.t)] {
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

/// The parts of the Problem 1 expansions `e` (either convention; THEORY.md sections 5 and 8).
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
        let src = "THEORY.md sections 5 and 8 (periodic convention: K = (kappa P2 - 2 beta l tau0)/L added to [2.8])";
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
    let src = "THEORY.md section 5, paper [3.7]-[3.12]";
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
            Ok(Derived { object, formula, source, variable, series, symbols, values: None })
        })
        .collect()
}

impl SeriesObject {
    /// Derives the object through `order` (THEORY.md section 5 order convention): one part for
    /// the foundation objects, several for the Problem 1 expansions.
    pub fn derive(self, order: usize, subs: &Substitutions) -> Result<Vec<Derived>, SeriesError> {
        let theta = Symbol::new("theta")?;
        let xh = Symbol::new("xh")?;
        let frac = |s: Series<Poly>| s.map(|c| Frac::from_poly(c.clone()));
        let parts: Vec<(&'static str, &'static str, &'static str, &'static str, Series<Frac>, Vec<Symbol>)> = match self {
            SeriesObject::Kernel => vec![(
                "kernel",
                "Z(z) = z cot z; (pi/L) cot(pi (x - xi)/L) = Z(lambda (xh - xih)) / (x - xi)",
                "THEORY.md section 5, paper [3.2]",
                "z",
                frac(kernel_series(order).map(Poly::from_q)),
                vec![],
            )],
            SeriesObject::Weight => vec![(
                "weight",
                "Y(xh; lambda) = sinc(lambda (1 + xh))^(1/2 + theta) sinc(lambda (1 - xh))^(1/2 - theta)",
                "THEORY.md section 5, paper [2.29], [3.1]",
                "lambda",
                frac(weight_series(order)?),
                vec![theta, xh],
            )],
            SeriesObject::Jacobi => vec![(
                "jacobi",
                "j_n(theta): J_n = int_{-1}^{1} y^n dy / omega(y) = (pi / cos(pi theta)) j_n(theta); coefficient n is j_n",
                "THEORY.md section 5, paper [3.5]",
                "n",
                frac(jacobi_moments(order)?),
                vec![theta],
            )],
            SeriesObject::Adhesion => {
                let e = crate::asymptotics::adhesion::adhesion_expansion_with(order, false)?;
                let (eps, b, sy) = (Symbol::new("eps")?, Symbol::new("B")?, Symbol::new("S")?);
                let src = "THEORY.md section 5, paper [3.13]-[3.19]";
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
        };
        let mut out: Vec<Derived> = parts
            .into_iter()
            .map(|(object, formula, source, variable, series, mut symbols)| {
                let series = substitute(series, &mut symbols, subs)?;
                Ok(Derived { object, formula, source, variable, series, symbols, values: None })
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
        let mut s = format!("object: {}\nformula: {}\nsource: {}\n{range}\n", self.object, self.formula, self.source);
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

    /// LaTeX: one `align*` line per non-zero coefficient.
    pub fn latex(&self) -> String {
        let mut s = format!("% {}: {} ({})\n\\begin{{align*}}\n", self.object, self.formula, self.source);
        let v = match self.variable {
            "lambda" => "\\lambda",
            other => other,
        };
        let lines: Vec<String> = self
            .series
            .coeffs()
            .iter()
            .enumerate()
            .filter(|(_, c)| !c.is_zero())
            .map(|(k, c)| match self.object {
                "jacobi" => format!("j_{{{k}}} &= {}", c.latex()),
                _ => format!("[{v}^{{{k}}}] &= {}", c.latex()),
            })
            .collect();
        s.push_str(&lines.join(" \\\\\n"));
        s.push_str("\n\\end{align*}\n");
        s
    }

    /// JSON in the layout `{"object", "variable", "order", "symbols", "coefficients"}`.
    pub fn json(&self) -> serde_json::Value {
        let mut v = self.series.to_json(self.object, self.variable, &self.symbols);
        if let Some((nu, vals)) = &self.values {
            v["nu"] = serde_json::json!(nu);
            v["values"] = serde_json::Value::Array(
                vals.iter().map(|(k, x)| serde_json::json!({"power": k, "value": x})).collect(),
            );
        }
        v
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
        let subs = Substitutions { theta: Some(q(1, 10)), xh: Some(q(0, 1)), t: None, nu: None };
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
            SeriesObject::Adhesion => "adhesion",
        }
    }
}
