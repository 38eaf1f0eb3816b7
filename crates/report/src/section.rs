//! What every report section returns, and the state the sections share.

use super::calibration::Table;
use super::chart::Chart;
use super::runner::RunCache;
use indicatif::ProgressBar;

/// Size of the run: the default report, or the fixed fast set of the snapshot test.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Profile {
    /// The default report (under 5 minutes on 2 cores, release build).
    Full,
    /// Small grids (snapshot test, seconds).
    Fast,
}

/// One section: Markdown (deterministic: no timings), charts (SVG + CSV), timings (separate file).
#[derive(Debug, Default)]
pub struct Section {
    /// Markdown text.
    pub markdown: String,
    /// Charts.
    pub charts: Vec<Chart>,
    /// Timing lines for `timings.md` (Markdown).
    pub timings: String,
    /// Further data files of the section, (file name, text), e.g. `coefficients.csv`.
    pub files: Vec<(String, String)>,
    /// Headline findings for the report's summary, one sentence each (deterministic).
    pub findings: Vec<String>,
}

/// Shared state of a report run (shared by reference between the threads: the sections and the
/// stability maps' cells run in parallel, [`super::parallel`]).
pub struct Ctx {
    /// Size of the run.
    pub profile: Profile,
    /// Derived expansions and every run, shared by the sections and their threads.
    pub cache: RunCache,
    /// Progress (stderr).
    pub progress: ProgressBar,
    /// The calibration table.
    pub table: Table,
}

impl Ctx {
    /// Shows what is being computed.
    pub fn step(&self, msg: impl Into<String>) {
        self.progress.set_message(msg.into());
        self.progress.tick();
    }
}

/// Formats digits for the text: one decimal, rounded down as every digit count is printed
/// ([`periodic_contact::numerics::accuracy::digits_text`]), or "fail".
pub fn fmt_digits(d: Option<f64>) -> String {
    match d {
        Some(x) => periodic_contact::numerics::accuracy::digits_text(x),
        None => "fail".into(),
    }
}
