#!/usr/bin/env bash
# Regenerates the shipped sigma0 tables from the category libraries, so that
# where every number comes from is one command (docs/backscatter.md).
#   scripts/make-backscatter-tables.sh [build-dir]
set -euo pipefail
build_dir=${1:-build}
ris="$build_dir/ris"
here=$(cd "$(dirname "$0")/.." && pwd)
out="$here/data/backscatter/ku-geometric-8.6GHz.csv"
tmp="$out.tmp"
{
  echo "# The standard scene's ten categories at 8.6 GHz, HH and VV, 0-90 deg at 1 deg"
  echo "# (the seed's sampling). Generated, not measured: every value is the"
  echo "# category's model in data/backscatter/ku-geometric.toml, evaluated by"
  echo "#   ris sigma0 --library data/backscatter/ku-geometric.toml --category all \\"
  echo "#     --frequency \"8.6 GHz\" --pol HH,VV --angles 0:90:1 --format csv"
  echo "# (scripts/make-backscatter-tables.sh). The models and their sources are"
  echo "# listed below and in the library file."
  RIS_DATA="$here/data" "$ris" sigma0 --library "$here/data/backscatter/ku-geometric.toml" \
    --category all --frequency "8.6 GHz" --pol HH,VV --angles 0:90:1 --format csv |
    sed "s|$here/||g"
} > "$tmp"
mv "$tmp" "$out"
echo "wrote $out"
