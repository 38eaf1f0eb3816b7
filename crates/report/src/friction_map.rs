//! Report section 12, its last part: the Problem 2 stability map with friction (issue 32, Build
//! item 5), lambda = pi a/L against nu for the periodic row of parabolic punches (k = L = E* = 1)
//! with Coulomb friction mu = 1/2, in both surface conventions, beside section 5's map of complete
//! adhesion: the same grid (a subset of its nu, below), the same bins and colours
//! (`stability::binned_chart`) and the horizon's curves of complete adhesion, so the two
//! compare cell for cell.
//!
//! A cell's value: the digits on which the two discretisations of the `f64` spectral row that
//! `solve` uses ([`COARSE`] and [`FINE`], (load nodes, polynomials per family)) agree on the load
//! P = P2/(E* k (L/pi)^2) (relative, capped at 16 as section 5's `f64` cells); "failed" with the
//! method's refusal listed. c/a is not judged: it is local in lambda, one root per cell and
//! discretisation, which would double the cost.
//!
//! A column (nu, convention, discretisation) is one load: the collocation of (17.11) on
//! (0, top), top the column's largest lambda, gives P at every lambda below it
//! ([`row_loads`]: the Volterra equation on (0, chi) involves F on (0, chi) only). Measured at
//! nu = 0, mu = 1/2, top = 1.4 (`cargo run --release --example friction_map_column -- 0 0.5 1.4`):
//! the column's P at lambda < top differs from a load solved at lambda by 1.5e-6 .. 2.7e-6
//! relative in COARSE and 3e-8 .. 2.7e-7 in FINE (`paper`, its nodes in eta^2, docs/theory.md
//! 17.8), 1.8e-8 .. 2.6e-7 and 7e-10 .. 6.4e-8 (`periodic`), and is less accurate than it (at
//! lambda = 1.2, against the verified MPFR P of 17.8, FINE's column is 1.8e-7 off in `paper`,
//! the direct load 3e-12; `periodic` 1.4e-8 and 5e-10): the top's nodes resolve F on (0, 1.4),
//! not on (0, lambda). The two columns' difference still bounds the column's error there
//! (`paper`, 1.2: 2.9e-6 against the 1.8e-7 error; `periodic` 4.5e-8 against 1.4e-8), so a cell's
//! digits are those of the column's P, at most about two fewer than a load solved at that lambda.
//! Solving
//! every cell on its own costs nine times as much (one load per cell).
//!
//! Cost (measured, release, machine shared by six sessions, load average 6 to 7): one nu in both
//! conventions, COARSE and FINE columns to 1.4, 4.7 s of CPU at nu = 0 (5.9 s at nu = 0.3); beta =
//! 0 (nu = 1/2) is one solve per node, no root. The default report's budget for this part is about
//! 4 s of CPU, so its map has nu = 0 (where complete adhesion's mode is strongest) and nu = 1/2
//! (where friction does nothing, Kuznetsov's load), not section 5's six nu; the fast report
//! (snapshot) one column, nu = 3/10 at section 5's fast lambda = 0.4.

use super::section::{fmt_digits, Ctx, Profile, Section};
use super::stability::{bin, binned_chart};
use exact_series::Q;
use periodic_contact::model::Material;
use periodic_contact::solve::answer_friction_row::{row_loads, COARSE, FINE};
use std::fmt::Write as _;

/// The friction coefficient of the map.
pub const MU: f64 = 0.5;

/// One cell of the map: the loads of the two discretisations, or the method's refusal.
#[derive(Debug, Clone)]
pub struct FrictionCell {
    /// Poisson's ratio.
    pub nu: f64,
    /// lambda = pi a/L.
    pub lambda: f64,
    /// P = P2/(E* k (L/pi)^2) on ([`COARSE`], [`FINE`]), or the refusal.
    pub load: Result<(f64, f64), String>,
}

impl FrictionCell {
    /// Digits where the two discretisations agree on P (relative, capped at 16); None: failed.
    pub fn digits(&self) -> Option<f64> {
        self.load.as_ref().ok().map(|(coarse, fine)| super::runner::digits_of((fine - coarse) / fine, 16.0))
    }

    /// The cell's bin on section 5's scale ([`bin`]).
    fn bin(&self) -> usize {
        bin(self.digits().map(Some).ok_or(()))
    }
}

/// beta = (1 - 2 nu)/(2 (1 - nu)) of nu = `n`/`d` (E* = 1), as section 5's cells build it.
fn beta_of(n: i64, d: i64) -> Result<f64, String> {
    let m = Material::from_contact_modulus(Q::new(n.into(), d.into()), Q::new(1.into(), 1.into()))
        .map_err(|e| e.to_string())?;
    periodic_contact::numerics::exact::to_f64(&m.beta()).ok_or_else(|| "beta is not finite".to_string())
}

/// The cells of one column: nu = `n`/`d`, every lambda of `lambdas` (ascending, the last the
/// column's top), in `periodic` or `paper`, from one load per discretisation ([`row_loads`]).
pub fn column(n: i64, d: i64, lambdas: &[f64], periodic: bool) -> Vec<FrictionCell> {
    let nu = n as f64 / d as f64;
    let top = lambdas.iter().copied().fold(0.0, f64::max);
    let loads = beta_of(n, d).and_then(|beta| {
        let at = |mesh| row_loads(beta, MU, top, lambdas, mesh, periodic).map_err(|e| e.to_string());
        Ok((at(COARSE)?, at(FINE)?))
    });
    lambdas
        .iter()
        .enumerate()
        .map(|(i, &lambda)| FrictionCell {
            nu,
            lambda,
            load: loads.as_ref().map(|(c, f)| (c[i], f[i])).map_err(Clone::clone),
        })
        .collect()
}

/// The grid of `profile`: nu as (numerator, denominator), and lambda (module doc).
pub fn grid(profile: Profile) -> (Vec<(i64, i64)>, Vec<f64>) {
    match profile {
        Profile::Full => (vec![(0, 1), (1, 2)], vec![0.2, 0.5, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3, 1.4]),
        Profile::Fast => (vec![(3, 10)], vec![0.4]),
    }
}

/// Appends the map to section 12 (module doc): the table of both conventions, the refusals, the
/// two charts and what they show; its CPU time to the timings.
pub fn part(ctx: &Ctx, s: &mut Section) {
    ctx.step("finite friction: stability map");
    let (nus, lambdas) = grid(ctx.profile);
    let columns: Vec<(i64, i64, bool)> =
        [false, true].iter().flat_map(|&p| nus.iter().map(move |&(n, d)| (n, d, p))).collect();
    let t0 = std::time::Instant::now();
    let done = super::parallel::map(&columns, |_| 1.0, |&(n, d, periodic)| column(n, d, &lambdas, periodic));
    let seconds = t0.elapsed().as_secs_f64();
    let _ = writeln!(s.timings, "| finite friction: stability map ({} columns) | {seconds:.2} |", columns.len());
    let (paper, periodic) = done.split_at(nus.len());
    let md = &mut s.markdown;
    let _ = writeln!(
        md,
        "### The Problem 2 stability map with friction\n\n\
         The periodic row of parabolic punches (k = L = E* = 1) with mu = {MU}, beside section 5's map of complete \
         adhesion (same lambda, same bins and colours, the dashed curves its horizon lambda_h(nu, d)). A cell: the \
         digits on which the `f64` spectral row's two discretisations that `solve` uses, (load nodes, polynomials) \
         = {COARSE:?} and {FINE:?}, agree on P = P2/(E* k (L/pi)^2) (P2 the finer's; c/a not judged). A column of \
         the map is one load per discretisation, solved to its largest lambda, which gives P below it too at up to \
         about two digits fewer than a load solved at that lambda (`crates/report/src/friction_map.rs`). {}\n\n\
         | nu | lambda | `paper`: P2 | digits | `periodic`: P2 | digits |\n|---:|---:|---:|---:|---:|---:|",
        if ctx.profile == Profile::Full {
            "nu = 0 and 1/2 only: section 5's six nu would cost about 25 s of CPU."
        } else {
            "The fast report: one cell, nu = 3/10 at lambda = 0.4."
        }
    );
    let unit = std::f64::consts::PI.powi(-2);
    let text = |c: &FrictionCell| match &c.load {
        Ok((_, fine)) => format!("{:.9} | {}", fine * unit, fmt_digits(c.digits())),
        Err(_) => "- | fail".into(),
    };
    for (a, b) in paper.iter().flatten().zip(periodic.iter().flatten()) {
        let _ = writeln!(md, "| {:.3} | {:.4} | {} | {} |", a.nu, a.lambda, text(a), text(b));
    }
    md.push('\n');
    let mut refusals: Vec<String> = Vec::new();
    for (name, cells) in [("paper", paper), ("periodic", periodic)] {
        for c in cells.iter().flatten() {
            if let Err(e) = &c.load {
                refusals.push(format!("`{name}` at nu = {:.3}, lambda = {:.3}: {e}", c.nu, c.lambda));
            }
        }
    }
    if !refusals.is_empty() {
        let _ = writeln!(md, "Failures, as the method reported them:\n");
        for r in &refusals {
            let _ = writeln!(md, "- {r}");
        }
        md.push('\n');
    }
    let mut row = "| `paper` | `periodic` |\n|---|---|\n|".to_string();
    for (name, cells) in [("paper", paper), ("periodic", periodic)] {
        let stem = format!("stability_p2_friction_{name}");
        let title = format!("Problem 2 with friction mu = {MU}, `{name}`: f64, two discretisations");
        let points: Vec<(f64, f64, usize)> = cells.iter().flatten().map(|c| (c.nu, c.lambda, c.bin())).collect();
        s.charts.push(binned_chart(&stem, &title, "nu", &points));
        row.push_str(&format!(" ![{title}]({stem}.svg) |"));
    }
    let _ = writeln!(md, "{row}\n\nData: `stability_p2_friction_paper.csv`, `stability_p2_friction_periodic.csv`.\n");
    if ctx.profile == Profile::Full {
        let _ = writeln!(md, "{}\n", shows(&nus, paper, periodic));
    } else {
        let _ = writeln!(
            md,
            "The fast report's cell: `paper` {}, `periodic` {}; the default report's map (nu = 0 and 1/2, lambda \
             0.2 .. 1.4) says what it shows against complete adhesion.\n",
            range(paper, 0.3),
            range(periodic, 0.3)
        );
    }
}

/// The digits' range "lo .. hi" of the solved cells of `cells` at nu = `nu`, and how many failed.
fn range(cells: &[Vec<FrictionCell>], nu: f64) -> String {
    let at: Vec<&FrictionCell> = cells.iter().flatten().filter(|c| c.nu == nu).collect();
    let digits: Vec<f64> = at.iter().filter_map(|c| c.digits()).collect();
    let failed = at.len() - digits.len();
    let (lo, hi) = digits.iter().fold((f64::INFINITY, 0.0f64), |(l, h), &d| (l.min(d), h.max(d)));
    let text = if digits.is_empty() {
        "none solved".into()
    } else {
        format!("{} .. {}", fmt_digits(Some(lo)), fmt_digits(Some(hi)))
    };
    if failed > 0 {
        format!("{text} digits, {failed} failed")
    } else {
        format!("{text} digits")
    }
}

/// What the map shows, against section 5's complete adhesion (its failure region: `paper`, small
/// nu, large lambda, the homogeneous mode of docs/theory.md section 11).
fn shows(nus: &[(i64, i64)], paper: &[Vec<FrictionCell>], periodic: &[Vec<FrictionCell>]) -> String {
    let per_nu: Vec<String> = nus
        .iter()
        .map(|&(n, d)| {
            let nu = n as f64 / d as f64;
            format!("nu = {nu}: `paper` {}, `periodic` {}", range(paper, nu), range(periodic, nu))
        })
        .collect();
    format!(
        "What it shows ({}): where section 5's complete adhesion fails in `paper` (small nu, large lambda: the \
         homogeneous mode, refusals at nu = 0 from lambda = 1.1 and at 1.0 2.3 verified MPFR digits, f64 4.2), friction solves every cell, \
         and the two discretisations agree about as well at lambda = 1.4 as at 0.2: no loss toward full contact, \
         so at the `f64` level the failure region does not survive friction (a remnant of the mode, if any, is \
         below the discretisations' difference, 3.6e-7 relative at lambda = 1.4 in `paper` (the columns' tops); docs/theory.md 17.8's \
         `nu_zero_two_node_counts_agree_to_lambda_1_4`: 8 and 12 nodes agree on P(1.4) to 1.0e-5 and 1.1e-5 \
         in `paper`, 1.2e-7 and 4.6e-8 in `periodic`, mu = 0.3 and 1). `paper` keeps fewer digits than \
         `periodic` below the column's top: there its column's P is 1.5e-6 .. 2.7e-6 off a load solved at that \
         lambda on the coarser discretisation (`periodic` at most 2.6e-7), interpolation, not a mode. At nu = 1/2 \
         friction does nothing (beta = 0): Kuznetsov's load in both conventions, the digits those of the \
         increments' rounding. Whether a remnant survives at 1e-20 needs the verified MPFR load per cell \
         (minutes each, 17.8): not run.",
        per_nu.join("; ")
    )
}
