"""A PPI run's B-scope and scope arrays are the CLI's files' pixels."""

import json

import numpy as np
import pytest

import ris
from conftest import DATA, STANDARD_SCENE, metadata_without_timing, read_raster, run_cli


PPI_RADAR = DATA / "radars" / "ppi-ground-mast-30m.toml"



@pytest.fixture(scope="module")
def ppi(tmp_path_factory):
    base = tmp_path_factory.mktemp("ppi")
    run_cli("simulate", "--quiet", "--scene", STANDARD_SCENE, "--radar", PPI_RADAR, "--seed", 4,
            "--out", base / "cli")
    result = ris.simulate(ris.load_scene(STANDARD_SCENE), ris.load_radar(PPI_RADAR), seed=4)
    result.write(base / "py")
    return base / "cli", result


def test_written_products_are_the_cli_bytes(ppi):
    cli, _ = ppi
    py = cli.parent / "py"
    names = sorted(p.name for p in cli.iterdir())
    assert "bscope.png" in names and names == sorted(p.name for p in py.iterdir())
    for name in names:
        a, b = (cli / name).read_bytes(), (py / name).read_bytes()
        if name == "metadata.json":
            assert metadata_without_timing(json.loads(a)) == metadata_without_timing(json.loads(b))
        else:
            assert a == b, name


def test_arrays_are_the_cli_files_pixels(ppi):
    cli, r = ppi
    assert r.kind == "ppi"
    pairs = {
        "bscope_mean_power_w": "mean_power_bscope.tif",
        "bscope_speckled_power_w": "speckled_power_bscope.tif",
        "bscope_grey": "bscope.png",
        "bscope_mask": "mask_bscope.tif",
        "scope_power_w": "ppi_scope_power.tif",
        "scope_mask": "ppi_scope_mask.tif",
        "scope_grey": "ppi_scope.png",
    }
    for attr, name in pairs.items():
        got, want = getattr(r, attr), read_raster(cli / name)
        assert got.shape == want.shape and got.dtype == want.dtype, attr
        assert np.array_equal(got, want, equal_nan=got.dtype.kind == "f"), attr
    # Some of each: data, no data (NaN) in the mean power, shadow flags.
    assert np.isnan(r.bscope_mean_power_w).any() and np.nanmax(r.bscope_mean_power_w) > 0
    assert not r.bscope_mask.flags.writeable


def test_axes_match_the_metadata(ppi):
    cli, r = ppi
    meta = json.loads((cli / "metadata.json").read_text())
    rays = meta["derived"]["rays"]
    az = r.ray_azimuth_deg
    assert az.shape == (r.bscope_grey.shape[0],) == (rays["in_sector"],)
    # The first ray of the sector (the padding rays are not in the B-scope).
    assert az[0] == pytest.approx(rays["first_ray_centre_deg"], abs=1e-9)
    np.testing.assert_allclose(np.diff(az), rays["spacing_deg"], rtol=0, atol=1e-9)
    scope = meta["derived"]["scope"]
    east, north = r.scope_axes_m
    n, p = scope["pixels"], scope["pixel_m"]
    assert east.shape == north.shape == (n,) == (r.scope_grey.shape[1],)
    assert east[0] == pytest.approx(-(n - 1) / 2 * p) and north[0] == pytest.approx((n - 1) / 2 * p)
    assert r.scope_presentation == "slant"
    site = meta["derived"]["site"]
    assert r.site_m == (site["x_m"], site["y_m"])
    # 7.5 m range bins from 0 m (the radar file's 50 ns pulse).
    R = r.slant_range_m
    assert R.shape == (r.bscope_grey.shape[1],)
    np.testing.assert_allclose(np.diff(R), 299792458.0 * 50e-9 / 2, rtol=1e-12)


def test_rerender_changes_the_pictures_not_the_mean(ppi):
    _, r = ppi
    mean, grey = r.bscope_mean_power_w, r.bscope_grey
    r.rerender(9)
    assert np.array_equal(mean, r.bscope_mean_power_w, equal_nan=True)
    assert not np.array_equal(grey, r.bscope_grey)
    r.rerender(4)
    assert np.array_equal(grey, r.bscope_grey)


def test_slar_products_on_a_ppi_run_and_back_raise(ppi):
    _, r = ppi
    with pytest.raises(ris.InputError, match="SLAR and SAR runs only"):
        r.mean_power_w
    slar = ris.simulate(ris.load_scene(STANDARD_SCENE), ris.load_radar(DATA / "radars" / "seed-fig4-5.toml"))
    with pytest.raises(ris.InputError, match="PPI runs only"):
        slar.bscope_grey
