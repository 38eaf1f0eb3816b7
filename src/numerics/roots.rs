//! Root finding in `f64`: Brent's method on a sign-changing bracket, the root finder of the
//! project's f64 stages (the f64 collocation and the MPFR solvers' low-precision locate stage);
//! and [`increasing_root`], Newton's method safeguarded by bisection for an increasing function
//! known with its slope whose evaluation may fail toward the bracket's upper end (Problem 2's
//! half-width for a given load, both f64 methods).

/// Why a root was not found.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RootError<E> {
    /// The function failed at a point (its own error).
    #[error(transparent)]
    Function(E),
    /// The end values do not bracket a root (same sign, or not finite).
    #[error("the bracket [{a}, {b}] does not change sign (f = {fa}, {fb})")]
    NoBracket {
        /// Left end.
        a: f64,
        /// Right end.
        b: f64,
        /// f(a).
        fa: f64,
        /// f(b).
        fb: f64,
    },
    /// The iteration did not reach the tolerance.
    #[error("Brent's iteration did not converge in {steps} steps (last bracket width {width:e})")]
    NoConvergence {
        /// Steps taken.
        steps: usize,
        /// Width of the last bracket.
        width: f64,
    },
}

/// A bracket [a, b] with its end values, f(a) f(b) <= 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bracket {
    /// Left end.
    pub a: f64,
    /// Right end.
    pub b: f64,
    /// f(a).
    pub fa: f64,
    /// f(b).
    pub fb: f64,
}

/// Maximum number of Brent steps (each at least halves the bracket every two steps, so 200 is far
/// beyond the 2 x 64 that a double-precision bracket can need).
pub const MAX_STEPS: usize = 200;

/// Brent's method (Brent 1973, ch. 4; `zbrent` of Numerical Recipes 9.3): a root of `f` in the
/// bracket to the absolute tolerance `xtol` (plus 2 eps |x|). Returns at once on an exact zero.
pub fn brent<E>(mut f: impl FnMut(f64) -> Result<f64, E>, bracket: Bracket, xtol: f64) -> Result<f64, RootError<E>> {
    let Bracket { mut a, mut b, mut fa, mut fb } = bracket;
    if fa == 0.0 {
        return Ok(a);
    }
    if fb == 0.0 {
        return Ok(b);
    }
    if !(fa.is_finite() && fb.is_finite()) || (fa > 0.0) == (fb > 0.0) {
        return Err(RootError::NoBracket { a, b, fa, fb });
    }
    let (mut c, mut fc) = (b, fb);
    let (mut d, mut e) = (b - a, b - a);
    for _ in 0..MAX_STEPS {
        if (fb > 0.0 && fc > 0.0) || (fb < 0.0 && fc < 0.0) {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol1 = 2.0 * f64::EPSILON * b.abs() + 0.5 * xtol;
        let xm = 0.5 * (c - b);
        if xm.abs() <= tol1 || fb == 0.0 {
            return Ok(b);
        }
        if e.abs() >= tol1 && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * xm * s;
                q = 1.0 - s;
            } else {
                let qq = fa / fc;
                let r = fb / fc;
                p = s * (2.0 * xm * qq * (qq - r) - (b - a) * (r - 1.0));
                q = (qq - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            }
            p = p.abs();
            let min1 = 3.0 * xm * q - (tol1 * q).abs();
            let min2 = (e * q).abs();
            if 2.0 * p < min1.min(min2) {
                e = d;
                d = p / q;
            } else {
                d = xm;
                e = d;
            }
        } else {
            d = xm;
            e = d;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol1 { d } else { tol1.copysign(xm) };
        fb = f(b).map_err(RootError::Function)?;
    }
    Err(RootError::NoConvergence { steps: MAX_STEPS, width: (c - b).abs() })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn brent_finds_cube_root_of_two() {
        let f = |x: f64| -> Result<f64, ()> { Ok(x * x * x - 2.0) };
        let r = brent(f, Bracket { a: 0.0, b: 2.0, fa: -2.0, fb: 6.0 }, 1e-15).unwrap();
        assert!((r - 2f64.cbrt()).abs() <= 4.0 * f64::EPSILON);
    }

    #[test]
    fn brent_refuses_a_non_bracket_and_passes_errors_through() {
        let f = |x: f64| -> Result<f64, &'static str> { Ok(x * x + 1.0) };
        assert!(matches!(
            brent(f, Bracket { a: -1.0, b: 1.0, fa: 2.0, fb: 2.0 }, 1e-12),
            Err(RootError::NoBracket { .. })
        ));
        let g = |_x: f64| -> Result<f64, &'static str> { Err("boom") };
        assert_eq!(brent(g, Bracket { a: 0.0, b: 1.0, fa: -1.0, fb: 1.0 }, 1e-12), Err(RootError::Function("boom")));
    }
}

/// What [`increasing_root`] found.
#[derive(Debug)]
pub struct IncreasingRoot<S, E> {
    /// The point and `f`'s output there, when Newton's step fell below the tolerance.
    pub found: Option<(f64, S)>,
    /// The bracket's upper end when the search stopped (lowered to every point where `f` failed).
    pub hi: f64,
    /// The last failure of `f`, if any.
    pub last_error: Option<E>,
}

/// x with value(x) = `target`, for an increasing function given with its slope:
/// f(x) = (output, value, slope). Newton's method from `guess` (the midpoint when the guess is
/// not finite or outside the bracket), safeguarded by bisection on the bracket (lo, hi), which
/// every evaluation narrows; a point where `f` fails becomes the new hi. Found when the Newton
/// step is at most `rel_tol` x; stops without a point when the bracket is narrower than
/// `rel_tol` hi or after `max_steps` evaluations.
pub fn increasing_root<S, E>(
    mut f: impl FnMut(f64) -> Result<(S, f64, f64), E>,
    target: f64,
    bracket: (f64, f64),
    guess: f64,
    rel_tol: f64,
    max_steps: usize,
) -> IncreasingRoot<S, E> {
    let (mut lo, mut hi) = bracket;
    let mut x = if guess.is_finite() && guess > lo && guess < hi { guess } else { 0.5 * (lo + hi) };
    let mut last_error = None;
    for _ in 0..max_steps {
        match f(x) {
            Ok((out, value, slope)) => {
                if value < target {
                    lo = x;
                } else {
                    hi = x;
                }
                let newton = x - (value - target) / slope;
                // Converged on the Newton step itself (a bisection step near the bracket's end
                // would also be small where the target is out of reach).
                if (newton - x).abs() <= rel_tol * x {
                    return IncreasingRoot { found: Some((x, out)), hi, last_error };
                }
                x = if newton > lo && newton < hi { newton } else { 0.5 * (lo + hi) };
            }
            Err(e) => {
                hi = x;
                last_error = Some(e);
                x = 0.5 * (lo + hi);
            }
        }
        if hi - lo <= rel_tol * hi {
            break;
        }
    }
    IncreasingRoot { found: None, hi, last_error }
}

#[cfg(test)]
mod increasing_tests {
    use super::*;

    /// x^3 = 2 on (0, 4) from a guess outside the bracket, failing beyond x = 3: the cube root to
    /// 1e-15 with its output; a target beyond the failures is not found, hi ends at the first failure above 3 (within 1e-14)
    /// and the last failure is kept.
    #[test]
    fn newton_with_failures_above() {
        let f = |x: f64| if x > 3.0 { Err(x) } else { Ok((x * 10.0, x * x * x, 3.0 * x * x)) };
        let r = increasing_root(f, 2.0, (0.0, 4.0), 7.0, 4.0 * f64::EPSILON, 200);
        let (x, out) = r.found.unwrap();
        assert!((x - 2f64.cbrt()).abs() < 1e-15 && out == x * 10.0, "{x}");
        let r = increasing_root(f, 100.0, (0.0, 4.0), 3.5, 4.0 * f64::EPSILON, 200);
        assert!(r.found.is_none() && r.hi <= 3.0 * (1.0 + 1e-14) && r.last_error.is_some(), "{r:?}");
    }
}
