"""A scene description's buildings and reflectors are traced from Python as
by ``ris simulate`` (docs/objects.md): the same bytes, and metadata's
``objects``."""

import subprocess

import ris
from conftest import DATA, RIS_EXE

TOWN = DATA.parent / "tests" / "data" / "objects" / "two-objects.toml"


def test_objects_are_traced_as_by_the_command_line(tmp_path):
    scene_path = TOWN
    radar = DATA / "radars" / "sar-x-band-town.toml"
    subprocess.run([RIS_EXE, "simulate", "--quiet", "--scene", str(scene_path), "--radar",
                    str(radar), "--out", str(tmp_path / "cli")], check=True)
    result = ris.simulate(ris.load_scene(scene_path), ris.load_radar(radar),
                          out=tmp_path / "py")
    assert result.metadata["objects"]["objects"] == 2
    assert result.metadata["objects"]["scattering_centres"] > 1
    for name in ("mean_power_slant.tif", "speckled_power_slant.tif"):
        assert (tmp_path / "cli" / name).read_bytes() == (tmp_path / "py" / name).read_bytes()
