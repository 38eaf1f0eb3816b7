//! The report's first screen and its line rule (issue 30): the title, a summary of what each
//! section ran (its table rows, and the cells where a method failed or refused: the reasons are in
//! the section), and a contents list linking every section ([`super::html::slug`] anchors, the
//! same in `report.md` viewers and `report.html`); then the sections. [`wrap_long_lines`] keeps
//! every Markdown line within [`LONGEST_LINE`] characters by wrapping prose (tables are kept
//! narrow by their sections: long coefficients are excerpts, [`super::coefficients`]). Tests:
//! the module's, and the report snapshot (`crates/cli/tests/all/report_snapshot.rs`).

use super::html::slug;
use std::fmt::Write as _;

/// Longest line of `report.md`.
pub const LONGEST_LINE: usize = 400;

/// Width prose is wrapped to when a line exceeds [`LONGEST_LINE`].
const WRAP: usize = 100;

/// What one level-2 section of the text holds.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SectionCount {
    /// The heading's text.
    pub heading: String,
    /// Rows of its tables (header rows not counted).
    pub rows: usize,
    /// Cells reading `fail`.
    pub failed: usize,
    /// Cells starting with `refused`.
    pub refused: usize,
}

/// The level-2 sections of `body` and what their tables hold.
pub fn count_sections(body: &str) -> Vec<SectionCount> {
    let mut out: Vec<SectionCount> = Vec::new();
    let lines: Vec<&str> = body.lines().collect();
    for (i, line) in lines.iter().enumerate() {
        if let Some(h) = line.strip_prefix("## ") {
            out.push(SectionCount { heading: h.trim().to_string(), rows: 0, failed: 0, refused: 0 });
            continue;
        }
        let Some(current) = out.last_mut() else { continue };
        let is_separator = |l: &str| l.starts_with('|') && l.chars().all(|c| "|-: ".contains(c));
        if !line.starts_with('|') || is_separator(line) || lines.get(i + 1).is_some_and(|n| is_separator(n)) {
            continue;
        }
        current.rows += 1;
        for cell in line.trim().trim_matches('|').split('|').map(str::trim) {
            if cell == "fail" {
                current.failed += 1;
            } else if cell.starts_with("refused") {
                current.refused += 1;
            }
        }
    }
    out
}

/// The report's text: title, summary (the sections' `findings` as headlines under the table),
/// contents, then `body` (the sections in order).
pub fn front(body: &str, scenes: usize, findings: &[String]) -> String {
    let counts = count_sections(body);
    let mut s = String::from("# periodic-contact report\n\n## Summary\n\n");
    let _ = writeln!(
        s,
        "What each section ran on the {scenes} scenes: the rows of its tables (each an actual run, a derived \
         series or a check against a closed form or a second method), and the cells where a method failed \
         (`fail`) or refused (`refused`); each section gives the reasons and the digits every method reached.\n\n\
         | section | table rows | `fail` cells | `refused` cells |\n|---|---:|---:|---:|"
    );
    for c in &counts {
        let _ = writeln!(s, "| [{}](#{}) | {} | {} | {} |", c.heading, slug(&c.heading), c.rows, c.failed, c.refused);
    }
    if !findings.is_empty() {
        s.push_str("\nHeadlines:\n\n");
        for f in findings {
            let _ = writeln!(s, "- {f}");
        }
    }
    s.push_str("\n## Contents\n\n");
    for c in &counts {
        let _ = writeln!(s, "- [{}](#{})", c.heading, slug(&c.heading));
    }
    s.push('\n');
    s.push_str(body);
    s
}

/// `md` with every line longer than `limit` that is prose (not a table row, heading or code)
/// wrapped at spaces to `WRAP` characters; a list item's continuation lines are indented.
pub fn wrap_long_lines(md: &str, limit: usize) -> String {
    let mut out = String::with_capacity(md.len());
    let mut code = false;
    for line in md.lines() {
        if line.starts_with("```") {
            code = !code;
        }
        if code || line.len() <= limit || line.starts_with('|') || line.starts_with('#') {
            out.push_str(line);
            out.push('\n');
            continue;
        }
        let indent = if line.starts_with("- ") { "  " } else { "" };
        let mut current = String::new();
        for word in line.split(' ') {
            if !current.is_empty() && current.len() + 1 + word.len() > WRAP {
                out.push_str(&current);
                out.push('\n');
                current = indent.to_string();
            } else if !current.is_empty() && current != indent {
                current.push(' ');
            }
            current.push_str(word);
        }
        out.push_str(&current);
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_rows_failures_and_refusals_per_section() {
        let body = "## 1. A\n\ntext\n\n| x | y |\n|---|---:|\n| 1 | fail |\n| 2 | refused: too big |\n\n## 2. B\n\n| z |\n|---|\n| 3 |\n";
        let c = count_sections(body);
        assert_eq!(c.len(), 2);
        assert_eq!((c[0].rows, c[0].failed, c[0].refused), (2, 1, 1));
        assert_eq!((c[1].rows, c[1].failed, c[1].refused), (1, 0, 0));
        let f = front(body, 3, &["Orders: all held.".to_string()]);
        assert!(f.contains("Headlines:\n\n- Orders: all held.\n"), "{f}");
        assert!(f.starts_with("# periodic-contact report\n\n## Summary\n"), "{f}");
        assert!(f.contains("| [1. A](#1-a) | 2 | 1 | 1 |") && f.contains("- [2. B](#2-b)"), "{f}");
        assert!(f.find("## Contents").unwrap() < f.find("## 1. A").unwrap());
    }

    #[test]
    fn long_prose_is_wrapped_and_nothing_else() {
        let long = vec!["word"; 150].join(" ");
        let table = format!("| {long} |");
        let md = format!("# {long}\n{long}\n- {long}\n{table}\n```\n{long}\n```\nshort\n");
        let w = wrap_long_lines(&md, 400);
        for line in w.lines().filter(|l| !l.starts_with('|') && !l.starts_with('#')) {
            assert!(line.len() <= WRAP || line == long, "{line}");
        }
        assert!(w.contains(&table) && w.contains(&format!("# {long}\n")) && w.contains(&format!("```\n{long}\n```")));
        assert!(w.lines().any(|l| l.starts_with("  word")), "a list item's continuation is indented");
        assert_eq!(w.split_whitespace().count(), md.split_whitespace().count(), "no word lost");
        assert!(w.ends_with("short\n"));
    }
}
