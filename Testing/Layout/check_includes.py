#!/usr/bin/env python3
"""The layout rule of Core, checked from the sources (the ctest layout.include_direction).

Core's folders are layers, bottom first, as listed in Core/CMakeLists.txt (VOLGRID_CORE_LAYERS). A Core
file may include files of its own folder and of the folders below it, never above; no Core file includes
VTK; every Core file lives in a layer folder; every .cxx has a header of its own in its folder (its stem, or
the family it belongs to: MeshWriterGmsh.cxx implements MeshWriter.h). Filters/ and Apps/ may include any
Core header. Prints one line per violation and exits 1 when there is any.

usage: check_includes.py SOURCE_DIR [LAYER ...]   (layers default to the list in Core/CMakeLists.txt)
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.M)


def layers_from_cmake(core):
    text = open(os.path.join(core, "CMakeLists.txt")).read()
    match = re.search(r"set\(VOLGRID_CORE_LAYERS([^\n]*\n[^\n]*?)CACHE", text)
    return match.group(1).split()


def core_files(core, layers):
    """{file name: layer} for every .h/.cxx of Core; files outside a layer folder map to None."""
    where = {}
    for root, _, names in os.walk(core):
        folder = os.path.relpath(root, core)
        for name in names:
            if name.endswith((".h", ".cxx")):
                where[name] = folder if folder in layers else None
    return where


def files_outside_core(source):
    """{file name: folder} of the VTK adapters and the CLI, which sit above Core."""
    found = {}
    for folder in ("Filters", "Apps"):
        for name in os.listdir(os.path.join(source, folder)):
            if name.endswith(".h"):
                found[name] = folder
    return found


def includes(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        return INCLUDE.findall(f.read())


def own_header(name, headers_here):
    stem = name[: -len(".cxx")]
    return any(stem == h[:-2] or (stem.startswith(h[:-2]) and stem[len(h) - 2].isupper()) for h in headers_here)


def check_core(core, layers):
    rank = {layer: i for i, layer in enumerate(layers)}
    where = core_files(core, layers)
    outside = files_outside_core(os.path.dirname(core))
    problems = []
    for name, layer in sorted(where.items()):
        if layer is None:
            problems.append(f"Core: {name} is in no layer folder ({' '.join(layers)})")
            continue
        path = os.path.join(core, layer, name)
        headers_here = [n for n, l in where.items() if l == layer and n.endswith(".h")]
        if name.endswith(".cxx") and not own_header(name, headers_here):
            problems.append(f"Core/{layer}/{name}: no header of its own in Core/{layer}")
        for kind, target in includes(path):
            if kind == "<" and target.startswith("vtk"):
                problems.append(f"Core/{layer}/{name}: includes VTK ({target})")
            base = os.path.basename(target)
            if kind == '"' and base in outside:
                problems.append(f"Core/{layer}/{name}: includes {base} of {outside[base]}")
            if kind != '"' or base not in where or where[base] is None:
                continue
            if rank[where[base]] > rank[layer]:
                problems.append(f"Core/{layer}/{name}: includes {base} of the higher layer {where[base]}")
    return problems


def main():
    source = sys.argv[1]
    core = os.path.join(source, "Core")
    layers = sys.argv[2:] or layers_from_cmake(core)
    problems = check_core(core, layers)
    for line in problems:
        print(line)
    print(f"{len(problems)} layout problem(s) in Core ({' < '.join(layers)})")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
