//! Axes: the ranges (automatic from the data, or fixed; equal aspect for Nyquist), tick labels,
//! and the mesh with its captions.

use super::layout::Layout;
use super::spec::{Kind, Spec};
use super::style::{derr, Style};
use crate::error::Result;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;

/// The chart of a plot: f64 data coordinates on both axes.
pub(super) type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Grows the bounds `b` to include `v` when it is finite.
fn widen(b: &mut (f64, f64), v: f64) {
    if v.is_finite() {
        b.0 = b.0.min(v);
        b.1 = b.1.max(v);
    }
}

/// The x and y ranges of the plot before the equal-aspect correction: the fixed ones where
/// given, else automatic from the data.
pub(super) fn data_ranges(s: &Spec) -> ((f64, f64), (f64, f64)) {
    match s.kind {
        Kind::Time => time_ranges(s),
        Kind::Nyquist => nyquist_ranges(s),
    }
}

/// A time plot: x spans the data, y the data within the x range, with a margin.
fn time_ranges(s: &Spec) -> ((f64, f64), (f64, f64)) {
    let mut xb = (f64::INFINITY, f64::NEG_INFINITY);
    let mut yb = (f64::INFINITY, f64::NEG_INFINITY);
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

/// A Nyquist plot: the critical region around −1, the circle and the points.
fn nyquist_ranges(s: &Spec) -> ((f64, f64), (f64, f64)) {
    let mut xb = (f64::INFINITY, f64::NEG_INFINITY);
    let mut yb = (f64::INFINITY, f64::NEG_INFINITY);
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

/// Equal aspect for an automatic Nyquist view on a `pw`×`ph` plotting box: widens the shorter
/// range. Other plots keep their ranges.
pub(super) fn equal_aspect(
    s: &Spec,
    (xr, yr): ((f64, f64), (f64, f64)),
    pw: i32,
    ph: i32,
) -> ((f64, f64), (f64, f64)) {
    if s.kind == Kind::Nyquist && s.xrange.is_none() && s.yrange.is_none() {
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
    }
}

/// Builds the chart on the plotting box of `lay` and draws its mesh: grid, axes, tick labels
/// and the axis captions.
pub(super) fn draw_mesh<'a, DB: DrawingBackend>(
    root: &'a DrawingArea<DB, Shift>,
    s: &Spec,
    st: &Style,
    lay: &Layout,
    (xr, yr): ((f64, f64), (f64, f64)),
) -> Result<Chart<'a, DB>> {
    let (k, small, font, fg) = (st.k, st.small, st.font, st.fg);
    let mut chart = ChartBuilder::on(root)
        .margin_top(lay.top.max(0) as u32)
        .margin_right(lay.right.max(0) as u32)
        .x_label_area_size(lay.bottom.max(0) as u32)
        .y_label_area_size(lay.left.max(0) as u32)
        .build_cartesian_2d(xr.0..xr.1, yr.0..yr.1)
        .map_err(derr)?;
    let nx = (f64::from(lay.pw) / (70.0 * k)).clamp(2.0, 10.0);
    let ny = (f64::from(lay.ph) / (40.0 * k)).clamp(2.0, 10.0);
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
        // FontFamily::SansSerif, not "sans-serif": plotters' From<&str> lowercases the name
        // (str::to_lowercase and Unicode tables in the wasm module, issue 15); the same font
        .label_style((FontFamily::SansSerif, small).into_font().color(&fg))
        .axis_desc_style((FontFamily::SansSerif, font).into_font().color(&fg))
        .x_desc(s.xlabel.as_str())
        .y_desc(s.ylabel.as_str())
        .bold_line_style(RGBAColor(0, 0, 0, 0.12).stroke_width(st.px(1.0).max(1) as u32))
        .light_line_style(RGBAColor(0, 0, 0, 0.0))
        .axis_style(fg.stroke_width(st.px(1.0).max(1) as u32))
        .set_tick_mark_size(LabelAreaPosition::Left, st.px(4.0))
        .set_tick_mark_size(LabelAreaPosition::Bottom, st.px(4.0))
        .draw()
        .map_err(derr)?;
    Ok(chart)
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
