#!/usr/bin/env python3
"""Writes data/scenes/town.toml: the shipped example town (issue 32).

A 1 km x 1 km scene of 1 m cells on a flat plain: 240 buildings on a grid of
streets (blocks of 60 m with 15-25 m streets), footprints 18-40 m, 2-8
storeys, a few L-shaped ones, a park with four trihedral corner reflectors
pointed at a north-flying right-looking radar 7 km west at 6 km altitude
(data/radars/sar-x-band-town.toml), and fields around. Deterministic: a
fixed seed, so the file it writes is the one in the repository.

    python3 scripts/make-town-scene.py > data/scenes/town.toml
"""
import math
import random

rng = random.Random(32)
print("""# town: the example scene of issue 32 (docs/objects.md), written by
# scripts/make-town-scene.py: 240 buildings and four corner reflectors on a
# 1 km x 1 km plain of 1 m cells. Simulate the description itself (ris scene
# build keeps only the painted grid):
#   ris simulate --scene data/scenes/town.toml \\
#                --radar data/radars/sar-x-band-town.toml --out out-town
name = "town"
description = "240 buildings and four corner reflectors on a plain (issue 32)"

[grid]
rows = 1000
cols = 1000
cell_size = 1.0
base_elevation = 0
base_category = 3

[category_names]
1 = "wheat stubble (streets and yards)"
3 = "short alfalfa (fields)"
5 = "tall corn (the park)"
8 = "short soybeans (roofs)"

[[object]]
type = "patch"
x = 150
y = 150
length = 700
width = 700
category = 1

[[object]]
type = "patch"
x = 430
y = 430
length = 140
width = 140
category = 5""")

n = 0
block = 60.0
for i in range(10):
    for j in range(10):
        x0 = 160 + i * 70.0
        y0 = 160 + j * 70.0
        if 4 <= i <= 5 and 4 <= j <= 5:
            continue  # the park
        for k in range(3 if (i + j) % 4 else 2):
            if n >= 240:
                break
            w = rng.uniform(18, 28)
            d = rng.uniform(15, block / (3 if (i + j) % 4 else 2) - 2)
            x = x0 + rng.uniform(0, block - w)
            y = y0 + k * block / (3 if (i + j) % 4 else 2) + 1
            storeys = rng.randint(2, 8)
            if rng.random() < 0.15:
                # An L: two wings.
                fp = [[x, y], [x + w, y], [x + w, y + d * 0.4], [x + w * 0.4, y + d * 0.4],
                      [x + w * 0.4, y + d], [x, y + d]]
            else:
                fp = [[x, y], [x + w, y], [x + w, y + d], [x, y + d]]
            wall = "brick" if rng.random() < 0.4 else "concrete"
            print("\n[[object]]")
            print('type = "building"')
            print("footprint = [" + ", ".join("[%.1f, %.1f]" % (a, b) for a, b in fp) + "]")
            print("storeys = %d" % storeys)
            print("category = 8")
            if wall != "concrete":
                print('wall_material = "%s"' % wall)
            n += 1

# Reflectors: apex on the radar (7 km west at 6 km): azimuth 180, tilt atan(6000 / u).
for (x, y) in [(450, 450), (550, 450), (450, 550), (550, 550)]:
    u = 7000.0 + x
    print("\n[[object]]")
    print('type = "reflector"')
    print('shape = "trihedral"')
    print("x = %.1f\ny = %.1f" % (x, y))
    print("size = 1.0")
    print("azimuth = 180")
    print("tilt = %.2f" % math.degrees(math.atan2(6000.0, u)))
