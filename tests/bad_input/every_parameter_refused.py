#!/usr/bin/env python3
"""Every parameter liftoff declares must refuse a value of the wrong type,
and every subsection a misspelt entry name: non-zero exit, a message that
names the entry, and no output folder.

    every_parameter_refused.py LIFTOFF

The parameters and the values each allows come from `liftoff --parameters
json`, so a parameter added later is covered without touching this file. Of
the numbered load subsections (Point load 1..8, ...) only the first is
tried: the others are declared by the same code.

An entry whose pattern is a number, a boolean or a selection is refused by
the ParameterHandler's check of its pattern while the scene is read, before
any of liftoff's classes sees it, along one path for all such entries: for
each, the test checks that its pattern cannot accept the wrong value, and
runs the binary on the first of them in every subsection. An entry with a
looser pattern (any text, a list, a map, a file name: functions, paths,
expressions) is checked by the class that reads it, so each one is run.
"""

import json
import os
import re
import subprocess
import sys
import tempfile

# Entries for which any text is a valid value: a folder name.
ANY_TEXT_IS_VALID = {("Output", "Directory")}
WRONG_VALUE = "@@"


def declared_entries(liftoff):
    """(path, entry, pattern description) of every declared entry."""
    text = subprocess.run([liftoff, "--parameters", "json"],
                          capture_output=True, text=True, check=True).stdout
    entries = []

    def walk(node, path):
        for key, child in node.items():
            if not isinstance(child, dict):
                continue
            if "value" in child:
                entries.append((path, key,
                                child.get("pattern_description", "")))
            else:
                walk(child, path + (key,))

    walk(json.loads(text), ())
    return entries


STRICT = re.compile(r"^\[(Double|Integer|Bool|Selection)\b")


def pattern_refuses(description, value):
    """Whether a number, boolean or selection pattern cannot match `value`
    (None for other patterns, which the binary must be asked about)."""
    match = STRICT.match(description)
    if not match:
        return None
    if match.group(1) == "Selection":
        options = description[len("[Selection "):].rstrip(" ]").split("|")
        return value not in [o.strip() for o in options]
    if match.group(1) == "Bool":
        return value not in ("true", "false", "yes", "no")
    # A number has at least one digit.
    return not re.search(r"[0-9]", value)


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

    runs_of_strict = set()
    for path, entry, pattern in entries:
        where = "/".join(path + (entry,))
        if (path[-1:] + (entry,)) in ANY_TEXT_IS_VALID:
            continue
        refuses = pattern_refuses(pattern, WRONG_VALUE)
        if refuses is False:
            report("%s: pattern %s refuses %s" % (where, pattern, WRONG_VALUE),
                   ["the pattern accepts it"])
        elif refuses and path in runs_of_strict:
            report("%s: pattern %s refuses %s" % (where, pattern, WRONG_VALUE),
                   [])
        else:
            if refuses:
                runs_of_strict.add(path)
            report("%s = %s refused" % (where, WRONG_VALUE),
                   refused(liftoff, scene(path, entry, WRONG_VALUE), entry))

    seen = set()
    for path, entry, _ in entries:
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
