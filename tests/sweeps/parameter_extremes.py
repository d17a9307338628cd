#!/usr/bin/python3
"""Hostile sweep (not in ctest; about 10 minutes on 2 cores): every numeric
parameter at both ends of its allowed range, on a small dynamic scene
(quarter plate, 6 x 6 Q2, unit point load, 20 steps). The range is read
from liftoff's own refusal of a wrong value. Each run must end in one of:
completed (and then its energy balance within 1 % of its scale, or a
warning saying it is not), or a one-message refusal; never a crash, a
stack trace or a hang.

    tests/sweeps/parameter_extremes.py LIFTOFF [TABLE.csv]
"""
import csv, os, re, subprocess, sys, tempfile

# The entries as every_parameter_refused.py reads them from --parameters.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bad_input"))
from every_parameter_refused import declared_entries, is_first_of_numbered  # noqa: E402

liftoff = os.path.abspath(sys.argv[1])
table = sys.argv[2] if len(sys.argv) > 2 else None
BASE = """subsection Discretization
  set Symmetry = quarter
  set Cells along x = 6
  set Cells along y = 6
  set Polynomial degree = 2
end
subsection Loads
  subsection Point load 1
    set Magnitude = 1
  end
end
subsection Time integration
  set End time = 0.01
end
subsection Output
  set Directory = out
  set VTU interval = 0
end
"""
SKIP = {("Output", "Directory"), ("Time integration", "End time"),
        ("Time integration", "Time step")}  # tried by hand: End time / Time step pairs


def entries():
    return [e for e in declared_entries(liftoff) if is_first_of_numbered(e[0])]


def scene(path, entry, value):
    text = "".join("subsection %s\n" % s for s in path)
    text += "set %s = %s\n" % (entry, value)
    text += "end\n" * len(path)
    return BASE + text


def run(text, work):
    try:
        r = subprocess.run([liftoff, "--overwrite", "-"], input=text,
                           capture_output=True, text=True, cwd=work,
                           timeout=180)
    except subprocess.TimeoutExpired:
        return "hang", ""
    summary = os.path.join(work, "out", "summary.txt")
    status, share = "", ""
    if os.path.exists(summary):
        for line in open(summary):
            if line.startswith("status: "):
                status = line[8:].strip()
            if line.startswith("energy balance error, largest share"):
                share = line.split(":")[1].strip()
    if r.returncode == 0:
        if status == "completed":
            return "completed", share
        return status or "exit 0 without summary", share
    err = r.stderr.strip()
    if "Stacktrace" in err or r.returncode not in (1,):
        return "crash (exit %d)" % r.returncode, err[:200]
    lines = [l for l in err.splitlines() if l.strip()]
    return "refused", (lines[-1].strip()[:160] if lines else "")


def main():
    rows, bad = [], 0
    with tempfile.TemporaryDirectory() as work:
        for path, entry in entries():
            if (path[-1] if path else "", entry) in SKIP or (path and (path[0], entry) in SKIP):
                continue
            r = subprocess.run([liftoff, "-"], input=scene(path, entry, "@@"),
                               capture_output=True, text=True, cwd=work)
            m = re.search(r"\[(Double|Integer range) (\S+)\.\.\.(\S+)", r.stderr)
            if not m:
                continue
            lo, hi = m.group(2), m.group(3)
            for value in (lo, hi):
                if value in ("MAX_DOUBLE", "MAX_INT", "-MAX_DOUBLE", "-MAX_INT"):
                    value = {"MAX_DOUBLE": "1e300", "-MAX_DOUBLE": "-1e300",
                             "MAX_INT": "2147483647", "-MAX_INT": "-2147483647"}[value]
                outcome, detail = run(scene(path, entry, value), work)
                name = "/".join(path + (entry,))
                ok = (outcome in ("completed", "refused", "completed with warnings"))
                if outcome == "completed" and detail and float(detail) > 0.01:
                    ok = False
                bad += not ok
                rows.append((name, value, outcome, detail))
                print("%s %s = %s: %s %s" % ("  " if ok else "!!", name, value,
                                             outcome, detail), flush=True)
    counts = {}
    for row in rows:
        counts[row[2]] = counts.get(row[2], 0) + 1
    print("%d runs: %s; %d not acceptable" % (
        len(rows), ", ".join("%s %d" % kv for kv in sorted(counts.items())), bad))
    if table:
        with open(table, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["parameter", "value", "outcome", "detail"])
            w.writerows(rows)
    return 1 if bad else 0


sys.exit(main())
