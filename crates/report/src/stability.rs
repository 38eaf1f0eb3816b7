//! Report section 5: stability maps from actual runs. Problem 1: lambda vs theta for the
//! parabola and the sinusoid (up to high load), on the same grid in both surface conventions
//! `paper` and `periodic` (docs/theory.md section 8), side by side; Problem 2: lambda vs nu (the same
//! in both conventions). Each cell runs every method; its digits are judged against the verified
//! MPFR run of the same cell (whose own digits are its verified ones). A cell is "failed" when the
//! method returned an error (no solution, no convergence, not physical, contact outside
//! (-L/2, L/2), load above the sinusoid's maximum, ill-conditioning): the error is listed as the
//! method stated it.

use super::calibration::rational;
use super::chart::{Chart, Curve, Draw, Legend};
use super::runner::{self, Knob, Outcome, RunCache};
use super::section::{fmt_digits, Ctx, Profile, Section};
use exact_series::Q;
use periodic_contact::model::{
    AdhesionProblem, AdhesionSize, Convention, Exact, Material, Period, PunchShape, SlidingProblem,
};
use periodic_contact::scene::SceneProblem;
use std::fmt::Write as _;

/// Digit bins of the maps.
const BINS: [&str; 5] = [">= 12 digits", "6 to 12 digits", "< 6 digits", "failed", "no reference"];
/// Palette indices of the bins (green, orange, red, grey, purple), the same in every map.
const BIN_COLOURS: [usize; 5] = [2, 3, 1, 7, 4];

/// The bin of a cell: Err(()) failed, Ok(None) unjudged, Ok(Some(d)) by its digits d.
pub(crate) fn bin(d: Result<Option<f64>, ()>) -> usize {
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
/// or friction (theta < 0: mu = tan(pi |theta|)/beta), kappa = E* cW/2 - beta mu [2.8], in the
/// surface convention `convention`.
fn sliding_at(shape: PunchShape, theta: f64, p2: f64, convention: Convention) -> Option<SlidingProblem> {
    let material = Material::from_contact_modulus(q(3, 10), q(1, 1)).ok()?;
    let beta = periodic_contact::numerics::exact::to_f64(&material.beta())?;
    if p2.is_nan() || p2 <= 0.0 {
        return None;
    }
    let t = (std::f64::consts::PI * theta.abs()).tan();
    let (mu, cw) = if theta < 0.0 { (rational(t / beta), q(0, 1)) } else { (q(0, 1), rational(2.0 * t)) };
    SlidingProblem::builder()
        .material(material)
        .period(Period::Finite(q(1, 1)))
        .shape(shape)
        .friction(mu)
        .wear(cw)
        .normal_load(Q::new(((p2 * 1e12).round() as i64).into(), 1_000_000_000_000i64.into()))
        .convention(convention)
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

fn run_cell(cache: &RunCache, problem: &SceneProblem, knobs: &[Knob], x: f64, lambda_target: f64) -> Cell {
    let reference_knob = knobs[knobs.len() - 1];
    let reference: Result<Outcome, String> = runner::run(problem, reference_knob, cache);
    let given = runner::given_size(problem);
    let mut digits = Vec::new();
    let mut why = Vec::new();
    let ref_ok = reference.as_ref().ok().filter(|r| r.verified_digits.unwrap_or(0.0) >= 2.0);
    for &k in &knobs[..knobs.len() - 1] {
        match runner::run(problem, k, cache) {
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

fn cell_text(d: &Result<Option<f64>, ()>) -> String {
    match d {
        Ok(Some(x)) => fmt_digits(Some(*x)),
        Ok(None) => "unjudged".into(),
        Err(()) => "fail".into(),
    }
}

/// The failures of `cells`, one line each, as the methods reported them; `prefix` names the
/// convention (empty for Problem 2).
fn failures(prefix: &str, x_name: &str, knobs: &[Knob], cells: &[Cell]) -> Vec<String> {
    let mut out = Vec::new();
    for c in cells {
        for (i, w) in c.why.iter().enumerate() {
            if let Some(w) = w {
                out.push(format!(
                    "{prefix}{} at {x_name} = {:.3}, lambda ~ {:.3}: {w}",
                    knobs[i].label(),
                    c.x,
                    c.lambda
                ));
            }
        }
    }
    out
}

fn write_failures(s: &mut Section, lines: &[String]) {
    if !lines.is_empty() {
        let _ = writeln!(s.markdown, "Failures, as the methods reported them:\n");
        for f in lines {
            let _ = writeln!(s.markdown, "- {f}");
        }
        s.markdown.push('\n');
    }
}

/// The horizon lambda_h(nu, d) at the bins' boundaries d = 12, 6, 2 (docs/theory.md section 11,
/// [`periodic_contact::asymptotics::adhesion_mode::horizon`]): below each dashed curve complete
/// adhesion keeps d digits; nu in steps of 0.01 (pi/2 at nu = 1/2).
fn horizon_curves() -> Vec<Curve> {
    [(12.0, 0), (6.0, 1), (2.0, 2)]
        .into_iter()
        .map(|(d, b)| Curve {
            name: format!("lambda_h(nu, {d:.0}): {d:.0} digits kept below"),
            points: (0..=50)
                .filter_map(|i| {
                    let m = Material::from_contact_modulus(q(i, 100), q(1, 1)).ok()?;
                    Some((i as f64 / 100.0, periodic_contact::asymptotics::adhesion_mode::horizon_of(&m, d)))
                })
                .collect(),
            draw: Draw::Dashed,
            colour: Some(BIN_COLOURS[b]),
        })
        .collect()
}

/// One map per method: the cells binned by digits (legend: the bins); the Problem 2 maps also the
/// horizon's curves ([`horizon_curves`]).
fn map_chart(stem: &str, title: &str, x_name: &str, knob: &Knob, i: usize, cells: &[Cell]) -> Chart {
    let points: Vec<(f64, f64, usize)> = cells.iter().map(|c| (c.x, c.lambda, bin(c.digits[i]))).collect();
    binned_chart(stem, &format!("{title}: {}", knob.label()), x_name, &points)
}

/// A map of cells (x, lambda, [`bin`]) in the bins' colours; with `x_name` "nu" (Problem 2) also
/// the horizon's curves ([`horizon_curves`]). Shared with the map with friction
/// ([`super::friction_map`]), so that the two compare cell for cell.
pub(crate) fn binned_chart(stem: &str, title: &str, x_name: &str, points: &[(f64, f64, usize)]) -> Chart {
    let curves = BINS
        .iter()
        .enumerate()
        .map(|(b, name)| Curve {
            name: name.to_string(),
            points: points.iter().filter(|p| p.2 == b).map(|p| (p.0, p.1)).collect(),
            draw: Draw::Markers,
            colour: Some(BIN_COLOURS[b]),
        })
        .filter(|c| !c.points.is_empty())
        .chain(if x_name == "nu" { horizon_curves() } else { Vec::new() })
        .collect();
    Chart {
        stem: stem.to_string(),
        title: title.to_string(),
        x_label: format!("{x_name} [-]"),
        // Problem 2 maps have nu on the x axis; their contact size is the half-width a.
        y_label: if x_name == "nu" { "lambda = pi a/L [-]".into() } else { "lambda = pi l/L [-]".into() },
        x_log: false,
        y_log: false,
        curves,
        legend: Legend::Above,
    }
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
    for c in cells {
        let mut row = format!("| {:.3} | {:.4} |", c.x, c.lambda);
        for d in &c.digits {
            row.push_str(&format!(" {} |", cell_text(d)));
        }
        let _ = writeln!(s.markdown, "{row}");
    }
    s.markdown.push('\n');
    write_failures(s, &failures("", x_name, knobs, cells));
    for (i, k) in knobs.iter().enumerate() {
        let stem_i = format!("{stem}_{}", k.method());
        let _ = writeln!(s.markdown, "![{title}: {}]({stem_i}.svg) (data: `{stem_i}.csv`)\n", k.label());
        s.charts.push(map_chart(&stem_i, title, x_name, k, i, cells));
    }
}

/// One Problem 1 map in one convention: its knobs and cells.
struct ConventionMap {
    convention: Convention,
    knobs: Vec<Knob>,
    cells: Vec<Cell>,
}

/// Problem 1 maps of one shape on one grid in both conventions, side by side: one table (each
/// convention's computed lambda and digits per method), the failures of each convention, and per
/// method the `paper` and `periodic` maps beside each other.
fn map_section_conventions(s: &mut Section, stem: &str, title: &str, note: &str, maps: &[ConventionMap]) {
    let _ = writeln!(s.markdown, "### {title}\n");
    if !note.is_empty() {
        let _ = writeln!(s.markdown, "{note}\n");
    }
    let mut head = "| theta |".to_string();
    let mut rule = "|---:|".to_string();
    for m in maps {
        head.push_str(&format!(" `{}`: lambda |", m.convention.name()));
        rule.push_str("---:|");
        for k in &m.knobs {
            head.push_str(&format!(" {} |", k.label()));
            rule.push_str("---:|");
        }
    }
    let _ = writeln!(s.markdown, "{head}\n{rule}");
    let rows = maps.iter().map(|m| m.cells.len()).min().unwrap_or(0);
    for r in 0..rows {
        let mut row = format!("| {:.3} |", maps[0].cells[r].x);
        for m in maps {
            let c = &m.cells[r];
            row.push_str(&format!(" {:.4} |", c.lambda));
            for d in &c.digits {
                row.push_str(&format!(" {} |", cell_text(d)));
            }
        }
        let _ = writeln!(s.markdown, "{row}");
    }
    s.markdown.push('\n');
    let lines: Vec<String> = maps
        .iter()
        .flat_map(|m| failures(&format!("`{}`, ", m.convention.name()), "theta", &m.knobs, &m.cells))
        .collect();
    write_failures(s, &lines);
    let mut head = "| method |".to_string();
    let mut rule = "|---|".to_string();
    for m in maps {
        head.push_str(&format!(" `{}` |", m.convention.name()));
        rule.push_str("---|");
    }
    let _ = writeln!(s.markdown, "{head}\n{rule}");
    let methods = maps.iter().map(|m| m.knobs.len()).min().unwrap_or(0);
    let mut data = Vec::new();
    for i in 0..methods {
        let mut row = format!("| {} |", maps[0].knobs[i].method());
        for m in maps {
            let k = &m.knobs[i];
            let stem_i = format!("{stem}_{}_{}", m.convention.name(), k.method());
            let t = format!("{title}, {}", m.convention.name());
            row.push_str(&format!(" ![{t}: {}]({stem_i}.svg) |", k.label()));
            data.push(format!("`{stem_i}.csv`"));
            s.charts.push(map_chart(&stem_i, &t, "theta", k, i, &m.cells));
        }
        let _ = writeln!(s.markdown, "{row}");
    }
    let _ = writeln!(s.markdown, "\nData: {}.\n", data.join(", "));
}

/// Series order of the Problem 1 maps: 12, except the `periodic` sinusoid's 8 (its exact
/// derivation takes about 2.5 s through Lambda^8 and 100 s through Lambda^12, release build,
/// `cargo run --release --example expansion_timing`).
fn series_order(shape: &PunchShape, convention: Convention) -> usize {
    match (shape, convention) {
        (PunchShape::Sinusoidal { .. }, Convention::PeriodicSurface) => 8,
        _ => 12,
    }
}

/// The quartic punch of `scenes/quartic.toml`, g = x^2 + x^4/10 (docs/theory.md section 9): its
/// centred frictionless contact reaches the small-slope limit |g'| = 1/2
/// ([`periodic_contact::params::sliding::MAX_CONTACT_SLOPE`]) at a = 0.2470 L (lambda = 0.776, L = 1); beyond
/// it the solvers answer with the small-slope warning (docs/theory.md section 9), so its map shows
/// how the methods fare on a steep polynomial, moved by friction and wear.
fn quartic() -> PunchShape {
    PunchShape::Polynomial { coefficients: vec![q(0, 1), q(0, 1), q(1, 1), q(0, 1), q(1, 10)] }
}

/// The quartic's frictionless load at lambda (E* = L = 1): the closed form of docs/theory.md section 9
/// ([`periodic_contact::verification::closed_form_load`], 64 bits; NaN if it fails, and the cell is skipped).
fn quartic_load(lam: f64) -> f64 {
    use periodic_contact::verification::closed_form_load::{frictionless_load_mpfr, EvenSlope};
    let prec = 64;
    let one = rug::Float::with_val(prec, 1);
    let a = rug::Float::with_val(prec, lam / std::f64::consts::PI);
    EvenSlope::new(&quartic(), None, prec)
        .and_then(|s| frictionless_load_mpfr(&s, &one, &a, Some(&one), prec))
        .map_or(f64::NAN, |v| v.value.to_f64())
}

/// The knobs of a Problem 1 map of `shape` in `convention`: the series (parabola and sinusoid
/// only), f64, and the verified MPFR reference last.
fn p1_knobs(shape: &PunchShape, convention: Convention) -> Vec<Knob> {
    match shape {
        // The report's series are the parabola's and the sinusoid's.
        PunchShape::Polynomial { .. } | PunchShape::Circular { .. } => vec![Knob::F64(None), Knob::MpfrVerified(30)],
        _ => vec![Knob::Series(series_order(shape, convention)), Knob::F64(None), Knob::MpfrVerified(30)],
    }
}

/// One map to compute: its name (timings and progress), convention (Problem 1), knobs and cells.
struct MapPlan {
    name: &'static str,
    convention: Option<Convention>,
    knobs: Vec<Knob>,
    jobs: Vec<CellJob>,
}

/// One cell to run: the problem at grid point (x, lambda).
struct CellJob {
    problem: SceneProblem,
    x: f64,
    lambda: f64,
}

/// The cells of one Problem 1 map: the grid (`thetas` x `lambdas`, load of each lambda from
/// `load`) of `shape` in `convention`, rows by lambda.
fn p1_plan(
    shape: &PunchShape,
    name: &'static str,
    convention: Convention,
    grid: (&[f64], &[f64]),
    load: &dyn Fn(f64) -> f64,
) -> MapPlan {
    let mut jobs = Vec::new();
    for &lam in grid.1 {
        for &th in grid.0 {
            if let Some(p) = sliding_at(shape.clone(), th, load(lam), convention) {
                jobs.push(CellJob { problem: SceneProblem::Sliding(p), x: th, lambda: lam });
            }
        }
    }
    MapPlan { name, convention: Some(convention), knobs: p1_knobs(shape, convention), jobs }
}

/// The cells of the Problem 2 map: lambda vs nu, in `convention` (docs/theory.md section 8,
/// Problem 2: `paper` keeps the Flamant far field, `periodic` makes u periodic).
fn p2_plan(profile: Profile, knobs: &[Knob], convention: Convention) -> MapPlan {
    let (nus, lambdas): (Vec<(i64, i64)>, Vec<f64>) = if profile == Profile::Full {
        // nu and lambda fine enough to show the horizon's curves (lambda_h(nu, 12) = 0.84 .. 1.53).
        (vec![(0, 1), (1, 10), (1, 5), (3, 10), (2, 5), (1, 2)], vec![0.2, 0.5, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3, 1.4])
    } else {
        (vec![(3, 10)], vec![0.4])
    };
    let mut jobs = Vec::new();
    for &lam in &lambdas {
        for &(n, d) in &nus {
            let nu = n as f64 / d as f64;
            let Ok(material) = Material::from_contact_modulus(q(n, d), q(1, 1)) else { continue };
            let Ok(p) = AdhesionProblem::new(
                material,
                Period::Finite(q(1, 1)),
                PunchShape::Parabolic { k: q(1, 1) },
                AdhesionSize::HalfWidth(rational(lam / std::f64::consts::PI)),
            ) else {
                continue;
            };
            jobs.push(CellJob { problem: SceneProblem::Adhesion(p.with_convention(convention)), x: nu, lambda: lam });
        }
    }
    let name = if convention == Convention::Paper { "adhesion" } else { "adhesion, periodic" };
    MapPlan { name, convention: None, knobs: knobs.to_vec(), jobs }
}

/// Runs every cell of `plans` on the report's thread pool ([`super::parallel::map`]), the
/// largest grid lambda first (the costly cells: the verified MPFR runs need hundreds of nodes
/// near full contact); returns per plan its cells in grid order and the sum of their run times.
fn run_plans(ctx: &Ctx, plans: &[MapPlan]) -> Vec<(Vec<Cell>, f64)> {
    let all: Vec<(usize, &CellJob)> =
        plans.iter().enumerate().flat_map(|(m, p)| p.jobs.iter().map(move |j| (m, j))).collect();
    let done = super::parallel::map(
        &all,
        |(_, j)| j.lambda,
        |&(m, j)| {
            let plan = &plans[m];
            let conv = plan.convention.map_or(String::new(), |c| format!(", {}", c.name()));
            ctx.step(format!("stability, {}{conv}: x = {}, lambda = {}", plan.name, j.x, j.lambda));
            let t0 = std::time::Instant::now();
            let cell = run_cell(&ctx.cache, &j.problem, &plan.knobs, j.x, j.lambda);
            (m, cell, t0.elapsed().as_secs_f64())
        },
    );
    let mut out: Vec<(Vec<Cell>, f64)> = plans.iter().map(|_| (Vec::new(), 0.0)).collect();
    for (m, cell, secs) in done {
        out[m].0.push(cell);
        out[m].1 += secs;
    }
    out
}

fn timing_line(s: &mut Section, name: &str, map: &ConventionMap, seconds: f64) {
    let _ = writeln!(
        s.timings,
        "| stability map, {name}, `{}` ({} cells) | {seconds:.2} |",
        map.convention.name(),
        map.cells.len()
    );
}

/// Builds section 5. Every cell of every map is one job on the report's thread pool
/// (`run_plans`); the cells are collected in grid order, so the text does not depend on the
/// threads. Timings: per map the sum of its cells' run times (they overlap in wall time).
pub fn section(ctx: &Ctx) -> Section {
    let full = ctx.profile == Profile::Full;
    let mut s = Section::default();
    let _ = writeln!(
        s.markdown,
        "## 5. Stability maps\n\n\
         Every cell is an actual run of every method. Digits of the series and of f64 are judged against the \
         verified MPFR run of the same cell (capped at 16); the MPFR column shows its own verified digits \
         (two runs). \"fail\": the method returned an error (listed below each table); \"unjudged\": the \
         reference failed. Problem 1 cells: nu = 0.3, E* = 1, L = 1, theta set by wear (theta > 0) or Coulomb \
         friction (theta < 0), the load from Kuznetsov's (parabola) or Westergaard's (sinusoid) law at the grid \
         lambda; the lambda shown is the computed one. Problem 1 is mapped on the same grid in both surface \
         conventions (docs/theory.md section 8): `paper` (the paper's equations) and `periodic` (the surface closes \
         over a period); the series of the `periodic` sinusoid is kept through Lambda^8 (its exact derivation \
         through Lambda^12 would take minutes).\n"
    );
    let _ = writeln!(
        s.timings,
        "### Stability maps (per map: the sum of its cells' run times)\n\n| map | seconds |\n|---|---:|"
    );
    let (p_thetas, p_lambdas): (Vec<f64>, Vec<f64>) = if full {
        (vec![-0.4, -0.2, 0.0, 0.2, 0.4], vec![0.1, 0.4, 0.7, 1.0, 1.3, 1.5])
    } else {
        (vec![-0.2, 0.2], vec![0.3])
    };
    // Kuznetsov [2.15] with E* = k = L = 1: P2 = ln sec(lambda)/pi.
    let kuznetsov = |lam: f64| (1.0 / lam.cos()).ln() / std::f64::consts::PI;
    let parabola = PunchShape::Parabolic { k: q(1, 1) };
    let (s_thetas, s_lambdas): (Vec<f64>, Vec<f64>) =
        if full { (vec![-0.2, 0.0, 0.2], vec![0.3, 0.7, 1.1, 1.4]) } else { (vec![0.2], vec![1.1]) };
    // Westergaard [2.17] with E* = L = 1, D = 1/100: P2 = pi D sin^2(lambda).
    let westergaard = |lam: f64| std::f64::consts::PI * 0.01 * lam.sin().powi(2);
    let sinusoid = PunchShape::Sinusoidal { amplitude: q(1, 100) };
    let adhesion_knobs = [Knob::F64(None), Knob::MpfrVerified(20)];
    let p_grid = (p_thetas.as_slice(), p_lambdas.as_slice());
    let s_grid = (s_thetas.as_slice(), s_lambdas.as_slice());
    let (q_thetas, q_lambdas) = (vec![-0.4, -0.2, 0.0, 0.2, 0.4], vec![0.2, 0.4, 0.6, 0.7, 0.8]);
    let q_grid = (q_thetas.as_slice(), q_lambdas.as_slice());
    let mut plans = vec![
        p1_plan(&parabola, "parabola", Convention::Paper, p_grid, &kuznetsov),
        p1_plan(&parabola, "parabola", Convention::PeriodicSurface, p_grid, &kuznetsov),
        p1_plan(&sinusoid, "sinusoid", Convention::Paper, s_grid, &westergaard),
        p1_plan(&sinusoid, "sinusoid", Convention::PeriodicSurface, s_grid, &westergaard),
        p2_plan(ctx.profile, &adhesion_knobs, Convention::Paper),
        p2_plan(ctx.profile, &adhesion_knobs, Convention::PeriodicSurface),
    ];
    // The quartic's maps: full report only.
    if full {
        for conv in [Convention::Paper, Convention::PeriodicSurface] {
            plans.push(p1_plan(&quartic(), "quartic", conv, q_grid, &quartic_load));
        }
    }
    let results = run_plans(ctx, &plans);
    let mut p1 = Vec::new();
    let (mut p2, mut p2_periodic) = ((Vec::new(), 0.0), (Vec::new(), 0.0));
    for (plan, (cells, secs)) in plans.into_iter().zip(results) {
        match plan.convention {
            Some(convention) => {
                let m = ConventionMap { convention, knobs: plan.knobs, cells };
                timing_line(&mut s, plan.name, &m, secs);
                p1.push(m);
            }
            None if plan.name == "adhesion" => p2 = (cells, secs),
            None => p2_periodic = (cells, secs),
        }
    }
    let _ = writeln!(s.timings, "| stability map, Problem 2 ({} cells) | {:.2} |", p2.0.len(), p2.1);
    let _ = writeln!(
        s.timings,
        "| stability map, Problem 2, `periodic` ({} cells) | {:.2} |",
        p2_periodic.0.len(),
        p2_periodic.1
    );
    // In the order of `plans`: parabola, sinusoid (each `paper`, `periodic`), then the quartic's.
    let mut p1 = p1.into_iter();
    let maps: Vec<ConventionMap> = p1.by_ref().take(2).collect();
    map_section_conventions(&mut s, "stability_p1_parabola", "Problem 1, parabola (k = 1)", "", &maps);
    let maps: Vec<ConventionMap> = p1.by_ref().take(2).collect();
    map_section_conventions(
        &mut s,
        "stability_p1_sinusoid",
        "Problem 1, sinusoid (D = 1/100), up to high load",
        "",
        &maps,
    );
    let maps: Vec<ConventionMap> = p1.collect();
    if !maps.is_empty() {
        let title = "Problem 1, quartic g = x^2 + x^4/10 (L = 1): beyond the small-slope limit";
        let note = format!(
            "The quartic of scene `quartic` (docs/theory.md section 9; issue 11), loaded by its frictionless \
             closed-form load at the grid lambda: where |g'| > {} (the theory assumes |g'| << 1 [1.9]; for the \
             centred frictionless contact lambda > 0.776, moved off centre by friction and wear) the solvers answer \
             with the small-slope warning of docs/theory.md section 9, not a refusal (one rule for every shape); \
             \"fail\" cells are the methods' own failures (listed below the table). No series column: the report's series are the \
             parabola's and the sinusoid's.",
            periodic_contact::params::sliding::MAX_CONTACT_SLOPE
        );
        map_section_conventions(&mut s, "stability_p1_quartic", title, &note, &maps);
    }
    let _ = writeln!(s.markdown, "Problem 2 exact series: {}\n", super::sweeps::adhesion_series_note());
    map_section(&mut s, "stability_p2", "Problem 2, parabola (k = 1, L = 1)", "nu", &adhesion_knobs, &p2.0);
    let _ = writeln!(s.markdown, "{}\n", mode_table(&p2.0));
    let _ = writeln!(
        s.markdown,
        "The same map in the `periodic` convention (u periodic: a laterally rigid row; docs/theory.md \
         section 8, Problem 2), where the Flamant far field of `paper` is replaced by zero mean lateral \
         strain: the loads differ (nu = 0, lambda = 0.6: 0.0716 against 0.0794), and the homogeneous mode, \
         with the same m*, is not excited (its local exponent grows with the contact instead of falling), so \
         the small-nu refusals of `paper` do not occur. The f64 column is the collocation in eta (the \
         lambda^2 series is `paper` only).\n"
    );
    map_section(
        &mut s,
        "stability_p2_periodic",
        "Problem 2, parabola (k = 1, L = 1), `periodic`",
        "nu",
        &adhesion_knobs,
        &p2_periodic.0,
    );
    s
}

/// The homogeneous solution's exponent m*(nu) at the map's nu (docs/theory.md section 11,
/// [`periodic_contact::asymptotics::adhesion_mode`]): where the Problem 2 map fails below nu = 1/2, the
/// problem fixes P' only up to C eta^m*.
fn mode_table(cells: &[Cell]) -> String {
    let mut nus: Vec<f64> = cells.iter().map(|c| c.x).collect();
    nus.sort_by(f64::total_cmp);
    nus.dedup();
    let mut out = String::from(
        "Below nu = 1/2 the incremental problem of Problem 2 is not unique: P' + C H(eta) solves it for every C, \
         H ~ eta^m* with Re M_m* = 0 (docs/theory.md section 11, `src/asymptotics/adhesion_mode.rs`); the \
         failures above are where the two runs pick different C. m*(nu) at the map's nu (secant on Re M_x, \
         13 significant digits, checked against mpmath to 13-14), and the horizon lambda_h(nu, d): the largest \
         lambda at which complete adhesion keeps d digits (the mode's growth from lambda to pi/2 by the frozen \
         symbol, margin 2 digits; the dashed curves of the maps at d = 12, 6, 2):\n\n\
         | nu | m* | lambda_h(nu, 20) | lambda_h(nu, 12) | lambda_h(nu, 2) |\n|---:|---:|---:|---:|---:|",
    );
    for nu in nus {
        let text = match Material::from_contact_modulus(rational(nu), q(1, 1)) {
            Ok(m) => {
                let c = periodic_contact::params::adhesion::AdhesionParamsF64::new(&m);
                match periodic_contact::asymptotics::adhesion_mode::symmetric_mode_exponent_refined(
                    c.eps, c.b, c.s, 2_000_000,
                ) {
                    Some(v) => periodic_contact::asymptotics::adhesion_mode::mode_text(v),
                    None if c.eps == 0.0 => "none (eps = 0: Re M_m > 0)".into(),
                    None => "> 2e6".into(),
                }
            }
            Err(_) => "-".into(),
        };
        let h = |d: f64| match Material::from_contact_modulus(rational(nu), q(1, 1)) {
            Ok(m) => periodic_contact::asymptotics::adhesion_mode::horizon_text(
                periodic_contact::asymptotics::adhesion_mode::horizon_of(&m, d),
            ),
            Err(_) => "-".into(),
        };
        out.push_str(&format!("\n| {nu:.3} | {text} | {} | {} | {} |", h(20.0), h(12.0), h(2.0)));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 31: the Problem 2 map (nu on x) draws lambda_h(nu, d), d = 12, 6, 2, as dashed curves
    /// over nu = 0 .. 1/2 in steps of 0.01, each rising with nu to pi/2 at nu = 1/2, the 12-digit
    /// curve from 0.84 at nu = 0 (inside the map's lambda grid 0.2 .. 1.4); the Problem 1 maps do not.
    #[test]
    fn the_problem_2_map_draws_the_horizon() {
        let knob = Knob::MpfrVerified(30);
        let chart = map_chart("p2", "Problem 2", "nu", &knob, 0, &[]);
        let dashed: Vec<&Curve> = chart.curves.iter().filter(|c| c.draw == Draw::Dashed).collect();
        assert_eq!(dashed.len(), 3, "{:?}", chart.curves.iter().map(|c| &c.name).collect::<Vec<_>>());
        for c in &dashed {
            assert_eq!(c.points.len(), 51, "{}", c.name);
            assert!(c.points.windows(2).all(|w| w[1].1 >= w[0].1), "{} does not rise with nu", c.name);
            assert_eq!(c.points[50], (0.5, std::f64::consts::FRAC_PI_2), "{}", c.name);
        }
        let first = dashed[0].points[0].1;
        assert!(dashed[0].name.contains("lambda_h(nu, 12)") && (0.8..0.9).contains(&first), "{first}");
        let p1 = map_chart("p1", "Problem 1", "theta", &knob, 0, &[]);
        assert!(p1.curves.iter().all(|c| c.draw != Draw::Dashed));
    }
}
