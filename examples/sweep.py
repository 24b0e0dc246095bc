#!/usr/bin/env python3
"""A depression-angle sweep from Python, no command line involved.

A flat scene of two crops in strips along the track (wheat stubble and tall
corn, the standard backscatter library) is imaged by a small X-band SLAR at
mid-swath depression angles of 15 to 45 deg; for each, the contrast between
the two strips in the mean-power image at mid-swath is set beside the
library's sigma0 ratio at the same incidence. Writes sweep.csv, and sweep.png when matplotlib
is installed (headless: the Agg backend).

    PYTHONPATH=build/python /usr/bin/python3 examples/sweep.py [OUT_DIR]
"""

import csv
import math
import pathlib
import sys

import numpy as np

import ris

C_M_PER_S = 299792458.0
WHEAT, CORN = 1, 5  # category ids of data/backscatter/ku-geometric.toml


def two_crop_scene(rows=120, cols=300, cell_m=10.0):
    """Flat ground; the northern half wheat stubble, the southern tall corn."""
    category = np.full((rows, cols), WHEAT, dtype=np.uint16)
    category[rows // 2:, :] = CORN
    return ris.Scene.from_arrays(np.zeros((rows, cols)), category, cell_m)


def radar_at(depression_deg, scene_width_m, near_edge_m=4000.0):
    """A 9.4 GHz SLAR whose mid-swath depression is depression_deg, with a
    sweep covering the scene's width (ground range near_edge_m onwards)."""
    mid_m = near_edge_m + scene_width_m / 2
    altitude_m = mid_m * math.tan(math.radians(depression_deg))
    near_r = math.hypot(altitude_m, near_edge_m) - 50.0
    far_r = math.hypot(altitude_m, near_edge_m + scene_width_m) + 50.0
    return ris.Radar.from_dict({
        "mode": "slar",
        "frequency": "9.4 GHz",
        "polarisation": "HH",
        "pulse_width": "0.1 us",
        "sweep_delay": f"{2 * near_r / C_M_PER_S:.9e} s",
        "sweep_length": f"{2 * (far_r - near_r) / C_M_PER_S:.9e} s",
        "azimuth_beamwidth": "5 mrad",
        "track": {"altitude": f"{altitude_m:.3f} m", "heading": "0 deg",
                  "near_edge_distance": f"{near_edge_m} m"},
    })


def main(out_dir):
    out_dir.mkdir(parents=True, exist_ok=True)
    scene = two_crop_scene()
    rows, cols = scene.shape
    width_m = cols * scene.cell_size_m[0]
    table = []
    for depression_deg in range(15, 46, 5):
        radar = radar_at(depression_deg, width_m)
        result = ris.simulate(scene, radar, seed=1)
        # The range bin at mid-swath, where the depression is depression_deg.
        altitude_m = radar.params()["track"]["altitude_m"]
        mid_r = math.hypot(altitude_m, 4000.0 + width_m / 2)
        b = int(np.argmin(np.abs(result.slant_range_m - mid_r)))
        power = result.mean_power_w[:, b]
        lines = power.size
        # Lines well inside each strip (the beam footprint is tens of metres);
        # the track flies north, so the first lines image the southern strip.
        corn = np.mean(power[lines // 8: 3 * lines // 8])
        wheat = np.mean(power[5 * lines // 8: 7 * lines // 8])
        incidence_deg = 90.0 - depression_deg  # mid-swath, flat ground
        s_wheat = ris.sigma0(WHEAT, incidence_deg, 9.4e9, "HH")
        s_corn = ris.sigma0(CORN, incidence_deg, 9.4e9, "HH")
        table.append({
            "depression_deg": depression_deg,
            "image_contrast_db": 10 * math.log10(corn / wheat),
            "sigma0_contrast_db": 10 * math.log10(float(s_corn) / float(s_wheat)),
        })
        print(f"depression {depression_deg:2d} deg: corn/wheat {table[-1]['image_contrast_db']:6.2f} dB "
              f"in the image, {table[-1]['sigma0_contrast_db']:6.2f} dB in sigma0")
    with open(out_dir / "sweep.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(table[0]))
        w.writeheader()
        w.writerows(table)
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print(f"wrote {out_dir / 'sweep.csv'} (matplotlib not installed: no plot)")
        return
    d = [t["depression_deg"] for t in table]
    plt.plot(d, [t["image_contrast_db"] for t in table], "o-", label="image (mean power)")
    plt.plot(d, [t["sigma0_contrast_db"] for t in table], "--", label="sigma0 at mid-swath")
    plt.xlabel("depression angle (deg)")
    plt.ylabel("tall corn / wheat stubble (dB)")
    plt.legend()
    plt.savefig(out_dir / "sweep.png", dpi=100)
    print(f"wrote {out_dir / 'sweep.csv'} and {out_dir / 'sweep.png'}")


if __name__ == "__main__":
    main(pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "sweep-out"))
