//! Drawing the lines of a plot: a series (clipped, decimated when dense, dashed) and the circle.

use super::color::Rgba;
use super::lines::{dashes, decimate, polylines};
use super::spec::{Circle, Dash, Series};
use super::style::derr;
use crate::error::Result;
use plotters::coord::Shift;
use plotters::prelude::{Color, DrawingArea, DrawingBackend, PathElement};

/// Draws a series clipped to the box `bx` = (x0, x1, y0, y1); `to_px` maps data to pixels, `k`
/// is the device pixel ratio, and `dense` asks for decimation (time plots).
pub(super) fn draw_series<DB: DrawingBackend, F: Fn((f64, f64)) -> (i32, i32)>(
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

/// Draws the circle `c` as a dashed polygon through the clipper.
pub(super) fn draw_circle<DB: DrawingBackend, F: Fn((f64, f64)) -> (i32, i32)>(
    root: &DrawingArea<DB, Shift>,
    c: &Circle,
    bx: (f64, f64, f64, f64),
    to_px: &F,
    k: f64,
) -> Result<()> {
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
    draw_series(root, &cs, bx, to_px, k, false)
}
