//! Code export: a design (plant, controller `u = Cr·r − Cy·y`) written out as a complete file
//! for another tool, one module per target:
//!
//! | target | module | what the file is |
//! |---|---|---|
//! | `python-control` | [`python`] | script defining `P`, `theta`, `Cr`, `Cy` (`control.tf`), a Padé loop for simulation |
//! | `matlab` | [`matlab`] | script: `tf` with `'InputDelay'`, `pidstd`/`pidstd2` when the structure is a standard PID |
//! | `julia` | [`julia`] | ControlSystems.jl script with `delay(θ)` |
//! | `iec61131-st` | [`st`] | function block: the sampled controller (difference equations, anti-windup) |
//! | `c` | [`c`] | C99 state struct + step function of the same sampled controller |
//!
//! Every file starts with a header naming the method, the plant and the date. The date is an
//! input (never read from a clock here), so the same design gives the same text byte for byte.
//! Numbers are written with Rust's shortest round-trip representation ([`num`]), which every
//! target's parser reads back to the same `f64`: the exported coefficients are pidlab's exactly.
//! Header text is reduced to printable ASCII ([`ascii`]) and cannot close the comment it sits in.

use crate::error::{Error, Result};
use crate::model::controller::Controller;
use crate::model::discrete::DiscreteController;
use crate::model::plant::{Family, Plant};
use crate::model::tf::Tf;

pub mod c;
pub mod julia;
pub mod matlab;
pub mod python;
pub mod sampled;
pub mod st;

/// An export target of API.md.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Target {
    /// python-control script.
    PythonControl,
    /// MATLAB (Control System Toolbox) script.
    Matlab,
    /// Julia (ControlSystems.jl) script.
    Julia,
    /// IEC 61131-3 Structured Text function block.
    St,
    /// C99 source file.
    C,
}

impl Target {
    /// The ids API.md lists, in its order.
    pub const IDS: [&'static str; 5] = ["python-control", "matlab", "julia", "iec61131-st", "c"];

    /// The target of an id; the error names `target` and lists the ids.
    pub fn from_id(id: &str) -> Result<Target> {
        Ok(match id {
            "python-control" => Target::PythonControl,
            "matlab" => Target::Matlab,
            "julia" => Target::Julia,
            "iec61131-st" => Target::St,
            "c" => Target::C,
            _ => {
                let hint = crate::error::did_you_mean(id, &Target::IDS)
                    .map(|c| format!(" (did you mean '{c}'?)"))
                    .unwrap_or_default();
                return Err(Error::new(
                    "target",
                    format!(
                        "unknown target '{}'{hint}; one of {}",
                        ascii(id),
                        Target::IDS.join(", ")
                    ),
                ));
            }
        })
    }

    /// The API id.
    pub fn id(self) -> &'static str {
        match self {
            Target::PythonControl => "python-control",
            Target::Matlab => "matlab",
            Target::Julia => "julia",
            Target::St => "iec61131-st",
            Target::C => "c",
        }
    }

    /// File name extension (without the dot).
    pub fn extension(self) -> &'static str {
        match self {
            Target::PythonControl => "py",
            Target::Matlab => "m",
            Target::Julia => "jl",
            Target::St => "st",
            Target::C => "c",
        }
    }

    /// Whether the target is a sampled controller (needs `sampling`).
    pub fn is_sampled(self) -> bool {
        matches!(self, Target::St | Target::C)
    }
}

/// Where the controller came from, for the header.
#[derive(Debug, Clone, PartialEq)]
pub struct Origin {
    /// Method id (a file-name-safe identifier), e.g. `arvanitis_alg1`; `None` for a controller
    /// given directly.
    pub method: Option<String>,
    /// Human title: the method's title and citation, or the caller's label.
    pub title: String,
    /// Named parameters of the structure (`kp`, `ki`, …), as `tune` returns them.
    pub named: Vec<(String, f64)>,
}

/// A design to export.
#[derive(Debug, Clone)]
pub struct Design {
    /// The plant (rational part and exact dead time).
    pub plant: Plant,
    /// The controller; a model-based set-point loop cannot be exported (see [`check`]).
    pub controller: Controller,
    /// Method or label for the header.
    pub origin: Origin,
    /// Date for the header (validated by the caller: printable ASCII), `None`: "not given".
    pub date: Option<String>,
}

/// An exported file.
#[derive(Debug, Clone, PartialEq)]
pub struct Exported {
    /// The file's text.
    pub text: String,
    /// A suggested file name (`pidlab_<method>.<ext>`; MATLAB-safe identifier stem).
    pub filename: String,
}

/// Checks what every target needs: a rational (Cr, Cy) pair.
pub fn check(d: &Design) -> Result<()> {
    if d.controller.model_loop.is_some() {
        return Err(Error::new(
            "controller.model_loop",
            "a model-based set-point path (internal model with dead time) is not rational and cannot be exported; export the (cr, cy) pair alone",
        ));
    }
    Ok(())
}

/// Exports a continuous-time design for `target` (`python-control`, `matlab` or `julia`);
/// the sampled targets go through their own modules with the sampled controller.
pub fn export_continuous(target: Target, d: &Design) -> Result<Exported> {
    check(d)?;
    let text = match target {
        Target::PythonControl => python::write(d),
        Target::Matlab => matlab::write(d),
        Target::Julia => julia::write(d),
        Target::St | Target::C => {
            return Err(Error::new(
                "sampling",
                format!("is required for target '{}'", target.id()),
            ))
        }
    };
    Ok(Exported {
        text,
        filename: filename(&d.origin, target),
    })
}

/// Exports the sampled controller `dc` (discretised from `d.controller` by the caller, with
/// [`DiscreteController::new`]: the same difference equations pidlab's sampled loop runs) for
/// `target` (`iec61131-st` or `c`).
pub fn export_sampled(target: Target, d: &Design, dc: &DiscreteController) -> Result<Exported> {
    check(d)?;
    let id = stem(&d.origin);
    let text = match target {
        Target::C => c::write(d, dc, &id),
        // `stem` is ASCII: no Unicode case tables needed (wasm module size, issue 15)
        Target::St => st::write(d, dc, &id.to_ascii_uppercase()),
        _ => {
            return Err(Error::new(
                "sampling",
                format!(
                    "applies to the sampled targets (iec61131-st, c); '{}' exports the continuous design",
                    target.id()
                ),
            ))
        }
    };
    Ok(Exported {
        text,
        filename: filename(&d.origin, target),
    })
}

/// `pidlab_<method>` (or `pidlab_controller`): a valid MATLAB, Julia, C and ST identifier.
pub fn stem(o: &Origin) -> String {
    let s: String = o
        .method
        .as_deref()
        .unwrap_or("controller")
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .take(40)
        .collect();
    // IEC 61131-3 identifiers have no double underscore and do not end with one
    let mut s = s.trim_matches('_').to_string();
    while s.contains("__") {
        s = s.replace("__", "_");
    }
    if s.is_empty() {
        s.push_str("controller");
    }
    format!("pidlab_{s}")
}

/// `<stem>.<ext>`.
pub fn filename(o: &Origin, t: Target) -> String {
    format!("{}.{}", stem(o), t.extension())
}

/// A number as a literal every target reads back to the same `f64`: the shortest round-trip
/// representation (Rust's `{:?}`), with a decimal point always in the mantissa (`1e20` →
/// `1.0e20`: IEC 61131-3 real literals need it). Callers pass finite numbers only.
pub fn num(x: f64) -> String {
    let s = format!("{x:?}");
    match s.find('e') {
        Some(i) if !s[..i].contains('.') => format!("{}.0{}", &s[..i], &s[i..]),
        _ => s,
    }
}

/// A list of numbers separated by `", "`.
pub fn nums(xs: &[f64]) -> String {
    xs.iter().map(|&x| num(x)).collect::<Vec<_>>().join(", ")
}

/// The continuous design as the MATLAB, Julia and python-control scripts write it:
/// `(pn, pd, theta, rn, rd, yn, yd)`, the coefficient lists ([`nums`], highest power first)
/// of the plant's rational part's numerator and denominator, the dead time ([`num`]), then
/// those of `Cr` and of `Cy`.
pub(crate) fn tf_texts(d: &Design) -> (String, String, String, String, String, String, String) {
    let (pn, pd) = d.plant.tf.to_desc();
    let (rn, rd) = d.controller.cr.to_desc();
    let (yn, yd) = d.controller.cy.to_desc();
    let theta = num(d.plant.delay);
    let n = |x: Vec<f64>| nums(&x);
    (n(pn), n(pd), theta, n(rn), n(rd), n(yn), n(yd))
}

/// Text reduced to printable ASCII for a comment or a string: Greek letters spelled out, a
/// few signs replaced, anything else non-printable becomes `?`; line breaks become spaces.
pub fn ascii(s: &str) -> String {
    let mut out = String::new();
    for c in s.chars() {
        let r: &str = match c {
            ' '..='~' => {
                out.push(c);
                continue;
            }
            'θ' => "theta",
            'τ' => "tau",
            'λ' => "lambda",
            'ζ' => "zeta",
            'ξ' => "xi",
            'ε' => "epsilon",
            'γ' => "gamma",
            'β' => "beta",
            'α' => "alpha",
            'φ' => "phi",
            'ω' => "w",
            '·' | '×' => "*",
            '−' | '–' | '—' => "-",
            '≥' => ">=",
            '≤' => "<=",
            '≠' => "!=",
            '²' => "^2",
            '⁻' => "^-",
            '¹' => "1",
            'é' | 'è' | 'ê' => "e",
            'á' | 'à' | 'â' | 'ä' => "a",
            'ó' | 'ö' | 'ô' => "o",
            'ú' | 'ü' => "u",
            'í' | 'ï' => "i",
            'ç' => "c",
            'ñ' => "n",
            '\n' | '\r' | '\t' => " ",
            _ => "?",
        };
        out.push_str(r);
    }
    out
}

/// `num/den` in descending powers, for the header: `[..] / [..]`.
fn tf_text(t: &Tf) -> String {
    let (n, d) = t.to_desc();
    format!("[{}] / [{}]", nums(&n), nums(&d))
}

/// The header lines (plain ASCII, no comment syntax): tool, method, plant, controller, date.
pub fn header(d: &Design, what: &str) -> Vec<String> {
    let mut h = vec![
        format!("pidlab export: {what}"),
        format!("Method: {}", ascii(&d.origin.title)),
    ];
    if let Some(m) = &d.origin.method {
        h.push(format!("Method id: {}", ascii(m)));
    }
    if !d.origin.named.is_empty() {
        let p: Vec<String> = d
            .origin
            .named
            .iter()
            .map(|(k, v)| format!("{}={}", ascii(k), num(*v)))
            .collect();
        h.push(format!("Parameters: {}", p.join(", ")));
    }
    h.push(format!("Plant: {}", plant_text(&d.plant)));
    h.push(format!(
        "  P(s) = {}, dead time theta = {} (descending powers of s)",
        tf_text(&d.plant.tf),
        num(d.plant.delay)
    ));
    h.push("Controller: u = Cr(s)*r - Cy(s)*y (two degrees of freedom)".into());
    h.push(format!("  Cr(s) = {}", tf_text(&d.controller.cr)));
    h.push(format!("  Cy(s) = {}", tf_text(&d.controller.cy)));
    h.push(format!(
        "Date: {}",
        d.date
            .as_deref()
            .map(ascii)
            .unwrap_or_else(|| "not given".into())
    ));
    h.push("Time is in the plant's own unit.".into());
    h
}

/// The plant in words: its family and parameters, or "rational plant with dead time".
fn plant_text(p: &Plant) -> String {
    match &p.family {
        Some(f) => {
            let names = Family::param_names(f.id()).unwrap_or(&[]);
            let vals: Vec<String> = names
                .iter()
                .zip(f.values())
                .map(|(n, v)| format!("{n}={}", num(v)))
                .collect();
            format!("family {} ({})", f.id(), vals.join(", "))
        }
        None => "rational part with dead time".into(),
    }
}

/// Header lines as comments: `prefix` before each line, `bad` sequences (the comment's own
/// terminator) broken up so no header text can end the comment.
pub fn comment_lines(lines: &[String], prefix: &str, bad: &[&str]) -> String {
    let mut out = String::new();
    for l in lines {
        let mut l = l.clone();
        for b in bad {
            // e.g. "*/" -> "* /"
            let mut it = b.chars();
            if let Some(first) = it.next() {
                let fixed = format!("{first} {}", it.as_str());
                l = l.replace(b, &fixed);
            }
        }
        out.push_str(prefix);
        out.push_str(&l);
        out.push('\n');
    }
    out
}

/// The coefficients of a PID in standard form recovered from a (Cr, Cy) pair: `Cy` is
/// `K_p(1 + 1/(T_i s) + T_d s/((T_d/N) s + 1))` (ideal derivative: `N = ∞`) and `Cr` the same
/// with set-point weights `b` on P and `c` on D (MATLAB's `pidstd2`).
#[derive(Debug, Clone, PartialEq)]
pub struct StdPid {
    /// Proportional gain.
    pub kp: f64,
    /// Integral time (`∞` without integral action is not produced: integral action required).
    pub ti: f64,
    /// Derivative time (0: PI).
    pub td: f64,
    /// Derivative filter divisor (`∞`: ideal derivative).
    pub n: f64,
    /// Weight of r in the proportional term (`None`: Cr is not of the weighted form).
    pub b: Option<f64>,
    /// Weight of r in the derivative term.
    pub c: Option<f64>,
}

/// Recognises a standard PID (with integral action) in `Cy` and, when `Cr` has the same
/// denominator and integral, its set-point weights. Relative agreement `rel` on the
/// coefficients recovered (the conversion is a few roundings away from exact).
pub fn std_pid(ctl: &Controller) -> Option<StdPid> {
    let (ny, dy) = ctl.cy.to_desc();
    // denominator a·s (ideal) or a·(T_f s² + s) (filtered), scaled by its s coefficient
    let (tf_, scale) = match dy.as_slice() {
        [a, z] if *z == 0.0 && *a != 0.0 => (0.0, *a),
        [t, a, z] if *z == 0.0 && *a != 0.0 && *t / *a > 0.0 => (*t / *a, *a),
        _ => return None,
    };
    let pad = |v: &[f64]| -> Option<[f64; 3]> {
        if v.len() > 3 {
            return None;
        }
        let mut o = [0.0; 3];
        for (i, x) in v.iter().rev().enumerate() {
            o[2 - i] = x / scale;
        }
        Some(o)
    };
    let [n2, n1, n0] = pad(&ny)?;
    // Cy·(s(T_f s + 1)) = (K_p T_f + K_d) s² + (K_p + K_i T_f) s + K_i
    let ki = n0;
    let kp = n1 - ki * tf_;
    let kd = n2 - kp * tf_;
    if !(ki != 0.0 && kp != 0.0 && kd.is_finite()) {
        return None;
    }
    if tf_ == 0.0 && ny.len() > 3 {
        return None;
    }
    if tf_ > 0.0 && kd == 0.0 {
        // a lag on a PI is not a standard PID
        return None;
    }
    let ti = kp / ki;
    let td = kd / kp;
    if ti <= 0.0 || td < 0.0 {
        return None;
    }
    let n = if tf_ == 0.0 { f64::INFINITY } else { td / tf_ };
    if !(kp.is_finite() && ti.is_finite() && td.is_finite() && (n.is_finite() || tf_ == 0.0)) {
        return None;
    }
    let mut out = StdPid {
        kp,
        ti,
        td,
        n,
        b: None,
        c: None,
    };
    let (nr, dr) = ctl.cr.to_desc();
    if dr == dy {
        let [m2, m1, m0] = pad(&nr)?;
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * a.abs().max(b.abs());
        if close(m0, ki) {
            let b = (m1 - ki * tf_) / kp;
            let c = if kd != 0.0 {
                (m2 - b * kp * tf_) / kd
            } else if m2 == 0.0 {
                1.0
            } else {
                return Some(out);
            };
            if b.is_finite() && c.is_finite() {
                out.b = Some(b);
                out.c = Some(c);
            }
        }
    }
    Some(out)
}
