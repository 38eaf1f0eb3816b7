//! Charts: data -> SVG (plotters) and the CSV behind it. Pure: no computation, no I/O.
//!
//! Every chart states its axes with units (or "dimensionless"), uses a log scale where the data
//! span decades (errors, times, loads over decades) and names every curve in its legend.

use plotters::prelude::*;

/// How a curve is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Draw {
    /// Line through markers (computed points).
    LineMarkers,
    /// Dashed line (closed forms, reference curves).
    Dashed,
    /// Markers only (maps).
    Markers,
}

/// One named curve.
#[derive(Debug, Clone)]
pub struct Curve {
    /// Legend text (names the method and its knob).
    pub name: String,
    /// (x, y) points; non-finite points are skipped when drawing (kept in the CSV).
    pub points: Vec<(f64, f64)>,
    /// Drawing style.
    pub draw: Draw,
    /// Fixed palette index (maps keep one colour per category across charts); `None`: by position.
    pub colour: Option<usize>,
}

/// A chart: title, axes, curves.
#[derive(Debug, Clone)]
pub struct Chart {
    /// File stem (`<stem>.svg`, `<stem>.csv`).
    pub stem: String,
    /// Caption.
    pub title: String,
    /// x-axis label with unit.
    pub x_label: String,
    /// y-axis label with unit.
    pub y_label: String,
    /// Log scale on x.
    pub x_log: bool,
    /// Log scale on y.
    pub y_log: bool,
    /// Curves.
    pub curves: Vec<Curve>,
    /// Where the legend goes.
    pub legend: Legend,
}

/// Legend position. `Above` adds head room above the data so the legend covers none of it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Legend {
    /// Upper left corner.
    UpperLeft,
    /// Upper right corner.
    UpperRight,
    /// Lower left corner.
    LowerLeft,
    /// Above the data, right.
    Above,
}

/// Colours of successive curves (distinguishable, print-safe).
const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

/// Colour of curve `i`.
pub fn colour(i: usize) -> RGBColor {
    PALETTE[i % PALETTE.len()]
}

impl Chart {
    /// The CSV behind the chart: `curve,x,y`, one row per point, full f64 precision (written by
    /// the `csv` crate: fields quoted when they hold a comma, a quote or a line break).
    pub fn csv(&self) -> String {
        let mut w = csv::Writer::from_writer(Vec::new());
        // Writing to a Vec cannot fail.
        w.write_record(["curve", &self.x_label, &self.y_label]).expect("in-memory CSV");
        for c in &self.curves {
            for (x, y) in &c.points {
                w.write_record([c.name.as_str(), &format!("{x:e}"), &format!("{y:e}")]).expect("in-memory CSV");
            }
        }
        String::from_utf8(w.into_inner().expect("in-memory CSV")).expect("UTF-8 fields")
    }

    /// Points as drawn: log axes are drawn as log10 of the data on a linear axis (ticks labelled
    /// 10^v), which gives evenly spaced decade labels over any span; non-finite points dropped.
    fn drawn(&self, c: &Curve) -> Vec<(f64, f64)> {
        c.points
            .iter()
            .filter(|(x, y)| x.is_finite() && y.is_finite() && (!self.x_log || *x > 0.0) && (!self.y_log || *y > 0.0))
            .map(|&(x, y)| (if self.x_log { x.log10() } else { x }, if self.y_log { y.log10() } else { y }))
            .collect()
    }

    fn finite_points(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.curves.iter().flat_map(|c| self.drawn(c))
    }

    /// Axis ranges with a margin (multiplicative on log axes).
    fn ranges(&self) -> ((f64, f64), (f64, f64)) {
        let (mut x0, mut x1, mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
        for (x, y) in self.finite_points() {
            x0 = x0.min(x);
            x1 = x1.max(x);
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
        let pad = |lo: f64, hi: f64, log: bool| -> (f64, f64) {
            if !lo.is_finite() {
                return (0.0, 1.0);
            }
            let m = if log {
                ((hi - lo) * 0.05).max(0.1)
            } else {
                ((hi - lo) * 0.05).max(hi.abs().max(lo.abs()) * 1e-3).max(1e-12)
            };
            (lo - m, hi + m)
        };
        let (xr, mut yr) = (pad(x0, x1, self.x_log), pad(y0, y1, self.y_log));
        if self.legend == Legend::Above {
            yr.1 += (yr.1 - yr.0) * 0.45;
        }
        (xr, yr)
    }

    /// Renders the chart as an SVG document (800 x 520 px).
    pub fn svg(&self) -> Result<String, String> {
        let mut buf = String::new();
        {
            let root = SVGBackend::with_string(&mut buf, (800, 520)).into_drawing_area();
            root.fill(&WHITE).map_err(|e| e.to_string())?;
            let ((x0, x1), (y0, y1)) = self.ranges();
            let (xl, yl) = (self.x_log, self.y_log);
            let fmt = |v: f64, log: bool| if log { log_axis_number(v) } else { axis_number(v) };
            let mut chart = ChartBuilder::on(&root)
                .caption(&self.title, ("sans-serif", 20))
                .margin(14)
                .x_label_area_size(48)
                .y_label_area_size(78)
                .build_cartesian_2d(x0..x1, y0..y1)
                .map_err(|e| e.to_string())?;
            chart
                .configure_mesh()
                .x_desc(self.x_label.as_str())
                .y_desc(self.y_label.as_str())
                .x_label_formatter(&|v| fmt(*v, xl))
                .y_label_formatter(&|v| fmt(*v, yl))
                .label_style(("sans-serif", 13))
                .axis_desc_style(("sans-serif", 15))
                .draw()
                .map_err(|e| e.to_string())?;
            for (i, c) in self.curves.iter().enumerate() {
                let col = colour(c.colour.unwrap_or(i));
                let pts = self.drawn(c);
                let anno = match c.draw {
                    Draw::LineMarkers => {
                        chart
                            .draw_series(pts.iter().map(|p| Circle::new(*p, 3, col.filled())))
                            .map_err(|e| e.to_string())?;
                        chart
                            .draw_series(LineSeries::new(pts.iter().copied(), col.stroke_width(2)))
                            .map_err(|e| e.to_string())?
                    }
                    Draw::Dashed => chart
                        .draw_series(DashedLineSeries::new(pts.iter().copied(), 8, 5, col.stroke_width(2)))
                        .map_err(|e| e.to_string())?,
                    Draw::Markers => chart
                        .draw_series(pts.iter().map(|p| Circle::new(*p, 5, col.filled())))
                        .map_err(|e| e.to_string())?,
                };
                let dashed = c.draw == Draw::Dashed;
                anno.label(c.name.clone()).legend(move |(x, y)| {
                    if dashed {
                        PathElement::new(vec![(x, y), (x + 7, y)], col.stroke_width(2))
                    } else {
                        PathElement::new(vec![(x, y), (x + 20, y)], col.stroke_width(3))
                    }
                });
            }
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK)
                .label_font(("sans-serif", 13))
                .position(match self.legend {
                    Legend::UpperLeft => SeriesLabelPosition::UpperLeft,
                    Legend::LowerLeft => SeriesLabelPosition::LowerLeft,
                    Legend::UpperRight | Legend::Above => SeriesLabelPosition::UpperRight,
                })
                .draw()
                .map_err(|e| e.to_string())?;
            root.present().map_err(|e| e.to_string())?;
        }
        Ok(buf)
    }
}

/// Tick label: plain for moderate magnitudes, `1e-12` style otherwise.
pub fn axis_number(v: f64) -> String {
    let a = v.abs();
    if v == 0.0 {
        "0".into()
    } else if (1e-3..1e4).contains(&a) {
        let s = format!("{v:.4}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        s.to_string()
    } else {
        let s = format!("{v:.1e}");
        s.replace(".0e", "e")
    }
}

/// Tick label of a log axis at exponent `v`: 10^v to two significant digits ("0.25", "6.3e-4",
/// "1e-20").
pub fn log_axis_number(v: f64) -> String {
    let x = 10f64.powf(v);
    let r = if (v - v.round()).abs() < 1e-9 { 10f64.powf(v.round()) } else { x };
    if (1e-3..1e4).contains(&r) {
        let s = format!("{}", format!("{r:.1e}").parse::<f64>().unwrap_or(r));
        s
    } else {
        format!("{r:.1e}").replace(".0e", "e")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_reads_back_names_with_commas_and_quotes() {
        let c = Chart {
            stem: "t".into(),
            title: "t".into(),
            x_label: "x, [s]".into(),
            y_label: "y \"rel\"".into(),
            x_log: false,
            y_log: false,
            curves: vec![Curve {
                name: "|q1|/q2, paper".into(),
                points: vec![(1.0, 2.5e-3)],
                draw: Draw::LineMarkers,
                colour: None,
            }],
            legend: Legend::UpperRight,
        };
        let text = c.csv();
        let mut r = csv::Reader::from_reader(text.as_bytes());
        assert_eq!(r.headers().unwrap().iter().collect::<Vec<_>>(), ["curve", "x, [s]", "y \"rel\""]);
        let rows: Vec<csv::StringRecord> = r.records().map(|x| x.unwrap()).collect();
        assert_eq!(rows.len(), 1);
        assert_eq!((&rows[0][0], &rows[0][1], &rows[0][2]), ("|q1|/q2, paper", "1e0", "2.5e-3"));
    }

    #[test]
    fn svg_names_axes_and_curves_and_csv_holds_every_point() {
        let c = Chart {
            stem: "t".into(),
            title: "test".into(),
            x_label: "wall time [s]".into(),
            y_label: "relative error [-]".into(),
            x_log: true,
            y_log: true,
            curves: vec![
                Curve {
                    name: "f64, nodes".into(),
                    points: vec![(1e-3, 1e-5), (1e-2, 1e-12)],
                    draw: Draw::LineMarkers,
                    colour: None,
                },
                Curve {
                    name: "closed form".into(),
                    points: vec![(1e-3, 1e-6), (f64::NAN, 1.0)],
                    draw: Draw::Dashed,
                    colour: None,
                },
            ],
            legend: Legend::UpperRight,
        };
        let svg = c.svg().unwrap();
        assert!(svg.contains("wall time [s]") && svg.contains("f64, nodes") && svg.contains("closed form"));
        assert_eq!(c.csv().lines().count(), 5);
        assert!(c.csv().starts_with("curve,wall time [s],relative error [-]\n"));
    }
}
