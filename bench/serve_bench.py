#!/usr/bin/env python3
"""`ris serve` latency, request to image bytes (docs/serve.md, issue 16's
goals: full re-simulation of the standard scene p95 < 100 ms, film-only
p95 < 30 ms on the 2-core machine). One client, sequential: each sample is
POST /api/simulate then GET /api/image/slant.png.

  full       the near-range depression alternates 20 / 20.5 deg (geometry,
             mean power and image all recomputed)
  film-only  the film gamma alternates 0.6 / 0.65 (re-rendered from the kept
             mean power)

Usage: bench/serve_bench.py [RIS_EXE] [--samples 60]
"""
import argparse
import os
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests",
                                "serve"))
from serve_harness import Server, percentile  # noqa: E402


def measure(server, bodies, samples):
    times_ms = []
    for i in range(samples + 3):
        t0 = time.perf_counter()
        status, run = server.post("/api/simulate", bodies[i % len(bodies)])
        image_status, png = server.request("GET", "/api/image/slant.png")
        dt = 1000 * (time.perf_counter() - t0)
        if status != 200 or image_status != 200:
            raise RuntimeError(f"request failed: {status} {run}")
        if i >= 3:  # the first few warm the caches
            times_ms.append(dt)
    return times_ms, run


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("ris_exe", nargs="?", default="build/ris")
    ap.add_argument("--samples", type=int, default=60)
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as out:
        server = Server(a.ris_exe, out)
        try:
            full, run_full = measure(server, [{"depression": "20.5 deg"},
                                              {"depression": "20 deg"}], a.samples)
            film, run_film = measure(server, [{"radar": {"film": {"gamma": 0.65}}},
                                              {"radar": {"film": {"gamma": 0.6}}}], a.samples)
        finally:
            server.stop()
    assert not run_full["film_only"] and run_film["film_only"]
    for name, t, goal in (("full re-simulation", full, 100), ("film-only", film, 30)):
        print(f"{name:20s} p50 {percentile(t, 50):6.1f} ms  p95 {percentile(t, 95):6.1f} ms  "
              f"(goal p95 < {goal} ms; {len(t)} samples)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
