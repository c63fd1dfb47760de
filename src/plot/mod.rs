//! Plotting for the page, drawn with `plotters` on an HTML canvas (`plotters-canvas`).
//!
//! This module holds no control math: it draws what the page hands it. The page calls the
//! wasm export `plot(spec)`, which calls [`draw`]; the spec is a plain JSON object:
//!
//! ```json
//! { "canvas": "plot-servo",            // id of a <canvas> element (required)
//!   "kind": "time" | "nyquist",        // axes: time response, or Nyquist plane (equal aspect)
//!   "title": "Set-point response", "xlabel": "t", "ylabel": "y",
//!   "dpr": 2,                          // device pixel ratio: scales fonts and line widths (0.5–4)
//!   "xrange": [0, 60], "yrange": [-1, 2],   // optional fixed ranges, else automatic
//!   "legend": true,                    // draw a legend of the labelled series (default true)
//!   "series": [ { "label": "y", "x": [..], "y": [..], "color": "#0072B2",
//!                 "dash": false, "faint": false, "width": 2 } ],
//!   "circle": { "cx": -1.4, "cy": 0, "r": 0.71, "label": "Ms circle", "color": "#D55E00" },
//!   "points": [ { "x": -1, "y": 0, "label": "−1", "color": "#000000" } ],
//!   "vlines": [ { "x": 30, "label": "load step", "color": "#999999" } ] }
//! ```
//!
//! Validation: every field is checked and an error names it (`spec.series[2].y[7]: …`).
//! `null` inside `x`/`y` marks a gap (the line is broken there); any other non-number is an
//! error. Nothing here panics on any input: lines are clipped to the plotting box in f64
//! before they are converted to pixels, long series are decimated (min/max per pixel column
//! for time plots), and the automatic Nyquist view is limited to the region around −1 so an
//! integrating loop's infinite low-frequency branch does not flatten the picture.
//!
//! Text is placed with canvas anchors only (no text measurement: plotters' web font backend
//! measures text by inserting a span into the document, which forces a layout per label and
//! would cost milliseconds per frame).

use crate::error::{Error, Result};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use serde_json::Value;

/// Maximum number of series in one plot.
const MAX_SERIES: usize = 64;
/// Maximum number of samples in one series.
const MAX_POINTS: usize = 1_000_000;

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

/// An RGBA colour.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rgba {
    /// Red, green, blue.
    pub rgb: (u8, u8, u8),
    /// Opacity in [0, 1].
    pub alpha: f64,
}

impl Rgba {
    fn style(self) -> RGBAColor {
        RGBAColor(self.rgb.0, self.rgb.1, self.rgb.2, self.alpha)
    }
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

fn err(path: &str, msg: impl Into<String>) -> Error {
    Error::new(path, msg)
}

fn get_str(obj: &serde_json::Map<String, Value>, key: &str, path: &str) -> Result<String> {
    match obj.get(key) {
        None | Some(Value::Null) => Ok(String::new()),
        Some(Value::String(s)) => {
            if s.chars().count() > 200 {
                Err(err(
                    &format!("{path}.{key}"),
                    "must be at most 200 characters",
                ))
            } else {
                Ok(s.clone())
            }
        }
        Some(_) => Err(err(&format!("{path}.{key}"), "must be a string")),
    }
}

fn get_bool(
    obj: &serde_json::Map<String, Value>,
    key: &str,
    path: &str,
    def: bool,
) -> Result<bool> {
    match obj.get(key) {
        None | Some(Value::Null) => Ok(def),
        Some(Value::Bool(b)) => Ok(*b),
        Some(_) => Err(err(&format!("{path}.{key}"), "must be true or false")),
    }
}

fn get_num(obj: &serde_json::Map<String, Value>, key: &str, path: &str) -> Result<Option<f64>> {
    match obj.get(key) {
        None | Some(Value::Null) => Ok(None),
        Some(Value::Number(n)) => match n.as_f64() {
            Some(v) if v.is_finite() => Ok(Some(v)),
            _ => Err(err(&format!("{path}.{key}"), "must be a finite number")),
        },
        Some(_) => Err(err(&format!("{path}.{key}"), "must be a number")),
    }
}

fn req_num(obj: &serde_json::Map<String, Value>, key: &str, path: &str) -> Result<f64> {
    get_num(obj, key, path)?.ok_or_else(|| err(&format!("{path}.{key}"), "is required"))
}

fn hex_digit(c: u8) -> Option<u8> {
    match c {
        b'0'..=b'9' => Some(c - b'0'),
        b'a'..=b'f' => Some(c - b'a' + 10),
        b'A'..=b'F' => Some(c - b'A' + 10),
        _ => None,
    }
}

/// Parses `#rgb`, `#rrggbb` or `#rrggbbaa`.
fn parse_color(s: &str, path: &str) -> Result<Rgba> {
    let bad = || {
        err(
            path,
            format!("must be a colour #rgb, #rrggbb or #rrggbbaa (got {s:?})"),
        )
    };
    let b = s.as_bytes();
    if b.first() != Some(&b'#') {
        return Err(bad());
    }
    let digits: Option<Vec<u8>> = b.iter().skip(1).map(|&c| hex_digit(c)).collect();
    let d = digits.ok_or_else(bad)?;
    let pair = |i: usize| -> u8 {
        d.get(i).copied().unwrap_or(0) * 16 + d.get(i + 1).copied().unwrap_or(0)
    };
    match d.len() {
        3 => {
            let one = |i: usize| d.get(i).copied().unwrap_or(0) * 17;
            Ok(Rgba {
                rgb: (one(0), one(1), one(2)),
                alpha: 1.0,
            })
        }
        6 => Ok(Rgba {
            rgb: (pair(0), pair(2), pair(4)),
            alpha: 1.0,
        }),
        8 => Ok(Rgba {
            rgb: (pair(0), pair(2), pair(4)),
            alpha: f64::from(pair(6)) / 255.0,
        }),
        _ => Err(bad()),
    }
}

fn get_color(
    obj: &serde_json::Map<String, Value>,
    key: &str,
    path: &str,
    def: Rgba,
) -> Result<Rgba> {
    match obj.get(key) {
        None | Some(Value::Null) => Ok(def),
        Some(Value::String(s)) => parse_color(s, &format!("{path}.{key}")),
        Some(_) => Err(err(
            &format!("{path}.{key}"),
            "must be a colour string like \"#0072B2\"",
        )),
    }
}

fn get_range(obj: &serde_json::Map<String, Value>, key: &str) -> Result<Option<(f64, f64)>> {
    let path = format!("spec.{key}");
    match obj.get(key) {
        None | Some(Value::Null) => Ok(None),
        Some(Value::Array(a)) if a.len() == 2 => {
            let lo = a.first().and_then(Value::as_f64);
            let hi = a.get(1).and_then(Value::as_f64);
            match (lo, hi) {
                (Some(lo), Some(hi)) if lo.is_finite() && hi.is_finite() && lo < hi => {
                    Ok(Some((lo, hi)))
                }
                _ => Err(err(&path, "must be [lo, hi] with finite lo < hi")),
            }
        }
        Some(_) => Err(err(&path, "must be an array [lo, hi]")),
    }
}

fn get_samples(
    obj: &serde_json::Map<String, Value>,
    key: &str,
    path: &str,
) -> Result<Vec<Option<f64>>> {
    let p = format!("{path}.{key}");
    let arr = match obj.get(key) {
        Some(Value::Array(a)) => a,
        None | Some(Value::Null) => return Err(err(&p, "is required (an array of numbers)")),
        Some(_) => return Err(err(&p, "must be an array of numbers")),
    };
    if arr.len() > MAX_POINTS {
        return Err(err(
            &p,
            format!("must have at most {MAX_POINTS} samples (got {})", arr.len()),
        ));
    }
    arr.iter()
        .enumerate()
        .map(|(i, v)| match v {
            Value::Null => Ok(None),
            Value::Number(n) => Ok(n.as_f64().filter(|x| x.is_finite())),
            _ => Err(err(
                &format!("{p}[{i}]"),
                "must be a number or null (a gap)",
            )),
        })
        .collect()
}

/// The default series colours: the Okabe–Ito colour-blind-safe palette (Okabe & Ito 2008).
pub const OKABE_ITO: [&str; 8] = [
    "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442",
];

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
        let kind = match o.get("kind") {
            None | Some(Value::Null) => Kind::Time,
            Some(Value::String(s)) if s == "time" => Kind::Time,
            Some(Value::String(s)) if s == "nyquist" => Kind::Nyquist,
            Some(_) => return Err(err("spec.kind", "must be \"time\" or \"nyquist\"")),
        };
        let dpr = get_num(o, "dpr", "spec")?.unwrap_or(1.0);
        if !(0.5..=4.0).contains(&dpr) {
            return Err(err(
                "spec.dpr",
                format!("must be between 0.5 and 4 (got {dpr})"),
            ));
        }
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
            let dash = match so.get("dash") {
                None | Some(Value::Null) | Some(Value::Bool(false)) => Dash::Solid,
                Some(Value::Bool(true)) => Dash::Dash,
                Some(Value::String(s)) if s == "solid" => Dash::Solid,
                Some(Value::String(s)) if s == "dash" => Dash::Dash,
                Some(Value::String(s)) if s == "dot" => Dash::Dot,
                Some(_) => {
                    return Err(err(
                        &format!("{path}.dash"),
                        "must be true/false or \"solid\", \"dash\", \"dot\"",
                    ))
                }
            };
            let faint = get_bool(so, "faint", &path, false)?;
            let width = get_num(so, "width", &path)?.unwrap_or(if faint { 1.5 } else { 2.0 });
            if !(0.25..=10.0).contains(&width) {
                return Err(err(&format!("{path}.width"), "must be between 0.25 and 10"));
            }
            series.push(Series {
                label: get_str(so, "label", &path)?,
                x,
                y,
                color,
                dash,
                faint,
                width,
            });
        }
        let circle = match o.get("circle") {
            None | Some(Value::Null) => None,
            Some(Value::Object(co)) => {
                let p = "spec.circle";
                let r = req_num(co, "r", p)?;
                if r <= 0.0 {
                    return Err(err("spec.circle.r", "must be > 0"));
                }
                Some(Circle {
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
                })
            }
            Some(_) => return Err(err("spec.circle", "must be an object {cx, cy, r}")),
        };
        let list = |key: &str| -> Result<&[Value]> {
            match o.get(key) {
                None | Some(Value::Null) => Ok(&[]),
                Some(Value::Array(a)) if a.len() <= 64 => Ok(a),
                Some(Value::Array(_)) => Err(err(&format!("spec.{key}"), "at most 64 entries")),
                Some(_) => Err(err(&format!("spec.{key}"), "must be an array")),
            }
        };
        let black = Rgba {
            rgb: (0, 0, 0),
            alpha: 1.0,
        };
        let grey = Rgba {
            rgb: (0x77, 0x77, 0x77),
            alpha: 1.0,
        };
        let mut points = Vec::new();
        for (i, pv) in list("points")?.iter().enumerate() {
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
        let mut vlines = Vec::new();
        for (i, lv) in list("vlines")?.iter().enumerate() {
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

/// Draws the plot described by `spec` on its canvas (wasm only; natively the spec is validated
/// and an error says that drawing needs a browser canvas).
///
/// `spec` may also be the JSON text of the spec (a JS string): the page passes
/// `JSON.stringify(spec)` because parsing text is much faster than converting a JS object with
/// long arrays element by element across the wasm boundary.
pub fn draw(spec: &Value) -> Result<()> {
    let parsed;
    let spec = match spec {
        Value::String(text) => {
            parsed = serde_json::from_str::<Value>(text)
                .map_err(|e| err("spec", format!("is not valid JSON ({e})")))?;
            &parsed
        }
        v => v,
    };
    let s = Spec::from_json(spec)?;
    draw_spec(&s)
}

#[cfg(target_arch = "wasm32")]
fn draw_spec(s: &Spec) -> Result<()> {
    let backend = plotters_canvas::CanvasBackend::new(&s.canvas).ok_or_else(|| {
        err(
            "spec.canvas",
            format!("no <canvas> element with id {:?}", s.canvas),
        )
    })?;
    let root = backend.into_drawing_area();
    render(s, &root)
}

#[cfg(not(target_arch = "wasm32"))]
fn draw_spec(_s: &Spec) -> Result<()> {
    Err(err(
        "spec.canvas",
        "drawing needs a browser canvas (the wasm build)",
    ))
}

/// Automatic axis bounds with a margin; never degenerate.
fn pad_range(lo: f64, hi: f64, frac: f64) -> (f64, f64) {
    if !(lo.is_finite() && hi.is_finite()) || lo > hi {
        return (0.0, 1.0);
    }
    let span = hi - lo;
    if span <= 1e-12 * lo.abs().max(hi.abs()).max(1e-300) {
        let d = if lo.abs() > 0.0 { 0.1 * lo.abs() } else { 1.0 };
        return (lo - d, hi + d);
    }
    (lo - frac * span, hi + frac * span)
}

/// Liang–Barsky clipping of the segment a→b to the box; None when it lies outside.
fn clip(
    a: (f64, f64),
    b: (f64, f64),
    bx: (f64, f64, f64, f64),
) -> Option<((f64, f64), (f64, f64))> {
    let (x0, x1, y0, y1) = bx;
    let dx = b.0 - a.0;
    let dy = b.1 - a.1;
    let mut t0 = 0.0f64;
    let mut t1 = 1.0f64;
    for (p, q) in [
        (-dx, a.0 - x0),
        (dx, x1 - a.0),
        (-dy, a.1 - y0),
        (dy, y1 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                if r > t1 {
                    return None;
                }
                t0 = t0.max(r);
            } else {
                if r < t0 {
                    return None;
                }
                t1 = t1.min(r);
            }
        }
    }
    Some((
        (a.0 + t0 * dx, a.1 + t0 * dy),
        (a.0 + t1 * dx, a.1 + t1 * dy),
    ))
}

/// Splits a series into clipped polylines in data coordinates.
fn polylines(s: &Series, bx: (f64, f64, f64, f64)) -> Vec<Vec<(f64, f64)>> {
    let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut cur: Vec<(f64, f64)> = Vec::new();
    let mut prev: Option<(f64, f64)> = None;
    for (x, y) in s.x.iter().zip(s.y.iter()) {
        let p = match (x, y) {
            (Some(x), Some(y)) => Some((*x, *y)),
            _ => None,
        };
        match (prev, p) {
            (Some(a), Some(b)) => match clip(a, b, bx) {
                Some((ca, cb)) => {
                    if cur.last() != Some(&ca) {
                        if cur.len() > 1 {
                            out.push(std::mem::take(&mut cur));
                        }
                        cur.clear();
                        cur.push(ca);
                    }
                    cur.push(cb);
                }
                None => {
                    if cur.len() > 1 {
                        out.push(std::mem::take(&mut cur));
                    }
                    cur.clear();
                }
            },
            _ => {
                if cur.len() > 1 {
                    out.push(std::mem::take(&mut cur));
                }
                cur.clear();
            }
        }
        prev = p;
    }
    if cur.len() > 1 {
        out.push(cur);
    }
    out
}

/// Reduces a pixel polyline: consecutive points in the same pixel column collapse to their
/// first, min, max and last (keeps the envelope of a dense time series exactly).
fn decimate(px: &[(i32, i32)]) -> Vec<(i32, i32)> {
    let mut out: Vec<(i32, i32)> = Vec::with_capacity(px.len().min(4096));
    let mut i = 0;
    while i < px.len() {
        let Some(&first) = px.get(i) else { break };
        let mut j = i;
        let (mut lo, mut hi, mut last) = (first, first, first);
        while let Some(&p) = px.get(j) {
            if p.0 != first.0 {
                break;
            }
            if p.1 < lo.1 {
                lo = p;
            }
            if p.1 > hi.1 {
                hi = p;
            }
            last = p;
            j += 1;
        }
        for p in [first, lo, hi, last] {
            if out.last() != Some(&p) {
                out.push(p);
            }
        }
        i = j.max(i + 1);
    }
    out
}

/// Cuts a pixel polyline into dash segments (on, off lengths in pixels).
fn dashes(px: &[(i32, i32)], on: f64, off: f64) -> Vec<Vec<(i32, i32)>> {
    let mut out = Vec::new();
    let mut cur: Vec<(i32, i32)> = Vec::new();
    let mut drawing = true;
    let mut left = on;
    for w in px.windows(2) {
        let (Some(&a), Some(&b)) = (w.first(), w.get(1)) else {
            continue;
        };
        let (ax, ay) = (f64::from(a.0), f64::from(a.1));
        let (dx, dy) = (f64::from(b.0) - ax, f64::from(b.1) - ay);
        let len = (dx * dx + dy * dy).sqrt();
        let mut pos = 0.0;
        if drawing && cur.is_empty() {
            cur.push(a);
        }
        while len - pos > left {
            pos += left;
            let p = (
                (ax + dx * pos / len).round() as i32,
                (ay + dy * pos / len).round() as i32,
            );
            if drawing {
                cur.push(p);
                out.push(std::mem::take(&mut cur));
                left = off;
            } else {
                cur.push(p);
                left = on;
            }
            drawing = !drawing;
        }
        left -= len - pos;
        if drawing {
            cur.push(b);
        }
    }
    if drawing && cur.len() > 1 {
        out.push(cur);
    }
    out
}

/// Chooses a tick label precision for the range.
fn decimals(lo: f64, hi: f64, nticks: f64) -> usize {
    let step = (hi - lo).abs() / nticks.max(1.0);
    if !(step.is_finite() && step > 0.0) {
        return 2;
    }
    let d = -(step.log10().floor());
    d.clamp(0.0, 8.0) as usize
}

fn fmt_tick(v: f64, dec: usize) -> String {
    let s = format!("{v:.dec$}");
    // avoid "-0" / "-0.00"
    if s.trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        s.trim_start_matches('-').to_string()
    } else {
        s
    }
}

fn derr<E: std::error::Error + Send + Sync>(e: DrawingAreaErrorKind<E>) -> Error {
    err("spec.canvas", format!("drawing failed: {e}"))
}

/// Renders a validated spec on any plotters drawing area.
pub fn render<DB: DrawingBackend>(s: &Spec, root: &DrawingArea<DB, Shift>) -> Result<()> {
    let k = s.dpr;
    let px = |v: f64| (v * k).round() as i32;
    let (w, h) = root.dim_in_pixel();
    if w < 40 || h < 40 {
        return Err(err(
            "spec.canvas",
            format!("canvas too small ({w}×{h} pixels)"),
        ));
    }
    root.fill(&WHITE).map_err(derr)?;
    let font = (13.0 * k).max(6.0);
    let small = (11.0 * k).max(5.0);
    let fg = RGBColor(0x22, 0x22, 0x22);

    // Data bounds.
    let mut xb = (f64::INFINITY, f64::NEG_INFINITY);
    let mut yb = (f64::INFINITY, f64::NEG_INFINITY);
    let widen = |b: &mut (f64, f64), v: f64| {
        if v.is_finite() {
            b.0 = b.0.min(v);
            b.1 = b.1.max(v);
        }
    };
    let (xr, yr) = match s.kind {
        Kind::Time => {
            for sr in &s.series {
                for (x, y) in sr.x.iter().zip(sr.y.iter()) {
                    if let (Some(x), Some(y)) = (x, y) {
                        widen(&mut xb, *x);
                        if s.xrange.is_none_or(|(lo, hi)| *x >= lo && *x <= hi) {
                            widen(&mut yb, *y);
                        }
                    }
                }
            }
            let xr = s.xrange.unwrap_or(if xb.0 <= xb.1 {
                (xb.0, xb.1)
            } else {
                (0.0, 1.0)
            });
            let xr = if xr.1 > xr.0 {
                xr
            } else {
                pad_range(xr.0, xr.1, 0.0)
            };
            let yr = s.yrange.unwrap_or_else(|| pad_range(yb.0, yb.1, 0.06));
            (xr, yr)
        }
        Kind::Nyquist => {
            // The view: the critical region. Points with |L| beyond `reach` are not used
            // for the automatic bounds (an integrator's branch goes to infinity).
            let mut reach: f64 = 3.0;
            if let Some(c) = &s.circle {
                reach = reach.max(1.5 * (c.cx.hypot(c.cy) + c.r));
            }
            reach = reach.min(50.0);
            widen(&mut xb, -1.0);
            widen(&mut yb, 0.0);
            for sr in &s.series {
                for (x, y) in sr.x.iter().zip(sr.y.iter()) {
                    if let (Some(x), Some(y)) = (x, y) {
                        if x.hypot(*y) <= reach {
                            widen(&mut xb, *x);
                            widen(&mut yb, *y);
                        }
                    }
                }
            }
            if let Some(c) = &s.circle {
                widen(&mut xb, c.cx - c.r);
                widen(&mut xb, c.cx + c.r);
                widen(&mut yb, c.cy - c.r);
                widen(&mut yb, c.cy + c.r);
            }
            for p in &s.points {
                widen(&mut xb, p.x);
                widen(&mut yb, p.y);
            }
            let xr = s.xrange.unwrap_or_else(|| pad_range(xb.0, xb.1, 0.08));
            let yr = s.yrange.unwrap_or_else(|| pad_range(yb.0, yb.1, 0.08));
            (xr, yr)
        }
    };

    // Layout.
    let left = px(58.0);
    let right = px(12.0);
    let legend = if s.legend {
        legend_entries(s)
    } else {
        Vec::new()
    };
    let line_h = (small * 1.4).round() as i32;
    let sample = px(22.0);
    let (legend_pos, rows) =
        legend_layout(&legend, (w as i32 - left - right).max(10), sample, small, k);
    let title_h = if s.title.is_empty() {
        0
    } else {
        (font * 1.5).round() as i32
    };
    let legend_top = px(6.0) + title_h;
    let top = legend_top + line_h * rows + px(6.0);
    let bottom = px(44.0);
    let pw = (w as i32 - left - right).max(10);
    let ph = (h as i32 - top - bottom).max(10);
    // Equal aspect for Nyquist: widen the shorter range.
    let (xr, yr) = if s.kind == Kind::Nyquist && s.xrange.is_none() && s.yrange.is_none() {
        let sx = (xr.1 - xr.0) / f64::from(pw);
        let sy = (yr.1 - yr.0) / f64::from(ph);
        if sx > sy {
            let c = 0.5 * (yr.0 + yr.1);
            let half = 0.5 * sx * f64::from(ph);
            (xr, (c - half, c + half))
        } else {
            let c = 0.5 * (xr.0 + xr.1);
            let half = 0.5 * sy * f64::from(pw);
            ((c - half, c + half), yr)
        }
    } else {
        (xr, yr)
    };

    if !s.title.is_empty() {
        let st = ("sans-serif", font)
            .into_font()
            .style(FontStyle::Bold)
            .color(&fg)
            .pos(Pos::new(HPos::Left, VPos::Top));
        root.draw_text(&s.title, &st, (left, px(6.0)))
            .map_err(derr)?;
    }

    let mut chart = ChartBuilder::on(root)
        .margin_top(top.max(0) as u32)
        .margin_right(right.max(0) as u32)
        .x_label_area_size(bottom.max(0) as u32)
        .y_label_area_size(left.max(0) as u32)
        .build_cartesian_2d(xr.0..xr.1, yr.0..yr.1)
        .map_err(derr)?;
    let nx = (f64::from(pw) / (70.0 * k)).clamp(2.0, 10.0);
    let ny = (f64::from(ph) / (40.0 * k)).clamp(2.0, 10.0);
    let dx = decimals(xr.0, xr.1, nx);
    let dy = decimals(yr.0, yr.1, ny);
    let xf = move |v: &f64| fmt_tick(*v, dx);
    let yf = move |v: &f64| fmt_tick(*v, dy);
    chart
        .configure_mesh()
        .x_labels(nx as usize)
        .y_labels(ny as usize)
        .x_label_formatter(&xf)
        .y_label_formatter(&yf)
        .label_style(("sans-serif", small).into_font().color(&fg))
        .axis_desc_style(("sans-serif", font).into_font().color(&fg))
        .x_desc(s.xlabel.as_str())
        .y_desc(s.ylabel.as_str())
        .bold_line_style(RGBAColor(0, 0, 0, 0.12).stroke_width(px(1.0).max(1) as u32))
        .light_line_style(RGBAColor(0, 0, 0, 0.0))
        .axis_style(fg.stroke_width(px(1.0).max(1) as u32))
        .set_tick_mark_size(LabelAreaPosition::Left, px(4.0))
        .set_tick_mark_size(LabelAreaPosition::Bottom, px(4.0))
        .draw()
        .map_err(derr)?;

    let bx = (xr.0, xr.1, yr.0, yr.1);
    let to_px = |p: (f64, f64)| chart.backend_coord(&p);

    // Reference lines: zero axes for Nyquist.
    if s.kind == Kind::Nyquist {
        let ax = RGBAColor(0, 0, 0, 0.35).stroke_width(px(1.0).max(1) as u32);
        for seg in [((xr.0, 0.0), (xr.1, 0.0)), ((0.0, yr.0), (0.0, yr.1))] {
            if let Some((a, b)) = clip(seg.0, seg.1, bx) {
                root.draw(&PathElement::new(vec![to_px(a), to_px(b)], ax))
                    .map_err(derr)?;
            }
        }
    }

    // Vertical markers.
    for v in &s.vlines {
        if v.x >= xr.0 && v.x <= xr.1 {
            let a = to_px((v.x, yr.0));
            let b = to_px((v.x, yr.1));
            let st = v.color.style().stroke_width(px(1.0).max(1) as u32);
            for d in dashes(&[a, b], 4.0 * k, 4.0 * k) {
                root.draw(&PathElement::new(d, st)).map_err(derr)?;
            }
            if !v.label.is_empty() {
                let ts = ("sans-serif", small)
                    .into_font()
                    .color(&v.color.style())
                    .pos(Pos::new(HPos::Left, VPos::Top));
                root.draw_text(&v.label, &ts, (b.0 + px(3.0), b.1 + px(2.0)))
                    .map_err(derr)?;
            }
        }
    }

    // Circle (as a polygon through the clipper).
    if let Some(c) = &s.circle {
        let n = 180;
        let xs: Vec<Option<f64>> = (0..=n)
            .map(|i| Some(c.cx + c.r * (f64::from(i) * std::f64::consts::TAU / f64::from(n)).cos()))
            .collect();
        let ys: Vec<Option<f64>> = (0..=n)
            .map(|i| Some(c.cy + c.r * (f64::from(i) * std::f64::consts::TAU / f64::from(n)).sin()))
            .collect();
        let cs = Series {
            label: c.label.clone(),
            x: xs,
            y: ys,
            color: c.color,
            dash: Dash::Dash,
            faint: false,
            width: 1.5,
        };
        draw_series(root, &cs, bx, &to_px, k, false)?;
    }

    // Faint series first, so the emphasised ones lie on top.
    for sr in s.series.iter().filter(|x| x.faint) {
        draw_series(root, sr, bx, &to_px, k, s.kind == Kind::Time)?;
    }
    for sr in s.series.iter().filter(|x| !x.faint) {
        draw_series(root, sr, bx, &to_px, k, s.kind == Kind::Time)?;
    }

    // Points.
    for p in &s.points {
        if p.x >= xr.0 && p.x <= xr.1 && p.y >= yr.0 && p.y <= yr.1 {
            let c = to_px((p.x, p.y));
            let st = p.color.style().stroke_width(px(2.0).max(1) as u32);
            let r = px(5.0);
            root.draw(&PathElement::new(vec![(c.0 - r, c.1), (c.0 + r, c.1)], st))
                .map_err(derr)?;
            root.draw(&PathElement::new(vec![(c.0, c.1 - r), (c.0, c.1 + r)], st))
                .map_err(derr)?;
            if !p.label.is_empty() {
                let ts = ("sans-serif", small)
                    .into_font()
                    .color(&p.color.style())
                    .pos(Pos::new(HPos::Left, VPos::Bottom));
                root.draw_text(&p.label, &ts, (c.0 + r, c.1 - r))
                    .map_err(derr)?;
            }
        }
    }

    // Legend: a band between the title and the plotting box, entries flowing left to right
    // (never covers the curves). Text width is estimated from the number of characters (no
    // text measurement, see the module documentation).
    for (i, (label, color, dash, width)) in legend.iter().enumerate() {
        let Some(&(lx, row)) = legend_pos.get(i) else {
            break;
        };
        let cy = legend_top + line_h * row + line_h / 2;
        let a = (left + lx, cy);
        let b = (left + lx + sample, cy);
        let st = color.style().stroke_width(px(*width).max(1) as u32);
        let segs = match dash {
            Dash::Solid => vec![vec![a, b]],
            Dash::Dash => dashes(&[a, b], 6.0 * k, 4.0 * k),
            Dash::Dot => dashes(&[a, b], 2.0 * k, 3.0 * k),
        };
        for seg in segs {
            root.draw(&PathElement::new(seg, st)).map_err(derr)?;
        }
        let ts = ("sans-serif", small)
            .into_font()
            .color(&fg)
            .pos(Pos::new(HPos::Left, VPos::Center));
        root.draw_text(label, &ts, (b.0 + px(4.0), cy))
            .map_err(derr)?;
    }
    root.present().map_err(derr)?;
    Ok(())
}

/// The legend entries: labelled series, then the circle.
fn legend_entries(s: &Spec) -> Vec<(String, Rgba, Dash, f64)> {
    let mut entries: Vec<(String, Rgba, Dash, f64)> = s
        .series
        .iter()
        .filter(|x| !x.label.is_empty())
        .map(|x| {
            let c = if x.faint {
                Rgba {
                    alpha: x.color.alpha * 0.45,
                    ..x.color
                }
            } else {
                x.color
            };
            (x.label.clone(), c, x.dash, x.width)
        })
        .collect();
    if let Some(c) = &s.circle {
        if !c.label.is_empty() {
            entries.push((c.label.clone(), c.color, Dash::Dash, 1.5));
        }
    }
    entries
}

/// Flows legend entries into rows of width `avail`: (x offset, row) per entry, and the row count.
fn legend_layout(
    entries: &[(String, Rgba, Dash, f64)],
    avail: i32,
    sample: i32,
    small: f64,
    k: f64,
) -> (Vec<(i32, i32)>, i32) {
    let mut pos = Vec::with_capacity(entries.len());
    let (mut x, mut row) = (0i32, 0i32);
    for e in entries {
        let tw = (e.0.chars().count() as f64 * small * 0.56).round() as i32;
        let ew = sample + (4.0 * k).round() as i32 + tw + (14.0 * k).round() as i32;
        if x > 0 && x + ew > avail {
            x = 0;
            row += 1;
        }
        pos.push((x, row));
        x += ew;
    }
    let rows = if entries.is_empty() { 0 } else { row + 1 };
    (pos, rows)
}

fn draw_series<DB: DrawingBackend, F: Fn((f64, f64)) -> (i32, i32)>(
    root: &DrawingArea<DB, Shift>,
    sr: &Series,
    bx: (f64, f64, f64, f64),
    to_px: &F,
    k: f64,
    dense: bool,
) -> Result<()> {
    let color = if sr.faint {
        Rgba {
            alpha: sr.color.alpha * 0.45,
            ..sr.color
        }
    } else {
        sr.color
    };
    let st = color
        .style()
        .stroke_width((sr.width * k).round().max(1.0) as u32);
    for line in polylines(sr, bx) {
        let mut pts: Vec<(i32, i32)> = line.into_iter().map(to_px).collect();
        pts.dedup();
        if dense {
            pts = decimate(&pts);
        }
        if pts.len() < 2 {
            continue;
        }
        let segs = match sr.dash {
            Dash::Solid => vec![pts],
            Dash::Dash => dashes(&pts, 7.0 * k, 5.0 * k),
            Dash::Dot => dashes(&pts, 2.0 * k, 3.5 * k),
        };
        for seg in segs {
            if seg.len() > 1 {
                root.draw(&PathElement::new(seg, st)).map_err(derr)?;
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use plotters_backend::{
        BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingErrorKind,
    };
    use serde_json::json;
    use wasm_bindgen_test::wasm_bindgen_test;

    thread_local! {
        static LOG: std::cell::RefCell<Option<Recorder>> = const { std::cell::RefCell::new(None) };
    }

    /// A drawing backend that records what is drawn, to test rendering natively.
    struct Recorder {
        w: u32,
        h: u32,
        paths: usize,
        texts: Vec<String>,
        out_of_canvas: usize,
    }

    #[derive(Debug)]
    struct NoErr;
    impl std::fmt::Display for NoErr {
        fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
            write!(f, "none")
        }
    }
    impl std::error::Error for NoErr {}

    impl DrawingBackend for Recorder {
        type ErrorType = NoErr;
        fn get_size(&self) -> (u32, u32) {
            (self.w, self.h)
        }
        fn ensure_prepared(&mut self) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
            Ok(())
        }
        fn present(&mut self) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
            let copy = Recorder {
                w: self.w,
                h: self.h,
                paths: self.paths,
                texts: self.texts.clone(),
                out_of_canvas: self.out_of_canvas,
            };
            LOG.with(|l| *l.borrow_mut() = Some(copy));
            Ok(())
        }
        fn draw_pixel(
            &mut self,
            _p: BackendCoord,
            _c: BackendColor,
        ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
            Ok(())
        }
        fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
            &mut self,
            path: I,
            _style: &S,
        ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
            self.paths += 1;
            for p in path {
                if p.0 < -2 || p.1 < -2 || p.0 > self.w as i32 + 2 || p.1 > self.h as i32 + 2 {
                    self.out_of_canvas += 1;
                }
            }
            Ok(())
        }
        fn draw_text<TStyle: BackendTextStyle>(
            &mut self,
            text: &str,
            _style: &TStyle,
            _pos: BackendCoord,
        ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
            self.texts.push(text.to_string());
            Ok(())
        }
        fn estimate_text_size<TStyle: BackendTextStyle>(
            &self,
            text: &str,
            _style: &TStyle,
        ) -> std::result::Result<(u32, u32), DrawingErrorKind<NoErr>> {
            Ok((text.len() as u32 * 7, 12))
        }
    }

    fn rec(w: u32, h: u32) -> Recorder {
        Recorder {
            w,
            h,
            paths: 0,
            texts: Vec::new(),
            out_of_canvas: 0,
        }
    }

    fn render_json(v: &Value, w: u32, h: u32) -> Result<Recorder> {
        let s = Spec::from_json(v)?;
        let area = rec(w, h).into_drawing_area();
        render(&s, &area)?;
        Ok(LOG.with(|l| l.take()).unwrap_or_else(|| rec(w, h)))
    }

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

    #[wasm_bindgen_test(unsupported = test)]
    fn colours_parse() {
        assert_eq!(
            parse_color("#0072B2", "c").map(|c| c.rgb),
            Ok((0, 0x72, 0xB2))
        );
        assert_eq!(parse_color("#fff", "c").map(|c| c.rgb), Ok((255, 255, 255)));
        let c = parse_color("#00000080", "c")
            .map(|c| c.alpha)
            .unwrap_or(0.0);
        assert!((c - 128.0 / 255.0).abs() < 1e-12);
        assert!(parse_color("#12", "c").is_err());
        assert!(parse_color("#ééé", "c").is_err());
    }

    #[wasm_bindgen_test(unsupported = test)]
    fn clipping_keeps_lines_inside() {
        // A line from far outside through the box is cut at the box edges.
        let r = clip((-10.0, 0.5), (10.0, 0.5), (0.0, 1.0, 0.0, 1.0));
        assert_eq!(r, Some(((0.0, 0.5), (1.0, 0.5))));
        assert_eq!(clip((2.0, 2.0), (3.0, 3.0), (0.0, 1.0, 0.0, 1.0)), None);
        // Huge values (an integrator's Nyquist branch) stay on the canvas.
        let t: Vec<f64> = (0..2000).map(|i| f64::from(i) * 0.01).collect();
        let y: Vec<f64> = t.iter().map(|v| (v * 3.0).sin()).collect();
        let re: Vec<f64> = (1..400).map(|i| -1e9 / f64::from(i)).collect();
        let im: Vec<f64> = (1..400).map(|i| -1e12 / f64::from(i * i)).collect();
        let r = render_json(
            &json!({"canvas": "c", "kind": "nyquist", "title": "Nyquist",
                    "series": [{"label": "L", "x": re, "y": im}],
                    "circle": {"cx": -1, "cy": 0, "r": 0.6, "label": "Ms"},
                    "points": [{"x": -1, "y": 0, "label": "−1"}]}),
            400,
            300,
        )
        .expect("renders");
        assert_eq!(r.out_of_canvas, 0);
        assert!(r.texts.iter().any(|t| t == "Nyquist"));
        let r = render_json(
            &json!({"canvas": "c", "series": [{"label": "y", "x": t, "y": y, "dash": "dash"},
                    {"label": "nominal", "x": [0, 1, null, 2, 3], "y": [0, 1, null, 1, 1], "faint": true}],
                    "vlines": [{"x": 5, "label": "load"}], "xlabel": "t", "ylabel": "y"}),
            360,
            200,
        )
        .expect("renders");
        assert_eq!(r.out_of_canvas, 0);
        assert!(r.paths > 10);
        assert!(r.texts.iter().any(|t| t == "nominal"));
    }

    #[wasm_bindgen_test(unsupported = test)]
    fn degenerate_inputs_do_not_fail() {
        // Empty series, constant data, a single point, a tiny canvas: no panic, sensible result.
        for v in [
            json!({"canvas": "c"}),
            json!({"canvas": "c", "series": [{"x": [], "y": []}]}),
            json!({"canvas": "c", "series": [{"x": [0, 1, 2], "y": [1, 1, 1]}]}),
            json!({"canvas": "c", "series": [{"x": [0], "y": [0]}]}),
            json!({"canvas": "c", "kind": "nyquist", "series": [{"x": [null], "y": [null]}]}),
        ] {
            assert!(render_json(&v, 300, 200).is_ok(), "{v}");
        }
        assert_eq!(
            render_json(&json!({"canvas": "c"}), 10, 10)
                .map(|_| ())
                .map_err(|e| e.path),
            Err("spec.canvas".to_string())
        );
    }

    #[wasm_bindgen_test(unsupported = test)]
    fn small_canvases_and_long_legends_do_not_panic() {
        // Layout margins larger than the canvas, a legend that wraps to many rows, extreme
        // ranges: rendering must return (Ok or an error), never panic.
        let many: Vec<Value> = (0..40)
            .map(|i| json!({"label": format!("a long legend entry number {i}"), "x": [0, 1], "y": [i, -i]}))
            .collect();
        for (w, h) in [
            (40, 40),
            (41, 300),
            (300, 41),
            (60, 60),
            (360, 225),
            (4000, 40),
        ] {
            for dpr in [0.5, 1.0, 4.0] {
                let v = json!({"canvas": "c", "title": "A title", "xlabel": "t", "ylabel": "y",
                               "dpr": dpr, "series": many,
                               "circle": {"cx": -1, "cy": 0, "r": 0.5, "label": "Ms"}});
                let _ = render_json(&v, w, h);
                let v = json!({"canvas": "c", "kind": "nyquist", "dpr": dpr,
                               "series": [{"x": [-1e300, 1e300, 0], "y": [1e300, -1e300, 0]}],
                               "xrange": [-1e-300, 1e-300]});
                let _ = render_json(&v, w, h);
            }
        }
    }

    #[wasm_bindgen_test(unsupported = test)]
    fn decimation_keeps_the_envelope() {
        let px: Vec<(i32, i32)> = (0..1000)
            .map(|i| (i / 100, if i % 2 == 0 { i % 37 } else { -(i % 41) }))
            .collect();
        let d = decimate(&px);
        assert!(d.len() <= 40);
        for col in 0..10 {
            let orig: Vec<i32> = px.iter().filter(|p| p.0 == col).map(|p| p.1).collect();
            let kept: Vec<i32> = d.iter().filter(|p| p.0 == col).map(|p| p.1).collect();
            assert_eq!(orig.iter().max(), kept.iter().max());
            assert_eq!(orig.iter().min(), kept.iter().min());
        }
    }

    #[wasm_bindgen_test(unsupported = test)]
    fn dashes_cover_half_the_length() {
        let d = dashes(&[(0, 0), (100, 0)], 5.0, 5.0);
        assert_eq!(d.len(), 10);
        let on: i32 = d
            .iter()
            .map(|s| s.last().map_or(0, |l| l.0) - s.first().map_or(0, |f| f.0))
            .sum();
        assert_eq!(on, 50);
    }

    /// A drawing backend that writes every call it receives, with its coordinates and style,
    /// as one line of text: two renderings are the same picture when their tapes are equal.
    struct Tape {
        w: u32,
        h: u32,
        log: String,
    }

    thread_local! {
        static TAPE: std::cell::RefCell<String> = const { std::cell::RefCell::new(String::new()) };
    }

    fn colour(c: BackendColor) -> String {
        format!("rgba({},{},{},{:?})", c.rgb.0, c.rgb.1, c.rgb.2, c.alpha)
    }

    fn stroke<S: BackendStyle>(s: &S) -> String {
        format!("{} w{}", colour(s.color()), s.stroke_width())
    }

    impl Tape {
        fn put(&mut self, line: String) {
            self.log.push_str(&line);
            self.log.push('\n');
        }
    }

    impl DrawingBackend for Tape {
        type ErrorType = NoErr;
        fn get_size(&self) -> (u32, u32) {
            (self.w, self.h)
        }
        fn ensure_prepared(&mut self) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
            Ok(())
        }
        fn present(&mut self) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
            self.put("present".to_string());
            let log = std::mem::take(&mut self.log);
            TAPE.with(|t| *t.borrow_mut() = log);
            Ok(())
        }
        fn draw_pixel(
            &mut self,
            p: BackendCoord,
            c: BackendColor,
        ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
            self.put(format!("pixel {p:?} {}", colour(c)));
            Ok(())
        }
        fn draw_line<S: BackendStyle>(
            &mut self,
            from: BackendCoord,
            to: BackendCoord,
            style: &S,
        ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
            self.put(format!("line {from:?} {to:?} {}", stroke(style)));
            Ok(())
        }
        fn draw_rect<S: BackendStyle>(
            &mut self,
            a: BackendCoord,
            b: BackendCoord,
            style: &S,
            fill: bool,
        ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
            self.put(format!("rect {a:?} {b:?} {} fill={fill}", stroke(style)));
            Ok(())
        }
        fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
            &mut self,
            path: I,
            style: &S,
        ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
            let pts: Vec<BackendCoord> = path.into_iter().collect();
            self.put(format!("path {} {pts:?}", stroke(style)));
            Ok(())
        }
        fn draw_circle<S: BackendStyle>(
            &mut self,
            c: BackendCoord,
            r: u32,
            style: &S,
            fill: bool,
        ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
            self.put(format!("circle {c:?} r{r} {} fill={fill}", stroke(style)));
            Ok(())
        }
        fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
            &mut self,
            vert: I,
            style: &S,
        ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
            let pts: Vec<BackendCoord> = vert.into_iter().collect();
            self.put(format!("polygon {} {pts:?}", stroke(style)));
            Ok(())
        }
        fn draw_text<TStyle: BackendTextStyle>(
            &mut self,
            text: &str,
            style: &TStyle,
            pos: BackendCoord,
        ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
            use plotters_backend::text_anchor::{HPos, VPos};
            use plotters_backend::FontTransform;
            let a = style.anchor();
            let h = match a.h_pos {
                HPos::Left => "left",
                HPos::Center => "center",
                HPos::Right => "right",
            };
            let v = match a.v_pos {
                VPos::Top => "top",
                VPos::Center => "center",
                VPos::Bottom => "bottom",
            };
            let t = match style.transform() {
                FontTransform::None => "none",
                FontTransform::Rotate90 => "rot90",
                FontTransform::Rotate180 => "rot180",
                FontTransform::Rotate270 => "rot270",
            };
            self.put(format!(
                "text {text:?} at {pos:?} {} {:?} {} {} anchor={h}/{v} transform={t}",
                style.family().as_str(),
                style.size(),
                style.style().as_str(),
                colour(style.color()),
            ));
            Ok(())
        }
        fn estimate_text_size<TStyle: BackendTextStyle>(
            &self,
            text: &str,
            _style: &TStyle,
        ) -> std::result::Result<(u32, u32), DrawingErrorKind<NoErr>> {
            Ok((text.len() as u32 * 7, 12))
        }
        fn blit_bitmap(
            &mut self,
            pos: BackendCoord,
            size: (u32, u32),
            src: &[u8],
        ) -> std::result::Result<(), DrawingErrorKind<NoErr>> {
            self.put(format!("blit {pos:?} {size:?} {} bytes", src.len()));
            Ok(())
        }
    }

    /// Renders `v` on a [`Tape`] and returns the tape.
    fn tape(v: &Value, w: u32, h: u32) -> String {
        let s = Spec::from_json(v).expect("valid spec");
        let area = Tape {
            w,
            h,
            log: String::new(),
        }
        .into_drawing_area();
        render(&s, &area).expect("renders");
        TAPE.with(|t| t.take())
    }

    /// The whole drawing of two representative plots, call by call, against a tape recorded
    /// from the code before the plot module was split into files (`render_golden.txt`). The
    /// plots have no log axis (the module has none). Time plot: two labelled series (one
    /// dense enough to be decimated, solid; one dashed with a gap and a point outside the
    /// fixed y range), a faint dotted unlabelled series, two vertical markers (one outside the
    /// range), a point marker, title, captions and legend. Nyquist plot at dpr 2: the loop with
    /// an integrator's far branch, the Ms circle in the legend, the critical point, equal aspect.
    #[wasm_bindgen_test(unsupported = test)]
    fn full_drawing_matches_the_golden_tape() {
        let t: Vec<f64> = (0..600).map(|i| f64::from(i) * 0.05).collect();
        let y: Vec<f64> = t
            .iter()
            .map(|v| 1.0 - (-v / 4.0).exp() * (2.0 * v).cos())
            .collect();
        let u: Vec<Value> = t
            .iter()
            .step_by(20)
            .enumerate()
            .map(|(i, v)| {
                if i == 7 {
                    Value::Null
                } else if i == 20 {
                    json!(3.5)
                } else {
                    json!(0.5 + 0.3 * (v / 3.0).sin())
                }
            })
            .collect();
        let tu: Vec<f64> = t.iter().step_by(20).copied().collect();
        let time = json!({"canvas": "c", "title": "Set-point response", "xlabel": "t",
            "ylabel": "y", "yrange": [-0.2, 1.8],
            "series": [
                {"label": "y (PID)", "x": t, "y": y},
                {"label": "u / 10", "x": tu, "y": u, "dash": "dash", "color": "#009E73"},
                {"x": [0, 10, 20, 30], "y": [0, 1, 1, 1], "dash": "dot", "faint": true}],
            "vlines": [{"x": 12.5, "label": "load step"}, {"x": 99}],
            "points": [{"x": 20, "y": 1, "label": "settled", "color": "#CC79A7"}]});
        let w: Vec<f64> = (1..300).map(|i| 0.01 * 1.03f64.powi(i)).collect();
        // L(jw) = e^{-jw} / (jw (1 + jw)) * 0.6
        let (re, im): (Vec<f64>, Vec<f64>) = w
            .iter()
            .map(|&w| {
                let (c, s) = (w.cos(), -w.sin());
                // 1 / (jw (1 + jw)) = 1 / (-w^2 + jw)
                let (a, b) = (-w * w, w);
                let d = a * a + b * b;
                let (gr, gi) = (0.6 * a / d, -0.6 * b / d);
                (gr * c - gi * s, gr * s + gi * c)
            })
            .unzip();
        let nyquist = json!({"canvas": "c", "kind": "nyquist", "dpr": 2, "title": "Nyquist",
            "xlabel": "Re L", "ylabel": "Im L",
            "series": [{"label": "L(jω)", "x": re, "y": im}],
            "circle": {"cx": -1, "cy": 0, "r": 0.625, "label": "Ms = 1.6"},
            "points": [{"x": -1, "y": 0, "label": "−1"}]});
        let got = format!(
            "# time 420x260\n{}# nyquist 700x500\n{}",
            tape(&time, 420, 260),
            tape(&nyquist, 700, 500)
        );
        // To look at a differing tape: PIDLAB_PLOT_TAPE=/tmp/tape.txt cargo test ... (native).
        if let Ok(path) = std::env::var("PIDLAB_PLOT_TAPE") {
            let _ = std::fs::write(path, &got);
        }
        let want = include_str!("render_golden.txt");
        for (i, (g, w)) in got.lines().zip(want.lines()).enumerate() {
            assert_eq!(g, w, "tape line {}", i + 1);
        }
        assert_eq!(got.lines().count(), want.lines().count(), "tape length");
        assert_eq!(got, want);
    }

    #[wasm_bindgen_test(unsupported = test)]
    fn draw_natively_says_it_needs_a_canvas() {
        let e = draw(&json!({"canvas": "c"})).expect_err("no canvas natively");
        assert_eq!(e.path, "spec.canvas");
        // The JSON-text form is validated the same way.
        let e = draw(&json!("{\"canvas\": \"c\", \"kind\": 3}")).expect_err("bad kind");
        assert_eq!(e.path, "spec.kind");
        let e = draw(&json!("{not json")).expect_err("bad text");
        assert_eq!(e.path, "spec");
    }
}
