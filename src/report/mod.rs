//! The report (`periodic-contact report`): pure functions from data to text, and the writer.

pub mod coefficients;

use std::path::{Path, PathBuf};

/// What a report run wrote.
#[derive(Debug, Clone)]
pub struct ReportFiles {
    /// Files written, in order.
    pub files: Vec<PathBuf>,
}

/// Writes the report into `out` (created if missing): `report.md` and `coefficients.tex`.
pub fn write_report(out: &Path, order: usize) -> anyhow::Result<ReportFiles> {
    std::fs::create_dir_all(out)?;
    let tables = coefficients::coefficient_tables(order)?;
    let md = out.join("report.md");
    let tex = out.join("coefficients.tex");
    std::fs::write(&md, coefficients::markdown(&tables, order))?;
    std::fs::write(&tex, coefficients::latex(&tables))?;
    Ok(ReportFiles { files: vec![md, tex] })
}
