//! Named symbols (theta, T, xh, eps, B, S, ...), interned once per process.
//!
//! A [`Symbol`] compares by its name, so the canonical order of monomials (and hence every printed
//! form) does not depend on the order in which symbols were first used.

use crate::SeriesError;
use std::collections::HashSet;
use std::fmt;
use std::sync::{Mutex, OnceLock};

/// An interned symbol name. Copy, ordered by name.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Symbol(&'static str);

fn interner() -> &'static Mutex<HashSet<&'static str>> {
    static INTERNER: OnceLock<Mutex<HashSet<&'static str>>> = OnceLock::new();
    INTERNER.get_or_init(|| Mutex::new(HashSet::new()))
}

impl Symbol {
    /// Interns `name`. The name must be an identifier: a letter or `_` first, then letters,
    /// digits or `_`.
    ///
    /// ```
    /// use exact_series::Symbol;
    /// let theta = Symbol::new("theta").unwrap();
    /// assert_eq!(theta.name(), "theta");
    /// assert!(Symbol::new("2x").is_err());
    /// ```
    pub fn new(name: &str) -> Result<Symbol, SeriesError> {
        let mut chars = name.chars();
        let ok = matches!(chars.next(), Some(c) if c.is_ascii_alphabetic() || c == '_')
            && chars.all(|c| c.is_ascii_alphanumeric() || c == '_');
        if !ok {
            return Err(SeriesError::InvalidSymbol { name: name.to_string() });
        }
        let mut set = interner().lock().unwrap_or_else(|e| e.into_inner());
        if let Some(s) = set.get(name) {
            return Ok(Symbol(s));
        }
        let leaked: &'static str = Box::leak(name.to_string().into_boxed_str());
        set.insert(leaked);
        Ok(Symbol(leaked))
    }

    /// The symbol's name.
    pub fn name(self) -> &'static str {
        self.0
    }

    /// The LaTeX form: Greek names get a backslash (`theta` -> `\theta`, `eps` -> `\varepsilon`),
    /// `xh` is `\hat{x}`; other names are printed as they are (multi-letter names in `\mathrm`).
    pub fn latex(self) -> String {
        const GREEK: [&str; 20] = [
            "alpha", "beta", "gamma", "delta", "zeta", "eta", "theta", "iota", "kappa", "lambda", "mu", "nu", "xi",
            "pi", "rho", "sigma", "tau", "phi", "chi", "psi",
        ];
        match self.0 {
            "eps" | "epsilon" => r"\varepsilon".to_string(),
            "xh" => r"\hat{x}".to_string(),
            "xih" => r"\hat{\xi}".to_string(),
            "Lambda" => r"\Lambda".to_string(),
            n if GREEK.contains(&n) => format!("\\{n}"),
            n if n.len() == 1 => n.to_string(),
            n => format!("\\mathrm{{{n}}}"),
        }
    }
}

impl fmt::Debug for Symbol {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.0)
    }
}

impl fmt::Display for Symbol {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.0)
    }
}
