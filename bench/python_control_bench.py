"""The benchmark's python-control half (not a test): the same slider update as
bench/bench-node.mjs on the boiler steam drum 0.547(1 - 0.418 s)e^{-0.1 s}/(s(1.06 s + 1)),
done the usual way with python-control: the delay replaced by a Padé(5) approximant, the
set-point and the load response as two forced responses on the same 3001-point grid
(t_end 30, dt 0.01, set-point step at 0, load step at 15), and Ms = max |1/(1 + L(jw))| on a
2000-point logarithmic grid (1e-3 .. 1e3 rad/s). python-control has no rule of pidlab's, so the
controller is given (pidlab's tune output, JSON on stdin: {cr: {num, den}, cy: {num, den}}) and
the update here has no tune step: it favours python-control.

    PY=$(bash scripts/ensure-python.sh); node ... | $PY bench/python_control_bench.py [runs]

Prints one JSON line: {"median_ms", "p95_ms", "min_ms", "cpu_median_ms", "runs", "ms", ...},
with the CPU-time medians of the two phases timed apart ("simulate_cpu_median_ms": Padé, the
closed-loop transfer functions and the two forced responses; "analyze_cpu_median_ms": Ms).
"""
import json
import sys
import time

import control
import numpy as np

RUNS = max(20, int(sys.argv[1]) if len(sys.argv) > 1 else 200)
ctl = json.load(sys.stdin)
K, TAU, TZ, THETA = 0.547, 1.06, 0.418, 0.1
T = np.linspace(0.0, 30.0, 3001)
W = np.logspace(-3, 3, 2000)
ng = np.array([-K * TZ, K])  # 0.547 (1 - 0.418 s)
dg = np.array([TAU, 1.0, 0.0])  # s (1.06 s + 1)
ncr, dcr = np.array(ctl["cr"]["num"]), np.array(ctl["cr"]["den"])
ncy, dcy = np.array(ctl["cy"]["num"]), np.array(ctl["cy"]["den"])
u_load = (T >= 15.0).astype(float)
r_sp = np.ones_like(T)


def simulate():
    """The simulate phase: Padé(5) delay, the closed-loop transfer functions, two forced responses."""
    pn, pd = control.pade(THETA, 5)
    gn, gd = np.polymul(ng, pn), np.polymul(dg, pd)  # G with the Padé delay
    # u = Cr r - Cy y + d (load at the plant input), y = G u
    char = np.polyadd(np.polymul(np.polymul(gd, dcy), dcr), np.polymul(np.polymul(gn, ncy), dcr))
    t_r = control.tf(np.polymul(np.polymul(gn, ncr), dcy), char)  # y/r
    t_d = control.tf(np.polymul(np.polymul(gn, dcy), dcr), char)  # y/d
    y = control.forced_response(t_r, T, r_sp).outputs + control.forced_response(t_d, T, u_load).outputs
    return y, gn, gd


def analyze(gn, gd):
    """The analyze phase: Ms = max |1/(1 + L(jw))| on the 2000-point grid."""
    loop = control.tf(np.polymul(gn, ncy), np.polymul(gd, dcy))
    mag = np.abs(1.0 / (1.0 + loop(1j * W)))
    return float(mag.max())


def update():
    y, gn, gd = simulate()
    return y, analyze(gn, gd)


for _ in range(5):
    y, ms = update()
wall, cpu = [], []
for _ in range(RUNS):
    c0, t0 = time.thread_time(), time.perf_counter()
    update()
    wall.append((time.perf_counter() - t0) * 1e3)
    cpu.append((time.thread_time() - c0) * 1e3)
wall.sort()
cpu.sort()
# the two phases timed apart (CPU time, median), as pidlab's simulate and analyze rows
sim_cpu, an_cpu = [], []
for _ in range(RUNS):
    c0 = time.thread_time()
    _, gn, gd = simulate()
    c1 = time.thread_time()
    analyze(gn, gd)
    sim_cpu.append((c1 - c0) * 1e3)
    an_cpu.append((time.thread_time() - c1) * 1e3)
sim_cpu.sort()
an_cpu.sort()
print(json.dumps({
    "runs": RUNS,
    "median_ms": wall[RUNS // 2],
    "p95_ms": wall[min(RUNS - 1, int(0.95 * RUNS))],
    "min_ms": wall[0],
    "cpu_median_ms": cpu[RUNS // 2],
    "simulate_cpu_median_ms": sim_cpu[RUNS // 2],
    "analyze_cpu_median_ms": an_cpu[RUNS // 2],
    "ms": ms,
    "y_end": float(y[-1]),
    "python_control": control.__version__,
    "numpy": np.__version__,
}))
