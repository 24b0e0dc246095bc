"""ris.study: the frequency/polarisation study (``ris study``, docs/study.md)
from Python, through the code the command line runs (the same bytes)."""

import csv
import io
import json
import math
import numbers
import os

import numpy as np

from . import _ris

# categories.csv / separability.csv / separability_bins.csv columns that are
# text, whole numbers or flags; every other column is a float (an empty
# field, a value the file leaves out, is NaN).
_TEXT_COLUMNS = {"run", "band", "polarisation", "name", "name_a", "name_b"}
_INT_COLUMNS = {"panel", "category", "category_a", "category_b", "pixels", "bins", "pixels_a",
                "pixels_b"}
_FLAG_COLUMNS = {"separated"}


def _error(key, message):
    err = _ris.InputError(message)
    err.file = ""
    err.key = key
    return err


def _typed(column, text):
    if column in _TEXT_COLUMNS:
        return text
    if column in _INT_COLUMNS:
        return int(text)
    if column in _FLAG_COLUMNS:
        return text == "1"
    return float(text) if text else math.nan


def _rows(csv_text):
    """A CSV table as a list of dicts, one per row, values typed."""
    return [{k: _typed(k, v) for k, v in row.items()}
            for row in csv.DictReader(io.StringIO(csv_text))]


def _path(name, value, kinds=()):
    """A path argument: a str or os.PathLike, or an object of `kinds` with a
    .path read from a file (a Scene or Radar loaded with load_*)."""
    if value is None:
        return None
    if isinstance(value, kinds):
        if value.path:
            return str(value.path)
        raise _error(name, f"{name}: the study reads its {name} from a file: give a path (this "
                           f"{type(value).__name__} was not loaded from one; write it first)")
    if isinstance(value, (str, os.PathLike)):
        return os.fspath(value)
    raise _error(name, f"{name}: expected a path, got {value!r}")


def _bands(bands):
    """'F:P, F:P' from a string or a list of 'F:P' strings or (F, P) pairs."""
    if bands is None or isinstance(bands, str):
        return bands
    expected = ("bands: expected \"F:P, F:P\" or a list of \"F:P\" strings or (frequency, "
                "polarisation) pairs such as [(\"8.6 GHz\", \"HH\")], got {!r}")
    try:
        entries = list(bands)
    except TypeError:
        raise _error("bands", expected.format(bands)) from None
    out = []
    for e in entries:
        if isinstance(e, str):
            out.append(e)
        elif isinstance(e, (tuple, list)) and len(e) == 2 and all(isinstance(x, str) for x in e):
            out.append(f"{e[0]}:{e[1]}")
        else:
            raise _error("bands", expected.format(bands))
    return ", ".join(out)


def _range_fraction(value):
    if value is None:
        return None
    expected = f"range_fraction: expected (lo, hi), fractions of the swath such as " \
               f"(0.3333, 0.6667), got {value!r}"
    if isinstance(value, (str, bytes)):
        raise _error("range_fraction", expected)
    try:
        lo, hi = value
    except (TypeError, ValueError):
        raise _error("range_fraction", expected) from None
    for x in (lo, hi):
        if isinstance(x, bool) or not isinstance(x, numbers.Real) or not math.isfinite(x):
            raise _error("range_fraction", expected)
    return float(lo), float(hi)


def _incidence_bin(value):
    if value is None or isinstance(value, str):
        return value
    raise _error("incidence_bin", f"incidence_bin: expected an angle with its unit such as "
                                  f"\"1 deg\" or \"0.02 rad\", got {value!r}")


def _whole(name, value, what, optional=False):
    if optional and value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < 0:
        raise _error(name, f"{name}: expected {what}, got {value!r}")
    return int(value)


class StudyResult:
    """One study: its panels (slant-range greytones, lines x bins), the
    tables ``ris study`` writes as lists of dicts (values as the files give
    them; NaN where the file leaves a field empty) and its metadata."""

    def __init__(self, impl):
        self._impl = impl
        panels = impl.panels
        #: the bands' labels, in panel order ("8.6 GHz HH")
        self.bands = [p["band"] for p in panels]
        #: the bands' frequencies (Hz) and polarisations
        self.frequencies_hz = [p["frequency_hz"] for p in panels]
        self.polarisations = [p["polarisation"] for p in panels]
        #: one uint8 array per panel, lines x bins (panel_<i>_<band>.png)
        self.slant_grey = [p["slant_grey"] for p in panels]
        #: categories.csv: per (panel, category) pixels, mean_grey, ...
        self.categories = _rows(impl.categories_csv)
        #: separability.csv: per (run, panel, pair) delta_db, z, jm, ...
        self.separability = _rows(impl.separability_csv)
        #: separability_bins.csv: the same per incidence bin
        self.separability_bins = _rows(impl.separability_bins_csv)
        #: metadata.json as a dict
        self.metadata = json.loads(impl.metadata_json)
        #: the study file's name ("" without one)
        self.title = impl.title

    verdict = property(lambda self: self.metadata["verdict"],
                       doc="\"best band: 8.6 GHz HH\" or \"no band separates these categories\".")

    @property
    def best_band(self):
        """The best band's label, or None when no band separates the categories."""
        best = self.metadata["best_panel"]
        return None if best is None else best["band"]

    @property
    def null_check_passed(self):
        """True/False, or None when the null check was not run."""
        check = self.metadata["null_check"]
        return None if check is None else check["passed"]

    def write(self, out_dir):
        """Writes the products ``ris study --out`` writes into out_dir (one
        folder, written as a whole)."""
        self._impl.write(os.fspath(out_dir))

    def to_xarray(self):
        """The study as an ``xarray.Dataset`` (needs python3-xarray).

        slant_grey on (band, line, bin) (line, bin: indices, as the panel
        PNGs); categories.csv's pixels, mean_grey, std_grey, mean_power_dbw on
        (band, category); separability.csv's bins, delta_db, z, jm, jm_noise,
        separated on (run, band, pair) with category_a, category_b on pair;
        score on (band). attrs: verdict, best_band ("" when none), metadata
        (metadata.json as a JSON string).
        """
        from . import _xarray
        xr = _xarray()
        cats = sorted({r["category"] for r in self.categories})
        names = {r["category"]: r["name"] for r in self.categories}
        pairs = sorted({(r["category_a"], r["category_b"]) for r in self.separability})
        runs = [r for r in ("library", "null") if any(s["run"] == r for s in self.separability)]
        nb = len(self.bands)
        data = {"slant_grey": (("band", "line", "bin"), np.stack(self.slant_grey))}
        for col in ("pixels", "mean_grey", "std_grey", "mean_power_dbw"):
            a = np.full((nb, len(cats)), np.nan)
            for r in self.categories:
                a[r["panel"] - 1, cats.index(r["category"])] = r[col]
            data[col] = (("band", "category"), a)
        for col in ("bins", "delta_db", "z", "jm", "jm_noise", "separated"):
            a = np.full((len(runs), nb, len(pairs)), np.nan)
            for r in self.separability:
                a[runs.index(r["run"]), r["panel"] - 1,
                  pairs.index((r["category_a"], r["category_b"]))] = r[col]
            data[col] = (("run", "band", "pair"), a)
        data["score"] = ("band", [p["separability"]["score"] for p in self.metadata["panels"]])
        coords = {"band": self.bands,
                  "frequency_hz": ("band", self.frequencies_hz, {"units": "Hz"}),
                  "polarisation": ("band", self.polarisations),
                  "category": cats,
                  "category_name": ("category", [names[c] for c in cats]),
                  "run": runs,
                  "category_a": ("pair", [p[0] for p in pairs]),
                  "category_b": ("pair", [p[1] for p in pairs])}
        attrs = {"verdict": self.verdict, "best_band": self.best_band or "",
                 "metadata": json.dumps(self.metadata)}
        return xr.Dataset(data, coords=coords, attrs=attrs)

    def __repr__(self):
        return f"<ris.StudyResult {len(self.bands)} bands: {self.verdict}>"


def study(study=None, scene=None, radar=None, backscatter=None, bands=None, range_fraction=None,
          incidence_bin=None, null_check=True, seed=None, out=None, panel_size=360, threads=0,
          progress=None):
    """The frequency/polarisation study, as ``ris study`` (docs/study.md):
    one scene and track imaged at several (frequency, polarisation) bands,
    each pair of categories compared at matched geometry.

    study: a study file (data/studies/*.toml) giving the inputs and window;
        an argument given here wins over it (``--study``).
    scene, radar, backscatter: paths (or a Scene / Radar loaded from a
        file); None: the study file's, else the standard scene, the
        figure-7 radar (data/radars/seed-fig7.toml), the standard library.
    bands: "1.25 GHz:HH, 8.6 GHz:VV" or a list of "F:P" strings or
        (frequency, polarisation) pairs; None: the file's, else the defaults.
    range_fraction: (lo, hi), fractions of the swath (``--range-fraction``).
    incidence_bin: the bins' width, an angle with its unit ("1 deg").
    null_check: False skips the null runs (``--no-null-check``).
    seed: fading seed (None: the file's, else 1); threads: 0 all cores.
    out: a folder to write the products into (``--out``); None: none
        written (``result.write(folder)`` later).
    panel_size: the contact sheet's panel size, pixels (``--panel-size``).
    progress: optional callable(stage: str, fraction_done: float).

    Returns a StudyResult. Bad input raises InputError naming the argument
    ("bands", "range_fraction", ...) before anything is simulated.
    """
    from . import Radar, Scene
    q = _ris._StudyRequest()
    q.study_file = _path("study", study) or ""
    q.scene = _path("scene", scene, (Scene,))
    q.radar = _path("radar", radar, (Radar,))
    q.backscatter = _path("backscatter", backscatter)
    q.bands = _bands(bands)
    fractions = _range_fraction(range_fraction)
    if fractions is not None:
        q.range_lo_fraction, q.range_hi_fraction = fractions
    q.incidence_bin = _incidence_bin(incidence_bin)
    if not isinstance(null_check, bool):
        raise _error("null_check", f"null_check: expected True or False, got {null_check!r}")
    q.null_check = null_check
    q.seed = _whole("seed", seed, "a whole number >= 0", optional=True)
    q.panel_px = _whole("panel_size", panel_size, "a number of pixels, 16 or more")
    q.threads = _whole("threads", threads, "0 (all cores) or more")
    if progress is not None and not callable(progress):
        raise _error("progress", f"progress: expected a callable(stage, fraction), got {progress!r}")
    out_dir = "" if out is None else os.fspath(out)
    return StudyResult(_ris._study(q, progress, out_dir))
