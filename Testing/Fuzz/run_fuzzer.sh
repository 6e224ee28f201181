#!/usr/bin/env bash
# Runs one reader fuzzer for a bounded time from its kept corpus (read-only: new inputs go to a scratch
# directory, so a test run never modifies the source tree). Fails on any crash, sanitizer report or leak.
#   run_fuzzer.sh FUZZER CORPUS_DIR SECONDS
set -euo pipefail
fuzzer="$1" corpus="$2" seconds="$3"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$scratch/new" "$scratch/artifacts"
[ -d "$corpus" ] || { echo "no kept corpus at $corpus: starting empty"; corpus="$scratch/empty"; mkdir -p "$corpus"; }
nice "$fuzzer" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$scratch/artifacts/" "$scratch/new" "$corpus" 2>&1 | tail -25
status=${PIPESTATUS[0]}
if ls "$scratch/artifacts/"* >/dev/null 2>&1; then
  echo "findings:"; ls -l "$scratch/artifacts/"
  exit 1
fi
exit "$status"
