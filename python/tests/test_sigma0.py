"""ris.sigma0 gives `ris sigma0`'s values."""

import json

import numpy as np
import pytest

import ris
from conftest import run_cli


def db(x):
    """As `ris sigma0` prints: 10 log10, floored at -100 dB."""
    with np.errstate(divide="ignore"):
        return np.maximum(-100.0, 10.0 * np.log10(x))


def test_library_categories_equal_the_cli_table():
    out = run_cli("sigma0", "--category", "all", "--frequency", "8.6 GHz", "--pol", "HH,VV",
                  "--angles", "0:90:5", "--format", "json").stdout
    series = json.loads(out)
    assert len(series) > 4
    for s in series:
        angles = np.array(s["angle_deg"])
        got = ris.sigma0(s["category"], angles, 8.6e9, s["polarisation"])
        # The same double computation; 1e-9 dB allows a last-bit log10 difference.
        np.testing.assert_allclose(db(got), s["sigma0_db"], rtol=0, atol=1e-9)
        by_name = ris.sigma0(s["name"], angles, 8.6e9, s["polarisation"])
        np.testing.assert_array_equal(by_name, got)


def test_model_equals_the_cli_model():
    out = run_cli("sigma0", "--model", 'name = "oh1992", rms_height = "1 cm", permittivity = "15 - 4j"',
                  "--frequency", "5.405 GHz", "--pol", "HH,VV,HV", "--angles", "10:70:10",
                  "--format", "json").stdout
    model = {"name": "oh1992", "rms_height": "1 cm", "permittivity": "15 - 4j"}
    for s in json.loads(out):
        got = ris.sigma0(model, s["angle_deg"], 5.405e9, s["polarisation"])
        np.testing.assert_allclose(db(got), s["sigma0_db"], rtol=0, atol=1e-9)


def test_vectorised_over_angles_frequencies_and_polarisations():
    angles = np.linspace(10, 60, 6).reshape(2, 3)
    pols = np.array([["HH", "VV", "HH"], ["VV", "HH", "VV"]])
    got = ris.sigma0(4, angles, [8.6e9, 9.4e9, 8.6e9], pols)
    assert got.shape == (2, 3)
    for i in range(2):
        for j in range(3):
            one = ris.sigma0(4, angles[i, j], [8.6e9, 9.4e9, 8.6e9][j], pols[i, j])
            assert one.shape == () and one == got[i, j]


def test_list_models():
    models = ris.list_models()
    assert "oh1992" in models and "constant_gamma" in models
    assert all(isinstance(v, str) and v for v in models.values())
