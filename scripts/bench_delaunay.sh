#!/usr/bin/env bash
# make bench: VolGrid's Delaunay kernel against TetGen, CGAL and vtkDelaunay3D on the same points.
#
#   scripts/bench_delaunay.sh [BUILD_DIR] [options]          (make bench runs `scripts/bench_delaunay.sh build`)
#
# Every (engine, input, n) case is a separate process of BUILD_DIR/bin/volgrid_bench_delaunay, so peak
# memory is per run. The JSON lines go to BUILD_DIR/bench/delaunay.jsonl, the table to stdout and to
# BUILD_DIR/bench/delaunay.txt. A case that fails, crashes or times out is listed as such, never dropped.
#
# Options:
#   --quick             the 100k-point cases only (random 100k, grid/jittered 46^3 = 97336, spheres 100k);
#                       vtkDelaunay3D is left out unless --vtk is given
#   --vtk / --no-vtk    force vtkDelaunay3D (random 100k) in or out
#   --engines LIST      comma-separated subset of volgrid,volgrid1,tetgen,cgal,vtk (volgrid1: VolGrid
#                       on one thread; volgrid: its defaults, all cores)
#   --inputs LIST       comma-separated subset of random,grid,jittered-grid,spheres
#   --sizes LIST        comma-separated n values to keep (e.g. 100000)
#   --repeat R          run each case R times and report the fastest (default 1)
#   --timeout S         per-run time limit in seconds (default 600)
#   --seed S            point generator seed (default 1)
#   --location L        VolGrid point location: walk (default) or bucket-grid
#   --no-sort           VolGrid: insert in input order (no BRIO/Hilbert sort)
#   --out FILE          JSON lines file (default BUILD_DIR/bench/delaunay.jsonl)
#   --table-only        do not run anything: print the table of an existing JSON lines file
set -euo pipefail

repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="build"
if [ $# -gt 0 ] && [ "${1#-}" = "$1" ]; then
  build_dir="$1"
  shift
fi
# A relative build dir is taken from the current directory, else from the repo root.
if [ ! -d "$build_dir" ] && [ -d "$repo_root/$build_dir" ]; then
  build_dir="$repo_root/$build_dir"
fi

if ! command -v python3 >/dev/null 2>&1; then
  echo "bench.sh: python3 is required (Debian's python3, which python3-paraview depends on)" >&2
  exit 2
fi

table_only=0
for a in "$@"; do
  if [ "$a" = "--table-only" ]; then table_only=1; fi
done

bin="$build_dir/bin/volgrid_bench_delaunay"
if [ "$table_only" -eq 0 ] && [ ! -x "$bin" ]; then
  if [ -f "$build_dir/CMakeCache.txt" ]; then
    echo "bench.sh: building volgrid_bench_delaunay in $build_dir" >&2
    cmake --build "$build_dir" --target volgrid_bench_delaunay -j "${JOBS:-2}" >&2
  fi
  if [ ! -x "$bin" ]; then
    echo "bench.sh: $bin not found: run 'make build' first (the benchmark is built in the ParaView flavour)" >&2
    exit 2
  fi
fi

export VOLGRID_BENCH_BIN="$bin"
export VOLGRID_BENCH_BUILD_DIR="$build_dir"
exec python3 - "$@" <<'PYTHON'
import json, os, subprocess, sys, time

args = sys.argv[1:]
opt = {"quick": False, "vtk": None, "engines": None, "inputs": None, "sizes": None, "repeat": 1,
       "timeout": 600, "seed": 1, "out": None, "table_only": False, "volgrid_args": []}
i = 0
while i < len(args):
    a = args[i]
    def val():
        global i
        if i + 1 >= len(args):
            sys.exit("bench.sh: %s needs a value" % a)
        i += 1
        return args[i]
    if a == "--quick": opt["quick"] = True
    elif a == "--vtk": opt["vtk"] = True
    elif a == "--no-vtk": opt["vtk"] = False
    elif a == "--engines": opt["engines"] = val().split(",")
    elif a == "--inputs": opt["inputs"] = val().split(",")
    elif a == "--sizes": opt["sizes"] = [int(x) for x in val().split(",")]
    elif a == "--repeat": opt["repeat"] = max(1, int(val()))
    elif a == "--timeout": opt["timeout"] = int(val())
    elif a == "--seed": opt["seed"] = int(val())
    elif a == "--out": opt["out"] = val()
    elif a == "--table-only": opt["table_only"] = True
    elif a == "--location": opt["volgrid_args"] += ["--location", val()]
    elif a == "--no-sort": opt["volgrid_args"] += ["--no-sort"]
    else: sys.exit("bench.sh: unknown option %s (see the header of scripts/bench_delaunay.sh)" % a)
    i += 1

binary = os.environ["VOLGRID_BENCH_BIN"]
build_dir = os.environ["VOLGRID_BENCH_BUILD_DIR"]
out_path = opt["out"] or os.path.join(build_dir, "bench", "delaunay.jsonl")
# volgrid: the default options (all cores, canonical numbering
# for large inputs); volgrid1: the same forced to one thread (VOLGRID_THREADS=1), for the sequential
# comparison. TetGen, CGAL (Delaunay_triangulation_3, sequential) and vtkDelaunay3D are sequential.
ENGINES = ["volgrid", "volgrid1", "tetgen", "cgal", "vtk"]
NAMES = {"volgrid": "VolGrid", "volgrid1": "VolGrid 1 thr", "tetgen": "TetGen", "cgal": "CGAL",
         "vtk": "vtkDelaunay3D"}
THREE = ["volgrid", "volgrid1", "tetgen", "cgal"]

# (input, n, engines) in run order.
if opt["quick"]:
    cases = [("random", 100000, ENGINES if opt["vtk"] else THREE),
             ("grid", 46 ** 3, THREE), ("jittered-grid", 46 ** 3, THREE), ("spheres", 100000, THREE)]
else:
    cases = [("random", 100000, ENGINES if opt["vtk"] is not False else THREE),
             ("random", 1000000, THREE), ("grid", 100 ** 3, THREE), ("jittered-grid", 100 ** 3, THREE),
             ("spheres", 1000000, THREE)]
cases = [(inp, n, [e for e in engs if opt["engines"] is None or e in opt["engines"]])
         for inp, n, engs in cases
         if (opt["inputs"] is None or inp in opt["inputs"]) and (opt["sizes"] is None or n in opt["sizes"])]

def load1():
    try:
        with open("/proc/loadavg") as f:
            return float(f.read().split()[0])
    except OSError:
        return None

def run_one(engine, inp, n, rep):
    cmd = [binary, "--engine", "volgrid" if engine == "volgrid1" else engine, "--input", inp, "--n", str(n),
           "--seed", str(opt["seed"])]
    env = dict(os.environ)
    if engine in ("volgrid", "volgrid1"):
        cmd += opt["volgrid_args"]
    if engine == "volgrid1":
        env["VOLGRID_THREADS"] = "1"
    base = {"engine": engine, "input": inp, "n": n, "seed": opt["seed"], "repeat": rep, "load1_before": load1(),
            "time": time.strftime("%Y-%m-%d %H:%M:%S")}
    t0 = time.time()
    try:
        p = subprocess.run(cmd, stdin=subprocess.DEVNULL, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           timeout=opt["timeout"], text=True)
    except subprocess.TimeoutExpired:
        base.update(ok=False, error="timeout after %d s" % opt["timeout"], status="timeout")
        return base
    wall = time.time() - t0
    rec = None
    for line in reversed(p.stdout.splitlines()):
        line = line.strip()
        if line.startswith("{"):
            try:
                rec = json.loads(line)
                break
            except ValueError:
                pass
    if rec is None:
        why = "killed by signal %d" % -p.returncode if p.returncode < 0 else "exit code %d" % p.returncode
        err = (p.stderr.strip().splitlines() or [""])[-1][:200]
        rec = {"ok": False, "error": why + (": " + err if err else "") + " (no JSON line)"}
    elif p.returncode != 0 and rec.get("ok"):
        rec.update(ok=False, error="exit code %d after a JSON line" % p.returncode)
    for k, v in base.items():
        rec.setdefault(k, v)
    rec["engine"] = engine  # volgrid1 runs the volgrid engine on one thread
    rec["load1_before"] = base["load1_before"]
    rec["wall_seconds"] = round(wall, 3)
    rec["status"] = "ok" if rec.get("ok") else rec.get("status", "failed")
    return rec

records = []
if opt["table_only"]:
    with open(out_path) as f:
        records = [json.loads(l) for l in f if l.strip()]
else:
    os.makedirs(os.path.dirname(os.path.abspath(out_path)), exist_ok=True)
    total = sum(len(e) for _, _, e in cases) * opt["repeat"]
    done = 0
    with open(out_path, "w") as out:
        for inp, n, engs in cases:
            for rep in range(opt["repeat"]):
                for engine in engs:
                    done += 1
                    sys.stderr.write("[%d/%d] %s %s n=%d%s ... " % (done, total, engine, inp, n,
                                     " (repeat %d)" % (rep + 1) if opt["repeat"] > 1 else ""))
                    sys.stderr.flush()
                    rec = run_one(engine, inp, n, rep)
                    sys.stderr.write(("%.3f s\n" % rec["seconds"]) if rec.get("ok") else rec["status"] + ": " + rec.get("error", "") + "\n")
                    records.append(rec)
                    out.write(json.dumps(rec, sort_keys=False) + "\n")
                    out.flush()

# ---- table: per (input, n, engine) the fastest successful run, else the last failure ----
best = {}
order = []
for r in records:
    key = (r["input"], int(r["n"]), r["engine"])
    if key not in best:
        order.append(key)
        best[key] = r
    else:
        cur = best[key]
        if r.get("ok") and (not cur.get("ok") or r["seconds"] < cur["seconds"]):
            best[key] = r
runs = {}
by_repeat = {}
for r in records:
    if r.get("ok"):
        key = (r["input"], int(r["n"]), r["engine"])
        runs.setdefault(key, []).append(r["seconds"])
        by_repeat.setdefault(key, {})[r.get("repeat", 0)] = r["seconds"]

def paired_median(a, b):
    """Median over repeats of a/b, each ratio taken between runs of the same round (adjacent in time)."""
    ra, rb = by_repeat.get(a, {}), by_repeat.get(b, {})
    q = sorted(ra[k] / rb[k] for k in ra if k in rb and rb[k] > 0)
    if len(q) < 2:
        return None
    m = len(q) // 2
    return q[m] if len(q) % 2 else 0.5 * (q[m - 1] + q[m])

lines = []
def emit(s=""):
    lines.append(s)

def fmt_int(v):
    return "{:,}".format(int(v))

emit("Delaunay benchmark (%s); seed %s; times are the triangulation call only, fastest of %s run(s)" %
     (records[0].get("time", "?") if records else time.strftime("%Y-%m-%d %H:%M:%S"), records[0].get("seed", opt["seed"]) if records else opt["seed"], max((r.get("repeat", 0) for r in records), default=0) + 1))
emit("bytes/tet = (peak RSS - RSS after the input was generated and handed to the engine) / finite tets")
hdr = "%-14s %9s %-14s %9s %11s %11s %9s %9s %6s" % ("input", "n", "engine", "seconds", "tets", "tets/s",
                                                     "peak MB", "bytes/tet", "load")
emit(hdr)
emit("-" * len(hdr))
prev = None
for key in order:
    inp, n, engine = key
    r = best[key]
    if prev is not None and prev != (inp, n):
        emit("")
    prev = (inp, n)
    load = r.get("load1_before")
    loads = "%.1f" % load if isinstance(load, (int, float)) else "-"
    if r.get("ok"):
        secs = "%.3f" % r["seconds"]
        if len(runs.get(key, [])) > 1:
            secs += "*"
        emit("%-14s %9d %-14s %9s %11s %11s %9.0f %9.1f %6s" % (inp, n, NAMES.get(engine, engine), secs,
             fmt_int(r["tets"]), fmt_int(r["tets_per_s"]), r["peak_rss_mb"], r["bytes_per_tet_beyond_input"], loads))
    else:
        emit("%-14s %9d %-14s %s: %s" % (inp, n, NAMES.get(engine, engine), r.get("status", "failed").upper(),
             r.get("error", "")))
if any(len(v) > 1 for v in runs.values()):
    emit("* fastest of several runs; all runs (seconds):")
    for k, v in runs.items():
        if len(v) > 1:
            emit("    %-14s %9d %-14s %s" % (k[0], k[1], NAMES.get(k[2], k[2]), " ".join("%.3f" % s for s in v)))

def ok(inp, n, engine):
    r = best.get((inp, n, engine))
    return r if r and r.get("ok") else None

emit("")
emit("Time ratios (< 1 means VolGrid is faster; fastest runs, and with --repeat the median of per-round ratios):")
for inp, n in dict.fromkeys((k[0], k[1]) for k in order):
    for mine in ["volgrid", "volgrid1"]:
        parts = []
        v = ok(inp, n, mine)
        for other in ["tetgen", "cgal", "vtk"]:
            if (inp, n, other) not in best or (inp, n, mine) not in best:
                continue
            o = ok(inp, n, other)
            label = "%s/%s" % (NAMES[mine], NAMES[other])
            txt = "%.3f" % (v["seconds"] / o["seconds"]) if v and o and o["seconds"] > 0 else "n/a"
            pm = paired_median((inp, n, mine), (inp, n, other))
            if pm is not None:
                txt += " (median %.3f)" % pm
            parts.append("%s %s" % (label, txt))
        if parts:
            emit("  %-14s %9d  %s" % (inp, n, "   ".join(parts)))
grid_sizes = sorted({k[1] for k in order if k[0] == "grid"} & {k[1] for k in order if k[0] == "jittered-grid"})
if grid_sizes:
    emit("Grid / jittered-grid time ratio per engine (cospherical slowdown):")
    for n in grid_sizes:
        parts = []
        for engine in ENGINES:
            g, j = ok("grid", n, engine), ok("jittered-grid", n, engine)
            if ("grid", n, engine) in best or ("jittered-grid", n, engine) in best:
                parts.append("%s %s" % (NAMES[engine], "%.2f" % (g["seconds"] / j["seconds"]) if g and j and j["seconds"] > 0 else "n/a"))
        emit("  n=%-9d %s" % (n, "   ".join(parts)))

# ---- issue 2, acceptance line 4 (only when the 1M cases were run) ----
N = 1000000
if any(k[1] == N for k in order):
    emit("")
    emit("Acceptance 4 (issue 2), this run (fastest runs):")
    def verdict(cond):
        return "n/a" if cond is None else ("PASS" if cond else "FAIL")
    v, t, c = ok("random", N, "volgrid"), ok("random", N, "tetgen"), ok("random", N, "cgal")
    emit("  1M random: VolGrid <= 0.5 x TetGen time      %s" % verdict(None if not (v and t) else v["seconds"] <= 0.5 * t["seconds"]))
    emit("  1M random: VolGrid <= CGAL sequential time    %s" % verdict(None if not (v and c) else v["seconds"] <= c["seconds"]))
    g, j = ok("grid", N, "volgrid"), ok("jittered-grid", N, "volgrid")
    emit("  grid <= 2 x jittered-grid time (VolGrid)      %s" % verdict(None if not (g and j) else g["seconds"] <= 2 * j["seconds"]))
    emit("  1M random: <= 60 bytes/tet beyond the input   %s" % verdict(None if not v else v["bytes_per_tet_beyond_input"] <= 60))
    v1 = ok("random", N, "volgrid1")
    if v1 and t and c:
        emit("  (one thread: VolGrid/TetGen %.3f, VolGrid/CGAL %.3f, %.1f bytes/tet; TetGen and CGAL are sequential)"
             % (v1["seconds"] / t["seconds"], v1["seconds"] / c["seconds"], v1["bytes_per_tet_beyond_input"]))

failed = [k for k in order if not best[k].get("ok")]
emit("")
emit("%d case(s), %d failed or timed out. JSON lines: %s" % (len(order), len(failed), out_path))
loads = [r["load1_before"] for r in records if isinstance(r.get("load1_before"), (int, float))]
if loads:
    emit("Machine: %d cores, 1-min load average before the runs %.1f..%.1f (a load above 0 on a shared machine"
         " inflates the times)" % (os.cpu_count() or 0, min(loads), max(loads)))

text = "\n".join(lines)
print(text)
if not opt["table_only"]:
    with open(os.path.join(os.path.dirname(os.path.abspath(out_path)), "delaunay.txt"), "w") as f:
        f.write(text + "\n")
PYTHON
