//! `periodic-contact series loading-law` (issue 12, asymptotics of the loading-law problem): the
//! printed coefficients at nu = 3/10, n = 1/5, order 8 (insta snapshots, text and JSON), checked
//! against the full MPFR solution of the loading-law problem (not only the snapshot), and the
//! refusals of bad input (exit code 2, the flag named).

use super::common;
use common::{assert_usage_error, run};
use periodic_contact::loading_law::collocation::{solve, LawSetting};
use periodic_contact::model::{Convention, Exact, Material};
use periodic_contact::numerics::tanh_sinh::TanhSinh;
use rug::Float;

const ARGS: [&str; 8] = ["series", "loading-law", "--nu", "3/10", "--ratio", "1/5", "--order", "8"];

fn snapshots() -> insta::Settings {
    let mut s = insta::Settings::clone_current();
    s.set_snapshot_path("../../../../snapshots");
    s.set_prepend_module_to_snapshot(false);
    s
}

/// The printed series summed at Lambda = pi/32 against the collocation's P(Lambda), c/l and
/// psi_hat(Lambda/2) (30 digits): they differ by the remainder after lambda^8, ~3e-13 of the value
/// (`tests/all/convergence_orders_loading_law.rs` measures its order), so the printed coefficients
/// are the expansion of the full solution.
#[test]
fn loading_law_series_snapshot_and_full_solution() {
    let (code, text, err) = run(&ARGS);
    assert_eq!(code, 0, "{err}");
    let mut args = ARGS.to_vec();
    args.extend(["--format", "json"]);
    let (code, json, err) = run(&args);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    snapshots().bind(|| {
        insta::assert_snapshot!("loading_law_nu_3_10_n_1_5_order8_text", text);
        insta::assert_json_snapshot!("loading_law_nu_3_10_n_1_5_order8_json", v);
    });
    assert!(v["verified_digits"].as_f64().unwrap() >= 30.0, "{json}");
    let prec = 150;
    let part = |name: &str| -> Vec<(u32, Float)> {
        let p = v["parts"].as_array().unwrap().iter().find(|p| p["object"] == name).unwrap();
        p["coefficients"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| {
                let x = Float::parse(c["value"].as_str().unwrap()).unwrap();
                (c["power"].as_u64().unwrap() as u32, Float::with_val(prec, x))
            })
            .collect()
    };
    let sum = |coeffs: &[(u32, Float)], x: &Float| {
        coeffs.iter().fold(Float::with_val(prec, 0), |acc, (k, c)| {
            acc + Float::with_val(prec, c * rug::ops::Pow::pow(x.clone(), *k))
        })
    };
    let material =
        Material::from_contact_modulus(Exact::new(3.into(), 10.into()), Exact::from_integer(1.into())).unwrap();
    let setting = LawSetting::linear(
        material,
        Exact::new(1.into(), 5.into()),
        Exact::new(1.into(), 32.into()),
        Convention::Paper,
    );
    let sol = solve(&setting, 18, 110, prec).unwrap();
    let lambda = sol.lambda_max.clone();
    let l2 = Float::with_val(prec, lambda.square_ref());
    let half = Float::with_val(prec, &lambda / 2u32);
    let pi = Float::with_val(prec, rug::float::Constant::Pi);
    let series = [
        ("P", sum(&part("load_C"), &lambda) * &l2, sol.load()),
        ("c/l", sum(&part("c_over_l"), &lambda), sol.centre_ratio()),
        (
            "psi_hat",
            sum(&part("slope_A_plus"), &half) * &pi / -2i32,
            sol.psi_hat(&half, &TanhSinh::new(118, 1.0, prec)),
        ),
    ];
    for (name, s, full) in series {
        let rel = Float::with_val(prec, &s - &full).to_f64().abs() / full.to_f64().abs();
        eprintln!("{name}: series {s:.25} full {full:.25} rel {rel:.1e}");
        assert!(rel < 1e-11 && rel > 1e-16, "{name}: {rel:e} (the lambda^10 remainder is ~3e-13)");
    }
}

#[test]
fn loading_law_series_refuses_bad_input() {
    for (args, needle) in [
        (
            vec!["series", "loading-law", "--order", "4", "--nu", "3/10", "--ratio", "-1/5"],
            "--ratio = -1/5: must be >= 0",
        ),
        (vec!["series", "loading-law", "--order", "4", "--nu", "3/10"], "--ratio"),
        (vec!["series", "loading-law", "--order", "4", "--ratio", "1/5"], "--nu"),
        (
            vec!["series", "loading-law", "--order", "4", "--nu", "0.6", "--ratio", "1/5"],
            "--nu = 3/5: must lie in [0, 1/2]",
        ),
        (vec!["series", "loading-law", "--order", "40", "--nu", "0.3", "--ratio", "1/5"], "--order"),
        (
            vec!["series", "loading-law", "--order", "4", "--nu", "0.3", "--ratio", "1/5", "--format", "latex"],
            "--format",
        ),
        (vec!["series", "loading-law", "--order", "4", "--nu", "0.3", "--ratio", "1/5", "--theta", "0"], "--theta"),
        (vec!["series", "adhesion", "--order", "4", "--nu", "0.3", "--ratio", "1/5"], "only the loading-law series"),
    ] {
        assert_usage_error(&args, needle);
    }
}

/// At nu = 0, n = 1/2 the output ends with the homogeneous mode, mu* = 31.8395100566 (the
/// independent mpmath value of `asymptotics::loading_law_modes`), in text and JSON.
#[test]
fn loading_law_series_names_the_mode() {
    let args = ["series", "loading-law", "--nu", "0", "--ratio", "1/2", "--order", "2"];
    let (code, text, err) = run(&args);
    assert_eq!(code, 0, "{err}");
    assert!(text.contains("homogeneous mode: mu* = 31.8395100566"), "{text}");
    let mut json_args = args.to_vec();
    json_args.extend(["--format", "json"]);
    let (code, json, err) = run(&json_args);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(v["mode"]["exponent"], "31.8395100566", "{json}");
    assert!(v["mode"]["digits"].as_f64().unwrap() >= 12.0, "{json}");
}
