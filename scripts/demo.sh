#!/usr/bin/env bash
# The main job on the built-in default scene (run by `make demo`).
set -euo pipefail
build_dir=${1:-build}
ris="$build_dir/ris"
out=out
mkdir -p "$out"
"$ris" --version
echo "ris: demo outputs are in $(cd "$out" && pwd)"
