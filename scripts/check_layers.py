#!/usr/bin/env python3
"""Fail on an include that points up the layer order (docs/design.md, "Layers").

Every library source (src/<layer>/..., include/ris/<layer>/...) may include
ris headers of its own layer or a lower one only. apps/ sits on top; tests
(*_test.cpp, tests/) and bench/ may include anything and are not checked.

Usage: scripts/check_layers.py [repo_root]   (exit 1 and one line per upward
include, naming file, line and both layers)
"""
import pathlib
import re
import sys

# Lowest first (src/kernels/: see KERNEL_LAYER). analysis (the study and the
# sensitivity analysis) runs simulations and compares them, so it sits above
# sim. perf holds the bench scene set-up (builds a scene, a radar and runs the
# simulation), so it sits above sim too: it may include sim, and only apps and
# benches include it. serve is the HTTP server of `ris serve`
# (it runs simulations through sim and draws through image). sensors_eo
# (optical and thermal sensors, docs/sensors.md) casts shadow rays through the
# objects layer's Embree scene, so it sits above objects.
LAYERS = ["util", "io", "scene", "sensor", "backscatter", "geometry", "objects",
          "sensors_eo", "image",
          "sim", "analysis", "perf", "serve", "apps"]
RANK = {name: i for i, name in enumerate(LAYERS)}
# The SIMD kernels (src/kernels/<folder>/, beside their portable twins) are
# each part of the stage they serve; the SIMD helpers (simd/, and the clone
# macros in include/ris/kernels/) are utilities.
KERNEL_LAYER = {"simd": "util", "util": "util", "gather": "geometry", "geometry": "geometry",
                "image": "image", "sim": "sim"}
# Inside sim, its rooms (src/sim/<room>/, docs/design.md "The rooms of
# src/sim"), lowest first: a room's files include its own room or lower ones
# through "sim/<room>/..."; the public headers (include/ris/sim/) are the
# layer's face and are not ranked.
SIM_ROOMS = ["engine", "targets", "sources", "modes", "stream", "run"]
SIM_ROOM_RANK = {name: i for i, name in enumerate(SIM_ROOMS)}
SIM_ROOM_INCLUDE = re.compile(r'^\s*#\s*include\s*"sim/([a-z_]+)/')
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]ris/([a-z_]+)/(?:([a-z_]+)/)?')
LOCAL_INCLUDE = re.compile(r'^\s*#\s*include\s*"(?:\.\./)*(?:src/)?([a-z_]+)/(?:([a-z_]+)/)?[^"]+"')


def kernel_layer(folder):
    return KERNEL_LAYER.get(folder, f"kernels/{folder}")


def layer_of(path: pathlib.Path, root: pathlib.Path):
    parts = path.relative_to(root).parts
    if parts[0] in ("apps", "python"):  # the CLI and the Python module sit on top
        return "apps"
    if parts[:2] == ("src", "kernels") and len(parts) > 3:
        return kernel_layer(parts[2])
    if parts[:3] == ("include", "ris", "kernels"):
        return "util"
    if parts[0] == "src" and len(parts) > 2:
        return parts[1]
    if parts[:2] == ("include", "ris") and len(parts) > 3:
        return parts[2]
    return None


def main() -> int:
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    files = [p for d in ("src", "include", "apps", "python") for p in (root / d).rglob("*")
             if p.suffix in (".h", ".hpp", ".cpp") and not p.name.endswith("_test.cpp")]
    errors = []
    for path in sorted(files):
        own = layer_of(path, root)
        if own is None:
            continue
        if own not in RANK:
            errors.append(f"{path.relative_to(root)}: layer '{own}' is not in the "
                          f"order {' < '.join(LAYERS)} (scripts/check_layers.py)")
            continue
        parts = path.relative_to(root).parts
        room = parts[2] if parts[:2] == ("src", "sim") and len(parts) > 3 else None
        if parts[:2] == ("src", "sim") and len(parts) == 3:
            errors.append(f"{path.relative_to(root)}: a file of src/sim outside its rooms "
                          f"({', '.join(SIM_ROOMS)})")
        if room is not None and room not in SIM_ROOM_RANK:
            errors.append(f"{path.relative_to(root)}: room '{room}' is not in the order "
                          f"{' < '.join(SIM_ROOMS)} (scripts/check_layers.py)")
            room = None
        for n, line in enumerate(path.read_text().splitlines(), 1):
            r = SIM_ROOM_INCLUDE.match(line) if room is not None else None
            if r and r.group(1) in SIM_ROOM_RANK and SIM_ROOM_RANK[r.group(1)] > SIM_ROOM_RANK[room]:
                errors.append(f"{path.relative_to(root)}:{n}: sim/{room} includes sim/"
                              f"{r.group(1)} (a room above): {line.strip()}")
            m = INCLUDE.match(line)
            if m and m.group(1) == "kernels":
                target = "util"  # include/ris/kernels/: the clone macros
            elif m:
                target = m.group(1)
            else:
                m = LOCAL_INCLUDE.match(line)
                if not m:
                    continue
                target = kernel_layer(m.group(2)) if m.group(1) == "kernels" else m.group(1)
            if target not in RANK:
                continue
            if RANK[target] > RANK[own]:
                errors.append(f"{path.relative_to(root)}:{n}: {own} includes "
                              f"{target} (upward): {line.strip()}")
    for e in errors:
        print(e)
    if errors:
        print(f"{len(errors)} upward include(s); order: {' < '.join(LAYERS)}")
        return 1
    print(f"layers ok: {' < '.join(LAYERS)}; sim's rooms: {' < '.join(SIM_ROOMS)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
