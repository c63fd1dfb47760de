//! Plant-aware parameter intervals: for a rule and the plant at hand, the interval of each
//! continuous parameter over which the rule gives a design worth drawing, with a suggested value
//! inside it (`admissible()` of the API; the page's sliders span these intervals).
//!
//! A value is **admissible** when the rule tunes without error and the nominal loop is stable
//! (exact-delay Nyquist verdict and Ms of [`crate::analysis::freq::stability_and_ms`], the
//! same computation as `analyze`). Inside the admissible set the slider keeps to
//! the **useful** part, where the sensitivity peak lies in [`MS_LOW`, `MS_HIGH`]: beyond Ms = 4
//! a loop is too fragile to study, below Ms = 1.1 so sluggish that the slider's travel is wasted
//! (Shamsuzzoha & Lee's λ from 6 to 1000 moves Ms from 1.06 to 1.00). Each end says why it is
//! there ([`End`]); the values beyond an `ms_high`/`ms_low` end are still accepted by `tune`.
//!
//! The method: the declared range is scanned on a grid ([`GRID`] points, logarithmic where it
//! covers two decades or more), the connected run of useful points around the one whose Ms is
//! nearest [`MS_SUGGESTED`] is taken, and each end is refined by bisection to a relative
//! [`REL`]. The set is taken to be connected around that point (the rules' parameters move Ms
//! monotonically on every plant we scanned; a second run elsewhere is not reported). A rule whose
//! parameter has a closed-form interval may narrow the scan through [`Rule::scan_range`].
//!
//! A paper preset's method and plant asked without parameters (the page's request after a
//! preset change) is answered from a table this scan generated ([`preset_intervals`]): the
//! same values, without the scan (Algorithm III's on the boiler is ~1 s).

use super::{ParamDefault, ParamInfo, Params, Rule};
use crate::error::{num, Error, Result};
use crate::model::plant::Plant;
use serde::Serialize;

/// Above this Ms the slider stops (the loop is too fragile to be worth a slider position).
pub const MS_HIGH: f64 = 4.0;
/// Below this Ms the slider stops (the loop is so robust that it is merely sluggish).
pub const MS_LOW: f64 = 1.1;
/// The suggested value of a parameter without a declared default gives this Ms (the middle of
/// the 1.4–2.0 band the papers recommend).
pub const MS_SUGGESTED: f64 = 1.6;
/// Beyond this mean response time of the servo loop, in units of the plant's own time scale
/// ([`time_scale`]), the slider stops: the set point is followed fifty times slower than the
/// plant itself answers (Arvanitis's θ_design = 1000 keeps Ms = 1.7 and draws a flat line).
pub const SLUGGISH: f64 = 50.0;
/// Grid points of the scan of one parameter.
pub const GRID: usize = 25;
/// Relative accuracy of the ends: a tenth of the page's inset from an open end (1/1000 of the
/// span), ~10 bisection steps per end.
pub const REL: f64 = 1e-4;
/// Grid points and relative accuracy for a rule that is slow to tune ([`Rule::slow_to_tune`]):
/// a coarser scan (about 20 designs in all), ends still inside the admissible set.
pub const GRID_SLOW: usize = 9;
/// See [`GRID_SLOW`].
pub const REL_SLOW: f64 = 1e-2;

/// Why an end of an interval is where it is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum End {
    /// The declared range ends here (the rule accepts nothing beyond).
    Declared,
    /// Beyond it the rule cannot design (an ill-posed or impossible design; open end).
    Fails,
    /// Beyond it the nominal loop is unstable (open end).
    Unstable,
    /// Beyond it Ms exceeds [`MS_HIGH`].
    MsHigh,
    /// Beyond it Ms falls below [`MS_LOW`].
    MsLow,
    /// Beyond it the servo loop is sluggish (mean response time above [`SLUGGISH`] × the
    /// plant's time scale).
    Sluggish,
    /// The Ms that the rule's λ reaches at that end of λ's interval (a target-Ms parameter).
    Achievable,
}

impl End {
    /// An open end: the end's outside neighbourhood is not admissible at all.
    pub fn is_open(self) -> bool {
        matches!(self, End::Fails | End::Unstable)
    }
}

/// Slider scale.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Scale {
    /// Linear.
    Linear,
    /// Logarithmic (the interval covers two decades or more).
    Log,
}

/// The interval of one continuous parameter for one plant. `S` is the type of its texts:
/// `String` as computed, `&'static str` in the presets' table ([`Stored`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Interval<S = String> {
    /// Parameter name.
    pub name: S,
    /// Smallest value of the interval.
    pub min: f64,
    /// Largest value of the interval.
    pub max: f64,
    /// `min` borders values where the rule fails or the loop is unstable.
    pub min_open: bool,
    /// `max` borders values where the rule fails or the loop is unstable.
    pub max_open: bool,
    /// Why the interval starts at `min`.
    pub min_end: End,
    /// Why it ends at `max`.
    pub max_end: End,
    /// Suggested value (the declared default when it lies inside, else the value that gives
    /// Ms = [`MS_SUGGESTED`], else the middle).
    pub suggested: f64,
    /// Slider scale.
    pub scale: Scale,
    /// Ms at `min`, at `max` and at `suggested` (absent for a target-Ms parameter).
    pub ms: Option<[f64; 3]>,
    /// The smallest and largest Ms over the interval (its grid points and ends).
    pub ms_range: Option<[f64; 2]>,
    /// What the ends mean, in words (for the page's hint).
    pub note: S,
}

/// One evaluation of the rule at a parameter value.
#[derive(Debug, Clone)]
enum Outcome {
    Fails(String),
    Unstable,
    /// Stable, with Ms and whether the loop is sluggish.
    Stable(f64, bool),
    /// Stable with this Ms, but the set-point path is improper by one (an ideal derivative on
    /// the set point: the servo step would be an impulse, which the simulator refuses).
    Impulse(f64),
}

impl Outcome {
    /// An impulse counted as a stable design: when every stable design of a scan has one,
    /// another parameter put it there (e.g. γ > 0 held while λ is scanned).
    fn relaxed(self) -> Outcome {
        match self {
            Outcome::Impulse(ms) => Outcome::Stable(ms, false),
            o => o,
        }
    }
    fn ms(&self) -> Option<f64> {
        match self {
            Outcome::Stable(ms, _) => Some(*ms),
            _ => None,
        }
    }
    fn useful(&self) -> bool {
        matches!(self, Outcome::Stable(m, false) if (MS_LOW..=MS_HIGH).contains(m))
    }
    fn stable(&self) -> bool {
        self.ms().is_some()
    }
    /// The end this outcome makes when it lies just outside a run.
    fn end(&self) -> End {
        match self {
            Outcome::Fails(_) | Outcome::Impulse(_) => End::Fails,
            Outcome::Unstable => End::Unstable,
            Outcome::Stable(m, _) if *m > MS_HIGH => End::MsHigh,
            Outcome::Stable(m, _) if *m < MS_LOW => End::MsLow,
            Outcome::Stable(..) => End::Sluggish,
        }
    }
}

/// The plant's own time scale: the dead time plus 1/|r| for every non-zero pole and zero of
/// its rational part (a pure integrator with dead time: θ). Errors: the roots cannot be
/// computed (`plant.num`, `plant.den`: [`crate::model::poly::Poly::roots`]).
pub fn time_scale(plant: &Plant) -> Result<f64> {
    let inv = |p: &crate::model::poly::Poly, field: &str| -> Result<f64> {
        Ok(p.roots()
            .map_err(|e| e.within(field))?
            .iter()
            .filter(|r| r.norm() > 0.0)
            .map(|r| 1.0 / r.norm())
            .sum())
    };
    Ok(plant.delay + inv(&plant.tf.num, "plant.num")? + inv(&plant.tf.den, "plant.den")?)
}

/// The mean response time of the servo loop y/r = P Cr e^{−θs}/(1 + P Cy e^{−θs}), i.e.
/// −T′(0)/T(0) (for a step response that settles, the area between 1 and y(t) divided by
/// the final value): with P = Np/Dp, Cr = Nr/Dr, Cy = Ny/Dy,
/// T = Np Nr Dy e^{−θs} / (Dr (Dp Dy + Np Ny e^{−θs})) and −(ln T)′(0) is a sum of the
/// ratios c₁/c₀ of the polynomials' lowest coefficients (exact, no simulation). `None` when
/// T(0) is 0 or infinite (no integral action, a model loop) or the result is not positive.
pub fn servo_mean_time(plant: &Plant, c: &crate::model::controller::Controller) -> Option<f64> {
    use crate::model::poly::Poly;
    if c.model_loop.is_some() {
        return None;
    }
    let th = plant.delay;
    let (np, dp) = (&plant.tf.num, &plant.tf.den);
    let (nr, dr) = (&c.cr.num, &c.cr.den);
    let (ny, dy) = (&c.cy.num, &c.cy.den);
    // (ln f)′(0) of a polynomial.
    let dl = |p: &Poly| p.coef(1) / p.coef(0);
    let a = dp.mul(dy);
    let b = np.mul(ny);
    let q0 = a.coef(0) + b.coef(0);
    let q1 = a.coef(1) + b.coef(1) - th * b.coef(0);
    // Dy/Dr: the integrators they share cancel (an I-PD's Cr = K_i/s and Cy = … + K_i/s).
    let k = dy.zero_root_multiplicity().min(dr.zero_root_multiplicity());
    let (dy, dr) = (dy.shift_down(k), dr.shift_down(k));
    let vals = [np.coef(0), nr.coef(0), dy.coef(0), dr.coef(0), q0];
    if vals.iter().any(|v| *v == 0.0 || !v.is_finite()) {
        return None;
    }
    let dln_t = dl(np) + dl(nr) + dl(&dy) - th - dl(&dr) - q1 / q0;
    let t = -dln_t;
    (t.is_finite() && t > 0.0).then_some(t)
}

/// Evaluates a rule on one plant, remembering the loop analysis of every feedback controller
/// seen (a set-point weight or filter changes the tuning but not the loop: one analysis).
struct Judge<'a> {
    rule: &'a dyn Rule,
    plant: &'a Plant,
    slow_time: f64,
    /// Grid points and relative accuracy of the ends.
    n: usize,
    rel: f64,
    seen: std::cell::RefCell<Vec<(LoopKey, Outcome)>>,
    /// The rules' own simulated work since the scan began ([`super::work`]).
    work: super::work::Scan,
    /// The scan's designs passed [`super::work::SCAN_MAX_PIECES`]: no further design is tuned.
    over: std::cell::Cell<bool>,
}

/// What identifies the loop a controller closes around the plant: the exact bit patterns of
/// Cy's coefficients (the common case, cheap to build and compare) and, for the rare
/// controller with a model-based set-point loop, that loop's full description (its `Debug`
/// text: every coefficient printed to round-trip precision). Equal keys mean the same loop.
#[derive(Debug, Clone, PartialEq, Eq)]
struct LoopKey(Vec<u64>, Option<String>);

fn loop_key(c: &crate::model::controller::Controller) -> LoopKey {
    let (num, den) = (c.cy.num.asc(), c.cy.den.asc());
    let mut bits = Vec::with_capacity(num.len() + den.len() + 1);
    bits.push(num.len() as u64);
    bits.extend(num.iter().chain(den).map(|x| x.to_bits()));
    LoopKey(bits, c.model_loop.as_ref().map(|m| format!("{m:?}")))
}

impl<'a> Judge<'a> {
    fn new(rule: &'a dyn Rule, plant: &'a Plant) -> Result<Self> {
        let ts = time_scale(plant)?;
        Ok(Judge {
            rule,
            plant,
            slow_time: if ts > 0.0 {
                SLUGGISH * ts
            } else {
                f64::INFINITY
            },
            n: if rule.slow_to_tune() { GRID_SLOW } else { GRID },
            rel: if rule.slow_to_tune() { REL_SLOW } else { REL },
            seen: Default::default(),
            work: super::work::Scan::begin(),
            over: Default::default(),
        })
    }

    /// Whether the designs tuned so far passed [`super::work::SCAN_MAX_PIECES`] (remembered).
    fn over_budget(&self) -> bool {
        if self.work.over() {
            self.over.set(true);
        }
        self.over.get()
    }

    /// The refusal of a scan of `decl` that passed [`super::work::SCAN_MAX_PIECES`].
    fn too_costly(&self, decl: &ParamInfo) -> Error {
        Error::new(
            format!("params.{}", decl.name),
            format!(
                "the scan of {} on this plant would need more than {} simulated pieces of the \
                 rule's own searches ({} spent; the designs cannot be taken without simulation \
                 here): no interval",
                decl.label,
                super::work::scan_limit(),
                self.work.spent()
            ),
        )
    }

    /// Tunes with `params` and judges the nominal loop; once the scan is over its budget, no
    /// design (the scan is then refused: [`intervals`]).
    fn outcome(&self, params: &Params) -> Outcome {
        if self.over_budget() {
            return Outcome::Fails("over the scan's budget".into());
        }
        let t = match self.rule.tune(self.plant, params) {
            Err(e) => return Outcome::Fails(e.to_string()),
            Ok(t) => t,
        };
        // The loop is the plant with the feedback path (Cy, and a model loop if any): a
        // parameter that changes only the set-point path is analysed once.
        let key = loop_key(&t.controller);
        let cached = self
            .seen
            .borrow()
            .iter()
            .find(|(k, _)| *k == key)
            .map(|(_, o)| o.clone());
        let o = cached.unwrap_or_else(|| {
            let o = match crate::analysis::freq::stability_and_ms(self.plant, &t.controller) {
                Ok((true, Some(ms))) if ms.is_finite() => Outcome::Stable(ms, false),
                Ok((false, _)) => Outcome::Unstable,
                Ok(_) => Outcome::Fails("no finite Ms".into()),
                Err(e) => Outcome::Fails(e.to_string()),
            };
            self.seen.borrow_mut().push((key, o.clone()));
            o
        });
        // A set-point path improper by one turns the set-point step into an impulse: the
        // simulator refuses it, so the page could not draw the servo response.
        let impulse = t.controller.model_loop.is_none() && t.controller.cr.relative_degree() < 0;
        match o {
            Outcome::Stable(ms, _) if impulse => Outcome::Impulse(ms),
            Outcome::Stable(ms, _) => Outcome::Stable(
                ms,
                servo_mean_time(self.plant, &t.controller).is_some_and(|m| m > self.slow_time),
            ),
            o => o,
        }
    }
}

/// Parameters that stand in for λ (a target Ms solved for, a fitted Ms): their interval is the
/// Ms range λ's interval reaches, and they are left out when the others are scanned.
fn stands_in(name: &str) -> bool {
    matches!(name, "target_ms" | "fit_ms")
}

/// The scan grid over `[lo, hi]`: logarithmic when the range covers two decades or more (with
/// `lo = 0` included as a point and the logarithmic part starting six decades below `hi` when
/// a range from 0 reaches 100 or more).
fn grid(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    let log_from = if lo > 0.0 && hi / lo >= 100.0 {
        Some(lo)
    } else if lo == 0.0 && hi >= 100.0 {
        Some(hi * 1e-6)
    } else {
        None
    };
    match log_from {
        Some(a) => {
            let mut v: Vec<f64> = (0..n)
                .map(|i| a * (hi / a).powf(i as f64 / (n - 1) as f64))
                .collect();
            v[n - 1] = hi;
            if lo == 0.0 {
                v.insert(0, 0.0);
            }
            v
        }
        // The last point exactly `hi` (lo + (hi − lo)·1 can round above it).
        None => (0..n)
            .map(|i| {
                if i + 1 == n {
                    hi
                } else {
                    lo + (hi - lo) * i as f64 / (n - 1) as f64
                }
            })
            .collect(),
    }
}

/// The point just outside an end `x` (towards `bad`): twice the bisection's tolerance away,
/// where the end's kind is read (and where a test can check it).
pub fn beyond(x: f64, bad: f64, rel: f64) -> f64 {
    let step = 2.0 * rel * if x != 0.0 { x.abs() } else { (bad - x).abs() };
    x + (bad - x).signum() * step
}

/// Ms varies by less than 5 % over these outcomes: the parameter shapes the set-point response,
/// not the loop.
fn ms_flat(outs: &[Outcome]) -> bool {
    let ms = outs.iter().filter_map(Outcome::ms);
    let (lo, hi) = ms.fold((f64::INFINITY, 0.0f64), |(a, b), m| (a.min(m), b.max(m)));
    hi <= lo * 1.05
}

/// The interval of the continuous parameter `decl` with the other parameters at `base`.
fn scan(judge: &Judge, base: &Params, decl: &ParamInfo) -> Result<Interval> {
    let name = decl.name.as_str();
    let (dlo, dhi) = (decl.min.unwrap_or(0.0), decl.max.unwrap_or(1.0));
    let (lo, hi) = match judge.rule.scan_range(judge.plant, name) {
        Some((a, b)) => (a.max(dlo), b.min(dhi)),
        None => (dlo, dhi),
    };
    let xs = grid(lo, hi, judge.n);
    let rel = judge.rel;
    let raw = |x: f64| judge.outcome(&base.clone().with(name, x));
    let outs: Vec<Outcome> = xs.iter().map(|&x| raw(x)).collect();
    // Impulses everywhere come from another parameter: judge this one without them.
    let relax =
        !outs.iter().any(Outcome::stable) && outs.iter().any(|o| matches!(o, Outcome::Impulse(_)));
    let at = |x: f64| {
        let o = raw(x);
        if relax {
            o.relaxed()
        } else {
            o
        }
    };
    let outs: Vec<Outcome> = if relax {
        outs.into_iter().map(Outcome::relaxed).collect()
    } else {
        outs
    };
    let ms_at = |x: f64| at(x).ms().unwrap_or(f64::NAN);
    let label = &decl.label;
    // The anchor: the useful point whose Ms is nearest MS_SUGGESTED, else the stable one.
    let nearest = |pred: &dyn Fn(&Outcome) -> bool| {
        outs.iter()
            .enumerate()
            .filter(|(_, o)| pred(o))
            .min_by(|(_, a), (_, b)| {
                let d = |o: &Outcome| (o.ms().unwrap_or(f64::INFINITY) / MS_SUGGESTED).ln().abs();
                d(a).total_cmp(&d(b))
            })
            .map(|(i, _)| i)
    };
    let (anchor, useful_only) = match nearest(&Outcome::useful) {
        Some(i) => (i, true),
        None => match nearest(&Outcome::stable) {
            Some(i) => (i, false),
            None => {
                // The rule refuses every value for one reason (e.g. Algorithm III's ISENSDCO,
                // infinite on every design of a plant whose u jumps): that reason, not
                // stability, is what the user must change.
                if let [Outcome::Fails(first), rest @ ..] = outs.as_slice() {
                    if rest
                        .iter()
                        .all(|o| matches!(o, Outcome::Fails(m) if m == first))
                    {
                        return Err(Error::new(
                            format!("params.{name}"),
                            format!(
                                "no value of {label} in [{}, {}] gives a design on this plant: \
                                 the rule refuses every one ({first})",
                                num(lo),
                                num(hi)
                            ),
                        ));
                    }
                }
                let why = outs
                    .iter()
                    .find_map(|o| match o {
                        Outcome::Fails(m) => Some(m.clone()),
                        Outcome::Impulse(_) => Some("an ideal derivative on the set point".into()),
                        _ => None,
                    })
                    .unwrap_or_else(|| "the loop is unstable".into());
                return Err(Error::new(
                    format!("params.{name}"),
                    format!(
                        "no value of {label} in [{}, {}] gives a stable loop on this plant \
                         (e.g. {why})",
                        num(lo),
                        num(hi)
                    ),
                ));
            }
        },
    };
    let pred = |o: &Outcome| {
        if useful_only {
            o.useful()
        } else {
            o.stable()
        }
    };
    let mut i0 = anchor;
    while i0 > 0 && pred(&outs[i0 - 1]) {
        i0 -= 1;
    }
    let mut i1 = anchor;
    while i1 + 1 < xs.len() && pred(&outs[i1 + 1]) {
        i1 += 1;
    }
    // Refines the end between the good grid point `good` and the bad one `bad`; the outcome
    // just beyond the end says why it is there.
    let refine = |good: f64, bad: f64| -> (f64, End) {
        let x = crate::numerics::bisect_predicate(|x| pred(&at(x)), good, bad, rel, 200);
        let end = match at(beyond(x, bad, rel)) {
            o if pred(&o) => at(bad).end(),
            o => o.end(),
        };
        (x, end)
    };
    let (min, min_end) = if i0 > 0 {
        refine(xs[i0], xs[i0 - 1])
    } else if lo > dlo {
        // A scan range narrowed by the rule starts where the rule says the design fails.
        (xs[0], End::Fails)
    } else {
        (xs[0], End::Declared)
    };
    let (max, max_end) = if i1 + 1 < xs.len() {
        refine(xs[i1], xs[i1 + 1])
    } else if hi < dhi {
        (xs[i1], End::Fails)
    } else {
        (xs[i1], End::Declared)
    };
    // A single admissible value (e.g. γ = 0 where any lead on the set point would leave an
    // ideal derivative there): the bisection cannot leave it, the interval is that point.
    let max = if i0 == i1 && i1 + 1 < xs.len() && max - min <= rel * (xs[i1 + 1] - xs[i1]) {
        min
    } else {
        max
    };
    // The suggestion: the declared default inside the interval; for a parameter the rule
    // chooses when absent, the rule's choice; else the value that gives Ms = MS_SUGGESTED.
    let inside = |x: f64| (min..=max).contains(&x) && pred(&at(x));
    let chosen = match decl.default {
        ParamDefault::Number(d) => Some(d),
        _ if !decl.required => judge
            .rule
            .tune(judge.plant, base)
            .ok()
            .and_then(|t| t.named(name)),
        _ => None,
    };
    let suggested = chosen.filter(|&x| inside(x)).unwrap_or_else(|| {
        let seg = (i0..i1).find(|&i| {
            let (a, b) = (outs[i].ms(), outs[i + 1].ms());
            matches!((a, b), (Some(a), Some(b)) if (a - MS_SUGGESTED) * (b - MS_SUGGESTED) <= 0.0)
        });
        match seg {
            Some(i) => {
                let above = outs[i].ms().unwrap_or(0.0) >= MS_SUGGESTED;
                crate::numerics::bisect_predicate(
                    |x| (ms_at(x) >= MS_SUGGESTED) == above,
                    xs[i],
                    xs[i + 1],
                    rel,
                    200,
                )
            }
            // Ms does not cross MS_SUGGESTED: the anchor, or the middle of the interval when
            // the parameter hardly moves Ms (a set-point weight, filter or design time).
            None if ms_flat(&outs[i0..=i1]) => {
                if min > 0.0 && max / min >= 100.0 {
                    (min * max).sqrt()
                } else {
                    0.5 * (min + max)
                }
            }
            None => xs[anchor].clamp(min, max),
        }
    });
    let scale = if min > 0.0 && max / min >= 100.0 {
        Scale::Log
    } else {
        Scale::Linear
    };
    let ms = [ms_at(min), ms_at(max), ms_at(suggested)];
    let ms = ms.iter().all(|m| m.is_finite()).then_some(ms);
    let ms_range = ms.map(|m| {
        let run = outs[i0..=i1].iter().filter_map(Outcome::ms);
        let all: Vec<f64> = run.chain(m).collect();
        [
            all.iter().copied().fold(f64::INFINITY, f64::min),
            all.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        ]
    });
    Ok(Interval {
        name: name.into(),
        min,
        max,
        min_open: min_end.is_open(),
        max_open: max_end.is_open(),
        min_end,
        max_end,
        suggested,
        scale,
        ms,
        ms_range,
        note: note(label, min, max, min_end, max_end),
    })
}

/// The ends in words.
fn note(label: &str, min: f64, max: f64, a: End, b: End) -> String {
    let why = |e: End, side: &str| match e {
        End::Declared => format!("the rule's {side} limit"),
        End::Fails => "the rule cannot design beyond it".to_string(),
        End::Unstable => "the loop is unstable beyond it".to_string(),
        End::MsHigh => format!("beyond it Ms > {MS_HIGH} (too fragile)"),
        End::MsLow => format!("beyond it Ms < {MS_LOW} (merely sluggish)"),
        End::Sluggish => "beyond it the loop is sluggish".to_string(),
        End::Achievable => "the Ms the rule reaches there".to_string(),
    };
    if min == max {
        return format!(
            "{label} = {} only on this plant ({}; {})",
            num(min),
            why(a, "lower"),
            why(b, "upper")
        );
    }
    format!(
        "{label} from {} ({}) to {} ({})",
        num(min),
        why(a, "lower"),
        num(max),
        why(b, "upper")
    )
}

/// The intervals of every continuous parameter of `rule` for `plant`, the others held at
/// `params` (a required parameter that is absent is held at its own suggestion, found first;
/// target-Ms parameters are left out of the scans and get the Ms range of λ's interval).
pub fn intervals(rule: &dyn Rule, plant: &Plant, params: &Params) -> Result<Vec<Interval>> {
    let info = rule.info();
    let judge = Judge::new(rule, plant)?;
    let mut base = params.clone();
    base.0.retain(|k, _| !stands_in(k));
    let decls: Vec<&ParamInfo> = info.params.iter().filter(|p| p.is_continuous()).collect();
    let mut order: Vec<&ParamInfo> = decls.iter().copied().filter(|p| p.required).collect();
    order.extend(
        decls
            .iter()
            .copied()
            .filter(|p| !p.required && !stands_in(&p.name)),
    );
    let mut out: Vec<Interval> = Vec::new();
    for d in order {
        let mut held = base.clone();
        held.0.remove(&d.name);
        let iv = scan(&judge, &held, d);
        if judge.over_budget() {
            return Err(judge.too_costly(d));
        }
        let iv = iv?;
        if !base.0.contains_key(&d.name) && d.required {
            base = base.with(&d.name, iv.suggested);
        }
        out.push(iv);
    }
    // Target-Ms parameters: the Ms that λ's interval reaches, within their declarations.
    let lambda = out.iter().find(|i| i.name == "lambda").cloned();
    for d in decls.iter().filter(|p| stands_in(&p.name)) {
        let Some(Interval {
            ms_range: Some([a, b]),
            ..
        }) = &lambda
        else {
            continue;
        };
        let (dlo, dhi) = (d.min.unwrap_or(1.0), d.max.unwrap_or(10.0));
        let (lo, hi) = (a.max(dlo), b.min(dhi));
        if lo >= hi {
            continue;
        }
        // The rule solves λ for the target with its own search, which may not reach the very
        // extremes of Ms (the bottom of a U-shaped Ms(λ) is a tangent): pull each end in, by
        // bisection towards the middle, until the rule gives a drawable design there.
        let mut others = base.clone();
        others.0.remove("lambda");
        let solves = |x: f64| {
            matches!(
                judge.outcome(&others.clone().with(&d.name, x)).relaxed(),
                Outcome::Stable(..)
            )
        };
        let mid = MS_SUGGESTED.clamp(lo, hi);
        if !solves(mid) {
            continue;
        }
        let pull = |end: f64| {
            if solves(end) {
                end
            } else {
                crate::numerics::bisect_predicate(solves, mid, end, 1e-4, 60)
            }
        };
        let (lo, hi) = (pull(lo), pull(hi));
        if lo >= hi {
            continue;
        }
        out.push(Interval {
            name: d.name.clone(),
            min: lo,
            max: hi,
            min_open: false,
            max_open: false,
            min_end: End::Achievable,
            max_end: End::Achievable,
            suggested: mid,
            scale: Scale::Linear,
            ms: None,
            ms_range: None,
            note: format!(
                "{} from {} to {}: the Ms that λ reaches over its interval",
                d.label,
                num(lo),
                num(hi)
            ),
        });
    }
    // In declaration order, as methods() lists them.
    // (an unknown name, None, first as `Option`'s order has it; positions are exact in f64)
    crate::numerics::sort_by_f64_key(&mut out, |i| {
        info.params
            .iter()
            .position(|p| p.name == i.name)
            .map_or(-1.0, |p| p as f64)
    });
    Ok(out)
}

/// `intervals` for the method `id` (errors as [`super::tune`]: unknown method, wrong family,
/// invalid `params`). Asked with no parameters for a paper preset's method and plant (what the
/// page asks after a preset change), the intervals come from the presets' table
/// ([`preset_intervals`]): the same values, bit for bit, that [`intervals`] computes.
pub fn admissible(id: &str, plant: &Plant, params: &Params) -> Result<Vec<Interval>> {
    let rule = super::find(id)?;
    let info = rule.info();
    super::check_family(&info, plant)?;
    rule.validate(params, &info)?;
    if params.0.is_empty() {
        if let Some(ivs) = preset_intervals(id, plant) {
            return Ok(ivs);
        }
    }
    intervals(rule.as_ref(), plant, params)
}

/// An [`Interval`] as the presets' table stores it (static strings).
pub type Stored = Interval<&'static str>;

impl Interval<&'static str> {
    /// The interval stored.
    pub fn interval(&self) -> Interval {
        Interval {
            name: self.name.into(),
            min: self.min,
            max: self.max,
            min_open: self.min_open,
            max_open: self.max_open,
            min_end: self.min_end,
            max_end: self.max_end,
            suggested: self.suggested,
            scale: self.scale,
            ms: self.ms,
            ms_range: self.ms_range,
            note: self.note.into(),
        }
    }
}

/// What identifies a plant in the presets' table: its `Debug` text (every coefficient, the dead
/// time and the family's parameters printed to round-trip precision, so equal keys mean the
/// same bits).
pub fn plant_key(plant: &Plant) -> String {
    format!("{plant:?}")
}

/// The intervals of `intervals(rule id, plant, no parameters)` when (`id`, `plant`) is a paper
/// preset's method and plant, from a table generated by that very scan
/// (`src/rules/admissible_presets.rs`; `tests/admissible_presets.rs` recomputes every entry and
/// compares the file's text, and regenerates it with `PIDLAB_WRITE_ADMISSIBLE_PRESETS=1`):
/// a preset change then waits for no scan (Arvanitis's Algorithm III on the boiler: ~1 s).
/// `None` for any other method or plant (a plant differing in one bit included).
#[cfg(feature = "full")]
pub fn preset_intervals(id: &str, plant: &Plant) -> Option<Vec<Interval>> {
    let key = plant_key(plant);
    super::admissible_presets::TABLE
        .iter()
        .find(|(m, p, _)| *m == id && *p == key)
        .map(|(_, _, ivs)| ivs.iter().map(Stored::interval).collect())
}

/// The first module has no presets' table (nor an `admissible` export).
#[cfg(not(feature = "full"))]
pub fn preset_intervals(_id: &str, _plant: &Plant) -> Option<Vec<Interval>> {
    None
}

/// The text of `src/rules/admissible_presets.rs` for these entries: (method id, plant key,
/// intervals as [`intervals`] computed them), in this order.
pub fn presets_table_source(entries: &[(String, String, Vec<Interval>)]) -> String {
    let mut s = String::from(
        "//! GENERATED by `PIDLAB_WRITE_ADMISSIBLE_PRESETS=1 cargo test --release --test \
         admissible_presets`: do not edit.\n\
         //! `admissible()` of every paper preset that applies a rule, asked as the page asks it \
         (its method and\n\
         //! plant, no parameters), computed by the live scan `rules::admissible::intervals` \
         ([`super::admissible::preset_intervals`]).\n\n\
         use super::admissible::{End, Scale, Stored};\n\n\
         /// (method id, plant key ([`super::admissible::plant_key`]), intervals).\n\
         #[rustfmt::skip]\n\
         pub static TABLE: &[(&str, &str, &[Stored])] = &[\n",
    );
    for (m, p, ivs) in entries {
        s += &format!("    ({m:?}, {p:?}, &[\n");
        for iv in ivs {
            s += &format!(
                "        Stored {{ name: {:?}, min: {:?}, max: {:?}, min_open: {}, max_open: {}, \
                 min_end: End::{:?}, max_end: End::{:?}, suggested: {:?}, scale: Scale::{:?}, \
                 ms: {:?}, ms_range: {:?}, note: {:?} }},\n",
                iv.name,
                iv.min,
                iv.max,
                iv.min_open,
                iv.max_open,
                iv.min_end,
                iv.max_end,
                iv.suggested,
                iv.scale,
                iv.ms,
                iv.ms_range,
                iv.note
            );
        }
        s += "    ]),\n";
    }
    s += "];\n";
    s
}
