//! Reference marks: the zero axes of the Nyquist plane, vertical marker lines, marked points,
//! and the title.

use super::color::Rgba;
use super::lines::{clip, dashes};
use super::spec::Spec;
use super::style::{derr, Style};
use crate::error::Result;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The title above the legend band, at `left`.
pub(super) fn draw_title<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    s: &Spec,
    st: &Style,
    left: i32,
) -> Result<()> {
    if !s.title.is_empty() {
        let ts = (FontFamily::SansSerif, st.font)
            .into_font()
            .style(FontStyle::Bold)
            .color(&st.fg)
            .pos(Pos::new(HPos::Left, VPos::Top));
        root.draw_text(&s.title, &ts, (left, st.px(6.0)))
            .map_err(derr)?;
    }
    Ok(())
}

/// The real and imaginary axes of the Nyquist plane, clipped to the ranges `xr`, `yr`.
pub(super) fn draw_zero_axes<DB: DrawingBackend, F: Fn((f64, f64)) -> (i32, i32)>(
    root: &DrawingArea<DB, Shift>,
    st: &Style,
    (xr, yr): ((f64, f64), (f64, f64)),
    to_px: &F,
) -> Result<()> {
    let bx = (xr.0, xr.1, yr.0, yr.1);
    let ax = RGBAColor(0, 0, 0, 0.35).stroke_width(st.px(1.0).max(1) as u32);
    for seg in [((xr.0, 0.0), (xr.1, 0.0)), ((0.0, yr.0), (0.0, yr.1))] {
        if let Some((a, b)) = clip(seg.0, seg.1, bx) {
            root.draw(&PathElement::new(vec![to_px(a), to_px(b)], ax))
                .map_err(derr)?;
        }
    }
    Ok(())
}

/// The vertical markers within the x range, dashed, with their labels at the top.
pub(super) fn draw_vlines<DB: DrawingBackend, F: Fn((f64, f64)) -> (i32, i32)>(
    root: &DrawingArea<DB, Shift>,
    s: &Spec,
    st: &Style,
    (xr, yr): ((f64, f64), (f64, f64)),
    to_px: &F,
) -> Result<()> {
    let k = st.k;
    for v in &s.vlines {
        if v.x >= xr.0 && v.x <= xr.1 {
            let a = to_px((v.x, yr.0));
            let b = to_px((v.x, yr.1));
            let ls = v.color.style().stroke_width(st.px(1.0).max(1) as u32);
            for d in dashes(&[a, b], 4.0 * k, 4.0 * k) {
                root.draw(&PathElement::new(d, ls)).map_err(derr)?;
            }
            let at = (b.0 + st.px(3.0), b.1 + st.px(2.0));
            draw_label(root, st, &v.label, v.color, VPos::Top, at)?;
        }
    }
    Ok(())
}

/// The marked points within the ranges: a cross with its label above right.
pub(super) fn draw_points<DB: DrawingBackend, F: Fn((f64, f64)) -> (i32, i32)>(
    root: &DrawingArea<DB, Shift>,
    s: &Spec,
    st: &Style,
    (xr, yr): ((f64, f64), (f64, f64)),
    to_px: &F,
) -> Result<()> {
    for p in &s.points {
        if p.x >= xr.0 && p.x <= xr.1 && p.y >= yr.0 && p.y <= yr.1 {
            let c = to_px((p.x, p.y));
            let ls = p.color.style().stroke_width(st.px(2.0).max(1) as u32);
            let r = st.px(5.0);
            root.draw(&PathElement::new(vec![(c.0 - r, c.1), (c.0 + r, c.1)], ls))
                .map_err(derr)?;
            root.draw(&PathElement::new(vec![(c.0, c.1 - r), (c.0, c.1 + r)], ls))
                .map_err(derr)?;
            let at = (c.0 + r, c.1 - r);
            draw_label(root, st, &p.label, p.color, VPos::Bottom, at)?;
        }
    }
    Ok(())
}

/// A mark's label, if any, in the small font and the mark's colour, left-aligned at `at` with
/// the vertical anchor `v`.
fn draw_label<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    st: &Style,
    label: &str,
    color: Rgba,
    v: VPos,
    at: (i32, i32),
) -> Result<()> {
    if !label.is_empty() {
        let ts = (FontFamily::SansSerif, st.small)
            .into_font()
            .color(&color.style())
            .pos(Pos::new(HPos::Left, v));
        root.draw_text(label, &ts, at).map_err(derr)?;
    }
    Ok(())
}
