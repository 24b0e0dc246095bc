"""ris.quality and ris.compare: the numbers of `ris quality --json` and
`ris compare --json` (tests/quality_cli_test.cpp's, compare_cli_test.cpp's inputs)."""

import json

import numpy as np
import pytest
from osgeo import gdal

import ris
from conftest import read_raster, run_cli


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    d = tmp_path_factory.mktemp("quality")
    run_cli("simulate", "--quiet", "--out", d / "a")
    run_cli("simulate", "--quiet", "--seed", "5", "--out", d / "b")
    run_cli("scene", "build", "-o", d / "scene.tif")
    return d


def cli_json(*args):
    return json.loads(run_cli(*args).stdout)


def test_quality_is_the_command_lines(runs):
    a = runs / "a"
    cli = cli_json("quality", "--json", a / "geocoded_power.tif", "--categories",
                   runs / "scene.tif", "--categories-band", "2")
    cats = read_raster(runs / "scene.tif", band=2)
    py = ris.quality(read_raster(a / "geocoded_power.tif"), categories=cats)
    del cli["image"]
    assert py == cli
    assert len(py["pairs"]) == 45

    cli = cli_json("quality", "--json", a / "speckled_power_slant.tif", "--mask",
                   a / "mask_slant.tif", "--target", "10,10", "--regions", "0,0,20,20",
                   "--window", "8")
    del cli["image"]
    # The pixel sizes `ris quality` takes from the image's metadata.
    meta = gdal.Open(str(a / "speckled_power_slant.tif")).GetMetadata()
    py = ris.quality(read_raster(a / "speckled_power_slant.tif"),
                     mask=read_raster(a / "mask_slant.tif"), targets=[(10, 10)],
                     regions=[(0, 0, 20, 20)], window=8,
                     line_spacing_m=float(meta["RIS_LINE_SPACING_M"]),
                     range_bin_m=float(meta["RIS_RANGE_BIN_M"]))
    assert py == cli
    assert py["edges"]["edges"] > 100


def test_compare_is_the_command_lines(runs):
    a, b = runs / "a", runs / "b"
    cli = cli_json("compare", "--json", a / "geocoded_power.tif", b / "geocoded_power.tif",
                   "--local-incidence", a / "local_incidence_deg.tif", "--categories",
                   runs / "scene.tif", "--categories-band", "2")
    for key in ("simulated", "real"):
        del cli[key]
    py = ris.compare(read_raster(a / "geocoded_power.tif"), read_raster(b / "geocoded_power.tif"),
                     local_incidence_deg=read_raster(a / "local_incidence_deg.tif"),
                     categories=read_raster(runs / "scene.tif", band=2))
    assert py == cli
    assert abs(py["registration"]["shift_x_px"]) < 0.2

    cli = cli_json("compare", "--json", a / "mean_power_slant.tif", b / "mean_power_slant.tif",
                   "--mask", a / "mask_slant.tif", "--no-register")
    for key in ("simulated", "real"):
        del cli[key]
    real = read_raster(b / "mean_power_slant.tif")
    py, aligned = ris.compare(read_raster(a / "mean_power_slant.tif"), real, register=False,
                              mask=read_raster(a / "mask_slant.tif"), return_aligned=True)
    assert py == cli
    assert "registration" not in py
    assert np.array_equal(aligned, real.astype(np.float32), equal_nan=True)


def test_bad_input_names_the_key():
    power = np.ones((20, 30), dtype=np.float32)
    with pytest.raises(ris.InputError) as e:
        ris.quality(power, mask=np.zeros((20, 29)))
    assert e.value.key == "mask"
    with pytest.raises(ris.InputError) as e:
        ris.quality(power, window=3)
    assert e.value.key == "window"
    with pytest.raises(ris.InputError) as e:
        ris.quality(power, targets=[(20, 0)])
    assert e.value.key == "target"
    with pytest.raises(ris.InputError) as e:
        ris.compare(power, np.ones((20, 31)))
    assert e.value.key == "real"
    with pytest.raises(ris.InputError) as e:
        ris.compare(power, power, max_shift_px=0)
    assert e.value.key == "max_shift"
