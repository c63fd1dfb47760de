//! Axes: automatic ranges and tick labels.

/// Automatic axis bounds with a margin; never degenerate.
pub(super) fn pad_range(lo: f64, hi: f64, frac: f64) -> (f64, f64) {
    if !(lo.is_finite() && hi.is_finite()) || lo > hi {
        return (0.0, 1.0);
    }
    let span = hi - lo;
    if span <= 1e-12 * lo.abs().max(hi.abs()).max(1e-300) {
        let d = if lo.abs() > 0.0 { 0.1 * lo.abs() } else { 1.0 };
        return (lo - d, hi + d);
    }
    (lo - frac * span, hi + frac * span)
}

/// Chooses a tick label precision for the range.
pub(super) fn decimals(lo: f64, hi: f64, nticks: f64) -> usize {
    let step = (hi - lo).abs() / nticks.max(1.0);
    if !(step.is_finite() && step > 0.0) {
        return 2;
    }
    let d = -(step.log10().floor());
    d.clamp(0.0, 8.0) as usize
}

pub(super) fn fmt_tick(v: f64, dec: usize) -> String {
    let s = format!("{v:.dec$}");
    // avoid "-0" / "-0.00"
    if s.trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        s.trim_start_matches('-').to_string()
    } else {
        s
    }
}
