//! The legend: its entries, their flow into rows, and their drawing in a band between the
//! title and the plotting box.

use super::color::Rgba;
use super::lines::dashes;
use super::spec::{Dash, Spec};
use super::style::{derr, Style};
use crate::error::Result;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The legend of one plot, flowed into rows.
pub(super) struct Legend {
    /// (label, colour, pattern, width) per entry.
    entries: Vec<(String, Rgba, Dash, f64)>,
    /// (x offset, row) per entry.
    pos: Vec<(i32, i32)>,
    /// Number of rows (0 without entries).
    pub(super) rows: i32,
    /// Height of a row in pixels.
    pub(super) line_h: i32,
    /// Length of the line sample in pixels.
    sample: i32,
}

impl Legend {
    /// The legend of `s` (empty when `s.legend` is false) flowed into rows `avail` pixels wide.
    pub(super) fn new(s: &Spec, st: &Style, avail: i32) -> Legend {
        let entries = if s.legend {
            legend_entries(s)
        } else {
            Vec::new()
        };
        let line_h = (st.small * 1.4).round() as i32;
        let sample = st.px(22.0);
        let (pos, rows) = legend_layout(&entries, avail, sample, st.small, st.k);
        Legend {
            entries,
            pos,
            rows,
            line_h,
            sample,
        }
    }

    /// Draws the entries in the band whose top-left corner is (`left`, `top`), flowing left to
    /// right (never covers the curves). Text width is estimated from the number of characters
    /// (no text measurement, see the module documentation).
    pub(super) fn draw<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        st: &Style,
        left: i32,
        top: i32,
    ) -> Result<()> {
        let (k, line_h, sample) = (st.k, self.line_h, self.sample);
        for (i, (label, color, dash, width)) in self.entries.iter().enumerate() {
            let Some(&(lx, row)) = self.pos.get(i) else {
                break;
            };
            let cy = top + line_h * row + line_h / 2;
            let a = (left + lx, cy);
            let b = (left + lx + sample, cy);
            let ls = color.style().stroke_width(st.px(*width).max(1) as u32);
            let segs = match dash {
                Dash::Solid => vec![vec![a, b]],
                Dash::Dash => dashes(&[a, b], 6.0 * k, 4.0 * k),
                Dash::Dot => dashes(&[a, b], 2.0 * k, 3.0 * k),
            };
            for seg in segs {
                root.draw(&PathElement::new(seg, ls)).map_err(derr)?;
            }
            let ts = (FontFamily::SansSerif, st.small)
                .into_font()
                .color(&st.fg)
                .pos(Pos::new(HPos::Left, VPos::Center));
            root.draw_text(label, &ts, (b.0 + st.px(4.0), cy))
                .map_err(derr)?;
        }
        Ok(())
    }
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
