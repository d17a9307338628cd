#!/usr/bin/env python3
"""Scenes of tests/bad_input that liftoff must refuse, run in one process
(`liftoff --batch`), as each would be alone by expect_failure.sh: each
must be among the scenes the batch names as failed, its message (the line
after "liftoff: error in SCENE:") must match the regular expression of its
first line "# EXPECT: ...", and it must leave no output folder. The
start-up of a process (0.3 to 0.5 s, mostly the dynamic loader) is paid
once for all of them instead of once each.

    refused_in_batch.py LIFTOFF SCENE.prm...

Each scene is copied into a folder of the same depth as tests/bad_input,
beside links to tests/meshes and prm/, so that the relative paths the
scenes give (../meshes/square.msh) name the same files; its `Directory =
out` becomes a folder of its own.
"""

import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def copy_scenes(scenes, work):
    """The scenes' copies in work/tests/bad_input, by name, with the
    regular expression each message must match."""
    os.makedirs(os.path.join(work, "tests", "bad_input"))
    os.symlink(os.path.join(HERE, "..", "meshes"),
               os.path.join(work, "tests", "meshes"))
    os.symlink(os.path.join(HERE, "..", "..", "prm"),
               os.path.join(work, "prm"))
    expected = {}
    for scene in scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        with open(scene) as f:
            text = f.read()
        first = text.split("\n", 1)[0]
        if not first.startswith("# EXPECT: "):
            sys.exit("FAIL %s has no '# EXPECT:' first line" % scene)
        text = re.sub(r"(set Directory\s*=\s*)out\s*$", r"\1out-" + name,
                      text, flags=re.M)
        path = os.path.join("tests", "bad_input", name + ".prm")
        with open(os.path.join(work, path), "w") as f:
            f.write(text)
        expected[path] = first[len("# EXPECT: "):]
    return expected


def main():
    liftoff, scenes = sys.argv[1], sys.argv[2:]
    failures = 0
    with tempfile.TemporaryDirectory() as work:
        expected = copy_scenes(scenes, work)
        run = subprocess.run([liftoff, "-q", "--batch"] + list(expected),
                             capture_output=True, text=True, cwd=work)
        messages = {name: header + message for name, header, message in
                    re.findall(r"liftoff: error in (\S+?):(.*)\n(.*)",
                               run.stderr)}
        named = re.search(r"scenes failed: (.*)", run.stderr)
        failed = set(named.group(1).split()) if named else set()
        for name, pattern in expected.items():
            problems = []
            if name not in failed:
                problems.append("not among the batch's failed scenes")
            if not re.search(pattern, messages.get(name, "")):
                problems.append("message does not match /%s/: %s"
                                % (pattern, messages.get(name, "")[:300]))
            stem = os.path.splitext(os.path.basename(name))[0]
            if os.path.exists(os.path.join(work, "out-" + stem)):
                problems.append("an output folder was created")
            print("%s %s%s" % ("FAIL" if problems else "PASS", stem,
                               ": " + "; ".join(problems) if problems
                               else ": refused, " + messages[name].strip()
                               [:120]))
            failures += bool(problems)
        if run.returncode != 1:
            print("FAIL the batch exits %d, not 1" % run.returncode)
            failures += 1
    print("%d of %d scenes refused as expected" % (len(expected) - failures,
                                                     len(expected)))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
