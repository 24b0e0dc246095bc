"""`cmake --install BUILD --prefix P` puts every file under P, the Python
package included, and the installed package imports from
P/lib/python3/dist-packages (run by ctest: python_install_prefix).

The install is staged with DESTDIR, so a rule with an absolute destination
outside the prefix lands in the staging folder (and is reported) instead of
changing the system.

    check_install_prefix.py CMAKE BUILD_DIR PYTHON
"""

import os
import pathlib
import subprocess
import sys
import tempfile

PREFIX = "/opt/ris-install-check"  # never written: the files go under DESTDIR


def main(cmake, build_dir, python):
    with tempfile.TemporaryDirectory() as tmp:
        stage = pathlib.Path(tmp) / "stage"
        env = dict(os.environ, DESTDIR=str(stage))
        subprocess.run([cmake, "--install", build_dir, "--prefix", PREFIX], env=env, check=True,
                       stdout=subprocess.DEVNULL)
        root = stage / PREFIX.lstrip("/")
        files = [p for p in stage.rglob("*") if p.is_file() or p.is_symlink()]
        outside = [str(p.relative_to(stage)) for p in files if root not in p.parents]
        if outside:
            print("installed outside the prefix " + PREFIX + ":\n  /" + "\n  /".join(outside))
            return 1
        package = root / "lib" / "python3" / "dist-packages"
        if not (package / "ris" / "__init__.py").is_file():
            print(f"no Python package in {PREFIX}/lib/python3/dist-packages/ris")
            return 1
        # As the README says: PYTHONPATH=<prefix>/lib/python3/dist-packages.
        # From another folder, so the build tree's package cannot be the one found.
        code = ("import ris, pathlib, sys; p = pathlib.Path(ris.__file__).resolve(); "
                "sys.exit(0 if str(p).startswith(sys.argv[1]) else 'imported ' + str(p)); ")
        env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "RIS_DATA")}
        env["PYTHONPATH"] = str(package)
        subprocess.run([python, "-c", code, str(package.resolve())], env=env, cwd=tmp, check=True)
        # Its data: the installed share/ris/data beside the package.
        code = ("import ris, pathlib, sys; d = pathlib.Path(ris.data_dir()).resolve(); "
                "assert d == pathlib.Path(sys.argv[1]), d; "
                "assert ris.load_radar(d / 'radars' / 'seed-fig4-5.toml').info()['range_bins'] > 0")
        subprocess.run([python, "-c", code, str((root / "share" / "ris" / "data").resolve())],
                       env=env, cwd=tmp, check=True)
        print(f"{len(files)} files, all under {PREFIX}; the package imports from it")
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
