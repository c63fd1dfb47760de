//! Loops with several exact dead times: the model-based set-point structures of
//! [`ModelLoop`](crate::model::controller::ModelLoop) (an internal process model with its own dead
//! time θ_m beside the plant's θ).
//!
//! ## Method
//! The loop is written over the stacked vector `ζ = [x; w; r; d]` (all states, the `m` delayed
//! channel inputs, set point, load) as rows: `ẋ = F ζ`, channel signals `s_j = S_j ζ` with
//! `w_j(t) = s_j(t − τ_j)`, `y = Y ζ`, `u = U ζ`. Channel 0 is the plant input `v = u + d`
//! (delay θ), channel 1 the model input `u₁` (delay θ_m). Zero delays are eliminated
//! algebraically.
//!
//! It is integrated like the one-delay loop of [`crate::sim`] (every piece: the delayed inputs
//! interpolated at degree [`DEG`] (7) from their history, the state equation integrated exactly by an
//! augmented matrix exponential), but on an explicit piece list: a uniform grid of step
//! `h ≤ min(0.55/ρ(A), min τ_j/3, t_end)` (and, on a neutral loop, the bound of `internal_step`;
//! not `dt`: the samples `k·dt` are read on the piece polynomials)
//! cut at every point `t_e + Σ k_j τ_j ≤ t_end` that an event `t_e` can reach through the
//! delays. Every discontinuity of the response (of any order)
//! therefore sits on a piece boundary, and the history a piece reads back (one delay earlier)
//! is smooth, so the error stays `O(h⁸)` for any ratio θ/θ_m. A piece of the grid length
//! reuses one propagator; the cut pieces get their own.

use crate::error::{Error, Result};
use crate::model::controller::Controller;
use crate::model::plant::Plant;
use crate::model::ss::{balance, realize, realize_paths, Ss};
use crate::sim::single::{divisor_step, neutral_bound, DELAY_PIECES, FAST_STEP};
use crate::sim::{
    interpolation_inverse, lagrange, piece_exponential, sample, Response, Scenario, Trajectory,
    DEG, NODES,
};
use nalgebra::{DMatrix, DVector};
use std::collections::hash_map::Entry;
use std::collections::HashMap;

/// Hard caps: pieces of one simulation and event-reachable breakpoints.
const MAX_PIECES: usize = 1_000_000;
const MAX_BREAKS: usize = 200_000;

/// A linear loop with `m` delayed channels in row form (see the module docs).
#[derive(Debug, Clone)]
pub(crate) struct MultiModel {
    n: usize,
    m: usize,
    /// `ẋ = F ζ`, n × (n + m + 2).
    f: DMatrix<f64>,
    /// Channel signals, m × (n + m + 2).
    s: DMatrix<f64>,
    /// Output row.
    y: DVector<f64>,
    /// Controller-output row.
    u: DVector<f64>,
    /// Channel delays.
    delays: Vec<f64>,
}

/// Row builder over `ζ = [x (n); w (m); r; d]`.
struct Rows {
    n: usize,
    m: usize,
}

impl Rows {
    fn width(&self) -> usize {
        self.n + self.m + 2
    }
    fn zero(&self) -> DVector<f64> {
        DVector::zeros(self.width())
    }
    fn w(&self, j: usize) -> usize {
        self.n + j
    }
    fn r(&self) -> usize {
        self.n + self.m
    }
    fn d(&self) -> usize {
        self.n + self.m + 1
    }
}

/// Output row `C x + D w` of a SISO realization at state offset `o` driven by channel `j`,
/// and its derivative row (`None` when D ≠ 0: the derivative of a delayed input is not a
/// signal of the loop).
fn output_rows(rows: &Rows, ss: &Ss, o: usize, j: usize) -> (DVector<f64>, Option<DVector<f64>>) {
    let k = ss.order();
    let mut out = rows.zero();
    let mut der = rows.zero();
    for i in 0..k {
        out[o + i] = ss.c[(0, i)];
    }
    out[rows.w(j)] = ss.d[(0, 0)];
    // ẏ = C A x + C B w
    let ca = &ss.c * &ss.a;
    for i in 0..k {
        der[o + i] = ca[(0, i)];
    }
    der[rows.w(j)] = (&ss.c * &ss.b)[(0, 0)];
    (out, (ss.d[(0, 0)] == 0.0).then_some(der))
}

/// The derivative row of a signal, or the error that explains why it does not exist.
fn need<'a>(
    kd: f64,
    der: &'a Option<DVector<f64>>,
    path: &str,
    what: &str,
) -> Result<Option<&'a DVector<f64>>> {
    if kd == 0.0 {
        return Ok(None);
    }
    match der {
        Some(d) => Ok(Some(d)),
        None => Err(Error::new(
            path,
            format!(
                "ideal derivative on {what}, which is biproper: the loop is ill-posed; add a \
                 derivative filter (N)"
            ),
        )),
    }
}

impl MultiModel {
    /// The loop of a controller with a model loop (see [`crate::model::controller::ModelLoop`]).
    pub(crate) fn new(plant: &Plant, c: &Controller, setpoint_step: bool) -> Result<MultiModel> {
        let ml = c
            .model_loop
            .as_ref()
            .ok_or_else(|| Error::new("controller.model_loop", "internal: missing"))?;
        let ps = realize(&plant.tf).map_err(|e| e.within("plant"))?;
        let ms = realize(&ml.model.tf).map_err(|e| e.within("controller.model_loop.model"))?;
        let (sl, kds) = realize_paths(&[
            (&ml.cr, "controller.model_loop.cr", 1.0),
            (&ml.cy, "controller.model_loop.cy", -1.0),
        ])?;
        let (cl, kdc) = realize_paths(&[
            (&c.cr, "controller.cr", 1.0),
            (&c.cy, "controller.cy", -1.0),
            (&c.cy, "controller.cy", 1.0),
        ])?;
        for (kd, path) in [
            (kds[0], "controller.model_loop.cr"),
            (kdc[0], "controller.cr"),
        ] {
            if kd != 0.0 && setpoint_step {
                return Err(Error::new(
                    path,
                    "ideal derivative on the set point: a set-point step gives an impulse in u; \
                     use a set-point weight, a set-point filter or a derivative filter (N)",
                ));
            }
        }
        let (np, nm, ns, nc) = (ps.order(), ms.order(), sl.order(), cl.order());
        let (op, om, os, oc) = (0, np, np + nm, np + nm + ns);
        let n = np + nm + ns + nc;
        let rows = Rows { n, m: 2 };
        let (y, ydot) = output_rows(&rows, &ps, op, 0);
        let (ym, ymdot) = output_rows(&rows, &ms, om, 1);
        // u₁ = C_s x_s + D_s[r; y_m] + k·ẏ_m   (the ṙ term is refused above for steps)
        let mut u1 = rows.zero();
        for i in 0..ns {
            u1[os + i] = sl.c[(0, i)];
        }
        u1[rows.r()] += sl.d[(0, 0)];
        u1 += &ym * sl.d[(0, 1)];
        if let Some(dr) = need(kds[1], &ymdot, "controller.model_loop.cy", "the model")? {
            u1 += dr * kds[1];
        }
        // u₂ = C_c x_c + D_c[r; y; y_m] + k_y·ẏ + k_m·ẏ_m
        let mut u2 = rows.zero();
        for i in 0..nc {
            u2[oc + i] = cl.c[(0, i)];
        }
        u2[rows.r()] += cl.d[(0, 0)];
        u2 += &y * cl.d[(0, 1)];
        u2 += &ym * cl.d[(0, 2)];
        if let Some(dr) = need(kdc[1], &ydot, "controller.cy", "the plant")? {
            u2 += dr * kdc[1];
        }
        if let Some(dr) = need(kdc[2], &ymdot, "controller.cy", "the model")? {
            u2 += dr * kdc[2];
        }
        let u = &u1 + &u2;
        let mut v = u.clone();
        v[rows.d()] += 1.0;
        // ẋ rows
        let mut f = DMatrix::zeros(n, rows.width());
        for i in 0..np {
            for k in 0..np {
                f[(op + i, op + k)] = ps.a[(i, k)];
            }
            f[(op + i, rows.w(0))] = ps.b[(i, 0)];
        }
        for i in 0..nm {
            for k in 0..nm {
                f[(om + i, om + k)] = ms.a[(i, k)];
            }
            f[(om + i, rows.w(1))] = ms.b[(i, 0)];
        }
        for i in 0..ns {
            let mut row = &ym * sl.b[(i, 1)];
            row[rows.r()] += sl.b[(i, 0)];
            for k in 0..ns {
                row[os + k] += sl.a[(i, k)];
            }
            f.row_mut(os + i).copy_from(&row.transpose());
        }
        for i in 0..nc {
            let mut row = &y * cl.b[(i, 1)] + &ym * cl.b[(i, 2)];
            row[rows.r()] += cl.b[(i, 0)];
            for k in 0..nc {
                row[oc + k] += cl.a[(i, k)];
            }
            f.row_mut(oc + i).copy_from(&row.transpose());
        }
        let mut s = DMatrix::zeros(2, rows.width());
        s.row_mut(0).copy_from(&v.transpose());
        s.row_mut(1).copy_from(&u1.transpose());
        let mut mm = MultiModel {
            n,
            m: 2,
            f,
            s,
            y,
            u,
            delays: vec![plant.delay, ml.model.delay],
        };
        mm.eliminate_zero_delays()?;
        mm.balance();
        Ok(mm)
    }

    /// Channels with no delay (`w_j = s_j`) solved algebraically and substituted everywhere;
    /// their columns are then zero.
    fn eliminate_zero_delays(&mut self) -> Result<()> {
        let z: Vec<usize> = (0..self.m).filter(|&j| self.delays[j] == 0.0).collect();
        if z.is_empty() {
            return Ok(());
        }
        let cols: Vec<usize> = z.iter().map(|&j| self.n + j).collect();
        let k = z.len();
        // w_Z = S_Z ζ → (I − E_ZZ) w_Z = S_Z ζ with the w_Z columns zeroed
        let mut ezz = DMatrix::identity(k, k);
        let mut rhs = DMatrix::zeros(k, self.n + self.m + 2);
        for (a, &j) in z.iter().enumerate() {
            for (b, &cb) in cols.iter().enumerate() {
                ezz[(a, b)] -= self.s[(j, cb)];
            }
            let mut row = self.s.row(j).into_owned();
            for &cb in &cols {
                row[cb] = 0.0;
            }
            rhs.row_mut(a).copy_from(&row);
        }
        let sol = ezz
            .lu()
            .solve(&rhs)
            .filter(|m| m.iter().all(|x| x.is_finite()));
        let sol = sol.ok_or_else(|| {
            Error::new(
                "controller",
                "the loop is ill-posed: 1 + L(j∞) = 0 with no dead time",
            )
        })?;
        let subst = |row: &mut DVector<f64>| {
            let coef: Vec<f64> = cols.iter().map(|&c| row[c]).collect();
            for &c in &cols {
                row[c] = 0.0;
            }
            for (a, cf) in coef.iter().enumerate() {
                if *cf != 0.0 {
                    *row += sol.row(a).transpose() * *cf;
                }
            }
        };
        for i in 0..self.n {
            let mut row = self.f.row(i).transpose();
            subst(&mut row);
            self.f.row_mut(i).copy_from(&row.transpose());
        }
        for j in 0..self.m {
            let mut row = self.s.row(j).transpose();
            subst(&mut row);
            self.s.row_mut(j).copy_from(&row.transpose());
        }
        subst(&mut self.y);
        subst(&mut self.u);
        Ok(())
    }

    /// Balances the state coordinates (`x = S x̃`) for a well-scaled exponential.
    fn balance(&mut self) {
        let n = self.n;
        let sc = balance(&self.f.view((0, 0), (n, n)).into_owned());
        for i in 0..n {
            for c in 0..self.f.ncols() {
                self.f[(i, c)] /= sc[i];
            }
            for r in 0..n {
                self.f[(r, i)] *= sc[i];
            }
            for j in 0..self.m {
                self.s[(j, i)] *= sc[i];
            }
            self.y[i] *= sc[i];
            self.u[i] *= sc[i];
        }
    }

    /// The smallest nonzero channel delay (0 without one).
    fn min_delay(&self) -> f64 {
        let positive = self.delays.iter().copied().filter(|d| *d > 0.0);
        positive.reduce(f64::min).unwrap_or(0.0)
    }

    /// The neutral part's gain: the spectral radius of `|E|`, `E` the channel signals'
    /// coefficients on the delayed channels (`s(t) = … + E·s(t − τ)`). Below 1 the difference
    /// equation is stable for every set of delays (Hale's strong stability); it plays the role
    /// of the one-delay loop's `|E|` in the neutral bound on the step (module docs of
    /// [`crate::sim`], "Near the neutral limit"), with the smallest delay as `θ`.
    fn neutral_gain(&self) -> f64 {
        let (n, m) = (self.n, self.m);
        let e = DMatrix::from_fn(m, m, |i, j| {
            if self.delays[i] > 0.0 && self.delays[j] > 0.0 {
                self.s[(i, n + j)].abs()
            } else {
                0.0
            }
        });
        crate::numerics::spectral_radius(&e)
    }

    fn a(&self) -> DMatrix<f64> {
        self.f.view((0, 0), (self.n, self.n)).into_owned()
    }

    /// Steady state `(y∞, u∞)` for constant `(r, d)`: `F ζ = 0`, `w = S ζ`.
    pub(crate) fn steady_state(&self, r: f64, d: f64) -> Option<(f64, f64)> {
        let (n, m) = (self.n, self.m);
        let k = n + m;
        let mut big = DMatrix::zeros(k, k);
        let mut rhs = DVector::zeros(k);
        for i in 0..n {
            for c in 0..k {
                big[(i, c)] = self.f[(i, c)];
            }
            rhs[i] = -(self.f[(i, k)] * r + self.f[(i, k + 1)] * d);
        }
        for j in 0..m {
            for c in 0..k {
                big[(n + j, c)] = self.s[(j, c)];
            }
            big[(n + j, n + j)] -= 1.0;
            rhs[n + j] = -(self.s[(j, k)] * r + self.s[(j, k + 1)] * d);
        }
        let norm = big.amax().max(1e-300);
        let sol = big.clone().lu().solve(&rhs)?;
        if !sol.iter().all(|z| z.is_finite()) {
            return None;
        }
        let res = &big * &sol - &rhs;
        if res.amax() > 1e-8 * norm * sol.amax().max(1.0) {
            return None;
        }
        let mut zeta = DVector::zeros(k + 2);
        zeta.rows_mut(0, k).copy_from(&sol);
        zeta[k] = r;
        zeta[k + 1] = d;
        let (y, u) = (self.y.dot(&zeta), self.u.dot(&zeta));
        (y.is_finite() && u.is_finite()).then_some((y, u))
    }
}

/// Propagators of one piece length (see `crate::sim`'s `Prop`), for `m` channels:
/// `z = [x₀ (n); w_j nodes (NODES each); r; d]`.
struct Prop {
    /// End state, row-major n × width.
    m_end: Vec<f64>,
    /// Rows of the channel signals at nodes 1..=DEG: `[node][channel]`.
    srows: Vec<Vec<Vec<f64>>>,
    /// Rows of y at nodes 1..=DEG.
    yrows: Vec<Vec<f64>>,
    /// Rows of u at nodes 1..=DEG.
    urows: Vec<Vec<f64>>,
}

fn propagators(mm: &MultiModel, len: f64, vinv: &DMatrix<f64>) -> Result<Prop> {
    let (n, m) = (mm.n, mm.m);
    let sz = n + NODES * m + 2;
    let (ir, id) = (n + NODES * m, n + NODES * m + 1);
    let (fr, fd) = (n + m, n + m + 1);
    let col = |c: usize| mm.f.column(c).into_owned();
    let bw: Vec<DVector<f64>> = (0..m).map(|j| col(n + j)).collect();
    let e1 = piece_exponential(&mm.a(), &bw, &col(fr), &col(fd), len)?;
    let width = sz;
    let mut p = Prop {
        m_end: vec![],
        srows: vec![],
        yrows: vec![],
        urows: vec![],
    };
    let mut ei = e1.clone();
    // a signal row over ζ = [x; w; r; d] mapped onto z at node i
    let map_row = |row: &DVector<f64>, mi: &DMatrix<f64>, i: usize| -> Vec<f64> {
        let mut out: Vec<f64> = (0..width)
            .map(|c| (0..n).fold(0.0, |acc, k| acc + row[k] * mi[(k, c)]))
            .collect();
        for j in 0..m {
            out[n + NODES * j + i] += row[n + j];
        }
        out[ir] += row[fr];
        out[id] += row[fd];
        out
    };
    for i in 1..=DEG {
        if i > 1 {
            ei = &ei * &e1;
        }
        let mut mi = DMatrix::zeros(n, width);
        mi.view_mut((0, 0), (n, n))
            .copy_from(&ei.view((0, 0), (n, n)));
        for j in 0..m {
            let o = n + NODES * j;
            mi.view_mut((0, o), (n, NODES))
                .copy_from(&(ei.view((0, o), (n, NODES)) * vinv));
        }
        mi.view_mut((0, ir), (n, 2))
            .copy_from(&ei.view((0, ir), (n, 2)));
        p.srows.push(
            (0..m)
                .map(|j| map_row(&mm.s.row(j).transpose(), &mi, i))
                .collect(),
        );
        p.yrows.push(map_row(&mm.y, &mi, i));
        p.urows.push(map_row(&mm.u, &mi, i));
        if i == DEG {
            p.m_end = (0..n)
                .flat_map(|r| (0..width).map(move |c| (r, c)))
                .map(|(r, c)| mi[(r, c)])
                .collect();
        }
    }
    Ok(p)
}

/// Every point `t_e + Σ k_j τ_j ≤ t_end` reachable from the events through the delays,
/// sorted, points closer than `tol` merged. Errors beyond `MAX_BREAKS` points.
fn breakpoints(events: &[f64], delays: &[f64], t_end: f64, tol: f64) -> Result<Vec<f64>> {
    let pos: Vec<f64> = delays.iter().copied().filter(|d| *d > 0.0).collect();
    let too_many = || {
        Error::new(
            "scenario.t_end",
            format!(
                "the dead times create more than {MAX_BREAKS} breakpoints before t_end; \
                 shorten t_end"
            ),
        )
    };
    // enumerate the multi-indices k with Σ k_j τ_j ≤ t_end − t_e (each delay used in order,
    // so every combination is visited once)
    fn walk(p: f64, j: usize, pos: &[f64], t_end: f64, tol: f64, out: &mut Vec<f64>) -> bool {
        if j == pos.len() {
            out.push(p);
            return out.len() <= MAX_BREAKS;
        }
        let mut q = p;
        while q <= t_end + tol {
            if !walk(q, j + 1, pos, t_end, tol, out) {
                return false;
            }
            q += pos[j];
        }
        true
    }
    let mut pts = Vec::new();
    for &e in events {
        if !walk(e, 0, &pos, t_end, tol, &mut pts) {
            return Err(too_many());
        }
    }
    crate::numerics::sort_f64(&mut pts);
    pts.dedup_by(|a, b| (*a - *b).abs() <= tol);
    Ok(pts)
}

/// Node values of channel `j`'s signal on `[t, t + len]` (its history, one delay earlier),
/// limits taken from inside the interval.
fn history(
    starts: &[f64],
    lens: &[f64],
    nodes: &[f64],
    c0: f64,
    len: f64,
    tol: f64,
    out: &mut [f64],
) {
    for (i, o) in out.iter_mut().enumerate() {
        let t = c0 + i as f64 * len / DEG as f64;
        let right = i < DEG; // right-hand limit except at the interval's right end
        if t < -tol || (!right && t <= tol) {
            *o = 0.0;
            continue;
        }
        let k = if right {
            starts.partition_point(|s| *s <= t + tol)
        } else {
            starts.partition_point(|s| *s < t - tol)
        }
        .saturating_sub(1);
        let sg = ((t - starts[k]) / lens[k]).clamp(0.0, 1.0);
        *o = lagrange(&nodes[k * NODES..(k + 1) * NODES], sg);
    }
}

/// Integrates the several-delay loop (see the module docs).
/// The internal step: at most `FAST_STEP/ρ(A)`, a third of every nonzero delay
/// (`single::DELAY_PIECES`), `t_end` and, on a neutral
/// loop, the one-delay loop's neutral bound (`single::neutral_bound`) with `|E|` = ρ(|E|) over
/// the delayed channels and `θ` the smallest delay; not `dt` (the samples are read on the piece
/// polynomials, as in the one-delay loop: `single::internal_step`).
fn internal_step(mm: &MultiModel, sc: &Scenario) -> f64 {
    let a = mm.a();
    let rho = if mm.n == 0 {
        0.0
    } else {
        crate::numerics::spectral_radius(&a)
    };
    let mut h = sc.t_end;
    if rho > 0.0 {
        h = h.min(FAST_STEP / rho);
    }
    for &d in &mm.delays {
        if d > 0.0 {
            h = h.min(d / DELAY_PIECES);
        }
    }
    if let Some(b) = neutral_bound(mm.min_delay(), mm.neutral_gain(), sc.t_end, MAX_PIECES) {
        h = h.min(b);
    }
    // a divisor of the plant's dead time, so that the plant channel's history nodes are nodes
    // of earlier pieces (copies, as in the one-delay loop) rather than interpolated: on a
    // neutral loop an interpolated history multiplies the error by the interpolation's
    // Lebesgue constant (> 1) times |E| every delay, which can grow (the boiler under
    // `praveen_kumar` at λ = 1.9, |E| = 0.82, with h = θ/18.46 diverged)
    let theta = mm.delays[0];
    if theta > 0.0 {
        divisor_step(theta, h)
    } else {
        // no plant delay: pieces that tile [0, t_end] (as `single::internal_step`)
        divisor_step(sc.t_end, h)
    }
}

/// Piece boundaries: the grid `k·h` (k = 0..=n_steps) merged with the breakpoints `brk` (a
/// grid point within `tol` of a breakpoint gives way to it).
fn piece_bounds(brk: &[f64], n_steps: usize, h: f64, tol: f64) -> Vec<f64> {
    let mut bounds: Vec<f64> = Vec::with_capacity(n_steps + brk.len() + 1);
    let mut bi = 0;
    for k in 0..=n_steps {
        let g = k as f64 * h;
        while bi < brk.len() && brk[bi] < g - tol {
            if bounds.last().is_none_or(|l| brk[bi] > l + tol) {
                bounds.push(brk[bi]);
            }
            bi += 1;
        }
        let near = bi < brk.len() && (brk[bi] - g).abs() <= tol;
        let p = if near { brk[bi] } else { g };
        if near {
            bi += 1;
        }
        if bounds.last().is_none_or(|l| p > l + tol) {
            bounds.push(p);
        }
    }
    bounds
}

/// Fills the node values of each delayed channel on piece `k` (`[t0, t0 + len)`) from the
/// channel's history one delay earlier; a channel without delay has none (zeros).
#[allow(clippy::too_many_arguments)]
fn fill_histories(
    mm: &MultiModel,
    z: &mut [f64],
    chans: &[Vec<f64>],
    starts: &[f64],
    lens: &[f64],
    k: usize,
    tol: f64,
) {
    let (n, m) = (mm.n, mm.m);
    let (t0, len) = (starts[k], lens[k]);
    for j in 0..m {
        let seg = &mut z[n + NODES * j..n + NODES * (j + 1)];
        if mm.delays[j] > 0.0 {
            history(
                &starts[..k],
                &lens[..k],
                &chans[j],
                t0 - mm.delays[j],
                len,
                tol,
                seg,
            );
        } else {
            seg.fill(0.0);
        }
    }
}

/// [`integrate`] at the rule's step ([`internal_step`]); a run whose step the piece cap set
/// above the neutral rule's is checked against a second run at about twice the step and
/// refused if they differ by more than 1e-9 (`super::neutral::checked`; no retry at a finer
/// step: the breakpoints add pieces).
fn integrate_checked(mm: &MultiModel, sc: &Scenario) -> Result<(Trajectory, Option<f64>)> {
    // the grid divides the plant's dead time (or t_end without one): `internal_step`
    let span = if mm.delays[0] > 0.0 {
        mm.delays[0]
    } else {
        sc.t_end
    };
    super::neutral::checked(
        (mm.min_delay(), mm.neutral_gain()),
        span,
        internal_step(mm, sc),
        sc.t_end,
        |_| None,
        |h| integrate(mm, sc, h),
        |r| &r.0,
    )
}

/// Integrates the loop piece by piece (see the module docs): the continuous response and the
/// time divergence was detected, if it was.
fn integrate(mm: &MultiModel, sc: &Scenario, h: f64) -> Result<(Trajectory, Option<f64>)> {
    let tol = 1e-9 * h;
    let events: Vec<f64> = [&sc.setpoint, &sc.disturbance]
        .iter()
        .filter(|e| e.size != 0.0 && e.time <= sc.t_end)
        .map(|e| e.time)
        .collect();
    let brk = breakpoints(&events, &mm.delays, sc.t_end, tol)?;
    let n_steps = ((sc.t_end + tol) / h).ceil().max(1.0) as usize;
    if n_steps.saturating_add(brk.len()) > MAX_PIECES {
        return Err(Error::new(
            "scenario.t_end",
            format!(
                "the loop needs an internal step of {h:.3e}; more than {MAX_PIECES} pieces: \
                 shorten t_end"
            ),
        ));
    }
    let bounds = piece_bounds(&brk, n_steps, h, tol);
    let starts: Vec<f64> = bounds[..bounds.len() - 1].to_vec();
    let lens: Vec<f64> = bounds.windows(2).map(|w| w[1] - w[0]).collect();
    let total = starts.len();
    let vinv = interpolation_inverse()?;
    let uniform = propagators(mm, h, &vinv)?;
    let mut cache: HashMap<u64, Prop> = HashMap::new();
    let (n, m) = (mm.n, mm.m);
    let width = n + NODES * m + 2;
    let mut traj = Trajectory {
        h,
        offsets: vec![0.0],
        lens: lens.clone(),
        starts: Some(starts.clone()),
        n_pieces: 0,
        v: Vec::with_capacity(total * NODES),
        y: Vec::with_capacity(total * NODES),
        setpoint: sc.setpoint,
        disturbance: sc.disturbance,
        tol,
    };
    let mut chans: Vec<Vec<f64>> = vec![Vec::with_capacity(total * NODES); m];
    let scale = sc.setpoint.size.abs().max(sc.disturbance.size.abs());
    let limit = 1e8 * scale.max(f64::MIN_POSITIVE);
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).fold(0.0, |s, (x, y)| s + x * y);
    let mut z = vec![0.0; width];
    let mut xn = vec![0.0; n];
    let mut sig = vec![0.0; m]; // channel signals at one node
                                // the channel rows over ζ, contiguous (node 0 of every piece reads them)
    let srows0: Vec<Vec<f64>> = (0..m)
        .map(|j| mm.s.row(j).iter().copied().collect())
        .collect();
    let mut diverged_at = None;
    let (fr, fd) = (n + m, n + m + 1);
    for k in 0..total {
        let (t0, len) = (starts[k], lens[k]);
        let r = traj.step_at(&sc.setpoint, t0);
        let d = traj.step_at(&sc.disturbance, t0);
        fill_histories(mm, &mut z, &chans, &starts, &lens, k, tol);
        z[n + NODES * m] = r;
        z[n + NODES * m + 1] = d;
        let p = if (len - h).abs() <= 1e-12 * h {
            &uniform
        } else {
            match cache.entry(len.to_bits()) {
                Entry::Occupied(o) => &*o.into_mut(),
                Entry::Vacant(v) => &*v.insert(propagators(mm, len, &vinv)?),
            }
        };
        // node 0 directly from ζ₀ = [x₀; w(t₀); r; d]
        let at0 = |row: &[f64]| -> f64 {
            let mut s = dot(&row[..n], &z[..n]);
            for j in 0..m {
                s += row[n + j] * z[n + NODES * j];
            }
            s + row[fr] * r + row[fd] * d
        };
        let mut bad = false;
        let mut push =
            |chans: &mut Vec<Vec<f64>>, traj: &mut Trajectory, s: &[f64], y: f64, u: f64| {
                for (c, x) in chans.iter_mut().zip(s) {
                    c.push(*x);
                }
                let vv = u + d;
                if !(vv.abs() <= limit && f64::abs(y) <= limit) {
                    bad = true;
                }
                traj.v.push(vv);
                traj.y.push(y);
            };
        for (j, o) in sig.iter_mut().enumerate() {
            *o = at0(&srows0[j]);
        }
        push(
            &mut chans,
            &mut traj,
            &sig,
            at0(mm.y.as_slice()),
            at0(mm.u.as_slice()),
        );
        for i in 0..DEG {
            for (o, row) in sig.iter_mut().zip(&p.srows[i]) {
                *o = dot(row, &z);
            }
            let y = dot(&p.yrows[i], &z);
            let u = dot(&p.urows[i], &z);
            push(&mut chans, &mut traj, &sig, y, u);
        }
        for (row, xr) in xn.iter_mut().enumerate() {
            *xr = dot(&p.m_end[row * width..(row + 1) * width], &z);
        }
        z[..n].copy_from_slice(&xn);
        if traj.close_piece(k, bad, &xn) {
            diverged_at = Some(t0);
            break;
        }
    }
    Ok((traj, diverged_at))
}

/// Simulates a loop whose controller has a model loop (called by [`crate::sim::simulate`]).
pub(crate) fn simulate(plant: &Plant, c: &Controller, sc: &Scenario) -> Result<Response> {
    simulate_at(plant, c, sc, None)
}

/// [`simulate`] with the grid step `h` (`None`: the rule's, [`internal_step`]); `h` a divisor
/// of the plant's dead time (`super::simulate_at_step`).
pub(crate) fn simulate_at(
    plant: &Plant,
    c: &Controller,
    sc: &Scenario,
    h: Option<f64>,
) -> Result<Response> {
    let mm = MultiModel::new(
        plant,
        c,
        sc.setpoint.size != 0.0 && sc.setpoint.time <= sc.t_end,
    )?;
    let (traj, diverged_at) = match h {
        Some(h) => integrate(&mm, sc, h)?,
        None => integrate_checked(&mm, sc)?,
    };
    Ok(sample(sc, traj, diverged_at, &|r, d| mm.steady_state(r, d)))
}
