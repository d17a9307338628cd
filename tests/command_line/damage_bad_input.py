#!/usr/bin/python3
"""scripts/liftoff-damage refuses bad input: one line on stderr that names
the field and what it allows, a non-zero exit, no traceback, and no result
written (no damage.csv, damage.md, passes.csv in --output).

    damage_bad_input.py LIFTOFF LIFTOFF_DAMAGE

Each case is a good description with one thing spoiled; the good one runs
(a single slab, one axle load, one bin, one wander position: one run).
Then SIGINT to the tool's process group midway through 5 runs: exit 130,
one line, nothing written but runs/; --reuse finishes.
"""

import copy
import json
import os
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "common"))
from checks import check, finish  # noqa: E402

LIFTOFF, TOOL = sys.argv[1], sys.argv[2]

SI_SCENE = """subsection Units
  set System           = SI
  set Length           = 3
  set Width            = 2
  set Thickness        = 0.2
  set Young's modulus  = 30e9
  set Density          = 2400
  set Subgrade modulus = 50e6
end
subsection Foundation
  set Model = tensionless
end
subsection Discretization
  set Cells along x = 3
  set Cells along y = 2
end
"""
# The same slab without units: the law's MR in Pa would mean nothing.
PLAIN_SCENE = """subsection Discretization
  set Cells along x = 3
  set Cells along y = 2
end
"""
GOOD = {
    "scene": "si.prm",
    "path": {"start": -2.5, "end": 2.5, "lane": 0},
    "axles": [{"name": "single", "wheels": "0, 0.8, 0.5; 0, -0.8, 0.5",
               "loads": [[80e3, 1e5]]}],
    "speeds": [[50, 1]],
    "temperature": {"expansion": 1e-5, "bins": [[0, 1]]},
    "wander": {"sd": 0, "positions": 1},
    "points": {"x": [0.5], "y": [0.3]},
    "law": {"MR": 4.5e6},
    "time step": 0.01}


def spoiled(change):
    d = copy.deepcopy(GOOD)
    change(d)
    return d


def setter(*path_value):
    *path, value = path_value

    def change(d):
        for key in path[:-1]:
            d = d[key]
        if value is DELETE:
            del d[path[-1]]
        else:
            d[path[-1]] = value
    return change


DELETE = object()

# (what, description or text, words the message must hold, extra options)
CASES = [
    ("not JSON", "{'scene': 1}", ["not JSON"], []),
    ("a list, not an object", [], ["wants an object"], []),
    ("law missing", spoiled(setter("law", DELETE)), ["'law' is missing"],
     []),
    ("a misspelt field", spoiled(setter("wandr", {})),
     ["unknown field 'wandr'", "wander"], []),
    ("temperature shares summing to 0.9",
     spoiled(setter("temperature", "bins", [[-5, 0.4], [5, 0.5]])),
     ["temperature bins", "sum to 0.9", "must sum to 1"], []),
    ("a law expression calling import",
     spoiled(setter("law", "log10 N", "__import__('os').getcwd()")),
     ["law:", "calls something other than"], []),
    ("a law expression naming an unknown",
     spoiled(setter("law", "log10 N", "2*(MR/stress)^1.22")),
     ["law:", "'stress'", "allowed"], []),
    ("MR of 0", spoiled(setter("law", "MR", 0)), ["MR", "> 0"], []),
    ("a speed of 0", spoiled(setter("speeds", [[0, 1]])),
     ["speeds", "speeds > 0"], []),
    ("0 wander positions", spoiled(setter("wander", "positions", 0)),
     ["wander", "'positions'", "integer >= 1"], []),
    ("negative passes",
     spoiled(setter("axles", 0, "loads", [[80e3, -1]])),
     ["axles item 1", "'loads'", "passes >= 0"], []),
    ("wheels without shares",
     spoiled(setter("axles", 0, "wheels", "0, 0.8; 0, -0.8")),
     ["axles item 1", "'wheels'", "dx, dy, share"], []),
    ("a path driving backwards", spoiled(setter("path", "end", -3)),
     ["path", "'end'", "beyond 'start'"], []),
    ("a missing scene file", spoiled(setter("scene", "nowhere.prm")),
     ["'scene'", "nowhere.prm"], []),
    ("a time step of text", spoiled(setter("time step", "1ms")),
     ["'time step'", "a number > 0"], []),
    ("a scene not in SI units", spoiled(setter("scene", "plain.prm")),
     ["SI units", "MR is in Pa"], []),
    ("a damage point off the plate",
     spoiled(setter("points", "x", [2.0])),
     ["run single-80kN-dT+0-w1-v50 failed", "log.txt"], []),
    ("--reuse with --overwrite", GOOD, ["--reuse", "--overwrite"],
     ["--reuse", "--overwrite"]),
    ("--set of an entry the tool sets", GOOD,
     ["--set Time integration/Time step", "from the description"],
     ["--set", "Time integration/Time step=1"]),
    ("--set without a value", GOOD, ["--set wants 'Section/Entry=value'"],
     ["--set", "Foundation"]),
]


def run(work, name, description, options):
    path = os.path.join(work, name + ".json")
    with open(path, "w") as f:
        f.write(description if isinstance(description, str)
                else json.dumps(description))
    output = os.path.join(work, name)
    done = subprocess.run([sys.executable, TOOL, path, "--executable",
                           LIFTOFF, "--output", output, "--no-plot"]
                          + options, capture_output=True, text=True)
    return done, output


def interrupt_check(work):
    """SIGINT to the tool's process group (as Ctrl-C sends it, to the tool
    and its liftoff runs) once its second run has started: exit 130, one
    line, nothing but runs/ in --output; --reuse then finishes."""
    description = spoiled(setter("wander", {"sd": 0.2, "positions": 5}))
    path = os.path.join(work, "interrupted.json")
    with open(path, "w") as f:
        f.write(json.dumps(description))
    output = os.path.join(work, "interrupted")
    command = [sys.executable, TOOL, path, "--executable", LIFTOFF,
               "--output", output, "--no-plot"]
    tool = subprocess.Popen(command, stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, text=True,
                            start_new_session=True)
    runs = os.path.join(output, "runs")
    for _ in range(600):
        if os.path.isdir(runs) and len(os.listdir(runs)) >= 2:
            break
        time.sleep(0.05)
    os.killpg(tool.pid, signal.SIGINT)
    lines = tool.communicate()[1].strip().splitlines()
    check(tool.returncode == 130 and len(lines) == 1
          and "interrupted; nothing written" in lines[0]
          and os.listdir(output) == ["runs"],
          "SIGINT midway: exit %d, %s, the folder holds %s"
          % (tool.returncode, lines, os.listdir(output)))
    done = subprocess.run(command + ["--reuse"], capture_output=True,
                          text=True)
    check(done.returncode == 0 and os.path.exists(
        os.path.join(output, "damage.csv")),
        "--reuse finishes the interrupted run set (exit %d)"
        % done.returncode)


def main():
    with tempfile.TemporaryDirectory() as work:
        for name, text in (("si.prm", SI_SCENE), ("plain.prm", PLAIN_SCENE)):
            with open(os.path.join(work, name), "w") as f:
                f.write(text)
        done, output = run(work, "good", GOOD, [])
        check(done.returncode == 0 and os.path.exists(
            os.path.join(output, "damage.csv")),
            "the good description runs (exit %d) %s"
            % (done.returncode, done.stderr.strip()))
        for k, (what, description, words, options) in enumerate(CASES):
            done, output = run(work, "case%d" % k, description, options)
            lines = done.stderr.strip().splitlines()
            written = [n for n in ("damage.csv", "damage.md", "passes.csv",
                                   "pass_damage.csv")
                       if os.path.exists(os.path.join(output, n))]
            check(done.returncode != 0 and len(lines) == 1
                  and lines[0].startswith("liftoff-damage: error: ")
                  and all(w in lines[0] for w in words) and not written,
                  "%s: exit %d, %s%s" % (what, done.returncode,
                                         " | ".join(lines) or "no message",
                                         ", wrote %s" % written
                                         if written else ""))
        interrupt_check(work)
    finish()


main()
