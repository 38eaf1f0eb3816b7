//! `report.html` in a real browser (issue 16): the page of the fast scene set
//! (`tests/data/report_scenes`, fast grids, order 4, as `tests/all/report_snapshot.rs`) opened in
//! headless Chromium (Debian's `chromium`), which must draw every chart:
//! 1. `--dump-dom` of the page with a probe script appended: every `<svg>` has a non-zero box on
//!    the page (`getBoundingClientRect`) and non-zero drawn content (`getBBox`), and there are as
//!    many as the report wrote SVG files;
//! 2. `--screenshot` of the charts alone, laid out in a grid of fixed cells: in every cell at least
//!    1 % of the pixels are not white (a chart that did not render is its white background only;
//!    the sparsest chart of the set covers far more with its axes, ticks and labels).
//!
//! Ignored by `cargo test` (it needs Chromium): `scripts/test` runs it after the test suite, with
//! Chromium installed by `scripts/setup --browser`:
//! `cargo test --test all report_html_browser:: -- --ignored`.

use super::common;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Side of a grid cell of the screenshot, in CSS pixels (device scale factor 1).
const CELL: (u32, u32) = (320, 220);
const COLUMNS: u32 = 4;

fn chromium() -> PathBuf {
    for c in ["/usr/bin/chromium", "/usr/bin/chromium-browser", "/usr/bin/google-chrome"] {
        if Path::new(c).exists() {
            return c.into();
        }
    }
    panic!("no Chromium found: install it with `scripts/setup --browser` (Debian package chromium)");
}

/// Runs headless Chromium on `page` with `extra` flags; its stdout.
fn run_chromium(page: &Path, profile: &Path, extra: &[String]) -> String {
    let mut cmd = Command::new(chromium());
    cmd.args([
        "--headless",
        "--no-sandbox",
        "--disable-gpu",
        "--disable-quic",
        "--no-first-run",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--hide-scrollbars",
        "--force-device-scale-factor=1",
        "--allow-file-access-from-files",
    ]);
    cmd.arg(format!("--user-data-dir={}", profile.display()));
    cmd.args(extra);
    cmd.arg(format!("file://{}", page.display()));
    let out = cmd.output().expect("chromium starts");
    assert!(out.status.success(), "chromium failed: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The page with `script` run at the end of its body.
fn with_script(html: &str, script: &str) -> String {
    let i = html.rfind("</body>").expect("the page has a body");
    format!("{}<script>{script}</script>\n{}", &html[..i], &html[i..])
}

const PROBE: &str = "
const rows = [];
document.querySelectorAll('svg').forEach((s, i) => {
  const r = s.getBoundingClientRect();
  const b = s.getBBox();
  rows.push([i, r.width, r.height, b.width, b.height, s.querySelectorAll('*').length].join(' '));
});
const pre = document.createElement('pre');
pre.id = 'svg-boxes';
pre.textContent = 'BOXES\\n' + rows.join('\\n') + '\\nEND';
document.body.appendChild(pre);
";

/// Keeps only the charts, each scaled into a fixed cell of a grid (CELL, COLUMNS).
fn grid_script() -> String {
    format!(
        "
const svgs = Array.from(document.querySelectorAll('svg'));
document.head.querySelectorAll('style').forEach(s => s.remove());
document.body.innerHTML = '';
document.body.style.margin = '0';
document.body.style.background = '#ffffff';
svgs.forEach((s, i) => {{
  s.style.position = 'absolute';
  s.style.left = ((i % {c}) * {w}) + 'px';
  s.style.top = (Math.floor(i / {c}) * {h}) + 'px';
  s.setAttribute('width', '{w}');
  s.setAttribute('height', '{h}');
  s.setAttribute('preserveAspectRatio', 'none');
  s.style.border = 'none';
  document.body.appendChild(s);
}});
",
        c = COLUMNS,
        w = CELL.0,
        h = CELL.1
    )
}

#[test]
#[ignore = "needs Chromium: scripts/setup --browser, then cargo test --test all report_html_browser:: -- --ignored"]
fn every_chart_renders_in_headless_chromium() {
    let (out, files) = common::fast_report("html-test");
    let n_svg = files.files.iter().filter(|p| p.extension().is_some_and(|x| x == "svg")).count();
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert_eq!(html.matches("<svg").count(), n_svg, "every chart inline, once");

    // 1. Boxes.
    let probe = out.join("probe.html");
    std::fs::write(&probe, with_script(&html, PROBE)).unwrap();
    let dom =
        run_chromium(&probe, &out.join("profile-dom"), &["--dump-dom".into(), "--virtual-time-budget=5000".into()]);
    let boxes = dom.split("BOXES\n").nth(1).and_then(|s| s.split("\nEND").next()).unwrap_or_else(|| panic!("{dom}"));
    let rows: Vec<Vec<f64>> =
        boxes.lines().map(|l| l.split_whitespace().map(|x| x.parse().unwrap()).collect()).collect();
    assert_eq!(rows.len(), n_svg, "{boxes}");
    for r in &rows {
        assert!(r[1] > 0.0 && r[2] > 0.0, "svg {} has an empty box on the page: {r:?}", r[0]);
        assert!(r[3] > 0.0 && r[4] > 0.0 && r[5] > 2.0, "svg {} draws nothing: {r:?}", r[0]);
    }

    // 2. Pixels.
    let grid = out.join("grid.html");
    std::fs::write(&grid, with_script(&html, &grid_script())).unwrap();
    let rows_n = (n_svg as u32).div_ceil(COLUMNS);
    let (w, h) = (COLUMNS * CELL.0, rows_n * CELL.1);
    let png = out.join("charts.png");
    run_chromium(
        &grid,
        &out.join("profile-shot"),
        &[
            format!("--screenshot={}", png.display()),
            format!("--window-size={w},{h}"),
            "--virtual-time-budget=5000".into(),
        ],
    );
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(&png).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    let channels = info.color_type.samples();
    assert!(info.width >= w && info.height >= h, "screenshot {}x{} < {w}x{h}", info.width, info.height);
    let pixel = |x: u32, y: u32| -> &[u8] {
        let i = (y as usize * info.line_size) + x as usize * channels;
        &buf[i..i + 3]
    };
    let mut total = 0usize;
    for k in 0..n_svg as u32 {
        let (x0, y0) = ((k % COLUMNS) * CELL.0, (k / COLUMNS) * CELL.1);
        let mut ink = 0usize;
        for y in y0..y0 + CELL.1 {
            for x in x0..x0 + CELL.0 {
                if pixel(x, y).iter().any(|&c| c < 240) {
                    ink += 1;
                }
            }
        }
        let fraction = ink as f64 / (CELL.0 * CELL.1) as f64;
        assert!(fraction > 0.01, "chart {k} looks blank: {:.4} of its cell is not white", fraction);
        total += ink;
    }
    assert!(total > 0);
    let _ = std::fs::remove_dir_all(&out);
}
