//! Report section "Loading law (Problem 2, P1 = N(P2))" (docs/theory.md section 10; issue 12): the
//! scenes' loading-law problems by the verified MPFR method
//! ([`periodic_contact::loading_law::verified::solve_law_sampled`]: two collocation runs, digits
//! from their agreement). One solve per scene and convention gives the whole loading history
//! (every smaller contact is a restriction of the Volterra solution) and the stresses of the
//! final contact. For each scene, in its own convention:
//! - a table: l, a, b, c/l, P1, P2, the friction complete adhesion needs, max |q1|/q2 over the
//!   profile points where q2 > 0 ([`periodic_contact::solve::answer_law::friction_needed_of`]; sampled, not a
//!   maximum over the contact), where it occurs, tension warnings (q2 < 0 beyond the accuracy),
//!   the verified digits of each group and the digits requested;
//! - the loading path at every fourth of its [`PATH_STEPS`] contacts;
//! - the homogeneous mode eta^mu* of the loading's self-similar start at each scene's nu and
//!   n = N'(0), and in the full profile over a grid of nu and n
//!   ([`periodic_contact::asymptotics::loading_law_modes`]);
//! - charts: the ends a, b and the half-length l against P2 along the loading; q1 and q2 across
//!   the final contact (xh = (x - c)/l in (-1, 1), over E* k l); |q1|/q2 across the contact against
//!   the friction needed (where complete adhesion would slip first).
//!
//! A second method's agreement (the f64 marching method of issue 12, when merged) enters as
//! [`Row::second`], computed by [`agreement`] from both methods' [`MethodValues`]; the table
//! gains its column when a row has one.

use super::chart::{Chart, Curve, Draw, Legend};
use super::section::{fmt_digits, Ctx, Profile, Section};
use periodic_contact::loading_law::verified::{solve_law_sampled, LawPathPoint, LawSolution, LawValues, PATH_STEPS};
use periodic_contact::model::OnPunchRow;
use periodic_contact::model::{Exact, LawSize, LoadingLaw, LoadingLawProblem};
use periodic_contact::numerics::accuracy::{print_mpfr, verified_digits_mpfr};
use periodic_contact::numerics::exact::{to_f64, to_float};
use periodic_contact::scene::{Scene, SceneProblem};
use periodic_contact::solve::answer_law::{friction_needed_of, tension_points_of};
use rug::Float;
use std::fmt::Write as _;
use std::time::Instant;

/// Digits asked of the full report's solves. Measured on the shipped scene (lambda = pi/6; two
/// runs of 19 and 32 collocation nodes; 20.0 / 20.0 / 19.1 / 13.9 digits verified for ends, loads,
/// path, stresses): 28.5 s of a 218.6 s report run, 52 s of a 454 s one (2 cores shared, load
/// average 3-7; the report took ~141 s before this section on a quieter machine); its `periodic`
/// twin took 133 s in the 454 s run (`cargo run --release --locked -q -- report --out /tmp/rep`,
/// `timings.md`).
pub const DIGITS: u32 = 12;

/// Digits asked in the fast profile (snapshot test).
pub const FAST_DIGITS: u32 = 6;

/// Working precision of the comparisons (beyond every run's).
const COMPARE_BITS: u32 = 256;

/// The profile points of the final contact: xh = k/20, k = -19..=19 (full; step 0.05, holding the
/// shipped scene's output points), or k/10, k = -9..=9 (fast).
pub fn profile_points(profile: Profile) -> Vec<Exact> {
    let n: i64 = if profile == Profile::Full { 20 } else { 10 };
    (1 - n..n).map(|k| Exact::new(k.into(), n.into())).collect()
}

/// The digits requested in `profile`.
pub fn digits_for(profile: Profile) -> u32 {
    if profile == Profile::Full {
        DIGITS
    } else {
        FAST_DIGITS
    }
}

/// What a table row compares across methods: the final contact and loads.
#[derive(Debug, Clone)]
pub struct MethodValues {
    /// Trailing end a.
    pub a: Float,
    /// Leading end b.
    pub b: Float,
    /// Centre c.
    pub c: Float,
    /// Half-length l.
    pub l: Float,
    /// Tangential load P1.
    pub p1: Float,
    /// Normal load P2.
    pub p2: Float,
}

impl MethodValues {
    /// From the MPFR method's values.
    pub fn of(v: &LawValues) -> Self {
        MethodValues {
            a: v.a.clone(),
            b: v.b.clone(),
            c: v.c.clone(),
            l: v.l.clone(),
            p1: v.p1.clone(),
            p2: v.p2.clone(),
        }
    }
}

/// Digits to which two methods agree: the fewest over a, b, c (scale l of `first`) and P1, P2
/// (scale P2 of `first`), at most `cap`.
pub fn agreement(first: &MethodValues, second: &MethodValues, cap: f64) -> f64 {
    let dig =
        |x: &Float, y: &Float, scale: &Float| verified_digits_mpfr(&Float::with_val(COMPARE_BITS, x - y), scale, cap);
    dig(&first.a, &second.a, &first.l)
        .min(dig(&first.b, &second.b, &first.l))
        .min(dig(&first.c, &second.c, &first.l))
        .min(dig(&first.p1, &second.p1, &first.p2))
        .min(dig(&first.p2, &second.p2, &first.p2))
}

/// One loading-law problem solved in one convention.
#[derive(Debug)]
pub struct Row {
    /// The scene.
    pub scene: String,
    /// The scene's problem.
    pub problem: LoadingLawProblem,
    /// The verified solution, or the solver's refusal as text.
    pub solution: Result<LawSolution, String>,
    /// A second method's name and the digits it agrees to with this one ([`agreement`]).
    pub second: Option<(String, f64)>,
}

/// The friction needed over the profile, as (value, its error scale, xh text) (module doc).
pub fn friction(problem: &LoadingLawProblem, sol: &LawSolution) -> Option<(Float, Float, String)> {
    let stress = stress_scale(problem, &sol.values);
    friction_needed_of(sol.values.stresses.iter().map(|s| (&s.xh, &s.q1, &s.q2)), &stress, sol.digits.stresses)
}

/// E* k l, the stresses' scale.
fn stress_scale(problem: &LoadingLawProblem, v: &LawValues) -> Float {
    let prec = v.l.prec();
    to_float(problem.material().contact_modulus(), prec) * to_float(problem.k(), prec) * &v.l
}

/// The loading-law problems of `scenes`, each in its own convention (a scene's twin in the
/// other convention is a second scene: the `periodic` twin of the shipped scene took 2.5 times the
/// `paper` solve in the measured report run, too much for the report's time).
pub fn problems(scenes: &[(String, Scene)]) -> Vec<(String, LoadingLawProblem)> {
    scenes
        .iter()
        .filter_map(|(name, scene)| match &scene.problem {
            SceneProblem::LoadingLaw(p) => Some((name.clone(), p.clone())),
            _ => None,
        })
        .collect()
}

fn law_text(law: &LoadingLaw) -> String {
    match law {
        LoadingLaw::Linear(n) => format!("P1 = {} P2", exact_series::q_text(n)),
        LoadingLaw::Polynomial(c) => {
            let terms: Vec<String> = c
                .iter()
                .enumerate()
                .filter(|(_, v)| !num_traits::Zero::is_zero(*v))
                .map(|(j, v)| match j {
                    0 => exact_series::q_text(v),
                    1 => format!("{} P2", exact_series::q_text(v)),
                    _ => format!("{} P2^{j}", exact_series::q_text(v)),
                })
                .collect();
            format!("P1 = {}", if terms.is_empty() { "0".into() } else { terms.join(" + ") })
        }
    }
}

fn size_text(size: &LawSize) -> String {
    match size {
        LawSize::HalfLength(l) => format!("l = {}", exact_series::q_text(l)),
        LawSize::NormalLoad(p) => format!("P2 = {}", exact_series::q_text(p)),
    }
}

/// Builds the section (no text when no scene has a loading law).
pub fn section(ctx: &Ctx, scenes: &[(String, Scene)]) -> Section {
    let mut s = Section::default();
    let problems = problems(scenes);
    if problems.is_empty() {
        return s;
    }
    let digits = digits_for(ctx.profile);
    let xh = profile_points(ctx.profile);
    let _ = writeln!(
        s.markdown,
        "## 9. Loading law (Problem 2, P1 = N(P2))\n\n\
         docs/theory.md section 10: the punches are loaded with P1 and P2 growing together by the scene's law, with \
         complete adhesion, and the contact [-a, b] grows at both ends (c = (b - a)/2 != 0 when P1 != 0). \
         Verified MPFR method (two Chebyshev-collocation runs of the moving-edge Volterra equations, the second \
         with 8 more nodes and 16 more bits; digits = their agreement on the scales l, P2, E* k l), {digits} \
         digits asked. One solve gives the whole loading: the path below is the same solution restricted to \
         l_j = j l/{PATH_STEPS} (digits on each contact's own l_j and P2_j). {} \
         Friction needed: max |q1|/q2 over the {} profile points xh = (x - c)/l where q2 > 0 (sampled, not a \
         maximum over the contact; digits from the stresses' digits through |d(q1/q2)| <= \
         10^-d E* k l (q2 + |q1|)/q2^2); a point with q2 < 0 beyond the accuracy is a tension warning. The same \
         numbers come from `periodic-contact solve SCENE --json --digits {digits}` (keys a, b, c, P1, P2, \
         path; friction_needed at its points).\n",
        if ctx.profile == Profile::Full {
            "Each scene in its own surface convention (docs/theory.md section 8: `periodic` keeps v and u periodic, \
             the term i beta (P2 + i P1)/L on the contact, and moves the centre; a scene per convention shows both)."
        } else {
            "Fast profile: fewer digits and profile points."
        },
        xh.len()
    );
    let _ = writeln!(s.timings, "### Loading law\n\n| scene | convention | seconds |\n|---|---|---:|");
    // One job per scene on the report's thread pool (results in the scenes' order).
    let solved = super::parallel::map(
        &problems,
        |_| 1.0,
        |(name, p)| {
            ctx.step(format!("loading law: {name} ({})", p.convention().name()));
            let t0 = Instant::now();
            let solution = solve_law_sampled(p, &[], &xh, digits).map_err(|e| e.to_string());
            (solution, t0.elapsed().as_secs_f64())
        },
    );
    let mut rows = Vec::new();
    for ((name, p), (solution, secs)) in problems.into_iter().zip(solved) {
        let _ = writeln!(s.timings, "| `{name}` | {} | {secs:.2} |", p.convention().name());
        rows.push(Row { scene: name, problem: p, solution, second: None });
    }
    table(&mut s, &rows, digits);
    ends_table(&mut s, &rows, digits);
    path_table(&mut s, &rows, digits);
    modes_table(ctx, &mut s, &rows);
    charts(&mut s, &rows);
    s
}

/// The homogeneous mode eta^mu* of the self-similar start
/// ([`periodic_contact::asymptotics::loading_law_modes`]) at each scene's nu and n = N'(0), and in the full
/// profile over a grid of nu and n: where mu* exists the law and both edge conditions fix the
/// history only up to C eta^mu*, and a discretisation's error at small sizes grows like
/// (Lambda/eta)^mu*.
fn modes_table(ctx: &Ctx, s: &mut Section, rows: &[Row]) {
    use periodic_contact::asymptotics::loading_law_modes::{mode_exponent, MODE_DIGITS, MU_MAX};
    let q = |n: i64, d: i64| Exact::new(n.into(), d.into());
    let mut cases: Vec<(String, Exact, Exact)> = rows
        .iter()
        .map(|r| {
            (format!("`{}`", r.scene), r.problem.material().poisson_ratio().clone(), r.problem.law().initial_ratio())
        })
        .collect();
    if ctx.profile == Profile::Full {
        for nu in [q(0, 1), q(1, 10), q(1, 5), q(3, 10), q(2, 5)] {
            for n in [q(1, 5), q(1, 2), q(1, 1)] {
                cases.push(("grid".into(), nu.clone(), n));
            }
        }
    }
    let _ = writeln!(
        s.markdown,
        "### Homogeneous mode of the loading\n\n\
         The self-similar start (the single punch, lambda -> 0) admits perturbations C eta^mu* where the 2x2 \
         Mellin symbol of the two edge conditions is singular (`src/asymptotics/loading_law_modes.rs`): there \
         the law and both edge conditions fix the history only up to C eta^mu*, and a discretisation's error \
         at small sizes grows toward the final size like (Lambda/eta)^mu*. mu* is the smallest real zero on \
         (0, {MU_MAX}] ({MODE_DIGITS} digits asked, two runs); complex zeros are counted by the argument principle in the \
         module's tests. Small mu* (small nu, large n) is where both loading-law methods lose their digits.\n\n\
         | case | nu | n = N'(0) | mu* | digits |\n|---|---|---|---|---|"
    );
    ctx.step("loading law: homogeneous modes".to_string());
    // One job per distinct (nu, n) on the report's thread pool (the scenes' cases may repeat each
    // other and the grid's); rows in the cases' order.
    let mut distinct: Vec<(Exact, Exact)> = vec![];
    for (_, nu, n) in &cases {
        if !distinct.iter().any(|(a, b)| a == nu && b == n) {
            distinct.push((nu.clone(), n.clone()));
        }
    }
    let found = super::parallel::map(
        &distinct,
        |_| 1.0,
        |(nu, n)| match mode_exponent(nu, n, MODE_DIGITS) {
            Ok(m) => match m.value_text() {
                Some(v) => format!("{v} | {}", fmt_digits(Some(m.digits))),
                None => format!("none below {MU_MAX} | -"),
            },
            Err(e) => format!("{e} | -"),
        },
    );
    let row_of = |nu: &Exact, n: &Exact| {
        let k = distinct.iter().position(|(a, b)| a == nu && b == n).expect("every case has its distinct entry");
        found[k].clone()
    };
    for (name, nu, n) in &cases {
        let row = row_of(nu, n);
        let _ = writeln!(s.markdown, "| {name} | {} | {} | {row} |", exact_series::q_text(nu), exact_series::q_text(n));
    }
    let _ = writeln!(s.markdown);
}

/// The ends of the final contact ([`periodic_contact::loading_law::ends`]): the phase phi of
/// sigma ~ C (d/l)^(1/2 -+ i eps), the zone where q2 < 0, and |q1|/q2 at d/l = 0.1 .. 1e-4.
fn ends_table(s: &mut Section, rows: &[Row], requested: u32) {
    let distances = periodic_contact::loading_law::ends::DISTANCES;
    let _ = write!(
        s.markdown,
        "Near the ends sigma = q2 + i q1 ~ C (d/l)^(1/2 -+ i eps) (d the distance to the end): its phase rotates \
         without bound, so the friction complete adhesion needs grows toward each end and q2 changes sign within \
         d/l = exp(-(pi/2 -+ phi)/eps) (the oscillating singularity). The friction needed is therefore given \
         against the distance (the full solution, both runs; the phase from d/l = 1e-11 with the change from \
         1e-9 as its error; `solve --json` key `end_stress`).\n\n| scene | end | phase phi | q2 < 0 within d/l |"
    );
    for k in distances {
        let _ = write!(s.markdown, " \\|q1\\|/q2 at d/l = 1e{k} |");
    }
    let _ = write!(s.markdown, " verified (friction / phase) |\n|---|---|---:|---:|");
    for _ in distances {
        s.markdown.push_str("---:|");
    }
    s.markdown.push_str("---|\n");
    for r in rows {
        let Ok(sol) = &r.solution else { continue };
        let (v, d) = (&sol.values, &sol.digits);
        let zone_digits = sol.tension_zone_digits();
        for (end, name) in v.ends.iter().zip(["leading (b)", "trailing (-a)"]) {
            let one = Float::with_val(end.phase.prec(), 1);
            let _ = write!(
                s.markdown,
                "| `{}` ({}) | {name} | {} | {} |",
                r.scene,
                r.problem.convention().name(),
                print_mpfr(&end.phase, &one, d.end_phases, requested),
                print_mpfr(&end.tension_within, &end.tension_within, zone_digits, requested)
            );
            for mu in &end.friction_needed {
                let text = mu.as_ref().map_or("q2 < 0".to_string(), |mu| print_mpfr(mu, mu, d.friction, requested));
                let _ = write!(s.markdown, " {text} |");
            }
            let _ = writeln!(s.markdown, " {} / {} |", fmt_digits(Some(d.friction)), fmt_digits(Some(d.end_phases)));
        }
    }
    s.markdown.push('\n');
}

/// The main table (module doc).
pub fn table(s: &mut Section, rows: &[Row], requested: u32) {
    let second = rows.iter().find_map(|r| r.second.as_ref().map(|(name, _)| name.clone()));
    let _ = write!(
        s.markdown,
        "| scene | convention | law | given | l | a | b | c/l | P1 | P2 | friction needed | at xh | tension | \
         verified (ends / loads / path / stresses) | requested |"
    );
    if let Some(name) = &second {
        let _ = write!(s.markdown, " {name} agrees |");
    }
    let _ = write!(s.markdown, "\n|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---|---:|");
    if second.is_some() {
        s.markdown.push_str("---:|");
    }
    s.markdown.push('\n');
    let mut refusals = Vec::new();
    for r in rows {
        let p = &r.problem;
        let head =
            format!("| `{}` | {} | {} | {} |", r.scene, p.convention().name(), law_text(p.law()), size_text(p.size()));
        let sol = match &r.solution {
            Ok(sol) => sol,
            Err(e) => {
                let _ = writeln!(s.markdown, "{head} refused | - | - | - | - | - | - | - | - | - | {requested} |");
                refusals.push(format!("`{}` ({}): {e}", r.scene, p.convention().name()));
                continue;
            }
        };
        let (v, d) = (&sol.values, &sol.digits);
        let prec = v.l.prec();
        let print = |x: &Float, scale: &Float, digits: f64| print_mpfr(x, scale, digits, requested);
        let one = Float::with_val(prec, 1);
        let c_over_l = Float::with_val(prec, &v.c / &v.l);
        let (fric, at) = match friction(p, sol) {
            Some((f, scale, at)) => (print(&f, &scale, d.stresses), at),
            None => ("none (no q2 > 0)".into(), "-".into()),
        };
        let stress = stress_scale(p, v);
        let tension = tension_points_of(v.stresses.iter().map(|s| (&s.xh, &s.q2)), &stress, d.stresses);
        let tension = if tension.is_empty() {
            "none".to_string()
        } else {
            format!("q2 < 0 at xh = {}", tension.iter().map(|x| exact_series::q_text(x)).collect::<Vec<_>>().join(", "))
        };
        let _ = write!(
            s.markdown,
            "{head} {} | {} | {} | {} | {} | {} | {fric} | {at} | {tension} | {} / {} / {} / {} | {requested} |",
            print(&v.l, &v.l, d.ends),
            print(&v.a, &v.l, d.ends),
            print(&v.b, &v.l, d.ends),
            print(&c_over_l, &one, d.ends),
            print(&v.p1, &v.p2, d.loads),
            print(&v.p2, &v.p2, d.loads),
            fmt_digits(Some(d.ends)),
            fmt_digits(Some(d.loads)),
            fmt_digits(Some(d.path)),
            fmt_digits(Some(d.stresses)),
        );
        if second.is_some() {
            let _ = write!(s.markdown, " {} |", r.second.as_ref().map_or("-".into(), |(_, x)| fmt_digits(Some(*x))));
        }
        s.markdown.push('\n');
    }
    s.markdown.push('\n');
    for r in rows {
        let Ok(sol) = &r.solution else { continue };
        let Some((_, _, at)) = friction(&r.problem, sol) else { continue };
        let st = &sol.values.stresses;
        if [st.first(), st.last()].iter().flatten().any(|p| exact_series::q_text(&p.xh) == at) {
            let _ = writeln!(
                s.markdown,
                "`{}` ({}): the largest sampled |q1|/q2 is at the outermost profile point xh = {at}, rising toward \
                 that end: complete adhesion would slip first near it, and the sampled value is a lower bound of the \
                 friction needed there.\n",
                r.scene,
                r.problem.convention().name()
            );
        }
    }
    if !refusals.is_empty() {
        let _ = writeln!(s.markdown, "Refusals, as stated:\n");
        for r in &refusals {
            let _ = writeln!(s.markdown, "- {r}");
        }
        s.markdown.push('\n');
    }
}

/// The loading path at every fourth contact (l_j = j l/16, j = 4, 8, 12, 16).
fn path_table(s: &mut Section, rows: &[Row], requested: u32) {
    let _ = writeln!(
        s.markdown,
        "Loading path (every fourth of its {PATH_STEPS} contacts; digits: the path's, on each contact's l_j and \
         P2_j):\n\n| scene | convention | j | l_j | a_j | b_j | c_j/l_j | P1_j | P2_j | digits |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|---:|"
    );
    for r in rows {
        let Ok(sol) = &r.solution else { continue };
        let d = sol.digits.path;
        for (j, p) in sol.values.path.iter().enumerate().map(|(i, p)| (i + 1, p)).filter(|(j, _)| j % 4 == 0) {
            let prec = p.l.prec();
            let print = |x: &Float, scale: &Float| print_mpfr(x, scale, d, requested);
            let _ = writeln!(
                s.markdown,
                "| `{}` | {} | {j} | {} | {} | {} | {} | {} | {} | {} |",
                r.scene,
                r.problem.convention().name(),
                print(&p.l, &p.l),
                print(&p.a, &p.l),
                print(&p.b, &p.l),
                print(&Float::with_val(prec, &p.c / &p.l), &Float::with_val(prec, 1)),
                print(&p.p1, &p.p2),
                print(&p.p2, &p.p2),
                fmt_digits(Some(d)),
            );
        }
    }
    s.markdown.push('\n');
}

/// One value of a path point.
type PathValue = fn(&LawPathPoint) -> &Float;

/// The three charts of each scene (the rows of one scene on one chart, named by convention).
fn charts(s: &mut Section, rows: &[Row]) {
    let mut scenes: Vec<&str> = rows.iter().map(|r| r.scene.as_str()).collect();
    scenes.dedup();
    for (i, name) in scenes.iter().enumerate() {
        let solved: Vec<(&Row, &LawSolution)> =
            rows.iter().filter(|r| r.scene == *name).filter_map(|r| r.solution.as_ref().ok().map(|x| (r, x))).collect();
        let Some((first, _)) = solved.first() else { continue };
        let p0 = &first.problem;
        // Lengths over L and loads over E* k L^2; the single punch has no L: its final l instead.
        let (big_l, unit_name) = match p0.period() {
            periodic_contact::model::Period::Finite(l) => (to_f64(l).unwrap_or(f64::NAN), "L"),
            periodic_contact::model::Period::Infinite => (solved[0].1.values.l.to_f64(), "l_final"),
        };
        let load_unit = to_f64(&(p0.material().contact_modulus() * p0.k())).unwrap_or(f64::NAN) * big_l * big_l;
        let mut ends = Vec::new();
        let mut stresses = Vec::new();
        let mut ratio = Vec::new();
        for (k, (r, sol)) in solved.iter().enumerate() {
            let conv = r.problem.convention().name();
            let v = &sol.values;
            let col = |j: usize| Some(3 * k + j);
            let getters: [(&str, PathValue); 3] = [("a", |p| &p.a), ("b", |p| &p.b), ("l", |p| &p.l)];
            for (j, (what, get)) in getters.into_iter().enumerate() {
                let origin = std::iter::once((0.0, 0.0));
                ends.push(Curve {
                    name: format!("{what}/{unit_name}, {conv}"),
                    points: origin
                        .chain(v.path.iter().map(|p| (p.p2.to_f64() / load_unit, get(p).to_f64() / big_l)))
                        .collect(),
                    draw: if what == "l" { Draw::Dashed } else { Draw::LineMarkers },
                    colour: col(j),
                });
            }
            let unit = stress_scale(&r.problem, v).to_f64();
            let xh = |x: &Exact| to_f64(x).unwrap_or(f64::NAN);
            for (j, (what, q)) in [("q2", true), ("q1", false)].into_iter().enumerate() {
                stresses.push(Curve {
                    name: format!("{what}/(E* k l), {conv}"),
                    points: v
                        .stresses
                        .iter()
                        .map(|s| (xh(&s.xh), if q { s.q2.to_f64() } else { s.q1.to_f64() } / unit))
                        .collect(),
                    draw: Draw::LineMarkers,
                    colour: col(j),
                });
            }
            ratio.push(Curve {
                name: format!("|q1|/q2, {conv}"),
                points: v
                    .stresses
                    .iter()
                    .map(|s| (xh(&s.xh), if s.q2 > 0 { (s.q1.to_f64() / s.q2.to_f64()).abs() } else { f64::NAN }))
                    .collect(),
                draw: Draw::LineMarkers,
                colour: col(0),
            });
            if let Some((f, _, _)) = friction(&r.problem, sol) {
                ratio.push(Curve {
                    name: format!("friction needed {:.4}, {conv}", f.to_f64()),
                    points: vec![(-1.0, f.to_f64()), (1.0, f.to_f64())],
                    draw: Draw::Dashed,
                    colour: col(1),
                });
            }
        }
        let law = format!("{}, {}", law_text(p0.law()), size_text(p0.size()));
        let stems =
            [format!("loading_law_{i}_ends"), format!("loading_law_{i}_stresses"), format!("loading_law_{i}_friction")];
        let _ = writeln!(
            s.markdown,
            "Scene `{name}` ({law}): ends against load along the loading ![ends]({}.svg) (data: `{}.csv`); \
             stresses across the final contact ![stresses]({}.svg) (data: `{}.csv`); |q1|/q2 against the friction \
             needed ![friction]({}.svg) (data: `{}.csv`).\n",
            stems[0], stems[0], stems[1], stems[1], stems[2], stems[2]
        );
        let charts = [
            (
                ends,
                "Contact ends along the loading",
                format!("normal load per punch P2/(E* k {unit_name}^2) [-]"),
                format!("a/{unit_name}, b/{unit_name}, l/{unit_name} [-]"),
                Legend::UpperLeft,
            ),
            (
                stresses,
                "Stresses across the final contact",
                "xh = (x - c)/l [-]".to_string(),
                "q/(E* k l) [-]".to_string(),
                Legend::Above,
            ),
            (
                ratio,
                "Friction complete adhesion needs",
                "xh = (x - c)/l [-]".to_string(),
                "|q1|/q2 [-]".to_string(),
                Legend::Above,
            ),
        ];
        for ((curves, title, x_label, y_label, legend), stem) in charts.into_iter().zip(stems) {
            s.charts.push(Chart {
                stem,
                title: format!("{title}, {law}"),
                x_label,
                y_label,
                x_log: false,
                y_log: false,
                curves,
                legend,
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn values(x: [f64; 6]) -> MethodValues {
        let f = |v: f64| Float::with_val(128, v);
        MethodValues { a: f(x[0]), b: f(x[1]), c: f(x[2]), l: f(x[3]), p1: f(x[4]), p2: f(x[5]) }
    }

    /// The agreement is the fewest digits over the ends (scale l) and loads (scale P2).
    #[test]
    fn agreement_is_the_worst_quantity_on_its_scale() {
        let u = values([0.2, 0.1, -0.05, 0.15, 0.01, 0.05]);
        let mut v = u.clone();
        v.b = Float::with_val(128, 0.1 + 0.15e-9);
        v.p1 = Float::with_val(128, 0.01 + 0.05e-12);
        assert!((agreement(&u, &v, 20.0) - 9.0).abs() < 1e-6, "{}", agreement(&u, &v, 20.0));
        v.b = u.b.clone();
        assert!((agreement(&u, &v, 20.0) - 12.0).abs() < 1e-6);
        assert_eq!(agreement(&u, &u, 20.0), 20.0);
    }

    #[test]
    fn profile_points_hold_the_shipped_points() {
        let full = profile_points(Profile::Full);
        assert_eq!(full.len(), 39);
        for x in [(-9, 10), (-1, 2), (0, 1), (1, 2), (9, 10)] {
            assert!(full.contains(&Exact::new(x.0.into(), x.1.into())), "{x:?}");
        }
        assert_eq!(profile_points(Profile::Fast).len(), 19);
    }
}
