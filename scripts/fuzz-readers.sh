#!/usr/bin/env bash
# Runs the libFuzzer reader targets (built by `make build` when clang is installed: build/fuzz/fuzz_*) for a
# longer time than ctest does, niced, and merges what they find into the kept corpus Testing/Data/fuzz/<reader>/
# (-merge=1 keeps only inputs that add coverage). Prints executions and coverage per reader.
#   scripts/fuzz-readers.sh [SECONDS_PER_READER=600] [READER...]     readers: stl obj off ply mesh poly msh stl_gz
set -uo pipefail
seconds="${1:-600}"
shift || true
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
readers=("$@")
[ "${#readers[@]}" -gt 0 ] || readers=(stl obj off ply mesh poly msh stl_gz)
status=0
for r in "${readers[@]}"; do
  fuzzer="$build/fuzz/fuzz_$r"
  kept="$root/Testing/Data/fuzz/$r"
  [ -x "$fuzzer" ] || { echo "$r: $fuzzer is not built (install clang, then make build)"; status=1; continue; }
  work=$(mktemp -d)
  mkdir -p "$work/corpus" "$work/artifacts" "$kept"
  nice "$fuzzer" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$work/artifacts/" "$work/corpus" "$kept" > "$work/log" 2>&1
  rc=$?
  execs=$(grep -m1 "stat::number_of_executed_units" "$work/log" | awk '{print $2}')
  cov=$(grep -E "^#[0-9]+.*cov:" "$work/log" | tail -1 | sed -E 's/.*cov: ([0-9]+) ft: ([0-9]+).*/cov \1 ft \2/')
  findings=$(ls "$work/artifacts" 2>/dev/null | wc -l)
  echo "$r: exit $rc, ${execs:-?} executions in $seconds s, ${cov:-no coverage line}, findings $findings"
  if [ "$findings" -gt 0 ]; then
    status=1
    mkdir -p "$root/build/fuzz-findings/$r" && cp "$work/artifacts/"* "$root/build/fuzz-findings/$r/"
    grep -m5 -E "ERROR|SUMMARY" "$work/log"
  fi
  "$fuzzer" -merge=1 "$kept" "$work/corpus" > /dev/null 2>&1 || true
  rm -rf "$work"
done
exit $status
