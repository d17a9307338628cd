"""summary.json against summary.txt of the same run and against closed
forms: both files hold the same keys in the same order, every number of the
text is a JSON number (an integer where the text shows a count), the same to
the text's six digits, and the counts are those of the scene (unknowns
3 (p nx + 1)(p ny + 1), steps End time / Time step)."""

import json
import os
import pathlib
import subprocess
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "common"))
from checks import check, finish  # noqa: E402

liftoff = sys.argv[1]
SCENE = """
subsection Plate
  set Aspect ratio = 1
end
subsection Discretization
  set Cells along x = 3
  set Cells along y = 2
  set Polynomial degree = 2
end
subsection Time integration
  set Time step = 0.01
  set End time = 0.05
end
subsection Foundation
  set Stiffness = 100
end
subsection Loads
  subsection Point load 1
    set Position  = 0.1, 0
    set Magnitude = 1
  end
end
subsection Output
  set Directory = %s
  set VTU interval = 0
end
"""


def text_entries(path):
    """(key, value) of summary.txt, a section's entries as 'section/name'."""
    entries, section = [], None
    for line in path.read_text().splitlines():
        if line.startswith("  "):
            name, value = line.strip().split(": ", 1)
            entries.append((section + "/" + name, value))
        else:
            key, _, value = line.partition(":")
            value = value.strip()
            if value:
                entries.append((key, value))
                section = None
            else:
                section = key
    return entries


def json_entries(document):
    entries = []
    for key, value in document.items():
        if isinstance(value, dict):
            entries += [(key + "/" + name, v) for name, v in value.items()]
        else:
            entries.append((key, value))
    return entries


with tempfile.TemporaryDirectory() as folder:
    output = os.path.join(folder, "run")
    scene = os.path.join(folder, "scene.prm")
    pathlib.Path(scene).write_text(SCENE % output)
    run = subprocess.run([liftoff, "--quiet", scene], capture_output=True,
                         text=True, timeout=120)
    check(run.returncode == 0, "the run ends with 0 (%d: %s)"
          % (run.returncode, run.stderr.strip()[-300:]))
    text = text_entries(pathlib.Path(output, "summary.txt"))
    with open(os.path.join(output, "summary.json")) as f:
        document = json.load(f)
    from_json = json_entries(document)

    check([k for k, _ in text] == [k for k, _ in from_json],
          "the same %d keys in the same order in both files" % len(text))
    mismatches = []
    for (key, t), (_, j) in zip(text, from_json):
        try:
            number = float(t)
        except ValueError:
            if j != t:
                mismatches.append((key, t, j))
            continue
        is_count = t.lstrip("-").isdigit()
        ok = (isinstance(j, int) if is_count else
              isinstance(j, (int, float)) and not isinstance(j, bool))
        ok = ok and abs(j - number) <= 5e-6 * max(abs(number), 1e-300)
        if not ok:
            mismatches.append((key, t, j))
    check(not mismatches, "every value of summary.txt is in summary.json, "
          "numbers as JSON numbers (counts as integers): %s" % mismatches[:3])
    check(document.get("dofs") == 3 * (2 * 3 + 1) * (2 * 2 + 1),
          "dofs = 3 (p nx + 1)(p ny + 1) = 105 (%s)" % document.get("dofs"))
    check(document.get("steps") == 5,
          "steps = End time / Time step = 5 (%s)" % document.get("steps"))
    check(document.get("status") == "completed",
          "status completed (%s)" % document.get("status"))
finish()
