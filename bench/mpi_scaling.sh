#!/usr/bin/env bash
# MPI scaling of a streamed run (issue 19, docs/scale.md): the same scene
# simulated by 1 rank x 2 threads, 2 ranks x 1 thread (the dynamic work
# queue and the static interleave) and 1 rank x 1 thread, each rank under
# /usr/bin/time: wall, CPU (user + sys) and peak RSS per rank, rank 0's
# passes, and a byte comparison of every product with the first run's.
#
#   bench/mpi_scaling.sh [BUILD_DIR] [SIZE] [scene|acquisition]
#                                  (defaults: build, 6000, scene)
#
# scene: SIZE x SIZE cells of 5 m of seeded noise terrain (2 km relief,
# five land-cover patches); the radar: the figure-4-5 SLAR with its sweep
# stretched over the scene (docs/performance.md, "Streaming").
# acquisition: a run on an acquisition's grid (ris/sim/acquisition_stream.h):
# the shipped airborne example (data/acquisitions/airborne-l-band-flight-
# line.toml) with SIZE lines of 5.9 m and 4,000 range bins of 1.5 m, its
# whole grid over the Winnipeg DEM of the tests; BLOCK_LINES=N in the
# environment sets --block-lines. The machine may be shared: compare CPU
# times, and wall times only when the load average printed before each run
# is below ~0.5.
set -euo pipefail
build=${1:-build}
size=${2:-6000}
mode=${3:-scene}
ris=$(realpath "$build/ris")
root=$(realpath "$(dirname "$0")/..")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
# OpenMPI's shared-memory single copy (CMA) is left on: with copy-in/copy-out
# (OMPI_MCA_btl_vader_single_copy_mechanism=none, needed in some containers)
# the results of pass 1 (tens of MB a block) move far slower (docs/scale.md).
mpirun_flags=(--oversubscribe --bind-to none)
[ "$(id -u)" -eq 0 ] && mpirun_flags+=(--allow-run-as-root)

if [ "$mode" = acquisition ]; then
  sed -e "s/^lines = 500/lines = $size/" -e 's/^range_spacing = "6.25 m"/range_spacing = "1.5 m"/' \
    -e 's/^bins = 600/bins = 4000/' "$root/data/acquisitions/airborne-l-band-flight-line.toml" \
    > acq.toml
  input=(-a acq.toml --dem "$root/tests/data/dem/winnipeg_dem.tif" --full-grid
         ${BLOCK_LINES:+--block-lines "$BLOCK_LINES"})
  cells=$((size * 4000))
  echo "acquisition: ${size} lines x 4000 bins ($cells pixels)${BLOCK_LINES:+, blocks of $BLOCK_LINES lines}"
else
"$ris" scene fractal --generator noise --size "$size" --cell-size 5 --relief 2000 --hurst 0.8 \
  --seed 7 --patches 1,2,3,4,5 --patch-size 3000 -o scene.tif > /dev/null 2>&1
python3 - "$((size * 5))" 2000 "$(dirname "$ris")/../data/radars/seed-fig4-5.toml" > radar.toml <<'PY'
import math, sys
W = float(sys.argv[1]); relief = float(sys.argv[2]); c = 299792458.0
H = 40000 * 0.3048; near_u = 109900 * 0.3048
near_r = math.hypot(near_u, H - relief) - 50.0
far_r = math.hypot(near_u + W, H) + 50.0
src = open(sys.argv[3]).read()
src = src.replace('sweep_delay = "2.38e-4 s"', 'sweep_delay = "%.6e s"' % (2 * near_r / c))
src = src.replace('sweep_length = "3.93e-5 s"', 'sweep_length = "%.6e s"' % (2 * (far_r - near_r) / c))
print(src)
PY
[ -s radar.toml ] || { echo "no radar (data/radars/seed-fig4-5.toml beside the build?)" >&2; exit 1; }
echo "scene: ${size} x ${size} cells ($((size * size)) cells), $(du -h scene.tif | cut -f1)"
input=(--scene scene.tif --radar radar.toml)
cells=$((size * size))
fi

# run NAME RANKS THREADS [SCHEDULE]
run() {
  local name=$1 ranks=$2 threads=$3 schedule=${4:-dynamic}
  local cmd=("$ris" simulate --quiet --threads "$threads" --stream "${input[@]}" --out "out-$name")
  echo
  echo "== $name: $ranks rank(s) x $threads thread(s)${4:+, $schedule}; load $(cut -d' ' -f1-3 /proc/loadavg)"
  if [ "$ranks" -eq 0 ]; then  # no mpirun
    /usr/bin/time -f "%e %U %S %M" -o "time-$name.0" "${cmd[@]}" > "log-$name"
  else
    RIS_MPI_SCHEDULE=$schedule mpirun "${mpirun_flags[@]}" -np "$ranks" \
      sh -c 'exec /usr/bin/time -f "%e %U %S %M" -o "$0.$OMPI_COMM_WORLD_RANK" "$@"' \
      "time-$name" "${cmd[@]}" > "log-$name"
  fi
  grep -E '^  [0-9.]+ s ' "log-$name" | sed 's/^/  rank 0: /'
  local cpu=0
  for f in time-"$name".*; do
    read -r wall user sys rss < "$f"
    printf '  rank %s: wall %6.2f s, CPU %6.2f s (user %.2f + sys %.2f), peak RSS %4d MiB\n' \
      "${f##*.}" "$wall" "$(echo "$user + $sys" | bc)" "$user" "$sys" "$((rss / 1024))"
    cpu=$(echo "$cpu + $user + $sys" | bc)
  done
  printf '  all ranks: CPU %.2f s, %.1f ns per cell\n' "$cpu" \
    "$(echo "$cpu * 1000000000 / $cells" | bc -l)"
  # The same bytes as the single-threaded single process (metadata.json
  # records the thread count, so the reference has the same).
  if [ "$name" != "1x1" ] && [ "$threads" -eq 1 ]; then
    for f in out-1x1/*; do cmp -s "$f" "out-$name/$(basename "$f")" || echo "  DIFFERS: $(basename "$f")"; done
  fi
}

run 1x1 0 1
run 1x2 0 2
run 2x1-dynamic 2 1 dynamic
run 2x1-interleaved 2 1 interleaved
