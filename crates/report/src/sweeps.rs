//! Report section 6: load-size curves from the scenes' `[sweep]`s, each point computed by the
//! method chosen for the scene's target, with the closed forms beside them where they exist
//! (docs/theory.md section 6): Kuznetsov [2.15] for the frictionless periodic parabola (and for
//! Problem 2 at nu = 1/2, eps = 0), Westergaard [2.17] for the frictionless sinusoid, and the
//! single-punch laws: l_s = a0/sqrt(1 - 4 theta^2) [3.10] (Problem 1, parabola) and
//! P2 = C_P E* k a^2 [3.18] (Problem 2).

use super::calibration::choose;
use super::chart::{Chart, Curve, Draw, Legend};
use super::choice::target_of;
use super::runner::{self, Knob};
use super::section::{Ctx, Section};
use periodic_contact::model::OnPunchRow;
use periodic_contact::model::{Exact, Period, PunchShape};
use periodic_contact::numerics::exact::to_f64;
use periodic_contact::params::sliding::{hertz_half_width_f64, SlidingParamsF64};
use periodic_contact::scene::{Scene, SceneProblem};
use std::f64::consts::PI;
use std::fmt::Write as _;

/// Where the report shows the exact series of Problem 2 (knob [`Knob::Series`] of
/// [`super::runner`], section 4) and where their term-by-term orders are checked.
pub fn adhesion_series_note() -> &'static str {
    "the exact series of Problem 2 ([3.18], `src/asymptotics/adhesion.rs`) are compared with the full \
     solution in section 4 (speed against accuracy); their term-by-term orders (remainders after m = 0..4 \
     corrections scale like lambda^(2m+2) at nu = 0, 0.3, 0.45) are checked by the test \
     `adhesion::against_series::remainders_against_full_solution`; the load-size curves here show the \
     full solutions."
}

fn f(x: &Exact) -> f64 {
    to_f64(x).unwrap_or(f64::NAN)
}

/// A closed form beside the computed curve: (legend, size as a function of P2).
/// A closed form: legend and the size as a function of P2.
type ClosedForm = (String, Box<dyn Fn(f64) -> f64>);

fn closed_forms(problem: &SceneProblem) -> Vec<ClosedForm> {
    let mut out: Vec<ClosedForm> = Vec::new();
    match problem {
        SceneProblem::Sliding(p) => {
            let e = f(p.material().contact_modulus());
            let frictionless = p.kappa_and_tau0_vanish();
            let big_l = match p.period() {
                Period::Finite(l) => Some(f(l)),
                Period::Infinite => None,
            };
            match p.shape() {
                PunchShape::Parabolic { k } => {
                    let k = f(k);
                    if let Ok(prm) = SlidingParamsF64::new(p) {
                        out.push((
                            "single punch l_s = a0/sqrt(1-4 theta^2) [3.10]".into(),
                            Box::new(move |p2: f64| prm.l_s(p2)),
                        ));
                    }
                    if let (true, Some(big_l)) = (frictionless, big_l) {
                        out.push((
                            "Kuznetsov [2.15]".into(),
                            Box::new(move |p2: f64| {
                                let a0sq = hertz_half_width_f64(p2, e, k).powi(2);
                                big_l / PI * (-(PI * PI * a0sq) / (2.0 * big_l * big_l)).exp().acos()
                            }),
                        ));
                    }
                }
                PunchShape::Sinusoidal { amplitude } => {
                    let d = f(amplitude);
                    if let (true, Some(big_l)) = (frictionless, big_l) {
                        out.push((
                            "Westergaard [2.17]".into(),
                            Box::new(move |p2: f64| big_l / PI * (p2 / (PI * e * d)).sqrt().asin()),
                        ));
                    }
                }
                // The new profiles' closed form (docs/theory.md section 9, P2 as a function of a) is in
                // the section "Punch shapes" ([`super::shapes`]), on its own grid of sizes.
                PunchShape::Polynomial { .. } | PunchShape::Circular { .. } => {}
            }
        }
        SceneProblem::LoadingLaw(_) => {}
        SceneProblem::Adhesion(p) => {
            let e = f(p.material().contact_modulus());
            let k = f(p.curvature());
            let cp = periodic_contact::params::adhesion::AdhesionParamsF64::new(p.material()).load_constant;
            out.push((
                "single punch P2 = C_P E* k a^2 [3.18]".into(),
                Box::new(move |p2: f64| (p2 / (cp * e * k)).sqrt()),
            ));
            if let Period::Finite(l) = p.period() {
                if *p.material().poisson_ratio() == Exact::new(1.into(), 2.into()) {
                    let big_l = f(l);
                    out.push((
                        "Kuznetsov (nu = 1/2) [2.15]".into(),
                        Box::new(move |p2: f64| big_l / PI * (-(PI * p2) / (e * k * big_l * big_l)).exp().acos()),
                    ));
                }
            }
        }
    }
    out
}

fn period_of(problem: &SceneProblem) -> Option<f64> {
    let p = match problem {
        SceneProblem::Sliding(p) => p.period(),
        SceneProblem::Adhesion(p) => p.period(),
        SceneProblem::LoadingLaw(p) => p.period(),
    };
    match p {
        Period::Finite(l) => Some(f(l)),
        Period::Infinite => None,
    }
}

/// Significant digits to print: what the method verified or is predicted to give, at most 12.
fn sig(d: f64) -> usize {
    (d.floor() as usize).clamp(2, 12)
}

/// Builds section 6.
pub fn section(ctx: &Ctx, scenes: &[(String, Scene)]) -> Section {
    let mut s = Section::default();
    let _ = writeln!(
        s.markdown,
        "## 6. Load-size curves\n\n\
         From each scene's `[sweep]`: every point is computed by the method chosen for the scene's target \
         (section above), the closed forms drawn beside them (dashed) where they exist. Sizes are contact \
         half-lengths l (Problem 1) or half-widths a (Problem 2), over the period L. Digits: verified (MPFR) or \
         predicted from the calibration (series, f64), and printed values carry no more. Problem 2 series: {}\n",
        adhesion_series_note()
    );
    for (name, scene) in scenes {
        let Some(sw) = &scene.sweep else { continue };
        if matches!(scene.problem, SceneProblem::LoadingLaw(_)) {
            let _ =
                writeln!(s.markdown, "### Scene `{name}`\n\nNot computed: {}.\n", runner::LOADING_LAW_NOT_IN_REPORT);
            continue;
        }
        let problems = scene.sweep_problems();
        let big_l = period_of(&scene.problem);
        let scale = big_l.unwrap_or(1.0);
        let forms = closed_forms(&scene.problem);
        let _ = writeln!(
            s.markdown,
            "### Scene `{name}` (sweep over {})\n\n![{name}](sweep_{name}.svg) (data: `sweep_{name}.csv`)\n",
            sw.parameter.key()
        );
        let mut head = "| P2 | size/L | method | digits |".to_string();
        let mut rule = "|---:|---:|---|---:|".to_string();
        for (fname, _) in &forms {
            head.push_str(&format!(" {fname}: rel. deviation |"));
            rule.push_str("---:|");
        }
        let _ = writeln!(s.markdown, "{head}\n{rule}");
        let mut pts = Vec::new();
        let mut fallbacks: Vec<String> = Vec::new();
        for p in &problems {
            ctx.step(format!("load-size curve: {name}"));
            // The chosen method first; if it fails, the next candidates predicted to meet the
            // target, cheapest first (the table says which method produced each point).
            let plan: Vec<(Knob, Option<f64>)> = match target_of(scene) {
                Err(d) => vec![(Knob::MpfrVerified(d), None)],
                Ok(t) => {
                    let c = choose(&ctx.table, p, t);
                    c.candidates[c.chosen..]
                        .iter()
                        .filter(|x| x.predicted.is_some_and(|d| d >= t as f64))
                        .map(|x| (x.knob, x.predicted))
                        .collect()
                }
            };
            let mut result = Err(String::from("no candidate"));
            let mut knob = plan[0].0;
            let mut digits_claim = plan[0].1;
            let mut failed = Vec::new();
            for &(k, pred) in &plan {
                knob = k;
                digits_claim = pred;
                result = runner::run(p, k, &ctx.cache);
                match &result {
                    Ok(_) => break,
                    Err(e) => failed.push(format!("{} failed ({e})", k.label())),
                }
            }
            if !failed.is_empty() && result.is_ok() {
                fallbacks.push(format!("- {}; used {} instead.", failed.join("; "), knob.label()));
            }
            match result {
                Ok(o) => {
                    let d = o.verified_digits.or(digits_claim).unwrap_or(2.0).min(if matches!(knob, Knob::F64(_)) {
                        15.0
                    } else {
                        70.0
                    });
                    let size = o.size.to_f64();
                    let load = o.load.to_f64();
                    let mut row = format!(
                        "| {:.*e} | {:.*e} | {} | {} {} |",
                        sig(d) - 1,
                        load,
                        sig(d) - 1,
                        size / scale,
                        knob.label(),
                        periodic_contact::numerics::accuracy::digits_text(d),
                        if o.verified_digits.is_some() { "verified" } else { "predicted" }
                    );
                    for (_, form) in &forms {
                        let c = form(load);
                        row.push_str(&format!(" {:.2e} |", ((size - c) / c).abs()));
                    }
                    let _ = writeln!(s.markdown, "{row}");
                    pts.push((load, size / scale));
                }
                Err(e) => {
                    let _ = writeln!(s.markdown, "| - | - | {} failed: {e} | - |", knob.label());
                }
            }
        }
        s.markdown.push('\n');
        if !fallbacks.is_empty() {
            let _ =
                writeln!(s.markdown, "Fallbacks (the chosen method failed at run time):\n\n{}\n", fallbacks.join("\n"));
        }
        let mut curves = vec![Curve {
            name: "computed (chosen method)".into(),
            points: pts.clone(),
            draw: Draw::LineMarkers,
            colour: None,
        }];
        let (lo, hi) = pts.iter().fold((f64::INFINITY, 0.0f64), |(a, b), p| (a.min(p.0), b.max(p.0)));
        let x_log = hi > 10.0 * lo;
        for (fname, form) in &forms {
            let n = 60;
            let pts: Vec<(f64, f64)> = (0..=n)
                .map(|i| {
                    let t = i as f64 / n as f64;
                    let x = if x_log { lo * (hi / lo).powf(t) } else { lo + (hi - lo) * t };
                    (x, form(x) / scale)
                })
                .collect();
            curves.push(Curve { name: fname.clone(), points: pts, draw: Draw::Dashed, colour: None });
        }
        let size_name =
            if matches!(scene.problem, SceneProblem::Sliding(_)) { "half-length l/L" } else { "half-width a/L" };
        s.charts.push(Chart {
            stem: format!("sweep_{name}"),
            title: format!("Load-size curve, {name}"),
            x_label: "load per punch P2 [units of E* x L]".into(),
            y_label: format!("contact {size_name} [-]"),
            x_log,
            y_log: x_log,
            curves,
            legend: Legend::UpperLeft,
        });
    }
    s
}
