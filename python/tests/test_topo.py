"""ris.topo: the layers of `ris topo` (tests/topo_cli_test.cpp's inputs)."""

import numpy as np
import pytest

import ris
from conftest import SOURCE_DIR, read_raster, run_cli, same_array

REAL = SOURCE_DIR / "tests" / "data" / "real"
DEMS = SOURCE_DIR / "tests" / "data" / "dem"

# ris.topo's key -> the file `ris topo` writes it to.
FILES = {
    "lat_deg": "lat.tif",
    "lon_deg": "lon.tif",
    "hgt_m": "hgt.tif",
    "incidence_deg": "incidence.tif",
    "incidence_geocentric_deg": "incidence_geocentric.tif",
    "local_incidence_deg": "local_incidence.tif",
    "look_deg": "look.tif",
    "heading_deg": "heading.tif",
    "gamma_area_m2": "gamma_area.tif",
    "simamp": "simamp.tif",
    "layover_shadow_mask": "layover_shadow_mask.tif",
}


@pytest.mark.parametrize("product, dem", [("winnipeg.h5", "winnipeg_dem.tif"),
                                          ("SanAnd_138.h5", "SanAnd_dem.tif")])
def test_topo_is_the_command_lines_layers(tmp_path, product, dem):
    acq, dem_path = REAL / product, DEMS / dem
    run_cli("topo", "-a", acq, "--dem", dem_path, "--out", tmp_path / "t", "--quiet")
    t = ris.topo(acq, dem_path)
    assert set(FILES) <= set(t)
    for key, name in FILES.items():
        cli = read_raster(tmp_path / "t" / name)
        assert t[key].dtype == cli.dtype, key
        assert same_array(t[key], cli), key  # the same values, bit for bit
    lines, bins = t["lat_deg"].shape
    assert t["window"][1] == lines and t["window"][3] == bins
    assert lines > 0 and bins > 0


def test_topo_bad_input_names_the_key():
    acq, dem = REAL / "winnipeg.h5", DEMS / "winnipeg_dem.tif"
    with pytest.raises(ris.InputError) as e:
        ris.topo(acq, dem, oversample=65)
    assert e.value.key == "oversample"
    with pytest.raises(ris.InputError) as e:
        ris.topo(acq, dem, threads=-1)
    assert e.value.key == "threads"
    with pytest.raises(ris.InputFileNotFoundError):
        ris.topo(acq, DEMS / "no-such-dem.tif")


def test_topo_keys_are_the_file_names_and_the_old_key_is_deprecated():
    t = ris.topo(REAL / "winnipeg.h5", DEMS / "winnipeg_dem.tif")
    # One name per product: each layer's key is its file's stem (plus the unit).
    for key, name in FILES.items():
        assert key == name[:-len(".tif")] or key.startswith(name[:-len(".tif")] + "_"), key
    assert "simulated_amplitude" not in t
    with pytest.warns(DeprecationWarning, match="simamp"):
        old = t["simulated_amplitude"]
    assert old is t["simamp"]
    with pytest.raises(KeyError):
        t["no_such_layer"]
