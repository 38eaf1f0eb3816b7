//! The polynomial profile of a series request: `coefficients` (exact, `?` for a symbol) or
//! `degree` (every coefficient symbolic; the adhesion series keeps the even ones), for the
//! polynomial objects only (docs/theory.md section 9).

use crate::asymptotics::catalog::SeriesObject;
use crate::asymptotics::polynomial::PolynomialProfile;
use crate::model::ModelError;
use exact_series::{parse_rational, Q};

/// The polynomial profile of `--coefficients` (`?` = symbolic) or `--degree` (every coefficient
/// symbolic; the adhesion series keeps the even ones only), for the polynomial objects; refused
/// for the others, and required by them.
pub(super) fn polynomial_profile(
    object: SeriesObject,
    coefficients: Option<&str>,
    degree: Option<&str>,
) -> Result<Option<PolynomialProfile>, ModelError> {
    let polynomial = matches!(object, SeriesObject::PolynomialSliding | SeriesObject::PolynomialAdhesion);
    let even = object == SeriesObject::PolynomialAdhesion;
    let profile = match (coefficients, degree) {
        (Some(_), Some(d)) => return Err(ModelError::new("--degree", d, "give either --coefficients or --degree")),
        (None, None) if polynomial => {
            return Err(ModelError::new("--shape", "polynomial", "needs --coefficients LIST or --degree D"))
        }
        (None, None) => return Ok(None),
        (Some(list), None) => {
            let c = list
                .split(',')
                .map(|item| match item.trim() {
                    "?" => Ok(None),
                    x => parse_rational(x).map(Some).map_err(|_| {
                        ModelError::new(
                            "--coefficients",
                            list,
                            format!("{x:?} is not an exact number (or ? for a symbol)"),
                        )
                    }),
                })
                .collect::<Result<Vec<_>, _>>()?;
            PolynomialProfile::new(c)
        }
        (None, Some(d)) => {
            let n = d.trim().parse::<usize>().map_err(|_| ModelError::new("--degree", d, "must be an integer"))?;
            if even && n % 2 == 1 {
                return Err(ModelError::new(
                    "--degree",
                    d,
                    "the adhesion series needs an even profile: an even degree",
                ));
            }
            let mut p = PolynomialProfile::symbolic(n)?;
            if even {
                let c = p
                    .coefficients()
                    .iter()
                    .enumerate()
                    .map(|(j, c)| if j % 2 == 1 { Some(Q::from_integer(0.into())) } else { c.clone() })
                    .collect();
                p = PolynomialProfile::new(c)?;
            }
            Ok(p)
        }
    }
    .map_err(|e| ModelError { parameter: e.parameter.replace("coefficients", "--coefficients"), ..e })?;
    if !polynomial {
        return Err(ModelError::new(
            if coefficients.is_some() { "--coefficients" } else { "--degree" },
            coefficients.or(degree).unwrap_or_default(),
            "only the sliding series with --shape polynomial and the adhesion series take a polynomial profile",
        ));
    }
    if even && !profile.is_even() {
        return Err(ModelError::new(
            "--coefficients",
            coefficients.unwrap_or_default(),
            "the adhesion series needs an even profile: every odd coefficient 0",
        ));
    }
    Ok(Some(profile))
}
