#!/usr/bin/env bash
# Hashes of every product's decoded pixels and of the text products for a
# fixed set of `ris simulate` runs: the proof that a refactoring moved no
# output value. Rasters (GeoTIFF, PNG) are decoded by GDAL to raw pixels
# (gdal_translate -of ENVI) and hashed, so compression settings do not count;
# metadata.json is hashed without its timing and version keys.
#
# Usage: scripts/product_hashes.sh RIS_BINARY WORK_DIR > hashes.txt
# Compare two runs with diff (e.g. the binary before and after a change).
set -euo pipefail
ris=$(realpath "$1")
work=$2
here="$(cd "$(dirname "$0")/.." && pwd)"
data="$here/data"
dem="$here/tests/data/dem"
rm -rf "$work"
mkdir -p "$work"
cd "$work"

# Inputs: the standard scene as a raster, radars with other headings, an
# imported DEM and a radar for it (as tests/terrain_cli_test.cpp).
"$ris" scene build -o scene.tif > /dev/null
for h in 30 90; do
  sed "s/^heading = \"0 deg\"/heading = \"$h deg\"/" "$data/radars/seed-fig4-5.toml" > "fig45-h$h.toml"
done
cat > dem-radar.toml << 'EOF'
name = "t"
mode = "slar"
frequency = "9.4 GHz"
polarisation = "HH"
pulse_width = "0.2 us"
near_range = "10000 m"
far_range = "14000 m"
azimuth_beamwidth = "0.2 deg"
[track]
altitude = "3000 m"
start_latlon = [34.13, -118.55]
end_latlon = [34.22, -118.55]
EOF
"$ris" scene import "$dem/SanAnd_dem.tif" --category grass -o dem.tif > /dev/null

run() {  # name, then the simulate arguments
  local name=$1
  shift
  "$ris" simulate --quiet --out "$name" "$@" > "$name.log" 2>&1 || {
    echo "run $name failed:" >&2
    cat "$name.log" >&2
    exit 1
  }
}
run default --threads 2
run default-t1 --threads 1
run sar-coherent --threads 2 --radar "$data/radars/sar-x-band-stripmap.toml" \
  --targets "$data/targets/corner-reflectors.toml"
sed 's/^coherent = true/coherent = false/' "$data/radars/sar-x-band-stripmap.toml" > sar-inc.toml
run sar-incoherent-notargets --threads 2 --radar sar-inc.toml
run sar-incoherent-targets --threads 2 --radar sar-inc.toml \
  --targets "$data/targets/corner-reflectors.toml"
run ppi --threads 2 --radar "$data/radars/ppi-ground-mast-30m.toml"
run ppi-t1 --threads 1 --radar "$data/radars/ppi-ground-mast-30m.toml"
run ppi-air --threads 2 --radar "$data/radars/ppi-airborne-nav-10000ft.toml"
run dem --threads 2 --scene dem.tif --radar dem-radar.toml \
  --backscatter "$data/backscatter/generic-terrain.toml"
run oblique30 --threads 2 --radar fig45-h30.toml
run oblique30-t1 --threads 1 --radar fig45-h30.toml
run heading90 --threads 2 --radar fig45-h90.toml
run heading90-t1 --threads 1 --radar fig45-h90.toml
run raster --threads 2 --scene scene.tif
run stream7 --threads 2 --scene scene.tif --stream --block-lines 7
run stream64 --threads 1 --scene scene.tif --stream --block-lines 64
run stream64-h90 --threads 2 --scene scene.tif --stream --block-lines 64 --radar fig45-h90.toml
# Runs that keep the per-sample geometry or add point targets (the line
# engine's kept-geometry sink): SLAR with targets along both axes and off
# them, the coherent SAR off the axes, lines finer and coarser than the
# cells (not one per cell row), the study (SlarOptions::keep_geometry), and
# PPI with targets (the polar source).
targets="$data/targets/corner-reflectors.toml"
run slar-targets --threads 2 --targets "$targets"
run slar-targets-h30 --threads 2 --radar fig45-h30.toml --targets "$targets"
run slar-targets-h90 --threads 2 --radar fig45-h90.toml --targets "$targets"
run slar-targets-h90-t1 --threads 1 --radar fig45-h90.toml --targets "$targets"
sed "s/^heading = \"0 deg\"/heading = \"30 deg\"/" "$data/radars/sar-x-band-stripmap.toml" \
  > sar-h30.toml
run sar-coherent-h30 --threads 2 --radar sar-h30.toml --targets "$targets"
run sar-coherent-h30-t1 --threads 1 --radar sar-h30.toml --targets "$targets"
sed 's/^\[track\]/azimuth_line_spacing = "2.5 m"\n[track]/' "$data/radars/seed-fig4-5.toml" \
  > fig45-fine.toml
run slar-fine-lines --threads 2 --radar fig45-fine.toml --targets "$targets"
sed 's/^\[sar\]/azimuth_line_spacing = "9 m"\n[sar]/' sar-inc.toml > sar-coarse.toml
run sar-coarse-lines --threads 2 --radar sar-coarse.toml
run ppi-targets --threads 2 --radar "$data/radars/ppi-ground-mast-30m.toml" --targets "$targets"
run ppi-air-targets --threads 1 --radar "$data/radars/ppi-airborne-nav-10000ft.toml" \
  --targets "$targets"
# Streamed runs of every mode the stream runs (scene windows, rays in blocks,
# an acquisition's lines in blocks), with targets and off the axes.
run stream16-targets --threads 2 --scene scene.tif --block-lines 16 --targets "$targets"
run stream16-h30 --threads 2 --scene scene.tif --block-lines 16 --radar fig45-h30.toml
run stream16-sar-coherent --threads 2 --scene scene.tif --block-lines 16 \
  --radar "$data/radars/sar-x-band-stripmap.toml" --targets "$targets"
run ppi-stream64 --threads 2 --scene scene.tif --block-lines 64 \
  --radar "$data/radars/ppi-ground-mast-30m.toml"
run ppi-stream64-targets --threads 1 --scene scene.tif --block-lines 64 \
  --radar "$data/radars/ppi-ground-mast-30m.toml" --targets "$targets"
acq=(--acquisition "$here/tests/data/real/winnipeg.h5" --dem "$dem/winnipeg_dem.tif")
run acquisition --threads 2 "${acq[@]}"
run acquisition-stream7 --threads 2 "${acq[@]}" --block-lines 7
# Under MPI (when the binary has it and mpirun is there): 1, 2 and 3 ranks.
if command -v mpirun > /dev/null && ldd "$ris" | grep libmpi > /dev/null; then
  for np in 1 2 3; do
    name=mpi$np
    OMPI_MCA_btl_vader_single_copy_mechanism=none \
      mpirun --allow-run-as-root --oversubscribe -np $np "$ris" simulate --quiet --threads 1 \
      --scene scene.tif --block-lines 16 --out "$name" > "$name.log" 2>&1 || {
      echo "run $name failed:" >&2
      cat "$name.log" >&2
      exit 1
    }
  done
fi
"$ris" study --out study --bands "8.6 GHz:HH, 1.25 GHz:VV" --threads 2 > study.log 2>&1 || {
  echo "run study failed:" >&2
  cat study.log >&2
  exit 1
}

for d in */; do
  d=${d%/}
  for f in $(cd "$d" && find . -type f | sort); do
    f=${f#./}
    case "$f" in
      *.tif | *.png)
        gdal_translate -q -of ENVI -mask none "$d/$f" decoded.raw > /dev/null
        echo "$d/$f $(md5sum < decoded.raw | cut -c1-32)"
        rm -f decoded.raw decoded.hdr decoded.raw.aux.xml
        ;;
      metadata.json)
        echo "$d/$f $(grep -v -E '"(version|seconds|elapsed|time|wall)[a-z_]*"' "$d/$f" | md5sum | cut -c1-32)"
        ;;
      *) echo "$d/$f $(md5sum < "$d/$f" | cut -c1-32)" ;;
    esac
  done
done
