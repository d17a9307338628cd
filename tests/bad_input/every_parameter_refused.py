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
The scenes run in one process (`liftoff --batch`), each in a folder of its
own as if run alone, so the start-up (0.4 s a process) is paid once.
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


class Batch:
    """The scenes to refuse, run in one liftoff process (--batch), each in
    a folder of its own as if run alone; problems() says what went wrong
    with each: the batch must name it among the scenes that failed, its
    message must name the entry, and it must create no output folder."""

    def __init__(self):
        self.scenes = []    # (text, what its message must mention)

    def add(self, text, must_mention):
        self.scenes.append((text, must_mention))
        return len(self.scenes) - 1

    def run(self, liftoff):
        self.work = tempfile.TemporaryDirectory()
        names = []
        for k, (text, _) in enumerate(self.scenes):
            name = "s%03d.prm" % k
            with open(os.path.join(self.work.name, name), "w") as f:
                f.write("subsection Output\n  set Directory = out%03d\nend\n"
                        % k + text)
            names.append(name)
        run = subprocess.run([liftoff, "-q", "--batch"] + names,
                             capture_output=True, text=True,
                             cwd=self.work.name)
        # Each failure is "liftoff: error in NAME:" and its message on the
        # next line; the batch's last line names every scene that failed.
        self.messages = dict(re.findall(r"liftoff: error in (\S+):\n(.*)",
                                        run.stderr))
        failed = re.search(r"scenes failed: (.*)", run.stderr)
        self.failed = set(failed.group(1).split()) if failed else set()
        self.exit_code = run.returncode

    def problems(self, k):
        name, (_, must_mention) = "s%03d.prm" % k, self.scenes[k]
        problems = []
        if name not in self.failed:
            problems.append("not among the batch's failed scenes")
        if must_mention not in self.messages.get(name, ""):
            problems.append("message does not name '%s': %s" %
                            (must_mention, self.messages.get(name, "")[:300]))
        if os.path.exists(os.path.join(self.work.name, "out%03d" % k)):
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

    batch, checks = Batch(), []
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
            checks.append(("%s = %s refused" % (where, WRONG_VALUE),
                           batch.add(scene(path, entry, WRONG_VALUE), entry)))

    seen = set()
    for path, entry, _ in entries:
        if path in seen:
            continue
        seen.add(path)
        misspelt = entry + "x"
        checks.append(("misspelt %s refused" % "/".join(path + (misspelt,)),
                       batch.add(scene(path, misspelt, "1"), misspelt)))

    batch.run(liftoff)
    report("the batch of %d scenes exits 1" % len(batch.scenes),
           [] if batch.exit_code == 1 else ["exit code %d" % batch.exit_code])
    for what, k in checks:
        report(what, batch.problems(k))

    print("%d of %d cases passed" % (cases - failures, cases))
    return 1 if failures or cases < 20 else 0


if __name__ == "__main__":
    sys.exit(main())
