#!/usr/bin/python3
"""The limits of the code's shape: no function of more than 60 lines in
source/, no class with more than 25 public members in include/, and
source/run/simulator.cc at most 450 lines (a ctest test, `code_shape`).

    /usr/bin/python3 scripts/code_shape.py [SOURCE_DIR]

Reads the clang-formatted layout of the project rather than parsing C++:
a function body is the lines from a `{` alone on a line, at the indentation
of the function's name, to the `}` at the same indentation; a public member
is a declaration (a line that ends in `;` or starts a function) at the
member indentation of a class's `public:` part, comments, `enum` values,
nested types' bodies and `using` lines not counted. Exits with 1 if a
limit is exceeded.
"""
import pathlib
import re
import sys

MAX_FUNCTION = 60
MAX_PUBLIC = 25
MAX_SIMULATOR = 450

DEFINITION = re.compile(r"^(\s*)(?:[\w:~<>,*& ]+::)?~?[\w]+(?:::[\w~]+)*\(")


def long_functions(path):
    lines = path.read_text().splitlines()
    found = []
    for i, line in enumerate(lines):
        if not (line.strip() == "{" and i > 0):
            continue
        indent = line[:len(line) - len(line.lstrip())]
        # The signature: back to the line at this indentation that opens
        # the name's parenthesis.
        j = i - 1
        while j >= 0 and not (lines[j].startswith(indent)
                              and not lines[j].startswith(indent + " ")
                              and "(" in lines[j]):
            if lines[j].strip() == "" or lines[j].strip().endswith(";"):
                j = -1
                break
            j -= 1
        if j < 0 or not DEFINITION.match(lines[j]):
            continue
        end = i + 1
        while end < len(lines) and lines[end] != indent + "}":
            end += 1
        length = end - j + 1
        if length > MAX_FUNCTION:
            name = lines[j].strip().split("(")[0]
            found.append((length, "%s:%d" % (path, j + 1), name))
    return found


def public_members(path):
    """(class, count) for every class of the header."""
    lines = path.read_text().splitlines()
    result = []
    for i, line in enumerate(lines):
        match = re.match(r"^(\s*)(class|struct) (\w+)[^;]*$", line)
        if not match:
            continue
        indent, kind, name = match.groups()
        member = indent + "  "
        public = kind == "struct"
        count = 0
        depth_open = False
        for body in lines[i + 1:]:
            if body == indent + "};":
                break
            if body.startswith(indent + "public:"):
                public = True
                continue
            if body.startswith(indent + "private:") or body.startswith(
                    indent + "protected:"):
                public = False
                continue
            if not public or not body.startswith(member) or body.startswith(
                    member + " "):
                continue
            text = body.strip()
            if depth_open:
                if text.startswith("};") or text == "}":
                    depth_open = False
                continue
            if text.startswith(("//", "/*", "*", "{", "}")):
                continue
            if text.startswith(("enum", "struct", "class")) and not \
                    text.endswith(";"):
                depth_open = True
                count += 1
                continue
            if text.startswith("using ") or text.startswith("template"):
                continue
            # A declaration: one line ending in ";" or a function's name
            # line (return type lines alone are not counted).
            if "(" in text or text.endswith(";"):
                if re.match(r"^[\w:<>,*& ]+$", text):
                    continue
                count += 1
        result.append((name, count, "%s:%d" % (path, i + 1)))
    return result


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    failed = False
    functions = []
    for path in sorted((root / "source").rglob("*.cc")):
        functions += long_functions(path)
    print("functions over %d lines in source/: %d" % (MAX_FUNCTION,
                                                     len(functions)))
    for length, where, name in sorted(functions, reverse=True):
        print("  %4d  %s  %s" % (length, where, name))
    failed |= bool(functions)

    classes = []
    for path in sorted((root / "include").rglob("*.h")):
        classes += [c for c in public_members(path) if c[1] > MAX_PUBLIC]
    print("classes with more than %d public members: %d" % (MAX_PUBLIC,
                                                           len(classes)))
    for name, count, where in sorted(classes, key=lambda c: -c[1]):
        print("  %4d  %s  %s" % (count, where, name))
    failed |= bool(classes)

    simulator = root / "source" / "run" / "simulator.cc"
    n = len(simulator.read_text().splitlines())
    print("source/run/simulator.cc: %d lines (limit %d)" % (n,
                                                            MAX_SIMULATOR))
    failed |= n > MAX_SIMULATOR
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
