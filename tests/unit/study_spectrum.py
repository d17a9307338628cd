#!/usr/bin/python3
"""The study tool's numerical pieces against independent references.

    study_spectrum.py LIFTOFF_STUDY

- spectrum(): the FFT route against the direct sum it replaces,
  2 |sum_k w_k d_k exp(-2 pi i f_j t_k)| / sum_k w_k at f_j = j / (t_n-1 -
  t_0) (Hann window w), on a series that starts at t_0 != 0, to 1e-12; and
  against the closed form: two sinusoids at frequencies of that grid show
  as peaks at their periods with their amplitudes (to 1 %).
- sample(): a linear function is reproduced exactly between the stored
  times, a stored time returns the stored value itself, and a time outside
  the history is refused.
- split_qoi(): "name@T" is the column from tau = T on, a riding probe's
  column ("w@patch_load_1") is a name, and a non-number after a second '@'
  is refused.
"""

import importlib.machinery
import importlib.util
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from checks import check, finish  # noqa: E402


def load_tool(path):
    loader = importlib.machinery.SourceFileLoader("liftoff_study", path)
    spec = importlib.util.spec_from_loader("liftoff_study", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


def direct_spectrum(taus, values):
    """The pure-Python sum the tool used before numpy."""
    n, length = len(taus), taus[-1] - taus[0]
    window = [0.5 - 0.5 * math.cos(2 * math.pi * k / (n - 1))
              for k in range(n)]
    weighted = [d * w for d, w in zip(values, window)]
    periods, amplitudes = [], []
    for j in range(1, n // 2 + 1):
        f = j / length
        c = sum(d * complex(math.cos(2 * math.pi * f * t),
                            -math.sin(2 * math.pi * f * t))
                for d, t in zip(weighted, taus))
        periods.append(1 / f)
        amplitudes.append(2 * abs(c) / sum(window))
    return np.array(periods), np.array(amplitudes)


def main():
    tool = load_tool(sys.argv[1])
    rng = np.random.default_rng(1)
    for n in (401, 400):
        dt = 2.5e-4
        taus = 0.03 + dt * np.arange(n)
        length = taus[-1] - taus[0]
        # Two sinusoids at frequencies of the grid (periods length / 7 and
        # length / 40), amplitudes 1e-3 and 3e-4, and a little noise.
        values = (1e-3 * np.sin(2 * np.pi * 7 * (taus - taus[0]) / length
                                + 0.4)
                  + 3e-4 * np.cos(2 * np.pi * 40 * (taus - taus[0]) / length)
                  + 1e-6 * rng.standard_normal(n))
        periods, amplitudes = tool.spectrum(taus, values)
        ref_periods, ref_amplitudes = direct_spectrum(list(taus),
                                                      list(values))
        difference = np.max(np.abs(amplitudes - ref_amplitudes))
        check(len(periods) == len(ref_periods)
              and np.allclose(periods, ref_periods, rtol=1e-13, atol=0)
              and difference <= 1e-12 * ref_amplitudes.max(),
              "n = %d: FFT spectrum equals the direct sum (largest "
              "difference %.2g of the largest amplitude)"
              % (n, difference / ref_amplitudes.max()))
        for j, amplitude in ((7, 1e-3), (40, 3e-4)):
            check(abs(amplitudes[j - 1] - amplitude) <= 0.01 * amplitude
                  and amplitudes[j - 1] == amplitudes[
                      max(0, j - 4):j + 3].max(),
                  "n = %d: a sinusoid of period length/%d and amplitude "
                  "%g shows as a peak of %.4g there" % (n, j, amplitude,
                                                        amplitudes[j - 1]))

    taus = np.array([0.0, 0.1, 0.2, 0.4])
    values = 3.0 - 2.0 * taus
    times = np.array([0.0, 0.05, 0.2, 0.3, 0.4])
    sampled = tool.sample(taus, values, times)
    check(np.allclose(sampled, 3.0 - 2.0 * times, rtol=0, atol=1e-15)
          and sampled[2] == values[2],
          "sample(): a linear function between stored times, a stored "
          "time's own value: %s" % sampled)
    try:
        tool.sample(taus, values, np.array([0.5]))
        refused = False
    except tool.StudyError:
        refused = True
    check(refused, "sample(): a time after the history is refused")
    split = [tool.split_qoi(q) for q in
             ("w(0;0)", "w(0;0)@0.1", "w@patch_load_1", "w@vehicle_1@0.25")]
    check(split == [("w(0;0)", None), ("w(0;0)", 0.1),
                    ("w@patch_load_1", None), ("w@vehicle_1", 0.25)],
          "split_qoi(): start times and riding probes' names: %s" % split)
    try:
        tool.split_qoi("w@vehicle_1@soon")
        refused = False
    except tool.StudyError:
        refused = True
    check(refused, "split_qoi(): a start time that is no number is refused")
    finish()


if __name__ == "__main__":
    main()
