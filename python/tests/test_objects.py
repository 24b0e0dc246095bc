"""A scene description's buildings and reflectors are traced from Python as
by ``ris simulate`` (docs/objects.md): the same bytes, and metadata's
``objects``."""

import subprocess

import ris
from conftest import DATA, RIS_EXE

TOWN = """
[grid]
rows = 100
cols = 300
cell_size = 2.0
base_category = 1

[[object]]
type = "building"
footprint = [[200, 70], [230, 70], [230, 130], [200, 130]]
height = 15
category = 2

[[object]]
type = "reflector"
shape = "trihedral"
x = 400
y = 100
size = 1.0
azimuth = 180
tilt = 39.04
"""


def test_objects_are_traced_as_by_the_command_line(tmp_path):
    scene_path = tmp_path / "town.toml"
    scene_path.write_text(TOWN)
    radar = DATA / "radars" / "sar-x-band-town.toml"
    subprocess.run([RIS_EXE, "simulate", "--quiet", "--scene", str(scene_path), "--radar",
                    str(radar), "--out", str(tmp_path / "cli")], check=True)
    result = ris.simulate(ris.load_scene(scene_path), ris.load_radar(radar),
                          out=tmp_path / "py")
    assert result.metadata["objects"]["objects"] == 2
    assert result.metadata["objects"]["scattering_centres"] > 1
    for name in ("mean_power_slant.tif", "speckled_power_slant.tif"):
        assert (tmp_path / "cli" / name).read_bytes() == (tmp_path / "py" / name).read_bytes()
