//! The layout of a plot on its canvas: the title line, the legend band under it, and the
//! plotting box with the tick label areas.

use super::legend::Legend;
use super::spec::Spec;
use super::style::Style;

/// Where the parts of a plot go, in device pixels.
pub(super) struct Layout {
    /// Width of the y tick label area (left margin of the plotting box).
    pub(super) left: i32,
    /// Right margin.
    pub(super) right: i32,
    /// Top of the plotting box (under the title and the legend band).
    pub(super) top: i32,
    /// Height of the x tick label area.
    pub(super) bottom: i32,
    /// Plotting box width (at least 10).
    pub(super) pw: i32,
    /// Plotting box height (at least 10).
    pub(super) ph: i32,
    /// Top of the legend band.
    pub(super) legend_top: i32,
    /// The legend, flowed into rows.
    pub(super) legend: Legend,
}

impl Layout {
    /// The layout of `s` on a `w`×`h` canvas.
    pub(super) fn new(s: &Spec, st: &Style, w: u32, h: u32) -> Layout {
        let left = st.px(58.0);
        let right = st.px(12.0);
        let legend = Legend::new(s, st, (w as i32 - left - right).max(10));
        let title_h = if s.title.is_empty() {
            0
        } else {
            (st.font * 1.5).round() as i32
        };
        let legend_top = st.px(6.0) + title_h;
        let top = legend_top + legend.line_h * legend.rows + st.px(6.0);
        let bottom = st.px(44.0);
        let pw = (w as i32 - left - right).max(10);
        let ph = (h as i32 - top - bottom).max(10);
        Layout {
            left,
            right,
            top,
            bottom,
            pw,
            ph,
            legend_top,
            legend,
        }
    }
}
