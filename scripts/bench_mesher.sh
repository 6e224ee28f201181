#!/usr/bin/env bash
# make bench, section 3: boundary recovery and exterior removal, VolGrid vs TetGen -pY, on bunny00.off
# (75k triangles) and the sphere-in-sphere far-field domain. TetGen's stage timings come from its -V
# output ("Boundary recovery seconds", "Exterior tets removal seconds"); VolGrid's from its statistics:
# recovery = building the boundary constraints + recovery + boundary Steiner point removal (TetGen reports
# building its subfaces and segments apart, as "Surface mesh seconds", and that is NOT added to its side),
# exterior = exterior removal. Neither side's "Delaunay seconds" is counted.
#   scripts/bench_mesher.sh [BUILD_DIR]
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-build}"
bench="$build/bin/volgrid_bench_mesher"
data="${VOLGRID_SHARED_DATA_DIR:-$root/../shared/data/real}"
work="$build/bench/mesher"
mkdir -p "$work"
echo "=== 3. Boundary-conforming meshing: VolGrid vs TetGen -pY (recovery + exterior removal) ==="
if [ ! -x "$bench" ] || ! command -v tetgen > /dev/null; then
  echo "  needs $bench (make bench builds it) and the tetgen program (scripts/install-deps.sh bench)"
  exit 1
fi
: > "$work/mesher.jsonl"
for case in bunny00 sphere-in-sphere; do
  poly="$work/$case.poly"
  if [ "$case" = "bunny00" ]; then
    args=(--input "$data/tetgen-tests/cgal/bunny00.off" --write-poly "$poly")
  else
    args=(--sphere-in-sphere --write-poly "$poly")
  fi
  /usr/bin/time -f '{"peak_rss_mb_time": %M}' -o "$work/$case.volgrid.time" "$bench" "${args[@]}" \
    >> "$work/mesher.jsonl" || echo "  VolGrid FAILED on $case"
  ( cd "$work" && /usr/bin/time -f '%M' -o "$case.tetgen.time" tetgen -pYV "$case.poly" > "$case.tetgen.log" 2>&1 ) \
    || echo "  TetGen FAILED on $case (see $work/$case.tetgen.log)"
done
python3 - "$work" <<'PYTHON'
import json, os, re, sys
work = sys.argv[1]
rows = {}
for line in open(os.path.join(work, "mesher.jsonl")):
    if line.startswith("{"):
        r = json.loads(line)
        rows["bunny00" if "bunny00" in r["input"] else "sphere-in-sphere"] = r
def tetgen(case):
    log = os.path.join(work, case + ".tetgen.log")
    out = {}
    if not os.path.exists(log):
        return out
    text = open(log).read()
    for key, pattern in [("delaunay", r"^Delaunay seconds:\s+([\d.]+)"),
                         ("recovery", r"^Boundary recovery seconds:\s+([\d.]+)"),
                         ("exterior", r"^Exterior tets removal seconds:\s+([\d.]+)"),
                         ("total", r"^Total running seconds:\s+([\d.]+)")]:
        m = re.search(pattern, text, re.M)
        if m:
            out[key] = float(m.group(1))
    m = re.search(r"Mesh tetrahedra:\s+(\d+)", text)
    if m:
        out["tets"] = int(m.group(1))
    try:
        out["peak_mb"] = int(open(os.path.join(work, case + ".tetgen.time")).read().split()[-1]) / 1024
    except (OSError, ValueError, IndexError):
        pass
    return out
print(f"  {'input':18} {'engine':8} {'tets':>9} {'delaunay s':>10} {'recovery s':>10} {'exterior s':>10} "
      f"{'rec+ext s':>9} {'total s':>8} {'peak MB':>8} {'tets/s':>10}")
for case in ["bunny00", "sphere-in-sphere"]:
    v, t = rows.get(case), tetgen(case)
    if v and v.get("ok"):
        ve = v["seconds_recovery"] + v["seconds_exterior"] + v["seconds_steiner_removal"]
        print(f"  {case:18} {'VolGrid':8} {v['tets']:>9} {v['seconds_delaunay']:>10.3f} "
              f"{v['seconds_recovery'] + v['seconds_steiner_removal']:>10.3f} {v['seconds_exterior']:>10.3f} "
              f"{ve:>9.3f} {v['seconds_total']:>8.3f} {v['peak_rss_mb']:>8.1f} {v['tets'] / v['seconds_total']:>10.0f}")
    else:
        print(f"  {case:18} VolGrid  FAILED {v.get('error') if v else ''}")
    if "recovery" in t:
        te = t["recovery"] + t.get("exterior", 0)
        print(f"  {case:18} {'TetGen':8} {t.get('tets', -1):>9} {t.get('delaunay', 0):>10.3f} {t['recovery']:>10.3f} "
              f"{t.get('exterior', 0):>10.3f} {te:>9.3f} {t.get('total', 0):>8.3f} {t.get('peak_mb', 0):>8.1f} "
              f"{t.get('tets', 0) / max(t.get('total', 1), 1e-9):>10.0f}")
        if v and v.get("ok"):
            print(f"  {case:18} recovery+exterior VolGrid/TetGen = {ve / te:.2f} (acceptance: <= 0.5)")
    else:
        print(f"  {case:18} TetGen   FAILED (see {work}/{case}.tetgen.log)")
PYTHON
