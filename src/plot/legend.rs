//! The legend: its entries and their flow into rows.

use super::color::Rgba;
use super::spec::{Dash, Spec};

/// The legend entries: labelled series, then the circle.
pub(super) fn legend_entries(s: &Spec) -> Vec<(String, Rgba, Dash, f64)> {
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
pub(super) fn legend_layout(
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
