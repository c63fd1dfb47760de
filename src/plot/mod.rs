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
//!
//! Files: `spec` (the types and `Spec::from_json`), `parse` (field readers naming the path),
//! `color` (`#hex` colours, the palette); `render` (the order of the parts), `style` (sizes
//! scaled by the pixel ratio), `layout` (title, legend band, plotting box), `axes` (ranges,
//! ticks, mesh), `series` (lines and the circle), `marks` (title, zero axes, markers, points),
//! `legend`, `lines` (clipping, decimation, dashes in data and pixel space).

mod axes;
mod color;
mod layout;
mod legend;
mod lines;
mod marks;
mod parse;
#[cfg(test)]
mod recorders;
mod render;
mod series;
mod spec;
mod style;

pub use color::{Rgba, OKABE_ITO};
pub use render::render;
pub use spec::{Circle, Dash, Kind, Point, Series, Spec, VLine};

use crate::error::Result;
use parse::err;
use serde_json::Value;

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
    use plotters::prelude::IntoDrawingArea;
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

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;
    use wasm_bindgen_test::wasm_bindgen_test;

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
