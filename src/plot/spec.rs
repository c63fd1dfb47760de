//! The plot specification: its types and their validation from JSON (the form is in the module
//! documentation of [`crate::plot`]).

use super::color::{parse_color, Rgba, OKABE_ITO};
use super::parse::{err, get_bool, get_color, get_num, get_range, get_samples, get_str, req_num};
use crate::error::Result;
use serde_json::Value;

/// Maximum number of series in one plot.
const MAX_SERIES: usize = 64;

/// Which axes to draw.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A response against time.
    Time,
    /// The Nyquist plane Re L / Im L, drawn with equal aspect.
    Nyquist,
}

/// How a series line is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dash {
    /// Solid line.
    Solid,
    /// Dashed line.
    Dash,
    /// Dotted line.
    Dot,
}

/// One line of a plot.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend text (no legend entry when empty).
    pub label: String,
    /// Abscissae; `None` marks a gap.
    pub x: Vec<Option<f64>>,
    /// Ordinates; `None` marks a gap.
    pub y: Vec<Option<f64>>,
    /// Line colour.
    pub color: Rgba,
    /// Line pattern.
    pub dash: Dash,
    /// Drawn faint (nominal response under a perturbation, pinned designs).
    pub faint: bool,
    /// Line width in CSS pixels.
    pub width: f64,
}

/// A circle (the Ms circle of the Nyquist plot: centre −1, radius 1/Ms).
#[derive(Debug, Clone, PartialEq)]
pub struct Circle {
    /// Centre, real part.
    pub cx: f64,
    /// Centre, imaginary part.
    pub cy: f64,
    /// Radius (> 0).
    pub r: f64,
    /// Legend text.
    pub label: String,
    /// Colour.
    pub color: Rgba,
}

/// A marked point (e.g. the critical point −1).
#[derive(Debug, Clone, PartialEq)]
pub struct Point {
    /// Abscissa.
    pub x: f64,
    /// Ordinate.
    pub y: f64,
    /// Text beside the marker.
    pub label: String,
    /// Colour.
    pub color: Rgba,
}

/// A vertical marker line (event times, the time divergence was detected).
#[derive(Debug, Clone, PartialEq)]
pub struct VLine {
    /// Abscissa.
    pub x: f64,
    /// Text at the top of the line.
    pub label: String,
    /// Colour.
    pub color: Rgba,
}

/// A validated plot specification (see the module documentation for the JSON form).
#[derive(Debug, Clone, PartialEq)]
pub struct Spec {
    /// Id of the canvas element.
    pub canvas: String,
    /// Axes kind.
    pub kind: Kind,
    /// Title drawn above the plot.
    pub title: String,
    /// x-axis caption.
    pub xlabel: String,
    /// y-axis caption.
    pub ylabel: String,
    /// Device pixel ratio (scales fonts and widths).
    pub dpr: f64,
    /// Fixed x range.
    pub xrange: Option<(f64, f64)>,
    /// Fixed y range.
    pub yrange: Option<(f64, f64)>,
    /// Draw a legend.
    pub legend: bool,
    /// The lines.
    pub series: Vec<Series>,
    /// Optional circle.
    pub circle: Option<Circle>,
    /// Marked points.
    pub points: Vec<Point>,
    /// Vertical markers.
    pub vlines: Vec<VLine>,
}

impl Spec {
    /// Validates a JSON plot specification.
    pub fn from_json(v: &Value) -> Result<Spec> {
        let o = v
            .as_object()
            .ok_or_else(|| err("spec", "must be an object"))?;
        let canvas = get_str(o, "canvas", "spec")?;
        if canvas.is_empty() {
            return Err(err(
                "spec.canvas",
                "is required (the id of a <canvas> element)",
            ));
        }
        let kind = parse_kind(o)?;
        let dpr = parse_dpr(o)?;
        let series = parse_series_list(o)?;
        let circle = parse_circle(o)?;
        let points = parse_points(o)?;
        let vlines = parse_vlines(o)?;
        Ok(Spec {
            canvas,
            kind,
            title: get_str(o, "title", "spec")?,
            xlabel: get_str(o, "xlabel", "spec")?,
            ylabel: get_str(o, "ylabel", "spec")?,
            dpr,
            xrange: get_range(o, "xrange")?,
            yrange: get_range(o, "yrange")?,
            legend: get_bool(o, "legend", "spec", true)?,
            series,
            circle,
            points,
            vlines,
        })
    }
}

/// A JSON object.
type Obj = serde_json::Map<String, Value>;

/// `spec.kind`: "time" (the default) or "nyquist".
fn parse_kind(o: &Obj) -> Result<Kind> {
    match o.get("kind") {
        None | Some(Value::Null) => Ok(Kind::Time),
        Some(Value::String(s)) if s == "time" => Ok(Kind::Time),
        Some(Value::String(s)) if s == "nyquist" => Ok(Kind::Nyquist),
        Some(_) => Err(err("spec.kind", "must be \"time\" or \"nyquist\"")),
    }
}

/// `spec.dpr`: the device pixel ratio, 1 by default, within 0.5–4.
fn parse_dpr(o: &Obj) -> Result<f64> {
    let dpr = get_num(o, "dpr", "spec")?.unwrap_or(1.0);
    if !(0.5..=4.0).contains(&dpr) {
        return Err(err(
            "spec.dpr",
            format!("must be between 0.5 and 4 (got {dpr})"),
        ));
    }
    Ok(dpr)
}

/// `spec.series`: at most [`MAX_SERIES`] series (none when absent).
fn parse_series_list(o: &Obj) -> Result<Vec<Series>> {
    // Borrowed, not cloned: the series hold most of the spec's data.
    let series_v: &[Value] = match o.get("series") {
        None | Some(Value::Null) => &[],
        Some(Value::Array(a)) => a,
        Some(_) => return Err(err("spec.series", "must be an array")),
    };
    if series_v.len() > MAX_SERIES {
        return Err(err("spec.series", format!("at most {MAX_SERIES} series")));
    }
    let mut series = Vec::with_capacity(series_v.len());
    for (i, sv) in series_v.iter().enumerate() {
        series.push(parse_series(i, sv)?);
    }
    Ok(series)
}

/// `spec.series[i]`; its default colour is the `i`-th of the Okabe–Ito palette.
fn parse_series(i: usize, sv: &Value) -> Result<Series> {
    let path = format!("spec.series[{i}]");
    let so = sv
        .as_object()
        .ok_or_else(|| err(&path, "must be an object"))?;
    let x = get_samples(so, "x", &path)?;
    let y = get_samples(so, "y", &path)?;
    if x.len() != y.len() {
        return Err(err(
            &format!("{path}.y"),
            format!(
                "must have as many samples as x ({} vs {})",
                y.len(),
                x.len()
            ),
        ));
    }
    let def = parse_color(
        OKABE_ITO
            .get(i % OKABE_ITO.len())
            .copied()
            .unwrap_or("#000000"),
        &path,
    )?;
    let color = get_color(so, "color", &path, def)?;
    let dash = parse_dash(so, &path)?;
    let faint = get_bool(so, "faint", &path, false)?;
    let width = get_num(so, "width", &path)?.unwrap_or(if faint { 1.5 } else { 2.0 });
    if !(0.25..=10.0).contains(&width) {
        return Err(err(&format!("{path}.width"), "must be between 0.25 and 10"));
    }
    Ok(Series {
        label: get_str(so, "label", &path)?,
        x,
        y,
        color,
        dash,
        faint,
        width,
    })
}

/// `<path>.dash`: false/true, or "solid", "dash", "dot".
fn parse_dash(so: &Obj, path: &str) -> Result<Dash> {
    match so.get("dash") {
        None | Some(Value::Null) | Some(Value::Bool(false)) => Ok(Dash::Solid),
        Some(Value::Bool(true)) => Ok(Dash::Dash),
        Some(Value::String(s)) if s == "solid" => Ok(Dash::Solid),
        Some(Value::String(s)) if s == "dash" => Ok(Dash::Dash),
        Some(Value::String(s)) if s == "dot" => Ok(Dash::Dot),
        Some(_) => Err(err(
            &format!("{path}.dash"),
            "must be true/false or \"solid\", \"dash\", \"dot\"",
        )),
    }
}

/// `spec.circle`: {cx, cy, r > 0, label, color}, vermilion by default.
fn parse_circle(o: &Obj) -> Result<Option<Circle>> {
    match o.get("circle") {
        None | Some(Value::Null) => Ok(None),
        Some(Value::Object(co)) => {
            let p = "spec.circle";
            let r = req_num(co, "r", p)?;
            if r <= 0.0 {
                return Err(err("spec.circle.r", "must be > 0"));
            }
            Ok(Some(Circle {
                cx: req_num(co, "cx", p)?,
                cy: req_num(co, "cy", p)?,
                r,
                label: get_str(co, "label", p)?,
                color: get_color(
                    co,
                    "color",
                    p,
                    Rgba {
                        rgb: (0xD5, 0x5E, 0x00),
                        alpha: 1.0,
                    },
                )?,
            }))
        }
        Some(_) => Err(err("spec.circle", "must be an object {cx, cy, r}")),
    }
}

/// `spec.<key>`: an array of at most 64 entries (none when absent).
fn list<'a>(o: &'a Obj, key: &str) -> Result<&'a [Value]> {
    match o.get(key) {
        None | Some(Value::Null) => Ok(&[]),
        Some(Value::Array(a)) if a.len() <= 64 => Ok(a),
        Some(Value::Array(_)) => Err(err(&format!("spec.{key}"), "at most 64 entries")),
        Some(_) => Err(err(&format!("spec.{key}"), "must be an array")),
    }
}

/// `spec.points`: {x, y, label, color}, black by default.
fn parse_points(o: &Obj) -> Result<Vec<Point>> {
    let black = Rgba {
        rgb: (0, 0, 0),
        alpha: 1.0,
    };
    let mut points = Vec::new();
    for (i, pv) in list(o, "points")?.iter().enumerate() {
        let p = format!("spec.points[{i}]");
        let po = pv
            .as_object()
            .ok_or_else(|| err(&p, "must be an object {x, y}"))?;
        points.push(Point {
            x: req_num(po, "x", &p)?,
            y: req_num(po, "y", &p)?,
            label: get_str(po, "label", &p)?,
            color: get_color(po, "color", &p, black)?,
        });
    }
    Ok(points)
}

/// `spec.vlines`: {x, label, color}, grey by default.
fn parse_vlines(o: &Obj) -> Result<Vec<VLine>> {
    let grey = Rgba {
        rgb: (0x77, 0x77, 0x77),
        alpha: 1.0,
    };
    let mut vlines = Vec::new();
    for (i, lv) in list(o, "vlines")?.iter().enumerate() {
        let p = format!("spec.vlines[{i}]");
        let lo = lv
            .as_object()
            .ok_or_else(|| err(&p, "must be an object {x}"))?;
        vlines.push(VLine {
            x: req_num(lo, "x", &p)?,
            label: get_str(lo, "label", &p)?,
            color: get_color(lo, "color", &p, grey)?,
        });
    }
    Ok(vlines)
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;
    use wasm_bindgen_test::wasm_bindgen_test;

    #[wasm_bindgen_test(unsupported = test)]
    fn errors_name_the_field() {
        let cases = [
            (json!(3), "spec"),
            (json!({}), "spec.canvas"),
            (json!({"canvas": "c", "kind": "bode"}), "spec.kind"),
            (
                json!({"canvas": "c", "series": [{"x": [1], "y": [1, 2]}]}),
                "spec.series[0].y",
            ),
            (
                json!({"canvas": "c", "series": [{"x": [1, "a"], "y": [1, 2]}]}),
                "spec.series[0].x[1]",
            ),
            (
                json!({"canvas": "c", "series": [{"x": [1], "y": [1], "color": "red"}]}),
                "spec.series[0].color",
            ),
            (
                json!({"canvas": "c", "circle": {"cx": -1, "cy": 0, "r": 0}}),
                "spec.circle.r",
            ),
            (json!({"canvas": "c", "xrange": [2, 1]}), "spec.xrange"),
            (json!({"canvas": "c", "dpr": 100}), "spec.dpr"),
            (
                json!({"canvas": "c", "points": [{"x": 1}]}),
                "spec.points[0].y",
            ),
        ];
        for (v, path) in cases {
            let e = Spec::from_json(&v).expect_err("must be rejected");
            assert_eq!(e.path, path, "{v}");
        }
    }
}
