#!/usr/bin/python3
"""doc/architecture.md's folder table against the tree.

    /usr/bin/python3 scripts/architecture_table.py [SOURCE_DIR]

The table "Layout: folders by topic" has one row per topic folder of
include/liftoff/ and source/, its last cell the folder's files: a stem for a
header with its source (`time_history`), `name.h` for a header alone,
followed by a note in parentheses where one helps. Prints every file of the
tree the table misses, every name it lists that the folder lacks, and every
folder missing from it or listed but absent; exits 1 if there is any.
"""
import pathlib
import re
import sys

ROW = re.compile(r"^\|\s*`([a-z_]+)/`\s*\|[^|]*\|([^|]*)\|\s*$")


def table(text):
    """{folder: set of names} from the folder table's rows."""
    rows = {}
    for line in text.splitlines():
        match = ROW.match(line)
        if match:
            cell = re.sub(r"\([^)]*\)", "", match.group(2))
            rows[match.group(1)] = {n.strip() for n in cell.split(",")
                                    if n.strip()}
    return rows


def tree(root):
    """{folder: set of names}: a stem where the header has a source of the
    same stem, else the file's own name (x.h, or x.cc for a source alone)."""
    folders = {}
    for folder in sorted((root / "include" / "liftoff").iterdir()):
        if not folder.is_dir():
            continue
        headers = {p.stem for p in folder.glob("*.h")}
        sources = {p.stem for p in (root / "source" / folder.name).glob("*.cc")}
        names = {s for s in headers if s in sources}
        names |= {h + ".h" for h in headers - sources}
        names |= {s + ".cc" for s in sources - headers}
        folders[folder.name] = names
    return folders


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    listed = table((root / "doc" / "architecture.md").read_text())
    present = tree(root)
    problems = []
    for folder in sorted(set(listed) | set(present)):
        if folder not in present:
            problems.append(f"{folder}/: in the table, not in the tree")
            continue
        if folder not in listed:
            problems.append(f"{folder}/: in the tree, not in the table")
            continue
        for name in sorted(present[folder] - listed[folder]):
            problems.append(f"{folder}/{name}: in the tree, not in the table")
        for name in sorted(listed[folder] - present[folder]):
            problems.append(f"{folder}/{name}: in the table, not in the tree")
    for line in problems:
        print(line)
    print(f"doc/architecture.md's folder table: {len(listed)} folders, "
          f"{sum(len(v) for v in present.values())} files in the tree, "
          f"{len(problems)} mismatches")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
