//! The values of det M along a scan grid, computed as the scan reaches them: the f64 screen
//! ([`super::screen`]) where its bound decides a question, MPFR where it does not.
//!
//! The scan asks two questions: the sign of det M at a grid point, and whether |det M| at one point
//! is below |det M| at another (as `to_f64` of the MPFR values compares them). A screened answer is
//! given only where the bound proves it equal to the answer from the MPFR values, so the scan
//! decides as the all-MPFR scan did, on fewer MPFR evaluations (the MPFR determinant costs three
//! transcendental calls per node; the screen two f64 ones). Without a symbol (the f64 mode check,
//! [`super::quick`]) a question the screen leaves open has no answer ([`first_change`] gives None).

use super::screen::{Approx, Screen};
use super::Symbol;
use rug::Float;

/// A scan over `grid` (lazily evaluated).
struct Scan<'a> {
    sym: Option<&'a Symbol>,
    screen: Option<&'a Screen>,
    grid: &'a [f64],
    screened: Vec<Option<Approx>>,
    exact: Vec<Option<Float>>,
}

impl<'a> Scan<'a> {
    fn screened(&mut self, k: usize) -> Approx {
        let (screen, mu) = (self.screen, self.grid[k]);
        *self.screened[k].get_or_insert_with(|| match screen {
            Some(s) => s.det(mu),
            None => Approx { value: 0.0, bound: f64::INFINITY },
        })
    }

    /// det M at grid point `k` in MPFR (as the all-MPFR scan computed it); None without a symbol.
    fn exact(&mut self, k: usize) -> Option<Float> {
        let (sym, mu) = (self.sym?, self.grid[k]);
        Some(self.exact[k].get_or_insert_with(|| sym.det(&Float::with_val(sym.prec, mu))).clone())
    }

    /// The MPFR value's `is_sign_negative` at point `k`.
    fn negative(&mut self, k: usize) -> Option<bool> {
        match self.screened(k).negative() {
            Some(n) => Some(n),
            None => Some(self.exact(k)?.is_sign_negative()),
        }
    }

    /// `to_f64().abs()` of the MPFR value at `i` below that at `j`.
    fn abs_less(&mut self, i: usize, j: usize) -> Option<bool> {
        let (a, b) = (self.screened(i), self.screened(j));
        // Where the MPFR values' to_f64 can lie: within 2 bounds of the screened value (the exact
        // value within one, the MPFR value within one more), widened by the final rounding.
        let range = |v: Approx| {
            let r = 2.0 * v.bound + 4.0 * f64::EPSILON * v.value.abs();
            (v.value.abs() - r, v.value.abs() + r)
        };
        let ((alo, ahi), (blo, bhi)) = (range(a), range(b));
        if ahi < blo {
            return Some(true);
        }
        if alo > bhi {
            return Some(false);
        }
        let abs = |v: Float| v.to_f64().abs();
        Some(abs(self.exact(i)?) < abs(self.exact(j)?))
    }
}

/// Where the scan of [`super::Symbol::first_zero`] over `grid` finds det M's first sign change:
/// Some(Some((mu_lo, mu_hi))) the grid step where it changes, Some(None) no change (the finer
/// rescans at local minima of |det M| included, `depth` levels deep), None where a question the
/// screen leaves open has no MPFR answer (`sym` None). With `sym`, the decisions of the all-MPFR
/// scan of that symbol.
pub(super) fn first_change(
    sym: Option<&Symbol>,
    screen: Option<&Screen>,
    grid: &[f64],
    depth: u32,
) -> Option<Option<(f64, f64)>> {
    let mut scan = Scan { sym, screen, grid, screened: vec![None; grid.len()], exact: vec![None; grid.len()] };
    for k in 1..grid.len() {
        if scan.negative(k - 1)? != scan.negative(k)? {
            return Some(Some((grid[k - 1], grid[k])));
        }
        // |det| smallest at grid[k] among its neighbours: a close pair may hide there.
        if depth > 0 && k + 1 < grid.len() && scan.abs_less(k, k - 1)? && scan.abs_less(k, k + 1)? {
            let (x0, x1) = (grid[k - 1], grid[k + 1]);
            let fine: Vec<f64> = (0..=128).map(|j| x0 + (x1 - x0) * j as f64 / 128.0).collect();
            if let Some(change) = first_change(sym, screen, &fine, depth - 1)? {
                return Some(Some(change));
            }
        }
    }
    Some(None)
}
