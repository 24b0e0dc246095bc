"""Shared fixtures of the Python API tests (run by ctest: python_tests)."""

import os
import pathlib
import subprocess

import numpy as np
import pytest
from osgeo import gdal

import ris

SOURCE_DIR = pathlib.Path(os.environ.get("RIS_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
RIS_EXE = os.environ.get("RIS_EXE", str(SOURCE_DIR / "build" / "ris"))
DATA = SOURCE_DIR / "data"
STANDARD_SCENE = DATA / "scenes" / "ku-geometric.toml"
STANDARD_RADAR = DATA / "radars" / "seed-fig4-5.toml"

# tests/test_inputs.h's kSmallSlarRadar: 9.4 GHz HH, 15 m bins, 5 mrad beam,
# track 3000 m up and 4000 m west of the scene, heading north.
SMALL_RADAR = {
    "mode": "slar",
    "frequency": "9.4 GHz",
    "polarisation": "HH",
    "pulse_width": "0.1 us",
    "sweep_delay": "33.4 us",
    "sweep_length": "10 us",
    "azimuth_beamwidth": "5 mrad",
    "track": {"altitude": "3000 m", "near_edge_distance": "4000 m"},
}


gdal.UseExceptions()


def read_raster(path, band=1):
    """A raster's band as numpy (GDAL)."""
    ds = gdal.Open(str(path))  # kept while the band is read (the band does not own it)
    return ds.GetRasterBand(band).ReadAsArray()


def same_array(a, b):
    """Equal values, NaN where the other has NaN, same shape."""
    return a.shape == b.shape and np.array_equal(a, b, equal_nan=a.dtype.kind == "f")


def metadata_without_timing(meta):
    """metadata.json without what differs between two runs of the same input
    (wall-clock times)."""
    def strip(x):
        if isinstance(x, dict):
            return {k: strip(v) for k, v in x.items() if "seconds" not in k and "time" not in k}
        if isinstance(x, list):
            return [strip(v) for v in x]
        return x
    return strip(meta)


def run_cli(*args):
    """Runs the ris command line; returns the completed process."""
    return subprocess.run([RIS_EXE, *map(str, args)], capture_output=True, text=True, check=True)


def small_scene(rows=40, cols=200, cell_m=10.0):
    """A flat scene with a 120 m block (slar_simulation_test.cpp's small_scene)."""
    elev = np.zeros((rows, cols), dtype=np.float32)
    elev[10:30, 80:100] = 120.0
    cat = np.ones((rows, cols), dtype=np.uint16)
    return ris.Scene.from_arrays(elev, cat, cell_m)


@pytest.fixture(scope="session")
def small_radar():
    return ris.Radar.from_dict(SMALL_RADAR)
