"""A radar with [[channel]] tables from Python: each channel's arrays are
its one-channel run's; the summary names the channels; the server-only
refusals do not apply here."""

import json

import pytest

import ris
from conftest import SOURCE_DIR, STANDARD_SCENE, same_array

MULTI = SOURCE_DIR / "tests" / "golden" / "multichannel" / "radar.toml"


def single_radar(tmp_path, frequency, polarisation, power=None):
    """The golden multi-channel radar as a one-channel file of one channel."""
    text = MULTI.read_text().split("\n[[channel]]")[0]
    keys = f'frequency = "{frequency}"\npolarisation = "{polarisation}"\n'
    if power:
        keys += f'transmit_power = "{power}"\n'
    path = tmp_path / f"{polarisation}.toml"
    path.write_text(keys + text)
    return path


def test_each_channel_is_its_own_run(tmp_path):
    scene = ris.load_scene(STANDARD_SCENE)
    r = ris.simulate(scene, ris.load_radar(MULTI), seed=5)
    assert r.channels == ["hh", "hv", "c_vv"]
    assert r.kind == "slar"
    s = r.summary
    assert s["mode"] == "SLAR" and s["strategy"] == "in_memory"
    assert "(SLAR, 3 channels)" in s["lines"][0]["text"]
    assert "mean_power_slant_c_vv" in s["products"] and "scene_mask" in s["products"]
    with pytest.raises(ris.InputError, match="channel"):
        r.mean_power_w  # which channel's? refused, naming channel(name)
    for name, freq, pol, power in (("hv", "8.6 GHz", "HV", None),
                                   ("c_vv", "5.3 GHz", "VV", "2 kW")):
        one = ris.simulate(scene, ris.load_radar(single_radar(tmp_path, freq, pol, power)), seed=5)
        ch = r.channel(name)
        assert same_array(ch.mean_power_w, one.mean_power_w), name
        assert same_array(ch.slant_grey, one.slant_grey), name
        assert same_array(ch.scene_mask, one.scene_mask), name
    with pytest.raises(ris.InputError, match="no channel"):
        r.channel("vv")
    meta = r.metadata
    assert [c["name"] for c in meta["channels"]] == ["hh", "hv", "c_vv"]
    r.write(tmp_path / "out")
    written = json.loads((tmp_path / "out" / "metadata.json").read_text())
    assert sorted(written["products"]) == sorted(p.name for p in (tmp_path / "out").iterdir())
