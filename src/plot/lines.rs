//! Line geometry: clipping to the plotting box in data coordinates, splitting a series at its
//! gaps, decimation of dense pixel polylines, and dash patterns.

use super::spec::Series;

/// Liang–Barsky clipping of the segment a→b to the box; None when it lies outside.
pub(super) fn clip(
    a: (f64, f64),
    b: (f64, f64),
    bx: (f64, f64, f64, f64),
) -> Option<((f64, f64), (f64, f64))> {
    let (x0, x1, y0, y1) = bx;
    let dx = b.0 - a.0;
    let dy = b.1 - a.1;
    let mut t0 = 0.0f64;
    let mut t1 = 1.0f64;
    for (p, q) in [
        (-dx, a.0 - x0),
        (dx, x1 - a.0),
        (-dy, a.1 - y0),
        (dy, y1 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                if r > t1 {
                    return None;
                }
                t0 = t0.max(r);
            } else {
                if r < t0 {
                    return None;
                }
                t1 = t1.min(r);
            }
        }
    }
    Some((
        (a.0 + t0 * dx, a.1 + t0 * dy),
        (a.0 + t1 * dx, a.1 + t1 * dy),
    ))
}

/// Splits a series into clipped polylines in data coordinates.
pub(super) fn polylines(s: &Series, bx: (f64, f64, f64, f64)) -> Vec<Vec<(f64, f64)>> {
    let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut cur: Vec<(f64, f64)> = Vec::new();
    let mut prev: Option<(f64, f64)> = None;
    for (x, y) in s.x.iter().zip(s.y.iter()) {
        let p = match (x, y) {
            (Some(x), Some(y)) => Some((*x, *y)),
            _ => None,
        };
        match (prev, p) {
            (Some(a), Some(b)) => match clip(a, b, bx) {
                Some((ca, cb)) => {
                    if cur.last() != Some(&ca) {
                        if cur.len() > 1 {
                            out.push(std::mem::take(&mut cur));
                        }
                        cur.clear();
                        cur.push(ca);
                    }
                    cur.push(cb);
                }
                None => {
                    if cur.len() > 1 {
                        out.push(std::mem::take(&mut cur));
                    }
                    cur.clear();
                }
            },
            _ => {
                if cur.len() > 1 {
                    out.push(std::mem::take(&mut cur));
                }
                cur.clear();
            }
        }
        prev = p;
    }
    if cur.len() > 1 {
        out.push(cur);
    }
    out
}

/// Reduces a pixel polyline: consecutive points in the same pixel column collapse to their
/// first, min, max and last (keeps the envelope of a dense time series exactly).
pub(super) fn decimate(px: &[(i32, i32)]) -> Vec<(i32, i32)> {
    let mut out: Vec<(i32, i32)> = Vec::with_capacity(px.len().min(4096));
    let mut i = 0;
    while i < px.len() {
        let Some(&first) = px.get(i) else { break };
        let mut j = i;
        let (mut lo, mut hi, mut last) = (first, first, first);
        while let Some(&p) = px.get(j) {
            if p.0 != first.0 {
                break;
            }
            if p.1 < lo.1 {
                lo = p;
            }
            if p.1 > hi.1 {
                hi = p;
            }
            last = p;
            j += 1;
        }
        for p in [first, lo, hi, last] {
            if out.last() != Some(&p) {
                out.push(p);
            }
        }
        i = j.max(i + 1);
    }
    out
}

/// Cuts a pixel polyline into dash segments (on, off lengths in pixels).
pub(super) fn dashes(px: &[(i32, i32)], on: f64, off: f64) -> Vec<Vec<(i32, i32)>> {
    let mut out = Vec::new();
    let mut cur: Vec<(i32, i32)> = Vec::new();
    let mut drawing = true;
    let mut left = on;
    for w in px.windows(2) {
        let (Some(&a), Some(&b)) = (w.first(), w.get(1)) else {
            continue;
        };
        let (ax, ay) = (f64::from(a.0), f64::from(a.1));
        let (dx, dy) = (f64::from(b.0) - ax, f64::from(b.1) - ay);
        let len = (dx * dx + dy * dy).sqrt();
        let mut pos = 0.0;
        if drawing && cur.is_empty() {
            cur.push(a);
        }
        while len - pos > left {
            pos += left;
            let p = (
                (ax + dx * pos / len).round() as i32,
                (ay + dy * pos / len).round() as i32,
            );
            if drawing {
                cur.push(p);
                out.push(std::mem::take(&mut cur));
                left = off;
            } else {
                cur.push(p);
                left = on;
            }
            drawing = !drawing;
        }
        left -= len - pos;
        if drawing {
            cur.push(b);
        }
    }
    if drawing && cur.len() > 1 {
        out.push(cur);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use wasm_bindgen_test::wasm_bindgen_test;

    #[wasm_bindgen_test(unsupported = test)]
    fn decimation_keeps_the_envelope() {
        let px: Vec<(i32, i32)> = (0..1000)
            .map(|i| (i / 100, if i % 2 == 0 { i % 37 } else { -(i % 41) }))
            .collect();
        let d = decimate(&px);
        assert!(d.len() <= 40);
        for col in 0..10 {
            let orig: Vec<i32> = px.iter().filter(|p| p.0 == col).map(|p| p.1).collect();
            let kept: Vec<i32> = d.iter().filter(|p| p.0 == col).map(|p| p.1).collect();
            assert_eq!(orig.iter().max(), kept.iter().max());
            assert_eq!(orig.iter().min(), kept.iter().min());
        }
    }

    #[wasm_bindgen_test(unsupported = test)]
    fn dashes_cover_half_the_length() {
        let d = dashes(&[(0, 0), (100, 0)], 5.0, 5.0);
        assert_eq!(d.len(), 10);
        let on: i32 = d
            .iter()
            .map(|s| s.last().map_or(0, |l| l.0) - s.first().map_or(0, |f| f.0))
            .sum();
        assert_eq!(on, 50);
    }
}
