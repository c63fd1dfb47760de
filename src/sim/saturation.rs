//! The continuous controller with actuator limits: a piecewise-linear loop, propagated
//! exactly between events that are located to round-off.
//!
//! The controller is written `A_o·v = T·r − S·y + W·u` ([`crate::model::discrete`]:
//! `A_o = R, W = 0` for anti-windup `"none"`, `A_o = R(s + 1/tt)/s, W = A_o − R` for
//! `"tracking"`) and realized jointly with inputs `[r, y, u]` (`W/A_o` is strictly proper,
//! so `v` does not depend on `u` directly; an ideal derivative on `y` is folded in as in
//! [`super::single`]). The applied input is `u = sat(v)`; the plant input is
//! `w(t) = u(t − θ) + d(t − θ)`. Between events the loop is one of two linear systems:
//! unsaturated (`u = v`) or at a limit `L` (`u = L`, the controller's state keeps evolving
//! with input `L`: for `"none"` this is the linear controller, which winds up).
//!
//! ## Method
//! With θ > 0 the plant input `w` on a piece is known from the response one dead time
//! earlier. The time axis is cut on the grid `h = θ/N` (`h ≤ 0.55/ρ(A)`, `N ≥ 3` and, when
//! the unsaturated mode is neutral, the bound `h ≤ 0.6·θ·(1 − |e|)` of [`crate::sim`]'s "Near
//! the neutral limit") and at every non-smooth instant — the set-point and load steps and every limit switch — and at
//! all their copies `+ kθ`, so the delayed input on each piece is the restriction of one
//! earlier piece's degree-7 polynomial (as in [`super::single`]); a cut is kept as its grid
//! step and offset, so its copies give pieces of the same length bit for bit (`GridTime`).
//! On a piece the augmented state `[x; ξ (monomial coefficients of w); r; L]` is propagated
//! exactly by a matrix exponential, cached per dynamics and piece length as rows over the
//! piece's start state (`PieceProp`: the switching functions at the nodes and the end state).
//! The mode's validity functions (`v − u_max` and `v − u_min` while free; below) are affine
//! in that state, so on a piece each is the smooth `τ ↦ c·exp(Mτ)·z`; its degree-7 interpolant
//! through the `NODES` = 8 node values is tested for a turn below zero by the signs of its
//! Bernstein coefficients ([`super::bernstein`]; beyond the round-off bound derived at
//! `switch_first`), so an excursion past a limit between two nodes is found too; the first
//! such place is refined on the exact function with Brent's method to round-off, the piece is
//! cut there, the mode switched, and `t* + kθ` scheduled as cuts. The step does not depend on
//! `dt` (until branch satsw, issue 15, the switches were sought at the nodes only and `h ≤ dt`
//! kept the nodes dense); the output samples are read on the piece polynomials. A jump of `v` across a limit (a set-point
//! step through a proportional path, a biproper plant's jump) switches the mode at the start
//! of the piece. No fixed-step integration is used.
//!
//! For "none" and "tracking" the vector field is continuous across the switching surface (at
//! `v = L` the tracking term `W·(u − v)` vanishes), so there is no sliding motion: the modes
//! are well defined.
//!
//! ## Conditional integration (clamping)
//! The controller is split as in [`crate::model::discrete::IntegralSplit`]: its integral
//! state, the residue at `s = 0`, `ẋ_I = e_I = g_r·r − g_y·y` (`K_i (r − y)` for a PID; with a
//! set-point filter `F` the integral of `r − y`, the filter's remainder `K_i (F − 1)/s` being
//! part of the rest), and a part without integrator, `v = x_I + v_rest`. The applied input is
//! `u = sat(v)`; the controller does not depend on `u`. The integral stops while `v` is at or
//! beyond a limit `L_σ` and `e_I` drives it further out (σ = +1 for `u_max`, −1 for `u_min`):
//! the right-hand side `ẋ_I = e_I·[not(σ(v − L_σ) ≥ 0 and σ e_I > 0)]` is discontinuous on
//! `v = L_σ`, and the loop is defined as its Filippov solution. With `s = dv_rest/dt` (a linear
//! function of the loop's state, the delayed input and its derivative) the modes are
//!
//! | mode | `ẋ_I` | holds while |
//! |---|---|---|
//! | free | `e_I` | `u_min ≤ v ≤ u_max` |
//! | clamped σ | 0 | `σ(v − L) ≥ 0`, `σ e_I ≥ 0` |
//! | integrating σ | `e_I` | `σ(v − L) ≥ 0`, `σ e_I ≤ 0` (the integral pulls `v` back) |
//! | sliding σ | `−s` (so `v ≡ L`) | `σ s ≤ 0`, `σ(e_I + s) ≥ 0` |
//!
//! Sliding is the chattering case: frozen, `v_rest` brings `v` back inside; free, the
//! integral pushes it out again. The Filippov solution keeps `v = L` with the convex
//! combination `ẋ_I = −s ∈ [0, e_I]` of the two fields (σ = +1): the integral follows the
//! proportional part down so that the output stays at the limit, which is also the limit
//! h → 0 of the sampled clamping law ([`super::sampled`]; tests/saturation.rs measures the
//! first-order convergence). It ends when `s` changes sign (→ clamped) or `e_I + s` does
//! (→ free). In the sliding mode the loop is integrated with the integral frozen and
//! `x_I = L − v_rest` is set at the piece's nodes and end (exact: nothing else in the loop
//! depends on `x_I` while `u = L`). Each validity function above is a linear function of
//! the augmented state, so its zero is located by Brent's method like a limit crossing; the
//! mode entered at a zero is fixed by the signs of `e_I` and `s` there (a jump of the state —
//! a set-point step, a biproper plant's jump, a kink of the delayed input — re-classifies
//! the mode at the piece's start). Defined for controllers with exactly one integrator
//! (PID, PI, I-PD, PID × filter, lead-lag × PI, 2-DOF); others are an error naming
//! `actuator.anti_windup`.
//!
//! ## Without dead time (θ = 0)
//! The plant input `w = u + d` is then instantaneous, so each mode's matrices are written for
//! the inputs `(d, r, L)` ([`SatLoop::eliminate_w`]): at a limit `w = L + d`; unsaturated
//! `u = v` and the loop's algebraic equation `v = g·X + h_r r + e (v + d)` (`e = −L(j∞)`,
//! nonzero only for a biproper loop: a biproper plant under a controller with direct
//! feed-through, or an ideal derivative on a plant of relative degree one) is solved,
//! `v = (g·X + h_r r + e d)/(1 − e)`. `v` is continuous across a switch (at `v = L` both give
//! `w = L + d`). The piece grid is `t_end/N ≤ 0.55/ρ` over the modes' matrices, and the
//! `w` slot of the augmented state carries the constant `d`. With `1 − e ≤ 0`
//! (`L(j∞) ≤ −1`) `v − e·sat(v) = …` is not monotone and has no unique solution: refused,
//! naming `plant.delay`.

use super::bernstein::{casteljau, first_crossing, PieceForms, ZERO_DEPTH};
use super::scenario::Scenario;
use super::single::{divisor_step, neutral_bound, LoopModel, DELAY_PIECES, FAST_STEP};
use super::trajectory::{lagrange, start_interpolation_inverse, Trajectory, DEG, NODES};
use crate::error::{Error, Result};
use crate::model::controller::Controller;
use crate::model::discrete::{default_tt, AntiWindup, IntegralSplit, Limits, PolyForm};
use crate::model::plant::Plant;
use crate::model::poly::Poly;
use crate::model::ss::{balance, realize_paths, Ss};
use crate::model::tf::Tf;
use crate::numerics::{brent, col_major_rows};
use nalgebra::{DMatrix, DVector, DVectorView};
use std::collections::{BTreeMap, HashMap};

/// Hard cap on the number of pieces of one simulation.
const MAX_PIECES: usize = 2_000_000;

/// The time spent at each limit: intervals `[t_a, t_b)` during which `u` is at a limit.
#[derive(Debug, Clone, PartialEq)]
pub struct LimitRecord {
    /// The limits.
    pub limits: Limits,
    /// Intervals during which the applied u is at a limit.
    pub intervals: Vec<(f64, f64)>,
}

impl LimitRecord {
    /// Fraction of `[a, b]` during which the applied u is at a limit.
    pub fn fraction_at_limit(&self, a: f64, b: f64) -> f64 {
        if b <= a {
            return 0.0;
        }
        let at: f64 = self
            .intervals
            .iter()
            .map(|(t0, t1)| (t1.min(b) - t0.max(a)).max(0.0))
            .sum();
        (at / (b - a)).clamp(0.0, 1.0)
    }
}

/// The loop matrices: state `X`, `Ẋ = A_m X + b_w,m w + b_r,m r + b_L,m L` in dynamics m
/// (0: unsaturated, or integrating; 1: at a limit L, or integral frozen),
/// `v = g·X + h_r r + e w`, `y = y_x·X + y_w w`.
/// "none"/"tracking": `X = [x_c; x_p]`, the controller driven by `u` (`b_L`).
/// "conditional": `X = [x_I; x_c; x_p]` with `x_c` the controller's part without integrator
/// (inputs r, y only: `b_L = 0`), `v = x_I + v_rest`; `cond` gives the integrator's input.
struct SatLoop {
    /// Indexed by [`Mode::kind`]: 0 unsaturated, 1 at a limit (integral frozen), 2 at a limit
    /// integrating (conditional).
    a: [DMatrix<f64>; 3],
    bw: [DVector<f64>; 3],
    br: [DVector<f64>; 3],
    bl: [DVector<f64>; 3],
    g: DVector<f64>,
    hr: f64,
    e: f64,
    yx: DVector<f64>,
    yw: f64,
    cond: Option<Cond>,
    rows: Option<Rows>,
    /// θ = 0: the plant input is `w = u + d` now, the `w` slot of the state carries `d`
    /// (module docs); `1 − e > 0` then.
    direct: bool,
}

/// Conditional integration: the integrator's input `e_I = ex·X + ew·w + er·r`
/// (`= g_r r − g_y y`, the unscaled `ẋ_I`), and `x_I = X[0]·g[0]` (after balancing).
struct Cond {
    ex: DVector<f64>,
    ew: f64,
    er: f64,
}

fn tf(num: Poly, den: &Poly) -> Tf {
    Tf {
        num,
        den: den.clone(),
    }
}

impl SatLoop {
    fn new(plant: &Plant, c: &Controller, aw: AntiWindup, setpoint_step: bool) -> Result<SatLoop> {
        // (the raw loop, then θ = 0's elimination of w, then balancing: `assemble`)
        let pf = PolyForm::new(c).map_err(|e| e.within("controller"))?;
        let (ao, w) = match aw {
            AntiWindup::None => (pf.r.clone(), Poly::constant(0.0)),
            AntiWindup::Tracking { tt } => {
                let tt = match tt {
                    Some(x) => crate::error::positive("actuator.anti_windup.tt", x)?,
                    None => default_tt(&pf).map_err(|e| e.within("actuator"))?,
                };
                pf.tracking(tt).map_err(|e| e.within("actuator"))?
            }
            AntiWindup::Conditional => {
                let sp = IntegralSplit::new(&pf).map_err(|e| e.within("actuator"))?;
                let (cs, kd) = realize_paths(&[
                    (&tf(sp.t_rest.clone(), &sp.r1), "controller.cr", 1.0),
                    (&tf(sp.s_rest.clone(), &sp.r1), "controller.cy", -1.0),
                ])?;
                return SatLoop::assemble(plant, &cs, &kd, Some((sp.g_r, sp.g_y)), setpoint_step);
            }
        };
        let (cs, kd) = realize_paths(&[
            (&tf(pf.t.clone(), &ao), "controller.cr", 1.0),
            (&tf(pf.s.clone(), &ao), "controller.cy", -1.0),
            (&tf(w, &ao), "actuator.anti_windup", 1.0),
        ])?;
        SatLoop::assemble(plant, &cs, &kd, None, setpoint_step)
    }

    /// The loop of a controller realized with inputs `[r, y]` (+ `u` without `integral`);
    /// `integral = Some((g_r, g_y))`: a separate integral state `ẋ_I = g_r r − g_y y` is
    /// added in front and `v = x_I + (controller output)` (conditional integration).
    fn assemble(
        plant: &Plant,
        cs: &Ss,
        kd: &[f64],
        integral: Option<(f64, f64)>,
        setpoint_step: bool,
    ) -> Result<SatLoop> {
        // the raw loop (unsaturated, or at a limit with u = L only through `b_u`), with the
        // integral state in front when there is one
        let ni = usize::from(integral.is_some());
        let raw = LoopModel::raw(plant, cs, kd[0], -kd[1], ni, setpoint_step)?;
        let nc = cs.order();
        let n = raw.a.nrows();
        let (oc, op, np) = (ni, ni + nc, n - ni - nc);
        let (dcr, dp, e) = (raw.h, raw.yw, raw.e);
        // y = C_p x_p + D_p w
        let cp = raw.yx.rows(op, np).into_owned();
        // at a limit (or integral frozen): ẋ_c = A_c x_c + b_r r + b_y y (+ b_u L),
        // ẋ_p = A_p x_p + b_p w; v = C_c x_c + D_r r + D_y y − k_dy ẏ
        let LoopModel {
            a: a1,
            bw,
            br,
            mut g,
            yx,
            ..
        } = raw;
        let mut m = if let Some((g_r, g_y)) = integral {
            // integrating: ẋ_I = g_r r − g_y (C_p x_p + D_p w); v = x_I + …
            g[0] = 1.0;
            let mut a0 = a1.clone();
            let mut ex = DVector::zeros(n);
            ex.rows_mut(op, np).copy_from(&(&cp * -g_y));
            a0.row_mut(0).copy_from(&ex.transpose());
            let mut bw0 = bw.clone();
            bw0[0] = -g_y * dp;
            let mut br0 = br.clone();
            br0[0] = g_r;
            let cond = Cond {
                ex,
                ew: -g_y * dp,
                er: g_r,
            };
            let mut gr = g.clone();
            gr[0] = 0.0;
            let rows = Rows {
                sa: a1.tr_mul(&gr),
                sw: gr.dot(&bw),
                sr: gr.dot(&br),
            };
            SatLoop {
                a: [a0.clone(), a1, a0],
                bw: [bw0.clone(), bw, bw0],
                br: [br0.clone(), br, br0],
                bl: [DVector::zeros(n), DVector::zeros(n), DVector::zeros(n)],
                g,
                hr: dcr,
                e,
                yx,
                yw: dp,
                cond: Some(cond),
                rows: Some(rows),
                direct: false,
            }
        } else {
            let mut bu = DVector::zeros(n);
            bu.rows_mut(oc, nc).copy_from(&cs.b.column(2));
            // unsaturated: u = v = g·X + h_r r + e w
            let a0 = &a1 + &bu * g.transpose();
            let bw0 = &bw + &bu * e;
            let br0 = &br + &bu * dcr;
            SatLoop {
                a: [a0.clone(), a1, a0],
                bw: [bw0.clone(), bw, bw0],
                br: [br0.clone(), br, br0],
                bl: [DVector::zeros(n), bu.clone(), bu],
                g,
                hr: dcr,
                e,
                yx,
                yw: dp,
                cond: None,
                rows: None,
                direct: false,
            }
        };
        if plant.delay == 0.0 {
            m.eliminate_w()?;
        }
        // balance the state coordinates (X = S X̃) for well-scaled exponentials
        let s = balance(&m.a[0]);
        for k in 0..3 {
            for i in 0..n {
                for j in 0..n {
                    m.a[k][(i, j)] *= s[j] / s[i];
                }
                m.bw[k][i] /= s[i];
                m.br[k][i] /= s[i];
                m.bl[k][i] /= s[i];
            }
        }
        for i in 0..n {
            m.g[i] *= s[i];
            m.yx[i] *= s[i];
            if let Some(cd) = m.cond.as_mut() {
                cd.ex[i] *= s[i];
            }
            if let Some(rw) = m.rows.as_mut() {
                rw.sa[i] *= s[i];
            }
        }
        Ok(m)
    }

    /// θ = 0: the plant input `w = u + d` is instantaneous. Unsaturated, `u = v` and
    /// `v = g·X + h_r r + e (v + d)` is solved, `v = (g·X + h_r r + e d)/(1 − e)`; at a limit
    /// `w = L + d`. Each mode's matrices then act on `[X; d (the w slot); r; L]`. With
    /// `1 − e ≤ 0` (`e = −L(j∞)`, the loop's high-frequency gain: a biproper loop with
    /// `L(j∞) ≤ −1`) `v − e·sat(v) = …` has no unique solution: refused.
    fn eliminate_w(&mut self) -> Result<()> {
        let ome = 1.0 - self.e;
        if ome <= 1e-12 {
            return Err(Error::new(
                "plant.delay",
                format!(
                    "without dead time the loop is algebraic: v = … + e·sat(v) with e = −L(j∞) \
                     = {} ≥ 1 has no unique solution; give the plant a dead time or sampling",
                    self.e
                ),
            ));
        }
        // the raw loop `Ẋ = A X + B_w w + B_r r + B_u u` of each kind
        let raw = |k: usize| -> (DMatrix<f64>, DVector<f64>, DVector<f64>, DVector<f64>) {
            if self.cond.is_some() {
                (
                    self.a[k].clone(),
                    self.bw[k].clone(),
                    self.br[k].clone(),
                    self.bl[k].clone(),
                )
            } else {
                (
                    self.a[1].clone(),
                    self.bw[1].clone(),
                    self.br[1].clone(),
                    self.bl[1].clone(),
                )
            }
        };
        let (a, bw, br, bu) = raw(0);
        let bwu = &bw + &bu;
        let a0 = &a + &bwu * (self.g.transpose() / ome);
        let br0 = &br + &bwu * (self.hr / ome);
        let bd0 = &bw + &bwu * (self.e / ome);
        let mut out = [0, 1, 2].map(|k| {
            let (a, bw, br, bu) = raw(k);
            let bl = &bw + &bu;
            (a, bw, br, bl)
        });
        out[0] = (a0, bd0, br0, DVector::zeros(self.order()));
        for (k, (a, bw, br, bl)) in out.into_iter().enumerate() {
            self.a[k] = a;
            self.bw[k] = bw;
            self.br[k] = br;
            self.bl[k] = bl;
        }
        self.direct = true;
        Ok(())
    }

    fn order(&self) -> usize {
        self.g.len()
    }

    /// `M` of the augmented system over `z = [X (n); ξ (NODES); r; L]` for a piece of
    /// length `len` (`w(τ) = Σ ξ_k (τ/len)^k`).
    fn augmented(&self, kind: usize, len: f64) -> DMatrix<f64> {
        let mode = kind;
        let n = self.order();
        let sz = n + NODES + 2;
        let mut big = DMatrix::zeros(sz, sz);
        big.view_mut((0, 0), (n, n)).copy_from(&self.a[mode]);
        for i in 0..n {
            big[(i, n)] = self.bw[mode][i];
            big[(i, n + NODES)] = self.br[mode][i];
            big[(i, n + NODES + 1)] = self.bl[mode][i];
        }
        for k in 0..DEG {
            big[(n + k, n + k + 1)] = (k + 1) as f64 / len;
        }
        big
    }
}

/// A time on the piece grid: step `g` (a whole number) and offset `off ∈ [0, h)` within it,
/// `t = g·h + off`. A piece's length is taken from the offsets (`(g₁ − g₀)·h + off₁ − off₀`),
/// so the pieces between the same two offsets of different steps — a switch's copies
/// `t* + kθ`, `θ = N·h`, are `(g + kN, off)` — have the same length bit for bit and share one
/// propagator (as `t* + kθ` summed in floating point they drifted by up to ~60 ulp of t,
/// a new length, so a new matrix exponential, at every copy).
#[derive(Clone, Copy, Debug)]
struct GridTime {
    g: f64,
    off: f64,
}

impl GridTime {
    fn at(self, h: f64) -> f64 {
        self.g * h + self.off
    }

    /// `self + τ` within its step (`τ ≤` the rest of the step), the step's end `(g + 1, 0)`
    /// when within `tol` of it.
    fn plus(self, tau: f64, h: f64, tol: f64) -> GridTime {
        let off = self.off + tau;
        if off >= h - tol {
            GridTime {
                g: self.g + 1.0,
                off: 0.0,
            }
        } else {
            GridTime { g: self.g, off }
        }
    }

    /// The length from `self` to `b`.
    fn to(self, b: GridTime, h: f64) -> f64 {
        (b.g - self.g) * h + (b.off - self.off)
    }
}

/// Ordered cut times (as bit patterns: positive floats order like their bits), each with
/// its place on the grid.
struct Cuts {
    h: f64,
    at: BTreeMap<u64, GridTime>,
}

impl Cuts {
    fn add(&mut self, c: GridTime) {
        let t = c.at(self.h);
        if t.is_finite() && t > 0.0 {
            self.at.entry(t.to_bits()).or_insert(c);
        }
    }

    /// The first cut later than `t + tol`.
    fn next_after(&self, t: f64, tol: f64) -> Option<(f64, GridTime)> {
        let lo = (t + tol).max(0.0).to_bits() + 1;
        self.at
            .range(lo..)
            .next()
            .map(|(b, c)| (f64::from_bits(*b), *c))
    }

    /// True when a cut lies within `tol` of `t`.
    fn contains(&self, t: f64, tol: f64) -> bool {
        let lo = (t - tol).max(0.0).to_bits();
        let hi = (t + tol).to_bits();
        self.at.range(lo..=hi).next().is_some()
    }
}

/// The output of [`integrate`]: the trajectory (applied `u + d` and `y`), the controller
/// output `v` at the same nodes, the limit each piece holds, divergence time and the time at
/// the limits.
pub(crate) struct SatRun {
    pub traj: Trajectory,
    pub v_nodes: Vec<f64>,
    /// Per piece: the limit `L` the applied input holds on it, NaN on an unsaturated piece.
    /// The trajectory stores the plant input `L + d`, whose sample `(L + d) − d` is `L` only
    /// when that subtraction is exact (`(−0.65 + 1.7) − 1.7 = −0.6500000000000001`): a
    /// held limit's samples are taken from here, `L` exactly.
    pub held: Vec<f64>,
    pub diverged_at: Option<f64>,
    pub record: LimitRecord,
}

/// The switching mode of the loop (module docs). `σ = 1` is the upper limit, `−1` the lower.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Mode {
    /// Unsaturated: `u = v`, the controller's linear law.
    Free,
    /// "none"/"tracking": at the limit `L_σ` (`u = L_σ`).
    Sat(i8),
    /// "conditional": `v` beyond `L_σ`, the integral's input drives it further out: frozen.
    Clamp(i8),
    /// "conditional": `v` beyond `L_σ`, the integral's input drives it back: integrating.
    Integ(i8),
    /// "conditional": sliding on `v = L_σ` (Filippov): `x_I = L_σ − v_rest`.
    Slide(i8),
}

impl Mode {
    fn side(self) -> i8 {
        match self {
            Mode::Free => 0,
            Mode::Sat(k) | Mode::Clamp(k) | Mode::Integ(k) | Mode::Slide(k) => k,
        }
    }

    /// Which matrices: 0 unsaturated, 1 at a limit (integral frozen), 2 at a limit
    /// integrating.
    fn kind(self) -> usize {
        match self {
            Mode::Free => 0,
            Mode::Integ(_) => 2,
            _ => 1,
        }
    }
}

/// The loop's switching functions at one state: `v`, the integrator's input `e` and
/// `s = dv_rest/dt` (conditional only; 0 otherwise), and the output `y`.
#[derive(Clone, Copy, Debug, Default)]
struct Point {
    v: f64,
    e: f64,
    s: f64,
    y: f64,
}

/// Precomputed rows for [`Point`] (no allocation per evaluation).
struct Rows {
    /// `s = sa·X + sw·w + sr·r + e·ẇ` (the frozen dynamics' derivative of `v_rest`).
    sa: DVector<f64>,
    sw: f64,
    sr: f64,
}

impl SatLoop {
    /// The switching functions at `z` in `mode` (θ = 0: the mode decides the plant input).
    fn point(&self, z: &[f64], len: f64, mode: Mode) -> Point {
        let n = self.order();
        let x = DVectorView::from_slice(&z[..n], n);
        let (xi0, r) = (z[n], z[n + NODES]);
        let gx = self.g.dot(&x) + self.hr * r;
        let (v, w, wdot) = if !self.direct {
            (gx + self.e * xi0, xi0, z[n + 1] / len)
        } else if mode == Mode::Free {
            let v = (gx + self.e * xi0) / (1.0 - self.e);
            (v, v + xi0, 0.0)
        } else {
            let w = z[n + NODES + 1] + xi0;
            (gx + self.e * w, w, 0.0)
        };
        let y = self.yx.dot(&x) + self.yw * w;
        match (&self.cond, &self.rows) {
            (Some(cd), Some(rw)) => Point {
                v,
                e: cd.ex.dot(&x) + cd.ew * w + cd.er * r,
                s: rw.sa.dot(&x) + rw.sw * w + rw.sr * r + self.e * wdot,
                y,
            },
            _ => Point {
                v,
                e: 0.0,
                s: 0.0,
                y,
            },
        }
    }
}

impl SatLoop {
    /// [`SatLoop::point`]'s quantities `v, y, e, s` as rows over the augmented state `z` of a
    /// piece of length `len` (they are linear in it), for the unsaturated dynamics (`free`) or
    /// a limit's (θ = 0 only: the mode decides the plant input), stored column by column
    /// (`rows[4·j + q]`: quantity q's coefficient of `z_j`) for [`col_major_rows`].
    fn point_rows(&self, free: bool, len: f64) -> Vec<f64> {
        let n = self.order();
        let sz = n + NODES + 2;
        let (i0, ir, il) = (n, n + NODES, n + NODES + 1);
        // v's row, and w's (the plant input's)
        let mut rv = vec![0.0; sz];
        let mut rw = vec![0.0; sz];
        for (r, g) in rv.iter_mut().zip(self.g.iter()) {
            *r = *g;
        }
        rv[ir] = self.hr;
        rv[i0] = self.e;
        if !self.direct {
            rw[i0] = 1.0;
        } else if free {
            // v = (g·X + h_r r + e d)/(1 − e), w = v + d
            let ome = 1.0 - self.e;
            for r in rv.iter_mut() {
                *r /= ome;
            }
            rw.copy_from_slice(&rv);
            rw[i0] += 1.0;
        } else {
            // w = L + d
            rv[il] = self.e;
            rw[i0] = 1.0;
            rw[il] = 1.0;
        }
        // a quantity `q·X + q_w w + q_r r`
        let lin = |q: &DVector<f64>, qw: f64, qr: f64| -> Vec<f64> {
            let mut row: Vec<f64> = (0..sz)
                .map(|j| if j < n { q[j] + qw * rw[j] } else { qw * rw[j] })
                .collect();
            row[ir] += qr;
            row
        };
        let ry = lin(&self.yx, self.yw, 0.0);
        let (re, rs) = match (&self.cond, &self.rows) {
            (Some(cd), Some(rr)) => {
                let mut rs = lin(&rr.sa, rr.sw, rr.sr);
                if !self.direct {
                    // `e·ẇ`, `ẇ(0) = ξ₁/len`
                    rs[i0 + 1] += self.e / len;
                }
                (lin(&cd.ex, cd.ew, cd.er), rs)
            }
            _ => (vec![0.0; sz], vec![0.0; sz]),
        };
        let mut cols = vec![0.0; 4 * sz];
        for j in 0..sz {
            cols[4 * j..4 * j + 4].copy_from_slice(&[rv[j], ry[j], re[j], rs[j]]);
        }
        cols
    }
}

/// The propagator of one piece length and dynamics kind (the cache's entry), as rows over
/// the piece's start state `z₀` (the one-delay loop's [`super::single`] `Prop`): the
/// switching functions at the nodes and the end state are `row·z₀`, one column-major pass
/// over `z₀` each, without the node states.
struct PieceProp {
    kind: usize,
    len: f64,
    /// [`SatLoop::point_rows`] of the kind (the switching functions at a state).
    rows: Vec<f64>,
    /// `P·Φʲ` (P the point rows, `Φ = exp(M·len/DEG)`, [`SatLoop::augmented`]), rows
    /// `4j + q` (quantity q of [`Point`] at node j), nodes 0–3 and 4–7, column by column
    /// (`sz × 16` each).
    nodes: [Vec<f64>; 2],
    /// The first `n` rows of `Φ^DEG` (the end state X) in blocks of [`END_ROWS`] rows (the
    /// last padded with zero rows), each block column by column (`sz × END_ROWS`).
    end: Vec<f64>,
    /// `max_j |c|·|Φ|ʲ` elementwise for the validity functions' coefficient rows `c` of v, e,
    /// s and e + s ([`validity_terms`]): with `|z₀|` it bounds the terms that cancel in a
    /// validity function at any node ([`switch_first`]'s round-off bound).
    bound: [Vec<f64>; 4],
}

/// Rows of one block of [`PieceProp::end`]: the loop's order is not bounded (a plant of any
/// order with its controller), so the end state is computed 8 rows at a time.
const END_ROWS: usize = 8;

/// The length of the end state's blocks for a loop of order `n` (`n` rounded up to
/// [`END_ROWS`]).
fn end_len(n: usize) -> usize {
    n.div_ceil(END_ROWS) * END_ROWS
}

impl PieceProp {
    fn new(m: &SatLoop, kind: usize, len: f64) -> PieceProp {
        let n = m.order();
        let sz = n + NODES + 2;
        let phi = (m.augmented(kind, len) * (len / DEG as f64)).exp();
        let phi_abs = phi.abs();
        let rows = m.point_rows(kind == 0, len);
        let p = DMatrix::from_column_slice(4, sz, &rows);
        // |c| of v, e, s, e + s
        let mut c_abs = DMatrix::<f64>::zeros(4, sz);
        for j in 0..sz {
            let c = &rows[4 * j..4 * j + 4];
            c_abs[(0, j)] = c[0].abs();
            c_abs[(1, j)] = c[2].abs();
            c_abs[(2, j)] = c[3].abs();
            c_abs[(3, j)] = (c[2] + c[3]).abs();
        }
        let mut nodes = [vec![0.0; 16 * sz], vec![0.0; 16 * sz]];
        let mut bound = c_abs.clone();
        let (mut pj, mut bj) = (p, c_abs);
        for j in 0..NODES {
            if j > 0 {
                pj = &pj * &phi;
                bj = &bj * &phi_abs;
                bound = bound.zip_map(&bj, f64::max);
            }
            let (half, r0) = (j / 4, 4 * (j % 4));
            for col in 0..sz {
                for q in 0..4 {
                    nodes[half][16 * col + r0 + q] = pj[(q, col)];
                }
            }
        }
        let mut phi_deg = phi.clone();
        for _ in 1..DEG {
            phi_deg = &phi_deg * &phi;
        }
        let mut end = vec![0.0; end_len(n) * sz];
        for r in 0..n {
            let (block, row) = (r / END_ROWS, r % END_ROWS);
            for col in 0..sz {
                end[block * END_ROWS * sz + END_ROWS * col + row] = phi_deg[(r, col)];
            }
        }
        PieceProp {
            kind,
            len,
            rows,
            nodes,
            end,
            bound: [0, 1, 2, 3].map(|q| bound.row(q).iter().copied().collect()),
        }
    }

    /// The switching functions at the nodes and the end state `X` (its first `n` entries;
    /// `x_end` holds [`end_len`]`(n)`) of the piece from `z0`.
    #[inline]
    fn propagate(&self, z0: &[f64], pts: &mut [Point; NODES], x_end: &mut [f64]) {
        let mut o = [0.0; 2 * 16];
        col_major_rows::<16>(&self.nodes[0], z0, &mut o[..16]);
        col_major_rows::<16>(&self.nodes[1], z0, &mut o[16..]);
        for (p, q) in pts.iter_mut().zip(o.chunks_exact(4)) {
            *p = Point {
                v: q[0],
                y: q[1],
                e: q[2],
                s: q[3],
            };
        }
        for (block, out) in self
            .end
            .chunks_exact(END_ROWS * z0.len())
            .zip(x_end.chunks_exact_mut(END_ROWS))
        {
            col_major_rows::<END_ROWS>(block, z0, out);
        }
    }

    /// The switching functions at the augmented state `z` (of a piece of this length).
    #[inline]
    fn point(&self, z: &[f64]) -> Point {
        let mut o = [0.0; 4];
        col_major_rows::<4>(&self.rows, z, &mut o);
        Point {
            v: o[0],
            y: o[1],
            e: o[2],
            s: o[3],
        }
    }
}

/// The propagators met so far, by dynamics kind and piece length (bit for bit); the last one
/// used is tried first (most pieces are whole steps in the mode of the piece before).
#[derive(Default)]
struct PropCache {
    entries: Vec<PieceProp>,
    index: HashMap<(usize, u64), usize>,
    last: usize,
}

impl PropCache {
    fn get(&mut self, m: &SatLoop, kind: usize, len: f64) -> &PieceProp {
        let hit = self
            .entries
            .get(self.last)
            .is_some_and(|e| e.kind == kind && e.len.to_bits() == len.to_bits());
        if !hit {
            let entries = &mut self.entries;
            self.last = *self.index.entry((kind, len.to_bits())).or_insert_with(|| {
                entries.push(PieceProp::new(m, kind, len));
                entries.len() - 1
            });
        }
        &self.entries[self.last]
    }
}

/// The validity functions' constant terms `c₀` (infinite: an absent function) and which of
/// [`PieceProp::bound`] bound the magnitudes of their coefficients (0: v, 1: e, 2: s, 3: e + s),
/// as [`validity`] writes them: `f_k(z) = c₀[k] ± row·z`.
fn validity_terms(mode: Mode, lim: Limits) -> [(f64, usize); 2] {
    let l = |k: i8| if k > 0 { lim.u_max } else { lim.u_min };
    match mode {
        Mode::Free => [(lim.u_max, 0), (-lim.u_min, 0)],
        Mode::Sat(k) => [(-f64::from(k) * l(k), 0), (f64::INFINITY, 0)],
        Mode::Clamp(k) | Mode::Integ(k) => [(-f64::from(k) * l(k), 0), (0.0, 1)],
        Mode::Slide(_) => [(0.0, 2), (0.0, 3)],
    }
}

/// The mode's validity functions (both ≥ 0 while the mode holds).
fn validity(mode: Mode, p: Point, lim: Limits) -> [f64; 2] {
    let l = |k: i8| if k > 0 { lim.u_max } else { lim.u_min };
    match mode {
        Mode::Free => [lim.u_max - p.v, p.v - lim.u_min],
        Mode::Sat(k) => [f64::from(k) * (p.v - l(k)), f64::INFINITY],
        Mode::Clamp(k) => [f64::from(k) * (p.v - l(k)), f64::from(k) * p.e],
        Mode::Integ(k) => [f64::from(k) * (p.v - l(k)), -f64::from(k) * p.e],
        Mode::Slide(k) => [-f64::from(k) * p.s, f64::from(k) * (p.e + p.s)],
    }
}

/// Conditional: the mode entered when `v` reaches `L_σ` (with `v̇` pointing out) or is found
/// at it: the integral's input `e` and `s = v̇_rest` decide (module docs).
fn entry(k: i8, p: Point) -> Mode {
    let (e, s) = (f64::from(k) * p.e, f64::from(k) * p.s);
    if e <= 0.0 {
        if e + s > 0.0 {
            Mode::Integ(k)
        } else {
            Mode::Free
        }
    } else if s >= 0.0 {
        Mode::Clamp(k)
    } else if e + s > 0.0 {
        Mode::Slide(k)
    } else {
        Mode::Free
    }
}

/// The mode after validity function `which` of `mode` reached zero at the point `p`.
fn transition(mode: Mode, which: usize, p: Point, conditional: bool) -> Mode {
    match (mode, which) {
        (Mode::Free, _) => {
            let k = if which == 0 { 1 } else { -1 };
            if conditional {
                match entry(k, p) {
                    // v̇ = 0 at the limit (a tangency): the side's least stiff mode
                    Mode::Free if f64::from(k) * p.e > 0.0 => Mode::Slide(k),
                    Mode::Free => Mode::Integ(k),
                    m => m,
                }
            } else {
                Mode::Sat(k)
            }
        }
        (Mode::Sat(_), _) | (Mode::Integ(_), 0) => Mode::Free,
        (Mode::Clamp(k), 0) => {
            if f64::from(k) * (p.e + p.s) > 0.0 {
                Mode::Slide(k)
            } else {
                Mode::Free
            }
        }
        (Mode::Clamp(k), _) => Mode::Integ(k),
        (Mode::Integ(k), _) | (Mode::Slide(k), 0) => Mode::Clamp(k),
        (Mode::Slide(_), _) => Mode::Free,
    }
}

/// The mode of a state found after a jump (a set-point step, a biproper plant's or a
/// derivative's jump): `v` beyond a limit, at it, or inside.
fn classify(mode: Mode, p: Point, lim: Limits, conditional: bool, eps: f64) -> Mode {
    for k in [1i8, -1] {
        let l = if k > 0 { lim.u_max } else { lim.u_min };
        if !l.is_finite() {
            continue;
        }
        let d = f64::from(k) * (p.v - l);
        if d > eps {
            return match (conditional, f64::from(k) * p.e > 0.0) {
                (false, _) => Mode::Sat(k),
                (true, true) => Mode::Clamp(k),
                (true, false) => Mode::Integ(k),
            };
        }
        if d >= -eps {
            return if conditional {
                entry(k, p)
            } else if mode == Mode::Sat(k) {
                mode
            } else {
                Mode::Free
            };
        }
    }
    Mode::Free
}

/// Simulates the continuous loop with limits (module docs). A run whose step the piece cap set
/// above the neutral rule's is checked against a second run at about twice the step and
/// refused if they differ by more than 1e-9 (`super::neutral::checked`; no retry at a finer
/// step: switches add pieces the step cannot foresee).
pub(crate) fn integrate(
    plant: &Plant,
    c: &Controller,
    sc: &Scenario,
    lim: Limits,
    aw: AntiWindup,
) -> Result<SatRun> {
    let theta = plant.delay;
    let m = SatLoop::new(
        plant,
        c,
        aw,
        sc.setpoint.size != 0.0 && sc.setpoint.time <= sc.t_end,
    )?;
    let h = sat_step(&m, theta, sc);
    super::neutral::checked(
        (theta, m.e.abs()),
        theta,
        h,
        sc.t_end,
        |_| None,
        |h| integrate_at(&m, theta, sc, lim, h),
        |r| &r.traj,
    )
}

/// The internal step of the loop with limits.
fn sat_step(m: &SatLoop, theta: f64, sc: &Scenario) -> f64 {
    // grid h = θ/N (θ = 0: t_end/N), h ≤ FAST_STEP/ρ over every mode's matrix,
    // N ≥ DELAY_PIECES, the neutral bound, as the one-delay loop (`single::internal_step`):
    // not by dt. Every limit switch on a piece is found on the interpolant of its validity
    // functions (`switch_first`: Bernstein sign test, not the node values), so an excursion
    // past a limit between two nodes is seen (until branch satsw the node test kept h ≤ dt).
    let rho =
        m.a.iter()
            .fold(0.0f64, |r, a| r.max(crate::numerics::spectral_radius(a)));
    let mut hmax = sc.t_end;
    if rho > 0.0 {
        hmax = hmax.min(FAST_STEP / rho);
    }
    if theta > 0.0 {
        hmax = hmax.min(theta / DELAY_PIECES);
    }
    // the unsaturated mode is the linear loop, neutral when 0 < |e| < 1 (e = −L(j∞)): the
    // one-delay loop's bound (`single::neutral_bound`; at a limit u is constant, no neutral term)
    if let Some(b) = neutral_bound(theta, m.e.abs(), sc.t_end, MAX_PIECES) {
        hmax = hmax.min(b);
    }
    divisor_step(if theta > 0.0 { theta } else { sc.t_end }, hmax)
}

/// [`integrate`] on the grid `h` (a divisor of `θ`, or of `t_end` without a dead time).
fn integrate_at(m: &SatLoop, theta: f64, sc: &Scenario, lim: Limits, h: f64) -> Result<SatRun> {
    let conditional = m.cond.is_some();
    let n = m.order();
    let sz = n + NODES + 2;
    let tol = 1e-9 * h;
    let t_end = sc.t_end;
    if t_end / h > MAX_PIECES as f64 {
        return Err(Error::new(
            "scenario.t_end",
            format!(
                "the loop needs an internal step of {h:.3e}; {:.0} pieces exceed the limit \
                 {MAX_PIECES}: shorten t_end",
                t_end / h
            ),
        ));
    }
    let mut cuts = Cuts {
        h,
        at: BTreeMap::new(),
    };
    // a step's copy one dead time later (θ = N·h; θ = 0: N = 0)
    let n_theta = (theta / h).round();
    let copy = |c: GridTime| GridTime {
        g: c.g + n_theta,
        off: c.off,
    };
    for ev in [&sc.setpoint, &sc.disturbance] {
        if ev.size != 0.0 && ev.time <= t_end {
            // (an event on a grid point, within tol, is no cut: the grid cuts there)
            let g = ((ev.time + tol) / h).floor();
            let off = ev.time - g * h;
            if off > tol && off < h - tol {
                cuts.add(GridTime { g, off });
            }
        }
    }
    // V⁻¹ column by column (the monomial coefficients of the delayed input from its nodes)
    let vinv: Vec<f64> = start_interpolation_inverse()?.as_slice().to_vec();
    let forms = PieceForms::shared();
    let mut props = PropCache::default();
    // room for the grid's pieces and as many cuts again, at most 2¹⁶ pieces (4 MB a vector;
    // they grow beyond that)
    let est = (2 * ((t_end / h).ceil() as usize + 2)).min(1 << 16);
    let mut traj = Trajectory {
        h,
        offsets: vec![0.0],
        lens: Vec::with_capacity(est),
        starts: Some(Vec::with_capacity(est)),
        n_pieces: 0,
        v: Vec::with_capacity(est * NODES),
        y: Vec::with_capacity(est * NODES),
        setpoint: sc.setpoint,
        disturbance: sc.disturbance,
        tol,
    };
    let mut v_nodes: Vec<f64> = Vec::with_capacity(est * NODES);
    let mut held: Vec<f64> = Vec::with_capacity(est);
    let mut record = LimitRecord {
        limits: lim,
        intervals: vec![],
    };
    let scale = sc.setpoint.size.abs().max(sc.disturbance.size.abs());
    let limit = 1e8 * scale.max(f64::MIN_POSITIVE);
    let vscale = [lim.u_min, lim.u_max]
        .iter()
        .filter(|x| x.is_finite())
        .fold(scale.max(1.0), |m, x| m.max(x.abs()));
    // round-off thresholds of the switching functions: v (units of u) and rates (u per time)
    let eps = 1e-12 * vscale;
    let eps_rate = eps / h;
    let lval = |mode: Mode| match mode.side() {
        1 => lim.u_max,
        -1 => lim.u_min,
        _ => 0.0,
    };
    let mut x = vec![0.0; n];
    let mut mode = Mode::Free;
    let mut sat_since = 0.0;
    let mut t = 0.0;
    let mut pos = GridTime { g: 0.0, off: 0.0 };
    let mut diverged_at = None;
    let mut just_switched = false;
    let mut zero_switches = 0usize;
    let step_at = |s: &super::Step, t: f64| {
        if s.size != 0.0 && t >= s.time - tol {
            s.size
        } else {
            0.0
        }
    };
    // work buffers (no allocation per piece)
    let mut wn = [0.0; NODES];
    let mut xi = [0.0; NODES];
    // the piece's start state, its switching functions at the nodes, its end state
    let mut zs = vec![0.0; sz];
    let mut x_end = vec![0.0; end_len(n)];
    let mut pts = [Point::default(); NODES];
    // the delayed input's node values on [t0, t1] (one earlier piece's restriction) into `wn`
    let direct = m.direct;
    let cursor = std::cell::Cell::new(0usize);
    let wv = |wn: &mut [f64; NODES], t0: f64, t1: f64, traj: &Trajectory| {
        wn.fill(0.0);
        if direct {
            // θ = 0: the w slot carries the load d (constant on the piece)
            wn.fill(step_at(&sc.disturbance, t0));
            return;
        }
        let (a, b) = (t0 - theta, t1 - theta);
        if b <= tol || traj.n_pieces == 0 {
            return;
        }
        // the piece holding the window: a cursor that moves with time (no search per piece;
        // the same piece as `traj.locate`)
        let mid = 0.5 * (a + b);
        let starts = traj.starts.as_deref().unwrap_or(&[]);
        let np = traj.n_pieces.min(starts.len());
        let mut k = cursor.get().min(np.saturating_sub(1));
        while k + 1 < np && starts[k + 1] <= mid + tol {
            k += 1;
        }
        while k > 0 && starts[k] > mid + tol {
            k -= 1;
        }
        cursor.set(k);
        let (p0, pl) = traj.piece(k);
        let vals = traj.v_nodes(k);
        if (a - p0).abs() <= tol && (b - p0 - pl).abs() <= tol {
            // the window is that piece (a grid step, or the copy of a cut one dead time
            // earlier: the usual case): its nodes, as the one-delay loop takes them
            wn.copy_from_slice(vals);
            return;
        }
        for (i, wi) in wn.iter_mut().enumerate() {
            let s = (a + (b - a) * i as f64 / DEG as f64 - p0) / pl;
            *wi = lagrange(vals, s);
        }
    };
    // `(applied u, reported v)` of a mode at a point
    let uv = |mode: Mode, p: Point| match mode {
        Mode::Free => (p.v, p.v),
        Mode::Slide(_) => (lval(mode), lval(mode)),
        _ => (lval(mode), p.v),
    };
    // the time at a limit: an interval opens when u leaves the linear law and closes on return
    let switch_at = |record: &mut LimitRecord, since: &mut f64, from: Mode, to: Mode, at: f64| {
        if from == Mode::Free && to != Mode::Free {
            *since = at;
        } else if from != Mode::Free && to == Mode::Free {
            record.intervals.push((*since, at));
        }
    };
    // the pieces run on to the first grid point after t_end (as the one-delay loop's steps
    // do), so that the sample at t_end is a right-hand limit like every other sample (on a
    // neutral loop t_end can be a jump t_e + kθ of u)
    let t_stop = ((t_end + tol) / h).ceil().max(1.0) * h;
    while t < t_stop - tol {
        if traj.n_pieces >= MAX_PIECES {
            return Err(Error::new(
                "scenario.t_end",
                format!("more than {MAX_PIECES} pieces (limit switches): shorten t_end"),
            ));
        }
        let mut end = GridTime {
            g: pos.g + 1.0,
            off: 0.0,
        };
        let mut t1 = end.at(h);
        if let Some((cn, c)) = cuts.next_after(t, tol) {
            if cn < t1 - tol {
                (t1, end) = (cn, c);
            }
        }
        let mut len = pos.to(end, h);
        let r = step_at(&sc.setpoint, t);
        let d = step_at(&sc.disturbance, t);
        let z = &mut zs[..sz];
        z[..n].copy_from_slice(&x);
        wv(&mut wn, t, t1, &traj);
        col_major_rows::<NODES>(&vinv, &wn, &mut xi);
        z[n..n + NODES].copy_from_slice(&xi);
        z[n + NODES] = r;
        z[n + NODES + 1] = lval(mode);
        // a jump across a switching surface at the piece start re-classifies the mode here
        // (not right after a located switch: there the function is zero to round-off)
        if !just_switched {
            let p = m.point(z, len, mode);
            let f = validity(mode, p, lim);
            let off = matches!(mode, Mode::Slide(_)) && (p.v - lval(mode)).abs() > eps;
            let e0 = if matches!(mode, Mode::Slide(_)) {
                eps_rate
            } else {
                eps
            };
            let e1 = if conditional && mode != Mode::Free {
                eps_rate
            } else {
                eps
            };
            if off || f[0] < -e0 || f[1] < -e1 {
                let new_mode = classify(mode, p, lim, conditional, eps);
                if new_mode != mode {
                    switch_at(&mut record, &mut sat_since, mode, new_mode, t);
                    if (mode == Mode::Free) != (new_mode == Mode::Free) {
                        cuts.add(copy(pos));
                    }
                    mode = new_mode;
                    z[n + NODES + 1] = lval(mode);
                }
            }
        }
        if let Mode::Slide(_) = mode {
            // on the sliding surface the integral holds v at the limit
            let p = m.point(&zs[..sz], len, mode);
            zs[0] += (lval(mode) - p.v) / m.g[0];
        }
        let mi = mode.kind();
        let mut pp = props.get(m, mi, len);
        pp.propagate(&zs, &mut pts, &mut x_end);
        // the first place on the piece where a validity function turns negative (on its
        // interpolant: `switch_first`), refined on the exact function
        let first = switch_first(&SwitchScan {
            m,
            forms,
            z0: &zs,
            pts: &pts,
            pp,
            kind: mi,
            mode,
            len,
            lim,
            xtol: 1e-15 * (t + len).max(1.0),
        });
        let mut switch_to = None;
        if let Some((tau, k)) = first {
            let zt = (m.augmented(mi, len) * tau).exp() * DVector::from_column_slice(&zs[..sz]);
            let to = transition(mode, k, m.point(zt.as_slice(), len, mode), conditional);
            switch_to = Some(to);
            if tau <= tol {
                // at the piece start: switch now and redo the piece
                zero_switches += 1;
                if zero_switches > 16 {
                    return Err(Error::new(
                        "actuator",
                        format!(
                            "internal: the limit modes chatter at t = {t} (mode {mode:?}); \
                             please report this loop"
                        ),
                    ));
                }
                switch_at(&mut record, &mut sat_since, mode, to, t);
                if (mode == Mode::Free) != (to == Mode::Free) {
                    cuts.add(copy(pos));
                }
                mode = to;
                just_switched = true;
                continue;
            }
            end = pos.plus(tau, h, tol);
            t1 = end.at(h);
            wv(&mut wn, t, t1, &traj);
            col_major_rows::<NODES>(&vinv, &wn, &mut xi);
            zs[n..n + NODES].copy_from_slice(&xi);
            len = pos.to(end, h);
            pp = props.get(m, mi, len);
            pp.propagate(&zs, &mut pts, &mut x_end);
        }
        zero_switches = 0;
        // store the piece: applied u + d at the nodes, y, v
        let mut bad = false;
        for p in pts {
            let y = p.y;
            let (u, v) = uv(mode, p);
            if !(v.abs() <= limit && y.abs() <= limit) {
                bad = true;
            }
            traj.v.push(u + d);
            traj.y.push(y);
            v_nodes.push(v);
        }
        held.push(if mode == Mode::Free {
            f64::NAN
        } else {
            lval(mode)
        });
        if let Some(s) = traj.starts.as_mut() {
            s.push(t);
        }
        traj.lens.push(len);
        traj.n_pieces += 1;
        x.copy_from_slice(&x_end[..n]);
        if let Mode::Slide(_) = mode {
            x[0] += (lval(mode) - pts[DEG].v) / m.g[0];
        }
        if bad || !x.iter().all(|q| q.is_finite()) {
            diverged_at = Some(t);
            let k = traj.n_pieces - 1;
            traj.keep_pieces(k);
            traj.lens.truncate(k);
            if let Some(s) = traj.starts.as_mut() {
                s.truncate(k);
            }
            v_nodes.truncate(k * NODES);
            held.truncate(k);
            break;
        }
        // a non-grid cut propagates its copy one dead time later (a switch only when it
        // changes the applied u's law)
        let on_grid = end.off <= tol;
        let u_switch = switch_to.is_some_and(|to| (to == Mode::Free) != (mode == Mode::Free));
        if !on_grid && (cuts.contains(t1, tol) || u_switch) {
            cuts.add(copy(end));
        }
        if let Some(to) = switch_to {
            switch_at(&mut record, &mut sat_since, mode, to, t1);
            mode = to;
        }
        just_switched = switch_to.is_some();
        (t, pos) = (t1, end);
    }
    if mode != Mode::Free {
        record.intervals.push((sat_since, t));
    }
    // the record covers [0, t_end] (the last piece may end after it)
    record.intervals.retain(|(a, _)| *a < t_end - tol);
    for iv in record.intervals.iter_mut() {
        iv.1 = iv.1.min(t_end);
    }
    Ok(SatRun {
        traj,
        v_nodes,
        held,
        diverged_at,
        record,
    })
}

/// What [`switch_first`] scans: the piece's start state `z0` (mode `mode`, its matrices
/// `kind`, length `len`, propagator `pp`), the switching functions at its nodes `pts`, and
/// Brent's tolerance.
struct SwitchScan<'a> {
    m: &'a SatLoop,
    forms: &'a PieceForms,
    z0: &'a [f64],
    pts: &'a [Point; NODES],
    pp: &'a PieceProp,
    kind: usize,
    mode: Mode,
    len: f64,
    lim: Limits,
    xtol: f64,
}

/// The first limit switch on a piece: `(τ, k)`, the earliest time at which validity function
/// `k` of the mode turns negative, or `None`.
///
/// Each validity function is affine in the augmented state, `f(τ) = c₀ + c·exp(Mτ)·z₀`, so
/// along the piece it is smooth and its degree-`DEG` interpolant `p` through the node values
/// agrees with it to the interpolation accuracy the step rules hold (docs/PERFORMANCE.md "The step no
/// longer follows dt"). `p`'s Bernstein coefficients on the piece bound it (convex hull): all
/// above `−δ` (below), `p` stays above `−δ` and the mode holds on the whole piece, the usual
/// case, decided by 8 sums. Otherwise the first place `σ₁` where `p` reaches `−δ` is isolated
/// by halving and bisection ([`first_crossing`]), and the exact `f` is bracketed around
/// `σ₁·len` (probes at distances doubling from `2⁻²⁰·len`, bounded by the piece's start and
/// by the end of `p`'s dip below `−δ`: the interpolation error, ~1e-10 of `f`'s range, shifts
/// a zero by about that fraction of the piece, so the first probe usually brackets it; each
/// probe costs an exponential) and its zero located by Brent's method to round-off. A dip of
/// `p` that the exact `f` does not share (a graze within the interpolation error) is no switch.
///
/// The threshold `δ` is the round-off of `p`, so that only a turn to negative beyond
/// round-off counts (after a located switch the function starts at 0 to round-off, and
/// the mode just entered must not be left again at once). The node values are
/// `f_j = c₀ + (c·Φʲ)·z₀` ([`PieceProp`]: `Φ` the cached step exponential, the row `c·Φʲ`
/// formed by `j ≤ DEG` products, each with a componentwise error ≤ `sz·ε` times the terms it
/// sums, then one more sum of `sz + 1` terms with `z₀`), so with
/// `S_j = |c₀| + (|c|·|Φ|ʲ)·|z₀|`, the size of the terms that cancel in `f_j`,
/// `|δf_j| ≤ ((DEG + 1)·sz + 1)·ε·S_j`; the Bernstein coefficients are fixed combinations of
/// the `f_j` (row sums of magnitudes ≤ `val_norm`, plus the `NODES`-term sum's own
/// `NODES·ε·val_norm·max|f_j|`, `|f_j| ≤ S_j`), and `p` is a convex combination of them:
/// `δ = val_norm·((DEG + 1)·sz + 1 + NODES)·ε·S` with `S = |c₀| + max_j (|c|·|Φ|ʲ)·|z₀| ≥
/// max_j S_j` (the row `max_j |c|·|Φ|ʲ` is [`PieceProp::bound`]). Until branch satprop the
/// node states were formed one product at a time and `S` took `|z_j|` in place of
/// `|Φ|ʲ·|z₀|` (no larger: the bound is now the same or looser by the cancellations within
/// `Φʲ·z₀`, still of the order of `ε` times the terms).
fn switch_first(sw: &SwitchScan) -> Option<(f64, usize)> {
    let SwitchScan {
        m,
        forms,
        z0,
        pts,
        pp,
        kind,
        mode,
        len,
        lim,
        xtol,
    } = *sw;
    let sz = z0.len();
    let val = |z: &[f64]| validity(mode, pp.point(z), lim);
    let terms = validity_terms(mode, lim);
    let gamma = ((DEG + 1) * sz + 1 + NODES) as f64 * f64::EPSILON * forms.val_norm;
    let mut first: Option<(f64, usize)> = None;
    let mut big: Option<(DMatrix<f64>, DVector<f64>)> = None;
    // both functions at the nodes
    let mut fboth = [[0.0; 2]; NODES];
    for (fj, p) in fboth.iter_mut().zip(pts) {
        *fj = validity(mode, *p, lim);
    }
    for (k, &(c0, ai)) in terms.iter().enumerate() {
        if !c0.is_finite() {
            // an absent limit (or the sat mode's second function): never reached
            continue;
        }
        let mut fv = [0.0; NODES];
        for (f, fj) in fv.iter_mut().zip(&fboth) {
            *f = fj[k];
        }
        // S = |c₀| + max_j (|c|·|Φ|ʲ)·|z₀| ≥ max_j S_j
        let s_max = c0.abs()
            + pp.bound[ai]
                .iter()
                .zip(z0)
                .map(|(b, x)| b * x.abs())
                .sum::<f64>();
        let thr = gamma * s_max;
        // Bernstein coefficients of p + δ (p's shifted by the constant δ: a partition of unity)
        let mut q = [0.0; NODES];
        for (qi, row) in q.iter_mut().zip(&forms.val) {
            *qi = row.iter().zip(&fv).map(|(a, f)| a * f).sum::<f64>() + thr;
        }
        if q.iter().all(|x| *x > 0.0) {
            continue;
        }
        let s1 = if q[0] <= 0.0 {
            0.0
        } else {
            match first_crossing(&q, 0.0, 1.0, ZERO_DEPTH, &q) {
                Some(s) => s,
                None => continue,
            }
        };
        let p_at = |s: f64| casteljau(&q, s) - thr;
        let (big, z0) =
            &*big.get_or_insert_with(|| (m.augmented(kind, len), DVector::from_column_slice(z0)));
        let f_at = |tau: f64| -> f64 {
            if tau <= 0.0 {
                return fv[0];
            }
            let zt = (big * tau).exp() * z0;
            val(zt.as_slice())[k]
        };
        let tau1 = s1 * len;
        let f1 = f_at(tau1);
        let d0 = len * (-20.0f64).exp2();
        // a bracket [a, b] of the exact f's zero: f(a) > 0 ≥ f(b) (a = 0 with f(0) ≤ 0: at
        // the start)
        let bracket = if f1 <= 0.0 {
            let (mut b, mut fb, mut d) = (tau1, f1, d0);
            loop {
                let a = (tau1 - d).max(0.0);
                let fa = f_at(a);
                if fa > 0.0 {
                    break Some((a, b, fa, fb));
                }
                if a <= 0.0 {
                    break Some((0.0, 0.0, fa, fa));
                }
                (b, fb, d) = (a, fa, 2.0 * d);
            }
        } else {
            let (mut a, mut fa, mut d) = (tau1, f1, d0);
            loop {
                let b = (tau1 + d).min(len);
                let fb = f_at(b);
                if fb <= 0.0 {
                    break Some((a, b, fa, fb));
                }
                // past p's dip (or the piece's end) with f still positive: a graze
                if b >= len || p_at(b / len) > 0.0 {
                    break None;
                }
                (a, fa, d) = (b, fb, 2.0 * d);
            }
        };
        let Some((a, b, fa, fb)) = bracket else {
            continue;
        };
        let tau = if b <= 0.0 || fb == 0.0 {
            b
        } else {
            match brent(f_at, a, b, fa, fb, xtol, 200) {
                Some((x, _)) => x,
                None => continue,
            }
        };
        if first.is_none_or(|(t0, _)| tau < t0) {
            first = Some((tau, k));
        }
    }
    first
}
