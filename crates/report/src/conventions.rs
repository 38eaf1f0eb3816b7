//! Report section 7: "paper vs periodic", the two surface conventions of Problem 1 side by side
//! (docs/theory.md section 8).
//!
//! `paper` solves [2.8] as the paper states it; `periodic` adds the constant
//! K = (kappa P2 - 2 beta l tau0)/L to its right side, so that the surface closes over every
//! period. For every friction or wear scene (kappa != 0 or tau0 != 0, so that K != 0) with a load
//! sweep, the section runs the verified MPFR solver ([`periodic_contact::sliding::solve_verified`]) at every
//! load of the sweep in both conventions and shows:
//! - the contact centre c/l and F_def/P2 against P2 (charts) and a table with the verified digits;
//!   refusals are listed as the solver stated them;
//! - for the parabola, the check of docs/theory.md section 8: lambda (so l) is the same in both
//!   conventions and c_periodic - c_paper = -K/(E* k) exactly (K from the periodic solution's l;
//!   an independent route, not the solvers' own K);
//! - from the exact series ([`periodic_contact::asymptotics::sliding::sliding_expansion_with`]) at the scene's
//!   theta, T, kappa and 1/pi: the size of the first interaction term of rbar = c/l, O(Lambda) in
//!   `periodic`, against the paper's first one, O(Lambda^2), as Lambda = pi l_s/L varies at the
//!   scene's load; and the MPFR shift (c/l)_periodic - (c/l)_paper beside its leading term
//!   r_1 Lambda.

use super::chart::{Chart, Curve, Draw, Legend};
use super::runner::RunCache;
use super::section::{fmt_digits, Ctx, Profile, Section};
use periodic_contact::asymptotics::sliding::SlidingShape;
use periodic_contact::model::OnPunchRow;
use periodic_contact::model::{Convention, Exact, Period, PunchShape, SlidingLoad, SlidingProblem};
use periodic_contact::numerics::accuracy::{print_mpfr, readable_f64};
use periodic_contact::numerics::evaluate;
use periodic_contact::numerics::exact::to_f64;
use periodic_contact::params::sliding::SlidingParamsMpfr;
use periodic_contact::scene::{Scene, SceneProblem, SweepParameter};
use periodic_contact::sliding::series::{expansion_shape, series_point};
use rug::Float;
use std::fmt::Write as _;
use std::time::Instant;

/// Digits of the verified MPFR runs of this section (as the stability maps and the forced-digits
/// scenes of the load-size curves).
pub const DIGITS: u32 = 30;

/// Significant digits printed at most in the tables.
const PRINTED: u32 = 10;

/// One friction or wear scene, computed in both conventions.
#[derive(Debug, Clone)]
pub struct Case {
    /// Scene name (the `paper` scene's when a scene and its `periodic` twin are both given).
    pub name: String,
    /// The scene's problem in the `paper` convention (its base load).
    pub problem: SlidingProblem,
    /// The loads of the scene's sweep.
    pub loads: Vec<Exact>,
}

/// The cases of `scenes`: Problem 1 scenes with a finite period, a given load, a `normal_load`
/// sweep and kappa != 0 or tau0 != 0 (else K = 0 and the conventions coincide). A scene and its
/// twin in the other convention (same problem and sweep otherwise) make one case.
pub fn cases(scenes: &[(String, Scene)]) -> Vec<Case> {
    let mut out: Vec<Case> = Vec::new();
    for (name, scene) in scenes {
        let SceneProblem::Sliding(p) = &scene.problem else { continue };
        let Some(sw) = &scene.sweep else { continue };
        if sw.parameter != SweepParameter::NormalLoad
            || !matches!(p.period(), Period::Finite(_))
            || !matches!(p.load(), SlidingLoad::NormalLoad(_))
            || p.kappa_and_tau0_vanish()
        {
            continue;
        }
        let Ok(paper) = p.to_builder().convention(Convention::Paper).build() else { continue };
        match out.iter_mut().find(|c| c.problem == paper && c.loads == sw.values) {
            Some(c) => {
                if p.convention() == Convention::Paper {
                    c.name = name.clone();
                }
            }
            None => out.push(Case { name: name.clone(), problem: paper, loads: sw.values.clone() }),
        }
    }
    out
}

/// The verified MPFR solution at one load in one convention.
#[derive(Debug, Clone)]
pub struct Point {
    /// lambda = pi l/L.
    pub lambda: f64,
    /// Half-length l.
    pub l: Float,
    /// Centre c.
    pub c: Float,
    /// F_def (problem units).
    pub f_def: Float,
    /// Verified digits (the minimum over the solution's quantities).
    pub digits: f64,
}

/// Solves `p` with the verified MPFR solver at `digits`; the first (smallest) physical contact
/// (once per problem in `cache`: the load-size curves solve the same scenes' loads).
pub fn solve_point(cache: &RunCache, p: &SlidingProblem, digits: u32) -> Result<Point, String> {
    let v = super::runner::verified_sliding(cache, p, digits)?.solution;
    let s = &v.solution;
    Ok(Point {
        lambda: s.lambda.as_ref().map_or(0.0, |x| x.to_f64()),
        l: s.l.clone(),
        c: s.c.clone(),
        f_def: s.f_def.clone(),
        digits: v.accuracy.digits_verified,
    })
}

/// K/(E* k) = (kappa P2/E* - 2 beta l tau0/E*)/(L k) (docs/theory.md section 8) at load `p2` (problem
/// units) and half-length `l`, from the problem's derived parameters; `None` for a single punch.
pub fn k_over_e_k(p: &SlidingProblem, p2: &Float, l: &Float, prec: u32) -> Option<Float> {
    let prm = SlidingParamsMpfr::new(p, prec).ok()?;
    let big_l = prm.period.as_ref()?;
    let kp2 = Float::with_val(prec, &prm.kappa * p2) / &prm.unit;
    let bt = Float::with_val(prec, 2 * Float::with_val(prec, &prm.beta * l)) * &prm.tau0;
    Some(Float::with_val(prec, kp2 - bt) / big_l / &prm.k)
}

/// The first interaction terms of rbar - rbar_s at one scene's theta, T, kappa and 1/pi:
/// coefficient r_1 of Lambda (`periodic`), r_2 of Lambda^2 in `periodic` and in `paper`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CentreTerms {
    /// Lambda = pi l_s/L at the scene's load and period.
    pub big_lambda: f64,
    /// r_1 (`periodic`).
    pub r1_periodic: f64,
    /// r_1 (`paper`: zero, its series being even in Lambda).
    pub r1_paper: f64,
    /// r_2 (`periodic`).
    pub r2_periodic: f64,
    /// r_2 (`paper`).
    pub r2_paper: f64,
}

impl CentreTerms {
    /// Lambda at which |r_1| Lambda = |r_2 (paper)| Lambda^2 (infinite when r_2 = 0).
    pub fn crossover(&self) -> f64 {
        (self.r1_periodic / self.r2_paper).abs()
    }
}

/// The coefficients of [`CentreTerms`] of `problem` (its load; its convention is ignored) from the
/// exact expansions, evaluated at 128 bits.
pub fn centre_terms(cache: &RunCache, problem: &SlidingProblem) -> Result<CentreTerms, String> {
    let prec = super::runner::SERIES_BITS;
    let sp = series_point(problem, prec).map_err(|e| e.to_string())?;
    let shape: SlidingShape = expansion_shape(problem).map_err(|e| e.to_string())?;
    let binds = sp.bindings();
    let coeff = |convention: Convention, k: usize| -> Result<f64, String> {
        let e = cache.expansion(shape, convention, 2)?;
        Ok(match e.rbar_minus_rbar_s.coeff(k) {
            Some(c) => evaluate::poly_mpfr(c, &binds, prec).map_err(|e| e.to_string())?.to_f64(),
            None => 0.0,
        })
    };
    Ok(CentreTerms {
        big_lambda: sp.big_lambda.to_f64(),
        r1_periodic: coeff(Convention::PeriodicSurface, 1)?,
        r2_periodic: coeff(Convention::PeriodicSurface, 2)?,
        r1_paper: coeff(Convention::Paper, 1)?,
        r2_paper: coeff(Convention::Paper, 2)?,
    })
}

fn describe(p: &SlidingProblem) -> String {
    let f = |x: &Exact| readable_f64(to_f64(x).unwrap_or(f64::NAN));
    let shape = match p.shape() {
        PunchShape::Parabolic { k } => format!("parabola k = {}", f(k)),
        PunchShape::Sinusoidal { amplitude } => format!("sinusoid D = {}", f(amplitude)),
        other => {
            let pars: Vec<String> = other.parameters().into_iter().map(|(k, v)| format!("{k} = {v}")).collect();
            format!("{} {}", other.name(), pars.join(", "))
        }
    };
    let period = match p.period() {
        Period::Finite(l) => f(l),
        Period::Infinite => "inf".into(),
    };
    let theta = SlidingParamsMpfr::new(p, 64).map(|x| readable_f64(x.theta.to_f64())).unwrap_or_default();
    format!(
        "{shape}, L = {period}, nu = {}, mu = {}, tau0 = {}, cW = {}; theta = {theta}",
        f(p.material().poisson_ratio()),
        f(p.friction()),
        f(p.adhesive_friction()),
        f(p.wear())
    )
}

/// Builds the section.
pub fn section(ctx: &Ctx, scenes: &[(String, Scene)]) -> Section {
    let mut s = Section::default();
    let cases = cases(scenes);
    let _ = writeln!(
        s.markdown,
        "## 7. Paper vs periodic: the two surface conventions of Problem 1\n\n\
         docs/theory.md section 8. In the paper's equations (`paper`, sections 2-3, the default) the surface does not \
         close over a period when there is friction or wear: integrating the gap across the free arc from the \
         trailing and from the leading end differs by M = (2/E*) beta P1 - cW P2, because the Flamant sum \
         carries a rigid rotation (mean v' = -beta P1/L) and steady wear lowers the surface uniformly \
         (cW P2/L). `periodic` adds to the right side of [2.8] the constant K = (kappa P2 - 2 beta l tau0)/L, \
         which closes the surface: it is the consistent choice for a row of identical punches at one height \
         when mu != 0 or cW != 0; the two coincide when K = 0 (frictionless without wear). K ~ 1/L, so at a \
         fixed load the expansions in Lambda = pi l_s/L gain odd powers: the first interaction term of the \
         centre rbar = c/l is O(Lambda) in `periodic`, before the paper's O(Lambda^2). For the parabola lambda \
         (so l) is the same in both and the centre moves by exactly -K/(E* k).\n\n\
         Each friction or wear scene with a load sweep is solved at every load in both conventions by the \
         verified MPFR method at {DIGITS} digits (two runs; digits = the fewer of the two conventions' verified \
         digits, printed values carry no more). Charts: c/l and F_def/P2 against P2; the size of the first \
         interaction terms of c/l from the exact series at the scene's theta, T, kappa and 1/pi, against Lambda \
         at the scene's load.\n"
    );
    if cases.is_empty() {
        let _ = writeln!(s.markdown, "No scene has friction or wear with a load sweep: nothing to compare.\n");
    }
    let _ = writeln!(s.timings, "### Paper vs periodic\n\n| scene | seconds |\n|---|---:|");
    for case in &cases {
        let t0 = Instant::now();
        case_section(ctx, &mut s, case);
        let _ = writeln!(s.timings, "| `{}` | {:.2} |", case.name, t0.elapsed().as_secs_f64());
    }
    s
}

type Run = (f64, Result<Point, String>);

fn case_section(ctx: &Ctx, s: &mut Section, case: &Case) {
    let name = &case.name;
    let parabola = matches!(case.problem.shape(), PunchShape::Parabolic { .. });
    let _ = writeln!(s.markdown, "### Scene `{name}` ({})\n", describe(&case.problem));
    let mut runs: Vec<(Convention, Vec<Run>)> = Vec::new();
    for convention in [Convention::Paper, Convention::PeriodicSurface] {
        let mut v = Vec::new();
        for load in &case.loads {
            ctx.step(format!(
                "paper vs periodic: {name}, {}, P2 = {}",
                convention.name(),
                periodic_contact::model::readable(load)
            ));
            let p = case.problem.to_builder().convention(convention).normal_load(load.clone()).build();
            let r = match p {
                Ok(p) => solve_point(&ctx.cache, &p, DIGITS),
                Err(e) => Err(e.to_string()),
            };
            v.push((to_f64(load).unwrap_or(f64::NAN), r));
        }
        runs.push((convention, v));
    }
    table(ctx, s, case, &runs, parabola);
    let refusals: Vec<String> = runs
        .iter()
        .flat_map(|(conv, v)| {
            v.iter().filter_map(move |(p2, r)| {
                r.as_ref().err().map(|e| format!("`{}` at P2 = {}: {e}", conv.name(), readable_f64(*p2)))
            })
        })
        .collect();
    if !refusals.is_empty() {
        let _ = writeln!(s.markdown, "Refusals, as the MPFR solver stated them:\n");
        for r in refusals {
            let _ = writeln!(s.markdown, "- {r}");
        }
        s.markdown.push('\n');
    }
    let curve = |runs: &[Run], conv: Convention, y: &dyn Fn(&Point, f64) -> f64| Curve {
        name: format!("{} (MPFR, {DIGITS} digits)", conv.name()),
        points: runs.iter().filter_map(|(p2, r)| r.as_ref().ok().map(|pt| (*p2, y(pt, *p2)))).collect(),
        draw: Draw::LineMarkers,
        colour: None,
    };
    let c_over_l = |pt: &Point, _: f64| Float::with_val(pt.c.prec(), &pt.c / &pt.l).to_f64();
    let fdef_over_p2 = |pt: &Point, p2: f64| pt.f_def.to_f64() / p2;
    let (lo, hi) = case.loads.iter().filter_map(to_f64).fold((f64::INFINITY, 0.0f64), |(a, b), x| (a.min(x), b.max(x)));
    let x_log = hi > 10.0 * lo;
    for (stem, title, y_label, y) in [
        ("centre", "contact centre c/l", "centre c/l [-]", &c_over_l as &dyn Fn(&Point, f64) -> f64),
        ("fdef", "deformation resistance F_def/P2", "F_def/P2 [-]", &fdef_over_p2),
    ] {
        let stem = format!("conventions_{name}_{stem}");
        let _ = writeln!(s.markdown, "![{name}: {title}]({stem}.svg) (data: `{stem}.csv`)\n");
        s.charts.push(Chart {
            stem,
            title: format!("{name}: {title}, paper vs periodic"),
            x_label: "load per punch P2 [units of E* x L]".into(),
            y_label: y_label.into(),
            x_log,
            y_log: false,
            curves: runs.iter().map(|(conv, v)| curve(v, *conv, y)).collect(),
            legend: Legend::Above,
        });
    }
    if matches!(case.problem.shape(), PunchShape::Polynomial { .. } | PunchShape::Circular { .. }) {
        let _ = writeln!(
            s.markdown,
            "No series terms: the report evaluates the exact series of the parabola and the sinusoid only (the \
             section \"Punch shapes\" checks this profile against the closed form of docs/theory.md section 9).\n"
        );
        return;
    }
    match centre_terms(&ctx.cache, &case.problem) {
        Ok(t) => terms_chart(s, name, &t, ctx.profile),
        Err(e) => {
            let _ = writeln!(s.markdown, "The series terms could not be evaluated: {e}\n");
        }
    }
}

/// The table: per load, each convention's lambda, c/l and F_def, the digits, the MPFR shift of
/// c/l beside its leading series term r_1 Lambda, and (parabola) the check
/// c_periodic - c_paper + K/(E* k), relative to l.
fn table(ctx: &Ctx, s: &mut Section, case: &Case, runs: &[(Convention, Vec<Run>)], parabola: bool) {
    let mut head = "| P2 |".to_string();
    let mut rule = "|---:|".to_string();
    for (conv, _) in runs {
        let n = conv.name();
        head.push_str(&format!(" `{n}`: lambda | c/l | F_def |"));
        rule.push_str("---:|---:|---:|");
    }
    head.push_str(" digits | shift (c/l)_per - (c/l)_pap | series r_1 Lambda |");
    rule.push_str("---:|---:|---:|");
    if parabola {
        head.push_str(" check: (c_per - c_pap + K/(E* k))/l |");
        rule.push_str("---:|");
    }
    let _ = writeln!(s.markdown, "{head}\n{rule}");
    let n = runs.iter().map(|r| r.1.len()).min().unwrap_or(0);
    for i in 0..n {
        let p2 = runs[0].1[i].0;
        let load = &case.loads[i];
        let leading = case
            .problem
            .to_builder()
            .normal_load(load.clone())
            .build()
            .map_err(|e| e.to_string())
            .and_then(|p| centre_terms(&ctx.cache, &p))
            .map_or("-".into(), |t| fmt6(t.r1_periodic * t.big_lambda));
        let pts: Vec<Option<&Point>> = runs.iter().map(|r| r.1[i].1.as_ref().ok()).collect();
        let digits = pts.iter().flatten().map(|p| p.digits).fold(f64::INFINITY, f64::min);
        let mut row = format!("| {} |", readable_f64(p2));
        for pt in &pts {
            match pt {
                Some(pt) => {
                    let prec = pt.l.prec();
                    let one = Float::with_val(prec, 1);
                    let col = Float::with_val(prec, &pt.c / &pt.l);
                    let scale_f = Float::with_val(prec, &pt.l * p2) * osculating_k(&case.problem);
                    row.push_str(&format!(
                        " {:.6} | {} | {} |",
                        pt.lambda,
                        print_mpfr(&col, &one, pt.digits, PRINTED),
                        print_mpfr(&pt.f_def, &scale_f, pt.digits, PRINTED)
                    ));
                }
                None => row.push_str(" refused | - | - |"),
            }
        }
        match (pts[0], pts.get(1).copied().flatten()) {
            (Some(a), Some(b)) => {
                let prec = a.l.prec();
                let shift = Float::with_val(prec, &b.c / &b.l) - Float::with_val(prec, &a.c / &a.l);
                row.push_str(&format!(
                    " {} | {} | {leading} |",
                    fmt_digits(Some(digits)),
                    print_mpfr(&shift, &Float::with_val(prec, 1), digits, 6)
                ));
                if parabola {
                    let p2f = periodic_contact::numerics::exact::to_float(load, prec);
                    let check = k_over_e_k(&case.problem, &p2f, &b.l, prec).map(|k| {
                        let d = Float::with_val(prec, &b.c - &a.c) + k;
                        Float::with_val(prec, d / &b.l).abs().to_f64()
                    });
                    row.push_str(&format!(" {} |", check.map_or("-".into(), |x| format!("{x:.1e}"))));
                }
            }
            _ => {
                row.push_str(&format!(" {} | - | {leading} |", fmt_digits(digits.is_finite().then_some(digits))));
                if parabola {
                    row.push_str(" - |");
                }
            }
        }
        let _ = writeln!(s.markdown, "{row}");
    }
    s.markdown.push('\n');
}

fn osculating_k(p: &SlidingProblem) -> f64 {
    SlidingParamsMpfr::new(p, 64).map(|x| x.k.to_f64()).unwrap_or(f64::NAN)
}

fn terms_chart(s: &mut Section, name: &str, t: &CentreTerms, profile: Profile) {
    let n = if profile == Profile::Full { 41 } else { 9 };
    let (lo, hi) = (0.01f64, 1.0f64);
    let grid: Vec<f64> = (0..n).map(|i| lo * (hi / lo).powf(i as f64 / (n - 1) as f64)).collect();
    let curve = |label: String, coeff: f64, power: i32, draw: Draw| Curve {
        name: label,
        points: grid.iter().map(|&x| (x, coeff.abs() * x.powi(power))).collect(),
        draw,
        colour: None,
    };
    let stem = format!("conventions_{name}_terms");
    s.charts.push(Chart {
        stem: stem.clone(),
        title: format!("{name}: first interaction terms of c/l"),
        x_label: "Lambda = pi l_s/L [-]".into(),
        y_label: "size of the term of c/l [-]".into(),
        x_log: true,
        y_log: true,
        curves: vec![
            curve("periodic O(Lambda): |r_1| Lambda".into(), t.r1_periodic, 1, Draw::LineMarkers),
            curve("paper O(Lambda^2): |r_2| Lambda^2".into(), t.r2_paper, 2, Draw::LineMarkers),
            curve("periodic O(Lambda^2): |r_2| Lambda^2".into(), t.r2_periodic, 2, Draw::Dashed),
        ],
        legend: Legend::UpperLeft,
    });
    let lam = t.big_lambda;
    let _ = writeln!(
        s.markdown,
        "![{name}: first interaction terms of c/l]({stem}.svg) (data: `{stem}.csv`)\n\n\
         Exact series at the scene's load (rbar - rbar_s = r_1 Lambda + r_2 Lambda^2 + ...; coefficients \
         evaluated at 128 bits, printed to 6 digits): `periodic` r_1 = {}, r_2 = {}; `paper` r_1 = {}, r_2 = {}. \
         At the scene's Lambda = {} the O(Lambda) term is {} and the paper's O(Lambda^2) term {} (ratio {}); \
         the O(Lambda) term is the larger for Lambda < {}.\n",
        fmt6(t.r1_periodic),
        fmt6(t.r2_periodic),
        fmt6(t.r1_paper),
        fmt6(t.r2_paper),
        fmt6(lam),
        fmt6(t.r1_periodic * lam),
        fmt6(t.r2_paper * lam * lam),
        fmt6((t.r1_periodic * lam / (t.r2_paper * lam * lam)).abs()),
        fmt6(t.crossover()),
    );
}

fn fmt6(x: f64) -> String {
    periodic_contact::numerics::accuracy::fmt_f64(x, 6)
}

#[cfg(test)]
mod tests {
    use super::*;
    use exact_series::Q;
    use periodic_contact::model::Material;
    use periodic_contact::scene::parse::parse_scene;

    fn q(n: i64, d: i64) -> Exact {
        Q::new(n.into(), d.into())
    }

    /// docs/theory.md section 8's check case: E* = k = L = 1, beta = 1/4 (nu = 1/3), mu = 2/5,
    /// tau0 = cW = 0, P2 = 1/20.
    fn theory_case(convention: Convention) -> SlidingProblem {
        SlidingProblem::builder()
            .material(Material::from_contact_modulus(q(1, 3), q(1, 1)).unwrap())
            .period(Period::Finite(q(1, 1)))
            .shape(PunchShape::Parabolic { k: q(1, 1) })
            .friction(q(2, 5))
            .normal_load(q(1, 20))
            .convention(convention)
            .build()
            .unwrap()
    }

    #[test]
    fn theory_check_values_and_the_k_shift() {
        // docs/theory.md section 8: lambda = 0.547045990639 in both conventions, c = -0.0118478575
        // (paper) and -0.0068478575 (periodic), so c_periodic - c_paper = -K/(E* k) = 0.005.
        let cache = RunCache::default();
        let pap = solve_point(&cache, &theory_case(Convention::Paper), 20).unwrap();
        let per = solve_point(&cache, &theory_case(Convention::PeriodicSurface), 20).unwrap();
        for pt in [&pap, &per] {
            assert!((pt.lambda - 0.547045990639).abs() < 1e-11, "{}", pt.lambda);
            assert!(pt.digits > 15.0, "{}", pt.digits);
        }
        assert!((pap.c.to_f64() + 0.0118478575).abs() < 1e-10, "{}", pap.c);
        assert!((per.c.to_f64() + 0.0068478575).abs() < 1e-10, "{}", per.c);
        let prec = pap.c.prec();
        // K = kappa P2/L = -beta mu P2 = -1/200 exactly (tau0 = 0).
        let k =
            k_over_e_k(&theory_case(Convention::PeriodicSurface), &Float::with_val(prec, 0.05), &per.l, prec).unwrap();
        assert!((k.to_f64() + 0.005).abs() < 1e-15, "{k}");
        let shift = Float::with_val(prec, &per.c - &pap.c) + &k;
        assert!(shift.to_f64().abs() < 1e-18, "c_per - c_pap + K/(E* k) = {shift}");
    }

    #[test]
    fn first_interaction_term_is_the_closed_surface_shift() {
        // For tau0 = 0 the O(Lambda) term of rbar is the centre's shift -K/(E* k l) at leading
        // order: K/(E* k l) = kappa (1 - 4 theta^2) Lambda/(2 rho), rho = 1 + O(Lambda^2), so
        // r_1 = -kappa (1 - 4 theta^2)/2; the paper's series has no odd term.
        let cache = RunCache::default();
        let p = theory_case(Convention::Paper);
        let t = centre_terms(&cache, &p).unwrap();
        let prm = SlidingParamsMpfr::new(&p, 128).unwrap();
        let (kappa, theta) = (prm.kappa.to_f64(), prm.theta.to_f64());
        let r1 = -kappa * (1.0 - 4.0 * theta * theta) / 2.0;
        assert!((t.r1_periodic - r1).abs() < 1e-14, "{} vs {r1}", t.r1_periodic);
        assert_eq!(t.r1_paper, 0.0);
        assert!(t.r2_paper != 0.0 && t.crossover().is_finite());
        // Lambda = pi l_s/L, l_s = a0/sqrt(1 - 4 theta^2), a0 = sqrt(2 P2/(pi E* k)) [3.10].
        let l_s = (2.0 * 0.05 / std::f64::consts::PI).sqrt() / (1.0 - 4.0 * theta * theta).sqrt();
        assert!((t.big_lambda - std::f64::consts::PI * l_s).abs() < 1e-14);
    }

    const SCENE: &str = r#"
[problem]
kind = "sliding"
CONVENTION
[material]
poisson_ratio = "0.3"
contact_modulus = "1"
[punch]
shape = "parabolic"
k = "1"
period = "1"
[sliding]
normal_load = "0.01"
FRICTION
[output]
digits = 20
[sweep]
normal_load = ["0.003", "0.03"]
"#;

    fn scene(convention: &str, friction: &str) -> Scene {
        parse_scene(&SCENE.replace("CONVENTION", convention).replace("FRICTION", friction)).unwrap()
    }

    #[test]
    fn cases_pair_twins_and_skip_problems_where_the_conventions_coincide() {
        let scenes = vec![
            ("a_periodic".to_string(), scene("convention = \"periodic\"", "friction = \"0.3\"")),
            ("b_paper".to_string(), scene("", "friction = \"0.3\"")),
            ("c_frictionless".to_string(), scene("", "")),
            ("d_wear".to_string(), scene("convention = \"periodic\"", "wear = \"0.4\"")),
        ];
        let c = cases(&scenes);
        let names: Vec<&str> = c.iter().map(|c| c.name.as_str()).collect();
        assert_eq!(names, ["b_paper", "d_wear"]);
        assert!(c.iter().all(|c| c.problem.convention() == Convention::Paper && c.loads.len() == 2));
    }
}
