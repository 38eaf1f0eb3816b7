//! Report section 4: speed against accuracy. One chart per problem: relative error (against a
//! high-precision reference run) vs wall time, one curve per method, points along its knob
//! (series order, f64 nodes, MPFR digits). Errors go into the Markdown; times only into the
//! charts, their CSV and `timings.md`.

use super::calibration::{adhesion_case, sliding_case};
use super::chart::{Chart, Curve, Draw, Legend};
use super::runner::{self, Knob};
use super::section::{Ctx, Profile, Section};
use periodic_contact::scene::SceneProblem;
use std::fmt::Write as _;

/// Floor of the error axis: errors below it (exact agreement at the reference's precision) are
/// drawn at it.
const ERROR_FLOOR: f64 = 1e-70;

struct Study {
    problem: &'static str,
    title: String,
    case: SceneProblem,
    reference: Knob,
    families: Vec<(&'static str, Vec<Knob>)>,
}

/// Builds section 4.
pub fn section(ctx: &Ctx) -> Section {
    let full = ctx.profile == Profile::Full;
    let big_lambda = 0.4;
    let lambda2 = 0.8;
    let studies = vec![
        Study {
            problem: "sliding",
            title: format!("Problem 1: parabola, nu = 0.3, mu = 0.3, Lambda = {big_lambda}"),
            case: SceneProblem::Sliding(sliding_case(big_lambda)),
            reference: Knob::Mpfr(if full { 100 } else { 50 }),
            families: vec![
                (
                    "series (order 2..16)",
                    if full {
                        (1..=8).map(|m| Knob::Series(2 * m)).collect()
                    } else {
                        vec![Knob::Series(4), Knob::Series(8)]
                    },
                ),
                (
                    "f64 collocation (nodes 4..96)",
                    if full {
                        [4, 8, 12, 16, 24, 32, 48, 64, 96].map(|n| Knob::F64(Some(n))).to_vec()
                    } else {
                        vec![Knob::F64(Some(8)), Knob::F64(Some(32))]
                    },
                ),
                (
                    "MPFR (digits 10..80)",
                    if full {
                        [10, 20, 40, 60, 80].map(Knob::Mpfr).to_vec()
                    } else {
                        vec![Knob::Mpfr(10), Knob::Mpfr(20)]
                    },
                ),
            ],
        },
        Study {
            problem: "adhesion",
            title: format!("Problem 2: parabola, nu = 0.3, lambda = {lambda2}"),
            case: SceneProblem::Adhesion(adhesion_case(lambda2)),
            reference: Knob::Mpfr(if full { 48 } else { 30 }),
            families: vec![
                (
                    "exact series (order 2..12)",
                    if full {
                        (1..=6).map(|m| Knob::Series(2 * m)).collect()
                    } else {
                        vec![Knob::Series(4), Knob::Series(8)]
                    },
                ),
                ("f64 lambda^2-series method", vec![Knob::F64(None)]),
                (
                    "MPFR Volterra (digits 8..32)",
                    if full {
                        [8, 12, 16, 24, 32].map(Knob::Mpfr).to_vec()
                    } else {
                        vec![Knob::Mpfr(8), Knob::Mpfr(16)]
                    },
                ),
            ],
        },
    ];
    let mut s = Section::default();
    let _ = writeln!(
        s.markdown,
        "## 4. Speed against accuracy\n\n\
         Error = max(|dl|, |dc|)/l (Problem 1, load given) or |dP2|/P2 (Problem 2, a given) against a reference \
         MPFR run at higher precision; wall time of one run on this machine (times: charts, their CSV and \
         `timings.md`; they are not in this text). The series' time excludes the one-off exact derivation of \
         its coefficients. MPFR here is one run at the precision and node count for the digits asked (`solve` \
         adds a second, verifying run). Errors below 1e-70 (agreement to the reference's last digit) are drawn at \
         1e-70. The Problem 2 series is P2 = C_P E* k a^2 (1 + c_2 lambda^2 + ...) [3.18] with its exact \
         coefficients evaluated at nu.\n"
    );
    for st in studies {
        ctx.step(format!("speed vs accuracy: {}", st.problem));
        let given = runner::given_size(&st.case);
        let reference = match runner::run(&st.case, st.reference, &ctx.cache) {
            Ok(r) => r,
            Err(e) => {
                let _ = writeln!(s.markdown, "{}: the reference run failed: {e}\n", st.title);
                continue;
            }
        };
        let _ = writeln!(
            s.markdown,
            "### {} (reference: {}, lambda = {:.6})\n\n![{}](speed_{}.svg) (data: `speed_{}.csv`)\n\n| method | knob | error | digits |\n|---|---:|---:|---:|",
            st.title,
            st.reference.label(),
            reference.lambda,
            st.title,
            st.problem,
            st.problem
        );
        let _ = writeln!(
            s.timings,
            "\n### Speed against accuracy, {}\n\n| method | knob | error | seconds |\n|---|---:|---:|---:|",
            st.title
        );
        let mut curves = Vec::new();
        for (name, knobs) in &st.families {
            let mut pts = Vec::new();
            for &k in knobs {
                ctx.step(format!("speed vs accuracy: {} {}", st.problem, k.label()));
                match runner::run(&st.case, k, &ctx.cache) {
                    Ok(o) => {
                        let err = runner::error(&o, &reference, given);
                        let _ = writeln!(
                            s.markdown,
                            "| {} | {} | {:.2e} | {} |",
                            k.method(),
                            k.value(),
                            err,
                            periodic_contact::numerics::accuracy::digits_text(runner::digits_of(err, 70.0))
                        );
                        let _ =
                            writeln!(s.timings, "| {} | {} | {:.2e} | {:.3e} |", k.method(), k.value(), err, o.seconds);
                        pts.push((o.seconds.max(1e-7), err.max(ERROR_FLOOR)));
                    }
                    Err(e) => {
                        let _ = writeln!(s.markdown, "| {} | {} | failed: {} | - |", k.method(), k.value(), e);
                    }
                }
            }
            curves.push(Curve { name: name.to_string(), points: pts, draw: Draw::LineMarkers, colour: None });
        }
        s.markdown.push('\n');
        s.charts.push(Chart {
            stem: format!("speed_{}", st.problem),
            title: format!("Speed vs accuracy, {}", st.title),
            x_label: "wall time of one run [s]".into(),
            y_label: if given {
                "relative error of P2 [-]".into()
            } else {
                "relative error max(|dl|,|dc|)/l [-]".into()
            },
            x_log: true,
            y_log: true,
            curves,
            legend: Legend::UpperRight,
        });
    }
    s
}
