"""Acquisition runs and streamed runs from Python: the command line's bytes
(every file of the output folder hashed, metadata.json included)."""

import hashlib

import pytest

import ris
from conftest import DATA, SOURCE_DIR, STANDARD_RADAR, STANDARD_SCENE, run_cli

WINNIPEG = SOURCE_DIR / "tests" / "data" / "real" / "winnipeg.h5"
WINNIPEG_DEM = SOURCE_DIR / "tests" / "data" / "dem" / "winnipeg_dem.tif"
PPI_RADAR = DATA / "radars" / "ppi-ground-mast-30m.toml"


def hashes(folder):
    """file name -> sha256 of every file of a product folder."""
    return {p.name: hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(folder.iterdir()) if p.is_file()}


def expect_same_folders(cli, py, at_least):
    a, b = hashes(cli), hashes(py)
    assert len(a) >= at_least, sorted(a)
    assert sorted(a) == sorted(b)
    assert {k for k in a if a[k] != b[k]} == set()


def acquisition_args(radar):
    return ["-a", WINNIPEG, "--dem", WINNIPEG_DEM, "--radar", radar, "--seed", 3, "--threads", 2,
            "--quiet"]


@pytest.mark.parametrize("block_lines", [0, 16])
def test_acquisition_run_is_the_command_lines(tmp_path, block_lines):
    extra = ["--block-lines", block_lines] if block_lines else []
    run_cli("simulate", *acquisition_args(STANDARD_RADAR), *extra, "--out", tmp_path / "cli")
    r = ris.simulate_acquisition(WINNIPEG, WINNIPEG_DEM, radar=STANDARD_RADAR, seed=3, threads=2,
                                 block_lines=block_lines, out=tmp_path / "py")
    assert r.acquisition and r.out_dir == str(tmp_path / "py")
    expect_same_folders(tmp_path / "cli", tmp_path / "py", 8)
    if block_lines:
        assert r.kind == "streamed"
        assert r.stream_summary["blocks"] == 16 and r.stream_summary["block_lines"] == 16
        with pytest.raises(ris.InputError, match="streamed run keeps no images"):
            r.mean_power_w
        assert r.metadata["acquisition"]["window"] is not None
        return
    # In memory: the arrays are the files' pixels, and write() their bytes.
    assert r.kind == "slar"
    assert r.mean_power_w.shape == r.local_incidence_deg.shape == r.layover_shadow_mask.shape
    r.write(tmp_path / "again")
    expect_same_folders(tmp_path / "cli", tmp_path / "again", 8)
    with pytest.raises(ris.InputError, match="no scene grid"):
        r.scene_mask


def test_acquisition_run_with_the_flat_earth_and_a_category(tmp_path):
    args = [*acquisition_args(STANDARD_RADAR), "--earth", "flat", "--category", 2]
    run_cli("simulate", *args, "--out", tmp_path / "cli")
    ris.simulate_acquisition(WINNIPEG, WINNIPEG_DEM, radar=STANDARD_RADAR, seed=3, threads=2,
                             earth="flat", category=2, out=tmp_path / "py")
    expect_same_folders(tmp_path / "cli", tmp_path / "py", 8)


@pytest.fixture(scope="module")
def scene_tif(tmp_path_factory):
    path = tmp_path_factory.mktemp("scene") / "ku.tif"
    run_cli("scene", "build", STANDARD_SCENE, "-o", path)
    return path


@pytest.mark.parametrize("radar", [STANDARD_RADAR, PPI_RADAR], ids=["slar", "ppi"])
def test_streamed_run_is_the_command_lines(tmp_path, scene_tif, radar):
    run_cli("simulate", "--scene", scene_tif, "--radar", radar, "--seed", 5, "--threads", 2,
            "--block-lines", 96, "--quiet", "--out", tmp_path / "cli")
    r = ris.simulate(scene_tif, radar, seed=5, threads=2, block_lines=96, out=tmp_path / "py")
    assert r.kind == "streamed" and r.stream_summary["blocks"] > 1
    expect_same_folders(tmp_path / "cli", tmp_path / "py", 6)
    # The streamed run's bytes are the in-memory run's too.
    ris.simulate(ris.load_scene(scene_tif), radar, seed=5, threads=2, out=tmp_path / "mem")
    expect_same_folders(tmp_path / "cli", tmp_path / "mem", 6)


def test_run_options_are_checked(tmp_path, scene_tif):
    with pytest.raises(ris.InputError, match="give out") as e:
        ris.simulate(scene_tif, STANDARD_RADAR, stream=True)
    assert e.value.key == "out"
    with pytest.raises(ris.InputError, match="scene raster") as e:
        ris.simulate(ris.Scene.from_arrays([[0.0, 0.0]], [[1, 1]], 10.0), STANDARD_RADAR,
                     stream=True, out=tmp_path / "x")
    with pytest.raises(ris.InputError, match="block_lines"):
        ris.simulate(scene_tif, STANDARD_RADAR, block_lines=-3, out=tmp_path / "x")
    with pytest.raises(ris.InputError, match="earth"):
        ris.simulate_acquisition(WINNIPEG, WINNIPEG_DEM, earth="round")
    with pytest.raises(ris.InputError, match="--dem|dem"):
        ris.simulate_acquisition(WINNIPEG, "")
    with pytest.raises(ris.InputFileNotFoundError):
        ris.simulate_acquisition(WINNIPEG, tmp_path / "no-dem.tif")
    assert not (tmp_path / "x").exists()
