"""to_xarray(): a Dataset with named dims and metre coordinates when xarray
imports; a clear ImportError when it does not."""

import builtins
import json
import sys

import numpy as np
import pytest

import ris
from conftest import DATA, STANDARD_SCENE, small_scene


@pytest.fixture(scope="module")
def slar(small_radar):
    scene = ris.Scene.from_arrays(np.zeros((40, 200)), np.ones((40, 200)), 10.0,
                                  crs="EPSG:32633", origin=(500000.0, 4600400.0))
    return ris.simulate(scene, small_radar, seed=2)


def test_slar_dataset(slar):
    xr = pytest.importorskip("xarray")
    ds = slar.to_xarray()
    assert isinstance(ds, xr.Dataset)
    assert ds["mean_power_w"].dims == ("line", "bin")
    assert ds["ground_grey"].dims == ("line", "ground_bin")
    assert ds["geocoded_grey"].dims == ds["local_incidence_deg"].dims == ("y", "x")
    np.testing.assert_array_equal(ds["speckled_power_w"].values, slar.speckled_power_w)
    np.testing.assert_array_equal(ds["geocoded_grey"].values, slar.geocoded_grey)
    np.testing.assert_array_equal(ds["bin"].values, slar.slant_range_m)
    np.testing.assert_array_equal(ds["ground_bin"].values, slar.ground_range_m)
    # Cell centres of the north-west-origin grid, metres.
    assert ds["x"].values[0] == 500005.0 and ds["x"].values[-1] == 500000.0 + 1995.0
    assert ds["y"].values[0] == 4600395.0 and ds["y"].values[-1] == 4600005.0
    # Lines: one scene cell apart (the default spacing), centres from 0.5 cell.
    np.testing.assert_allclose(np.diff(ds["line"].values), 10.0, rtol=1e-12)
    assert ds["line"].values[0] == pytest.approx(5.0)
    assert all(ds[c].attrs["units"] == "m" for c in ("x", "y", "line", "bin", "ground_bin"))
    assert ds.attrs["crs_wkt"] == "EPSG:32633" and ds.attrs["kind"] == "slar"
    assert json.loads(ds.attrs["metadata"])["derived"] == slar.metadata["derived"]
    assert ds["mean_power_w"].attrs["units"] == "W"


def test_scene_dataset():
    pytest.importorskip("xarray")
    s = ris.load_scene(STANDARD_SCENE)
    ds = s.to_xarray()
    assert ds["elevation_m"].dims == ("y", "x")
    np.testing.assert_array_equal(ds["elevation_m"].values, s.elevation_m)
    x0, dx, _, y0, _, dy = s.geotransform
    assert ds["x"].values[1] - ds["x"].values[0] == pytest.approx(dx)
    assert ds["y"].values[0] == pytest.approx(y0 + dy / 2)
    assert ds.attrs["crs_wkt"] == (s.crs or "")


def test_ppi_dataset():
    pytest.importorskip("xarray")
    r = ris.simulate(ris.load_scene(STANDARD_SCENE),
                     ris.load_radar(DATA / "radars" / "ppi-ground-mast-30m.toml"))
    ds = r.to_xarray()
    assert ds["bscope_grey"].dims == ("ray", "bin") and ds["scope_grey"].dims == ("y", "x")
    np.testing.assert_array_equal(ds["ray"].values, r.ray_azimuth_deg)
    np.testing.assert_array_equal(ds["scope_power_w"].values, r.scope_power_w)
    east, north = r.scope_axes_m
    np.testing.assert_array_equal(ds["x"].values, east)  # slant scope: metres from the radar
    assert ds.attrs["scope_presentation"] == "slant" and ds.attrs["crs_wkt"] == ""


def test_without_xarray_a_clear_import_error(slar, monkeypatch):
    """xarray absent (simulated): ImportError naming the package to install;
    the numpy arrays still work."""
    real_import = builtins.__import__

    def no_xarray(name, *args, **kwargs):
        if name == "xarray" or name.startswith("xarray."):
            raise ModuleNotFoundError("No module named 'xarray'")
        return real_import(name, *args, **kwargs)

    for mod in [m for m in sys.modules if m == "xarray" or m.startswith("xarray.")]:
        monkeypatch.delitem(sys.modules, mod)
    monkeypatch.setattr(builtins, "__import__", no_xarray)
    with pytest.raises(ImportError, match="python3-xarray"):
        slar.to_xarray()
    with pytest.raises(ImportError, match="python3-xarray"):
        small_scene().to_xarray()
    assert slar.mean_power_w.shape[1] == slar.slant_range_m.size
