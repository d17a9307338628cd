"""scripts/liftoff_view_marks.py against a run with one load of each kind:
the marks liftoff-view draws (plain Python, no ParaView) are where the
scene puts them, a moving load where the run's history.csv has it.
    view_marks.py LIFTOFF SCRIPTS_DIR"""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, sys.argv[2])
import liftoff_view_marks as marks_of  # noqa: E402
from liftoff_runs import used_parameters  # noqa: E402

SCENE = """
subsection Discretization
  set Cells along x = 4
  set Cells along y = 4
end
subsection Slabs
  set Slabs along x = 2
  set Slabs along y = 2
  set Shear stiffness = 100
end
subsection Loads
  subsection Point load 1
    set Magnitude = 1
    set Position = 0.2, 0.1
  end
  subsection Point load 2
    set Magnitude = 1
    set Path = -0.4 + tau; -0.1
  end
  subsection Patch load 1
    set Magnitude = 20
    set Size = 0.1, 0.2
    set Path = -0.2; 0.1
  end
  subsection Line load 1
    set Magnitude = 1
    set Segment = -0.3, -0.3, 0.3, -0.2
  end
  subsection Deflectometer 1
    set Peak force = 1
    set Duration = 0.1
    set Position = 0.25, -0.25
    set Sensor offsets = 0, 0.1, 0.2
    set Sensor direction = 0, 2
  end
end
subsection Time integration
  set Time step = 0.02
  set End time = 0.1
end
subsection Output
  set Directory = out
  set VTU interval = 0
  set Probe points = 0.1, 0.3
end
"""

failures = 0


def check(ok, what):
    global failures
    failures += not ok
    print(("PASS " if ok else "FAIL ") + what)


def close(points, wanted):
    return len(points) == len(wanted) and all(
        abs(a - b) < 1e-9 for p, q in zip(points, wanted)
        for a, b in zip(p, q))


os.chdir(tempfile.mkdtemp())
open("scene.prm", "w").write(SCENE)
status = subprocess.call([sys.argv[1], "-q", "scene.prm"],
                         stdout=subprocess.DEVNULL)
check(status == 0, "the run ends with exit %d" % status)
used = used_parameters("out")
history = marks_of.History("out/history.csv")
marks = marks_of.scene_marks(used, history, 0.06, (-0.5, 0.5, -0.5, 0.5))
by_kind = {}
for kind, points in marks:
    by_kind.setdefault(kind, []).append(points)
arrows = sorted(p[0] for p in by_kind.get("arrow", []))
check(close(arrows, [(-0.34, -0.1), (0.2, 0.1)]),
      "arrows at the standing load and the moving one at tau = 0.06 "
      "(history.csv): %s" % arrows)
path = by_kind.get("path", [[]])[0]
check(len(path) == 6 and close([path[0], path[-1]], [(-0.4, -0.1),
                                                     (-0.3, -0.1)]),
      "the moving load's path: %d points from %s to %s" % (
          len(path), path[:1], path[-1:]))
outlines = by_kind.get("outline", [])
rectangle = [o for o in outlines if len(o) == 4]
check(close(rectangle[0] if rectangle else [],
            [(-0.25, 0.0), (-0.15, 0.0), (-0.15, 0.2), (-0.25, 0.2)]),
      "the patch's outline: %s" % rectangle)
disc = [o for o in outlines if len(o) == 48]
radius = max(abs(x - 0.25) for x, _ in disc[0]) if disc else 0
check(len(disc) == 1 and abs(radius - 0.15) < 1e-9,
      "the deflectometer's plate: a disc of radius %.6g" % radius)
lines = by_kind.get("line", [])
check(close(lines[0], [(-0.3, -0.3), (0.3, -0.2)]) and
      close([p for line in lines[1:] for p in line],
            [(0.0, -0.5), (0.0, 0.5), (-0.5, 0.0), (0.5, 0.0)]),
      "the line load and the joints x1 = 0, y1 = 0: %s" % lines)
sensors = [p[0] for p in by_kind.get("sensor", [])]
check(close(sensors, [(0.25, -0.25), (0.25, -0.15), (0.25, -0.05)]),
      "the sensors along +y: %s" % sensors)
check(close([p[0] for p in by_kind.get("probe", [])], [(0.1, 0.3)]),
      "the probe from history.csv's columns")
print("%d failed" % failures)
sys.exit(1 if failures else 0)
