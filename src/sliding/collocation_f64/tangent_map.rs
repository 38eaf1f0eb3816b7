//! Geometry of the tangent map (docs/theory.md section 2): u -> x - c and its Jacobian, periodic
//! t = tan(pi (x - c)/L) = m u (m = tan lambda), or single x - c = l u.

use std::f64::consts::PI;

/// Largest lambda considered: contact fraction 2 lambda/pi = 1 - 1e-6.
pub(super) const LAMBDA_MAX: f64 = PI / 2.0 * (1.0 - 1e-6);

/// u -> x - c and its Jacobian: periodic t = tan(pi (x-c)/L) = m u, or single x - c = l u.
#[derive(Debug, Clone, Copy)]
pub(super) enum Map {
    Periodic { big_l: f64, lambda: f64, m: f64 },
    Single { l: f64 },
}

impl Map {
    pub(super) fn periodic(big_l: f64, lambda: f64) -> Self {
        Map::Periodic { big_l, lambda, m: lambda.tan() }
    }
    /// x(u) - c = (L/pi) atan(m u)   (or l u).
    pub(super) fn offset(&self, u: f64) -> f64 {
        match *self {
            Map::Periodic { big_l, m, .. } => big_l / PI * (m * u).atan(),
            Map::Single { l } => l * u,
        }
    }
    /// dx/du = (L/pi) m/(1 + m^2 u^2)   (or l).
    pub(super) fn jac(&self, u: f64) -> f64 {
        match *self {
            Map::Periodic { big_l, m, .. } => big_l / PI * m / (1.0 + m * m * u * u),
            Map::Single { l } => l,
        }
    }
    /// Weight of C0: (1/pi) m^2 u/(1 + m^2 u^2) (docs/theory.md section 2); 0 for a single punch.
    pub(super) fn c0_weight(&self, u: f64) -> f64 {
        match *self {
            Map::Periodic { m, .. } => m * m * u / (PI * (1.0 + m * m * u * u)),
            Map::Single { .. } => 0.0,
        }
    }
    /// u of the point x = c + l xh: tan(lambda xh)/tan(lambda)   (or xh).
    pub(super) fn u_of_xh(&self, xh: f64) -> f64 {
        match *self {
            Map::Periodic { lambda, m, .. } => (lambda * xh).tan() / m,
            Map::Single { .. } => xh,
        }
    }
    /// u of the point x = c + xi: tan(pi xi/L)/m   (or xi/l).
    pub(super) fn u_of_offset(&self, xi: f64) -> f64 {
        match *self {
            Map::Periodic { big_l, m, .. } => (PI * xi / big_l).tan() / m,
            Map::Single { l } => xi / l,
        }
    }
    /// Half-length l = L lambda/pi   (or l).
    pub(super) fn half_length(&self) -> f64 {
        match *self {
            Map::Periodic { big_l, lambda, .. } => big_l * lambda / PI,
            Map::Single { l } => l,
        }
    }
    /// lambda = pi l/L (0 for a single punch).
    pub(super) fn lambda(&self) -> f64 {
        match *self {
            Map::Periodic { lambda, .. } => lambda,
            Map::Single { .. } => 0.0,
        }
    }
}
