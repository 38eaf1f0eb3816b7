//! The values of det M along a scan grid, computed as the scan reaches them: the f64 screen
//! ([`super::screen`]) where its bound decides a question, MPFR where it does not.
//!
//! The scan asks two questions: the sign of det M at a grid point, and whether |det M| at one point
//! is below |det M| at another (as `to_f64` of the MPFR values compares them). A screened answer is
//! given only where the bound proves it equal to the answer from the MPFR values, so the scan
//! decides as the all-MPFR scan did, on fewer MPFR evaluations (the MPFR determinant costs three
//! transcendental calls per node; the screen two f64 ones).

use super::screen::Approx;
use super::Symbol;
use rug::Float;

/// A scan over `grid` (lazily evaluated).
pub(super) struct Scan<'a> {
    sym: &'a Symbol,
    grid: &'a [f64],
    screened: Vec<Option<Approx>>,
    exact: Vec<Option<Float>>,
}

impl<'a> Scan<'a> {
    pub(super) fn new(sym: &'a Symbol, grid: &'a [f64]) -> Self {
        Scan { sym, grid, screened: vec![None; grid.len()], exact: vec![None; grid.len()] }
    }

    fn screened(&mut self, k: usize) -> Approx {
        let (sym, mu) = (self.sym, self.grid[k]);
        *self.screened[k].get_or_insert_with(|| match &sym.screen {
            Some(s) => s.det(mu),
            None => Approx { value: 0.0, bound: f64::INFINITY },
        })
    }

    /// det M at grid point `k` in MPFR (as the all-MPFR scan computed it).
    pub(super) fn exact(&mut self, k: usize) -> Float {
        let (sym, mu) = (self.sym, self.grid[k]);
        self.exact[k].get_or_insert_with(|| sym.det(&Float::with_val(sym.prec, mu))).clone()
    }

    /// The MPFR value's `is_sign_negative` at point `k`.
    pub(super) fn negative(&mut self, k: usize) -> bool {
        match self.screened(k).negative() {
            Some(n) => n,
            None => self.exact(k).is_sign_negative(),
        }
    }

    /// `to_f64().abs()` of the MPFR value at `i` below that at `j`.
    pub(super) fn abs_less(&mut self, i: usize, j: usize) -> bool {
        let (a, b) = (self.screened(i), self.screened(j));
        // Where the MPFR values' to_f64 can lie: within 2 bounds of the screened value (the exact
        // value within one, the MPFR value within one more), widened by the final rounding.
        let range = |v: Approx| {
            let r = 2.0 * v.bound + 4.0 * f64::EPSILON * v.value.abs();
            (v.value.abs() - r, v.value.abs() + r)
        };
        let ((alo, ahi), (blo, bhi)) = (range(a), range(b));
        if ahi < blo {
            return true;
        }
        if alo > bhi {
            return false;
        }
        let abs = |v: Float| v.to_f64().abs();
        abs(self.exact(i)) < abs(self.exact(j))
    }
}
