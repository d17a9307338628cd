#!/usr/bin/env python3
"""The speed sweep of the strip of test moving_beam_winkler (doc/studies.md,
"A load crossing a strip: speed against v_cr"): liftoff's deflection under
a force crossing the strip on a damped bilateral bed against the infinite
beam's steady state (Kenney), from 0.2 to 2 v_cr.

    /usr/bin/python3 benchmarks/moving_speed_sweep.py build/liftoff \\
        doc/figures/moving-loads/speed-sweep.png [FACTOR]

prints a table (v / v_cr, w under the load by liftoff and by the closed
form, both over the static closed form, the basin's error) and draws it.
FACTOR (default 1) multiplies the cells and so divides h and the step
h / (2 v), the patch kept: the figures' discretisation error.
"""

import os
import sys
import tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests",
                                "verification"))
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests",
                                "common"))
import moving_beam_winkler as strip  # noqa: E402

strip.LIFTOFF = sys.argv[1]
figure = sys.argv[2]
factor = int(sys.argv[3]) if len(sys.argv) > 3 else 1
strip.CELLS *= factor
strip.H /= factor
static = strip.SteadyState(1e-9, strip.DAMPING).patch(0)[0]
ratios = np.round(np.arange(0.2, 2.01, 0.15), 2)
rows = []
with tempfile.TemporaryDirectory() as work:
    for ratio in ratios:
        under, exact, basin, scale = strip.measure(ratio * strip.V_CR,
                                                   work)[:4]
        rows.append((ratio, under / static, exact / static, basin,
                     scale / static))
        print("v/v_cr %.2f  w/w_static liftoff %8.5f  closed form %8.5f  "
              "basin error %.1e of max|w| (max|w|/w_static %.4f)" % rows[-1])

fine = np.linspace(0.05, 2.05, 201)
curve = [strip.SteadyState(r * strip.V_CR).patch(0)[0] / static for r in fine]
largest = [abs(strip.SteadyState(r * strip.V_CR).patch(
    np.linspace(-6 * strip.ELL, 4 * strip.ELL, 401))).max() / static
    for r in fine]
rows = np.array(rows)
plt.figure(figsize=(6.4, 4.2))
plt.plot(fine, curve, "k-", label="closed form: w under the load")
plt.plot(fine, largest, "k--", label="closed form: largest |w| of the basin")
plt.plot(rows[:, 0], rows[:, 1], "o", color="C0", label="liftoff: w under the load")
plt.xlabel("v / v_cr")
plt.ylabel("w / w_static")
plt.title("force crossing a strip, bilateral bed, c = 0.3 of critical")
plt.grid(alpha=0.3)
plt.legend()
plt.tight_layout()
plt.savefig(figure, dpi=110)
print("wrote", figure)
