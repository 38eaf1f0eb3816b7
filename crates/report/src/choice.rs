//! Report section on method choice: for each scene, the method chosen for its accuracy target
//! from the calibration table ([`super::calibration::choose`]), why, and a check by actual runs:
//! the chosen method meets the target and the next cheaper one does not.

use super::calibration::{choose, Choice, Table};
use super::runner::{self, Knob, RunCache};
use super::section::{fmt_digits, Ctx, Section};
use periodic_contact::scene::{Scene, SceneProblem};
use std::fmt::Write as _;

/// Target when a scene states neither `target_digits` nor `digits`.
pub const DEFAULT_TARGET: u32 = 10;

/// What a scene asks: `Ok(target)` to choose, `Err(digits)` when `digits` forces MPFR.
pub fn target_of(scene: &Scene) -> Result<u32, u32> {
    match (scene.output.target_digits, scene.output.digits) {
        (Some(t), _) => Ok(t),
        (None, Some(d)) => Err(d),
        (None, None) => Ok(DEFAULT_TARGET),
    }
}

/// Actual digits of the chosen method and of the next cheaper one, against a reference MPFR run
/// at `target + 20` digits.
#[derive(Debug, Clone, PartialEq)]
pub struct ChoiceCheck {
    /// The choice.
    pub choice: Choice,
    /// Digits reached by the chosen method (None: it failed).
    pub chosen_digits: Option<f64>,
    /// Digits reached by the next cheaper method (None: none, or it failed).
    pub cheaper_digits: Option<f64>,
}

impl ChoiceCheck {
    /// The chosen method meets the target.
    pub fn chosen_meets(&self) -> bool {
        self.chosen_digits.is_some_and(|d| d >= self.choice.target as f64)
    }
    /// The next cheaper method (if any) does not.
    pub fn cheaper_misses(&self) -> bool {
        self.choice.next_cheaper().is_none() || !self.cheaper_digits.is_some_and(|d| d >= self.choice.target as f64)
    }
}

/// Chooses and checks by running.
pub fn check_choice(
    table: &Table,
    problem: &SceneProblem,
    target: u32,
    cache: &RunCache,
) -> Result<ChoiceCheck, String> {
    let choice = choose(table, problem, target);
    let reference = runner::run(problem, Knob::Mpfr(target + 20), cache)?;
    let given = runner::given_size(problem);
    let digits = |k: Knob, cache: &RunCache| {
        runner::run(problem, k, cache).ok().map(|o| {
            let d = runner::digits_of(runner::error(&o, &reference, given), (target + 20) as f64);
            // Verified MPFR claims no more than it verified.
            o.verified_digits.map_or(d, |v| d.min(v.max(target as f64)))
        })
    };
    let chosen_digits = digits(choice.knob(), cache);
    let cheaper_digits = choice.next_cheaper().and_then(|k| digits(k, cache));
    Ok(ChoiceCheck { choice, chosen_digits, cheaper_digits })
}

/// Builds the method-choice section.
pub fn section(ctx: &Ctx, scenes: &[(String, Scene)]) -> Section {
    let mut s = Section::default();
    let _ = writeln!(
        s.markdown,
        "## 2. Method choice by accuracy target\n\n\
         Each scene's `[output] target_digits` (default {DEFAULT_TARGET}; `digits` instead forces MPFR at that \
         precision) selects the cheapest method predicted to meet it by the committed calibration table \
         `calibration/methods.csv` (machine: {}; regenerate with `periodic-contact calibrate`). The prediction \
         is a heuristic: digits interpolated in ln(lambda) between calibrated sizes, series extrapolated below \
         them with slope N + 2 (see `src/report/calibration.rs`). Check: the chosen method and the next cheaper \
         candidate are run and compared with an MPFR run at target + 20 digits.\n\n\
         | scene | lambda (est.) | target | chosen | achieved | next cheaper | achieved | chosen meets, cheaper misses |\n\
         |---|---:|---:|---|---:|---|---:|---|",
        if ctx.table.machine.is_empty() { "unstated" } else { ctx.table.machine.as_str() }
    );
    let mut whys = Vec::new();
    for (name, scene) in scenes {
        ctx.step(format!("method choice: {name}"));
        if matches!(scene.problem, SceneProblem::LoadingLaw(_)) {
            let _ =
                writeln!(s.markdown, "| `{name}` | - | - | {} | - | - | - | - |", runner::LOADING_LAW_NOT_IN_REPORT);
            continue;
        }
        match target_of(scene) {
            Err(d) => {
                let _ = writeln!(
                    s.markdown,
                    "| `{name}` | {:.4} | {d} (forced `digits`) | {} | - | - | - | forced |",
                    super::calibration::lambda_estimate(&scene.problem),
                    Knob::MpfrVerified(d).label()
                );
            }
            Ok(t) => match check_choice(&ctx.table, &scene.problem, t, &ctx.cache) {
                Ok(c) => {
                    let _ = writeln!(
                        s.markdown,
                        "| `{name}` | {:.4} | {t} | {} | {} | {} | {} | {} |",
                        c.choice.lambda,
                        c.choice.knob().label(),
                        fmt_digits(c.chosen_digits),
                        c.choice.next_cheaper().map_or("none".into(), |k| k.label()),
                        if c.choice.next_cheaper().is_some() { fmt_digits(c.cheaper_digits) } else { "-".into() },
                        match (c.chosen_meets(), c.cheaper_misses()) {
                            (true, true) => "yes",
                            (true, false) => "no: a cheaper method would do",
                            (false, _) => "no: the chosen method misses",
                        }
                    );
                    whys.push(format!("- `{name}`: {}.", c.choice.why()));
                }
                Err(e) => {
                    let _ = writeln!(s.markdown, "| `{name}` | - | {t} | reference failed: {e} | - | - | - | - |");
                }
            },
        }
    }
    let _ = writeln!(s.markdown, "\nWhy:\n\n{}\n", whys.join("\n"));
    s
}
