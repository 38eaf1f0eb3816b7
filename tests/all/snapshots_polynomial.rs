//! insta snapshots of the exact series of polynomial punches through order 12 (issue 11), in
//! text, LaTeX and JSON; files in the top-level `snapshots/` folder.
//!
//! Parameter choices (the coefficients are rational functions of every symbol kept, so the fully
//! symbolic quartic is megabytes at order 12: `PolynomialSlidingExpansion` docs):
//! - quartic g = x^2 + rho_4 x^4 (rho_4 symbolic), `paper`, frictionless and centred
//!   (theta = rbar_s = 0); and with wear dominating friction, theta = 1/4 (kappa = tan(pi/4) = 1,
//!   exact) at rbar_s = 1/6 = 2 theta/3, where the single-punch Jacobian is a square,
//!   Delta = 4 (1 + 35 rho_4/12)^2 (a smaller denominator), in both conventions;
//! - asymmetric cubic g = x^2 + rho_3 x^3, frictionless (theta = 0), rbar_s symbolic (it is an
//!   algebraic root of Tb_s = 0 there);
//! - Problem 2 for the quartic, exact in eps, B, S and sigma_4.

use exact_series::Q;
use periodic_contact::asymptotics::catalog::{
    derive_polynomial_adhesion, derive_polynomial_sliding, Derived, Substitutions,
};
use periodic_contact::asymptotics::polynomial::PolynomialProfile;
use periodic_contact::model::Convention;

fn q(n: i64, d: i64) -> Q {
    Q::new(n.into(), d.into())
}

fn profile(c: &[Option<(i64, i64)>]) -> PolynomialProfile {
    PolynomialProfile::new(c.iter().map(|x| x.map(|(n, d)| q(n, d))).collect()).unwrap()
}

fn quartic() -> PolynomialProfile {
    profile(&[Some((0, 1)), Some((0, 1)), Some((1, 1)), Some((0, 1)), None])
}

fn snap_parts(name: &str, parts: Vec<Derived>) {
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path("../../snapshots");
    settings.set_prepend_module_to_snapshot(false);
    settings.bind(|| {
        let text: Vec<String> = parts.iter().map(|d| d.text()).collect();
        let latex: Vec<String> = parts.iter().map(|d| d.latex()).collect();
        let json: Vec<serde_json::Value> = parts.iter().map(|d| d.json()).collect();
        insta::assert_snapshot!(format!("{name}_text"), text.join("\n"));
        insta::assert_snapshot!(format!("{name}_latex"), latex.join("\n"));
        insta::assert_json_snapshot!(format!("{name}_json"), json);
    });
}

fn at(theta: Q, rbar_s: Option<Q>) -> Substitutions {
    Substitutions { theta: Some(theta), rbar_s, ..Substitutions::default() }
}

#[test]
fn sliding_quartic_frictionless_order12() {
    let parts = derive_polynomial_sliding(&quartic(), Convention::Paper, 12, &at(q(0, 1), Some(q(0, 1))));
    snap_parts("sliding_polynomial_quartic_frictionless_order12", parts.unwrap());
}

#[test]
fn sliding_quartic_wear_order12() {
    let parts = derive_polynomial_sliding(&quartic(), Convention::Paper, 12, &at(q(1, 4), Some(q(1, 6))));
    snap_parts("sliding_polynomial_quartic_theta_1_4_order12", parts.unwrap());
}

/// The `periodic` convention at order 8: its order-12 output is 3.2 MB (denominators of degree
/// 2n - 1 in rho_4), too large to review as a snapshot; `series sliding --shape polynomial
/// --coefficients 0,0,1,0,? --theta 1/4 --rbar-s 1/6 --convention periodic --order 12` prints it.
#[test]
fn sliding_periodic_quartic_wear_order8() {
    let parts = derive_polynomial_sliding(&quartic(), Convention::PeriodicSurface, 8, &at(q(1, 4), Some(q(1, 6))));
    snap_parts("sliding_periodic_polynomial_quartic_theta_1_4_order8", parts.unwrap());
}

#[test]
fn sliding_cubic_frictionless_order12() {
    let cubic = profile(&[Some((0, 1)), Some((0, 1)), Some((1, 1)), None]);
    let parts = derive_polynomial_sliding(&cubic, Convention::Paper, 12, &at(q(0, 1), None));
    snap_parts("sliding_polynomial_cubic_frictionless_order12", parts.unwrap());
}

#[test]
fn adhesion_quartic_order12() {
    let parts = derive_polynomial_adhesion(&quartic(), 12, &Substitutions::default());
    snap_parts("adhesion_polynomial_quartic_order12", parts.unwrap());
}
