"""Optical and thermal images from Python (ris.sensor): the arrays equal the
GeoTIFFs `ris sensor` writes from the same files (grid and camera), the
place and the georeferencing are the scene's, and bad arguments raise
InputError naming the argument."""

import numpy as np
import pytest

import ris
from conftest import DATA, read_raster, run_cli

SCENE = """name = "eo-py"
[grid]
rows = 40
cols = 50
cell_size = 5.0
base_category = 21
origin = [690000, 5330000]
crs = "EPSG:32632"
[[object]]
type = "pyramid"
x = 100
y = 80
base = 60
height = 30
category = 26
"""

OPTICAL = """kind = "optical"
date = "2024-06-21"
time = "09:30:00"
bands = ["blue", "green", "red"]
noise = 0.2
[camera]
position = [690125, 5329950]
altitude = "200 m"
heading = "0 deg"
depression = "50 deg"
fov = "40 deg"
columns = 48
rows = 32
mtf_at_nyquist = 0.4
[detector]
electrons_per_radiance = 150
read_noise = 10
full_well = 30000
bits = 12
"""

THERMAL = """kind = "thermal"
date = "2024-06-21"
time = "13:00:00"
bands = ["lwir", "mwir"]
"""

TABLE = DATA / "sensors_eo" / "generic-terrain-eo.csv"


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    d = tmp_path_factory.mktemp("sensor")
    (d / "s.toml").write_text(SCENE)
    (d / "o.toml").write_text(OPTICAL)
    (d / "t.toml").write_text(THERMAL)
    return d


def test_optical_equals_the_command_line(files, tmp_path):
    img = ris.sensor(files / "s.toml", files / "o.toml", TABLE, threads=2)
    assert list(img.bands) == ["blue", "green", "red"] and img.unit == "W m-2 sr-1 um-1"
    run_cli("sensor", "optical", files / "s.toml", "--sensor", files / "o.toml",
            "--table", TABLE, "-q", "-o", tmp_path / "out")
    for i, name in enumerate(img.bands):
        np.testing.assert_array_equal(read_raster(tmp_path / "out" / "radiance.tif", i + 1),
                                      img.bands[name])
        np.testing.assert_array_equal(
            read_raster(tmp_path / "out" / "camera_radiance.tif", i + 1),
            img.camera["bands"][name])
        np.testing.assert_array_equal(
            read_raster(tmp_path / "out" / "camera_digital_number.tif", i + 1),
            img.camera["digital_numbers"][name])
    np.testing.assert_array_equal(read_raster(tmp_path / "out" / "camera_range_m.tif"),
                                  img.camera["range_m"])
    assert img.geotransform == (690000.0, 5.0, 0.0, 5330200.0, 0.0, -5.0)
    assert 48.0 < img.latitude_deg < 48.2  # the scene's centre through EPSG:32632
    assert len(img.camera["gcps"]) > 3 and img.to_numpy().shape == (3, 40, 50)


def test_thermal_reads_kelvin(files):
    img = ris.sensor(ris.load_scene(files / "s.toml"), files / "t.toml", TABLE)
    assert img.unit == "K" and img.camera is None
    lwir = img.bands["lwir"]
    assert np.all((lwir > 280) & (lwir < 340))


def test_bad_arguments_name_the_argument(files):
    with pytest.raises(ris.InputError) as e:
        ris.sensor(files / "s.toml", 3)
    assert e.value.key == "sensor"
    with pytest.raises(ris.InputError) as e:
        ris.sensor(files / "s.toml", files / "t.toml", threads=-1)
    assert e.value.key == "threads"
    with pytest.raises(ris.InputError) as e:
        ris.sensor(ris.Scene.from_arrays(np.zeros((4, 4)), np.full((4, 4), 21), 1.0),
                   files / "t.toml")
    assert e.value.key == "scene"
    bad = files / "bad.toml"
    bad.write_text(THERMAL.replace('"mwir"', '"uv"'))
    with pytest.raises(ris.InputError) as e:
        ris.sensor(files / "s.toml", bad)
    assert "uv" in str(e.value)
