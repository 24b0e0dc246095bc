"""ris.permittivity gives `ris dielectric`'s values."""

import json
import warnings

import numpy as np
import pytest

import ris
from conftest import run_cli


@pytest.mark.parametrize("frequencies, conductivity", [
    ("5.3 GHz,1.4 GHz", "dobson1985"),
    ("1.25 GHz,0.5 GHz", "peplinski1995"),
])
def test_models_equal_the_cli_json(frequencies, conductivity):
    out = run_cli("dielectric", "--model", "all", "--moisture", "0.05:0.45:0.05",
                  "--frequency", frequencies, "--clay", 0.25, "--sand", 0.35,
                  "--bulk-density", 1.4, "--temperature", 15, "--conductivity", conductivity,
                  "--allow-extrapolation", "--format", "json").stdout
    series = json.loads(out)
    assert len(series) == 6
    for s in series:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            eps = ris.permittivity(s["model"], s["moisture_m3_m3"], s["frequency_ghz"] * 1e9,
                                   clay=0.25, sand=0.35, bulk_density_g_cm3=1.4,
                                   temperature_c=15, conductivity=conductivity,
                                   allow_extrapolation=True)
        # The same double computation, printed by the CLI to round-trip
        # precision: equal to the last bit.
        np.testing.assert_array_equal(eps.real, s["eps_real"])
        np.testing.assert_array_equal(-eps.imag, s["eps_imag"])


def test_conductivity_fits_differ_in_the_loss_only_for_dobson():
    a = ris.permittivity("dobson1985", 0.3, 5.3e9)
    b = ris.permittivity("dobson1985", 0.3, 5.3e9, conductivity="peplinski1995",
                         allow_extrapolation=True)
    assert a.real == b.real and abs(a.imag / b.imag - 1) > 0.05
    h = ris.permittivity("hallikainen1985", 0.3, 5.3e9, conductivity="peplinski1995")
    assert h == ris.permittivity("hallikainen1985", 0.3, 5.3e9)


def test_broadcasts_moisture_against_frequency():
    mv = np.array([[0.1], [0.2], [0.3]])
    f = np.array([1.4e9, 5.3e9, 9.4e9])
    eps = ris.permittivity("mironov2009", mv, f)
    assert eps.shape == (3, 3) and eps.dtype == np.complex128
    for i in range(3):
        for j in range(3):
            assert eps[i, j] == ris.permittivity("mironov2009", mv[i, 0], f[j])
    # Wetter soil: larger eps' (every model).
    assert np.all(np.diff(eps.real, axis=0) > 0)
    assert np.all(eps.imag < 0)  # eps = eps' - j eps'', eps'' > 0


def test_outside_the_validity_range_raises_or_warns():
    with pytest.raises(ris.InputError, match="dobson1985.*allow_extrapolation"):
        ris.permittivity("dobson1985", 0.2, 0.5e9)
    with pytest.warns(UserWarning, match="dobson1985"):
        eps = ris.permittivity("dobson1985", [0.2, 0.3], 0.5e9, allow_extrapolation=True)
    assert np.all(np.isfinite(eps))


@pytest.mark.parametrize("kwargs, key", [
    (dict(model="debye"), "model"),
    (dict(moisture_m3_m3=1.2), "moisture_m3_m3"),
    (dict(moisture_m3_m3=float("nan")), "moisture_m3_m3"),
    (dict(frequency_hz=0.0), "frequency_hz"),
    (dict(moisture_m3_m3="wet"), "moisture_m3_m3"),
    (dict(clay=0.7, sand=0.5), "sand"),
    (dict(clay=-0.1), "clay"),
    (dict(bulk_density_g_cm3=3.0), "bulk_density_g_cm3"),
    (dict(conductivity="ohm"), "conductivity"),
    (dict(moisture_m3_m3=[0.1, 0.2], frequency_hz=[1e9, 2e9, 3e9]), "moisture_m3_m3"),
])
def test_bad_input_raises_naming_the_argument(kwargs, key):
    args = dict(model="hallikainen1985", moisture_m3_m3=0.2, frequency_hz=5.3e9)
    args.update(kwargs)
    with pytest.raises(ris.InputError) as e:
        ris.permittivity(**args)
    assert e.value.key == key and str(e.value)


def test_the_cli_python_and_the_library_list_the_same_models():
    # ris.DIELECTRIC_MODELS is the library's registry (through the binding);
    # `ris dielectric --model all` lists the same names in the same order.
    cli = json.loads(run_cli("dielectric", "--model", "all", "--moisture", "0.2",
                             "--format", "json").stdout)
    assert tuple(s["model"] for s in cli) == ris.DIELECTRIC_MODELS
    assert ris.DIELECTRIC_MODELS == ("dobson1985", "hallikainen1985", "mironov2009")
    for name in ris.DIELECTRIC_MODELS:  # every name resolves
        assert ris.permittivity(name, 0.2, 5.3e9).real > 1.0
    with pytest.raises(ris.InputError, match="known: " + ", ".join(ris.DIELECTRIC_MODELS)):
        ris.permittivity("topp1980", 0.2, 5.3e9)
