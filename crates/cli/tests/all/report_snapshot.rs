//! The report text for a fixed, fast scene set (`tests/data/report_scenes`, fast profile,
//! coefficient tables through order 4): snapshot-tested. Timings stay out of it (they go to
//! `timings.md`, checked here to state the machine). The loading-law section's numbers are
//! checked against `periodic-contact solve --json` on the same scene.

use super::common;
// The report of the fixed fast scene set, shared with the report crate's own tests.
#[path = "../../../report/tests/all/common/mod.rs"]
mod report_common;
use periodic_contact_report::{loading_law, section::Profile};
use rug::Float;

#[test]
fn report_text_fast_scene_set() {
    let (out, files) = report_common::fast_report("report-test");
    let md = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert_eq!(md, files.markdown);
    // Every chart has its SVG and CSV; the SVG names its axes and curves.
    let svgs: Vec<_> = files.files.iter().filter(|p| p.extension().is_some_and(|x| x == "svg")).collect();
    assert!(svgs.len() >= 8, "{svgs:?}");
    for svg in &svgs {
        assert!(svg.with_extension("csv").exists(), "{}", svg.display());
        let text = std::fs::read_to_string(svg).unwrap();
        assert!(
            text.contains("[-]") || text.contains("[s]") || text.contains("units"),
            "{}: axis units",
            svg.display()
        );
    }
    check_loading_law_against_solve(&md, &out);
    check_front_page(&md);
    check_html_page(&out, &svgs);
    let timings = std::fs::read_to_string(out.join("timings.md")).unwrap();
    assert!(timings.contains("Machine:") && timings.contains("logical CPUs"));
    assert!(!md.contains("seconds") && !md.contains("wall time:"), "timings leaked into report.md");
    let _ = std::fs::remove_dir_all(&out);
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path("../../../../snapshots");
    settings.set_prepend_module_to_snapshot(false);
    settings.bind(|| insta::assert_snapshot!("report_fast_scene_set", md));
}

/// Issue 30: the report opens with its summary, then the contents, then sections numbered in
/// order from 1 to 12 (each section keeps its number; 8, punch shapes, is absent without a
/// polynomial or circular scene, as here; 12, finite friction, follows 11's pointer to the
/// timings); no line is longer than 400 characters.
fn check_front_page(md: &str) {
    assert!(md.starts_with("# periodic-contact report\n\n## Summary\n"), "{}", &md[..200.min(md.len())]);
    let headings: Vec<&str> = md.lines().filter_map(|l| l.strip_prefix("## ")).collect();
    assert_eq!(&headings[..2], ["Summary", "Contents"]);
    let numbers: Vec<usize> =
        headings[2..].iter().map(|h| h.split('.').next().and_then(|n| n.parse().ok()).unwrap_or(0)).collect();
    assert_eq!(numbers, [1, 2, 3, 4, 5, 6, 7, 9, 10, 11, 12], "{headings:?}");
    assert!(headings.iter().any(|h| h.starts_with("11. Timings")), "{headings:?}");
    assert!(headings.last().is_some_and(|h| h.starts_with("12. Finite friction")), "{headings:?}");
    let longest = md.lines().map(str::len).max().unwrap_or(0);
    assert!(longest <= 400, "a line of {longest} characters");
    for h in &headings[2..] {
        assert!(md.contains(&format!("- [{h}](#")), "{h} is not in the contents");
    }
}

/// `report.html` (issue 16): one self-contained page; every chart's SVG inline exactly as in its
/// file, no `<img>`, and nothing fetched from elsewhere (no `src`/`href` to a URL, no script, no
/// style sheet link; `http` occurs only as the SVG namespace name). The browser check is
/// `tests/all/report_html_browser.rs`.
fn check_html_page(out: &std::path::Path, svgs: &[&std::path::PathBuf]) {
    let html = std::fs::read_to_string(out.join("report.html")).expect("report.html is written");
    assert!(html.starts_with("<!DOCTYPE html>"), "{}", &html[..100.min(html.len())]);
    assert_eq!(html.matches("<svg").count(), svgs.len(), "one inline svg per chart file");
    for svg in svgs {
        let text = std::fs::read_to_string(svg).unwrap();
        let element = &text[text.find("<svg").unwrap()..];
        assert!(html.contains(element.trim_end()), "{} is not inline", svg.display());
    }
    assert!(!html.contains("<img") && !html.contains("<script") && !html.contains("<link"), "external resources");
    // In-page links of the contents list (`href="#..."`) are the only links.
    let without_namespace = html.replace("xmlns=\"http://www.w3.org/2000/svg\"", "").replace("href=\"#", "in-page=\"#");
    for url in ["http://", "https://", "//cdn", "src=", "href=", "@import", "url("] {
        assert!(!without_namespace.contains(url), "report.html contains {url:?}");
    }
    // The tables and the report's sections are there.
    assert!(html.contains("<table>") && html.contains("<h2 id=\"11-timings\">11. Timings</h2>"), "tables and sections");
    // Issue 30: the summary first, and a contents list whose links reach the sections' ids.
    let (summary, contents) = (html.find("<h2 id=\"summary\">").unwrap(), html.find("<h2 id=\"contents\">").unwrap());
    assert!(summary < contents && contents < html.find("<h2 id=\"1-exact-coefficient").unwrap());
    assert!(html.contains("<a href=\"#3-convergence-orders-series-against-the-high-precision-solution\">"));
}

fn float(s: &str) -> Float {
    Float::with_val(256, Float::parse(s.trim()).unwrap_or_else(|e| panic!("{s:?}: {e}")))
}

/// The cells of the Markdown table row of `md` that starts with `prefix`.
fn row<'a>(md: &'a str, prefix: &str) -> Vec<&'a str> {
    let line = md.lines().find(|l| l.starts_with(prefix)).unwrap_or_else(|| panic!("no row {prefix}:\n{md}"));
    line.split('|').map(str::trim).filter(|c| !c.is_empty()).collect()
}

/// |x - y| <= 10^-(d - 1) |scale|: agreement to d digits, each side rounded once.
fn agree(x: &Float, y: &Float, scale: &Float, d: f64) -> bool {
    Float::with_val(256, x - y).abs().to_f64() <= 10f64.powf(-(d - 1.0)) * scale.to_f64().abs()
}

/// The section "Loading law" on `tests/data/report_scenes/loading_law.toml` against
/// `solve --json --digits 6` on the same scene with the point where the report found the friction
/// needed: the same two runs, so l, a, b, P1, P2 and the loading path print identically (same digits);
/// c/l = c/l of the JSON; the friction needed is the JSON's |q1|/q2 at that point, and it is the
/// largest |q1|/q2 of the chart's CSV; the stresses' CSV holds the JSON's q1, q2 there.
fn check_loading_law_against_solve(md: &str, out: &std::path::Path) {
    assert!(md.contains("## 9. Loading law (Problem 2, P1 = N(P2))"), "{md}");
    let digits = loading_law::FAST_DIGITS.to_string();
    let r = row(md, "| `loading_law` | paper |");
    // scene, convention, law, given, l, a, b, c/l, P1, P2, friction, at, tension, verified, requested.
    assert_eq!(r.len(), 15, "{r:?}");
    assert_eq!((r[2], r[3], r[12], r[14]), ("P1 = 1/5 P2", "l = 1/10", "none", digits.as_str()), "{r:?}");
    let at = r[11];
    let scene = std::fs::read_to_string(concat!(
        concat!(env!("CARGO_MANIFEST_DIR"), "/../.."),
        "/tests/data/report_scenes/loading_law.toml"
    ))
    .unwrap()
    .replace("points = [\"0.5\"]", &format!("points = [\"{at}\"]"));
    assert!(scene.contains(&format!("points = [\"{at}\"]")), "{scene}");
    let path = common::scene_file("report_loading_law.toml", &scene);
    let v = common::json(&["solve", &path, "--json", "--digits", &digits]);
    // `solve` prints one digit more than requested (issue 34: a text of exactly the requested digits
    // holds fewer); the report's cells are the same values at the requested digits.
    let s = |key: &str| v[key].as_str().unwrap_or_else(|| panic!("{key}: {v}")).to_string();
    for (cell, key) in [(r[4], "l"), (r[5], "a"), (r[6], "b"), (r[8], "P1"), (r[9], "P2")] {
        assert!(same_value(cell, &s(key)), "{key}: {cell} vs {}", s(key));
    }
    let verified: Vec<f64> = r[13].split('/').map(|x| x.trim().parse().unwrap()).collect();
    let (ends, path_digits, stresses) = (verified[0], verified[2], verified[3]);
    // `solve` claims what its printed texts hold (issue 34): at most the report's verified digits.
    let claim = |key: &str| v["accuracy"][key].as_str().unwrap().parse::<f64>().unwrap();
    assert!(claim("ends") <= ends + 0.05 && claim("path") <= path_digits + 0.05, "{v}");
    let ends = claim("ends");
    let (c, l) = (float(&s("c")), float(&s("l")));
    let one = Float::with_val(256, 1);
    assert!(agree(&float(r[7]), &Float::with_val(256, &c / &l), &one, ends), "c/l {} vs {c}/{l}", r[7]);
    // The friction needed at its point.
    let fields: f64 = v["accuracy"]["fields"].as_str().unwrap().parse().unwrap();
    let friction = float(r[10]);
    assert!(agree(&friction, &float(&s("friction_needed")), &friction, stresses.min(fields) - 1.0), "{v}");
    assert_eq!(v["friction_needed_at_xh"].as_str().unwrap(), at);
    // The path at j = 4, 8, 12, 16.
    let json_path = v["path"].as_array().unwrap();
    assert_eq!(json_path.len(), 16);
    for j in [4usize, 8, 12, 16] {
        let p = row(md, &format!("| `loading_law` | paper | {j} |"));
        let q = &json_path[j - 1];
        let raw = |k: &str| q[k].as_str().unwrap().to_string();
        // The report's cells at the requested digits, `solve`'s texts one digit longer (issue 34).
        for (cell, key) in [(p[3], "l"), (p[4], "a"), (p[5], "b"), (p[7], "P1"), (p[8], "P2")] {
            assert!(same_value(cell, &raw(key)), "path {j} {key}: {cell} vs {}", raw(key));
        }
        let c_over_l = Float::with_val(256, float(&raw("c")) / float(&raw("l")));
        assert!(
            agree(&float(p[6]), &c_over_l, &one, path_digits.min(claim("path"))),
            "path {j}: {} vs {c_over_l}",
            p[6]
        );
    }
    // The charts' data: the largest |q1|/q2 is the friction needed; q1, q2 at its point over E* k l
    // (E* = k = 1) are the JSON's.
    let csv = |stem: &str| std::fs::read_to_string(out.join(format!("{stem}.csv"))).unwrap();
    let values = |text: &str, curve: &str| -> Vec<(f64, f64)> {
        csv::Reader::from_reader(text.as_bytes())
            .records()
            .map(|r| r.unwrap())
            .filter(|r| &r[0] == curve)
            .map(|r| (r[1].parse().unwrap(), r[2].parse().unwrap()))
            .collect()
    };
    let ratio = values(&csv("loading_law_0_friction"), "|q1|/q2, paper");
    assert_eq!(ratio.len(), loading_law::profile_points(Profile::Fast).len());
    let max = ratio.iter().map(|p| p.1).filter(|y| y.is_finite()).fold(0.0, f64::max);
    let requested = loading_law::FAST_DIGITS as f64;
    assert!(agree(&Float::with_val(256, max), &friction, &friction, requested), "{max} vs {friction}");
    // xh as exact text ("9/10", "0", "-1/2").
    let x_at = match at.split_once('/') {
        Some((n, d)) => n.parse::<f64>().unwrap() / d.parse::<f64>().unwrap(),
        None => at.parse().unwrap(),
    };
    let stresses_csv = csv("loading_law_0_stresses");
    let pt = &v["points"][0];
    for (curve, key) in [("q1/(E* k l), paper", "q1"), ("q2/(E* k l), paper", "q2")] {
        let (_, y) = *values(&stresses_csv, curve).iter().find(|p| (p.0 - x_at).abs() < 1e-12).unwrap();
        let q = float(pt[key].as_str().unwrap()).to_f64() / l.to_f64();
        assert!((y - q).abs() <= 10f64.powf(-(fields.min(stresses).min(requested) - 1.0)), "{key}: {y} vs {q}");
    }
}

/// A report cell and `solve`'s text of the same value: `solve` prints one digit more (issue 34), so
/// they agree to half a unit of the cell's last digit and of the text's.
fn same_value(cell: &str, text: &str) -> bool {
    let (a, b) = (float(cell), float(text));
    let mantissa = cell.split('e').next().unwrap();
    let sig = mantissa.chars().filter(char::is_ascii_digit).count() as i32;
    let unit = Float::with_val(256, Float::with_val(256, a.abs_ref()).log10().floor());
    let ulp = Float::with_val(256, Float::with_val(256, &unit - (sig - 1)).exp10());
    Float::with_val(256, &a - &b).abs() <= ulp * 0.55
}
