//! Report section 4: stability maps from actual runs. Problem 1: lambda vs theta for the
//! parabola and the sinusoid (up to high load); Problem 2: lambda vs nu. Each cell runs every
//! method; its digits are judged against the verified MPFR run of the same cell (whose own
//! digits are its verified ones). A cell is "failed" when the method returned an error (no
//! solution, no convergence, contact outside (-L/2, L/2), load above the sinusoid's maximum,
//! ill-conditioning).

use super::calibration::rational;
use super::chart::{Chart, Curve, Draw, Legend};
use super::runner::{self, Knob, Outcome};
use super::section::{fmt_digits, Ctx, Profile, Section};
use crate::model::{AdhesionProblem, AdhesionSize, Exact, Material, Period, PunchShape, SlidingProblem};
use crate::scene::SceneProblem;
use exact_series::Q;
use std::fmt::Write as _;

/// Digit bins of the maps.
const BINS: [&str; 5] = [">= 12 digits", "6 to 12 digits", "< 6 digits", "failed", "no reference"];
/// Palette indices of the bins (green, orange, red, grey, purple), the same in every map.
const BIN_COLOURS: [usize; 5] = [2, 3, 1, 7, 4];

fn bin(d: Result<Option<f64>, ()>) -> usize {
    match d {
        Err(()) => 3,
        Ok(None) => 4,
        Ok(Some(x)) if x >= 12.0 => 0,
        Ok(Some(x)) if x >= 6.0 => 1,
        Ok(Some(_)) => 2,
    }
}

fn q(n: i64, d: i64) -> Exact {
    Q::new(n.into(), d.into())
}

/// Problem 1 at nu = 0.3, E* = 1, L = 1 with theta set by wear (theta > 0: cW = 2 tan(pi theta))
/// or friction (theta < 0: mu = tan(pi |theta|)/beta), kappa = E* cW/2 - beta mu [2.8].
fn sliding_at(shape: PunchShape, theta: f64, p2: f64) -> Option<SlidingProblem> {
    let material = Material::from_contact_modulus(q(3, 10), q(1, 1)).ok()?;
    let beta = crate::numerics::exact::to_f64(&material.beta())?;
    let t = (std::f64::consts::PI * theta.abs()).tan();
    let (mu, cw) = if theta < 0.0 { (rational(t / beta), q(0, 1)) } else { (q(0, 1), rational(2.0 * t)) };
    SlidingProblem::builder()
        .material(material)
        .period(Period::Finite(q(1, 1)))
        .shape(shape)
        .friction(mu)
        .wear(cw)
        .normal_load(Q::new(((p2 * 1e12).round() as i64).into(), 1_000_000_000_000i64.into()))
        .build()
        .ok()
}

struct Cell {
    x: f64,
    lambda: f64,
    /// Per method: Err(()) failed, Ok(None) unjudged, Ok(Some(d)) digits.
    digits: Vec<Result<Option<f64>, ()>>,
    why: Vec<Option<String>>,
}

fn run_cell(ctx: &mut Ctx, problem: &SceneProblem, knobs: &[Knob], x: f64, lambda_target: f64) -> Cell {
    let reference_knob = knobs[knobs.len() - 1];
    let reference: Result<Outcome, String> = runner::run(problem, reference_knob, &mut ctx.cache);
    let given = runner::given_size(problem);
    let mut digits = Vec::new();
    let mut why = Vec::new();
    let ref_ok = reference.as_ref().ok().filter(|r| r.verified_digits.unwrap_or(0.0) >= 2.0);
    for &k in &knobs[..knobs.len() - 1] {
        match runner::run(problem, k, &mut ctx.cache) {
            Ok(o) => {
                digits.push(Ok(ref_ok.map(|r| runner::digits_of(runner::error(&o, r, given), 16.0))));
                why.push(None);
            }
            Err(e) => {
                digits.push(Err(()));
                why.push(Some(e));
            }
        }
    }
    match &reference {
        Ok(r) => {
            digits.push(Ok(r.verified_digits));
            why.push(None);
        }
        Err(e) => {
            digits.push(Err(()));
            why.push(Some(e.clone()));
        }
    }
    let lambda = reference.as_ref().map(|r| r.lambda).unwrap_or(lambda_target);
    Cell { x, lambda, digits, why }
}

fn map_section(s: &mut Section, stem: &str, title: &str, x_name: &str, knobs: &[Knob], cells: &[Cell]) {
    let _ = writeln!(s.markdown, "### {title}\n");
    let mut head = format!("| {x_name} | lambda |");
    let mut rule = "|---:|---:|".to_string();
    for k in knobs {
        head.push_str(&format!(" {} |", k.label()));
        rule.push_str("---:|");
    }
    let _ = writeln!(s.markdown, "{head}\n{rule}");
    let mut failures = Vec::new();
    for c in cells {
        let mut row = format!("| {:.3} | {:.4} |", c.x, c.lambda);
        for (i, d) in c.digits.iter().enumerate() {
            let cell = match d {
                Ok(Some(x)) => fmt_digits(Some(*x)),
                Ok(None) => "unjudged".into(),
                Err(()) => "fail".into(),
            };
            row.push_str(&format!(" {cell} |"));
            if let Some(w) = &c.why[i] {
                failures.push(format!(
                    "{} at {x_name} = {:.3}, lambda ~ {:.3}: {}",
                    knobs[i].label(),
                    c.x,
                    c.lambda,
                    w
                ));
            }
        }
        let _ = writeln!(s.markdown, "{row}");
    }
    s.markdown.push('\n');
    if !failures.is_empty() {
        let _ = writeln!(s.markdown, "Failures, as the methods reported them:\n");
        for f in failures {
            let _ = writeln!(s.markdown, "- {f}");
        }
        s.markdown.push('\n');
    }
    for (i, k) in knobs.iter().enumerate() {
        let stem_i = format!("{stem}_{}", k.method());
        let curves = BINS
            .iter()
            .enumerate()
            .map(|(b, name)| Curve {
                name: name.to_string(),
                points: cells.iter().filter(|c| bin(c.digits[i]) == b).map(|c| (c.x, c.lambda)).collect(),
                draw: Draw::Markers,
                colour: Some(BIN_COLOURS[b]),
            })
            .filter(|c| !c.points.is_empty())
            .collect();
        let _ = writeln!(s.markdown, "![{title}: {}]({stem_i}.svg) (data: `{stem_i}.csv`)\n", k.label());
        s.charts.push(Chart {
            stem: stem_i,
            title: format!("{title}: {}", k.label()),
            x_label: format!("{x_name} [-]"),
            // Problem 2 maps have nu on the x axis; their contact size is the half-width a.
            y_label: if x_name == "nu" { "lambda = pi a/L [-]".into() } else { "lambda = pi l/L [-]".into() },
            x_log: false,
            y_log: false,
            curves,
            legend: Legend::Above,
        });
    }
}

/// Builds section 4.
pub fn section(ctx: &mut Ctx) -> Section {
    let full = ctx.profile == Profile::Full;
    let mut s = Section::default();
    let _ = writeln!(
        s.markdown,
        "## 4. Stability maps\n\n\
         Every cell is an actual run of every method. Digits of the series and of f64 are judged against the \
         verified MPFR run of the same cell (capped at 16); the MPFR column shows its own verified digits \
         (two runs). \"fail\": the method returned an error (listed below each table); \"unjudged\": the \
         reference failed. Problem 1 cells: nu = 0.3, E* = 1, L = 1, theta set by wear (theta > 0) or Coulomb \
         friction (theta < 0), the load from Kuznetsov's (parabola) or Westergaard's (sinusoid) law at the grid \
         lambda; the lambda shown is the computed one.\n"
    );
    let sliding_knobs = [Knob::Series(12), Knob::F64(None), Knob::MpfrVerified(30)];
    let (thetas, lambdas): (Vec<f64>, Vec<f64>) = if full {
        (vec![-0.4, -0.2, 0.0, 0.2, 0.4], vec![0.1, 0.4, 0.7, 1.0, 1.3, 1.5])
    } else {
        (vec![-0.2, 0.2], vec![0.3])
    };
    let mut cells = Vec::new();
    for &lam in &lambdas {
        for &th in &thetas {
            ctx.step(format!("stability, parabola: theta = {th}, lambda = {lam}"));
            // Kuznetsov [2.15] with E* = k = L = 1: P2 = ln sec(lambda)/pi.
            let p2 = (1.0 / lam.cos()).ln() / std::f64::consts::PI;
            if let Some(p) = sliding_at(PunchShape::Parabolic { k: q(1, 1) }, th, p2) {
                cells.push(run_cell(ctx, &SceneProblem::Sliding(p), &sliding_knobs, th, lam));
            }
        }
    }
    map_section(&mut s, "stability_p1_parabola", "Problem 1, parabola (k = 1)", "theta", &sliding_knobs, &cells);
    let (thetas, lambdas): (Vec<f64>, Vec<f64>) =
        if full { (vec![-0.2, 0.0, 0.2], vec![0.3, 0.7, 1.1, 1.4]) } else { (vec![0.2], vec![1.1]) };
    let mut cells = Vec::new();
    for &lam in &lambdas {
        for &th in &thetas {
            ctx.step(format!("stability, sinusoid: theta = {th}, lambda = {lam}"));
            // Westergaard [2.17] with E* = L = 1, D = 1/100: P2 = pi D sin^2(lambda).
            let p2 = std::f64::consts::PI * 0.01 * lam.sin().powi(2);
            if let Some(p) = sliding_at(PunchShape::Sinusoidal { amplitude: q(1, 100) }, th, p2) {
                cells.push(run_cell(ctx, &SceneProblem::Sliding(p), &sliding_knobs, th, lam));
            }
        }
    }
    map_section(
        &mut s,
        "stability_p1_sinusoid",
        "Problem 1, sinusoid (D = 1/100), up to high load",
        "theta",
        &sliding_knobs,
        &cells,
    );
    let adhesion_knobs = [Knob::F64(None), Knob::MpfrVerified(20)];
    let (nus, lambdas): (Vec<(i64, i64)>, Vec<f64>) = if full {
        (vec![(0, 1), (3, 20), (3, 10), (9, 20), (1, 2)], vec![0.2, 0.5, 0.8, 1.1, 1.4])
    } else {
        (vec![(3, 10)], vec![0.4])
    };
    let mut cells = Vec::new();
    for &lam in &lambdas {
        for &(n, d) in &nus {
            let nu = n as f64 / d as f64;
            ctx.step(format!("stability, adhesion: nu = {nu}, lambda = {lam}"));
            let Ok(material) = Material::from_contact_modulus(q(n, d), q(1, 1)) else { continue };
            let Ok(p) = AdhesionProblem::new(
                material,
                Period::Finite(q(1, 1)),
                PunchShape::Parabolic { k: q(1, 1) },
                AdhesionSize::HalfWidth(rational(lam / std::f64::consts::PI)),
            ) else {
                continue;
            };
            cells.push(run_cell(ctx, &SceneProblem::Adhesion(p), &adhesion_knobs, nu, lam));
        }
    }
    let _ = writeln!(s.markdown, "Problem 2 exact series: {}\n", super::sweeps::adhesion_series_note());
    map_section(&mut s, "stability_p2", "Problem 2, parabola (k = 1, L = 1)", "nu", &adhesion_knobs, &cells);
    s
}
