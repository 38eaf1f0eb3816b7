//! Report section 3: convergence orders of the exact series against the high-precision solution,
//! per scene and number of corrections m: the remainder after m corrections must scale like
//! Lambda^(2m+2) (docs/theory.md section 5). Scenes in the `periodic` convention (docs/theory.md section 8)
//! have series in every power of Lambda: keeping every term through Lambda^m, the centre's
//! remainder scales like Lambda^(m+1) and the parabola's l (even in Lambda) like Lambda^(m+1) for
//! odd m, Lambda^(m+2) for even m; they are studied at smaller Lambda, where the slope settles
//! (as in `tests/all/convergence_orders_periodic.rs`). Reuses [`periodic_contact::verification::convergence`].

use super::section::{Ctx, Profile, Section};
use periodic_contact::model::OnPunchRow;
use periodic_contact::model::{Convention, Period, PunchShape, SlidingLoad};
use periodic_contact::scene::{Scene, SceneProblem};
use periodic_contact::verification::convergence::sliding_convergence;
use std::fmt::Write as _;
use std::time::Instant;

/// Whether the study applies: a periodic parabola at a given load (the sinusoid's shape changes
/// with L, so fixing P2 and varying L does not isolate Lambda).
fn applies(scene: &Scene) -> bool {
    matches!(&scene.problem, SceneProblem::Sliding(p)
        if matches!(p.shape(), PunchShape::Parabolic { .. })
        && matches!(p.period(), Period::Finite(_))
        && matches!(p.load(), SlidingLoad::NormalLoad(_)))
}

/// Lambda values, number of corrections (`paper`: m = 1..=n; `periodic`: m = 1..=2n) and MPFR
/// digits of one study.
type Plan = (&'static [f64], usize, u32);

fn plan(profile: Profile, convention: Convention) -> Plan {
    match (profile, convention) {
        (Profile::Full, Convention::Paper) => (&[0.03, 0.042, 0.06, 0.085], 5, 50),
        (Profile::Fast, Convention::Paper) => (&[0.04, 0.06], 2, 30),
        // The pairs of terms Lambda^(m+1), Lambda^(m+2) are of similar size: a smaller Lambda lets
        // the slope settle (tests/all/convergence_orders_periodic.rs: within 0.1 at these values).
        (Profile::Full, Convention::PeriodicSurface) => (&[0.01, 0.014, 0.02, 0.028], 4, 60),
        (Profile::Fast, Convention::PeriodicSurface) => (&[0.01, 0.014], 1, 30),
    }
}

/// Builds section 3 for the scenes.
pub fn section(ctx: &Ctx, scenes: &[(String, Scene)]) -> Section {
    let (lambdas, corrections, digits) = plan(ctx.profile, Convention::Paper);
    let (p_lambdas, p_corrections, p_digits) = plan(ctx.profile, Convention::PeriodicSurface);
    let mut s = Section::default();
    // The summary's headline: rows, and the worst gap between observed and predicted orders of l
    // and c (scene, m, observed, predicted).
    let mut rows = 0usize;
    let mut worst_l: Option<(f64, String)> = None;
    let mut worst_c: Option<(f64, String)> = None;
    let note = |worst: &mut Option<(f64, String)>, name: &str, m: usize, observed: f64, predicted: f64| {
        let gap = (observed - predicted).abs();
        if worst.as_ref().is_none_or(|(g, _)| gap > *g) {
            *worst = Some((gap, format!("`{name}`, m = {m}: {observed:.2} vs {predicted}")));
        }
    };
    let md = &mut s.markdown;
    let _ = writeln!(
        md,
        "## 3. Convergence orders: series against the high-precision solution\n\n\
         At the scene's load P2, the period L is varied so that Lambda = pi l_s/L takes the values {lambdas:?}; \
         the series truncated after m corrections (every term through Lambda^(2m)) is compared with the MPFR \
         solution at {digits} digits. Observed order = least-squares slope of log(remainder) against \
         log(Lambda); predicted 2m + 2. Remainders are relative to l_s. The centre's order is shown when the \
         centre does not vanish (theta != 0 or tau0 > 0).\n\n\
         Scenes in the `periodic` convention (docs/theory.md section 8; section 7 below) have series in every power \
         of Lambda: row m keeps every term through Lambda^m (m = 1..{}), compared with the `periodic` MPFR \
         solution at {p_digits} digits at Lambda = {p_lambdas:?} (smaller: consecutive terms are of similar \
         size, and the slope needs a smaller Lambda to settle). Predicted: m + 1 for the centre; for the \
         parabola's l (even in Lambda) m + 1 for odd m and m + 2 for even m.\n",
        2 * p_corrections
    );
    for (name, scene) in scenes {
        if !applies(scene) {
            continue;
        }
        let SceneProblem::Sliding(p) = &scene.problem else { continue };
        ctx.step(format!("convergence orders: {name}"));
        let t0 = Instant::now();
        let periodic = p.convention() == Convention::PeriodicSurface;
        let (lams, corr, dig) =
            if periodic { (p_lambdas, p_corrections, p_digits) } else { (lambdas, corrections, digits) };
        match sliding_convergence(name, p, lams, corr, dig) {
            Ok(study) => {
                // `periodic`: every power of Lambda, both predicted orders; `paper`: even powers.
                let _ = if periodic {
                    writeln!(
                        md,
                        "### Scene `{name}`, convention `periodic` (theta = {:.6}, T = {:.6})\n\n\
                         | m (through Lambda^m) | predicted (c) | observed (c) | predicted (l) | observed (l) | remainder of l / l_s |\n\
                         |---:|---:|---:|---:|---:|---|",
                        study.theta, study.t
                    )
                } else {
                    writeln!(
                        md,
                        "### Scene `{name}` (theta = {:.6}, T = {:.6})\n\n\
                         | m | predicted order | observed (l) | observed (c) | remainder of l / l_s |\n|---:|---:|---:|---:|---|",
                        study.theta, study.t
                    )
                };
                for r in &study.rows {
                    rows += 1;
                    note(&mut worst_l, name, r.corrections, r.observed_l, r.predicted_l);
                    if let Some(c) = r.observed_c {
                        note(&mut worst_c, name, r.corrections, c, r.predicted);
                    }
                    let (m, predicted, (lo, hi)) = (r.corrections, r.predicted, r.remainder_range);
                    let c = r.observed_c.map_or("-".into(), |c| format!("{c:.3}"));
                    let _ = if periodic {
                        writeln!(
                            md,
                            "| {m} | {predicted} | {c} | {} | {:.3} | {lo:.1e} .. {hi:.1e} |",
                            r.predicted_l, r.observed_l
                        )
                    } else {
                        writeln!(md, "| {m} | {predicted} | {:.3} | {c} | {lo:.1e} .. {hi:.1e} |", r.observed_l)
                    };
                }
                md.push('\n');
            }
            Err(e) => {
                let _ = writeln!(md, "### Scene `{name}`\n\nThe study failed: {e}\n");
            }
        }
        let _ = writeln!(s.timings, "| convergence orders, `{name}` | {:.2} |", t0.elapsed().as_secs_f64());
    }
    let _ = writeln!(s.markdown, "### Problem 2\n\n{}\n", super::sweeps::adhesion_series_note());
    if let Some((gap, at)) = &worst_l {
        let c = worst_c.as_ref().map_or(String::new(), |(g, at)| format!("; of c within {g:.2} (worst {at})"));
        s.findings.push(format!(
            "Convergence orders (section 3): {rows} rows; observed order of l within {gap:.2} of the predicted \
             (worst {at}){c}."
        ));
    }
    s
}
