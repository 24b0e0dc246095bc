#!/usr/bin/env bash
# The main job on the built-in default scene (run by `make demo`).
set -euo pipefail
build_dir=${1:-build}
ris="$build_dir/ris"
out=out
data="$(cd "$(dirname "$0")/../data" && pwd)"
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

# The other modes on the same scene (docs/modes.md): a coherent SAR with
# three corner reflectors (their measured impulse responses are printed and
# in $out/sar/metadata.json) and a ground PPI radar on a 30 m mast.
"$ris" simulate --quiet --radar "$data/radars/sar-x-band-stripmap.toml" \
  --targets "$data/targets/corner-reflectors.toml" --out "$out/sar"
"$ris" simulate --quiet --radar "$data/radars/ppi-ground-mast-30m.toml" --out "$out/ppi"

echo "ris: demo outputs are in $(cd "$out" && pwd)"
echo "ris:   SLAR images: $out/slant_range.png, $out/ground_range.png; shadow map: $out/shadowmap.txt"
echo "ris:   SAR: $out/sar/slant_range.png; PPI scope: $out/ppi/ppi_scope.png"
