"""simulate(..., calibrated=True) writes the calibrated images as
``ris simulate --calibrated`` does; a streamed run refuses them naming the
option."""

import pytest

import ris
from conftest import STANDARD_SCENE


def test_calibrated_images_are_written(tmp_path):
    scene = ris.load_scene(STANDARD_SCENE)
    ris.simulate(scene, None, out=tmp_path / "out", calibrated=True,
                 products=["sigma0_slant", "gamma0_slant_db"])
    names = sorted(p.name for p in (tmp_path / "out").iterdir())
    assert names == ["gamma0_slant_db.tif", "metadata.json", "sigma0_slant.tif"]


def test_a_streamed_run_refuses_them(tmp_path):
    with pytest.raises(ris.InputError, match="--calibrated"):
        ris.simulate(STANDARD_SCENE, None, out=tmp_path / "out", block_lines=64, calibrated=True)
