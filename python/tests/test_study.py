"""ris.study: the command line's `ris study` from Python (the same bytes in
the out folder, the tables as Python data), and bad arguments refused by
name before anything runs."""

import csv
import hashlib
import json

import numpy as np
import pytest

import ris
from conftest import DATA, read_raster, run_cli

STUDY_FILE = DATA / "studies" / "seed-fig7.toml"
BANDS = "8.6 GHz:HH, 1.25 GHz:VV"


def hashes(folder):
    return {p.name: hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(folder.iterdir()) if p.is_file()}


def test_study_is_the_command_lines(tmp_path):
    run_cli("study", "--bands", BANDS, "--range-fraction", "0.25,0.75", "--incidence-bin", "2 deg",
            "--seed", 5, "--panel-size", 200, "--threads", 2, "--quiet", "--out", tmp_path / "cli")
    r = ris.study(bands=[("8.6 GHz", "HH"), "1.25 GHz:VV"], range_fraction=(0.25, 0.75),
                  incidence_bin="2 deg", seed=5, panel_size=200, threads=2, out=tmp_path / "py")
    cli, py = hashes(tmp_path / "cli"), hashes(tmp_path / "py")
    assert len(cli) == 7 and cli == py  # 2 panels, sheet, 3 CSV, metadata.json
    r.write(tmp_path / "again")
    assert hashes(tmp_path / "again") == cli

    # The tables are the files' rows, typed.
    with open(tmp_path / "cli" / "categories.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(r.categories) == len(rows) > 0
    for got, want in zip(r.categories, rows):
        assert got["band"] == want["band"] and got["category"] == int(want["category"])
        assert got["pixels"] == int(want["pixels"])
        assert np.isnan(got["mean_grey"]) if want["mean_grey"] == "" else \
            got["mean_grey"] == float(want["mean_grey"])
    with open(tmp_path / "cli" / "separability.csv", newline="") as f:
        pairs = list(csv.DictReader(f))
    assert [(p["run"], p["jm"], p["separated"]) for p in r.separability] == \
        [(p["run"], float(p["jm"]) if p["jm"] else pytest.approx(np.nan, nan_ok=True),
          p["separated"] == "1") for p in pairs]
    assert r.metadata == json.loads((tmp_path / "cli" / "metadata.json").read_text())
    assert r.bands == ["8.6 GHz HH", "1.25 GHz VV"]
    assert r.verdict == r.metadata["verdict"] and r.null_check_passed is True
    # The panels are the PNGs' pixels.
    for i, (grey, band) in enumerate(zip(r.slant_grey, ["8.6GHz_HH", "1.25GHz_VV"])):
        png = read_raster(tmp_path / "cli" / f"panel_{i + 1}_{band}.png")
        assert grey.dtype == np.uint8 and np.array_equal(grey, png)


def test_study_file_with_arguments_winning(tmp_path):
    run_cli("study", "--study", STUDY_FILE, "--bands", "8.6 GHz:VV", "--no-null-check", "--quiet",
            "--out", tmp_path / "cli")
    stages = []
    r = ris.study(STUDY_FILE, bands="8.6 GHz:VV", null_check=False, out=tmp_path / "py",
                  progress=lambda stage, f: stages.append(f))
    assert hashes(tmp_path / "cli") == hashes(tmp_path / "py")
    assert r.title == "seed figure 7" and r.null_check_passed is None
    assert r.metadata["method"]["window"]["range_fraction"] == pytest.approx([1 / 3, 2 / 3], 1e-9)
    assert stages and stages[-1] <= 1.0


def test_study_to_xarray():
    pytest.importorskip("xarray")
    r = ris.study(bands="8.6 GHz:HH, 8.6 GHz:VV", range_fraction=(0.3333, 0.6667))
    ds = r.to_xarray()
    assert ds["slant_grey"].shape == (2,) + r.slant_grey[0].shape
    assert list(ds["band"].values) == r.bands
    first = r.categories[0]
    assert ds["pixels"].sel(band=first["band"], category=first["category"]) == first["pixels"]
    sep = r.separability[0]
    got = ds["jm"].sel(run=sep["run"], band=sep["band"])
    pair = [i for i in range(ds.sizes["pair"])
            if (ds["category_a"][i], ds["category_b"][i]) == (sep["category_a"], sep["category_b"])]
    assert float(got[pair[0]]) == pytest.approx(sep["jm"], nan_ok=True)
    assert ds.attrs["verdict"] == r.verdict


@pytest.mark.parametrize("kwargs, key, words", [
    ({"bands": "25 GHz:HH"}, "bands", "25 GHz HH is outside"),
    ({"bands": "8.6 GHz:XX"}, "bands", "XX"),
    ({"bands": [8.6e9]}, "bands", "pairs"),
    ({"bands": "8.6 GHz:HH, 8600 MHz:hh"}, "bands", "duplicate"),
    ({"range_fraction": (0.6, 0.4)}, "range_fraction", "0 <= lo < hi <= 1"),
    ({"range_fraction": 0.5}, "range_fraction", "(lo, hi)"),
    ({"incidence_bin": 1.0}, "incidence_bin", "unit"),
    ({"incidence_bin": "0 deg"}, "incidence_bin", "(0, 90]"),
    ({"panel_size": 8}, "panel_size", "16 or more"),
    ({"seed": -1}, "seed", "whole number"),
    ({"null_check": "no"}, "null_check", "True or False"),
    ({"scene": 3}, "scene", "path"),
])
def test_bad_arguments_are_refused_by_name(tmp_path, kwargs, key, words):
    with pytest.raises(ris.InputError) as e:
        ris.study(out=tmp_path / "out", **kwargs)
    assert e.value.key == key and f"{key}" in str(e.value) and words in str(e.value)
    assert not isinstance(e.value, FileNotFoundError)
    assert not (tmp_path / "out").exists()  # nothing written


def test_a_missing_study_file_is_file_not_found(tmp_path):
    with pytest.raises(ris.InputFileNotFoundError):
        ris.study(tmp_path / "none.toml")
