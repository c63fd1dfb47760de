//! `julia` target: a ControlSystems.jl script. The plant is `P * delay(theta)` (exact dead
//! time, a `DelayLtiSystem`), the controller `Cr`, `Cy` as `tf`. Delay systems close only
//! through `feedback`, and an ideal derivative (improper `Cy`) has no state-space form, so the
//! loop is formed as `L = tf(Cy*P) * delay(theta)` (proper) and
//! `y/r = (Cr/Cy)·feedback(L, 1)`, `y/d = feedback(L, 1)·(1/Cy)` when `Cy` is improper, else
//! `feedback(P*delay(theta), Cy)`.

use super::{comment_lines, header, tf_texts, Design};
use std::fmt::Write;

/// The script's text.
pub fn write(d: &Design) -> String {
    let mut s = comment_lines(&header(d, "Julia script (ControlSystems.jl)"), "# ", &[]);
    let (pn, pd, theta, rn, rd, yn, yd) = tf_texts(d);
    let _ = write!(
        s,
        r#"
using ControlSystems

# Plant with its exact dead time: P(s)*exp(-theta*s).
P = tf([{pn}], [{pd}])
theta = {theta}
P_delay = P * delay(theta)

# Controller (two degrees of freedom): u = Cr(s)*r - Cy(s)*y.
Cr = tf([{rn}], [{rd}])
Cy = tf([{yn}], [{yd}])

# Loop transfer function with the exact dead time (Cy*P is proper).
L = ss(Cy * P) * delay(theta)
T_yr = ss(minreal(Cr / Cy)) * feedback(L, 1.0)   # y/r = (Cr/Cy) * L/(1 + L)
"#,
    );
    if d.controller.cy.is_proper() {
        s.push_str(
            "T_yd = feedback(P_delay, ss(Cy))                 # y/d (load at the plant input)\n",
        );
    } else {
        let _ = writeln!(
            s,
            "T_yd = feedback(L, 1.0) * ss(tf([{yd}], [{yn}]))   # y/d = P/(1 + L) = (L/(1 + L)) / Cy",
        );
    }
    s.push_str(
        r#"
# Step responses (ControlSystems simulates the dead time exactly):
# using Plots; plot(step(T_yr, 50)); plot!(step(T_yd, 50))
"#,
    );
    s
}
