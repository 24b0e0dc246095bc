"""Radar.info(): `ris radar info`'s derived quantities in its units."""

import math
import re

import pytest

import ris
from conftest import DATA, run_cli


@pytest.mark.parametrize("name", ["seed-fig4-5.toml", "sar-x-band-stripmap.toml"])
def test_info_gives_degrees_where_the_command_line_prints_degrees(name):
    path = DATA / "radars" / name
    info = ris.load_radar(path).info()
    assert not [k for k in info if k.endswith("_rad")]
    out = run_cli("radar", "info", path).stdout
    for what, prefix in (("depression", "depression"), ("incidence", "incidence")):
        m = re.search(rf"{what} near / far\s+([\d.]+) deg / ([\d.]+) deg", out)
        assert m, out
        near, far = float(m.group(1)), float(m.group(2))
        # The CLI prints 3 decimals of the same degrees.
        assert info[f"near_{prefix}_deg"] == pytest.approx(near, abs=5e-4)
        assert info[f"far_{prefix}_deg"] == pytest.approx(far, abs=5e-4)
    # The radians metadata.json keeps, converted: the same angle.
    assert info["near_incidence_deg"] + info["near_depression_deg"] == pytest.approx(90.0, abs=1e-9)
    m = re.search(r"range bins\s+(\d+)", out)
    assert info["range_bins"] == int(m.group(1))


def test_metadata_keeps_radians():
    # metadata.json's radar_derived is unchanged (bytes of the products).
    scene = ris.load_scene(DATA / "scenes" / "ku-geometric.toml")
    radar = ris.load_radar(DATA / "radars" / "seed-fig4-5.toml")
    derived = ris.simulate(scene, radar, seed=1).metadata["derived"]["radar"]
    info = radar.info()
    assert math.degrees(derived["near_incidence_rad"]) == pytest.approx(info["near_incidence_deg"])
