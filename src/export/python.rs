//! `python-control` target: a runnable script defining `P` (the rational part), `theta`, `Cr`
//! and `Cy` as `control.tf` with pidlab's coefficients, and, because python-control has no
//! exact dead time, a Padé approximant of stated order for its simulations.
//!
//! Run as `python pidlab_x.py`: closed-loop stability and step responses with the Padé plant;
//! `--json`: the four transfer functions (coefficients as python-control holds them and their
//! frequency responses evaluated by python-control) for checking against pidlab; `--plot`:
//! the step responses with matplotlib.

use super::{comment_lines, header, nums, tf_texts, Design};
use std::fmt::Write;

/// Padé order used for the simulations of the script (stated in its text).
pub const PADE_ORDER: usize = 6;

/// The frequencies at which `--json` evaluates the transfer functions (rad per time unit).
pub const CHECK_W: [f64; 6] = [0.013, 0.1, 0.37, 1.0, 2.9, 10.0];

/// The script's text.
pub fn write(d: &Design) -> String {
    let mut s = comment_lines(&header(d, "python-control script"), "# ", &[]);
    let (pn, pd, theta, rn, rd, yn, yd) = tf_texts(d);
    let _ = write!(
        s,
        r#"#
# Run: python {{this file}}          (closed loop with a Pade dead time, step responses)
#      python {{this file}} --json   (the transfer functions, for checking against pidlab)
#      python {{this file}} --plot   (step responses with matplotlib)
import json
import sys

import control
import numpy as np

# Plant: P(s) * exp(-theta*s); P is the rational part, theta the exact dead time.
P = control.tf([{pn}], [{pd}])
theta = {theta}

# Controller (two degrees of freedom): u = Cr(s)*r - Cy(s)*y.
Cr = control.tf([{rn}], [{rd}])
Cy = control.tf([{yn}], [{yd}])

# python-control has no exact dead time: its simulations below replace exp(-theta*s) by a
# Pade approximant of order PADE_ORDER (the frequency responses use the exact delay).
PADE_ORDER = {pade}
if theta > 0:
    D = control.tf(*control.pade(theta, PADE_ORDER))
else:
    D = control.tf([1.0], [1.0])
P_pade = P * D


def plant_freq(w):
    """P(jw) * exp(-j*w*theta): the plant with its exact dead time."""
    return complex(P(1j * w)) * np.exp(-1j * w * theta)


def _nd(sys):
    return np.asarray(sys.num[0][0], float), np.asarray(sys.den[0][0], float)


def closed_loop(plant):
    """y/r and y/d (load at the plant input) of the loop on `plant`, formed from the
    polynomials so that a denominator Cr and Cy share gives no cancelling pole-zero pair."""
    n_p, d_p = _nd(plant)
    n_r, d_r = _nd(Cr)
    n_y, d_y = _nd(Cy)
    char = np.polyadd(np.polymul(d_p, d_y), np.polymul(n_p, n_y))  # 1 + plant*Cy = char/(d_p d_y)
    q, rem = np.polydiv(d_r, d_y)
    if len(d_r) >= len(d_y) and np.allclose(rem, 0.0, rtol=0.0, atol=1e-12 * np.max(np.abs(d_r))):
        # d_r = d_y * q
        y_r = control.tf(np.polymul(n_p, n_r), np.polymul(q, char))
    else:
        y_r = control.tf(np.polymul(np.polymul(n_p, n_r), d_y), np.polymul(d_r, char))
    y_d = control.tf(np.polymul(n_p, d_y), char)
    return y_r, y_d, char


def as_json():
    w = [{check_w}]
    out = {{"theta": theta, "pade_order": PADE_ORDER, "w": w}}
    for name, sys in (("P", P), ("Cr", Cr), ("Cy", Cy)):
        n, d = _nd(sys)
        resp = [complex(sys(1j * x)) for x in w]
        out[name] = {{
            "num": [float(c) for c in n],
            "den": [float(c) for c in d],
            "freq_re": [z.real for z in resp],
            "freq_im": [z.imag for z in resp],
        }}
    resp = [plant_freq(x) for x in w]
    out["P_delay"] = {{"freq_re": [z.real for z in resp], "freq_im": [z.imag for z in resp]}}
    return out


def main(argv):
    if "--json" in argv:
        print(json.dumps(as_json()))
        return 0
    y_r, y_d, char = closed_loop(P_pade)
    poles = np.roots(char)
    stable = bool(np.all(poles.real < 0))
    print("closed-loop poles with the order-%d Pade dead time: max real part %.6g (%s)"
          % (PADE_ORDER, max(poles.real), "stable" if stable else "NOT stable"))
    if not stable:
        return 0
    for label, sys in (("set-point step", y_r), ("load step", y_d)):
        res = control.step_response(sys)
        y = np.asarray(res.outputs).ravel()
        t = np.asarray(res.time)
        k = int(np.argmax(np.abs(y)))
        print("%s: y(end) = %.6g at t = %.6g, peak |y| = %.6g at t = %.6g"
              % (label, y[-1], t[-1], abs(y[k]), t[k]))
        if "--plot" in argv:
            import matplotlib.pyplot as plt
            plt.plot(t, y, label=label)
    if "--plot" in argv:
        import matplotlib.pyplot as plt
        plt.xlabel("t")
        plt.ylabel("y")
        plt.legend()
        plt.show()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
"#,
        pade = PADE_ORDER,
        check_w = nums(&CHECK_W),
    );
    s
}
