//! Drawing a validated spec on any plotters drawing area.

use super::axes::{decimals, fmt_tick, pad_range};
use super::color::Rgba;
use super::legend::{legend_entries, legend_layout};
use super::lines::{clip, dashes, decimate, polylines};
use super::parse::err;
use super::spec::{Dash, Kind, Series, Spec};
use crate::error::{Error, Result};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

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
