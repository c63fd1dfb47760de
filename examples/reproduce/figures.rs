//! The papers' simulation figures as SVG (`docs/figures/*.svg`), drawn from the figure data the
//! sections write as CSV (`docs/figures/*.csv`) in the same run, and the report's figure list.
//!
//! Each SVG is a function of its CSV files only (see `svg.rs`: no fonts, integer pixels), so
//! `tests/figures.rs` re-renders them from the committed CSVs and compares bytes.

use crate::svg::{render, Chart, Curve, Legend, Panel};
use std::fmt::Write;
use std::path::Path;

/// A figure: where it is from, its file name and how it is drawn.
pub struct Figure {
    /// Paper (report section title).
    pub paper: &'static str,
    /// The paper's figure number(s), e.g. "Fig. 8".
    pub number: &'static str,
    /// SVG file name under docs/figures/.
    pub file: String,
    /// The CSV files it is drawn from.
    pub sources: Vec<String>,
    /// The chart.
    pub chart: Chart,
}

/// Figures of the papers' lists that are not regenerated, with the reason (`"—"`: a note on a
/// paper whose figures are all drawn). Every paper's Fig. 1 is a block diagram.
pub const MISSING: [(&str, &str, &str); 1] = [(
    "all five papers",
    "—",
    "every figure but the Fig. 1 block diagrams is drawn",
)];

/// A CSV file: header and rows of fields (quoted fields unquoted).
struct Csv {
    header: Vec<String>,
    rows: Vec<Vec<String>>,
}

fn split(line: &str) -> Vec<String> {
    let mut out = vec![];
    let mut cur = String::new();
    let mut quoted = false;
    for ch in line.chars() {
        match ch {
            '"' => quoted = !quoted,
            ',' if !quoted => out.push(std::mem::take(&mut cur)),
            c => cur.push(c),
        }
    }
    out.push(cur);
    out
}

impl Csv {
    fn read(dir: &Path, name: &str) -> Result<Csv, String> {
        let text = std::fs::read_to_string(dir.join(name)).map_err(|e| format!("{name}: {e}"))?;
        let mut lines = text.lines();
        let header = split(lines.next().ok_or(format!("{name}: empty"))?);
        let rows = lines.filter(|l| !l.is_empty()).map(split).collect();
        Ok(Csv { header, rows })
    }
    fn col(&self, name: &str) -> Result<usize, String> {
        self.header
            .iter()
            .position(|h| h == name)
            .ok_or(format!("no column {name}"))
    }
    fn num(row: &[String], i: usize) -> f64 {
        row.get(i)
            .and_then(|s| s.trim().parse::<f64>().ok())
            .unwrap_or(f64::NAN)
    }
    /// Column `y` against column `x`, over the rows `keep` accepts.
    fn xy(&self, x: usize, y: usize, keep: impl Fn(&[String]) -> bool) -> Vec<(f64, f64)> {
        self.rows
            .iter()
            .filter(|r| keep(r))
            .map(|r| (Csv::num(r, x), Csv::num(r, y)))
            .collect()
    }
}

fn curve(label: &str, points: Vec<(f64, f64)>) -> Curve {
    Curve {
        label: label.to_string(),
        points,
        markers: false,
        color: None,
    }
}

/// Shamsuzzoha & Lee 2008, Figs. 8-9: the λ guidelines, column `lambda_ms<Ms>` against
/// column `x`, for Ms = 1.6, 1.8, 2.0.
fn lambda_guidelines(csv: &Csv, x: usize) -> Result<Vec<Curve>, String> {
    ["1.6", "1.8", "2.0"]
        .iter()
        .map(|ms| {
            let y = csv.col(&format!("lambda_ms{ms}"))?;
            Ok(curve(&format!("Ms = {ms}"), csv.xy(x, y, |_| true)))
        })
        .collect()
}

fn panel(y_label: &str, curves: Vec<Curve>) -> Panel {
    Panel {
        title: String::new(),
        y_label: y_label.into(),
        curves,
    }
}

fn chart(title: String, x_label: &str, x_range: Option<(f64, f64)>, panels: Vec<Panel>) -> Chart {
    Chart {
        title,
        x_label: x_label.into(),
        x_range,
        x_log: false,
        panels,
        legend: Legend::LowerRight,
    }
}

/// Wide CSV: every column whose name starts with `prefix` (all but `t` when empty) against t,
/// labelled by `label(name)`; a column with no finite value (a loop the study could not run,
/// e.g. Ajmeri & Ali's Example 4) is left out.
fn wide(csv: &Csv, prefix: &str, label: impl Fn(&str) -> String) -> Result<Vec<Curve>, String> {
    let t = csv.col("t")?;
    Ok(csv
        .header
        .iter()
        .enumerate()
        .filter(|(i, h)| *i != t && h.starts_with(prefix) && h.as_str() != "r")
        .map(|(i, h)| curve(&label(h), csv.xy(t, i, |_| true)))
        .filter(|c| c.points.iter().any(|p| p.1.is_finite()))
        .collect())
}

fn arvanitis_label(col: &str) -> String {
    let k = col.trim_start_matches("y_");
    match k {
        "alg1" => "proposed (Method I, Algorithm I)".into(),
        "alg1_125" => "proposed, 1.25 τ_D".into(),
        "alg2" => "proposed (Algorithm II, ζ = 0.6)".into(),
        "alg3" => "proposed (Algorithm III)".into(),
        "m2_xi" => "proposed (Method II, ξ = 0.707)".into(),
        "m2_beta" => "proposed (Method II, min. (13))".into(),
        "gu2006" => "Gu et al. 2006".into(),
        "luyben2003" => "Luyben 2003".into(),
        "shamsuzzoha_lee2006" => "Shamsuzzoha & Lee 2006".into(),
        other => other.into(),
    }
}

fn sl_label(m: &str) -> String {
    match m {
        "proposed" => "proposed".into(),
        "wang_cai" => "Wang & Cai".into(),
        "zhang" => "Zhang et al.".into(),
        "skogestad" => "Skogestad".into(),
        "gu" => "Gu et al.".into(),
        "luyben" => "Luyben".into(),
        "wang_cluett" => "Wang & Cluett".into(),
        "rivera" => "Rivera et al.".into(),
        "chidambaram_sree" => "Chidambaram & Sree".into(),
        other => other.replace('_', " "),
    }
}

/// Long CSV `method,case,t,y,u`: y against t of `case`, one curve per method (first-seen order).
fn long_responses(csv: &Csv, case: &str, col: &str) -> Result<Vec<Curve>, String> {
    let (m, c, t, y) = (
        csv.col("method")?,
        csv.col("case")?,
        csv.col("t")?,
        csv.col(col)?,
    );
    let mut methods: Vec<String> = vec![];
    for r in &csv.rows {
        if r[c] == case && !methods.contains(&r[m]) {
            methods.push(r[m].clone());
        }
    }
    Ok(methods
        .iter()
        .map(|name| {
            curve(
                &sl_label(name),
                csv.xy(t, y, |r| r[m] == *name && r[c] == case),
            )
        })
        .collect())
}

/// Long CSV `curve,x,…`: column `y` against column `x`, one curve per value of `curve`
/// (first-seen order), labelled by `label(value)`.
fn groups(
    csv: &Csv,
    x: &str,
    y: &str,
    label: impl Fn(&str) -> String,
) -> Result<Vec<Curve>, String> {
    let (c, x, y) = (csv.col("curve")?, csv.col(x)?, csv.col(y)?);
    let mut ids: Vec<String> = vec![];
    for r in &csv.rows {
        if !ids.contains(&r[c]) {
            ids.push(r[c].clone());
        }
    }
    Ok(ids
        .iter()
        .map(|id| curve(&label(id), csv.xy(x, y, |r| r[c] == *id)))
        .collect())
}

/// `tau_i=0.5` → `τ_I = 0.5`, `inf` → `∞` (the curve keys of Arvanitis' Figs. 2-7).
fn greek(key: &str) -> String {
    key.replace("tau_i", "τ_I")
        .replace("tau_d", "τ_D")
        .replace("tau_z", "τ_Z")
        .replace('=', " = ")
        .replace(" d = ", ", d = ")
        .replace("inf", "∞")
}

/// The window of the Nyquist plane Arvanitis' Figs. 2-3 show (re, im): the critical point −1,
/// the real-axis crossings and the start of the delay's spiral; points outside break the line.
pub const NYQUIST_WINDOW: ((f64, f64), (f64, f64)) = ((-3.0, 1.0), (-3.0, 1.5));

/// Points outside the window made non-finite (they break the line).
fn window(curves: &mut [Curve], (x, y): ((f64, f64), (f64, f64))) {
    for c in curves {
        for p in &mut c.points {
            if !(p.0 >= x.0 && p.0 <= x.1 && p.1 >= y.0 && p.1 <= y.1) {
                *p = (f64::NAN, f64::NAN);
            }
        }
    }
}

/// How one of Arvanitis' Figs. 2-7 is drawn: number, title, x and y (column, axis label), log
/// x axis, the window shown (points outside break the line; x range `None`: the data's), the
/// legend's corner.
type ArvFig<'a> = (
    usize,
    &'a str,
    (&'a str, &'a str),
    (&'a str, &'a str),
    bool,
    (Option<(f64, f64)>, (f64, f64)),
    Legend,
);

/// Arvanitis et al. 2012, Figs. 2-7: the Section 3 analysis (`arvanitis2012_fig{2..7}.csv`).
fn arvanitis_section3(dir: &Path, v: &mut Vec<Figure>) -> Result<(), String> {
    const ARV: &str = "Arvanitis et al. 2012";
    const ALL: (f64, f64) = (f64::NEG_INFINITY, f64::INFINITY);
    let (nx, ny) = NYQUIST_WINDOW;
    let list: [ArvFig; 6] = [
        (
            2,
            "Nyquist plots of G_L (7), K_C = 0.5, d = τ_Z = 0.5, τ_D = 1.5, various τ_I",
            ("re", "Re G_L(jw)"),
            ("im", "Im G_L(jw)"),
            false,
            (Some(nx), ny),
            Legend::LowerRight,
        ),
        (
            3,
            "Nyquist plots of G_L (7), K_C = 0.3, d = τ_Z = 0.5, τ_I = 2.5, various τ_D",
            ("re", "Re G_L(jw)"),
            ("im", "Im G_L(jw)"),
            false,
            (Some(nx), ny),
            Legend::LowerRight,
        ),
        (
            4,
            "PM_max (12) against τ_D, one curve per τ_I, d = τ_Z = 1.5",
            ("tau_d", "τ_D"),
            ("pm_max_deg", "PM_max (degrees)"),
            false,
            (None, ALL),
            Legend::UpperLeft,
        ),
        (
            5,
            "GM_max as the ultimate gain K_u against τ_D, one curve per τ_I, d = τ_Z = 0.5",
            ("tau_d", "τ_D"),
            ("k_u", "K_u (gain margin at K_C = 1)"),
            false,
            (None, ALL),
            Legend::UpperRight,
        ),
        (
            6,
            "τ_D,GMmax(τ_I, τ_Z, d) against τ_I",
            ("tau_i", "τ_I (log scale)"),
            ("tau_d_gm_max", "τ_D,GMmax"),
            true,
            (Some((0.1, 100.0)), ALL),
            Legend::UpperRight,
        ),
        (
            7,
            "τ_D,maxGM,I-P(τ_I, τ_Z, d) against τ_I (→ ∞ as τ_I → d + τ_Z + 1)",
            ("tau_i", "τ_I (log scale)"),
            ("tau_d_max_gm_ip", "τ_D,maxGM,I-P"),
            true,
            (Some((1.0, 100.0)), (0.0, 6.0)),
            Legend::UpperRight,
        ),
    ];
    for (n, title, x, y, x_log, (x_range, y_win), legend) in list {
        let src = format!("arvanitis2012_fig{n}.csv");
        let csv = Csv::read(dir, &src)?;
        let mut curves = groups(&csv, x.0, y.0, greek)?;
        window(&mut curves, (x_range.unwrap_or(ALL), y_win));
        let number = ["Fig. 2", "Fig. 3", "Fig. 4", "Fig. 5", "Fig. 6", "Fig. 7"][n - 2];
        let mut ch = chart(
            format!("Arvanitis et al. 2012, {number}: {title}"),
            x.1,
            x_range,
            vec![panel(y.1, curves)],
        );
        ch.x_log = x_log;
        ch.legend = legend;
        v.push(Figure {
            paper: ARV,
            number,
            file: format!("arvanitis2012_fig{n}.svg"),
            sources: vec![src],
            chart: ch,
        });
    }
    Ok(())
}

/// Every regenerated figure, drawn from the CSVs in `dir`.
pub fn figures(dir: &Path) -> Result<Vec<Figure>, String> {
    let mut v = vec![];
    let mut add = |paper, number, file: &str, sources: &[&str], chart| {
        v.push(Figure {
            paper,
            number,
            file: file.into(),
            sources: sources.iter().map(|s| s.to_string()).collect(),
            chart,
        })
    };
    // Arvanitis et al. 2012, Figs. 8–12: boiler steam drum, set point at 0, load at 30.
    const ARV: &str = "Arvanitis et al. 2012";
    for (n, what) in [
        (8, "Algorithm I of Method I"),
        (9, "Algorithm II of Method I, ζ_des = 0.6"),
        (10, "Algorithm III (min. of (13))"),
        (11, "Method II, ξ_des = 0.707"),
        (12, "Method II minimizing (13)"),
    ] {
        let src = format!("arvanitis2012_fig{n}.csv");
        let csv = Csv::read(dir, &src)?;
        let ys = wide(&csv, "y_", arvanitis_label)?;
        let us = wide(&csv, "u_", |c| arvanitis_label(c.trim_start_matches("u_")))?;
        let number = ["Fig. 8", "Fig. 9", "Fig. 10", "Fig. 11", "Fig. 12"][n - 8];
        add(
            ARV,
            number,
            &format!("arvanitis2012_fig{n}.svg"),
            &[src.as_str()],
            chart(
                format!("Arvanitis et al. 2012, {number}: boiler steam drum, {what} (set point at 0, load at 30)"),
                "time",
                Some((0.0, 60.0)),
                vec![panel("output y", ys), panel("control u", us)],
            ),
        );
    }
    // Shamsuzzoha & Lee 2008, Figs. 2–6: nominal set-point and load responses.
    const SL: &str = "Shamsuzzoha & Lee 2008";
    for ex in 1..=5 {
        let src = format!("shamsuzzoha_lee2008_ex{ex}_responses.csv");
        let csv = Csv::read(dir, &src)?;
        let number = ["Fig. 2", "Fig. 3", "Fig. 4", "Fig. 5", "Fig. 6"][ex - 1];
        add(
            SL,
            number,
            &format!("shamsuzzoha_lee2008_fig{}.svg", ex + 1),
            &[src.as_str()],
            chart(
                format!("Shamsuzzoha & Lee 2008, {number}: response of the nominal system, Example {ex}"),
                "time",
                None,
                vec![
                    panel("output y", long_responses(&csv, "nominal", "y")?),
                    panel("control u", long_responses(&csv, "nominal", "u")?),
                ],
            ),
        );
    }
    {
        let f = "shamsuzzoha_lee2008_fig8_fig7.csv";
        let g = "shamsuzzoha_lee2008_fig7_chen_seborg.csv";
        let csv = Csv::read(dir, f)?;
        let cs = Csv::read(dir, g)?;
        let x = csv.col("theta_over_tau")?;
        let curves = vec![
            curve("proposed", csv.xy(x, csv.col("load_iae_ms2.0")?, |_| true)),
            curve(
                "Zhang et al.",
                csv.xy(x, csv.col("zhang_load_iae_ms2.0")?, |_| true),
            ),
            curve(
                "Chen & Seborg",
                cs.xy(
                    cs.col("theta_over_tau")?,
                    cs.col("chen_seborg_load_iae_ms2.0")?,
                    |_| true,
                ),
            ),
        ];
        add(
            SL,
            "Fig. 7",
            "shamsuzzoha_lee2008_fig7.svg",
            &[f, g],
            chart(
                "Shamsuzzoha & Lee 2008, Fig. 7: load IAE at Ms = 2.0, FODIP e^(-θs)/(s(s+1))"
                    .into(),
                "θ/τ",
                None,
                vec![panel("IAE (unit load step)", curves)],
            ),
        );
        add(
            SL,
            "Fig. 8",
            "shamsuzzoha_lee2008_fig8.svg",
            &[f],
            chart(
                "Shamsuzzoha & Lee 2008, Fig. 8: λ guidelines for FODIP".into(),
                "θ/τ",
                None,
                vec![panel("λ", lambda_guidelines(&csv, x)?)],
            ),
        );
        let f9 = "shamsuzzoha_lee2008_fig9.csv";
        let c9 = Csv::read(dir, f9)?;
        let x9 = c9.col("theta")?;
        add(
            SL,
            "Fig. 9",
            "shamsuzzoha_lee2008_fig9.svg",
            &[f9],
            chart(
                "Shamsuzzoha & Lee 2008, Fig. 9: λ guidelines for DIP".into(),
                "θ",
                None,
                vec![panel("λ", lambda_guidelines(&c9, x9)?)],
            ),
        );
    }
    // Kaya 2020, Figs. 4–9.
    const KAYA: &str = "Kaya 2020";
    for (n, what, ylab) in [
        (4, "closed-loop responses, Example 1", "output y"),
        (5, "closed-loop responses, perturbed Example 1", "output y"),
        (6, "output responses, Example 2", "output y"),
        (7, "process inputs, Example 2", "input u"),
        (8, "output responses, Example 3", "output y"),
        (9, "process inputs, Example 3", "input u"),
    ] {
        let src = format!("kaya2020_fig{n}.csv");
        let csv = Csv::read(dir, &src)?;
        let number = ["Fig. 4", "Fig. 5", "Fig. 6", "Fig. 7", "Fig. 8", "Fig. 9"][n - 4];
        add(
            KAYA,
            number,
            &format!("kaya2020_fig{n}.svg"),
            &[src.as_str()],
            chart(
                format!("Kaya 2020, {number}: {what}"),
                "time (s)",
                None,
                vec![panel(ylab, wide(&csv, "", |c| c.to_string())?)],
            ),
        );
    }
    // Kaya 2020, Figs. 2-3: the ISTE fits (lines) and our optimized settings (asterisks), one
    // panel per T₀/T; colours as the paper's (black T_d/T, red T_i/T, blue KK_c).
    {
        let (f, g) = ("kaya2020_fig2_fig3.csv", "kaya2020_optima.csv");
        let (fit, opt) = (Csv::read(dir, f)?, Csv::read(dir, g)?);
        for (number, file, (lo, hi)) in [
            ("Fig. 2", "kaya2020_fig2.svg", (0.1, 1.0)),
            ("Fig. 3", "kaya2020_fig3.svg", (1.1, 2.0)),
        ] {
            let mut panels = vec![];
            for (k, t0) in ["0.7", "1.0"].iter().enumerate() {
                let mut curves = vec![];
                for (csv, markers) in [(&fit, false), (&opt, true)] {
                    let (y, x) = (csv.col("t0_over_t")?, csv.col("theta_over_t")?);
                    for (color, (col, name)) in [
                        ("td_over_t", "T_d/T"),
                        ("ti_over_t", "T_i/T"),
                        ("kkc", "KK_c"),
                    ]
                    .into_iter()
                    .enumerate()
                    {
                        let what = if markers { "optimized" } else { "fit" };
                        let mut c = curve(
                            &format!("{name}, {what}"),
                            csv.xy(x, csv.col(col)?, |r| r[y] == *t0),
                        );
                        c.markers = markers;
                        c.color = Some(color);
                        curves.push(c);
                    }
                }
                let mut p = panel("setting", curves);
                p.title = format!("({}) T_0/T = {t0}", ["a", "b"][k]);
                panels.push(p);
            }
            add(
                KAYA,
                number,
                file,
                &[f, g],
                chart(
                    format!(
                        "Kaya 2020, {number}: I-PD parameters over {lo} ≤ θ/T ≤ {hi}, ISTE \
                         (lines: Eqs. 5-7; asterisks: our optima, 3/3-Padé design loop)"
                    ),
                    "θ/T",
                    Some((lo - 0.02, hi + 0.02)),
                    panels,
                ),
            );
        }
    }
    // Medarametla & Manimozhi 2018: Fig. 2 (Ms against λ/θ), Figs. 13–14 (CSTR).
    const MED: &str = "Medarametla & Manimozhi 2018";
    {
        let f = "medarametla_fig2_ms_lambda.csv";
        let csv = Csv::read(dir, f)?;
        let mut all = groups(&csv, "lambda_over_theta", "ms", |id| id.to_string())?;
        // Ms ≤ 4 shown (the range of Table 1's guidelines, 1.3-3, with room): near the
        // smallest admissible λ Ms grows without bound and would flatten every curve.
        window(&mut all, ((f64::NEG_INFINITY, f64::INFINITY), (0.0, 4.0)));
        // The paper's panels, by the curve names' family (studies::fig2's names).
        let mut panels = vec![];
        for (title, family) in [
            ("(a) pure integrating process with time delay", "PIPTD"),
            ("(b) double integrating process with time delay", "DIPTD"),
            (
                "(c) integrating first order process with time delay",
                "IFOPTD θ",
            ),
            ("(d) IFOPTD with zero", "IFOPTD+zero"),
        ] {
            let mut p = panel(
                "Ms",
                all.iter()
                    .filter(|c| c.label.starts_with(family))
                    .map(|c| curve(&c.label, c.points.clone()))
                    .collect(),
            );
            p.title = title.into();
            panels.push(p);
        }
        let drawn: usize = panels.iter().map(|p| p.curves.len()).sum();
        if drawn != all.len() {
            return Err(format!("{f}: {} curves, {drawn} in the panels", all.len()));
        }
        let mut ch = chart(
            "Medarametla & Manimozhi 2018, Fig. 2: variation of Ms with λ/θ (k = θ = 1, Ms ≤ 4 shown)"
                .into(),
            "λ/θ",
            None,
            panels,
        );
        ch.legend = Legend::UpperRight;
        ch.x_log = true;
        add(MED, "Fig. 2", "medarametla_fig2.svg", &[f], ch);
        let s = "medarametla_cstr_servo.csv";
        let csv = Csv::read(dir, s)?;
        let t = csv.col("t")?;
        let mut a = panel(
            "reactor temperature T (K)",
            vec![
                curve("set point", csv.xy(t, csv.col("r")?, |_| true)),
                curve(
                    "proposed, nonlinear CSTR",
                    csv.xy(t, csv.col("T")?, |_| true),
                ),
            ],
        );
        a.title = "(a) nominal servo response".into();
        let mut b = panel(
            "jacket temperature T_j (K)",
            vec![curve("proposed", csv.xy(t, csv.col("Tj")?, |_| true))],
        );
        b.title = "(b) control signal".into();
        add(
            MED,
            "Fig. 13",
            "medarametla_fig13.svg",
            &[s],
            chart(
                "Medarametla & Manimozhi 2018, Fig. 13: jacketed CSTR (Example 6), set point 344 → 346 K".into(),
                "time (s)",
                None,
                vec![a, b],
            ),
        );
        let g = "medarametla_cstr_regulatory.csv";
        let csv = Csv::read(dir, g)?;
        let t = csv.col("t")?;
        add(
            MED,
            "Fig. 14",
            "medarametla_fig14.svg",
            &[g],
            chart(
                "Medarametla & Manimozhi 2018, Fig. 14: nominal regulatory response of Example 6 (T_j 317.4 → 310 K)".into(),
                "time (s)",
                None,
                vec![panel(
                    "reactor temperature T (K)",
                    vec![
                        curve("set point", csv.xy(t, csv.col("r")?, |_| true)),
                        curve("proposed, nonlinear CSTR", csv.xy(t, csv.col("T")?, |_| true)),
                    ],
                )],
            ),
        );
    }
    medarametla(dir, &mut v)?;
    praveen_kumar(dir, &mut v)?;
    arvanitis_section3(dir, &mut v)?;
    Ok(v)
}

fn medarametla_label(col: &str) -> String {
    let k = &col[2..];
    let (k, tail) = match k.strip_suffix("_load_only") {
        Some(k) => (k, " (load step only)"),
        None => (k, ""),
    };
    let name = match k {
        "proposed" => "proposed",
        "anil_padma_sree" => "Anil & Padma Sree",
        "ajmeri_ali" => "Ajmeri & Ali",
        other => other,
    };
    format!("{name}{tail}")
}

/// Medarametla & Manimozhi 2018, Figs. 3–12: Examples 1–5, nominal (odd) and gain and delay
/// +20 % (even), output and control signal (`medarametla_ex*_*.csv`; Examples 2 and 4 in four
/// panels, servo and regulatory apart, as their captions list them).
fn medarametla(dir: &Path, v: &mut Vec<Figure>) -> Result<(), String> {
    const MED: &str = "Medarametla & Manimozhi 2018";
    const NUMBERS: [&str; 10] = [
        "Fig. 3", "Fig. 4", "Fig. 5", "Fig. 6", "Fig. 7", "Fig. 8", "Fig. 9", "Fig. 10", "Fig. 11",
        "Fig. 12",
    ];
    for ex in 1..=5 {
        for (j, cond) in ["nominal", "perturbed"].iter().enumerate() {
            let number = NUMBERS[2 * (ex - 1) + j];
            let file = format!("medarametla_fig{}.svg", 3 + 2 * (ex - 1) + j);
            let what = if j == 0 {
                "nominal response"
            } else {
                "perturbed response (gain and delay +20 %)"
            };
            if ex == 2 || ex == 4 {
                // Figs. 5-6, 9-10: (a) servo response, (b) its control signal, (c) regulatory
                // response, (d) its control signal (separate files; each panel its own time span).
                let (sf, rf) = (
                    format!("medarametla_ex{ex}_{cond}_servo.csv"),
                    format!("medarametla_ex{ex}_{cond}_regulatory.csv"),
                );
                let (s, r) = (Csv::read(dir, &sf)?, Csv::read(dir, &rf)?);
                let mut panels = vec![];
                for (k, (csv, prefix, y, what)) in [
                    (&s, "y_", "output y", "servo response"),
                    (
                        &s,
                        "u_",
                        "control signal u",
                        "control signal for the servo response",
                    ),
                    (&r, "y_", "output y", "regulatory response"),
                    (
                        &r,
                        "u_",
                        "control signal u",
                        "control signal for the regulatory response",
                    ),
                ]
                .into_iter()
                .enumerate()
                {
                    let mut p = panel(y, wide(csv, prefix, medarametla_label)?);
                    p.title = format!("({}) {} {what}", ["a", "b", "c", "d"][k], cond);
                    panels.push(p);
                }
                v.push(Figure {
                    paper: MED,
                    number,
                    file,
                    sources: vec![sf, rf],
                    chart: chart(
                        format!("Medarametla & Manimozhi 2018, {number}: Example {ex}, {what}"),
                        "time (s)",
                        None,
                        panels,
                    ),
                });
                continue;
            }
            let src = format!("medarametla_ex{ex}_{cond}.csv");
            let csv = Csv::read(dir, &src)?;
            // Figs. 11-12 (Example 5) show the response only; the others also the control.
            let mut panels = vec![panel("output y", wide(&csv, "y_", medarametla_label)?)];
            if ex != 5 {
                panels.push(panel(
                    "control signal u",
                    wide(&csv, "u_", medarametla_label)?,
                ));
            }
            v.push(Figure {
                paper: MED,
                number,
                file,
                sources: vec![src],
                chart: chart(
                    format!("Medarametla & Manimozhi 2018, {number}: {what} of Example {ex}"),
                    "time (s)",
                    None,
                    panels,
                ),
            });
        }
    }
    Ok(())
}

/// Praveen Kumar & Narayana, Figs. 3–15: servo and regulatory runs (0.2 steps) of Examples 1–2,
/// output and manipulated variable, nominal and with the dead time +40 %, proposed and Pai et
/// al. 2010 (`praveen_kumar_ex*_*.csv`).
fn praveen_kumar(dir: &Path, v: &mut Vec<Figure>) -> Result<(), String> {
    const PK: &str = "Praveen Kumar & Narayana";
    // Fig. 2: λτ for Ms = 2 against θ/τ, one curve per z/τ (the rule's target-Ms solve).
    let f2 = "praveen_kumar_fig2.csv";
    let csv = Csv::read(dir, f2)?;
    let mut ch = chart(
        "Praveen Kumar & Narayana, Fig. 2: λτ for Ms = 2 against θ/τ, plant (1 − (z/τ)ŝ)e^(−(θ/τ)ŝ)/(ŝ(ŝ + 1))"
            .into(),
        "θ/τ",
        None,
        vec![panel(
            "λτ (Ms = 2)",
            groups(&csv, "theta_over_tau", "lambda_tau", |c| c.to_string())?,
        )],
    );
    ch.legend = Legend::UpperRight;
    v.push(Figure {
        paper: PK,
        number: "Fig. 2",
        file: "praveen_kumar_fig2.svg".into(),
        sources: vec![f2.into()],
        chart: ch,
    });
    let list: [(&str, usize, &str, &str, &str); 13] = [
        ("Fig. 3", 1, "nominal", "servo", "y"),
        ("Fig. 4", 1, "nominal", "servo", "u"),
        ("Fig. 5", 1, "nominal", "regulatory", "y"),
        ("Fig. 6", 1, "nominal", "regulatory", "u"),
        ("Fig. 7", 1, "perturbed", "servo", "y"),
        ("Fig. 8", 2, "nominal", "servo", "y"),
        ("Fig. 9", 2, "nominal", "servo", "u"),
        ("Fig. 10", 2, "nominal", "regulatory", "y"),
        ("Fig. 11", 2, "nominal", "regulatory", "u"),
        ("Fig. 12", 2, "perturbed", "servo", "y"),
        ("Fig. 13", 2, "perturbed", "servo", "u"),
        ("Fig. 14", 2, "perturbed", "regulatory", "y"),
        ("Fig. 15", 2, "perturbed", "regulatory", "u"),
    ];
    for (number, ex, cond, run, sig) in list {
        let src = format!("praveen_kumar_ex{ex}_{cond}.csv");
        let csv = Csv::read(dir, &src)?;
        let t = csv.col("t")?;
        let curves = [("proposed", "proposed"), ("pai2010", "Pai et al. 2010")]
            .iter()
            .map(|(k, label)| -> Result<Curve, String> {
                let c = csv.col(&format!("{sig}_{run}_{k}"))?;
                Ok(curve(label, csv.xy(t, c, |_| true)))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let what = match (sig, run) {
            ("y", "servo") => "servo response",
            ("u", "servo") => "manipulated variable for servo response",
            ("y", _) => "regulatory response",
            _ => "manipulated variable for regulatory response",
        };
        let cond_text = if cond == "nominal" {
            "nominal conditions"
        } else {
            "perturbed conditions (dead time +40 %)"
        };
        let file = format!(
            "praveen_kumar_fig{}.svg",
            number.trim_start_matches("Fig. ")
        );
        v.push(Figure {
            paper: PK,
            number,
            file,
            sources: vec![src],
            chart: chart(
                format!(
                    "Praveen Kumar & Narayana, {number}: {what} of example {ex} under {cond_text}"
                ),
                "time (s)",
                None,
                vec![panel(
                    if sig == "y" {
                        "output y"
                    } else {
                        "manipulated variable u"
                    },
                    curves,
                )],
            ),
        });
    }
    Ok(())
}

/// Width and per-panel height of every SVG (pixels).
pub const SIZE: (u32, u32) = (760, 340);

/// The SVG of `f`.
pub fn svg(f: &Figure) -> Result<String, String> {
    render(&f.chart, SIZE.0, SIZE.1).map_err(|e| format!("{}: {e}", f.file))
}

/// The report's figure section: per paper, links to the SVGs (and their CSVs), then the figures
/// not regenerated.
pub fn section(figs: &[Figure]) -> String {
    let mut o = String::from(
        "## Figures\n\nEvery regenerated figure, as SVG drawn from the CSV beside it \
         (plotters' SVG backend, same bytes every run; `tests/figures.rs` checks them).\n\n",
    );
    let mut papers: Vec<&str> = vec![];
    for f in figs {
        if !papers.contains(&f.paper) {
            papers.push(f.paper);
        }
    }
    for p in papers {
        let _ = write!(o, "- {p}:");
        let mut of_paper: Vec<&Figure> = figs.iter().filter(|f| f.paper == p).collect();
        of_paper.sort_by_key(|f| {
            f.number
                .trim_start_matches("Fig. ")
                .parse::<u32>()
                .unwrap_or(0)
        });
        for f in of_paper {
            let srcs: Vec<String> = f
                .sources
                .iter()
                .map(|s| format!("[csv](figures/{s})"))
                .collect();
            let _ = write!(
                o,
                " [{}](figures/{}) ({});",
                f.number,
                f.file,
                srcs.join(", ")
            );
        }
        o.pop();
        o.push('\n');
    }
    let missing: Vec<_> = MISSING.iter().filter(|m| m.1 != "—").collect();
    if missing.is_empty() {
        o.push_str(
            "\nEvery figure of the five papers is regenerated except each paper's Fig. 1 (a block \
             diagram).\n",
        );
    } else {
        o.push_str("\nNot regenerated yet:\n\n");
        for (p, n, why) in missing {
            let _ = writeln!(o, "- {p}, {n}: {why}.");
        }
    }
    o
}
