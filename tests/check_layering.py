#!/usr/bin/env python3
"""Fails when a dependency runs against the direction docs/architecture.md draws.

Usage: check_layering.py SOURCE_DIR BUILD_DIR

Two views of the same rule:
- includes: every #include in a source file, resolved to the file it names, must name a file in
  the same folder or in a lower layer;
- links: every target in BUILD_DIR/target_graph.txt (written at configure time by
  cmake/target_graph.cmake) may link only targets of its own folder or of a lower layer.
Backends also never reach into each other: only backends/registry.cpp (the composition root,
library sfx_backends) knows every backend.
"""
import os
import re
import sys

# Lower number = lower layer. A folder may depend on its own layer's files and on lower layers.
# shader_src is the shared headers and shaders the SDK builds on; tests may use samples (the
# engine samples' own tests) but samples never use tests.
LAYERS = [
    ("shader_src", 0),
    ("sdk", 1),
    ("tiers", 2),
    ("backends", 3),
    ("tools", 4),
    ("samples", 5),
    ("tests", 6),
]
BACKENDS = ("backends/vulkan", "backends/gl", "backends/null")
SOURCE_SUFFIXES = (".cpp", ".hpp", ".h", ".c", ".frag", ".vert", ".comp")
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^">]+)[">]', re.M)


def layer_of(path):
    for folder, rank in LAYERS:
        if path == folder or path.startswith(folder + "/"):
            return folder, rank
    return None, None


def backend_of(path):
    for b in BACKENDS:
        if path.startswith(b + "/"):
            return b
    return None


def source_files(root):
    for folder, _ in LAYERS:
        for dirpath, dirnames, filenames in os.walk(os.path.join(root, folder)):
            dirnames[:] = [d for d in dirnames if d not in ("corpus",)]
            for name in filenames:
                if name.endswith(SOURCE_SUFFIXES):
                    yield os.path.relpath(os.path.join(dirpath, name), root)


def check_includes(root, files):
    by_suffix = {}
    for f in files:
        parts = f.split("/")
        for i in range(len(parts)):
            by_suffix.setdefault("/".join(parts[i:]), []).append(f)
    errors = []
    for f in files:
        folder, rank = layer_of(f)
        with open(os.path.join(root, f), encoding="utf-8", errors="replace") as handle:
            text = handle.read()
        for name in INCLUDE.findall(text):
            local = os.path.normpath(os.path.join(os.path.dirname(f), name))
            if local in by_suffix.get(os.path.basename(name), []):
                targets = [local]
            else:
                targets = by_suffix.get(name, [])
            if not targets:
                continue  # a system or generated header
            # A name two layers provide resolves to the lowest one the includer may use.
            allowed = [t for t in targets if layer_of(t)[1] <= rank]
            if not allowed:
                errors.append(f"{f}: includes {name} ({targets[0]}), above its layer {folder}")
                continue
            mine = backend_of(f)
            for t in allowed:
                other = backend_of(t)
                if mine and other and mine != other:
                    errors.append(f"{f}: includes {name} from another backend ({t})")
    return errors


def check_links(build):
    graph = os.path.join(build, "target_graph.txt")
    if not os.path.exists(graph):
        return [f"{graph} is missing: configure the build first (cmake/target_graph.cmake writes it)"], 0
    folders = {}
    links = {}
    with open(graph, encoding="utf-8") as handle:
        for line in handle:
            fields = line.rstrip("\n").split("\t")
            if len(fields) != 3:
                continue
            target, folder, linked = fields
            folders[target] = folder
            links[target] = linked.split()
    errors = []
    for target, linked in links.items():
        folder, rank = layer_of(folders[target])
        if folder is None:
            continue  # the root's interface targets: warnings, the package bundle, the fuzzers
        for other in linked:
            other_folder, other_rank = layer_of(folders.get(other, ""))
            if other_folder is None:
                continue
            if other_rank > rank:
                errors.append(f"target {target} ({folders[target]}) links {other} ({folders[other]}), above its layer")
            mine, theirs = backend_of(folders[target] + "/"), backend_of(folders[other] + "/")
            if mine and theirs and mine != theirs:
                errors.append(f"target {target} ({folders[target]}) links another backend's {other}")
    return errors, len(links)


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    root, build = sys.argv[1], sys.argv[2]
    files = sorted(source_files(root))
    errors = check_includes(root, files)
    link_errors, targets = check_links(build)
    errors += link_errors
    for e in errors:
        print("layering:", e)
    print(f"layering: {len(files)} files and {targets} targets checked, {len(errors)} arrow(s) running back up")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
