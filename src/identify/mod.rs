//! Identification of a plant family from an open-loop test: `t`, the input `u` (held between
//! samples, any shape) and the measured output `y`, both at rest at `t[0]`.
//!
//! The model is `y(t) = c + k·g(t; φ)`: `g` the exact held-input response of the family's
//! rational part with unit gain, delayed by θ ([`response::held_response`]: the delay is a
//! real parameter, not rounded to the grid), `c` the output's resting value (estimated), `k`
//! the gain, `φ` the nonlinear parameters (τ, τ_z or z, θ). For a given φ the best `k` and `c`
//! are linear least squares, so the Levenberg–Marquardt fit runs on φ alone (variable
//! projection, Golub–Pereyra); the starting φ is the best of a grid scored by the same exact
//! simulation (dead time from the first output movement above the noise, time constants on a
//! log grid over the test's span), which works for any input shape and any noise level where
//! tangent or area rules need a clean step. Approximate 95 % confidence intervals come from the
//! Jacobian of all the parameters (k and c included) at the optimum, `σ²(JᵀJ)⁻¹`.
//! `"auto"` fits several families and ranks them by AICc (Hurvich–Tsai:
//! `N ln(SSR/N) + 2p + 2p(p+1)/(N−p−1)`, p = the family's parameters plus the offset).

pub mod lm;
pub mod response;

use crate::error::{Error, Result};
use crate::model::plant::Family;
use crate::model::poly::Poly;
use crate::model::tf::Tf;
use nalgebra::DMatrix;

/// Fewest samples accepted.
pub const MIN_SAMPLES: usize = 10;
/// Most samples accepted (the wasm boundary takes at most 100,000 values in one input, three
/// arrays of 30,000 samples fit; decimate longer logs).
pub const MAX_SAMPLES: usize = 30_000;
/// The families that can be fitted, in the order `"auto"` tries them (the simplest first, so
/// an exact tie keeps the simpler one).
pub const FAMILIES: [&str; 6] = [
    "piptd",
    "diptd",
    "ifoptd",
    "fopdt_ir",
    "ipdt_ir",
    "ifoptd_zero",
];
/// Default iteration limit of the Levenberg–Marquardt fit.
pub const MAX_ITER: usize = 100;
/// Two-sided 95 % normal quantile (the intervals are approximate: linearised, N ≫ p).
const Z95: f64 = 1.959_963_984_540_054;

/// A validated test record.
#[derive(Debug, Clone)]
pub struct Data {
    /// Sample times (strictly increasing).
    pub t: Vec<f64>,
    /// Input deviations from `u[0]`.
    pub du: Vec<f64>,
    /// Measured output.
    pub y: Vec<f64>,
    /// The input's resting value `u[0]`.
    pub u0: f64,
}

impl Data {
    /// Validates a test: same lengths, finite values, `t` strictly increasing, between
    /// [`MIN_SAMPLES`] and [`MAX_SAMPLES`] samples, an input that moves after `t[0]` and an
    /// output that is not constant. Errors name the field (`t`, `u[3]`, …).
    pub fn new(t: Vec<f64>, u: Vec<f64>, y: Vec<f64>) -> Result<Data> {
        let n = t.len();
        if n < MIN_SAMPLES {
            return Err(Error::new(
                "t",
                format!("at least {MIN_SAMPLES} samples are needed (got {n})"),
            ));
        }
        if n > MAX_SAMPLES {
            return Err(Error::new(
                "t",
                format!("at most {MAX_SAMPLES} samples are accepted (got {n}): decimate the log"),
            ));
        }
        for (name, v) in [("u", &u), ("y", &y)] {
            if v.len() != n {
                return Err(Error::new(
                    name,
                    format!("must have as many samples as t ({n}), got {}", v.len()),
                ));
            }
        }
        for (name, v) in [("t", &t), ("u", &u), ("y", &y)] {
            if let Some(i) = v.iter().position(|x| !x.is_finite()) {
                return Err(Error::new(
                    format!("{name}[{i}]"),
                    format!("must be a finite number (got {})", v[i]),
                ));
            }
        }
        if let Some(i) = (1..n).find(|&i| t[i] <= t[i - 1]) {
            return Err(Error::new(
                format!("t[{i}]"),
                format!(
                    "times must be strictly increasing (t[{i}] = {} after t[{}] = {})",
                    t[i],
                    i - 1,
                    t[i - 1]
                ),
            ));
        }
        let u0 = u[0];
        let du: Vec<f64> = u.iter().map(|x| x - u0).collect();
        match du.iter().position(|x| *x != 0.0) {
            None => {
                return Err(Error::new(
                    "u",
                    "is constant: the test must move the input (a step, pulse, doublet or PRBS)",
                ))
            }
            Some(i) if i == n - 1 => {
                return Err(Error::new(
                    "u",
                    "moves only at the last sample: no response to it is recorded",
                ))
            }
            _ => {}
        }
        if y.iter().all(|x| *x == y[0]) {
            return Err(Error::new(
                "y",
                "is constant: the output does not respond to the input",
            ));
        }
        Ok(Data { t, du, y, u0 })
    }

    /// Index of the first input change.
    fn first_move(&self) -> usize {
        self.du.iter().position(|x| *x != 0.0).unwrap_or(0)
    }
}

/// What was fitted and how well.
#[derive(Debug, Clone)]
pub struct Fit {
    /// The fitted plant (parameters in [`Family::param_names`] order).
    pub family: Family,
    /// The output's resting value `c` (the model is `c + P·(u − u0)`).
    pub offset: f64,
    /// The input's resting value `u[0]`.
    pub u0: f64,
    /// Root-mean-square residual.
    pub rmse: f64,
    /// The model's output at the sample times (absolute: offset included).
    pub y_fit: Vec<f64>,
    /// Approximate 95 % intervals: `(name, Some([lo, hi]))`, `None` when not identifiable; the
    /// family's parameters in order, then `offset`.
    pub ci: Vec<(String, Option<[f64; 2]>)>,
    /// AICc of the fit.
    pub aicc: f64,
    /// Parameters estimated (the family's plus the offset).
    pub n_params: usize,
    /// Levenberg–Marquardt iterations of the retained start.
    pub iterations: usize,
    /// Noise level estimated from the data alone (second differences, median absolute
    /// deviation), for comparison with `rmse`.
    pub noise: f64,
    /// What the data could not pin down.
    pub warnings: Vec<String>,
}

/// The nonlinear part of a family: which parameters, their bounds and the unit-gain model.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Kind {
    FopdtIr,
    IpdtIr,
    Ifoptd,
    Piptd,
    IfoptdZero,
    Diptd,
}

impl Kind {
    fn from_id(id: &str) -> Option<Kind> {
        Some(match id {
            "fopdt_ir" => Kind::FopdtIr,
            "ipdt_ir" => Kind::IpdtIr,
            "ifoptd" => Kind::Ifoptd,
            "piptd" => Kind::Piptd,
            "ifoptd_zero" => Kind::IfoptdZero,
            "diptd" => Kind::Diptd,
            _ => return None,
        })
    }

    fn id(self) -> &'static str {
        match self {
            Kind::FopdtIr => "fopdt_ir",
            Kind::IpdtIr => "ipdt_ir",
            Kind::Ifoptd => "ifoptd",
            Kind::Piptd => "piptd",
            Kind::IfoptdZero => "ifoptd_zero",
            Kind::Diptd => "diptd",
        }
    }

    /// The nonlinear parameters (family names), in the family's order after `k`.
    fn names(self) -> &'static [&'static str] {
        &Family::param_names(self.id()).unwrap_or(&[])[1..]
    }

    /// The unit-gain rational part at natural parameter values (same order as `names`).
    fn unit_tf(self, v: &[f64]) -> Tf {
        let s = Poly::s();
        let (num, den) = match self {
            Kind::FopdtIr => (Poly::linear(-v[1], 1.0), Poly::linear(v[0], 1.0)),
            Kind::IpdtIr => (Poly::linear(-v[1], 1.0), s.mul(&Poly::linear(v[0], 1.0))),
            Kind::Ifoptd => (Poly::constant(1.0), s.mul(&Poly::linear(v[0], 1.0))),
            Kind::IfoptdZero => (Poly::linear(v[1], 1.0), s.mul(&Poly::linear(v[0], 1.0))),
            Kind::Piptd => (Poly::constant(1.0), s.clone()),
            Kind::Diptd => (Poly::constant(1.0), s.mul(&s)),
        };
        Tf { num, den }
    }
}

/// Scales of the test: span after the first input change, first-move delay, noise.
struct Scales {
    /// `t_end − t_u` (t_u: the first input change).
    span: f64,
    /// Time from the first input change to the first output movement above the noise.
    first_move: f64,
    /// Noise standard deviation estimated from second differences.
    noise: f64,
}

fn scales(d: &Data) -> Scales {
    let n = d.t.len();
    let j0 = d.first_move();
    let tu = d.t[j0];
    let span = d.t[n - 1] - tu;
    // σ from second differences: for white noise Δ²y has variance 6σ²; the median absolute
    // deviation (/0.6745) ignores the few large ones at the input's switches
    let mut d2: Vec<f64> = (2..n)
        .map(|i| (d.y[i] - 2.0 * d.y[i - 1] + d.y[i - 2]).abs())
        .collect();
    crate::numerics::sort_f64(&mut d2);
    let noise = if d2.is_empty() {
        0.0
    } else {
        d2[d2.len() / 2] / 0.6745 / 6f64.sqrt()
    };
    let y0 = d.y[..j0.max(1)].iter().sum::<f64>() / j0.max(1) as f64;
    let range = d.y.iter().map(|y| (y - y0).abs()).fold(0.0, f64::max);
    let thr = (4.0 * noise).max(0.03 * range);
    let first_move = (j0..n)
        .find(|&i| (d.y[i] - y0).abs() > thr)
        .map_or(span, |i| d.t[i] - tu);
    Scales {
        span,
        first_move,
        noise,
    }
}

/// The nonlinear parameters as the optimiser sees them: `ln τ` (τ > 0 on a log scale), the
/// others as they are, each in a box.
struct Space {
    kind: Kind,
    lo: Vec<f64>,
    hi: Vec<f64>,
    scale: Vec<f64>,
}

impl Space {
    fn new(kind: Kind, sc: &Scales, dt_min: f64) -> Space {
        let (mut lo, mut hi, mut scale) = (vec![], vec![], vec![]);
        for n in kind.names() {
            let (l, h, s) = match *n {
                // τ from well below the sampling interval to far beyond the test
                "tau" => ((1e-3 * dt_min).ln(), (100.0 * sc.span).ln(), 1.0),
                "tau_z" => (0.0, 20.0 * sc.span, 1e-2 * sc.span),
                "z" => (-20.0 * sc.span, 20.0 * sc.span, 1e-2 * sc.span),
                // the response to the first input change must start inside the record
                _ => (0.0, sc.span, 1e-2 * sc.span),
            };
            lo.push(l);
            hi.push(h);
            scale.push(s);
        }
        Space {
            kind,
            lo,
            hi,
            scale,
        }
    }

    fn natural(&self, x: &[f64]) -> Vec<f64> {
        self.kind
            .names()
            .iter()
            .zip(x)
            .map(|(n, v)| if *n == "tau" { v.exp() } else { *v })
            .collect()
    }
}

/// The unit-gain response at natural parameters (θ last).
fn unit_response(kind: Kind, d: &Data, nat: &[f64]) -> Result<Vec<f64>> {
    let theta = *nat.last().unwrap_or(&0.0);
    response::held_response(&kind.unit_tf(nat), theta, &d.t, &d.du)
}

/// Best `k`, `c` for a unit response `g` (linear least squares) and the residual `y − c − k g`.
fn project(g: &[f64], y: &[f64]) -> (f64, f64, Vec<f64>) {
    let n = g.len() as f64;
    let (gm, ym) = (g.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let (mut sgg, mut sgy) = (0.0, 0.0);
    for (gi, yi) in g.iter().zip(y) {
        sgg += (gi - gm) * (gi - gm);
        sgy += (gi - gm) * (yi - ym);
    }
    let k = if sgg > 0.0 { sgy / sgg } else { 0.0 };
    let c = ym - k * gm;
    let r = g.iter().zip(y).map(|(gi, yi)| yi - c - k * gi).collect();
    (k, c, r)
}

fn sq(r: &[f64]) -> f64 {
    r.iter().map(|v| v * v).sum()
}

/// Starting points: every combination of a log grid of τ over the test, fractions of the
/// first-move delay for θ, and zero sizes relative to τ, scored by the projected cost.
fn grid(sp: &Space, sc: &Scales, dt_min: f64) -> Vec<Vec<f64>> {
    let lo_tau = (sc.span / 300.0).max(0.5 * dt_min).min(sc.span);
    let taus: Vec<f64> = (0..8)
        .map(|i| lo_tau * (sc.span / lo_tau).powf(i as f64 / 7.0))
        .collect();
    let mut thetas: Vec<f64> = [0.0, 0.3, 0.6, 0.9]
        .iter()
        .map(|f| f * sc.first_move)
        .collect();
    if sp.kind == Kind::Piptd || sp.kind == Kind::Diptd {
        thetas = (0..12).map(|i| i as f64 / 10.0 * sc.first_move).collect();
    }
    let mut out = vec![];
    for &th in &thetas {
        let th = th.min(sc.span);
        match sp.kind {
            Kind::Piptd | Kind::Diptd => out.push(vec![th]),
            Kind::Ifoptd => taus.iter().for_each(|t| out.push(vec![t.ln(), th])),
            Kind::FopdtIr | Kind::IpdtIr => {
                for t in &taus {
                    for f in [0.0, 0.25, 1.0] {
                        out.push(vec![t.ln(), f * t, th]);
                    }
                }
            }
            Kind::IfoptdZero => {
                for t in &taus {
                    for f in [-1.0, -0.25, 0.0, 0.5, 2.0] {
                        out.push(vec![t.ln(), f * t, th]);
                    }
                }
            }
        }
    }
    out
}

/// Fits one family (`id` one of [`FAMILIES`]) to the data.
pub fn fit(d: &Data, id: &str, max_iter: usize) -> Result<Fit> {
    let kind = Kind::from_id(id).ok_or_else(|| {
        Error::new(
            "family",
            format!(
                "'{id}' cannot be identified (one of {}, or auto)",
                FAMILIES.join(", ")
            ),
        )
    })?;
    let sc = scales(d);
    let dt_min =
        d.t.windows(2)
            .map(|w| w[1] - w[0])
            .fold(f64::INFINITY, f64::min);
    let sp = Space::new(kind, &sc, dt_min);
    let cost_at = |x: &[f64]| -> Result<Vec<f64>> {
        let g = unit_response(kind, d, &sp.natural(x))?;
        Ok(project(&g, &d.y).2)
    };
    // the grid's two best starts
    let mut scored: Vec<(f64, Vec<f64>)> = grid(&sp, &sc, dt_min)
        .into_iter()
        .filter_map(|x| cost_at(&x).ok().map(|r| (sq(&r), x)))
        .filter(|(c, _)| c.is_finite())
        .collect();
    crate::numerics::sort_by_f64_key(&mut scored, |s| s.0);
    if scored.is_empty() {
        return Err(Error::new(
            "y",
            "no starting point gives a finite model response",
        ));
    }
    let mut best: Option<lm::LmResult> = None;
    for (_, x0) in scored.iter().take(2) {
        let mut f = |x: &[f64]| cost_at(x);
        let r = lm::minimize(&mut f, x0, &sp.lo, &sp.hi, &sp.scale, max_iter)?;
        if best.as_ref().is_none_or(|b| r.cost < b.cost) {
            best = Some(r);
        }
    }
    let mut best = best.expect("at least one start");
    // fopdt_ir with τ_z > 0 jumps at the dead time: see `jump_piece`
    let mut piece: Option<Piece> = None;
    if kind == Kind::FopdtIr && best.x[1] > 0.0 {
        let (b, p) = jump_piece(d, &sp, best.clone(), &cost_at, max_iter)?;
        if b.cost <= best.cost {
            best = b;
            piece = p;
        }
    }
    let nat = sp.natural(&best.x);
    let g = unit_response(kind, d, &nat)?;
    let (k, c, r) = project(&g, &d.y);
    if k == 0.0 || !k.is_finite() {
        return Err(Error::new(
            "y",
            "the output does not respond to the input (fitted gain 0)",
        ));
    }
    let mut vals = vec![k];
    vals.extend_from_slice(&nat);
    let family = Family::from_params(id, |name| {
        Family::param_names(id)
            .and_then(|ns| ns.iter().position(|n| *n == name))
            .map(|i| vals[i])
    })
    .map_err(|e| Error::new("y", format!("the fit gives an invalid plant ({e})")))?;
    let n = d.t.len();
    let ssr = sq(&r);
    let p = vals.len() + 1;
    let y_fit: Vec<f64> = g.iter().map(|gi| c + k * gi).collect();
    let aicc = aicc(ssr, n, p);
    let mut warnings = vec![];
    if best.iterations >= max_iter {
        warnings.push(format!(
            "the fit stopped at the iteration limit ({max_iter}): the result may not be the best"
        ));
    }
    // parameters held out of the covariance: a bound reached (τ_z = 0, θ = 0: an active
    // constraint, the linearisation does not apply) and θ inside a jump piece
    let fixed: Vec<bool> = kind
        .names()
        .iter()
        .enumerate()
        .map(|(j, n)| {
            (piece.is_some() && *n == "theta")
                || ((*n == "tau_z" || *n == "theta") && best.x[j] <= sp.lo[j])
        })
        .collect();
    let mut ci = intervals(kind, d, &vals, c, ssr, &sp, &fixed, &mut warnings)?;
    if let Some(p) = &piece {
        // θ: the profile interval; τ_z follows θ (τ_z(θ) decreasing in θ), ± its own half-width
        let half = ci[2].1.map_or(0.0, |[lo, hi]| (hi - lo) / 2.0);
        ci[2].1 = Some([p.tau_z_at(p.hi) - half, p.tau_z_at(p.lo) + half]);
        ci[3].1 = Some([p.lo, p.hi]);
        warnings.push(format!(
            "theta: a fopdt_ir model with tau_z > 0 jumps at the dead time, so sampled data place θ only \
             to whole sampling intervals (θ and tau_z trade off between the jumps): θ in ({:.6}, {:.6}] \
             fits within the 95 % profile bound (tau_z following it, from {:.6} to {:.6}); the middle of \
             the best interval is reported",
            p.lo,
            p.hi,
            p.tau_z_at(p.lo),
            p.tau_z_at(p.hi)
        ));
        if p.open {
            warnings.push(format!(
                "theta: the profile interval was cut after {MAX_PIECES} sampling intervals on a side: \
                 θ is at least that uncertain"
            ));
        }
    }
    // bounds reached and a test too short for the time constant
    for (j, name) in kind.names().iter().enumerate() {
        let x = best.x[j];
        if piece.is_some() && *name == "theta" {
            continue;
        }
        if x <= sp.lo[j] && (*name == "tau_z" || *name == "theta") {
            warnings.push(match *name {
                "tau_z" => "tau_z: at its bound 0 (the data show no inverse response: a plain lag; no interval)".into(),
                _ => "theta: at its bound 0 (no dead time seen; no interval)".into(),
            });
        } else if x >= sp.hi[j] || (x <= sp.lo[j] && *name == "tau") {
            warnings.push(format!(
                "{name}: at the bound of its search range ({:.4e}): the test cannot determine it",
                nat[j]
            ));
        }
    }
    if kind == Kind::FopdtIr && sc.span < nat[2] + 3.0 * nat[0] {
        warnings.push(format!(
            "the test ends {:.3} after the input change, before the response settles (θ + 3τ = {:.3}): \
             the gain and the time constant are extrapolated",
            sc.span,
            nat[2] + 3.0 * nat[0]
        ));
    }
    Ok(Fit {
        family,
        offset: c,
        u0: d.u0,
        rmse: (ssr / n as f64).sqrt(),
        y_fit,
        ci,
        aicc,
        n_params: p,
        iterations: best.iterations,
        noise: sc.noise,
        warnings,
    })
}

/// Eigenvalues and eigenvectors (columns) of a small symmetric matrix by cyclic Jacobi
/// rotations (written by hand: nalgebra's SVD or symmetric eigen-decomposition would add
/// about 100 kB to the wasm module for a 5×5 matrix; Jacobi is exact to round-off here).
pub fn jacobi_eigen(mut a: DMatrix<f64>) -> (Vec<f64>, DMatrix<f64>) {
    let n = a.nrows();
    let mut v = DMatrix::identity(n, n);
    for _ in 0..100 {
        let mut off = 0.0;
        let mut diag = 0.0;
        for i in 0..n {
            diag += a[(i, i)] * a[(i, i)];
            for j in i + 1..n {
                off += a[(i, j)] * a[(i, j)];
            }
        }
        if off <= 1e-32 * diag || !off.is_finite() {
            break;
        }
        for p in 0..n {
            for q in p + 1..n {
                if a[(p, q)] == 0.0 {
                    continue;
                }
                // the rotation that zeroes a_pq (Numerical Recipes §11.1)
                let th = (a[(q, q)] - a[(p, p)]) / (2.0 * a[(p, q)]);
                let t = th.signum() / (th.abs() + (th * th + 1.0).sqrt());
                let c = 1.0 / (t * t + 1.0).sqrt();
                let s = t * c;
                for k in 0..n {
                    let (kp, kq) = (a[(k, p)], a[(k, q)]);
                    a[(k, p)] = c * kp - s * kq;
                    a[(k, q)] = s * kp + c * kq;
                }
                for k in 0..n {
                    let (pk, qk) = (a[(p, k)], a[(q, k)]);
                    a[(p, k)] = c * pk - s * qk;
                    a[(q, k)] = s * pk + c * qk;
                }
                for k in 0..n {
                    let (kp, kq) = (v[(k, p)], v[(k, q)]);
                    v[(k, p)] = c * kp - s * kq;
                    v[(k, q)] = s * kp + c * kq;
                }
            }
        }
    }
    ((0..n).map(|i| a[(i, i)]).collect(), v)
}

/// The interval of dead times that fit a fopdt_ir record with τ_z > 0 equally well.
#[derive(Debug, Clone)]
struct Piece {
    lo: f64,
    hi: f64,
    tau: f64,
    /// `(1 + τ_z/τ)e^{θ/τ}`: what the samples after the jump fix.
    a: f64,
    /// The profile walk stopped at [`MAX_PIECES`] pieces: the interval is at least this wide.
    open: bool,
}

/// Most sampling pieces the jump search visits in each walk (a bounded run on long records
/// whose jump is lost in the noise).
const MAX_PIECES: usize = 40;

impl Piece {
    /// τ_z that keeps the fit when θ moves inside the piece.
    fn tau_z_at(&self, theta: f64) -> f64 {
        (self.tau * (self.a * (-theta / self.tau).exp() - 1.0)).max(0.0)
    }
}

/// `(b_prev, b_next]`: the dead times between two consecutive breakpoints `t_i − t_j` (j an
/// input switch) around θ; inside it every sample sees the same switches.
fn piece_of(d: &Data, theta: f64, theta_max: f64) -> (f64, f64) {
    let n = d.t.len();
    let (mut lo, mut hi) = (0.0f64, theta_max);
    for j in 1..n {
        if d.du[j] == d.du[j - 1] {
            continue;
        }
        let target = d.t[j] + theta;
        let i = d.t.partition_point(|x| *x < target);
        if i < n {
            hi = hi.min(d.t[i] - d.t[j]);
        }
        if i > j {
            lo = lo.max(d.t[i - 1] - d.t[j]);
        }
    }
    (lo, hi.max(lo))
}

/// A fopdt_ir model with τ_z > 0 is biproper: its response jumps by `−kτ_z/τ` at the dead time.
/// Between two breakpoints `t_i − t_j` the samples see the same jumps and the smooth part
/// `k[1 − (1 + τ_z/τ)e^{−(t−t_j−θ)/τ}]` depends on θ and τ_z only through
/// `(1 + τ_z/τ)e^{θ/τ}`: the cost is flat in θ inside such a piece and jumps between pieces, so
/// LM cannot move θ. This walks the pieces from the LM result, refitting (τ, τ_z) with θ held
/// at each piece's middle, downhill while the cost falls, and returns the best piece (its part
/// where τ_z ≥ 0) with θ at its middle. `None` when τ_z reaches 0 there (no jump: LM's θ
/// stands).
fn jump_piece(
    d: &Data,
    sp: &Space,
    start: lm::LmResult,
    cost_at: &dyn Fn(&[f64]) -> Result<Vec<f64>>,
    max_iter: usize,
) -> Result<(lm::LmResult, Option<Piece>)> {
    let theta_max = sp.hi[2];
    // the invariant of the piece and the warm start at another θ
    let shift = |x: &[f64], theta: f64| -> Vec<f64> {
        let tau = x[0].exp();
        let a = (1.0 + x[1] / tau) * (x[2] / tau).exp();
        vec![
            x[0],
            (tau * (a * (-theta / tau).exp() - 1.0)).max(0.0),
            theta,
        ]
    };
    // the best fit with θ inside the piece (flat there while τ_z > 0; where τ_z reaches 0 the
    // jump vanishes and θ becomes smooth, so LM finds it), from the middle
    let at = |x: &[f64], p: (f64, f64)| -> Result<lm::LmResult> {
        let x0 = shift(x, 0.5 * (p.0 + p.1));
        let lo = [sp.lo[0], sp.lo[1], p.0 + 1e-9 * (p.1 - p.0)];
        let hi = [sp.hi[0], sp.hi[1], p.1];
        // a piece's fit starts next to its optimum (the warm start keeps the invariant)
        lm::minimize(
            &mut |x| cost_at(x),
            &x0,
            &lo,
            &hi,
            &sp.scale,
            max_iter.min(30),
        )
    };
    let mut piece = piece_of(d, start.x[2], theta_max);
    let mut cur = at(&start.x, piece)?;
    if start.cost < cur.cost {
        cur = start.clone();
    }
    let neighbour = |p: (f64, f64), up: bool| -> Option<(f64, f64)> {
        if up {
            (p.1 < theta_max).then(|| piece_of(d, p.1 + 1e-9 * (p.1 - p.0).max(1e-300), theta_max))
        } else {
            (p.0 > 0.0).then(|| piece_of(d, p.0, theta_max))
        }
    };
    let mut dir: Option<bool> = None;
    for _ in 0..MAX_PIECES {
        let dirs: Vec<bool> = dir.map_or(vec![false, true], |u| vec![u]);
        let mut moved = false;
        for up in dirs {
            let Some(np) = neighbour(piece, up) else {
                continue;
            };
            if np == piece {
                continue;
            }
            let r = at(&cur.x, np)?;
            if r.cost < cur.cost {
                cur = r;
                piece = np;
                dir = Some(up);
                moved = true;
                break;
            }
        }
        if !moved {
            break;
        }
    }
    let tau = cur.x[0].exp();
    let a = (1.0 + cur.x[1] / tau) * (cur.x[2] / tau).exp();
    // τ_z ≥ 0 ⇔ θ ≤ τ ln a
    let hi = piece.1.min(tau * a.ln());
    if hi <= piece.0 || cur.x[1] <= 0.0 {
        return Ok((cur, None));
    }
    // the 95 % profile interval: the neighbouring pieces whose best cost stays within
    // χ²₁(0.95)·s² = 3.84·s² of the minimum (s² = SSR/(N − 5)); the jump at a few samples is all
    // that separates the pieces, so a small jump in noise leaves several of them
    let n = d.t.len() as f64;
    let limit = cur.cost * (1.0 + 3.84 / (n - 5.0).max(1.0));
    let mut open = false;
    let mut lo_p = piece;
    let mut steps = 0;
    while let Some(np) = neighbour(lo_p, false) {
        if np == lo_p || at(&cur.x, np)?.cost > limit {
            break;
        }
        lo_p = np;
        steps += 1;
        if steps >= MAX_PIECES {
            open = true;
            break;
        }
    }
    let mut hi_p = piece;
    let mut steps = 0;
    while let Some(np) = neighbour(hi_p, true) {
        if np == hi_p {
            break;
        }
        let r = at(&cur.x, np)?;
        if r.cost > limit {
            break;
        }
        hi_p = np;
        steps += 1;
        if steps >= MAX_PIECES {
            open = true;
            break;
        }
        if r.x[1] <= 0.0 {
            // τ_z reached 0: the smooth FOPDT end of the family (no jump, θ continuous, the
            // cost rising past the best θ of this piece); the whole piece is kept, so the
            // interval is conservative by less than one sampling interval at this end
            break;
        }
    }
    let p = Piece {
        lo: lo_p.0,
        hi: if hi_p == piece { hi } else { hi_p.1 },
        tau,
        a,
        open,
    };
    let theta = 0.5 * (piece.0 + hi);
    let mut x = cur.x.clone();
    x[1] = p.tau_z_at(theta);
    x[2] = theta;
    Ok((
        lm::LmResult {
            x,
            cost: cur.cost,
            iterations: cur.iterations,
        },
        Some(p),
    ))
}

/// AICc (Hurvich & Tsai 1989) of a least-squares fit with Gaussian errors, p parameters.
pub fn aicc(ssr: f64, n: usize, p: usize) -> f64 {
    let nf = n as f64;
    let pf = p as f64;
    let base = nf * (ssr / nf).max(f64::MIN_POSITIVE).ln() + 2.0 * pf;
    if n > p + 1 {
        base + 2.0 * pf * (pf + 1.0) / (nf - pf - 1.0)
    } else {
        f64::INFINITY
    }
}

/// The intervals: `(name, [lo, hi])`, `None` where none can be given.
pub type Intervals = Vec<(String, Option<[f64; 2]>)>;

/// A family that could not be fitted and why.
pub type Failed = (String, Error);

/// Linearised 95 % intervals of every parameter (the family's, then the offset) from the
/// Jacobian in natural units: `k` and `c` analytic (`g`, 1), the others by central differences.
/// A direction the data do not determine (a singular value below 1e-6 of the largest, the
/// columns scaled to unit norm) makes the parameters along it unidentifiable (`None`).
#[allow(clippy::too_many_arguments)] // one private helper of `fit`, all its inputs
fn intervals(
    kind: Kind,
    d: &Data,
    vals: &[f64],
    c: f64,
    ssr: f64,
    sp: &Space,
    fixed: &[bool],
    warnings: &mut Vec<String>,
) -> Result<Intervals> {
    let n = d.t.len();
    let p = vals.len() + 1;
    let k = vals[0];
    let nat = &vals[1..];
    let mut jac = DMatrix::zeros(n, p);
    let g = unit_response(kind, d, nat)?;
    for i in 0..n {
        jac[(i, 0)] = g[i];
        jac[(i, p - 1)] = 1.0;
    }
    for (j, name) in kind.names().iter().enumerate() {
        let v = nat[j];
        let h = 1e-6 * v.abs().max(sp.scale[j]);
        let mut plus = nat.to_vec();
        let mut minus = nat.to_vec();
        plus[j] += h;
        // one-sided at the lower bound 0 of τ_z and θ
        let lower_edge = (*name == "tau_z" || *name == "theta") && v - h < 0.0;
        if !lower_edge {
            minus[j] -= h;
        }
        let gp = unit_response(kind, d, &plus)?;
        let gm = unit_response(kind, d, &minus)?;
        let den = if lower_edge { h } else { 2.0 * h };
        for i in 0..n {
            jac[(i, j + 1)] = k * (gp[i] - gm[i]) / den;
        }
    }
    let mut names: Vec<String> = std::iter::once("k".to_string())
        .chain(kind.names().iter().map(|s| s.to_string()))
        .collect();
    names.push("offset".into());
    let mut all = vals.to_vec();
    all.push(c);
    let dof = n.saturating_sub(p).max(1) as f64;
    let s2 = ssr / dof;
    for (j, f) in fixed.iter().enumerate() {
        if *f {
            jac.column_mut(j + 1).fill(0.0);
        }
    }
    // unit-norm columns, then the SVD
    let norms: Vec<f64> = (0..p).map(|j| jac.column(j).norm()).collect();
    for (j, nj) in norms.iter().enumerate() {
        if *nj > 0.0 {
            jac.column_mut(j).scale_mut(1.0 / nj);
        }
    }
    // eigen-decomposition of the scaled normal matrix: λ_r = σ_r², σ the singular values
    let (lam, v) = jacobi_eigen(jac.transpose() * &jac);
    let lmax = lam.iter().cloned().fold(0.0, f64::max);
    let mut unident = vec![false; p];
    let mut cov = DMatrix::<f64>::zeros(p, p);
    for (r, l) in lam.iter().enumerate() {
        // σ_r ≤ 1e-6 σ_max: the data do not determine that direction (forming JᵀJ squares the
        // condition number, so λ cannot resolve σ below ~1e-8 σ_max anyway)
        if l.is_nan() || *l <= 1e-12 * lmax {
            for j in 0..p {
                if v[(j, r)].abs() > 0.1 {
                    unident[j] = true;
                }
            }
            continue;
        }
        for a in 0..p {
            for b in 0..p {
                cov[(a, b)] += v[(a, r)] * v[(b, r)] / l;
            }
        }
    }
    let mut out = vec![];
    for j in 0..p {
        let name = &names[j];
        if j >= 1 && j < p - 1 && fixed[j - 1] {
            out.push((name.clone(), None));
            continue;
        }
        if unident[j] || norms[j] == 0.0 {
            warnings.push(format!(
                "{name}: not identifiable from these data (its effect cannot be told apart from the others')"
            ));
            out.push((name.clone(), None));
            continue;
        }
        let sd = (s2 * cov[(j, j)]).sqrt() / norms[j];
        let half = Z95 * sd;
        let v = all[j];
        if !half.is_finite() {
            out.push((name.clone(), None));
            continue;
        }
        if half > v.abs() && name != "offset" && !(v == 0.0 && (name == "tau_z" || name == "theta"))
        {
            warnings.push(format!(
                "{name}: poorly determined: the 95 % interval [{:.4}, {:.4}] is wider than ± the value {:.4} \
                 (a longer test, or one with more excitation, would pin it down)",
                v - half,
                v + half,
                v
            ));
        }
        out.push((name.clone(), Some([v - half, v + half])));
    }
    Ok(out)
}

/// Fits every family of `families` (default [`FAMILIES`]) and returns the fits sorted by AICc,
/// best first, with the families that could not be fitted and why.
pub fn rank(d: &Data, families: &[&str], max_iter: usize) -> Result<(Vec<Fit>, Vec<Failed>)> {
    let mut fits = vec![];
    let mut failed = vec![];
    for id in families {
        match fit(d, id, max_iter) {
            Ok(f) => fits.push(f),
            Err(e) => failed.push((id.to_string(), e)),
        }
    }
    if fits.is_empty() {
        let (id, e) = failed
            .first()
            .cloned()
            .unwrap_or(("family".into(), Error::new("family", "no family to fit")));
        return Err(Error::new(
            "family",
            format!("auto: no family could be fitted ({id}: {e})"),
        ));
    }
    // stable sort: an exact tie keeps the order of `families` (the simpler first)
    crate::numerics::sort_by_f64_key(&mut fits, |f| f.aicc);
    Ok((fits, failed))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Jacobi on a symmetric positive definite 4×4 (BᵀB): V diag(λ) Vᵀ rebuilds it, V is
    /// orthogonal and the product of the eigenvalues is the determinant, to round-off.
    #[wasm_bindgen_test::wasm_bindgen_test(unsupported = test)]
    fn jacobi_rebuilds_the_matrix() {
        let b = DMatrix::from_row_slice(
            5,
            4,
            &[
                1.0, 2.0, 3.0, 3.0, 0.5, -1.0, 2.0, -0.5, 2.0, 0.1, 0.3, 2.1, -1.0, 4.0, 1.0, 3.0,
                0.7, 0.7, -2.0, 1.4,
            ],
        );
        let m = b.transpose() * &b;
        let (lam, v) = jacobi_eigen(m.clone());
        let rebuilt =
            &v * DMatrix::from_diagonal(&nalgebra::DVector::from_vec(lam.clone())) * v.transpose();
        assert!((rebuilt - &m).amax() < 1e-13 * m.amax());
        assert!((v.transpose() * &v - DMatrix::identity(4, 4)).amax() < 1e-14);
        let det: f64 = lam.iter().product();
        assert!((det - m.clone().determinant()).abs() < 1e-10 * m.amax().powi(4));
    }
}
