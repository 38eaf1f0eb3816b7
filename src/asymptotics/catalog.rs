//! The catalogue of derived series objects that the CLI (`periodic-contact series OBJECT`) and
//! the report print: each with its name, formula, equation number and expansion variable.

use super::{jacobi_moments::jacobi_moments, kernel::kernel_series, weight::weight_series};
use exact_series::{Poly, Ring, Series, SeriesError, Symbol, Q};

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
    /// The exact coefficients, possibly with symbols substituted.
    pub series: Series<Poly>,
    /// Symbols that may occur in the coefficients.
    pub symbols: Vec<Symbol>,
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
}

/// Exact values substituted for symbols before printing.
#[derive(Debug, Clone, Default)]
pub struct Substitutions {
    /// theta, |theta| < 1/2.
    pub theta: Option<Q>,
    /// xh in [-1, 1].
    pub xh: Option<Q>,
}

impl SeriesObject {
    /// Derives the object through `order` (THEORY.md section 5 order convention).
    pub fn derive(self, order: usize, subs: &Substitutions) -> Result<Derived, SeriesError> {
        let theta = Symbol::new("theta")?;
        let xh = Symbol::new("xh")?;
        let (object, formula, source, variable, series, mut symbols) = match self {
            SeriesObject::Kernel => (
                "kernel",
                "Z(z) = z cot z; (pi/L) cot(pi (x - xi)/L) = Z(lambda (xh - xih)) / (x - xi)",
                "THEORY.md section 5, paper [3.2]",
                "z",
                kernel_series(order).map(Poly::from_q),
                vec![],
            ),
            SeriesObject::Weight => (
                "weight",
                "Y(xh; lambda) = sinc(lambda (1 + xh))^(1/2 + theta) sinc(lambda (1 - xh))^(1/2 - theta)",
                "THEORY.md section 5, paper [2.29], [3.1]",
                "lambda",
                weight_series(order)?,
                vec![theta, xh],
            ),
            SeriesObject::Jacobi => (
                "jacobi",
                "j_n(theta): J_n = int_{-1}^{1} y^n dy / omega(y) = (pi / cos(pi theta)) j_n(theta); coefficient n is j_n",
                "THEORY.md section 5, paper [3.5]",
                "n",
                jacobi_moments(order)?,
                vec![theta],
            ),
        };
        let mut series = series;
        if let Some(t) = &subs.theta {
            series = series.map(|c| c.subs(theta, t));
            symbols.retain(|s| *s != theta);
        }
        if let Some(x) = &subs.xh {
            series = series.map(|c| c.subs(xh, x));
            symbols.retain(|s| *s != xh);
        }
        Ok(Derived {
            object,
            formula,
            source,
            variable,
            series,
            symbols,
        })
    }
}

impl Derived {
    /// Plain text: a header, then one line per non-zero coefficient, then the series.
    pub fn text(&self) -> String {
        let n = self.series.order().unwrap_or(0);
        let range = if self.object == "jacobi" {
            format!("index n, j_0 .. j_{n}")
        } else {
            format!(
                "variable {v}, order {n} (every term through {v}^{n})",
                v = self.variable
            )
        };
        let mut s = format!(
            "object: {}\nformula: {}\nsource: {}\n{range}\n",
            self.object, self.formula, self.source
        );
        for (k, c) in self.series.coeffs().iter().enumerate() {
            if !c.is_zero() {
                let label = if self.object == "jacobi" {
                    format!("j_{k}")
                } else {
                    format!("[{}^{k}]", self.variable)
                };
                s.push_str(&format!("{label} {}\n", c.text()));
            }
        }
        s
    }

    /// LaTeX: one `align*` line per non-zero coefficient.
    pub fn latex(&self) -> String {
        let mut s = format!(
            "% {}: {} ({})\n\\begin{{align*}}\n",
            self.object, self.formula, self.source
        );
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
        self.series
            .to_json(self.object, self.variable, &self.symbols)
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
        let d = SeriesObject::Kernel
            .derive(4, &Substitutions::default())
            .unwrap();
        assert!(
            d.text().contains("[z^2] -1/3\n[z^4] -1/45\n"),
            "{}",
            d.text()
        );
    }

    #[test]
    fn weight_substitution_is_exact() {
        let subs = Substitutions {
            theta: Some(q(1, 10)),
            xh: Some(q(0, 1)),
        };
        let d = SeriesObject::Weight.derive(2, &subs).unwrap();
        // At xh = 0: Y = sinc(lambda) = 1 - lambda^2/6 + ..., independent of theta.
        assert_eq!(d.series.coeff(2).unwrap().as_q(), Some(q(-1, 6)));
        assert!(d.symbols.is_empty());
    }
}
