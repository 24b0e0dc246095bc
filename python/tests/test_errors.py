"""Every bad input raises ris.InputError (a ValueError) or, for a missing
file, ris.InputFileNotFoundError (also a FileNotFoundError), with a message."""

import numpy as np
import pytest

import ris
from conftest import SMALL_RADAR, STANDARD_RADAR, small_scene


def test_missing_files_raise_file_not_found(tmp_path):
    missing = tmp_path / "nope.toml"
    for call in (lambda: ris.load_scene(missing), lambda: ris.load_radar(missing)):
        with pytest.raises(FileNotFoundError, match="nope.toml") as e:
            call()
        assert isinstance(e.value, ris.InputError) and isinstance(e.value, ValueError)
        assert e.value.file == str(missing)
    with pytest.raises(ris.InputFileNotFoundError, match="nope.toml"):
        ris.simulate(small_scene(), ris.Radar.from_dict(SMALL_RADAR), backscatter=missing)


def test_bad_radar_text_names_the_key(tmp_path):
    with pytest.raises(ris.InputError, match="frequency") as e:
        ris.Radar.from_dict(dict(SMALL_RADAR, frequency="fast"))
    assert e.value.key == "frequency"
    with pytest.raises(ris.InputError, match="expected TOML"):
        ris.Radar.from_toml("frequency = ")
    with pytest.raises(ris.InputError, match="wavelenght"):
        ris.Radar.from_dict(dict(SMALL_RADAR, wavelenght="3 cm"))
    bad = tmp_path / "r.toml"
    bad.write_text(STANDARD_RADAR.read_text().replace('pulse_width = "1.63e-7 s"', 'pulse_width = "-1 s"'))
    with pytest.raises(ris.InputError, match="pulse_width"):
        ris.load_radar(bad)
    with pytest.raises(ris.InputError, match="dict"):
        ris.Radar.from_dict(["frequency"])


def test_dict_keys_are_names_never_pasted_into_toml():
    # A key that would be TOML structure (a table header, a second key, a
    # comment) is refused naming it, before anything is parsed.
    for key in ('frequency = "1 Hz"\n#', "track]\n[x", "a.b", 'q"uote', "", "sp ace"):
        with pytest.raises(ris.InputError, match="not a key name") as e:
            ris.Radar.from_dict(dict(SMALL_RADAR, **{key: 1}))
        assert e.value.key == key
    with pytest.raises(ris.InputError, match="keys must be strings"):
        ris.Radar.from_dict({**SMALL_RADAR, 3: 1})
    with pytest.raises(ris.InputError, match="not a key name"):
        ris.Radar.from_dict(dict(SMALL_RADAR, track={"altitude]\n[y": 1}))
    # A value is a string, whatever it holds: the line it tries to add is not read.
    with pytest.raises(ris.InputError, match="polarisation") as e:
        ris.Radar.from_dict(dict(SMALL_RADAR, polarisation='HH"\ntransmit_power = "1e300 W'))
    assert e.value.key == "polarisation"


def test_deep_toml_text_is_refused():
    with pytest.raises(ris.InputError, match="levels deep"):
        ris.Radar.from_toml("x = " + "[" * 100000 + "]" * 100000)


@pytest.mark.parametrize("kwargs, message", [
    (dict(elevation_m=np.zeros(5)), "2-D"),
    (dict(category=np.ones((3, 4))), "shape"),
    (dict(category=np.full((4, 5), 1.5)), "whole numbers"),
    (dict(category=np.full((4, 5), 70000)), "65535"),
    (dict(category=np.full((4, 5), 65535)), "reserved"),
    (dict(elevation_m=np.full((4, 5), np.inf)), "infinite"),
    (dict(elevation_m=np.full((4, 5), np.nan), valid=np.ones((4, 5))), "NaN"),
    (dict(cell_size_m=0.0), "cell size > 0"),
    (dict(cell_size_m="big"), "number"),
])
def test_bad_arrays_are_refused_with_a_message(kwargs, message):
    args = dict(elevation_m=np.zeros((4, 5)), category=np.ones((4, 5)), cell_size_m=10.0)
    args.update(kwargs)
    with pytest.raises(ris.InputError, match=message):
        ris.Scene.from_arrays(**args)


def test_odd_arrays_are_converted():
    base = np.arange(40, dtype=np.float64).reshape(4, 10)
    s = ris.Scene.from_arrays(base[:, ::2], np.ones((4, 10), dtype=np.int32)[:, ::2], 5)
    assert s.elevation_m.dtype == np.float32
    np.testing.assert_array_equal(s.elevation_m, base[:, ::2])
    holes = base.copy()
    holes[0, 0] = np.nan  # no data
    s = ris.Scene.from_arrays(holes, np.ones((4, 10)), 5)
    assert s.valid[0, 0] == 0 and s.valid[0, 1] == 1 and s.category[0, 0] == 65535


def test_bad_run_options(small_radar):
    scene = small_scene()
    with pytest.raises(ris.InputError, match="threads"):
        ris.simulate(scene, small_radar, threads=-1)
    with pytest.raises(ris.InputError, match="seed"):
        ris.simulate(scene, small_radar, seed=-1)
    with pytest.raises(ris.InputError, match="film"):
        ris.simulate(scene, small_radar).rerender(2, film={"gama": 1})
    far = dict(SMALL_RADAR, track={"altitude": "3000 m", "near_edge_distance": "40000 m"})
    with pytest.raises(ris.InputError):
        ris.simulate(scene, far)


def test_bad_sigma0_arguments():
    with pytest.raises(ris.InputError, match="0, 90"):
        ris.sigma0(4, [10, 100], 8.6e9)
    with pytest.raises(ris.InputError, match="category"):
        ris.sigma0(999, [10], 8.6e9)
    with pytest.raises(ris.InputError, match="no category"):
        ris.sigma0("no such thing", [10], 8.6e9)
    with pytest.raises(ris.InputError, match="XX|polarisation"):
        ris.sigma0(4, [10], 8.6e9, "XX")
    with pytest.raises(ris.InputError, match="frequency"):
        ris.sigma0(4, [10], -1.0)
    with pytest.raises(ris.InputError):
        ris.sigma0({"name": "no_such_model"}, [10], 8.6e9)
    with pytest.raises(ris.InputError, match="broadcast"):
        ris.sigma0(4, [10, 20, 30], [8.6e9, 9e9])


def _only_input_error(call, match):
    """call() raises ris.InputError and not its missing-file subclass."""
    with pytest.raises(ris.InputError, match=match) as e:
        call()
    assert not isinstance(e.value, FileNotFoundError), e.value
    return e.value


def test_bad_values_keep_the_class_input_error(tmp_path):
    # The text's pseudo-file ("<dict>", the source named, "model") is not on
    # disk, and is not a missing file either.
    e = _only_input_error(lambda: ris.Radar.from_dict(dict(SMALL_RADAR, frequency="8.6 parsecs")),
                          "frequency")
    assert e.file == "<dict>" and e.key == "frequency"
    _only_input_error(lambda: ris.Radar.from_toml("frequency = 3", source=str(tmp_path / "r.toml")),
                      "")
    _only_input_error(lambda: ris.Radar.from_toml("frequency = "), "expected TOML")
    _only_input_error(lambda: ris.sigma0({"name": "oh1992", "rms_height": "1 parsec",
                                          "permittivity": "15 - 4j"}, [30.0], 5.3e9, "HH"),
                      "rms_height")
    # A real file that is not there is still the subclass.
    with pytest.raises(ris.InputFileNotFoundError):
        ris.load_radar(tmp_path / "r.toml")
