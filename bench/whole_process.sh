#!/usr/bin/env bash
# Whole-process time of `ris --version` and of the default `ris simulate`
# (the standard scene, built on the fly, the seed's figure-4-5 radar, every
# product written), as a user sees it: process start-up (dynamic loading),
# reading inputs, simulation, writing products.
#
#   bench/whole_process.sh [BUILD_DIR] [RUNS]     (defaults: build, 20)
#
# Uses hyperfine (Debian package `hyperfine`) when installed, else a loop
# with /usr/bin/time -f (wall, user, system seconds per run). Run it on a
# quiet machine (uptime load below ~0.5); the figures in docs/performance.md
# ("Whole process") came from it.
set -euo pipefail
build=${1:-build}
runs=${2:-20}
ris=$(realpath "$build/ris")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

echo "load: $(cut -d' ' -f1-3 /proc/loadavg)"
if command -v hyperfine >/dev/null 2>&1; then
  hyperfine --warmup 2 --runs "$runs" -N \
    "$ris --version" \
    "$ris simulate --quiet --out $work/out" \
    "$ris simulate --quiet --compress none --out $work/out" \
    "$ris simulate --quiet --products slant_range --out $work/out"
else
  for cmd in "--version" "simulate --quiet --out $work/out" \
             "simulate --quiet --compress none --out $work/out" \
             "simulate --quiet --products slant_range --out $work/out"; do
    # shellcheck disable=SC2086
    for _ in 1 2; do "$ris" $cmd >/dev/null; done  # warm-up
    for _ in $(seq "$runs"); do
      # shellcheck disable=SC2086
      /usr/bin/time -f "%e %U %S" "$ris" $cmd 2>&1 >/dev/null | tail -1
    done | sort -n | awk -v c="ris $cmd" '{w[NR]=$1; u+=$2; s+=$3}
      END {printf "%-60s median %.3f s wall, mean %.3f s user + %.3f s sys (%d runs)\n",
           c, w[int((NR+1)/2)], u/NR, s/NR, NR}'
  done
fi
