#!/usr/bin/env bash
# Installs every Debian package ris needs to build, test and benchmark.
# Idempotent: packages already present are skipped. Works as root or via sudo.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libgdal-dev gdal-bin
  # The HDF5 C library: the tests damage copies of NISAR products (tests/hdf5_edit.h)
  libhdf5-dev
  # PROJ's grids: EGM96 geoid heights to ellipsoidal heights (ris topo, docs/geometry.md)
  proj-data
  libcli11-dev libtomlplusplus-dev nlohmann-json3-dev
  libfmt-dev libspdlog-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libcairo2-dev fonts-dejavu-core
  libkissfft-dev
  # Boost.Math's Gauss-Legendre rules (header-only): the I2EM's HV integral
  libboost-dev
  # Eigen (header-only): the Hermitian eigen-decomposition of the polarimetric
  # decompositions (ris polsar, docs/polarimetry.md)
  libeigen3-dev
  # Orfeo ToolBox's applications: the independent H/A/alpha that
  # tests/polsar_cli_test.cpp compares ris polsar with (skipped without it)
  otb-bin
  # Random123 (header-only): the reference Philox the tests compare ris's with
  librandom123-dev
  # The libFuzzer harnesses (make fuzz, fuzz/): clang and its libFuzzer
  clang libfuzzer-14-dev
  clang-format ccache python3 hyperfine
  # ris serve's HTTP server (docs/serve.md), and libpng for its in-memory pictures
  libcpp-httplib-dev libpng-dev
  # ris serve's end-to-end test in a headless browser (tests/serve/serve_browser.py)
  chromium chromium-driver python3-selenium
  # ris serve's map and charts (docs/serve.md), served from /usr/share/javascript
  # (optional at run time: the page degrades to plain images without them)
  libjs-leaflet libjs-chart.js
  # The Python module (import ris, docs/python.md) and its tests
  pybind11-dev python3-dev python3-numpy python3-pytest python3-gdal
  # MPI (Debian's OpenMPI): mpirun -np N ris simulate ... --stream (docs/scale.md)
  libopenmpi-dev openmpi-bin
  # The Python module's to_xarray() (optional at run time; its tests run when it imports)
  python3-xarray
  # Cultural objects (issue 32, src/objects/, docs/objects.md): Embree 3's BVH for
  # the shooting-and-bouncing-rays tracer, and Assimp to read OBJ/PLY/STL/glTF meshes
  libembree-dev libassimp-dev
  # OpenCV (core, imgproc, ml): ris scene classify's segmentation and k-means
  # (issue 34, src/image/classify/, docs/classify.md)
  libopencv-dev
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "ris: all build dependencies are installed"
  exit 0
fi

echo "ris: installing ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
  sudo_cmd=()
elif command -v sudo >/dev/null 2>&1; then
  sudo_cmd=(sudo)
else
  echo "ris: need root or sudo to install: ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
