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

# The seed's figure-4-5 SLAR simulation of the standard scene (docs/outputs.md):
# greytone images in slant and ground range, power and mask GeoTIFFs, the
# seed's shadow map and metadata.json, all in $out.
"$ris" simulate --out "$out"

echo "ris: demo outputs are in $(cd "$out" && pwd)"
echo "ris:   SLAR images: $out/slant_range.png, $out/ground_range.png; shadow map: $out/shadowmap.txt"
