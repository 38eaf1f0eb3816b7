//! The exact series of Problem 2 ([`crate::asymptotics::adhesion`]) against the two solvers:
//! coefficient by coefficient against method 2, and term by term (observed orders of the
//! remainders) against method 1. Here, above both layers, so that the series do not depend on
//! the solvers.

use super::series_f64;
use super::solve_mpfr_with;
use super::volterra_mpfr::VolterraParams;
use crate::asymptotics::adhesion::{
    adhesion_expansion, adhesion_expansion_with, adhesion_values, series_constants, stress_coefficient_mpfr,
};
use crate::model::{AdhesionProblem, AdhesionSize, Material, Period, PunchShape};
use exact_series::Q;
use num_bigint::BigInt;
use rug::{Complex, Float};

fn q(n: i64, d: i64) -> Q {
    Q::new(BigInt::from(n), BigInt::from(d))
}

fn nu(n: i64, d: i64) -> Q {
    q(n, d)
}

fn material(nu: &Q) -> Material {
    Material::from_contact_modulus(nu.clone(), Q::from_integer(1.into())).unwrap()
}

/// Against the other, numerical implementation of the same expansion: method 2
/// ([`super::series_f64`]: f64 Taylor coefficients of G at each tanh-sinh node, integrated numerically;
/// no symbolic expansion in s, no moment recurrence). f_n = pi p_n; psi_n = -(2/pi) Im c_n.
#[test]
fn against_f64_series_method() {
    let order = 12;
    let e = adhesion_expansion_with(order, false).unwrap();
    for nu_v in [nu(0, 1), nu(1, 4), nu(9, 20), nu(1, 2)] {
        let v = adhesion_values(&e, &nu_v, 64).unwrap();
        let sol = series_f64::solve_nominal(&material(&nu_v), 0.3).unwrap();
        let pi = std::f64::consts::PI;
        for j in 0..=order / 2 {
            let p = v.volterra[j].to_f64() * pi;
            // The solution's coefficients are in tau = sigma^2: F_j = f_j lambda^(2j).
            let scale = 0.3f64.powi(2 * j as i32);
            let f = sol.f[j] / scale;
            assert!((p - f).abs() <= 1e-11 * f.abs().max(1.0), "nu {nu_v} p_{j}: {p} vs {f}");
            let psi = v.slope[2 * j + 1].to_f64();
            let psi_f = -2.0 / pi * sol.c[j].im / scale;
            assert!((psi - psi_f).abs() <= 1e-11 * psi.abs().max(1.0), "nu {nu_v} psi_{j}: {psi} vs {psi_f}");
        }
    }
}

/// Observed order log2(r(2 lambda)/r(lambda)) of a remainder.
fn observed_order(r_coarse: f64, r_fine: f64) -> f64 {
    (r_coarse / r_fine).log2()
}

/// Term by term against the full solution (method 1, [`super::volterra_mpfr`]: MPFR Chebyshev
/// collocation of the Volterra equation, 30 digits; no expansion in lambda): after m corrections
/// the remainders of P2/(C_P E* k a^2), psi/(k a) and (q2 + i q1)/(E* k a) at x/a = 1/2 scale like
/// lambda^(2m+2) (observed order within 0.1 between lambda = pi/32 and pi/64, L = 1, k = E* = 1).
#[test]
fn remainders_against_full_solution() {
    let order = 8;
    let e = adhesion_expansion(order).unwrap();
    let prec = 128;
    for nu_v in [nu(0, 1), nu(3, 10), nu(9, 20)] {
        let v = adhesion_values(&e, &nu_v, prec).unwrap();
        let constants = series_constants(&nu_v, prec).unwrap();
        let xi = q(1, 2);
        let xi_f = crate::numerics::exact::to_float(&xi, prec);
        let stress: Vec<Complex> = (0..=order / 2)
            .map(|n| stress_coefficient_mpfr(&e, n, &xi_f, &constants, prec, prec).unwrap().unwrap())
            .collect();
        let pi = Float::with_val(prec, rug::float::Constant::Pi);
        let stress_scale = Float::with_val(prec, &pi / &v.b);
        // rem[m][quantity] at each lambda.
        let mut rem: Vec<Vec<[f64; 3]>> = Vec::new();
        for a_den in [32i64, 64] {
            let a = q(1, a_den);
            let problem = AdhesionProblem::new(
                material(&nu_v),
                Period::Finite(q(1, 1)),
                PunchShape::parabolic(q(1, 1)).unwrap(),
                AdhesionSize::HalfWidth(a.clone()),
            )
            .unwrap();
            let sol = solve_mpfr_with(
                &problem,
                std::slice::from_ref(&xi),
                VolterraParams::for_digits(30),
                super::TensionZones::Skip,
            )
            .unwrap();
            let lambda = Float::with_val(prec, &sol.lambda);
            let a_f = crate::numerics::exact::to_float(&a, prec);
            let load =
                Float::with_val(prec, &sol.normal_load / (Float::with_val(prec, &a_f * &a_f) * &v.load_constant));
            let pt = &sol.points[0];
            let psi = Float::with_val(prec, &pt.psi / &a_f);
            let sig =
                Complex::with_val(prec, (Float::with_val(prec, &pt.q2 / &a_f), Float::with_val(prec, &pt.q1 / &a_f)));
            let chi = Float::with_val(prec, &lambda * &xi_f);
            let l2 = Float::with_val(prec, &lambda * &lambda);
            let mut per_m = Vec::new();
            let (mut s_load, mut s_psi, mut s_sig) =
                (Float::with_val(prec, 0), Float::with_val(prec, 0), Complex::with_val(prec, 0));
            let mut lp = Float::with_val(prec, 1); // lambda^(2m)
            for m in 0..=order / 2 {
                s_load += Float::with_val(prec, &v.load[2 * m] * &lp);
                // psi/(k a) = (L/(pi a)) sum_J psi_J chi^(2J+1) = sum_J psi_J lambda^(2J) xi^(2J+1)
                let xp = Float::with_val(prec, rug::ops::Pow::pow(&xi_f, 2 * m as u32 + 1));
                s_psi += Float::with_val(prec, &v.slope[2 * m + 1] * &lp) * xp;
                s_sig += Complex::with_val(prec, &stress[m] * &lp) * &stress_scale;
                let r = [
                    Float::with_val(prec, &load - &s_load).abs().to_f64(),
                    Float::with_val(prec, &psi - &s_psi).abs().to_f64(),
                    Complex::with_val(prec, &sig - &s_sig).abs().real().to_f64(),
                ];
                per_m.push(r);
                lp *= &l2;
            }
            let _ = chi;
            rem.push(per_m);
        }
        for m in 0..=order / 2 {
            for (k, name) in ["P2", "psi", "stress"].iter().enumerate() {
                let p = observed_order(rem[0][m][k], rem[1][m][k]);
                eprintln!("nu {nu_v} m {m} {name}: r = {:e}, {:e}, order {p:.3}", rem[0][m][k], rem[1][m][k]);
                assert!((p - (2 * m + 2) as f64).abs() < 0.1, "nu {nu_v} m {m} {name}: order {p}");
            }
        }
    }
}
