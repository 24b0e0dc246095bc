"""ris.greytone on an array gives `ris greytone` on the same GeoTIFF."""

import numpy as np
import pytest

import ris
from conftest import DATA, STANDARD_RADAR, STANDARD_SCENE, read_raster, run_cli




@pytest.fixture(scope="module")
def mean_power(tmp_path_factory):
    """The standard run's mean_power_slant.tif, written by the CLI."""
    base = tmp_path_factory.mktemp("grey")
    run_cli("simulate", "--quiet", "--scene", STANDARD_SCENE, "--radar", STANDARD_RADAR,
            "--products", "mean_power_slant", "--out", base / "run")
    return base, base / "run" / "mean_power_slant.tif"


@pytest.mark.parametrize("seed", [1, 17])
def test_equals_the_cli_on_the_same_input(mean_power, seed):
    base, tif = mean_power
    png, speckled = base / f"g{seed}.png", base / f"s{seed}.tif"
    run_cli("greytone", tif, "--radar", STANDARD_RADAR, "--seed", seed, "--out", png,
            "--speckled", speckled)
    g = ris.greytone(read_raster(tif), radar=STANDARD_RADAR, seed=seed)
    assert np.array_equal(g.grey, read_raster(png))
    assert np.array_equal(g.speckled_power_w, read_raster(speckled), equal_nan=True)
    assert g.fading and g.grey.dtype == np.uint8


def test_default_radar_is_the_clis(mean_power):
    base, tif = mean_power
    run_cli("greytone", tif, "--out", base / "default.png")
    assert np.array_equal(ris.greytone(read_raster(tif)).grey, read_raster(base / "default.png"))


def test_a_simulation_rerendered_equals_greytone_of_its_mean_power():
    radar = ris.load_radar(STANDARD_RADAR)
    r = ris.simulate(ris.load_scene(STANDARD_SCENE), radar, seed=5)
    g = ris.greytone(r.mean_power_w, radar=radar, seed=5)
    assert np.array_equal(g.grey, r.slant_grey)
    g = ris.greytone(r.mean_power_w, radar=radar, seed=6, film={"gamma": 0.3})
    r.rerender(6, film={"gamma": 0.3})
    assert np.array_equal(g.grey, r.slant_grey)
    assert g.film["gamma"] == 0.3
    assert g.greytones_per_decade == pytest.approx(255 * 0.3 / g.film["density_range"], rel=1e-12)


def test_equation_15_without_fading():
    """MODEL.md eq. 15: a factor of 10 in power moves G by 255 gamma / X;
    with fading off the grey is exactly round(G_ref + that * log10(P/P_ref))."""
    text = (DATA / "radars" / "seed-fig4-5.toml").read_text()
    r = ris.Radar.from_toml(text + "\n[film.terms]\nfading = false\n", "nofade")
    p = np.logspace(-14, -10, 40, dtype=np.float32).reshape(2, 20)
    g = ris.greytone(p, radar=r, looks=4.0)
    assert not g.fading
    assert np.array_equal(g.speckled_power_w, p)
    want = g.reference_greytone + g.greytones_per_decade * np.log10(
        p.astype(np.float64) / g.reference_power_w)
    np.testing.assert_array_equal(g.grey, np.clip(np.round(want), 0, 255).astype(np.uint8))


def test_looks_set_the_speckle_spread():
    """Exact fading: Y ~ Gamma(N, 1/N), variance 1/N (MODEL.md, "Fading")."""
    p = np.full((400, 50), 1e-12, dtype=np.float32)
    for n in (1.0, 16.0):
        y = ris.greytone(p, looks=n, seed=3).speckled_power_w / 1e-12
        # 20000 samples: the variance's standard error is ~1 % (N=16) to 1.4 % (N=1).
        assert np.var(y) == pytest.approx(1.0 / n, rel=0.06)
        assert np.mean(y) == pytest.approx(1.0, abs=0.03)


@pytest.mark.parametrize("kwargs, key", [
    (dict(mean_power_w=np.zeros(5)), "mean_power_w"),
    (dict(mean_power_w=np.full((3, 4), -1.0)), "mean_power_w"),
    (dict(mean_power_w=np.array([["a", "b"]])), "mean_power_w"),
    (dict(mean_power_w=np.full((3, 4), np.inf)), "mean_power_w"),
    (dict(looks=[1.0, 2.0]), "looks"),
    (dict(looks=0.0), "looks"),
    (dict(film={"gama": 1}), "film"),
    (dict(seed=-1), "seed"),
])
def test_bad_input_raises_naming_the_argument(kwargs, key):
    args = dict(mean_power_w=np.ones((3, 4)) * 1e-12, looks=1.0)
    args.update(kwargs)
    with pytest.raises(ris.InputError) as e:
        ris.greytone(**args)
    assert e.value.key == key and str(e.value)


def test_without_looks_the_columns_must_be_the_radars_bins():
    with pytest.raises(ris.InputError, match="range bins") as e:
        ris.greytone(np.ones((3, 4)) * 1e-12)
    assert e.value.key == "mean_power_w"


def test_strided_and_other_dtypes_are_converted():
    p = np.logspace(-14, -10, 600).reshape(20, 30)  # float64
    want = ris.greytone(np.ascontiguousarray(p[:, ::2], dtype=np.float32), looks=3.0, seed=2)
    for a in (p[:, ::2], np.asfortranarray(p[:, ::2])):
        got = ris.greytone(a, looks=3.0, seed=2)
        assert np.array_equal(got.grey, want.grey)
        assert np.array_equal(got.speckled_power_w, want.speckled_power_w)
