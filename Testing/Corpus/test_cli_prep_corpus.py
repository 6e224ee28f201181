#!/usr/bin/env python3
"""`volgrid prep` on every file of the shared corpus, then `volgrid check` on what it wrote.

What a user relies on: prep never crashes or hangs; when it says a surface is meshable, the written
surface really is closed, without non-manifold edges, consistently oriented and free of
self-intersections (an independent `volgrid check` finds it meshable); when it says not, it names what is left (self-intersections,
non-manifold edges, open holes beyond the fill limit, intersecting shells).

usage: test_cli_prep_corpus.py VOLGRID_CLI SHARED_DATA_DIR [--timeout S] [--jobs N]
"""
import concurrent.futures
import json
import os
import subprocess
import sys
import tempfile

LEFT_OVER = ["self_intersecting_pairs", "shell_intersecting_pairs", "non_manifold_edges", "boundary_edges",
             "degenerate_triangles", "duplicate_triangles"]


def corpus_files(data_dir):
    files = []
    with open(os.path.join(data_dir, "SOURCES.md"), encoding="utf-8") as sources:
        for line in sources:
            cells = [c.strip() for c in line.split("|")]
            if len(cells) >= 11 and "/" in cells[1] and cells[1] != "file":
                files.append(cells[1])
    return files


def last_json(text):
    for line in reversed(text.strip().splitlines()):
        if line.startswith("{"):
            try:
                return json.loads(line)
            except ValueError:
                return None
    return None


def run(cli, data_dir, name, timeout, scratch):
    out = os.path.join(scratch, name.replace("/", "_") + ".vtp")
    try:
        prep = subprocess.run([cli, "prep", os.path.join(data_dir, name), out, "--json"],
                              capture_output=True, text=True, timeout=timeout)
        check = None
        if prep.returncode == 0:
            check = subprocess.run([cli, "check", out, "--json"], capture_output=True, text=True,
                                   timeout=timeout)
    except subprocess.TimeoutExpired:
        return name, "timeout", None, None, ""
    finally:
        if os.path.exists(out):
            os.remove(out)
    return name, prep.returncode, last_json(prep.stdout), check, prep.stderr.strip()


def main():
    cli, data_dir = sys.argv[1], sys.argv[2]
    timeout = float(sys.argv[sys.argv.index("--timeout") + 1]) if "--timeout" in sys.argv else 180
    jobs = int(sys.argv[sys.argv.index("--jobs") + 1]) if "--jobs" in sys.argv else 2
    files = corpus_files(data_dir)
    problems, meshable, left, unreadable = [], 0, 0, 0
    with tempfile.TemporaryDirectory() as scratch, \
            concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        for name, code, summary, check, err in pool.map(
                lambda f: run(cli, data_dir, f, timeout, scratch), files):
            if code == "timeout":
                problems.append(f"{name}: no answer within {timeout:.0f} s")
            elif code not in (0, 1):
                problems.append(f"{name}: prep exit code {code} (crash?) {err[-200:]}")
            elif code == 0:
                meshable += 1
                verdict = last_json(check.stdout) if check is not None else None
                # check exits 1 for any defect, also those the mesher accepts (a non-manifold vertex):
                # its "meshable" verdict is what prep promises.
                if not verdict or not verdict.get("meshable"):
                    problems.append(f"{name}: prep said meshable but check disagrees: "
                                    f"{check.stdout.strip()[-300:] if check else ''}")
            elif summary is None:
                unreadable += 1
                if not err:
                    problems.append(f"{name}: prep failed without a message")
            else:
                left += 1
                if not any(summary.get(k, 0) for k in LEFT_OVER) and not summary.get("holes_left_open"):
                    problems.append(f"{name}: prep said not meshable but names nothing left: {summary}")
    for line in problems:
        print("FAIL:", line)
    print(f"prep over the corpus: {len(files)} files, {meshable} made meshable (confirmed by check), "
          f"{left} with unrepairable defects named, {unreadable} unreadable, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
