//! Line charts as SVG with plotters' SVG backend, for the reproduction figures.
//!
//! No font feature: plotters' naive text layout estimates label sizes and the backend writes
//! `<text>` elements that the viewer renders, so the output depends only on the data (the same
//! bytes on every machine, offline). Coordinates are integer pixels.

use plotters::prelude::*;

/// One curve: a legend label and its points (non-finite points break the line).
pub struct Curve {
    /// Legend label.
    pub label: String,
    /// (x, y) points.
    pub points: Vec<(f64, f64)>,
    /// Drawn as asterisks at the points instead of a line (e.g. optimized points beside a
    /// fitted formula).
    pub markers: bool,
    /// Palette index of the colour; `None`: the curve's position in its panel.
    pub color: Option<usize>,
}

/// One panel of a figure (panels are stacked vertically and share the x axis).
pub struct Panel {
    /// Panel title (e.g. "(a)"), may be empty.
    pub title: String,
    /// y-axis description.
    pub y_label: String,
    /// The curves.
    pub curves: Vec<Curve>,
}

/// A chart: title, x axis and panels.
pub struct Chart {
    /// Title above the first panel.
    pub title: String,
    /// x-axis description.
    pub x_label: String,
    /// x range; `None`: the data's.
    pub x_range: Option<(f64, f64)>,
    /// Log-scaled x axis (positive data).
    pub x_log: bool,
    /// The panels.
    pub panels: Vec<Panel>,
    /// Corner of every panel's legend.
    pub legend: Legend,
}

/// Where a panel's legend goes (the corner the curves leave empty).
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Legend {
    /// Lower right (the default).
    LowerRight,
    /// Upper right.
    UpperRight,
    /// Upper left.
    UpperLeft,
}

const PALETTE: [RGBColor; 8] = [
    RGBColor(0, 0, 0),
    RGBColor(214, 39, 40),
    RGBColor(31, 119, 180),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(140, 86, 75),
    RGBColor(23, 190, 207),
];

/// The data range of `f` over the finite points of `curves`, widened by 5 % (or ±0.5 when flat).
fn range(curves: &[Curve], f: impl Fn(&(f64, f64)) -> f64, x: Option<(f64, f64)>) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for c in curves {
        for p in &c.points {
            let v = f(p);
            if !(v.is_finite() && p.0.is_finite() && p.1.is_finite()) {
                continue;
            }
            if let Some((a, b)) = x {
                if p.0 < a || p.0 > b {
                    continue;
                }
            }
            lo = lo.min(v);
            hi = hi.max(v);
        }
    }
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    if hi - lo < 1e-12 * hi.abs().max(1.0) {
        return (lo - 0.5, hi + 0.5);
    }
    let pad = 0.05 * (hi - lo);
    (lo - pad, hi + pad)
}

/// Runs of consecutive finite points.
fn segments(points: &[(f64, f64)]) -> Vec<Vec<(f64, f64)>> {
    let mut out = vec![];
    let mut cur = vec![];
    for &p in points {
        if p.0.is_finite() && p.1.is_finite() {
            cur.push(p);
        } else if !cur.is_empty() {
            out.push(std::mem::take(&mut cur));
        }
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out
}

/// Renders `chart` to an SVG document of `width` × (`panel_height` per panel) pixels.
pub fn render(chart: &Chart, width: u32, panel_height: u32) -> Result<String, String> {
    let mut buf = String::new();
    {
        let n = chart.panels.len().max(1);
        let root = SVGBackend::with_string(&mut buf, (width, panel_height * n as u32 + 30))
            .into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let root = root
            .titled(&chart.title, ("sans-serif", 16))
            .map_err(|e| e.to_string())?;
        let areas = root.split_evenly((n, 1));
        for (area, panel) in areas.iter().zip(&chart.panels) {
            draw_panel(area, chart, panel)?;
        }
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(buf)
}

fn draw_panel(
    area: &DrawingArea<SVGBackend, plotters::coord::Shift>,
    chart: &Chart,
    panel: &Panel,
) -> Result<(), String> {
    let (x0, x1) = chart
        .x_range
        .unwrap_or_else(|| range(&panel.curves, |p| p.0, None));
    let (y0, y1) = range(&panel.curves, |p| p.1, Some((x0, x1)));
    let mut b = ChartBuilder::on(area);
    b.margin(12).x_label_area_size(40).y_label_area_size(60);
    if !panel.title.is_empty() {
        b.caption(&panel.title, ("sans-serif", 14));
    }
    let e = |e: plotters::drawing::DrawingAreaErrorKind<std::io::Error>| e.to_string();
    macro_rules! mesh {
        ($c:expr) => {
            $c.configure_mesh()
                .x_desc(chart.x_label.as_str())
                .y_desc(panel.y_label.as_str())
                .light_line_style(RGBColor(235, 235, 235))
                .label_style(("sans-serif", 12))
                .draw()
                .map_err(e)?
        };
    }
    if chart.x_log {
        let mut c = b
            .build_cartesian_2d((x0.max(1e-300)..x1).log_scale(), y0..y1)
            .map_err(e)?;
        mesh!(c);
        draw_curves(&mut c, &panel.curves, None)?;
        legend(&mut c, chart.legend)
    } else {
        let mut c = b.build_cartesian_2d(x0..x1, y0..y1).map_err(e)?;
        mesh!(c);
        draw_curves(&mut c, &panel.curves, Some((x0, x1)))?;
        legend(&mut c, chart.legend)
    }
}

/// An asterisk (a cross over a plus, 4 px arms) centred at `$at`.
macro_rules! asterisk {
    ($at:expr, $style:expr) => {
        EmptyElement::at($at)
            + Cross::new((0, 0), 3, $style)
            + PathElement::new(vec![(0, -4), (0, 4)], $style)
            + PathElement::new(vec![(-4, 0), (4, 0)], $style)
    };
}

/// Draws `curves` as lines (points with x outside `x_clip` break them) or asterisks, each with
/// its legend entry.
fn draw_curves<'a, X: Ranged<ValueType = f64>, Y: Ranged<ValueType = f64>>(
    c: &mut ChartContext<'a, SVGBackend<'a>, Cartesian2d<X, Y>>,
    curves: &[Curve],
    x_clip: Option<(f64, f64)>,
) -> Result<(), String> {
    let e = |e: plotters::drawing::DrawingAreaErrorKind<std::io::Error>| e.to_string();
    for (i, curve) in curves.iter().enumerate() {
        let col = PALETTE[curve.color.unwrap_or(i) % PALETTE.len()];
        let pts: Vec<(f64, f64)> = curve
            .points
            .iter()
            .map(|&(x, y)| match x_clip {
                Some((x0, x1)) if x < x0 || x > x1 => (f64::NAN, y),
                _ => (x, y),
            })
            .collect();
        if curve.markers {
            let style = col.stroke_width(1);
            let s = c
                .draw_series(
                    pts.iter()
                        .filter(|p| p.0.is_finite() && p.1.is_finite())
                        .map(|&p| asterisk!(p, style)),
                )
                .map_err(e)?;
            s.label(curve.label.as_str())
                .legend(move |(x, y)| asterisk!((x + 10, y), style));
            continue;
        }
        for (j, seg) in segments(&pts).into_iter().enumerate() {
            let s = c
                .draw_series(LineSeries::new(seg, col.stroke_width(2)))
                .map_err(e)?;
            if j == 0 {
                s.label(curve.label.as_str()).legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], col.stroke_width(2))
                });
            }
        }
    }
    Ok(())
}

fn legend<'a, X: Ranged, Y: Ranged>(
    c: &mut ChartContext<'a, SVGBackend<'a>, Cartesian2d<X, Y>>,
    at: Legend,
) -> Result<(), String> {
    c.configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 12))
        .position(match at {
            Legend::LowerRight => SeriesLabelPosition::LowerRight,
            Legend::UpperRight => SeriesLabelPosition::UpperRight,
            Legend::UpperLeft => SeriesLabelPosition::UpperLeft,
        })
        .draw()
        .map_err(|e| e.to_string())
}
