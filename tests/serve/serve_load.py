#!/usr/bin/env python3
"""Load test of `ris serve` (docs/serve.md): N concurrent clients on loopback
for a given time, each re-simulating (depression, film, seed) and fetching
the image. Passes when no request failed (a 409 "superseded" is a correct
answer, counted apart) and the server's resident memory at the end is within
25% + 32 MiB of its size after the first seconds. Prints p50/p95 latency.
--no-memory-bound drops the memory condition (the ASan build: its
quarantine of freed blocks, 256 MiB by default, is what would be measured).

Usage: serve_load.py RIS_EXE OUT_DIR [--clients 8] [--seconds 20] [--no-memory-bound]
"""
import argparse
import os
import random
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from serve_harness import Server, percentile  # noqa: E402


def client(server, stop_at, k, results):
    rng = random.Random(k)
    while time.time() < stop_at:
        choice = rng.random()
        if choice < 0.4:
            body = {"depression": f"{rng.uniform(18, 24):.2f} deg"}
        elif choice < 0.8:
            body = {"radar": {"film": {"gamma": round(rng.uniform(0.4, 1.2), 2)}}}
        else:
            body = {"seed": rng.randrange(1000)}
        t0 = time.perf_counter()
        try:
            status, _ = server.request("POST", "/api/simulate", body)
            image_status, png = server.request("GET", "/api/image/slant.png")
            ok = status in (200, 409) and image_status == 200 and png[1:4] == b"PNG"
        except OSError as e:
            status, ok = str(e), False
        results.append((ok, status, time.perf_counter() - t0))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("ris_exe")
    ap.add_argument("out_dir")
    ap.add_argument("--clients", type=int, default=8)
    ap.add_argument("--seconds", type=float, default=20.0)
    ap.add_argument("--no-memory-bound", action="store_true")
    a = ap.parse_args()
    server = Server(a.ris_exe, a.out_dir)
    results = []
    try:
        warm_s = min(3.0, a.seconds / 4)
        stop_at = time.time() + a.seconds
        threads = [threading.Thread(target=client, args=(server, stop_at, k, results))
                   for k in range(a.clients)]
        for t in threads:
            t.start()
        time.sleep(warm_s)
        rss_warm = server.rss_kib()
        health = []
        while time.time() < stop_at:
            t0 = time.perf_counter()
            status, _ = server.request("GET", "/api/health")
            health.append((status, time.perf_counter() - t0))
            time.sleep(0.2)
        for t in threads:
            t.join()
        rss_end = server.rss_kib()
    finally:
        code, out = server.stop()
    failed = [r for r in results if not r[0]]
    superseded = sum(1 for r in results if r[1] == 409)
    lat_ms = [1000 * r[2] for r in results]
    health_ms = [1000 * h[1] for h in health]
    print(f"{a.clients} clients, {a.seconds:.0f} s: {len(results)} simulate+image requests, "
          f"{len(failed)} failed, {superseded} superseded (409)")
    print(f"latency p50 {percentile(lat_ms, 50):.1f} ms, p95 {percentile(lat_ms, 95):.1f} ms; "
          f"health p95 {percentile(health_ms, 95):.1f} ms over {len(health)} checks")
    print(f"server RSS {rss_warm / 1024:.1f} MiB after {warm_s:.0f} s, "
          f"{rss_end / 1024:.1f} MiB at the end; exit code {code} after SIGINT")
    ok = True
    if failed or any(h[0] != 200 for h in health):
        print(f"FAIL: failed requests, e.g. {failed[:3]}")
        ok = False
    if not a.no_memory_bound and rss_end > 1.25 * rss_warm + 32 * 1024:
        print("FAIL: server memory grew")
        ok = False
    if code != 0:
        print(f"FAIL: server exit code {code} after SIGINT:\n{out}")
        ok = False
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
