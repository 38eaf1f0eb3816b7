//! Elastic half-plane in plane strain (docs/theory.md section 1).

use super::{error::ModelError, Exact};
use num_traits::{One, Signed, Zero};

/// Isotropic elastic half-plane: Poisson's ratio `nu` in [0, 1/2] and the contact modulus
/// `E* = E/(1 - nu^2)` (plane strain), both exact.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Material {
    poisson_ratio: Exact,
    contact_modulus: Exact,
}

impl Material {
    /// From nu and the contact modulus E*.
    pub fn from_contact_modulus(nu: Exact, e_star: Exact) -> Result<Self, ModelError> {
        check_nu(&nu)?;
        if !e_star.is_positive() {
            return Err(ModelError::new("contact_modulus", super::readable(&e_star), "must be > 0"));
        }
        Ok(Material { poisson_ratio: nu, contact_modulus: e_star })
    }

    /// From nu and Young's modulus E: E* = E/(1 - nu^2), exactly.
    pub(crate) fn from_youngs_modulus(nu: Exact, e: Exact) -> Result<Self, ModelError> {
        check_nu(&nu)?;
        if !e.is_positive() {
            return Err(ModelError::new("youngs_modulus", super::readable(&e), "must be > 0"));
        }
        let e_star = &e / (Exact::one() - &nu * &nu);
        Ok(Material { poisson_ratio: nu, contact_modulus: e_star })
    }

    /// Poisson's ratio nu, in [0, 1/2].
    pub fn poisson_ratio(&self) -> &Exact {
        &self.poisson_ratio
    }

    /// Contact modulus E* = E/(1 - nu^2) > 0.
    pub fn contact_modulus(&self) -> &Exact {
        &self.contact_modulus
    }

    /// beta = (1 - 2 nu) / (2 (1 - nu)), in [0, 1/2] (docs/theory.md section 1), exact.
    pub fn beta(&self) -> Exact {
        let one = Exact::one();
        let two = &one + &one;
        (&one - &two * &self.poisson_ratio) / (&two * (&one - &self.poisson_ratio))
    }

    /// 3 - 4 nu, the argument of eps = ln(3 - 4 nu)/(2 pi) (docs/theory.md section 1), exact.
    pub(crate) fn kolosov(&self) -> Exact {
        Exact::from_integer(3.into()) - Exact::from_integer(4.into()) * &self.poisson_ratio
    }
}

fn check_nu(nu: &Exact) -> Result<(), ModelError> {
    let half = Exact::new(1.into(), 2.into());
    if nu < &Exact::zero() || nu > &half {
        return Err(ModelError::new("poisson_ratio", super::readable(nu), "must lie in [0, 1/2]"));
    }
    Ok(())
}
