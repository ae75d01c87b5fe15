#!/usr/bin/env python3
"""docs/architecture.md's file tables against the tree.

  check_architecture_doc.py <source dir>

"The backends, file by file": every file its Vulkan and GL columns name exists in
backends/vulkan/ or backends/gl/, and every source file there (*.cpp, *.hpp) is named, so the
table cannot drift when files are split, renamed or added. "Tests, file by file": every file or
folder a bullet names exists (in the bullet's tests/<folder>/, or from the source dir when the
name has a slash; in tests/ for the bullet of `tests/*.sh`), and every folder of tests/ has a
bullet.

A name is a file when it is in backticks and has an extension (.cpp, .hpp, .h, .py, .sh, or .*
after a name with an underscore), ends in a slash, or is a test source without its extension
(test_ao); other backticked words (CTest names such as fallback.*, functions) are not files.
"""
import glob
import os
import re
import sys

FILE_TOKEN = re.compile(r"^[\w./*-]+\.(cpp|hpp|h|py|sh)$|^[\w./*-]*_[\w*-]*\.\*$|^[\w./-]+/$|^test_[\w*]+$")


def section(text, title):
    match = re.search(r"^## " + re.escape(title) + r"\n(.*?)(?=^## |\Z)", text, re.S | re.M)
    if not match:
        sys.exit(f"check_architecture_doc: no section '## {title}' in docs/architecture.md")
    return match.group(1)


def file_tokens(text):
    return [t for t in re.findall(r"`([^`]+)`", text) if FILE_TOKEN.match(t)]


def matches(root, base, token):
    """The paths a token names: from the source dir when it has a slash, else in `base`."""
    where = os.path.join(root, token) if "/" in token.rstrip("/") else os.path.join(root, base, token)
    if re.match(r"^test_[\w*]+$", token):
        where += ".cpp"
    return sorted(glob.glob(where))


def main():
    root = sys.argv[1]
    text = open(os.path.join(root, "docs/architecture.md"), encoding="utf-8").read()
    errors = []

    backends = section(text, "The backends, file by file")
    cited = {"vulkan": set(), "gl": set()}
    for line in backends.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if not line.startswith("|") or len(cells) != 3 or cells[1].startswith("Vulkan") or set(cells[1]) <= set("- "):
            # Prose around the table: names with a slash must exist.
            for token in file_tokens(line):
                if "/" in token and not matches(root, None, token):
                    errors.append(f"backends section names {token}, which does not exist")
            continue
        for backend, cell in (("vulkan", cells[1]), ("gl", cells[2])):
            for token in file_tokens(cell):
                found = matches(root, f"backends/{backend}", token)
                if not found:
                    errors.append(f"backends table names {token} for {backend}, not in backends/{backend}/")
                cited[backend].update(os.path.basename(f) for f in found)
    for backend, names in cited.items():
        for path in sorted(glob.glob(os.path.join(root, f"backends/{backend}/*.[ch]pp"))):
            if os.path.basename(path) not in names:
                errors.append(f"backends/{backend}/{os.path.basename(path)} is in no row of the backends table")

    tests = section(text, "Tests, file by file")
    bulleted = set()
    for bullet in re.split(r"^- ", tests, flags=re.M)[1:]:
        head = re.match(r"`tests/(\w+/|\*\.\w+`)", bullet)
        if not head:
            errors.append(f"tests bullet does not start with `tests/<folder>/` or `tests/*.<ext>`: {bullet.splitlines()[0]}")
            continue
        folder = head.group(1).rstrip("/") if head.group(1).endswith("/") else ""
        bulleted.add(folder)
        base = f"tests/{folder}" if folder else "tests"
        for token in file_tokens(bullet):
            if not matches(root, base, token):
                errors.append(f"tests bullet of {base}/ names {token}, which does not exist")
    for path in sorted(glob.glob(os.path.join(root, "tests/*/"))):
        folder = os.path.basename(os.path.dirname(path))
        if folder not in bulleted and folder != "data":  # data: the inputs of the other folders' tests
            errors.append(f"tests/{folder}/ has no bullet in 'Tests, file by file'")

    for e in errors:
        print(f"check_architecture_doc: {e}", file=sys.stderr)
    if errors:
        return 1
    print("check_architecture_doc: the file tables match the tree")
    return 0


if __name__ == "__main__":
    sys.exit(main())
