//! `c` target: one C99 file with the sampled controller as a state struct, an `init` and a
//! `step` function (the statements of [`DiscreteController::step`], see [`super::sampled`]),
//! and, under `#ifdef PIDLAB_EXPORT_MAIN`, a `main` that reads `r y` pairs from standard input
//! and prints `v u` per line (`%.17g`, round-trip exact): how the test runs it.

use super::sampled::{diff_eq, header as sampled_header, tables};
use super::{comment_lines, header, num, nums, Design};
use crate::model::discrete::{DiscreteController, Law};
use std::fmt::Write;

/// The C source. `name` is the identifier prefix (e.g. `pidlab_kaya`).
pub fn write(d: &Design, dc: &DiscreteController, name: &str) -> String {
    let mut h = header(d, "C99 sampled controller");
    h.extend(sampled_header(dc));
    h.push(format!(
        "Use: {name}_state s; {name}_init(&s); then every h: u = {name}_step(&s, r, y, &v);"
    ));
    h.push("Build the demo: cc -std=c99 -DPIDLAB_EXPORT_MAIN file.c (stdin: r y per line).".into());
    let mut s = String::from("/*\n");
    s.push_str(&comment_lines(&h, " * ", &["*/"]));
    s.push_str(" */\n");
    let eq = diff_eq(dc);
    let n = eq.order();
    // ASCII: `name` is a `stem` (no Unicode case tables in the wasm module, issue 15)
    let up = name.to_ascii_uppercase();
    let _ = write!(
        s,
        r#"
#include <stdio.h>

#define {up}_N {n} /* order of the difference equation */

/* State: histories newest first (index i: the value i samples ago), all zero at rest. */
typedef struct {{
    double r[{up}_N + 1]; /* set points r_k, r_(k-1), ... */
    double y[{up}_N + 1]; /* measurements */
    double u[{up}_N + 1]; /* applied inputs u = sat(v) */
    double v[{up}_N + 1]; /* outputs of the difference equation */
    double x;             /* integral state (conditional integration) */
    double e_prev;        /* previous integrator input (conditional integration) */
}} {name}_state;

/* Coefficients in powers of z^-1 (index i multiplies the value i samples ago), a[0] = 1:
 * c_k = sum_i (b_r[i] r_(k-i) - b_y[i] y_(k-i)) + sum_(i>=1) (b_u[i] u_(k-i) - a[i] v_(k-i)) */
"#
    );
    for (t, xs) in tables(eq) {
        let _ = writeln!(
            s,
            "static const double {name}_{t}[{up}_N + 1] = {{{}}};",
            nums(xs)
        );
    }
    if let Law::Clamped { integrator: ig, .. } = &dc.law {
        let _ = write!(
            s,
            r#"/* Conditional integration: x_k = x_(k-1) + c0 e_k + c1 e_(k-1), e_k = g_r r_k - g_y y_k */
static const double {name}_c0 = {c0};
static const double {name}_c1 = {c1};
static const double {name}_g_r = {gr};
static const double {name}_g_y = {gy};
"#,
            c0 = num(ig.c0),
            c1 = num(ig.c1),
            gr = num(ig.g_r),
            gy = num(ig.g_y),
        );
    }
    let (lo, hi) = (dc.limits.u_min, dc.limits.u_max);
    if lo.is_finite() {
        let _ = writeln!(s, "static const double {name}_u_min = {};", num(lo));
    }
    if hi.is_finite() {
        let _ = writeln!(s, "static const double {name}_u_max = {};", num(hi));
    }
    let _ = write!(
        s,
        r#"
/* Back to rest. */
void {name}_init({name}_state *s)
{{
    int i;
    for (i = 0; i <= {up}_N; i++) {{
        s->r[i] = 0.0;
        s->y[i] = 0.0;
        s->u[i] = 0.0;
        s->v[i] = 0.0;
    }}
    s->x = 0.0;
    s->e_prev = 0.0;
}}

static void {name}_push(double *hist, double x)
{{
    int i;
    for (i = {up}_N; i > 0; i--)
        hist[i] = hist[i - 1];
    hist[0] = x;
}}

/* The difference equation's terms but b_u[0] u_k (r_k and y_k already pushed). */
static double {name}_known(const {name}_state *s)
{{
    double c = 0.0;
    int i;
    for (i = 0; i <= {up}_N; i++) {{
        c += {name}_b_r[i] * s->r[i] - {name}_b_y[i] * s->y[i];
        if (i >= 1)
            c += {name}_b_u[i] * s->u[i - 1] - {name}_a[i] * s->v[i - 1];
    }}
    return c;
}}

/* u_k = sat(v_k) */
static double {name}_sat(double v)
{{
    double u = v;
"#
    );
    if lo.is_finite() {
        let _ = writeln!(s, "    if (u < {name}_u_min)\n        u = {name}_u_min;");
    }
    if hi.is_finite() {
        let _ = writeln!(s, "    if (u > {name}_u_max)\n        u = {name}_u_max;");
    }
    let _ = write!(
        s,
        r#"    return u;
}}

/* One sample: reads r_k and y_k, returns u_k (hold it until the next sample); *v_out (may be
 * NULL) receives v_k, the output before the limits. */
double {name}_step({name}_state *s, double r, double y, double *v_out)
{{
    double v, u;
    {name}_push(s->r, r);
    {name}_push(s->y, y);
"#
    );
    match &dc.law {
        Law::Linear(eq) => {
            let w0 = eq.b_u[0];
            if w0 == 0.0 {
                s.push_str(&format!("    v = {name}_known(s);\n"));
            } else {
                // v = c + w0·sat(v), solved exactly (0 ≤ w0 < 1)
                let _ = writeln!(
                    s,
                    "    {{\n        /* v = c + b_u[0] sat(v), solved exactly (0 <= b_u[0] < 1) */"
                );
                let _ = writeln!(s, "        double c = {name}_known(s);");
                let _ = writeln!(s, "        double free_v = c / (1.0 - {name}_b_u[0]);");
                let mut first = true;
                if hi.is_finite() {
                    let _ = writeln!(
                        s,
                        "        if (free_v > {name}_u_max)\n            v = c + {name}_b_u[0] * {name}_u_max;"
                    );
                    first = false;
                }
                if lo.is_finite() {
                    let _ = writeln!(
                        s,
                        "        {}if (free_v < {name}_u_min)\n            v = c + {name}_b_u[0] * {name}_u_min;",
                        if first { "" } else { "else " }
                    );
                    first = false;
                }
                if first {
                    let _ = writeln!(s, "        v = free_v;");
                } else {
                    let _ = writeln!(s, "        else\n            v = free_v;");
                }
                s.push_str("    }\n");
            }
            let _ = write!(
                s,
                "    u = {name}_sat(v);\n    {name}_push(s->v, v);\n    {name}_push(s->u, u);\n"
            );
        }
        Law::Clamped { .. } => {
            let mut clamp = vec![];
            if hi.is_finite() {
                clamp.push(format!("(v > {name}_u_max && dx > 0.0)"));
            }
            if lo.is_finite() {
                clamp.push(format!("(v < {name}_u_min && dx < 0.0)"));
            }
            let cond = if clamp.is_empty() {
                "0".to_string()
            } else {
                clamp.join(" || ")
            };
            let _ = write!(
                s,
                r#"    {{
        /* conditional integration: the integral state stops while v is at a limit and
         * its increment drives v further out */
        double e = {name}_g_r * r - {name}_g_y * y;
        double dx = {name}_c0 * e + {name}_c1 * s->e_prev;
        double vr;
        s->e_prev = e;
        vr = {name}_known(s);
        {name}_push(s->v, vr);
        v = s->x + dx + vr;
        if (!({cond}))
            s->x += dx;
        v = s->x + vr;
    }}
    u = {name}_sat(v);
    {name}_push(s->u, u);
"#
            );
        }
    }
    let _ = write!(
        s,
        r#"    if (v_out)
        *v_out = v;
    return u;
}}

#ifdef PIDLAB_EXPORT_MAIN
/* Demo / check: reads "r y" per line from stdin, prints "v u" per line. */
int main(void)
{{
    {name}_state s;
    double r, y, v, u;
    {name}_init(&s);
    while (scanf("%lf %lf", &r, &y) == 2) {{
        u = {name}_step(&s, r, y, &v);
        printf("%.17g %.17g\n", v, u);
    }}
    return 0;
}}
#endif
"#
    );
    s
}
