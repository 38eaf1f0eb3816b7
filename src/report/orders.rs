//! Report section 2: convergence orders of the exact series against the high-precision solution,
//! per scene and number of corrections m: the remainder after m corrections must scale like
//! Lambda^(2m+2) (THEORY.md section 5). Reuses [`crate::verification::convergence`].

use super::section::{Ctx, Profile, Section};
use crate::model::{Period, PunchShape, SlidingLoad};
use crate::scene::{Scene, SceneProblem};
use crate::verification::convergence::sliding_convergence;
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

/// Builds section 2 for the scenes.
pub fn section(ctx: &mut Ctx, scenes: &[(String, Scene)]) -> Section {
    let (lambdas, corrections, digits): (&[f64], usize, u32) = match ctx.profile {
        Profile::Full => (&[0.03, 0.042, 0.06, 0.085], 5, 50),
        Profile::Fast => (&[0.04, 0.06], 2, 30),
    };
    let mut s = Section::default();
    let md = &mut s.markdown;
    let _ = writeln!(
        md,
        "## 2. Convergence orders: series against the high-precision solution\n\n\
         At the scene's load P2, the period L is varied so that Lambda = pi l_s/L takes the values {lambdas:?}; \
         the series truncated after m corrections (every term through Lambda^(2m)) is compared with the MPFR \
         solution at {digits} digits. Observed order = least-squares slope of log(remainder) against \
         log(Lambda); predicted 2m + 2. Remainders are relative to l_s. The centre's order is shown when the \
         centre does not vanish (theta != 0 or tau0 > 0).\n"
    );
    for (name, scene) in scenes {
        if !applies(scene) {
            continue;
        }
        let SceneProblem::Sliding(p) = &scene.problem else { continue };
        ctx.step(format!("convergence orders: {name}"));
        let t0 = Instant::now();
        match sliding_convergence(name, p, lambdas, corrections, digits) {
            Ok(study) => {
                let _ = writeln!(
                    md,
                    "### Scene `{name}` (theta = {:.6}, T = {:.6})\n\n\
                     | m | predicted order | observed (l) | observed (c) | remainder of l / l_s |\n|---:|---:|---:|---:|---|",
                    study.theta, study.t
                );
                for r in &study.rows {
                    let _ = writeln!(
                        md,
                        "| {} | {} | {:.3} | {} | {:.1e} .. {:.1e} |",
                        r.corrections,
                        r.predicted,
                        r.observed_l,
                        r.observed_c.map_or("-".into(), |c| format!("{c:.3}")),
                        r.remainder_range.0,
                        r.remainder_range.1
                    );
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
    s
}
