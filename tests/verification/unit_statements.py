#!/usr/bin/env python3
"""The units that `liftoff --parameters` states must be the units the run
reads. Every input is dimensionless (doc/model.md, "Units"): w in F0 L^2 / D,
pressures in F0 / L^2, line loads in F0 / L, forces in F0. A unit statement
is a convention, so what a run can check is that inputs said to share a
unit act alike, and the closed form that ties them to w:

- the statement of each entry names its unit (the self-weight was once
  documented in D / L^3, which for a 5 m slab with F0 = 50 kN reads its
  weight 163 times too small);
- Self weight q and a Pressure of Magnitude q on the whole plate give the
  same static deflection, w = q / Gamma on a bilateral bed (a free plate
  sinks rigidly: nothing bends);
- an Initial gap g is a length in w's unit: under the same weight the plate
  sits at w = q / Gamma + g.

    unit_statements.py LIFTOFF
"""

import os
import re
import subprocess
import sys
import tempfile

STATED_UNITS = {
    ("Loads", "Self weight"): "F0 / L^2",
    ("Loads", "Pressure 1", "Magnitude"): "F0 / L^2",
    ("Loads", "Line load 1", "Magnitude"): "F0 / L",
    ("Loads", "Point load 1", "Magnitude"): "F0",
    ("Foundation", "Initial gap"): "F0 L^2 / D",
    ("Initial conditions", "Displacement"): "F0 L^2 / D",
}

GAMMA, Q, GAP = 10.0, 0.3, 0.05

failures = 0


def check(ok, what):
    global failures
    print("%s %s" % ("PASS" if ok else "FAIL", what))
    failures += 0 if ok else 1


def documentation(liftoff):
    """Each entry's documentation, by its path of subsections and name."""
    text = subprocess.run([liftoff, "--parameters"], capture_output=True,
                          text=True, check=True).stdout
    path, comment, docs = [], [], {}
    for line in text.splitlines():
        line = line.strip()
        if line.startswith("#"):
            comment.append(line.lstrip("# "))
            continue
        if line.startswith("subsection "):
            path.append(line[len("subsection "):].strip())
        elif line == "end":
            path.pop()
        elif line.startswith("set "):
            name = line[4:].split("=", 1)[0].strip()
            docs[tuple(path) + (name,)] = " ".join(comment)
        comment = []
    return docs


def static_deflection(liftoff, extra):
    """w at three points of a free square plate on a bilateral bed."""
    scene = """subsection Analysis
  set Type = static
end
subsection Foundation
  set Model = bilateral
  set Stiffness = %g
end
subsection Discretization
  set Cells along x = 2
  set Cells along y = 2
end
subsection Output
  set Directory = out
  set Probe points = 0, 0; 0.5, 0.5; -0.25, 0.5
end
%s""" % (GAMMA, extra)
    with tempfile.TemporaryDirectory() as work:
        run = subprocess.run([liftoff, "-q", "-"], input=scene,
                             capture_output=True, text=True, cwd=work)
        if run.returncode != 0:
            print(run.stderr)
            return None
        with open(os.path.join(work, "out", "history.csv")) as f:
            header, row = f.readline().strip().split(","), f.readline()
        values = dict(zip(header, row.strip().split(",")))
        return [float(v) for k, v in values.items() if k.startswith("w(")]


def main():
    liftoff = os.path.abspath(sys.argv[1])
    docs = documentation(liftoff)
    for entry, unit in STATED_UNITS.items():
        text = docs.get(entry, "")
        # The whole unit: "F0" must not be the start of "F0 / L^2".
        stated = re.search(re.escape(unit) + r"(?![\w^]|\s*[/^L])", text)
        check(stated is not None,
              "%s says its unit is %s: <%s>" % ("/".join(entry), unit, text))

    weight = static_deflection(liftoff, "subsection Loads\n  set Self weight"
                               " = %g\nend\n" % Q)
    pressure = static_deflection(
        liftoff, "subsection Loads\n  subsection Pressure 1\n    set "
        "Magnitude = %g\n  end\nend\n" % Q)
    settled = static_deflection(
        liftoff, "subsection Loads\n  set Self weight = %g\nend\nsubsection "
        "Foundation\n  set Initial gap = %g\nend\n" % (Q, GAP))
    for name, values, expected in [("Self weight", weight, Q / GAMMA),
                                   ("Pressure 1", pressure, Q / GAMMA),
                                   ("Self weight on a gap", settled,
                                    Q / GAMMA + GAP)]:
        ok = values is not None and all(
            abs(w - expected) < 1e-9 * expected for w in values)
        check(ok, "%s = %g: w = %s, expected %g everywhere"
              % (name, Q, values, expected))
    print("%d failed" % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
