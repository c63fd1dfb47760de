//! Drawing a validated spec on any plotters drawing area: the order of the parts.

use super::axes::{data_ranges, draw_mesh, equal_aspect};
use super::layout::Layout;
use super::marks::{draw_points, draw_title, draw_vlines, draw_zero_axes};
use super::parse::err;
use super::series::{draw_circle, draw_series};
use super::spec::{Kind, Spec};
use super::style::{derr, Style};
use crate::error::Result;
use plotters::coord::Shift;
use plotters::prelude::*;

/// Renders a validated spec on any plotters drawing area.
pub fn render<DB: DrawingBackend>(s: &Spec, root: &DrawingArea<DB, Shift>) -> Result<()> {
    let (w, h) = root.dim_in_pixel();
    if w < 40 || h < 40 {
        return Err(err(
            "spec.canvas",
            format!("canvas too small ({w}×{h} pixels)"),
        ));
    }
    root.fill(&WHITE).map_err(derr)?;
    let st = Style::new(s.dpr);
    let k = st.k;
    let lay = Layout::new(s, &st, w, h);
    let ranges = equal_aspect(s, data_ranges(s), lay.pw, lay.ph);
    let (xr, yr) = ranges;
    draw_title(root, s, &st, lay.left)?;
    let chart = draw_mesh(root, s, &st, &lay, ranges)?;

    let bx = (xr.0, xr.1, yr.0, yr.1);
    let to_px = |p: (f64, f64)| chart.backend_coord(&p);
    if s.kind == Kind::Nyquist {
        draw_zero_axes(root, &st, ranges, &to_px)?;
    }
    draw_vlines(root, s, &st, ranges, &to_px)?;
    if let Some(c) = &s.circle {
        draw_circle(root, c, bx, &to_px, k)?;
    }
    // Faint series first, so the emphasised ones lie on top.
    for sr in s.series.iter().filter(|x| x.faint) {
        draw_series(root, sr, bx, &to_px, k, s.kind == Kind::Time)?;
    }
    for sr in s.series.iter().filter(|x| !x.faint) {
        draw_series(root, sr, bx, &to_px, k, s.kind == Kind::Time)?;
    }
    draw_points(root, s, &st, ranges, &to_px)?;
    lay.legend.draw(root, &st, lay.left, lay.legend_top)?;
    root.present().map_err(derr)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::super::lines::clip;
    use super::super::recorders::{rec, Recorder, Tape, LOG, TAPE};
    use super::*;
    use serde_json::{json, Value};
    use wasm_bindgen_test::wasm_bindgen_test;

    fn render_json(v: &Value, w: u32, h: u32) -> Result<Recorder> {
        let s = Spec::from_json(v)?;
        let area = rec(w, h).into_drawing_area();
        render(&s, &area)?;
        Ok(LOG.with(|l| l.take()).unwrap_or_else(|| rec(w, h)))
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
}
