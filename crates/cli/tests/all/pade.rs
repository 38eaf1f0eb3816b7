//! Padé resummation (docs/theory.md section 11): the gain over the plain series from the same
//! coefficients against closed forms, the honesty of the estimated digits, the `pade` method of
//! `solve` and `series --pade`. Run in release: `cargo test --release --test all pade::`.

use super::common;

use periodic_contact::asymptotics::sliding::{sliding_expansion_with, SlidingShape};
use periodic_contact::model::{Convention, Material, Period, PunchShape, SlidingProblem};
use periodic_contact::numerics::accuracy::verified_digits_mpfr;
use periodic_contact::numerics::evaluate::series_q_mpfr;
use periodic_contact::numerics::pade::{resum, resum_conformal};
use periodic_contact::sliding::series::{pade::solve_pade_with, solve_series_with};
use periodic_contact::verification::pade::{frictionless_l_over_ls, singularity_map, LAMBDAS};
use rug::Float;

const PREC: u32 = 200;

fn q(n: i64, d: i64) -> exact_series::Q {
    exact_series::Q::new(n.into(), d.into())
}

/// (plain digits, Pade digits against the closed form, Pade estimated digits, the same two after
/// the conformal map of the singularities at w = +-2 pi i) of Kuznetsov's l/l_s at lambda from the
/// exact coefficients through Lambda^order.
fn kuznetsov(order: usize, lam: f64) -> (f64, f64, f64, f64, f64) {
    let e = sliding_expansion_with(SlidingShape::Parabolic, order, Convention::Paper).unwrap();
    let f = frictionless_l_over_ls(&e);
    let lambda = Float::with_val(PREC, lam);
    let w: Float = Float::with_val(PREC, lambda.clone().cos().ln()) * -2;
    let truth = Float::with_val(PREC, &lambda / w.clone().sqrt());
    let d = |x: &Float| verified_digits_mpfr(&Float::with_val(PREC, x - &truth), &truth, 50.0);
    let plain = d(&series_q_mpfr(&f, &w, PREC));
    let r = resum(&f, &w, &truth, 50.0, PREC);
    let b = r.best().expect("a Pade value");
    let cw: Vec<Float> = f.coeffs().iter().map(|c| periodic_contact::numerics::exact::to_float(c, PREC)).collect();
    let map = singularity_map(SlidingShape::Parabolic, PREC);
    let rc = resum_conformal(&cw, &map, &w, &truth, 50.0, PREC).expect("w is off the cuts");
    let c = rc.best().expect("a conformal Pade value");
    (plain, d(&b.value), b.digits, d(&c.value), c.digits)
}

#[test]
fn kuznetsov_l_gains_five_digits_at_lambda_1_2() {
    // Exact coefficients through Lambda^24 (13 in w = Lambda^2), theta = T = 0: the Pade
    // approximants in w gain 2 digits, in z after the conformal map of the cut plane 5.
    let (plain, pade, estimated, conformal, conformal_estimated) = kuznetsov(24, 1.2);
    eprintln!(
        "Kuznetsov l at lambda = 1.2, order 24: plain {plain:.1}, Pade {pade:.1} (estimated {estimated:.1}), \
         conformal + Pade {conformal:.1} (estimated {conformal_estimated:.1})"
    );
    assert!(pade - plain >= 1.5, "plain {plain}, Pade {pade}");
    assert!(conformal - plain >= 5.0, "plain {plain}, conformal {conformal}");
    assert!(estimated <= pade + 0.5, "estimated {estimated} > true {pade}");
    assert!(conformal_estimated <= conformal + 0.5, "estimated {conformal_estimated} > true {conformal}");
}

#[test]
#[ignore = "long tier: 17 s alone in the test profile (opt-level 2) on a loaded 2-core machine (scripts/test --long)"]
fn estimates_are_honest_on_the_closed_forms() {
    for shape in [SlidingShape::Parabolic, SlidingShape::Sinusoidal] {
        let e = sliding_expansion_with(shape, 24, Convention::Paper).unwrap();
        let f = frictionless_l_over_ls(&e);
        for lam in LAMBDAS {
            let lambda = Float::with_val(PREC, lam);
            let w = match shape {
                SlidingShape::Parabolic => Float::with_val(PREC, lambda.clone().cos().ln()) * -2,
                SlidingShape::Sinusoidal => Float::with_val(PREC, lambda.clone().sin().square()),
            };
            let truth = Float::with_val(PREC, &lambda / w.clone().sqrt());
            let r = resum(&f, &w, &truth, 50.0, PREC);
            for c in r.candidates.iter().filter(|c| c.refusal.is_none()) {
                let t = verified_digits_mpfr(&Float::with_val(PREC, &c.value - &truth), &truth, 50.0);
                eprintln!("{shape:?} lambda {lam} [{}/{}]: estimated {:.1}, true {t:.1}", c.l, c.m, c.digits);
                assert!(
                    c.digits <= t + 0.5,
                    "{shape:?} lambda {lam} [{}/{}]: estimated {} > true {t}",
                    c.l,
                    c.m,
                    c.digits
                );
            }
        }
    }
}

/// The frictionless parabola E* = k = L = 1 at the load of Kuznetsov's lambda (P2 = (1/pi) ln sec
/// lambda [2.15]), as an exact rational within 1e-15.
fn kuznetsov_problem(lam: f64) -> SlidingProblem {
    let p2 = (1.0 / lam.cos()).ln() / std::f64::consts::PI;
    SlidingProblem::builder()
        .material(Material::from_contact_modulus(q(3, 10), q(1, 1)).unwrap())
        .period(Period::Finite(q(1, 1)))
        .shape(PunchShape::Parabolic { k: q(1, 1) })
        .normal_load(exact_series::Q::new(((p2 * 1e15).round() as i64).into(), 1_000_000_000_000_000i64.into()))
        .build()
        .unwrap()
}

#[test]
fn the_pade_method_beats_the_series_method_and_its_estimate_is_honest() {
    let e = sliding_expansion_with(SlidingShape::Parabolic, 24, Convention::Paper).unwrap();
    let p = kuznetsov_problem(1.2);
    let pade = solve_pade_with(&e, &p, &[], 24, 30).unwrap();
    // The reference: the closed form at the problem's exact load, l = (L/pi) arccos(exp(-pi P2)).
    let sp = periodic_contact::sliding::series::point::series_point(&p, PREC).unwrap();
    let pi = Float::with_val(PREC, rug::float::Constant::Pi);
    let lambda = Float::with_val(PREC, Float::with_val(PREC, -sp.big_lambda.clone().square() / 2).exp().acos());
    let l = Float::with_val(PREC, &lambda / &pi);
    let truth = |x: &Float| verified_digits_mpfr(&Float::with_val(PREC, x - &l), &l, 30.0);
    let pade_true = truth(&pade.solution.l);
    eprintln!(
        "pade method: l estimated {:.1}, true {pade_true:.1}; {:?}",
        pade.solution.accuracy.contact, pade.chosen[0]
    );
    assert!(pade.solution.accuracy.contact <= pade_true + 0.5);
    assert_eq!(pade.chosen[0].quantity, "l/l_s");
    // The series method at the same order sums the same terms plainly: 8.3 digits (or refuses,
    // depending on its rate estimate); the Pade method gains 2.
    match solve_series_with(&e, &p, &[], 24, 30) {
        Ok(s) => {
            let series_true = truth(&s.l);
            eprintln!("series method: estimated {:.1}, true {series_true:.1}", s.accuracy.contact);
            assert!(pade_true >= series_true + 1.5, "Pade {pade_true}, series {series_true}");
        }
        Err(err) => eprintln!("series method refused: {err}"),
    }
}

#[test]
fn solve_method_pade_cli() {
    let scene = common::scene_file(
        "pade_kuznetsov.toml",
        "[problem]\nkind = \"sliding\"\n[material]\npoisson_ratio = \"0.3\"\ncontact_modulus = \"1\"\n[punch]\nshape = \"parabolic\"\nk = \"1\"\nperiod = \"1\"\n\
         [sliding]\nnormal_load = \"0.1\"\n[output]\nmethod = \"pade\"\nseries_order = 16\ndigits = 20\n",
    );
    let v = common::json(&["solve", &scene, "--json"]);
    assert_eq!(v["provenance"]["method"], "pade", "{v}");
    assert_eq!(v["pade"]["variable"], "w = Lambda^2", "{v}");
    assert!(v["digits_estimated"].as_str().is_some(), "{v}");
    // Problem 2 refuses the method, naming it and the way to its Pade approximants.
    let (code, _, err) = common::run(&["solve", "scenes/adhesion_nu03.toml", "--method", "pade"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("pade") && err.contains("--pade"), "{err}");
}

#[test]
fn series_pade_cli() {
    let (code, out, err) = common::run(&["series", "sliding", "--order", "8", "--theta", "0", "--T", "0", "--pade"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("pade: l_over_ls\n  variable w = Lambda^2; coefficients exact; w^0 .. w^4"), "{out}");
    assert!(out.contains("  [2/2] P = 1 + "), "{out}");
    assert!(out.contains("  [2/2] poles: "), "{out}");
    // Symbols left: not built, and why.
    let (code, out, _) = common::run(&["series", "sliding", "--order", "4", "--pade"]);
    assert_eq!(code, 0);
    assert!(out.contains("not built: coefficients hold the symbols theta, T"), "{out}");
    // Problem 2 at nu: from the 30-digit values.
    let (code, out, err) = common::run(&["series", "adhesion", "--order", "8", "--nu", "3/10", "--pade"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("pade: load_c\n  variable w = lambda^2; coefficients the 30-digit values at nu = 3/10"),
        "{out}"
    );
    // Text only.
    let (code, _, err) = common::run(&["series", "kernel", "--order", "8", "--pade", "--format", "json"]);
    assert_eq!(code, 2);
    assert!(err.contains("--pade"), "{err}");
    // Without --pade the output is unchanged (no Pade section).
    let (_, out, _) = common::run(&["series", "kernel", "--order", "8"]);
    assert!(!out.contains("Pade"), "{out}");
}

/// Issue 31: `solve --method pade` maps Kuznetsov's cuts (w = +-2 pi i, conformal map) and chooses
/// the approximant in z by its own estimate. At the default order 12 (7 coefficients in w) and
/// lambda = 1.2: l has 7.0 true digits (estimated 5.4) against 4.9 for the series method's full
/// sum (which claims 1.7 and prints 2.3 true digits); at order 24 13.7 against 8.3 (+5.4).
#[test]
#[ignore = "long tier: 5 s alone in the test profile (opt-level 2) on a loaded 2-core machine (scripts/test --long)"]
fn the_pade_method_maps_kuznetsovs_cuts() {
    for (order, gain) in [(12usize, 2.0), (24, 5.0)] {
        let e = sliding_expansion_with(SlidingShape::Parabolic, order, Convention::Paper).unwrap();
        let p = kuznetsov_problem(1.2);
        let pade = solve_pade_with(&e, &p, &[], order, 30).unwrap();
        let sp = periodic_contact::sliding::series::point::series_point(&p, PREC).unwrap();
        let pi = Float::with_val(PREC, rug::float::Constant::Pi);
        let lambda = Float::with_val(PREC, Float::with_val(PREC, -sp.big_lambda.clone().square() / 2).exp().acos());
        let l = Float::with_val(PREC, &lambda / &pi);
        let truth = |x: &Float| verified_digits_mpfr(&Float::with_val(PREC, x - &l), &l, 30.0);
        let series = truth(&solve_series_with(&e, &p, &[], order, 30).unwrap().l);
        let (pade_true, est) = (truth(&pade.solution.l), pade.solution.accuracy.contact);
        eprintln!("order {order}: pade {pade_true:.2} (estimated {est:.2}), series {series:.2}; {:?}", pade.chosen[0]);
        assert!(pade.chosen[0].map.is_some_and(|m| m.contains("2 pi i")), "{:?}", pade.chosen[0]);
        assert!(est <= pade_true + 0.5, "estimated {est} > true {pade_true}");
        assert!(pade_true >= series + gain, "order {order}: Pade {pade_true}, series {series}");
    }
}

/// Issue 31: `solve --method pade` at its default order (24, `DEFAULT_PADE_ORDER`) against
/// `solve --method series` at its default (12), both as printed, on Kuznetsov's l at
/// lambda = 1.2 (P2 = ln sec(1.2)/pi, L = k = E* = 1): the closed form l = arccos(exp(-pi P2))/pi.
/// Measured: pade 11.9 digits (8.3 s; it claims 10.0, printed on 2026-11-27 after issue 34's
/// safety factor on the Pade claims), series 4.0 (claims 1.6; 0.2 s).
#[test]
#[ignore = "long tier: 5 s alone in the test profile (opt-level 2) on a loaded 2-core machine (scripts/test --long)"]
fn the_pade_method_at_its_default_order_gains_five_digits() {
    let scene = common::scene_file(
        "kuznetsov_1_2.toml",
        "[problem]\nkind = \"sliding\"\n[material]\npoisson_ratio = \"0.3\"\ncontact_modulus = \"1\"\n\
         [punch]\nshape = \"parabolic\"\nk = \"1\"\nperiod = \"1\"\n[sliding]\nnormal_load = \"0.3231\"\n",
    );
    let p2 = Float::with_val(PREC, Float::parse("0.3231").unwrap());
    let pi = Float::with_val(PREC, rug::float::Constant::Pi);
    let truth = Float::with_val(PREC, Float::with_val(PREC, -(p2 * &pi)).exp().acos()) / &pi;
    let digits = |method: &str| {
        let v = common::json(&["solve", &scene, "--method", method, "--format", "json"]);
        let l = v["l"].as_str().unwrap_or_else(|| panic!("{method}: l in {v}"));
        let x = Float::with_val(PREC, Float::parse(l).unwrap());
        (verified_digits_mpfr(&Float::with_val(PREC, &x - &truth), &truth, 30.0), v["provenance"]["order"].clone())
    };
    let (pade, pade_order) = digits("pade");
    let (series, series_order) = digits("series");
    eprintln!(
        "l at lambda = 1.2: pade {pade:.1} digits (order {pade_order}), series {series:.1} (order {series_order})"
    );
    assert!(pade >= series + 5.0, "pade {pade}, series {series}");
}
