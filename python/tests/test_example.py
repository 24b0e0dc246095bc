"""examples/sweep.py runs headless and writes its table."""

import csv
import os
import subprocess
import sys

from conftest import SOURCE_DIR


def test_sweep_example_runs(tmp_path):
    subprocess.run([sys.executable, str(SOURCE_DIR / "examples" / "sweep.py"), str(tmp_path)],
                   check=True, env=dict(os.environ, MPLBACKEND="Agg"), capture_output=True)
    with open(tmp_path / "sweep.csv") as f:
        rows = list(csv.DictReader(f))
    assert [int(r["depression_deg"]) for r in rows] == list(range(15, 46, 5))
    # On flat ground both strips share every geometric factor, so their
    # contrast in a range bin is the sigma0 ratio at that bin's incidence;
    # the bin centre is within half a bin (7.5 m slant) of mid-swath, where
    # sigma0 is evaluated. Measured 0.0063 dB worst; about 3 times that.
    for r in rows:
        image, model = float(r["image_contrast_db"]), float(r["sigma0_contrast_db"])
        assert abs(image - model) < 0.02, r
