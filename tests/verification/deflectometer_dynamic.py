#!/usr/bin/env python3
"""scripts/liftoff-backcalc --histories, the dynamic fit, round trip: the
sensors' histories liftoff makes with known E = 30 GPa, k = 50 MPa/m and
dashpots c = 1e5 Pa s/m (0.33 of the critical 2 sqrt(k rho h)) are fitted
back from the AREA method on their peaks (E -19 %, k -25 %) and c = 0.05
of the critical. The test: 40 kN in a 30 ms half-sine on the 150 mm plate,
a 4 m square slab 0.25 m thick on a bilateral bed, quarter model, 4 x 4
cells Q2, steps of 2 ms to 40 ms, sensors at 0, 305, 610 and 914 mm (84
samples).

- with noise (normal, seed 7, standard deviation 1 % of each sensor's
  peak, 1 to 1.4 um; step tolerance 1e-3): E within 3 %, k within 2 %, c
  within 10 %, and each within 3 standard deviations of the Jacobian's
  uncertainty (measured +0.39 %, -0.09 %, -1.3 %: 0.4, 0.1 and 1.0
  sigma; 20 runs);
- without noise, from the noisy fit, to the fit's tolerance (a step of
  1e-9 in ln E, ln k and c / critical): E, k and c within 1e-6 (within
  5e-11, the report's ten digits), every sensor's RMS residual below 1e-4
  um (0.000); 16 runs;
- the script writes fit.txt, histories_fit.csv and histories_fit.png;
- bad input is refused in one line naming the cause (exit 1, no output
  folder): no time column, a sensor column missing in a row, NaN, time
  not increasing, times after the pulse or beyond the scene's End time,
  a negative thickness, an unknown option, a static scene, histories of
  one time with a deflection (the first two rows of the truth: k and c
  act as one stiffness there; before, fitted to k = 1.5e8 +- 0.00037 %
  and c = 0, exit 0);
- two times suffice: the first three rows (0, 2, 4 ms) fitted back to
  1e-6, the scaled Jacobian's condition number below 1e3 (50.6);
- the conditioning's judgement against a hand calculation: the Jacobian
  [[1, 1], [0, 1e-4]] has the condition number 2e4 once its columns are
  scaled (sigma = sqrt 2 and 1e-4 / sqrt 2), and the judgement names both
  values as not separated.

    deflectometer_dynamic.py LIFTOFF
"""

import os
import random
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..",
                                "scripts"))
from checks import check, finish  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
BACKCALC = os.path.join(HERE, "..", "..", "scripts", "liftoff-backcalc")
LIFTOFF = os.path.abspath(sys.argv[1])
E, K, C = 30e9, 50e6, 1e5

SCENE = f"""
subsection Units
  set System = SI
  set Length = 4
  set Width = 4
  set Thickness = 0.25
  set Young's modulus = {E}
  set Density = 2400
  set Gravity = 0
  set Subgrade modulus = {K}
  set Dashpot coefficient = {C}
end
subsection Plate
  set Poisson ratio = 0.15
end
subsection Foundation
  set Model = bilateral
end
subsection Discretization
  set Symmetry = quarter
  set Cells along x = 4
  set Cells along y = 4
  set Polynomial degree = 2
end
subsection Loads
  subsection Deflectometer 1
    set Peak force = 40e3
    set Duration = 0.03
    set Sensor offsets = 0, 0.305, 0.61, 0.914
  end
end
subsection Time integration
  set Time step = 2e-3
  set End time = 0.04
end
subsection Output
  set Directory = truth
  set Write energies = false
  set VTU interval = 0
end
"""
FITTED = re.compile(r"fitted: +E = (\S+) Pa \+- (\S+) %, k = (\S+) N/m\^3 "
                    r"\+- (\S+) %, c = (\S+) Pa s/m \+- (\S+) Pa s/m")


def backcalc(measured, output, *options):
    """The later of two options wins: the test's options follow these."""
    done = subprocess.run(
        [sys.executable, BACKCALC, "--histories", measured, "--scene",
         "scene.prm", "--thickness", "0.25", "--poisson", "0.15",
         "--executable", LIFTOFF, "--output", output, *options],
        capture_output=True, text=True)
    numbers = FITTED.search(done.stdout)
    if done.returncode != 0 or not numbers:
        print(done.stdout + done.stderr)
        return done, None
    print("\n".join(line for line in done.stdout.splitlines()
                    if not line.startswith("liftoff run")))
    e, se, k, sk, c, sc = map(float, numbers.groups())
    return done, (e, se * e / 100, k, sk * k / 100, c, sc)


def sensor_residuals(stdout):
    table = stdout.split("rms residual over time [um]\n", 1)[1]
    return [float(line.split()[3]) for line in table.splitlines()
            if line.startswith("  ")]


def noisy_histories(seed):
    """truth/history.csv's sensors with noise of 1 % of each one's peak."""
    with open("truth/history.csv") as f:
        rows = [line.strip().split(",") for line in f]
    sensors = [i for i, n in enumerate(rows[0]) if n.startswith("d(")]
    columns = [0] + sensors
    peaks = {i: max(abs(float(row[i])) for row in rows[1:]) for i in sensors}
    random.seed(seed)
    with open("noisy.csv", "w") as f:
        f.write(",".join(rows[0][i] for i in columns) + "\n")
        for row in rows[1:]:
            f.write(",".join([row[0]] + [repr(float(row[i]) + 0.01 * peaks[i]
                                              * random.gauss(0, 1))
                                         for i in sensors]) + "\n")


def round_trip():
    """The noisy histories from the AREA method's start, then the exact
    ones from the noisy fit (fewer runs than from the AREA start)."""
    noisy_histories(7)
    _, noisy = backcalc("noisy.csv", "noisy", "--tolerance", "1e-3",
                        "--no-plot")
    if noisy is None:
        check(False, "1 % noise: the fit runs")
        return
    e, se, k, sk, c, sc = noisy
    print(f"1 % noise: E {e / E - 1:+.2%} ({abs(e - E) / se:.1f} sigma), "
          f"k {k / K - 1:+.2%} ({abs(k - K) / sk:.1f} sigma), "
          f"c {c / C - 1:+.2%} ({abs(c - C) / sc:.1f} sigma)")
    check(abs(e / E - 1) < 0.03 and abs(k / K - 1) < 0.02
          and abs(c / C - 1) < 0.10,
          "1 % noise: E within 3 %, k within 2 %, c within 10 %")
    check(abs(e - E) < 3 * se and abs(k - K) < 3 * sk and abs(c - C) < 3 * sc,
          "1 % noise: the true E, k and c within 3 standard deviations")
    done, exact = backcalc("truth/history.csv", "exact", "--tolerance",
                           "1e-9", "--start", f"{e!r},{k!r},{c!r}")
    if exact is None:
        check(False, "no noise: the fit runs")
        return
    e, _, k, _, c, _ = exact
    rms = max(sensor_residuals(done.stdout))
    check(max(abs(e / E - 1), abs(k / K - 1), abs(c / C - 1)) < 1e-6
          and rms < 1e-4,
          f"no noise: E, k, c back to {e / E - 1:.1e}, {k / K - 1:.1e}, "
          f"{c / C - 1:.1e}; largest RMS residual {rms:.1e} um")
    check(all(os.path.isfile(os.path.join("exact", name)) for name in
              ("fit.txt", "histories_fit.csv", "histories_fit.png")),
          "fit.txt, histories_fit.csv and histories_fit.png written")


def write(name, text):
    with open(name, "w") as f:
        f.write(text)
    return name


def first_rows(n):
    """The first n rows of the truth's histories."""
    with open("truth/history.csv") as f:
        return write(f"first{n}.csv", "".join(f.readlines()[:n + 1]))


def two_times():
    done, fit = backcalc(first_rows(3), "two_times", "--tolerance", "1e-9",
                         "--no-plot")
    condition = re.search(r"condition number (\S+);", done.stdout)
    if fit is None or not condition:
        check(False, "two times: the fit runs")
        return
    e, _, k, _, c, _ = fit
    check(max(abs(e / E - 1), abs(k / K - 1), abs(c / C - 1)) < 1e-6
          and float(condition.group(1)) < 1e3,
          f"two times: E, k, c back to {e / E - 1:.1e}, {k / K - 1:.1e}, "
          f"{c / C - 1:.1e}; condition number {condition.group(1)}")


def conditioning():
    import backcalc_fit
    parameters = [backcalc_fit.Parameter("E", "Pa", 1.0),
                  backcalc_fit.Parameter("k", "N/m^3", 1.0)]
    result = backcalc_fit.FitResult([1.0, 1.0], [0.0, 0.0], None, "", 1)
    result.singular, result.weak = backcalc_fit.scaled_singular(
        [[1.0, 1.0], [0.0, 1e-4]])
    _, error = backcalc_fit.judgement(parameters, result)
    check(abs(result.condition() / 2e4 - 1) < 1e-6 and error is not None
          and "do not separate E and k" in error,
          f"[[1, 1], [0, 1e-4]]: condition number {result.condition():.6g} "
          f"(2e4 by hand), refused: {error}")


def refusals():
    good = "t [s],d(0) [um],d(0.305) [um],d(0.61) [um],d(0.914) [um]\n"
    rows = "0,0,0,0,0\n0.016,141,131,113,95\n0.03,20,19,17,15\n"
    static = write("static.prm", SCENE.replace(
        "subsection Units", "subsection Analysis\n  set Type = static\nend\n"
        "subsection Units"))
    write("g.csv", good + rows)
    cases = [
        ("no time column", write("a.csv", good.replace("t [s]", "time")
                                 + rows), [], "no time column"),
        ("a row without a sensor", write("b.csv", good + rows
                                         + "0.032,1,2,3\n"), [],
         "line 5: 4 values"),
        ("NaN", write("c.csv", good + rows.replace("113", "nan")), [],
         "d(0.61) [um] = \"nan\""),
        ("time not increasing", write("d.csv", good + rows.replace(
            "0.03,", "0.01,")), [], "line 4: the time 0.01 s does not follow"),
        ("times after the pulse", write("e.csv", good + "0.031,1,1,1,1\n"
                                        "0.035,2,2,2,2\n"), [],
         "after the pulse (0 to 0.03 s)"),
        ("times beyond the End time", write("f.csv", good + rows
                                            + "0.05,1,1,1,1\n"), [],
         "End time, 0.04 s"),
        ("a negative thickness", "g.csv", ["--thickness", "-0.25"],
         "--thickness = -0.25 must be > 0"),
        ("an unknown option", "g.csv", ["--dampnig-start", "0.1"],
         "unrecognized arguments: --dampnig-start"),
        ("a static scene", "g.csv", ["--scene", static], "is static"),
        ("one time with a deflection", first_rows(2), [],
         "holds 1 time with a deflection (0.002 s); k and c need 2")]
    for what, measured, options, cause in cases:
        done, _ = backcalc(measured, "refused", *options)
        lines = done.stderr.strip().splitlines()
        check(done.returncode == 1 and len(lines) == 1 and cause in lines[0]
              and not os.path.exists("refused"),
              f"{what}: refused in one line ({lines[-1] if lines else ''})")


with tempfile.TemporaryDirectory() as folder:
    os.chdir(folder)
    write("scene.prm", SCENE)
    subprocess.run([LIFTOFF, "--quiet", "scene.prm"], check=True,
                   stdout=subprocess.DEVNULL)
    refusals()
    two_times()
    round_trip()
conditioning()
finish()
