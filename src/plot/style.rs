//! What every part of a drawing shares: sizes scaled by the device pixel ratio, the text colour,
//! and the conversion of plotters' drawing errors.

use super::parse::err;
use crate::error::Error;
use plotters::prelude::*;

/// Sizes and colours scaled for one spec's device pixel ratio.
pub(super) struct Style {
    /// Device pixel ratio.
    pub(super) k: f64,
    /// Title and axis caption font size.
    pub(super) font: f64,
    /// Tick label, legend and marker label font size.
    pub(super) small: f64,
    /// Text and axis colour.
    pub(super) fg: RGBColor,
}

impl Style {
    pub(super) fn new(dpr: f64) -> Style {
        Style {
            k: dpr,
            font: (13.0 * dpr).max(6.0),
            small: (11.0 * dpr).max(5.0),
            fg: RGBColor(0x22, 0x22, 0x22),
        }
    }

    /// A length in CSS pixels as device pixels.
    pub(super) fn px(&self, v: f64) -> i32 {
        (v * self.k).round() as i32
    }
}

pub(super) fn derr<E: std::error::Error + Send + Sync>(e: DrawingAreaErrorKind<E>) -> Error {
    err("spec.canvas", format!("drawing failed: {e}"))
}
