"""A quad-pol run from Python: the four SLCs as one complex array (HH, HV,
VH, VV) that equals the written slc_*.tif, C3/T3 as ris polsar averages
them, an xarray Dataset with a polarisation dimension, and a clear error
on a run that is not quad-pol."""

import numpy as np
import pytest

import ris
from conftest import DATA, read_raster

# The town's quad-pol radar over a 300 m x 200 m plain of 1 m cells.
RADAR = DATA / "radars" / "sar-x-band-town-quadpol.toml"


@pytest.fixture(scope="module")
def quad():
    scene = ris.Scene.from_arrays(np.zeros((200, 300)), np.full((200, 300), 3), 1.0)
    return ris.simulate(scene, ris.load_radar(RADAR), seed=4)


def test_slc_is_the_written_products(quad, tmp_path):
    assert quad.channels == ["hh", "hv", "vh", "vv"]
    slc = quad.slc
    assert slc.dtype == np.complex64 and slc.shape[0] == 4
    quad.write(tmp_path / "out")
    for i, pol in enumerate(("hh", "hv", "vh", "vv")):
        written = read_raster(tmp_path / "out" / f"slc_{pol}.tif")
        np.testing.assert_array_equal(written, slc[i])
    # Each channel's speckled image is |z|^2 of its SLC.
    np.testing.assert_allclose(quad.channel("vv").speckled_power_w, np.abs(slc[3]) ** 2,
                               rtol=1e-5, equal_nan=True)


def test_c3_and_t3_are_the_boxcar_of_the_slcs(quad):
    slc = quad.slc.astype(np.complex128)
    c3 = quad.polarimetric_matrix("c3", window=3)
    assert c3.shape == (3, 3) + slc.shape[1:]
    hh, hv, vv = slc[0], (slc[1] + slc[2]) / 2, slc[3]
    # A pixel whose full 3 x 3 box holds data (the swath is wider than the plain).
    finite = np.isfinite(slc[0])
    ok = finite[:-2, :-2] & finite[1:-1, 1:-1] & finite[2:, 2:] & finite[:-2, 2:] & finite[2:, :-2]
    rows, cols = np.nonzero(ok)
    r, b = rows[len(rows) // 2] + 1, cols[len(cols) // 2] + 1
    assert np.all(np.isfinite(slc[:, r - 1:r + 2, b - 1:b + 2]))
    box = np.s_[r - 1:r + 2, b - 1:b + 2]
    assert c3[0, 0, r, b].real == pytest.approx(np.mean(np.abs(hh[box]) ** 2), rel=1e-5)
    assert c3[1, 1, r, b].real == pytest.approx(np.mean(2 * np.abs(hv[box]) ** 2), rel=1e-5)
    c13 = np.mean(hh[box] * np.conj(vv[box]))
    assert abs(c3[0, 2, r, b] - c13) <= 1e-5 * abs(c13)
    t3 = quad.polarimetric_matrix("t3", window=3)
    assert t3[0, 0, r, b].real == pytest.approx(np.mean(np.abs(hh[box] + vv[box]) ** 2) / 2,
                                                rel=1e-5)
    # The trace is the span in both bases.
    assert np.trace(t3[:, :, r, b]).real == pytest.approx(np.trace(c3[:, :, r, b]).real, rel=1e-5)
    with pytest.raises(ris.InputError, match="window"):
        quad.polarimetric_matrix("c3", window=4)
    with pytest.raises(ris.InputError, match="kind"):
        quad.polarimetric_matrix("s2")


def test_polsar_xarray_has_a_polarisation_dimension(quad):
    pytest.importorskip("xarray")
    ds = quad.polsar_xarray(window=3)
    assert ds["slc"].dims == ("polarisation", "line", "bin")
    assert list(ds["polarisation"].values) == ["HH", "HV", "VH", "VV"]
    assert ds["c3"].dims == ("row", "col", "line", "bin")
    np.testing.assert_array_equal(ds["slc"].sel(polarisation="VH").values, quad.slc[2])


def test_a_single_pol_run_has_no_slc(small_radar):
    scene = ris.Scene.from_arrays(np.zeros((40, 200)), np.ones((40, 200)), 10.0)
    r = ris.simulate(scene, small_radar, seed=1)
    with pytest.raises(ris.InputError, match="quad_pol"):
        r.slc
