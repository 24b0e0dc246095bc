"""An imported DEM simulates in Python as `ris scene import` + `ris simulate`."""

import json
import os

import numpy as np
import pytest
from osgeo import gdal

import ris
from conftest import DATA, SOURCE_DIR, metadata_without_timing, read_raster, run_cli


DEM = SOURCE_DIR / "tests" / "data" / "dem" / "SanAnd_dem.tif"  # geographic: reprojected to UTM
RADAR = SOURCE_DIR / "tests" / "golden" / "dem-sanand" / "radar.toml"
LIBRARY = DATA / "backscatter" / "generic-terrain.toml"



@pytest.fixture(scope="module")
def dem_runs(tmp_path_factory):
    """tests/golden/dem-sanand's two CLI steps, and the same in Python."""
    base = tmp_path_factory.mktemp("dem")
    run_cli("scene", "import", DEM, "-o", base / "scene.tif")
    # No --backscatter: the library the imported scene names (generic-terrain).
    run_cli("simulate", "--quiet", "--scene", base / "scene.tif", "--radar", RADAR,
            "--seed", 2, "--out", base / "cli")
    scene = ris.load_scene(DEM)
    result = ris.simulate(scene, ris.load_radar(RADAR), seed=2)
    result.write(base / "py")
    return base, scene, result


def test_imported_scene_is_the_clis(dem_runs):
    base, scene, _ = dem_runs
    cli = gdal.Open(str(base / "scene.tif"))
    assert scene.geotransform == pytest.approx(cli.GetGeoTransform(), rel=0, abs=0)
    elev, cat = read_raster(base / "scene.tif", 1), read_raster(base / "scene.tif", 2)
    valid = scene.valid == 1
    # The file holds NaN where no data; the scene, 0 and valid = 0.
    assert np.array_equal(valid, ~np.isnan(elev)) and 0 < np.count_nonzero(~valid) < valid.size
    assert np.array_equal(scene.elevation_m[valid], elev[valid])
    assert np.array_equal(scene.category[valid], cat[valid])
    assert set(np.unique(scene.category[scene.valid == 1])) == {21}  # grass, as the CLI
    assert "UTM" in scene.crs or "32611" in scene.crs
    assert os.path.samefile(scene.backscatter_library, LIBRARY)
    assert os.path.samefile(ris.load_scene(base / "scene.tif").backscatter_library, LIBRARY)


def test_the_scene_geotiff_simulates_as_the_dem(dem_runs):
    base, _, r = dem_runs
    again = ris.simulate(ris.load_scene(base / "scene.tif"), ris.load_radar(RADAR), seed=2)
    assert np.array_equal(again.speckled_power_w, r.speckled_power_w, equal_nan=True)


def test_products_are_the_cli_bytes(dem_runs):
    base, _, r = dem_runs
    names = sorted(p.name for p in (base / "cli").iterdir())
    assert names == sorted(p.name for p in (base / "py").iterdir())
    for name in names:
        if name == "metadata.json":  # names the scene file: compared below
            continue
        assert (base / "cli" / name).read_bytes() == (base / "py" / name).read_bytes(), name
    assert np.array_equal(r.mean_power_w, read_raster(base / "cli" / "mean_power_slant.tif"),
                          equal_nan=True)
    assert np.array_equal(r.slant_grey, read_raster(base / "cli" / "slant_range.png"))
    assert np.array_equal(r.geocoded_grey, read_raster(base / "cli" / "geocoded_grey.tif"))
    meta = json.loads((base / "cli" / "metadata.json").read_text())
    assert metadata_without_timing(r.metadata)["derived"] == metadata_without_timing(meta)["derived"]
    assert np.nanmax(r.mean_power_w) > 0 and (r.scene_mask != 0).any()
