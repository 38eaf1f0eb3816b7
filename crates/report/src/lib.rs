//! The report (`periodic-contact report`): the main job. It opens with its findings
//! ([`summary`]: what each section ran, its failures and refusals, and a contents list), then the
//! sections (each a module, data -> text and charts; the runs are in [`runner`]):
//! 1. exact coefficient tables ([`coefficients`]; long coefficients as excerpts, whole in
//!    `coefficients.csv` and `coefficients.tex`);
//! 2. method choice by accuracy target ([`choice`], from the calibration table [`calibration`]);
//! 3. convergence orders of the series against the MPFR solution ([`orders`]);
//! 4. speed against accuracy ([`speed`]);
//! 5. stability maps from actual runs ([`stability`]);
//! 6. load-size curves from the scenes' sweeps with closed forms ([`sweeps`]);
//! 7. paper vs periodic: the two surface conventions of Problem 1 on the friction and wear scenes
//!    ([`conventions`]);
//! 8. punch shapes: the scenes' polynomial and circular profiles against the closed-form
//!    frictionless load of docs/theory.md section 9 ([`shapes`]; no text when no scene has one);
//! 9. loading law: Problem 2 under P1 = N(P2), the scenes' loading-law problems with their loading
//!    path, stresses and the friction they need ([`loading_law`]; no text when no scene has one);
//! 10. Pade resummation ([`pade`]);
//! 11. timings of this run with the machine, in `timings.md` (kept out of `report.md`, which is
//!     deterministic and snapshot-tested);
//! 12. finite friction ([`friction`]: the single punch and the periodic row with stick and slip,
//!     after the timings so that the sections before it keep their text; its last part the Problem
//!     2 stability map with friction, [`friction_map`]).
//!
//! No line of `report.md` exceeds [`summary::LONGEST_LINE`] characters.
//!
//! Every chart is written as SVG ([`chart`], plotters) with the CSV of its data beside it;
//! `report.html` ([`html`]) is the whole report as one page with the charts inline.

pub mod calibration;
pub mod chart;
pub mod choice;
pub mod coefficients;
pub mod conventions;
pub mod friction;
pub mod friction_map;
pub mod html;
pub mod loading_law;
pub mod orders;
pub mod pade;
pub mod parallel;
pub mod runner;
pub mod section;
pub mod shapes;
pub mod speed;
pub mod stability;
pub mod summary;
pub mod sweeps;

use indicatif::{ProgressBar, ProgressStyle};
use periodic_contact::scene::{parse::parse_scene, Scene};
use section::{Ctx, Profile, Section};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// What a report run wrote.
#[derive(Debug, Clone)]
pub struct ReportFiles {
    /// Files written, in order.
    pub files: Vec<PathBuf>,
    /// The Markdown text of `report.md` (deterministic).
    pub markdown: String,
}

/// How to run the report.
#[derive(Debug, Clone)]
pub struct ReportOptions {
    /// Output folder (created if missing).
    pub out: PathBuf,
    /// Scene folder (`*.toml`, read in file-name order).
    pub scenes: PathBuf,
    /// Order of the coefficient tables.
    pub order: usize,
    /// Size of the run.
    pub profile: Profile,
    /// Show a progress bar on stderr.
    pub progress: bool,
    /// Threads for the sections and cells (`None`: one per logical CPU, or `RAYON_NUM_THREADS`;
    /// `Some(1)`: everything on the calling thread). The text does not depend on it.
    pub jobs: Option<usize>,
}

/// Why a report could not be written.
#[derive(Debug, thiserror::Error)]
pub enum ReportError {
    /// A scene file is invalid (exit code 2).
    #[error("scene {path}: {error}")]
    Scene {
        /// The file.
        path: String,
        /// What is wrong.
        error: periodic_contact::model::ModelError,
    },
    /// Reading or writing failed.
    #[error("{path}: {error}")]
    Io {
        /// The file or folder.
        path: String,
        /// The I/O error.
        error: std::io::Error,
    },
    /// The series engine failed (coefficient tables).
    #[error("coefficient tables: {0}")]
    Series(#[from] exact_series::SeriesError),
    /// The calibration table is malformed.
    #[error(transparent)]
    Calibration(#[from] calibration::TableError),
    /// The HTML page could not be made.
    #[error(transparent)]
    Html(#[from] html::HtmlError),
    /// The thread pool could not be started.
    #[error("report threads: {0}")]
    Threads(String),
    /// A chart could not be drawn.
    #[error("chart {stem}: {why}")]
    Chart {
        /// The chart.
        stem: String,
        /// Why.
        why: String,
    },
}

fn io(path: &Path) -> impl Fn(std::io::Error) -> ReportError + '_ {
    move |error| ReportError::Io { path: path.display().to_string(), error }
}

/// Reads every `*.toml` scene of `dir`, sorted by file name; the name is the file stem. Scenes with
/// finite friction (`[adhesion] friction`, docs/theory.md section 17) are left out: the sections
/// run the complete-adhesion methods, which such a scene refuses, and section 12 ([`friction`])
/// computes its own fixed cases; `solve` answers them.
pub fn load_scenes(dir: &Path) -> Result<Vec<(String, Scene)>, ReportError> {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(io(dir))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    paths.sort();
    let mut out = Vec::new();
    for p in paths {
        let text = std::fs::read_to_string(&p).map_err(io(&p))?;
        let scene = parse_scene(&text).map_err(|error| ReportError::Scene { path: p.display().to_string(), error })?;
        if matches!(&scene.problem, periodic_contact::scene::SceneProblem::Adhesion(a) if a.friction().is_some()) {
            continue;
        }
        let name = p.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
        out.push((name, scene));
    }
    Ok(out)
}

/// The machine, as stated in `timings.md`: architecture, CPU model, logical CPUs.
pub fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .map(|l| l.split(':').nth(1).unwrap_or("").trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let n = std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1);
    format!("{} {}, {cpu}, {n} logical CPUs", std::env::consts::ARCH, std::env::consts::OS)
}

/// Writes the report into `opts.out`: `report.md`, `coefficients.tex`, `timings.md`, for
/// every chart `<stem>.svg` and `<stem>.csv`, and `report.html`, the whole report as one
/// self-contained page ([`html::page`]).
pub fn write_report(opts: &ReportOptions) -> Result<ReportFiles, ReportError> {
    let start = Instant::now();
    std::fs::create_dir_all(&opts.out).map_err(io(&opts.out))?;
    let scenes = load_scenes(&opts.scenes)?;
    let progress = if opts.progress {
        let pb = ProgressBar::new(10);
        pb.set_style(
            ProgressStyle::with_template("{spinner} [{elapsed_precise}] section {pos}/{len} {wide_msg}")
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
        );
        pb.enable_steady_tick(std::time::Duration::from_millis(200));
        pb
    } else {
        ProgressBar::hidden()
    };
    let ctx =
        Ctx { profile: opts.profile, cache: Default::default(), progress, table: calibration::Table::committed()? };
    let order = opts.order;
    // The sections, independent of each other (they share only the run cache), in the report's
    // order; `cost` orders their start (the costliest first, measured: the stability maps, then the
    // loading law, the punch shapes and the load-size curves) so that the long ones overlap.
    type Build<'a> = Box<dyn Fn(&Ctx) -> Result<(Section, String), ReportError> + Sync + 'a>;
    let plain = |f: fn(&Ctx, &[(String, Scene)]) -> Section| -> Build<'_> {
        let scenes = &scenes;
        Box::new(move |c: &Ctx| Ok((f(c, scenes), String::new())))
    };
    let jobs: Vec<(&str, f64, Build)> = vec![
        (
            "1. coefficient tables",
            1.0,
            Box::new(move |_: &Ctx| {
                let tables = coefficients::coefficient_tables(order)?;
                let tex = coefficients::latex(&tables);
                let files = vec![("coefficients.csv".to_string(), coefficients::csv(&tables))];
                Ok((Section { markdown: coefficients::markdown(&tables, order), files, ..Default::default() }, tex))
            }),
        ),
        ("method choice", 2.0, plain(choice::section)),
        ("2. convergence orders", 1.5, plain(orders::section)),
        ("3. speed against accuracy", 2.5, Box::new(|c: &Ctx| Ok((speed::section(c), String::new())))),
        ("4. stability maps", 100.0, Box::new(|c: &Ctx| Ok((stability::section(c), String::new())))),
        ("5. load-size curves", 9.0, plain(sweeps::section)),
        ("6. paper vs periodic", 3.0, plain(conventions::section)),
        ("punch shapes", 8.0, plain(shapes::section)),
        ("loading law", 20.0, plain(loading_law::section)),
        ("Pade resummation", 5.0, Box::new(|c: &Ctx| Ok((pade::section(c), String::new())))),
        ("12. finite friction", 1.0, Box::new(|c: &Ctx| Ok((friction::section(c), String::new())))),
    ];
    let done = parallel::with_jobs(opts.jobs, || {
        parallel::map(
            &jobs,
            |j| j.1,
            |(name, _, build)| {
                let t0 = Instant::now();
                let r = build(&ctx);
                ctx.progress.inc(1);
                (r, format!("| {name} | {:.2} |\n", t0.elapsed().as_secs_f64()))
            },
        )
    })
    .map_err(ReportError::Threads)?;
    ctx.progress.finish_and_clear();
    let threads = opts.jobs.unwrap_or_else(rayon::current_num_threads);
    let mut files = Vec::new();
    let mut sections: Vec<Section> = Vec::new();
    let mut timings = String::new();
    let mut tex = String::new();
    for (r, line) in done {
        let (section, t) = r?;
        sections.push(section);
        tex.push_str(&t);
        timings.push_str(&line);
    }

    let mut body = String::new();
    let names: Vec<&str> = scenes.iter().map(|s| s.0.as_str()).collect();
    // the last section (12, finite friction) follows the timings' pointer: the sections before it
    // keep their text
    let (friction_section, numbered) = match sections.split_last() {
        Some((last, rest)) => (Some(last), rest),
        None => (None, &sections[..]),
    };
    for (i, s) in numbered.iter().enumerate() {
        if i == 0 {
            let _ = writeln!(
                body,
                "Scenes: {}. Timings of this run and the machine: `timings.md` (section 11; kept out of this \
                 text, which is deterministic).\n",
                names.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", ")
            );
        }
        body.push_str(&s.markdown);
    }
    let _ = writeln!(body, "## 11. Timings\n\nSee `timings.md`: measured in the run that wrote this report.");
    if let Some(f) = friction_section {
        body.push('\n');
        body.push_str(&f.markdown);
    }
    let findings: Vec<String> = sections.iter().flat_map(|s| s.findings.iter().cloned()).collect();
    let md = summary::wrap_long_lines(&summary::front(&body, names.len(), &findings), summary::LONGEST_LINE);
    let write = |files: &mut Vec<PathBuf>, name: &str, text: &str| -> Result<(), ReportError> {
        let p = opts.out.join(name);
        write_whole(&p, text.as_bytes()).map_err(io(&p))?;
        files.push(p);
        Ok(())
    };
    write(&mut files, "report.md", &md)?;
    write(&mut files, "coefficients.tex", &tex)?;
    for s in &sections {
        for (name, text) in &s.files {
            write(&mut files, name, text)?;
        }
    }
    let mut svgs = std::collections::BTreeMap::new();
    for s in &sections {
        for c in &s.charts {
            let svg = c.svg().map_err(|why| ReportError::Chart { stem: c.stem.clone(), why })?;
            write(&mut files, &format!("{}.svg", c.stem), &svg)?;
            write(&mut files, &format!("{}.csv", c.stem), &c.csv())?;
            svgs.insert(format!("{}.svg", c.stem), svg);
        }
    }
    write(&mut files, "report.html", &html::page("periodic-contact report", &md, &svgs, &tex)?)?;
    let mut t = format!(
        "# Timings of this report run\n\nMachine: {}. Build: {}. Profile: {:?}. Threads: {threads} (the sections and \
         the stability maps' cells run in parallel, so the section times below overlap). Total wall time: {:.1} s.\n\n\
         | section | seconds |\n|---|---:|\n{timings}",
        machine(),
        if cfg!(debug_assertions) { "debug" } else { "release" },
        opts.profile,
        start.elapsed().as_secs_f64()
    );
    for s in &sections {
        if !s.timings.is_empty() {
            t.push('\n');
            t.push_str(&s.timings);
        }
    }
    write(&mut files, "timings.md", &t)?;
    Ok(ReportFiles { files, markdown: md })
}

/// Writes `bytes` to `path` whole or not at all (issue 34): into `.NAME.partial-PID` in the same
/// directory, flushed to the disk, then renamed over `path` (atomic on one file system). An
/// interrupted run (Ctrl-C, a kill) leaves `path` as it was; the report writes its files only
/// after every section is computed, so an interruption during the computation leaves the previous
/// report intact (test `crates/cli/tests/all/interrupt.rs`).
pub fn write_whole(path: &std::path::Path, bytes: &[u8]) -> std::io::Result<()> {
    use std::io::Write as _;
    let name = path.file_name().map_or_else(|| "out".into(), |n| n.to_string_lossy().into_owned());
    let tmp = path.with_file_name(format!(".{name}{}", partial_suffix()));
    let result = (|| {
        let mut f = std::fs::File::create(&tmp)?;
        f.write_all(bytes)?;
        f.sync_all()?;
        std::fs::rename(&tmp, path)
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// The ending of this process's temporary names in [`write_whole`]: `.partial-PID`.
fn partial_suffix() -> String {
    format!(".partial-{}", std::process::id())
}

/// Removes this process's temporary files of [`write_whole`] from `dir` (the CLI's Ctrl-C handler
/// calls it before it exits): the files `.NAME.partial-PID` of this process id; returns how many were
/// removed. Other processes' temporary files are left alone.
pub fn remove_partial_files(dir: &std::path::Path) -> usize {
    let suffix = partial_suffix();
    let Ok(entries) = std::fs::read_dir(dir) else { return 0 };
    entries
        .filter_map(Result::ok)
        .filter(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            name.starts_with('.') && name.ends_with(&suffix)
        })
        .filter(|e| std::fs::remove_file(e.path()).is_ok())
        .count()
}
