#!/usr/bin/env python3
"""Lists the functions longer than a limit (default 150 lines) in project C++ sources.

Usage: Testing/Layout/function_lengths.py [--limit N] [folders...]   (default folders: Core Apps Filters)

How it counts (the sources are clang-formatted, Allman braces): a function body opens with a line that
is only '{' at some indentation, after a signature line at that indentation containing '(' that is not
a control statement, a lambda or an initializer; the body ends at the next line starting with '}' at
that indentation. The length runs from the signature's first line to the closing brace, comments and
blank lines included. Member functions defined inside a class are counted too; lambdas count towards
the function that holds them.
"""
import os
import re
import sys

CONTROL = re.compile(r"^\s*(if|for|while|switch|else|do|catch|try|return|case)\b")
SCOPE = re.compile(r"^\s*(namespace|class|struct|enum|union)\b")


def functions(path):
    lines = open(path, errors="replace").read().split("\n")
    for i, line in enumerate(lines):
        if line.strip() != "{":
            continue
        ind = line[: len(line) - 1]
        j = i - 1
        while j > 0 and (lines[j].startswith(ind + " ") or lines[j].strip() == ""):
            j -= 1
        sig = lines[j]
        if not sig.startswith(ind) or sig[len(ind) : len(ind) + 1] == " ":
            continue
        head = sig.split("(")[0]
        if "(" not in sig or CONTROL.match(sig) or SCOPE.match(sig) or "[" in head or "=" in head:
            continue
        k = i + 1
        while k < len(lines) and not (lines[k].startswith(ind + "}") and not lines[k].startswith(ind + "} ")):
            k += 1
        yield k - j + 1, j + 1, re.sub(r"\(.*", "", sig).split()[-1]


def main(argv):
    limit = 150
    if len(argv) >= 2 and argv[0] == "--limit":
        limit = int(argv[1])
        argv = argv[2:]
    found = []
    for root in argv or ["Core", "Apps", "Filters"]:
        for folder, _, files in os.walk(root):
            for name in files:
                if name.endswith((".cxx", ".h")):
                    path = os.path.join(folder, name)
                    found += [(n, path, line, fn) for n, line, fn in functions(path) if n > limit]
    for n, path, line, fn in sorted(found, reverse=True):
        print(f"{n:5d} {path}:{line} {fn}")
    print(f"{len(found)} functions over {limit} lines")


if __name__ == "__main__":
    main(sys.argv[1:])
