//! `report.html`: the whole report as one self-contained page (issue 16). Pure: the Markdown of
//! `report.md`, the SVG text of every chart and the LaTeX of `coefficients.tex` -> one HTML text.
//!
//! - Markdown -> HTML by `pulldown-cmark` (CommonMark with GitHub tables), so the page says what
//!   `report.md` says, from the same data, in the same order.
//! - Every image `![caption](stem.svg)` becomes the chart's `<svg>` element itself, inline in a
//!   `<figure>` with the caption (an image whose SVG is not among the charts is an error: a page
//!   with a broken picture is never written).
//! - The formulas of the report are plain text (`l/l_s`, `Lambda^2`), shown as code; the LaTeX
//!   tables of `coefficients.tex` follow in a closed `<details>` block as their source text.
//! - No script, no font, no style sheet from elsewhere: one inline `<style>`; the only `http`
//!   text is the SVG namespace name `http://www.w3.org/2000/svg`, which nothing fetches.
//!
//! Deterministic: the same inputs give the same bytes (no date, no timing).

use pulldown_cmark::{html, CowStr, Event, Options, Parser, Tag, TagEnd};
use std::collections::BTreeMap;

/// The page's style sheet (inline; system fonts only).
const STYLE: &str = "body{font-family:system-ui,sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;\
line-height:1.45;color:#111}\
table{border-collapse:collapse;margin:1em 0;font-size:0.9em}\
th,td{border:1px solid #bbb;padding:0.25em 0.5em;vertical-align:top}\
th{background:#f2f2f2}\
code{font-family:ui-monospace,monospace;font-size:0.92em;background:#f6f6f6;padding:0 0.15em}\
pre{background:#f6f6f6;padding:0.8em;overflow-x:auto;font-size:0.85em}\
figure{margin:1em 0}\
figure svg{max-width:100%;height:auto;border:1px solid #ddd}\
td figure svg{max-width:480px}\
figcaption{font-size:0.9em;color:#444}";

/// Why a page could not be made.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum HtmlError {
    /// `report.md` shows an SVG that is not among the charts.
    #[error("report.md shows {file}, which is not among the charts of this run")]
    MissingChart {
        /// The file name the Markdown names.
        file: String,
    },
}

/// The SVG element of a chart file's text, without an XML declaration or doctype (inline SVG in
/// HTML takes the element only).
fn svg_element(text: &str) -> &str {
    match text.find("<svg") {
        Some(i) => text[i..].trim_end(),
        None => text.trim(),
    }
}

/// Escapes text for HTML element content and attribute values.
fn escape(text: &str) -> String {
    let mut s = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => s.push_str("&amp;"),
            '<' => s.push_str("&lt;"),
            '>' => s.push_str("&gt;"),
            '"' => s.push_str("&quot;"),
            other => s.push(other),
        }
    }
    s
}

/// The anchor of a heading, as Markdown viewers (GitHub) make it: lower case, letters, digits,
/// `-` and `_` kept, spaces to `-`, the rest dropped. `report.html` gives its `<h2>` the same ids,
/// so the report's contents list links in both.
pub fn slug(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
            _ => None,
        })
        .collect()
}

/// The page: `title`, the report's `markdown` with every `![..](name.svg)` replaced by the SVG
/// text `charts[name.svg]`, then `latex` (the coefficient tables' LaTeX source) in a closed
/// `<details>` block when not empty.
pub fn page(title: &str, markdown: &str, charts: &BTreeMap<String, String>, latex: &str) -> Result<String, HtmlError> {
    let parser = Parser::new_ext(markdown, Options::ENABLE_TABLES);
    let mut events: Vec<Event> = Vec::new();
    // Inside an SVG image: (file, caption text so far).
    let mut image: Option<(String, String)> = None;
    // An open level-2 heading: the index of its start event and its text so far (for its id).
    let mut heading: Option<(usize, String)> = None;
    for event in parser {
        match (&mut heading, &event) {
            (None, Event::Start(Tag::Heading { level: pulldown_cmark::HeadingLevel::H2, .. })) => {
                heading = Some((events.len(), String::new()));
            }
            (Some((_, text)), Event::Text(t) | Event::Code(t)) => text.push_str(t),
            (Some((at, text)), Event::End(TagEnd::Heading(_))) => {
                let id = slug(text);
                if let Event::Start(Tag::Heading { id: slot, .. }) = &mut events[*at] {
                    *slot = Some(CowStr::from(id));
                }
                heading = None;
            }
            _ => {}
        }
        match (&mut image, event) {
            (None, Event::Start(Tag::Image { dest_url, .. })) if dest_url.ends_with(".svg") => {
                image = Some((dest_url.to_string(), String::new()));
            }
            (Some((_, caption)), Event::Text(t) | Event::Code(t)) => caption.push_str(&t),
            (Some(_), Event::End(TagEnd::Image)) => {
                let (file, caption) = image.take().expect("inside an image");
                let svg = charts.get(&file).ok_or(HtmlError::MissingChart { file: file.clone() })?;
                events.push(Event::InlineHtml(CowStr::from(format!(
                    "<figure id=\"{id}\">{svg}<figcaption>{caption}</figcaption></figure>",
                    id = escape(file.trim_end_matches(".svg")),
                    svg = svg_element(svg),
                    caption = escape(&caption),
                ))));
            }
            (Some(_), _) => {}
            (None, e) => events.push(e),
        }
    }
    let mut body = String::new();
    html::push_html(&mut body, events.into_iter());
    let mut s = format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>{}</title>\n\
         <style>{STYLE}</style>\n</head>\n<body>\n",
        escape(title)
    );
    s.push_str(&body);
    if !latex.trim().is_empty() {
        s.push_str(
            "<details>\n<summary>LaTeX source of the coefficient tables (<code>coefficients.tex</code>)</summary>\n<pre>",
        );
        s.push_str(&escape(latex));
        s.push_str("</pre>\n</details>\n");
    }
    s.push_str("</body>\n</html>\n");
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn charts() -> BTreeMap<String, String> {
        let mut m = BTreeMap::new();
        m.insert(
            "a.svg".to_string(),
            "<?xml version=\"1.0\"?>\n<svg width=\"10\" height=\"10\" xmlns=\"http://www.w3.org/2000/svg\"><rect width=\"5\" height=\"5\"/></svg>\n"
                .to_string(),
        );
        m
    }

    #[test]
    fn images_become_inline_svg_with_caption() {
        let md = "# T\n\n![load & size](a.svg) (data: `a.csv`)\n\n| x | y |\n|---|---|\n| 1 | ![c](a.svg) |\n";
        let p = page("report", md, &charts(), "\\frac{1}{2} < 1").unwrap();
        assert_eq!(p.matches("<svg").count(), 2, "{p}");
        assert!(!p.contains("<img"), "{p}");
        assert!(!p.contains("<?xml"), "{p}");
        assert!(p.contains("<figcaption>load &amp; size</figcaption>"), "{p}");
        assert!(p.contains("<table>") && p.contains("<td>1</td>"), "{p}");
        assert!(p.contains("<pre>\\frac{1}{2} &lt; 1</pre>"), "{p}");
        assert!(p.contains("<code>a.csv</code>"), "{p}");
        assert_eq!(p, page("report", md, &charts(), "\\frac{1}{2} < 1").unwrap(), "deterministic");
    }

    #[test]
    fn level_two_headings_get_the_markdown_anchor() {
        assert_eq!(
            slug("3. Convergence orders: series against the solution"),
            "3-convergence-orders-series-against-the-solution"
        );
        assert_eq!(slug("9. Loading law (Problem 2, P1 = N(P2))"), "9-loading-law-problem-2-p1--np2");
        let p = page("r", "## 2. Method `choice`\n\n[go](#2-method-choice)\n", &charts(), "").unwrap();
        assert!(p.contains("<h2 id=\"2-method-choice\">2. Method <code>choice</code></h2>"), "{p}");
        assert!(p.contains("<a href=\"#2-method-choice\">go</a>"), "{p}");
    }

    #[test]
    fn a_missing_chart_is_an_error() {
        let e = page("r", "![x](b.svg)", &charts(), "").unwrap_err();
        assert_eq!(e, HtmlError::MissingChart { file: "b.svg".into() });
        assert_eq!(e.to_string(), "report.md shows b.svg, which is not among the charts of this run");
    }

    #[test]
    fn other_images_stay_images() {
        let p = page("r", "![x](b.png)", &charts(), "").unwrap();
        assert!(p.contains("<img src=\"b.png\" alt=\"x\""), "{p}");
    }
}
