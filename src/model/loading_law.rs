//! Problem 2 under a loading law P1 = N(P2) (docs/theory.md section 10; issue 12): the statement.
//! The contact [-a, b] grows at both ends; P1 and P2 grow together along N.
//!
//! Solved so far (the solver refuses the rest by name, [`LoadingLawProblem::new`]): a periodic row
//! of parabolic punches, both surface conventions, the linear law N = n P2 or a polynomial law
//! N(P2) = sum_j c_j P2^j (numpy order, c_0 = 0, N' >= 0 checked on the loading path by the
//! solver), given the final half-length l = (a + b)/2 or the final load P2.

use super::{readable, Convention, Exact, Material, ModelError, OnPunchRow, Period, PunchRow, PunchShape};
use num_traits::{Signed, Zero};

/// The loading law P1 = N(P2).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum LoadingLaw {
    /// P1 = n P2 (scene key `tangential_ratio`).
    Linear(Exact),
    /// P1 = sum_j c_j P2^j, c_0 = 0 (scene key `loading_law`, numpy order).
    Polynomial(Vec<Exact>),
}

impl LoadingLaw {
    /// N'(P2) coefficients (numpy order): the linear law's \[n\].
    pub(crate) fn derivative(&self) -> Vec<Exact> {
        match self {
            LoadingLaw::Linear(n) => vec![n.clone()],
            LoadingLaw::Polynomial(c) => {
                c.iter().enumerate().skip(1).map(|(j, cj)| cj * Exact::from_integer((j as i64).into())).collect()
            }
        }
    }
    /// n = N'(0), the ratio the loading starts with (0 for a law without a linear term).
    pub fn initial_ratio(&self) -> Exact {
        self.derivative().into_iter().next().unwrap_or_else(|| Exact::from_integer(0.into()))
    }
    /// The scene key that gives this law (for messages): `tangential_ratio` or `loading_law`.
    pub fn key(&self) -> &'static str {
        match self {
            LoadingLaw::Linear(_) => "tangential_ratio",
            LoadingLaw::Polynomial(_) => "loading_law",
        }
    }
    /// The law as the scene writes it, readable: "1/5" or "[0, 1/5, 1/100]".
    pub fn text(&self) -> String {
        match self {
            LoadingLaw::Linear(n) => readable(n),
            LoadingLaw::Polynomial(c) => format!("[{}]", c.iter().map(readable).collect::<Vec<_>>().join(", ")),
        }
    }
    /// Whether N is linear (n constant along the loading).
    pub fn ratio(&self) -> Option<Exact> {
        match self {
            LoadingLaw::Linear(n) => Some(n.clone()),
            LoadingLaw::Polynomial(c) if c.iter().skip(2).all(Zero::is_zero) => {
                Some(c.get(1).cloned().unwrap_or_else(Exact::zero))
            }
            LoadingLaw::Polynomial(_) => None,
        }
    }
}

/// The size given: the final half-length or the final normal load.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum LawSize {
    /// l = (a + b)/2 (scene key `half_length`), 0 < 2 l < L.
    HalfLength(Exact),
    /// P2 > 0 (scene key `normal_load`).
    NormalLoad(Exact),
}

/// A validated loading-law problem.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct LoadingLawProblem {
    row: PunchRow,
    /// The row's parabola's k (kept apart: the shape is the parabola by construction).
    k: Exact,
    law: LoadingLaw,
    size: LawSize,
    convention: Convention,
}

impl LoadingLawProblem {
    /// Validates: a parabolic punch (others refused naming `shape`), N(0) = 0 (c_0 = 0), at least
    /// one coefficient, sizes > 0 and 2 l < L for a periodic row (the single punch, period
    /// `inf`, has no upper bound).
    pub fn new(
        material: Material,
        period: Period,
        shape: PunchShape,
        law: LoadingLaw,
        size: LawSize,
        convention: Convention,
    ) -> Result<Self, ModelError> {
        let k = match &shape {
            PunchShape::Parabolic { k } => k.clone(),
            other => {
                return Err(ModelError::new(
                    "shape",
                    other.name(),
                    "\"parabolic\": the loading-law problem is solved for the parabola so far",
                ))
            }
        };
        let row = PunchRow::new(material, period, shape)?;
        let period = row.period();
        if let LoadingLaw::Polynomial(c) = &law {
            if c.is_empty() {
                return Err(ModelError::new("loading_law", "[]", "at least [\"0\", n]: N(P2) = sum_j c_j P2^j"));
            }
            if !c[0].is_zero() {
                return Err(ModelError::new(
                    "loading_law",
                    law.text(),
                    format!("N(0) = 0, i.e. coefficients[0] = 0 (got {})", readable(&c[0])),
                ));
            }
        }
        match &size {
            LawSize::HalfLength(l) => {
                let too_big = match period {
                    Period::Finite(big_l) => (l + l) >= *big_l,
                    Period::Infinite => false,
                };
                if !l.is_positive() || too_big {
                    let range = match period {
                        Period::Finite(big_l) => format!("0 < 2 l < L = {}", readable(big_l)),
                        Period::Infinite => "l > 0".into(),
                    };
                    return Err(ModelError::new("half_length", readable(l), range));
                }
            }
            LawSize::NormalLoad(p) => {
                if !p.is_positive() {
                    return Err(ModelError::new("normal_load", readable(p), "must be > 0"));
                }
            }
        }
        Ok(LoadingLawProblem { row, k, law, size, convention })
    }

    /// Curvature k of g = k x^2 (the row's parabola).
    pub fn k(&self) -> &Exact {
        &self.k
    }
    /// The law.
    pub fn law(&self) -> &LoadingLaw {
        &self.law
    }
    /// The size given.
    pub fn size(&self) -> &LawSize {
        &self.size
    }
    /// Surface convention.
    pub fn convention(&self) -> Convention {
        self.convention
    }
}

/// The punch row: material, period and the parabola g = k x^2.
impl OnPunchRow for LoadingLawProblem {
    fn row(&self) -> &PunchRow {
        &self.row
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Exact {
        Exact::new(n.into(), d.into())
    }

    #[test]
    fn loading_law_problem_validation() {
        let m = Material::from_contact_modulus(q(3, 10), q(1, 1)).unwrap();
        let l = Period::Finite(q(1, 1));
        let k = PunchShape::Parabolic { k: q(1, 1) };
        let lin = LoadingLaw::Linear(q(1, 5));
        let ok = LoadingLawProblem::new(
            m.clone(),
            l.clone(),
            k.clone(),
            lin.clone(),
            LawSize::HalfLength(q(1, 6)),
            Convention::Paper,
        );
        assert!(ok.is_ok());
        let single = LoadingLawProblem::new(
            m.clone(),
            Period::Infinite,
            k.clone(),
            lin.clone(),
            LawSize::HalfLength(q(7, 3)),
            Convention::Paper,
        );
        assert!(single.is_ok(), "{single:?}");
        let e = LoadingLawProblem::new(
            m.clone(),
            Period::Infinite,
            k.clone(),
            lin.clone(),
            LawSize::HalfLength(q(0, 1)),
            Convention::Paper,
        )
        .unwrap_err();
        assert_eq!((e.parameter.as_str(), e.expected.as_str()), ("half_length", "l > 0"));
        let e = LoadingLawProblem::new(
            m.clone(),
            l.clone(),
            k.clone(),
            lin.clone(),
            LawSize::HalfLength(q(1, 2)),
            Convention::Paper,
        )
        .unwrap_err();
        assert_eq!((e.parameter.as_str(), e.value.as_str()), ("half_length", "1/2"));
        let bad = LoadingLaw::Polynomial(vec![q(1, 100), q(1, 5)]);
        let e = LoadingLawProblem::new(
            m.clone(),
            l.clone(),
            k.clone(),
            bad,
            LawSize::NormalLoad(q(1, 10)),
            Convention::Paper,
        )
        .unwrap_err();
        assert_eq!(e.parameter, "loading_law");
        assert!(e.expected.contains("N(0) = 0"), "{e}");
        let circle = PunchShape::Circular { radius: q(1, 2) };
        let e = LoadingLawProblem::new(m, l, circle, lin, LawSize::HalfLength(q(1, 6)), Convention::Paper).unwrap_err();
        assert_eq!(e.parameter, "shape");
        assert_eq!(LoadingLaw::Polynomial(vec![q(0, 1), q(1, 5), q(1, 100)]).derivative(), vec![q(1, 5), q(1, 50)]);
        assert_eq!(LoadingLaw::Polynomial(vec![q(0, 1), q(1, 5)]).ratio(), Some(q(1, 5)));
    }
}
