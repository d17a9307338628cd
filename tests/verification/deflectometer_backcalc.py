#!/usr/bin/env python3
"""scripts/liftoff-backcalc's round trip: a basin made by liftoff with known
E = 30 GPa and k = 50 MPa/m (a static deflectometer test, 40 kN on the 150
mm plate, h = 0.25 m, nu = 0.15, a 6 m square slab on a bilateral bed,
quarter model, Q2, 12 cells along a side) is fitted back from the AREA
method's start (E -21 %, k +4 %: the AREA method assumes an infinite
slab):

- without noise, to the fit's tolerance (a step of 1e-9 in ln E and ln k):
  E and k within 1e-6 (measured 7e-10 and -2e-10), every residual below
  1e-4 um (1e-7 um), in 15 liftoff runs;
- with 1 % noise on each sensor (normal, seeded; step tolerance 1e-4), E
  within 5 % and k within 3 %, about 3 standard deviations of the
  Jacobian's uncertainty (1.4 % and 0.9 % here; seed 1 gives -4.7 % and
  +2.8 %); measured +0.91 % and -0.40 % (0.6 and 0.5 sigma), each within 3
  standard deviations;
- the script writes fit.csv, fit.txt and basin_fit.png, and refuses a basin
  without the AREA sensors, naming the missing offset, in one line.

    deflectometer_backcalc.py LIFTOFF
"""

import csv
import os
import random
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
BACKCALC = os.path.join(HERE, "..", "..", "scripts", "liftoff-backcalc")
LIFTOFF = os.path.abspath(sys.argv[1])
E, K = 30e9, 50e6

SCENE = f"""
subsection Analysis
  set Type = static
end
subsection Units
  set System = SI
  set Length = 6
  set Width = 6
  set Thickness = 0.25
  set Young's modulus = {E}
  set Density = 2400
  set Gravity = 0
  set Subgrade modulus = {K}
end
subsection Plate
  set Poisson ratio = 0.15
end
subsection Foundation
  set Model = bilateral
end
subsection Discretization
  set Symmetry = quarter
  set Cells along x = 12
  set Cells along y = 12
  set Polynomial degree = 2
end
subsection Loads
  subsection Deflectometer 1
    set Peak force = 40e3
    set Pulse shape = constant
  end
end
subsection Output
  set Directory = truth
  set Write energies = false
end
"""

failures = 0


def check(ok, what):
    global failures
    print(("PASS " if ok else "FAIL ") + what)
    failures += not ok


def backcalc(basin, output, tolerance="1e-9"):
    done = subprocess.run([sys.executable, BACKCALC, basin, "--scene",
                           "scene.prm", "--thickness", "0.25", "--poisson",
                           "0.15", "--executable", LIFTOFF, "--output",
                           output, "--tolerance", tolerance],
                          capture_output=True, text=True)
    print(done.stdout + done.stderr)
    numbers = re.search(r"fitted: +E = (\S+) Pa \+- (\S+) %, k = (\S+) "
                        r"N/m\^3 \+- (\S+) %", done.stdout)
    if done.returncode != 0 or not numbers:
        return done, None
    e, se, k, sk = map(float, numbers.groups())
    return done, (e, se * e / 100, k, sk * k / 100)


with tempfile.TemporaryDirectory() as folder:
    os.chdir(folder)
    with open("scene.prm", "w") as f:
        f.write(SCENE)
    subprocess.run([LIFTOFF, "--quiet", "scene.prm"], check=True,
                   stdout=subprocess.DEVNULL)
    _, exact = backcalc("truth/basin.csv", "exact")
    with open("exact/fit.csv") as f:
        residuals = [abs(float(r["residual [m]"])) for r in csv.DictReader(f)]
    check(exact is not None and abs(exact[0] / E - 1) < 1e-6
          and abs(exact[2] / K - 1) < 1e-6 and max(residuals) < 1e-10,
          f"no noise: E, k back to {exact[0] / E - 1:.1e}, "
          f"{exact[2] / K - 1:.1e}; largest residual {max(residuals):.1e} m")
    check(all(os.path.isfile(os.path.join("exact", name))
              for name in ("fit.csv", "fit.txt", "basin_fit.png")),
          "fit.csv, fit.txt and basin_fit.png written")

    random.seed(7)
    with open("truth/basin.csv") as f:
        rows = list(csv.reader(f))
    for row in rows[1:]:
        row[3] = repr(float(row[3]) * (1 + 0.01 * random.gauss(0, 1)))
    with open("noisy.csv", "w") as f:
        csv.writer(f).writerows(rows)
    _, noisy = backcalc("noisy.csv", "noisy", "1e-4")
    e, se, k, sk = noisy
    print(f"1 % noise: E {e / E - 1:+.2%} ({abs(e - E) / se:.1f} sigma), "
          f"k {k / K - 1:+.2%} ({abs(k - K) / sk:.1f} sigma)")
    check(abs(e / E - 1) < 0.05 and abs(k / K - 1) < 0.03,
          "1 % noise: E within 5 %, k within 3 %")
    check(abs(e - E) < 3 * se and abs(k - K) < 3 * sk,
          "1 % noise: the true E and k within 3 standard deviations")

    with open("short.csv", "w") as f:
        f.write("offset [m],peak_w [m]\n0,1e-4\n0.305,9e-5\n0.61,8e-5\n")
    refused, _ = backcalc("short.csv", "short")
    lines = refused.stderr.strip().splitlines()
    check(refused.returncode == 1 and len(lines) == 1
          and "914 mm" in lines[0],
          "a basin without the sensor at 914 mm refused in one line")

print(f"{failures} failure(s)")
sys.exit(1 if failures else 0)
