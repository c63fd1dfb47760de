//! `matlab` target: a Control System Toolbox script. The plant is `tf(num, den,
//! 'InputDelay', theta)` (exact dead time), the controller `Cr`, `Cy` as `tf`; when `Cy` is a
//! standard PID (integral action, ideal or first-order-filtered derivative) it is also given as
//! `pidstd(Kp, Ti, Td, N)`, and when `Cr` is the same PID with set-point weights, the pair as
//! `pidstd2(Kp, Ti, Td, N, b, c)`. The `tf` coefficients are the design; the standard-form
//! numbers are recovered from them (a few roundings away) and the script checks they agree.

use super::{comment_lines, header, num, std_pid, tf_texts, Design};
use std::fmt::Write;

/// The script's text.
pub fn write(d: &Design) -> String {
    let mut s = comment_lines(
        &header(d, "MATLAB script (Control System Toolbox)"),
        "% ",
        &[],
    );
    let (pn, pd, theta, rn, rd, yn, yd) = tf_texts(d);
    let _ = write!(
        s,
        r#"
% Plant with its exact dead time: P(s)*exp(-theta*s).
theta = {theta};
P = tf([{pn}], [{pd}], 'InputDelay', theta);

% Controller (two degrees of freedom): u = Cr(s)*r - Cy(s)*y.
Cr = tf([{rn}], [{rd}]);
Cy = tf([{yn}], [{yd}]);
"#,
    );
    let proper = d.controller.cy.is_proper() && d.controller.cr.is_proper();
    match std_pid(&d.controller) {
        Some(p) => {
            let n = if p.n.is_finite() {
                num(p.n)
            } else {
                "Inf".into()
            };
            let _ = write!(
                s,
                r#"
% Cy in standard form: Kp*(1 + 1/(Ti*s) + Td*s/((Td/N)*s + 1)) (N = Inf: ideal derivative).
Kp = {kp};
Ti = {ti};
Td = {td};
N = {n};
C = pidstd(Kp, Ti, Td, N);
% the standard form is recovered from the tf coefficients: the two agree to rounding
assert(max(abs(freqresp(tf(C) - Cy, [0.1, 1, 10]))) <= 1e-9 * max(abs(freqresp(Cy, [0.1, 1, 10]))));
"#,
                kp = num(p.kp),
                ti = num(p.ti),
                td = num(p.td),
            );
            if let (Some(b), Some(c)) = (p.b, p.c) {
                if b == 1.0 && c == 1.0 {
                    s.push_str("% Cr = Cy: a one-degree-of-freedom PID on the error, C above.\n");
                } else {
                    let _ = write!(
                        s,
                        r#"
% Cr is the same PID with set-point weights b (proportional) and c (derivative):
% u = Kp*[(b*r - y) + 1/(Ti*s)*(r - y) + Td*s/((Td/N)*s + 1)*(c*r - y)].
b = {b};
c = {c};
C2 = pidstd2(Kp, Ti, Td, N, b, c);
"#,
                        b = num(b),
                        c = num(c),
                    );
                }
            } else {
                s.push_str(
                    "% Cr is not a set-point-weighted form of this PID (e.g. a set-point filter): use Cr above.\n",
                );
            }
        }
        None => s.push_str(
            "\n% Cy is not a standard PID (pidstd) with integral action: the tf form above is the controller.\n",
        ),
    }
    if proper {
        s.push_str(
            r#"
% Closed loop (exact dead time; the load d enters at the plant input).
T_yr = feedback(P, Cy) * Cr;   % y/r
T_yd = feedback(P, Cy);        % y/d
step(T_yr, T_yd); legend('set-point step', 'load step');
"#,
        );
    } else {
        s.push_str(
            r#"
% Closed loop (exact dead time; the load d enters at the plant input). The ideal derivative
% makes Cy improper, which feedback() cannot take: form L = Cy*P first (proper).
L = Cy * P;
T_yr = minreal(Cr / Cy) * feedback(L, 1);   % y/r = (Cr/Cy) * L/(1 + L)
T_yd = feedback(L, 1) / Cy;                 % y/d = P/(1 + L)
step(T_yr, T_yd); legend('set-point step', 'load step');
"#,
        );
    }
    s
}
