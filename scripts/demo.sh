#!/usr/bin/env bash
# The main job on the built-in default scene (run by `make demo`).
set -euo pipefail
build_dir=${1:-build}
ris="$build_dir/ris"
out=out
mkdir -p "$out"
"$ris" --version

# The standard scene (data/scenes/ku-geometric.toml) and its picture.
"$ris" scene build -o "$out/ku-geometric.tif"
"$ris" scene preview -o "$out/ku-geometric-preview.png"
"$ris" scene info "$out/ku-geometric.tif"

echo "ris: demo outputs are in $(cd "$out" && pwd)"
