#!/usr/bin/env bash
# Runs the libFuzzer harnesses built by `make fuzz` (fuzz/, docs/testing.md).
#   scripts/fuzz.sh BUILD_DIR SECONDS [HARNESS...]
# Each harness runs SECONDS on BUILD_DIR/corpus/<h> (a working copy seeded
# from fuzz/corpus/<h>, so the repository's corpus changes only when someone
# copies a new input in on purpose), with a 2 GiB RSS limit and a 10 s
# per-input timeout. Findings go to BUILD_DIR/findings/<h>/; the last lines
# of each log (executions, coverage, corpus size) are printed as a summary.
# -max_len=65536: inputs up to 64 KiB, enough for the deep-nesting and
# many-objects seeds to grow (libFuzzer's default stops at the largest seed).
# Exits 1 when any harness reported a finding.
set -uo pipefail
build=${1:?build folder}
seconds=${2:?seconds per harness}
shift 2
src="$(cd "$(dirname "$0")/.." && pwd)"
harnesses=("$@")
if [ ${#harnesses[@]} -eq 0 ]; then
  for d in "$src"/fuzz/corpus/*/; do harnesses+=("$(basename "$d")"); done
fi
status=0
for h in "${harnesses[@]}"; do
  exe="$build/fuzz/${h}_fuzz"
  [ -x "$exe" ] || { echo "fuzz: $exe not built" >&2; exit 2; }
  work="$build/corpus/$h"
  findings="$build/findings/$h"
  mkdir -p "$work" "$findings"
  echo "fuzz: $h for ${seconds}s"
  "$exe" -max_total_time="$seconds" -max_len=65536 -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 \
    -artifact_prefix="$findings/" "$work" "$src/fuzz/corpus/$h" > "$build/$h.log" 2>&1
  rc=$?
  grep -E "^#[0-9]+.*(DONE|pulse)|stat::number_of_executed_units|stat::peak_rss_mb|cov:" \
    "$build/$h.log" | tail -3
  if [ $rc -ne 0 ] || [ -n "$(ls -A "$findings")" ]; then
    echo "fuzz: $h: FINDING (exit $rc): $(ls "$findings")"
    status=1
  fi
done
exit $status
