#!/usr/bin/env python3
"""Every parameter liftoff declares must refuse a value of the wrong type,
and every subsection a misspelt entry name: non-zero exit, a message that
names the entry, and no output folder.

    every_parameter_refused.py LIFTOFF

The list of parameters comes from `liftoff --parameters`, so a parameter
added later is covered without touching this file. Of the numbered load
subsections (Point load 1..8, ...) only the first is tried: the others are
declared by the same code.
"""

import os
import re
import subprocess
import sys
import tempfile

# Entries for which any text is a valid value: a folder name.
ANY_TEXT_IS_VALID = {("Output", "Directory")}
WRONG_VALUE = "@@"


def declared_entries(liftoff):
    text = subprocess.run([liftoff, "--parameters"], capture_output=True,
                          text=True, check=True).stdout
    path, entries = [], []
    for line in text.splitlines():
        line = line.strip()
        if line.startswith("subsection "):
            path.append(line[len("subsection "):].strip())
        elif line == "end":
            path.pop()
        elif line.startswith("set "):
            name = line[4:].split("=", 1)[0].strip()
            entries.append((tuple(path), name))
    return entries


def is_first_of_numbered(path):
    return all(not re.search(r" ([2-9])$", s) for s in path)


def scene(path, entry, value):
    text = "".join("subsection %s\n" % s for s in path)
    text += "set %s = %s\n" % (entry, value)
    text += "end\n" * len(path)
    return text


def refused(liftoff, text, must_mention):
    """Run the scene in a fresh folder; return a list of what went wrong."""
    with tempfile.TemporaryDirectory() as work:
        text = "subsection Output\n  set Directory = out\nend\n" + text
        run = subprocess.run([liftoff, "-"], input=text, capture_output=True,
                             text=True, cwd=work)
        problems = []
        if run.returncode == 0:
            problems.append("exit code 0")
        if must_mention not in run.stderr:
            problems.append("message does not name '%s': %s" %
                            (must_mention, run.stderr.strip()[:300]))
        if os.path.exists(os.path.join(work, "out")):
            problems.append("an output folder was created")
        return problems


def main():
    liftoff = os.path.abspath(sys.argv[1])
    entries = [e for e in declared_entries(liftoff)
               if is_first_of_numbered(e[0])]
    failures, cases = 0, 0

    def report(what, problems):
        nonlocal failures, cases
        cases += 1
        if problems:
            failures += 1
            print("FAIL %s: %s" % (what, "; ".join(problems)))
        else:
            print("PASS %s" % what)

    for path, entry in entries:
        where = "/".join(path + (entry,))
        if (path[-1:] + (entry,)) in ANY_TEXT_IS_VALID:
            continue
        report("%s = %s refused" % (where, WRONG_VALUE),
               refused(liftoff, scene(path, entry, WRONG_VALUE), entry))

    seen = set()
    for path, entry in entries:
        if path in seen:
            continue
        seen.add(path)
        misspelt = entry + "x"
        report("misspelt %s refused" % "/".join(path + (misspelt,)),
               refused(liftoff, scene(path, misspelt, "1"), misspelt))

    print("%d of %d cases passed" % (cases - failures, cases))
    return 1 if failures or cases < 20 else 0


if __name__ == "__main__":
    sys.exit(main())
