#!/usr/bin/env python3
"""Mutation check (docs/testing.md, "Mutation check"): applies each one-line
mutant of tests/mutants/mutants.toml to the core, rebuilds, runs the tests
named for it and reports whether they fail (the mutant is killed) or pass
(it survives: a wrong change the suite would not notice).

  scripts/mutants.py [--build DIR] [--only NAME ...] [--check]

--check only verifies that every mutant's `from` text occurs exactly once in
its file (ctest runs this, so moving code without updating the list fails).
The source tree is restored after each mutant, also on Ctrl-C. Exit status:
0 when every mutant is killed, 1 otherwise, 2 for a bad list.
Plain Python 3 (tomllib), no other module.
"""
import argparse
import pathlib
import subprocess
import sys
import time
import tomllib

ROOT = pathlib.Path(__file__).resolve().parent.parent
LIST = ROOT / "tests" / "mutants" / "mutants.toml"


def load():
    with open(LIST, "rb") as f:
        doc = tomllib.load(f)
    mutants = doc.get("mutant", [])
    errors = []
    for i, m in enumerate(mutants):
        for key in ("name", "file", "from", "to", "tests", "why"):
            if key not in m:
                errors.append(f"{LIST}: mutant[{i}] lacks `{key}`")
        if "file" in m and "from" in m:
            path = ROOT / m["file"]
            if not path.is_file():
                errors.append(f"{LIST}: mutant {m.get('name')}: no file {m['file']}")
                continue
            n = path.read_text().count(m["from"])
            if n != 1:
                errors.append(
                    f"{LIST}: mutant {m.get('name')}: `from` occurs {n} times in {m['file']} "
                    "(expected exactly once: the code moved; update the mutant)")
    return mutants, errors


def run(cmd, **kw):
    return subprocess.run(cmd, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True, **kw)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--only", nargs="*")
    ap.add_argument("--check", action="store_true")
    a = ap.parse_args()
    mutants, errors = load()
    if errors:
        print("\n".join(errors), file=sys.stderr)
        return 2
    if a.check:
        print(f"{len(mutants)} mutants, each `from` found once")
        return 0
    if a.only:
        mutants = [m for m in mutants if m["name"] in a.only]
    build = ROOT / a.build
    results = []
    for m in mutants:
        path = ROOT / m["file"]
        original = path.read_text()
        t0 = time.time()
        try:
            path.write_text(original.replace(m["from"], m["to"], 1))
            b = run(["cmake", "--build", str(build), "--target", "ris", "ris_tests"])
            if b.returncode != 0:
                verdict = "killed (does not build)"
            else:
                t = run([str(build / "ris_tests"), f"--gtest_filter={m['tests']}"])
                if "0 tests, listed below" in t.stdout or "Running 0 tests" in t.stdout:
                    verdict = "ERROR: the filter matches no test"
                else:
                    verdict = "killed" if t.returncode != 0 else "SURVIVED"
        finally:
            path.write_text(original)
        results.append((m["name"], verdict, time.time() - t0))
        print(f"{m['name']:<34} {verdict:<26} {time.time() - t0:5.0f} s", flush=True)
    # Rebuild the unmutated tree so the build folder is left as it was.
    run(["cmake", "--build", str(build), "--target", "ris", "ris_tests"])
    survived = [r for r in results if not r[1].startswith("killed")]
    print(f"{len(results) - len(survived)} of {len(results)} mutants killed")
    return 1 if survived else 0


if __name__ == "__main__":
    sys.exit(main())
