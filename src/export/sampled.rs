//! What the two sampled targets ([`super::c`], [`super::st`]) share: the header lines of the
//! sampled controller and its coefficient tables, read from the one
//! [`DiscreteController`] pidlab's own sampled loop steps (never a second discretisation).
//!
//! Both files transliterate [`DiscreteController::step`] statement by statement, in the same
//! order of floating-point operations, so they give its `u_k`:
//!
//! ```text
//! push r_k, y_k into the histories (newest first)
//! Linear:  c = Σ_i (b_r[i] r[i] − b_y[i] y[i]) + Σ_{i≥1} (b_u[i] u[i−1] − a[i] v[i−1])
//!          v = c                         (b_u[0] = 0)
//!          v = c/(1 − b_u[0]), or c + b_u[0]·limit when that is beyond the limit (tracking)
//! Clamped: e = g_r r − g_y y; dx = c0 e + c1 e_prev; e_prev = e
//!          vr = c of the rest; push vr into v; v = x + dx + vr
//!          x += dx unless v is beyond a limit and dx pushes it further; v = x + vr
//! u = sat(v); (Linear) push v; push u
//! ```

use super::num;
use crate::model::discrete::{AntiWindup, DiffEq, DiscreteController, Law};

/// Header lines describing the sampled controller.
pub fn header(dc: &DiscreteController) -> Vec<String> {
    let lim = |x: f64| if x.is_finite() { num(x) } else { "none".into() };
    let aw = match dc.anti_windup {
        AntiWindup::None => "none".to_string(),
        AntiWindup::Tracking { tt } => format!(
            "tracking (back-calculation), tt = {}",
            tt.map(num).unwrap_or_else(|| "default".into())
        ),
        AntiWindup::Conditional => "conditional integration (clamping)".into(),
    };
    vec![
        format!(
            "Sampled: h = {} (plant time unit), discretisation {}, from pidlab's difference equations",
            num(dc.h),
            dc.method.name()
        ),
        format!(
            "Actuator limits: u_min = {}, u_max = {}; anti-windup: {aw}",
            lim(dc.limits.u_min),
            lim(dc.limits.u_max)
        ),
        "Call once per sample: read r_k and y_k at t_k = k*h, apply u_k until t_(k+1).".into(),
    ]
}

/// The arrays of a difference equation, named as in the files: `(name, coefficients)`.
pub fn tables(eq: &DiffEq) -> [(&'static str, &[f64]); 4] {
    [
        ("a", &eq.a),
        ("b_r", &eq.b_r),
        ("b_y", &eq.b_y),
        ("b_u", &eq.b_u),
    ]
}

/// The difference equation with the histories (the linear law or the clamped law's rest).
pub fn diff_eq(dc: &DiscreteController) -> &DiffEq {
    match &dc.law {
        Law::Linear(eq) => eq,
        Law::Clamped { rest, .. } => rest,
    }
}
