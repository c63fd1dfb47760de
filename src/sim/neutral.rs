//! The accuracy check of a neutral loop whose internal step the piece limit caps (module docs
//! of [`crate::sim`], "Near the neutral limit"; shared by the one-delay, several-delay and
//! saturating integrators).
//!
//! On a neutral loop (`0 < |E| < 1`) the step rule asks `h ≤ 0.6·θ·(1 − |E|)`: below it the
//! interpolation error injected on each piece, which returns every θ multiplied by `E`, could
//! be amplified by the scheme on the barely damped chain of roots near `Re s = ln|E|/θ`. Over a
//! long window on a loop very close to the limit that step needs more pieces than the limit
//! allows, and the step is then capped by that limit (`single::neutral_bound`). Such a run is
//! often still accurate, but its error then grows exponentially in time (measured on issue 15's plant under
//! Algorithm III at ζ 1.79, |E| = 0.99968, at θ/131 against θ/262, samples every 0.01: 2e-14
//! over [0, 100], 2.9e-12 at 150, 1.2e-10 at 350, 3.9e-9 at 500 — largest at the jumps of u,
//! `t_load + kθ`; at θ/66, 3.4e-4 by t = 1000), not as `h⁸`, so no Richardson factor bounds it.
//! A capped run is therefore checked against a second run at about twice the step
//! (`span/⌊N/2⌋` for `h = span/N`, so the delay still maps steps onto steps): the largest
//! difference of y and u, relative to their largest magnitude, is taken as the capped run's
//! error — an upper bound whenever the finer run is at most half as wrong as the coarser one,
//! which both regimes give (`O(h⁸)`: 1/256; exponential growth: a rate that rises with h) and
//! 256 times too cautious in the first. Above [`CHECK_TOL`] the one-delay loop tries once more
//! at the finest step its whole piece limit allows (checked against the first run); what still
//! fails is refused with an error saying so, and the time up to which the two runs agreed
//! within it as the window to try. [`checked`] is that procedure, for every integrator: a capped
//! run is never returned silently inaccurate.

use super::single::capped_need;
use super::trajectory::Trajectory;
use crate::error::{Error, Result};

/// A run at the rule's step `h`, checked when the piece cap set `h` above the neutral rule's
/// step (module docs). `run(h)` integrates at a step and `traj` reads a run's trajectory;
/// `(θ, |E|)` are the loop's delay and neutral gain (its smallest delay and `ρ(|E|)` for several
/// delays), `span` what the grid divides (θ, or t_end without a dead time); `finest(need)` a
/// finer step the integrator's whole piece limit allows (the one-delay loop), tried once when
/// the first check fails, checked against the first run.
pub(crate) fn checked<R>(
    (theta, ae): (f64, f64),
    span: f64,
    h: f64,
    t_end: f64,
    finest: impl FnOnce(f64) -> Option<f64>,
    run: impl Fn(f64) -> Result<R>,
    traj: impl Fn(&R) -> &Trajectory,
) -> Result<R> {
    let first = run(h)?;
    let Some(need) = capped_need(theta, ae, h) else {
        return Ok(first);
    };
    let (hc, ratio) = coarse_step(span, h);
    let coarse = run(hc)?;
    let Err(refused) = verify(traj(&first), traj(&coarse), ratio, ae, need, t_end) else {
        return Ok(first);
    };
    let Some(hf) = finest(need) else {
        return Err(refused);
    };
    let fine = run(hf)?;
    if capped_need(theta, ae, hf).is_some() {
        verify(traj(&fine), traj(&first), h / hf, ae, need, t_end)?;
    }
    Ok(fine)
}

/// The largest difference between a capped run and its check run that is accepted, relative
/// to the response's largest |y|, |u|: an order above the simulator's stated 1e-10, because on
/// a loop this close to neutral the integrators' own round-off floor reaches 1e-10 (measured
/// on issue 15's plant under Algorithm III at ζ 1.79, |E| = 0.99968: the saturating
/// integrator, limits never reached, at the rule's own step θ/5239 is 3.1e-11 off the linear
/// one over [0, 20], and two of its capped runs, θ/4342 against θ/2171 over t_end = 60, differ
/// by 2.2e-10; linear runs at θ/2171…θ/5239 agree to 2e-12), while a run in the growth regime
/// passes 1e-9 within a few dozen time units of passing 1e-10 (×3 per 50 time units there).
const CHECK_TOL: f64 = 1e-9;

/// The check's coarse step and the ratio of the steps: for `h = span/N`, `span/⌊N/2⌋` (at least
/// one piece per span) and `N/⌊N/2⌋`.
fn coarse_step(span: f64, h: f64) -> (f64, f64) {
    let n = (span / h).round().max(1.0);
    let nc = (n / 2.0).floor().max(1.0);
    (span / nc, n / nc)
}

/// `d/m` with `0/0 = 0` (a signal identically zero in both runs).
fn rel(d: f64, m: f64) -> f64 {
    if d == 0.0 {
        0.0
    } else {
        d / m
    }
}

/// The capped run's error bound and the time up to which it held: y and u of both runs
/// compared at the midpoint of every piece of the coarse run (inside pieces, so both read the
/// same side of the jumps on their boundaries) up to the earlier of their ends; the largest
/// differences relative to the fine run's largest |y|, |u| there. Returns the bound and the last
/// check time at which the differences so far were still within [`CHECK_TOL`] of those
/// magnitudes (`None` if they always were).
fn estimate(fine: &Trajectory, coarse: &Trajectory) -> (f64, Option<f64>) {
    let end = fine.end().min(coarse.end());
    let (mut ym, mut um, mut dy, mut du) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    // the running largest differences, recorded where they grow: (time before, dy, du)
    let mut grow: Vec<(f64, f64, f64)> = Vec::new();
    let mut t_prev = 0.0;
    for k in 0..coarse.n_pieces {
        let (t0, len) = coarse.piece(k);
        let t = t0 + 0.5 * len;
        if t > end {
            break;
        }
        let (yf, uf) = fine.y_u_at(t);
        let (yc, uc) = coarse.y_u_at(t);
        ym = ym.max(yf.abs());
        um = um.max(uf.abs());
        let (ey, eu) = ((yf - yc).abs(), (uf - uc).abs());
        // a NaN difference (a run that left the numbers) fails the check
        if ey > dy || eu > du || ey.is_nan() || eu.is_nan() {
            dy = if ey.is_nan() {
                f64::INFINITY
            } else {
                dy.max(ey)
            };
            du = if eu.is_nan() {
                f64::INFINITY
            } else {
                du.max(eu)
            };
            grow.push((t_prev, dy, du));
        }
        t_prev = t;
    }
    let e = rel(dy, ym).max(rel(du, um));
    let first_bad = grow
        .iter()
        .find(|&&(_, y, u)| rel(y, ym).max(rel(u, um)) > CHECK_TOL)
        .map(|g| g.0);
    (e, first_bad)
}

/// Refuses a capped run whose error bound ([`estimate`]) is above [`CHECK_TOL`]; `ae` is `|E|`,
/// `need` the step the neutral rule asked for, `ratio` the coarse run's step over the fine's.
fn verify(
    fine: &Trajectory,
    coarse: &Trajectory,
    ratio: f64,
    ae: f64,
    need: f64,
    t_end: f64,
) -> Result<()> {
    let (est, first_bad) = estimate(fine, coarse);
    if est <= CHECK_TOL {
        return Ok(());
    }
    let h = fine.h;
    // where the two runs parted (against the whole run's magnitudes): guidance for the window
    // to try, not a promise (a shorter window is run at a shorter step, but its magnitudes are
    // its own)
    let hint = match first_bad {
        Some(t) if t > 0.0 => {
            // two significant digits, rounded down
            let e = t.log10().floor() as i32;
            let q = 10f64.powi(e - 1);
            let dec = (1 - e).max(0) as usize;
            format!(
                " (the two runs agree within 1e-9 up to t ≈ {:.*})",
                dec,
                (t / q).floor() * q
            )
        }
        _ => String::new(),
    };
    Err(Error::new(
        "scenario.t_end",
        format!(
            "this loop is nearly neutral (|L(j∞)| = {ae:.6}): 1e-10 needs an internal step of \
             {need:.3e}, more pieces over t_end = {t_end} than the limit allows; at the step the \
             limit allows, {h:.3e}, the response is not accurate (it differs by {est:.1e} \
             of its largest value from a second run at {ratio:.3} times that step): shorten \
             t_end{hint}"
        ),
    ))
}

#[cfg(test)]
mod tests {
    use super::coarse_step;
    use wasm_bindgen_test::wasm_bindgen_test;

    #[wasm_bindgen_test(unsupported = test)]
    fn the_coarse_step_divides_the_span() {
        // h = θ/7 → θ/3 (ratio 7/3); θ/8 → θ/4 (2); θ/1 → θ/1 (1: no coarser divisor)
        let th = 0.521;
        for (n, nc) in [(7.0, 3.0), (8.0, 4.0), (261.0, 130.0), (1.0, 1.0)] {
            let (hc, r) = coarse_step(th, th / n);
            assert_eq!(hc, th / nc);
            assert_eq!(r, n / nc);
        }
    }
}
