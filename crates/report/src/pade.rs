//! Report section "Pade resummation" (docs/theory.md section 11): per object (Kuznetsov's l, the
//! sinusoid's a, Problem 1 with friction l and c, Problem 2's P2 at nu = 0 and 3/10) and contact
//! size lambda, the digits of the plain partial sum and of the best Padé approximant from the same
//! coefficients against the full solution, the Padé method's estimate, and every refusal with its
//! reason ([`periodic_contact::verification::pade`]); for the two closed-form objects also after the
//! conformal map of their known singularity. One chart (digits against lambda per object: plain
//! dashed, Padé solid, conformal + Padé markers where the singularity is known) and one table. The default report takes the parabola's series
//! through Lambda^16, the sinusoid's through Lambda^12 (its symbolic derivation is the dearest)
//! and Problem 2's through lambda^12, references at 20 digits; `--fast` every series through order 8,
//! references at 12 digits, at three sizes. The claim at order 24 (Kuznetsov's l at
//! lambda = 1.2: 8.3 digits plain, 13.7 conformal + Padé) is asserted in `tests/all/pade.rs`.

use super::chart::{Chart, Curve, Draw, Legend};
use super::section::{Ctx, Profile, Section};
use periodic_contact::asymptotics::sliding::SlidingShape;
use periodic_contact::model::Convention;
use periodic_contact::verification::pade::{pade_objects, pade_rows_at, PadeObject, PadePlan, PadeRow, PadeSeries};
use std::fmt::Write as _;

/// The plan of a profile: orders, sizes, reference digits (module doc).
fn plan(profile: Profile) -> PadePlan {
    match profile {
        Profile::Full => PadePlan::report(),
        Profile::Fast => PadePlan { parabola: 8, sinusoid: 8, adhesion: 8, lambdas: vec![0.4, 1.0, 1.4], digits: 12 },
    }
}

fn cell(d: Option<f64>) -> String {
    d.map_or("-".into(), periodic_contact::numerics::accuracy::digits_text)
}

/// Every row of the chart, in its order ([`periodic_contact::verification::pade::pade_rows`]'s): each
/// (object, lambda) is one job on the report's thread pool ([`super::parallel::map`]), the dearest
/// first (the references near full contact: Problem 2's verified Volterra runs, then the friction
/// rows' verified reductions), from the expansions of the report's cache (the parabola's and the
/// sinusoid's are those of the other sections) and Problem 2's derived once.
fn rows(ctx: &Ctx, plan: &PadePlan) -> Result<Vec<PadeRow>, String> {
    let parabola = ctx.cache.expansion(SlidingShape::Parabolic, Convention::Paper, plan.parabola)?;
    let sinusoid = ctx.cache.expansion(SlidingShape::Sinusoidal, Convention::Paper, plan.sinusoid)?;
    let adhesion = periodic_contact::asymptotics::adhesion::adhesion_expansion_with(plan.adhesion, false)
        .map_err(|e| format!("the Problem 2 expansion: {e}"))?;
    // Problem 2's references through the report's memo: the stability map solves the same
    // problems (lambda = 0.8 and 1.4 at nu = 0 and 3/10) at the same digits.
    let reference = |p: &periodic_contact::model::AdhesionProblem, digits: u32| {
        super::runner::verified_adhesion(&ctx.cache, p, digits)
    };
    let series =
        PadeSeries { parabola: &parabola, sinusoid: &sinusoid, adhesion: &adhesion, adhesion_reference: &reference };
    let jobs: Vec<(PadeObject, f64)> =
        pade_objects().into_iter().flat_map(|o| plan.lambdas.iter().map(move |&l| (o.clone(), l))).collect();
    let cost = |(o, l): &(PadeObject, f64)| match o {
        PadeObject::Adhesion(_) => 2.0 + l,
        PadeObject::Friction => 1.0 + l,
        _ => 0.0,
    };
    let done = super::parallel::map(&jobs, cost, |(o, l)| pade_rows_at(plan, &series, o, *l));
    Ok(done.into_iter().flatten().collect())
}

/// Builds the section.
pub fn section(ctx: &Ctx) -> Section {
    ctx.step("Pade resummation");
    let plan = plan(ctx.profile);
    let mut s = Section::default();
    let rows = match rows(ctx, &plan) {
        Ok(r) => r,
        Err(why) => {
            let _ = writeln!(s.markdown, "## 10. Pade resummation\n\nNot computed: {why}.\n");
            return s;
        }
    };
    let md = &mut s.markdown;
    let _ = writeln!(
        md,
        "## 10. Pade resummation\n\n\
         docs/theory.md section 11. The same exact coefficients summed plainly and by near-diagonal Pade \
         approximants [L/M] (L + M = all coefficients, |L - M| <= 2) in w = Lambda^2 (Problem 1) or \
         w = lambda^2 (Problem 2's load), the series through order N (column N: the parabola {}, the sinusoid \
         {}, Problem 2 {}), both against a reference without the series (closed form, or the verified MPFR \
         solver at {} digits; capped at its digits). Coefficients: exact rationals for the frictionless \
         punches, MPFR values (exact binary rationals) at transcendental parameters. The chosen approximant is \
         the most diagonal one not refused; its estimated digits are its agreement with its neighbours \
         [L-1/M] and [L/M-1] (the `friction` rows: the Pade method's claim, that agreement with the \
         difference taken {} times); an approximant with a pole within {}% of |w| of the segment [0, w] not \
         matched by a zero is refused. lambda = pi l/L (pi a/L); digits on the scale l (Problem 1) or P2.\n",
        plan.parabola,
        plan.sinusoid,
        plan.adhesion,
        plan.digits,
        periodic_contact::sliding::series::pade::ESTIMATE_SAFETY,
        periodic_contact::numerics::pade::POLE_MARGIN * 100.0
    );
    let _ = writeln!(
        md,
        "The closed-form objects have known singularities (Kuznetsov: w = +-2 pi i, where exp(-w/2) = -1; the \
         sinusoid: w = 1, where sin lambda = 1): their rows are also resummed after the conformal map of the cut \
         plane onto the unit disc (`conformal`: the series of f(w(z)) in z, Pade approximants in z at z(w); \
         docs/theory.md section 11).\n"
    );
    let _ = writeln!(md, "![Pade resummation](pade.svg) (data: `pade.csv`)\n");
    let _ = writeln!(
        md,
        "| object | lambda | N | w | coefficients | plain digits | Pade [L/M] | Pade digits | estimated | conformal [L/M] | conformal digits | estimated | reference |\n\
         |---|---:|---:|---:|---|---:|---|---:|---:|---|---:|---:|---|"
    );
    let mut refusals = vec![];
    for r in &rows {
        let (lm, true_d, est) = match r.pade {
            Some((l, m, e, t)) => (format!("[{l}/{m}]"), Some(t), Some(e)),
            // No reference: no comparison was made (the reason is listed below the table).
            None if r.plain.is_none() => ("-".into(), None, None),
            None => ("refused".into(), None, None),
        };
        let (clm, ctrue, cest) = match (r.conformal, &r.map) {
            (Some((l, m, e, t)), _) => (format!("[{l}/{m}]"), Some(t), Some(e)),
            (None, Some(_)) => ("refused".into(), None, None),
            (None, None) => ("-".into(), None, None),
        };
        let w = if r.w.is_finite() { format!("{:.4}", r.w) } else { "-".into() };
        let _ = writeln!(
            md,
            "| {} | {} | {} | {w} | {} | {} | {lm} | {} | {} | {clm} | {} | {} | {} |",
            r.object,
            r.lambda,
            r.order,
            r.coefficients,
            cell(r.plain),
            cell(true_d),
            cell(est),
            cell(ctrue),
            cell(cest),
            r.reference
        );
        if let Some(why) = &r.refusal {
            refusals.push(format!("- {} at lambda = {}: {why}", r.object, r.lambda));
        }
    }
    if !refusals.is_empty() {
        let _ = writeln!(md, "\nRefusals (no Pade value, or no reference):\n\n{}", refusals.join("\n"));
    }
    md.push('\n');
    s.charts.push(chart(&rows));
    s
}

fn chart(rows: &[PadeRow]) -> Chart {
    let mut objects: Vec<&str> = vec![];
    for r in rows {
        if !objects.contains(&r.object.as_str()) {
            objects.push(&r.object);
        }
    }
    let mut curves = vec![];
    for (i, o) in objects.iter().enumerate() {
        let of = |f: &dyn Fn(&PadeRow) -> Option<f64>| -> Vec<(f64, f64)> {
            rows.iter().filter(|r| r.object == *o).map(|r| (r.lambda, f(r).unwrap_or(f64::NAN))).collect()
        };
        curves.push(Curve {
            name: format!("{o}, Pade"),
            points: of(&|r| r.pade.map(|p| p.3)),
            draw: Draw::LineMarkers,
            colour: Some(i),
        });
        curves.push(Curve {
            name: format!("{o}, plain"),
            points: of(&|r| r.plain),
            draw: Draw::Dashed,
            colour: Some(i),
        });
        // The conformal map where the singularity is known (the two closed-form objects).
        if rows.iter().any(|r| r.object == *o && r.map.is_some()) {
            curves.push(Curve {
                name: format!("{o}, conformal + Pade"),
                points: of(&|r| r.conformal.map(|p| p.3)),
                draw: Draw::Markers,
                colour: Some(i),
            });
        }
    }
    Chart {
        stem: "pade".into(),
        title: "Pade resummation: digits against the full solution".into(),
        x_label: "contact size lambda = pi l/L [-]".into(),
        y_label: "correct digits [-]".into(),
        x_log: false,
        y_log: false,
        curves,
        legend: Legend::Above,
    }
}
