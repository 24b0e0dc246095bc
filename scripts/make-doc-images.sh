#!/usr/bin/env bash
# Makes every picture in docs/images/ from the command printed beside it in
# README.md and docs/*.md: each command runs into a temporary folder and its
# product becomes the PNG (ris's own PNG outputs as written, or
# gdal_translate where the picture is a reduced or cropped product).
#
#   scripts/make-doc-images.sh BUILD_DIR [--check] [--heavy] [--only A,B] [--out DIR]
#
#   BUILD_DIR  the build folder holding `ris` (e.g. build)
#   --check    a quick subset (the cheap pictures), written into a temporary
#              folder, not docs/images: fails unless every command runs and
#              writes its PNG (ctest: doc_images_check)
#   --heavy    also the 40,000^2-cell stream example (stream-40k-ground-range;
#              about 16 GB of disk in $TMPDIR and several minutes on two
#              cores: not for a shared machine)
#   --only     only these pictures (names without .png)
#   --out DIR  write the PNGs into DIR (default docs/images)
#
# Pictures and where their command is printed (the function of each name
# below runs exactly that command):
#   ku-geometric-preview             README.md, docs/scene-format.md
#   slar-ku-geometric-fig4-5         README.md, docs/outputs.md (ground_range.png, halved)
#   slar-ku-geometric-fig7           docs/outputs.md (the same with seed-fig7.toml)
#   sigma0-ku-geometric-8.6GHz       README.md, docs/backscatter.md
#   study-ku-geometric-fig7          README.md, docs/study.md (contact_sheet.png)
#   fractal-alps-preview             README.md, docs/terrain.md
#   fractal-alps-geocoded            README.md, docs/terrain.md (geocoded_grey.png)
#   sar-ku-geometric-corner-reflectors  README.md (slant_range.png)
#   ppi-ku-geometric-mast-30m        README.md (ppi_scope.png)
#   ppi-ku-geometric-nav-10000ft     README.md (ppi_scope.png)
#   topo-winnipeg-incidence          docs/geometry.md (incidence.png of ris topo)
#   topo-winnipeg-simamp             docs/geometry.md (simamp.png of ris topo)
#   simulate-sanand-mean             docs/geometry.md (slant_range.png, fading off)
#   fading                           docs/greytone.md (four ris greytone panels side by side)
#   compare-ku-geometric-two-seeds   docs/quality.md (sheet.png of ris compare)
#   sensitivity-ku-geometric-cell-factor  docs/quality.md (cell_factor.png)
#   serve-page                       docs/serve.md: not a command's product: a
#                                    screenshot of `ris serve` in the browser
#                                    test's headless Chromium
#                                    (scripts/serve_screenshot.py); skipped
#                                    with a note when Chromium is missing
#   town-sar-x-ground-range          README.md "Buildings and reflectors" (ground_range.png, 600 px)
#   town-quadpol-pauli               README.md, docs/polarimetry.md (polsar/pauli.png, 600 px)
#   town-camera                      README.md, docs/sensors.md (camera_preview.png of ris sensor)
#   stream-40k-ground-range          README.md, docs/performance.md (--heavy only)
# The pic_* functions are called by name ("pic_$name"), which shellcheck cannot see.
# shellcheck disable=SC2317
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
PYTHON=${PYTHON:-/usr/bin/python3}

usage() { sed -n '2,20p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 2; }
[[ $# -ge 1 ]] || usage
BUILD=$(cd "$1" && pwd) || { echo "make-doc-images: no build folder $1" >&2; exit 2; }
shift
RIS=$BUILD/ris
[[ -x $RIS ]] || { echo "make-doc-images: $RIS not found: build the target ris first" >&2; exit 2; }
CHECK=0 HEAVY=0 ONLY="" DEST=$ROOT/docs/images
while [[ $# -gt 0 ]]; do
  case $1 in
    --check) CHECK=1 ;;
    --heavy) HEAVY=1 ;;
    --only) ONLY=${2:?--only needs a list}; shift ;;
    --out) DEST=${2:?--out needs a folder}; shift ;;
    *) echo "make-doc-images: unknown option $1" >&2; usage ;;
  esac
  shift
done

WORK=$(mktemp -d "${TMPDIR:-/tmp}/ris-doc-images.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
if [[ $CHECK == 1 ]]; then DEST=$WORK/images; fi
mkdir -p "$DEST"
DATA=$ROOT/data
TESTDATA=$ROOT/tests/data
cd "$WORK"

run() { "$RIS" "$@" > /dev/null; }  # a command as printed (its report is not needed)
# A product reduced to WIDTH x HEIGHT pixels by block averaging.
shrink() { gdal_translate -q -of PNG -r average -outsize "$3" "$4" "$1" "$2"; rm -f "$2.aux.xml"; }
put() { cp "$1" "$DEST/$2.png"; }

# README.md "A first example"; docs/scene-format.md.
pic_ku-geometric-preview() {
  run scene build "$DATA/scenes/ku-geometric.toml" -o scene.tif
  run scene preview scene.tif -o preview.png
  put preview.png ku-geometric-preview
}

# README.md: `ris simulate --scene ... --radar data/radars/seed-fig4-5.toml --out out`;
# docs/outputs.md: its ground-range picture shrunk by half.
pic_slar-ku-geometric-fig4-5() {
  run simulate --quiet --scene "$DATA/scenes/ku-geometric.toml" \
      --radar "$DATA/radars/seed-fig4-5.toml" --out out
  shrink out/ground_range.png half.png 50% 50%
  put half.png slar-ku-geometric-fig4-5
}

# docs/outputs.md: the same with `--radar data/radars/seed-fig7.toml`.
pic_slar-ku-geometric-fig7() {
  run simulate --quiet --scene "$DATA/scenes/ku-geometric.toml" \
      --radar "$DATA/radars/seed-fig7.toml" --out out-fig7
  shrink out-fig7/ground_range.png half7.png 50% 50%
  put half7.png slar-ku-geometric-fig7
}

# README.md; docs/backscatter.md (the same plot with the defaults spelled out).
pic_sigma0-ku-geometric-8.6GHz() {
  run sigma0 --category all -f "8.6 GHz" -p HH,VV -a 0:80:1 --plot sigma0.png
  put sigma0.png sigma0-ku-geometric-8.6GHz
}

# README.md: `ris study --study data/studies/seed-fig7.toml --panel-size 240`;
# docs/study.md: `ris study --out study --panel-size 240` (the same panels).
pic_study-ku-geometric-fig7() {
  run study --quiet --study "$DATA/studies/seed-fig7.toml" --panel-size 240 --out study-fig7
  put study-fig7/contact_sheet.png study-ku-geometric-fig7
}

alps_scene() {
  [[ -f alps.tif ]] || run scene fractal --size 300 --cell-size 30 --relief 1500 --hurst 0.75 \
      --seed 7 --patches forest,grass,rock --patch-size 1500 --centre 46.5,8.0 -o alps.tif
}

# README.md "Real terrain"; docs/terrain.md "Pictures".
pic_fractal-alps-preview() {
  alps_scene
  run scene preview alps.tif -o alps-preview.png
  put alps-preview.png fractal-alps-preview
}

pic_fractal-alps-geocoded() {
  alps_scene
  run simulate --quiet --scene alps.tif --radar "$DATA/radars/slar-x-band-alps.toml" --out alps-out
  put alps-out/geocoded_grey.png fractal-alps-geocoded
}

# README.md "SAR, PPI and point targets".
pic_sar-ku-geometric-corner-reflectors() {
  run simulate --quiet --radar "$DATA/radars/sar-x-band-stripmap.toml" \
      --targets "$DATA/targets/corner-reflectors.toml" --out out-sar
  put out-sar/slant_range.png sar-ku-geometric-corner-reflectors
}

pic_ppi-ku-geometric-mast-30m() {
  run simulate --quiet --radar "$DATA/radars/ppi-ground-mast-30m.toml" --out out-ppi
  put out-ppi/ppi_scope.png ppi-ku-geometric-mast-30m
}

pic_ppi-ku-geometric-nav-10000ft() {
  run simulate --quiet --radar "$DATA/radars/ppi-airborne-nav-10000ft.toml" --out out-nav
  put out-nav/ppi_scope.png ppi-ku-geometric-nav-10000ft
}

winnipeg_topo() {
  [[ -d winnipeg-topo ]] || run topo -a "$TESTDATA/real/winnipeg.h5" \
      --dem "$TESTDATA/dem/winnipeg_dem.tif" --out winnipeg-topo
}

# docs/geometry.md "Worked example: winnipeg.h5".
pic_topo-winnipeg-incidence() {
  winnipeg_topo
  put winnipeg-topo/incidence.png topo-winnipeg-incidence
}

pic_topo-winnipeg-simamp() {
  winnipeg_topo
  put winnipeg-topo/simamp.png topo-winnipeg-simamp
}

# docs/geometry.md: SanAnd_138.h5 with its DEM, `[film.terms] fading = false`
# in a copy of the radar file.
pic_simulate-sanand-mean() {
  { cat "$DATA/radars/seed-fig4-5.toml"; printf '\n[film.terms]\nfading = false\n'; } > nofade.toml
  run simulate --quiet -a "$TESTDATA/real/SanAnd_138.h5" --dem "$TESTDATA/dem/SanAnd_dem.tif" \
      --radar nofade.toml --out sanand
  put sanand/slant_range.png simulate-sanand-mean
}

# docs/greytone.md "What fading looks like": `ris simulate --out sim --seed 1`,
# then `ris greytone sim/mean_power_slant.tif --radar RADAR.toml --seed 1` with
# four radars; lines 440-699 of each panel, side by side 6 pixels apart.
pic_fading() {
  local base=$DATA/radars/seed-fig4-5.toml
  run simulate --quiet --out sim --seed 1
  { cat "$base"; printf '\n[film.terms]\nfading = false\n'; } > fade-off.toml
  cp "$base" fade-exact.toml
  sed 's/^fading = "exact".*/fading = "seed"/' "$base" > fade-seed.toml
  sed 's/^independent_samples = "seed".*/independent_samples = 10/' "$base" > fade-n10.toml
  grep -q '^fading = "seed"' fade-seed.toml && grep -q '^independent_samples = 10' fade-n10.toml
  local panels=()
  for r in fade-off fade-exact fade-seed fade-n10; do
    run greytone sim/mean_power_slant.tif --radar "$r.toml" --out "$r.png" --seed 1
    panels+=("$r.png")
  done
  "$PYTHON" - fading.png "${panels[@]}" <<'PY'
import sys
import numpy as np
from osgeo import gdal
gap, rows = 6, slice(440, 700)
panels = [gdal.Open(p).ReadAsArray()[rows] for p in sys.argv[2:]]
h, w = panels[0].shape
sheet = np.zeros((h, len(panels) * w + (len(panels) - 1) * gap), np.uint8)
for i, p in enumerate(panels):
    sheet[:, i * (w + gap):i * (w + gap) + w] = p
mem = gdal.GetDriverByName("MEM").Create("", sheet.shape[1], sheet.shape[0], 1, gdal.GDT_Byte)
mem.GetRasterBand(1).WriteArray(sheet)
gdal.GetDriverByName("PNG").CreateCopy(sys.argv[1], mem)
PY
  rm -f fading.png.aux.xml
  put fading.png fading
}

# docs/quality.md "Examples": two seeds of the default simulation compared.
pic_compare-ku-geometric-two-seeds() {
  run simulate --quiet --out a
  run simulate --quiet --seed 9 --out b
  run compare a/geocoded_power.tif b/geocoded_power.tif \
      --local-incidence a/local_incidence_deg.tif --out cmp
  put cmp/sheet.png compare-ku-geometric-two-seeds
}

# docs/quality.md "Example" of ris sensitivity.
pic_sensitivity-ku-geometric-cell-factor() {
  run sensitivity --vary cell_factor=1,2,4,8 --vary mislabel=0,0.05,0.2 \
      --vary frequency="1.25 GHz,5.3 GHz,8.6 GHz" --out sens
  put sens/cell_factor.png sensitivity-ku-geometric-cell-factor
}

# docs/serve.md: a screenshot, not a command's product.
pic_serve-page() {
  local rc=0
  "$PYTHON" "$ROOT/scripts/serve_screenshot.py" "$RIS" serve-page.png || rc=$?
  if [[ $rc == 77 ]]; then
    echo "make-doc-images: serve-page skipped (no headless Chromium; docs/serve.md)" >&2
    return 0
  fi
  [[ $rc == 0 ]] || return "$rc"
  put serve-page.png serve-page
}

# README.md "Buildings and reflectors": the example town (docs/objects.md).
pic_town-sar-x-ground-range() {
  run simulate --quiet --scene "$DATA/scenes/town.toml" \
      --radar "$DATA/radars/sar-x-band-town.toml" --out out-town
  shrink out-town/ground_range.png town.png 600 0
  put town.png town-sar-x-ground-range
}

# README.md "SAR, PPI and point targets", docs/polarimetry.md: the town's
# quad-pol Pauli picture (slant range, near range left).
pic_town-quadpol-pauli() {
  run simulate --quiet --scene "$DATA/scenes/town.toml" \
      --radar "$DATA/radars/sar-x-band-town-quadpol.toml" --out out-town-qp
  shrink out-town-qp/polsar/pauli.png pauli.png 600 0
  put pauli.png town-quadpol-pauli
}

# README.md "Optical and thermal images", docs/sensors.md: the town through
# an oblique frame camera.
pic_town-camera() {
  run sensor optical "$DATA/scenes/town.toml" --table "$DATA/sensors_eo/town-eo.csv" \
      --sensor "$DATA/sensors_eo/optical-camera-town.toml" -o out-town-camera
  put out-town-camera/camera_preview.png town-camera
}

# README.md "Large scenes"; docs/performance.md. --heavy only.
pic_stream-40k-ground-range() {
  run scene fractal --generator noise --size 40000 --cell-size 5 --relief 2000 \
      --patches 1,2,3,4,5 --patch-size 3000 -o big.tif
  run simulate --scene big.tif --radar "$DATA/radars/seed-fig4-5-200km.toml" --out big-out
  shrink big-out/ground_range.tif big.png 600 0
  put big.png stream-40k-ground-range
}

ALL=(ku-geometric-preview slar-ku-geometric-fig4-5 slar-ku-geometric-fig7
     sigma0-ku-geometric-8.6GHz study-ku-geometric-fig7 fractal-alps-preview
     fractal-alps-geocoded sar-ku-geometric-corner-reflectors ppi-ku-geometric-mast-30m
     ppi-ku-geometric-nav-10000ft topo-winnipeg-incidence topo-winnipeg-simamp
     simulate-sanand-mean fading compare-ku-geometric-two-seeds
     sensitivity-ku-geometric-cell-factor town-sar-x-ground-range town-quadpol-pauli
     town-camera serve-page)
# --check: a few seconds of the cheapest commands, one of each kind of
# conversion (ris's PNG, halved by gdal_translate, composed in Python).
QUICK=(ku-geometric-preview sigma0-ku-geometric-8.6GHz fractal-alps-preview
       fractal-alps-geocoded topo-winnipeg-incidence slar-ku-geometric-fig4-5)

if [[ -n $ONLY ]]; then
  IFS=, read -r -a NAMES <<< "$ONLY"
elif [[ $CHECK == 1 ]]; then
  NAMES=("${QUICK[@]}")
else
  NAMES=("${ALL[@]}")
  [[ $HEAVY == 1 ]] && NAMES+=(stream-40k-ground-range)
fi

for name in "${NAMES[@]}"; do
  if ! declare -F "pic_$name" > /dev/null; then
    echo "make-doc-images: no picture $name (names: ${ALL[*]} stream-40k-ground-range)" >&2
    exit 2
  fi
  if [[ $name == stream-40k-ground-range && $HEAVY != 1 ]]; then
    echo "make-doc-images: $name needs --heavy (16 GB of disk, minutes of two cores)" >&2
    exit 2
  fi
  start=$SECONDS
  "pic_$name"
  if [[ $name != serve-page || -f $DEST/$name.png ]]; then
    # A PNG, not an empty or partial file.
    [[ $(head -c 8 "$DEST/$name.png" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] || {
      echo "make-doc-images: $DEST/$name.png is not a PNG" >&2
      exit 1
    }
  fi
  echo "$name.png ($((SECONDS - start)) s)"
done
[[ $CHECK == 1 ]] && echo "make-doc-images: check ok (${#NAMES[@]} pictures made)"
exit 0
