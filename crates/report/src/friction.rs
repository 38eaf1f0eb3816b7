//! Section 12, finite friction (docs/theory.md section 17): the single punch's stick ratio c/a and
//! load coefficient P/(E* k a^2) against beta/mu, their approach to complete adhesion as mu grows,
//! and the periodic row's c/a and load P = P2/(E* k (L/pi)^2) against lambda at two mu in both
//! surface conventions; nu = 0 throughout (beta = 1/2), every value with its estimate (the
//! difference of two discretisations). Cheap by design (coarse f64 meshes: n = 10 against 20 stick
//! elements, marches (8, 12) against (16, 24)): 3.2 s in the debug build's fast report with
//! (10, 16) and (20, 32), measured, about 2 s now, a few tenths in release. Then the row at
//! lambda = 1.2 by the spectral method `solve` uses (docs/theory.md sections 17.5, 17.8): c/a and
//! P on (load nodes, polynomials) = (6, 6) against (8, 8) (`solve` uses (8, 6) and (10, 8)), the
//! four cases in parallel ([`super::parallel::map`]). Measured with them: the section took 49.6 s
//! of a 209 s full release report at load average 10.8 on 2 cores (overlapping section 4's 208 s;
//! the report is about 27 s on an idle machine).

use super::section::{Ctx, Section};
use periodic_contact::adhesion::friction::row_f64::row_stick_ratio;
use periodic_contact::adhesion::friction::row_load_f64::march;
use periodic_contact::adhesion::friction::single_punch::{solve, Method};
use periodic_contact::adhesion::friction::spectral_row::stick_ratio_f64;
use periodic_contact::solve::answer_friction_row::row_load;
use std::fmt::Write;

/// beta at nu = 0.
const BETA: f64 = 0.5;
/// Stick elements of the coarser single-punch mesh.
const N: usize = 10;
/// Complete adhesion's single-punch load coefficient at nu = 0, pi/(2 (1 - 2 eps S))
/// (docs/theory.md section 4; `growing_friction_levels_off_below_complete_adhesion` checks it).
const ADHESION_CP: f64 = 1.957_87;

/// A value with its estimate, as "v (e)".
fn with_error(v: f64, e: f64) -> String {
    format!("{v:.5} ({e:.0e})")
}

/// The section (module doc).
pub fn section(ctx: &Ctx) -> Section {
    ctx.step("finite friction");
    let mut s = Section::default();
    let md = &mut s.markdown;
    let _ = writeln!(
        md,
        "## 12. Finite friction\n\n\
         Problem 2 with Coulomb friction mu (docs/theory.md section 17): stick in the middle |x| < c, slip at the \
         ends c < |x| < a, normal loading of parabolic punches, nu = 0. f64 methods on coarse meshes; in brackets \
         the difference from a mesh half as fine (the estimate; `solve` uses meshes four times finer).\n\n\
         Single punch (self-similar: c/a and P/(E* k a^2) constant during loading), against beta/mu:\n\n\
         | beta/mu | mu | c/a | P/(E* k a^2) |\n|---|---|---|---|"
    );
    let mut failed = Vec::new();
    for (ratio, mu) in [(2.0, 0.25), (1.0, 0.5), (0.5, 1.0), (0.3, 0.5 / 0.3), (0.1, 5.0)] {
        match solve(BETA, mu, N, Method::Increment) {
            Ok(r) => {
                let _ = writeln!(
                    md,
                    "| {ratio} | {mu:.4} | {} | {} |",
                    with_error(r.gamma, r.gamma_error),
                    with_error(r.load_coefficient, r.load_coefficient_error)
                );
            }
            Err(e) => failed.push(format!("single punch mu = {mu}: {e}")),
        }
    }
    let _ = writeln!(
        md,
        "\nApproach to complete adhesion (P/(E* k a^2) = {ADHESION_CP} at nu = 0) as mu grows:\n\n\
         | mu | c/a | P/(E* k a^2) | gap to complete adhesion |\n|---|---|---|---|"
    );
    for mu in [1.0, 4.0, 16.0, 64.0] {
        match solve(BETA, mu, N, Method::Increment) {
            Ok(r) => {
                let _ = writeln!(
                    md,
                    "| {mu} | {} | {} | {:.4} |",
                    with_error(r.gamma, r.gamma_error),
                    with_error(r.load_coefficient, r.load_coefficient_error),
                    ADHESION_CP - r.load_coefficient
                );
            }
            Err(e) => failed.push(format!("single punch mu = {mu}: {e}")),
        }
    }
    let _ = writeln!(
        md,
        "\nThe gap levels off near 0.008 on these coarse meshes: as mu grows the slip zones do not close but tend to about \
         0.0037 a, and P/(E* k a^2) to 1.95054, 0.375% below complete adhesion, approached like 1/mu (the MPFR spectral \
         method to mu = 64 and the increment method to mu = 1024, docs/theory.md 17.3: complete adhesion's |q1|/q2 takes \
         every value near its ends, so some slip remains whatever mu).\n\n\
         Periodic row, lambda = pi a/L, P = P2/(E* k (L/pi)^2) (c/a: n = 20, the estimate the larger of its difference from n = 10 and half \
         that of n = 10 and 5; P: marches (8, 12) against (16, 24)):\n\n\
         | convention | mu | lambda | c/a | P |\n|---|---|---|---|---|"
    );
    for periodic in [false, true] {
        let name = if periodic { "periodic" } else { "paper" };
        for mu in [0.3, 1.0] {
            let (coarse, fine) =
                match (march(BETA, mu, 1.2, 8, 12, periodic, None), march(BETA, mu, 1.2, 16, 24, periodic, None)) {
                    (Ok(c), Ok(f)) => (c, f),
                    (Err(e), _) | (_, Err(e)) => {
                        failed.push(format!("row {name} mu = {mu}: {e}"));
                        continue;
                    }
                };
            for j in [2, 5, 8, 11] {
                let (c, f) = (coarse[j], fine[2 * j + 1]);
                // n = 5, 10, 20: the last difference can vanish by chance, so half the first
                // bounds the estimate from below (first order)
                let g = |n| row_stick_ratio(BETA, mu, f.lambda, n, periodic);
                let ratio = match (g(5), g(10), g(20)) {
                    (Ok(g0), Ok(g1), Ok(g2)) => with_error(g2, (g2 - g1).abs().max(0.5 * (g1 - g0).abs())),
                    (Err(e), _, _) | (_, Err(e), _) | (_, _, Err(e)) => format!("refused: {e}"),
                };
                let _ = writeln!(
                    md,
                    "| {name} | {mu} | {:.2} | {ratio} | {} |",
                    f.lambda,
                    with_error(f.load, (f.load - c.load).abs())
                );
            }
        }
    }
    let _ = writeln!(
        md,
        "\nThe conventions part ways: in `periodic` (u periodic, a laterally rigid row) the stick zone grows toward the \
         whole contact with lambda, in `paper` (the Flamant far field) it shrinks.\n\n\
         The row at lambda = 1.2 by the spectral method (what `solve` answers with; docs/theory.md 17.8): c/a and P on \
         (load nodes, polynomials per family) = (8, 8), in brackets the difference from (6, 6):\n\n\
         | convention | mu | c/a | P |\n|---|---|---|---|"
    );
    let cases: Vec<(bool, f64)> = [false, true].iter().flat_map(|&p| [0.3, 1.0].map(|mu| (p, mu))).collect();
    let rows = super::parallel::map(
        &cases,
        |_| 1.0,
        |&(periodic, mu)| {
            let g = |n| stick_ratio_f64(BETA, mu, 1.2, n, periodic);
            let p = |mesh| row_load(BETA, mu, 1.2, mesh, periodic);
            match (g(6), g(8), p((6, 6)), p((8, 8))) {
                (Ok(g0), Ok(g1), Ok(p0), Ok(p1)) => {
                    Ok(format!("{} | {:.8} ({:.0e})", with_error(g1, (g1 - g0).abs()), p1, (p1 - p0).abs()))
                }
                (Err(e), ..) | (_, Err(e), ..) => Err(e.to_string()),
                (.., Err(e), _) | (.., Err(e)) => Err(e.to_string()),
            }
        },
    );
    for (&(periodic, mu), row) in cases.iter().zip(rows) {
        let name = if periodic { "periodic" } else { "paper" };
        match row {
            Ok(r) => {
                let _ = writeln!(md, "| {name} | {mu} | {r} |");
            }
            Err(e) => failed.push(format!("row {name} mu = {mu} (spectral): {e}")),
        }
    }
    let _ = writeln!(
        md,
        "\nThe spectral method and the marches agree within the marches' estimates. This section computes the approach \
         to complete adhesion only for the single punch at nu = 0 (the table above); its rate in 1/mu is measured in \
         docs/theory.md, not here, at nu = 0.3 by the spectral method resolving narrow slip zones (`Spectral::narrow`). \
         Single punch (17.3 \"Large mu\", `examples/mu_rate.rs`, n = 18; at mu = 1024 n = 10 and 14 agree to 2.7e-5 \
         relative in 1 - c/a and 1.6e-3 of the load's gap): 1 - c/a falls from 2.1076e-3 at mu = 1 to 1.6076e-6 at mu = 1024 and levels off at \
         delta_inf/a = 1.599e-6 (the fit (17.15) through mu = 64, 256, 1024); the load's gap 1 - C_P/C_P_ca fits \
         G_inf + G_1/mu with G_inf = 1.599e-6, G_1 = 4.91e-6. Periodic row (17.8, `examples/mu_rate_row.rs`, \
         (load nodes, n) = (8, 10) and (12, 14) agreeing to 1.2e-6 or better in 1 - P/P_ca): 1 - P/P_ca at mu = 1 is 5.959e-4 and \
         1.1631e-2 (`paper`, lambda = 0.6, 1.2), 9.474e-5 and 3.354e-5 (`periodic`), and levels off at \
         G_inf = 2.99e-6, 1.91e-4, 3.51e-7, 1.00e-7 (the fit G_inf + G_1/mu through mu = 16, 64; it predicts mu = 8 \
         within 7-9 %). So with finite friction the limit mu -> infinity stays below complete adhesion (the single \
         punch keeps slip zones 1.6e-6 a wide). Not here: the row's load with verified digits (`solve --method mpfr`, docs/theory.md 17.8).\n"
    );
    for f in &failed {
        let _ = writeln!(md, "Not computed: {f}.\n");
    }
    super::friction_map::part(ctx, &mut s);
    s.findings.push(
        "Finite friction (nu = 0, mu = 1/2): the single punch sticks on c/a = 0.52 with 15% more load than Hertz; on \
         the periodic row the stick zone shrinks with lambda in `paper` and grows toward the whole contact in \
         `periodic`."
            .into(),
    );
    s
}
