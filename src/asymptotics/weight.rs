//! The weight series Y(xh; lambda) (docs/theory.md section 5; the paper's [2.29], [3.1]).
//!
//! R(x, a) = (L/pi) sin(pi (x+a)/L)^(1/2+theta) sin(pi (b-x)/L)^(1/2-theta) = l omega(xh) Y with
//! Y = sinc(lambda (1 + xh))^(1/2 + theta) sinc(lambda (1 - xh))^(1/2 - theta), sinc z = sin z / z:
//! a series in lambda^2 with coefficients in Q[theta, xh].

use exact_series::{Poly, Ring, Series, SeriesError, Symbol, Q};

/// The symbol names used by this object.
pub const THETA: &str = "theta";
/// Linear contact variable xh = (x - c)/l.
pub const XH: &str = "xh";

/// Y(xh; lambda) through lambda^order, coefficients in Q[theta, xh].
pub fn weight_series(order: usize) -> Result<Series<Poly>, SeriesError> {
    let prec = order + 1;
    let theta = Poly::symbol(Symbol::new(THETA)?);
    let xh = Poly::symbol(Symbol::new(XH)?);
    let half = Poly::from_q(&Q::new(1.into(), 2.into()));
    let one = Poly::one();
    let sinc = Series::<Poly>::sinc_series(prec);
    let left = sinc.rescale_var(&one.add(&xh)).pow(&half.add(&theta))?;
    let right = sinc.rescale_var(&one.sub(&xh)).pow(&half.sub(&theta))?;
    Ok(left.mul(&right))
}
