"""ris: a radar image simulator (SLAR, stripmap SAR, PPI), from Python.

The same C++ library as the ``ris`` command line, with numpy arrays in and
out (docs/python.md)::

    import ris
    scene = ris.load_scene("data/scenes/ku-geometric.toml")
    radar = ris.load_radar("data/radars/seed-fig4-5.toml")
    result = ris.simulate(scene, radar, seed=1)
    grey = result.slant_grey            # uint8, lines x bins
    result.write("out")                 # the files `ris simulate` writes

Units are SI and carried in names: metres (``_m``), watts (``_w``), hertz
(``_hz``), degrees (``_deg``). Bad input raises :class:`InputError` (a
``ValueError``) with the command line's message; a missing file raises
:class:`InputFileNotFoundError` (also a ``FileNotFoundError``).
"""

import math
import numbers
import warnings as _warnings

import numpy as np

from . import _ris
from ._ris import InputError, InputFileNotFoundError

__version__ = _ris.__version__
__all__ = [
    "InputError",
    "InputFileNotFoundError",
    "Scene",
    "Radar",
    "Result",
    "load_scene",
    "load_radar",
    "simulate",
    "sigma0",
    "list_models",
]


def _error(key, message):
    err = InputError(message)
    err.file = ""
    err.key = key
    return err


def _grid(name, value, dtype, shape=None):
    """A C-contiguous 2-D array of ``dtype`` (converted when the values fit)."""
    a = np.asarray(value)
    if a.ndim != 2:
        raise _error(name, f"{name}: expected a 2-D array (rows, cols), got {a.ndim} dimensions")
    if shape is not None and a.shape != shape:
        raise _error(name, f"{name}: expected shape {shape} like elevation_m, got {a.shape}")
    if a.dtype != dtype and np.issubdtype(dtype, np.integer):
        if not (np.issubdtype(a.dtype, np.integer) or np.issubdtype(a.dtype, np.bool_)):
            if not np.all(np.isfinite(a)) or np.any(a != np.round(a)):
                raise _error(name, f"{name}: expected whole numbers, got {a.dtype} with fractions or NaN")
        info = np.iinfo(dtype)
        if a.size and (a.min() < info.min or a.max() > info.max):
            raise _error(name, f"{name}: values must lie in [{info.min}, {info.max}]")
    return np.ascontiguousarray(a, dtype=dtype)


class Scene:
    """A ground-truth scene: elevation (m), backscatter category and validity
    on a north-up grid (row 0 north). Arrays are read-only numpy views of the
    C++ scene (no copy)."""

    def __init__(self, _impl):
        self._impl = _impl

    @classmethod
    def from_arrays(cls, elevation_m, category, cell_size_m, valid=None, crs=None, origin=None):
        """A scene from numpy arrays.

        elevation_m: 2-D heights in metres (converted to float32); NaN cells
            are no data (refused where ``valid`` says 1).
        category: 2-D backscatter category ids, 0..65534, same shape.
        cell_size_m: cell size in metres (square cells), > 0.
        valid: optional 2-D mask, nonzero = data (default: every non-NaN cell).
        crs: optional CRS as WKT or "EPSG:n" (stored as given); None: a local frame.
        origin: (x, y) in metres of the grid's north-west corner; default puts
            the south-west corner at (0, 0).
        """
        elev = _grid("elevation_m", elevation_m, np.float32)
        cat = _grid("category", category, np.uint16, elev.shape)
        nan = np.isnan(elev)
        if valid is None:
            ok = ~nan
        else:
            ok = _grid("valid", valid, np.bool_, elev.shape)
            if np.any(ok & nan):
                raise _error("elevation_m", "elevation_m: NaN in cells that valid marks as data")
        if np.any(np.isinf(elev)):
            raise _error("elevation_m", "elevation_m: infinite heights")
        if np.any(ok & (cat == 0xFFFF)):
            raise _error("category", "category: 65535 is reserved for no data")
        try:
            cell = float(cell_size_m)
        except (TypeError, ValueError):
            raise _error("cell_size_m", f"cell_size_m: expected a number of metres, got {cell_size_m!r}")
        if not (cell > 0.0 and math.isfinite(cell)):
            raise _error("cell_size_m", f"cell_size_m: expected a cell size > 0 m, got {cell_size_m!r}")
        if origin is None:
            origin = (0.0, elev.shape[0] * cell)
        ox, oy = (float(v) for v in origin)
        elev = np.where(ok, elev, np.float32(0.0)).astype(np.float32)
        cat = np.where(ok, cat, np.uint16(0xFFFF)).astype(np.uint16)
        impl = _ris._scene_from_arrays(elev, cat, ok.astype(np.uint8), cell, ox, oy, crs or "")
        return cls(impl)

    @property
    def elevation_m(self):
        """Heights in metres above the datum (float32, rows x cols, read-only)."""
        return self._impl.elevation_m

    @property
    def category(self):
        """Backscatter category ids (uint16, rows x cols; 65535 = no data)."""
        return self._impl.category

    @property
    def valid(self):
        """1 where the scene has data, 0 elsewhere (uint8, rows x cols)."""
        return self._impl.valid

    @property
    def shape(self):
        """(rows, cols)."""
        return (self._impl.rows, self._impl.cols)

    @property
    def cell_size_m(self):
        """(dx, dy): cell size in metres along x (east) and y (north)."""
        return (self._impl.dx_m, self._impl.dy_m)

    @property
    def crs(self):
        """The CRS as WKT, or None for a local frame."""
        return self._impl.crs or None

    @property
    def geotransform(self):
        """GDAL's geotransform (x0, dx, 0, y0, 0, -dy), metres."""
        return self._impl.geotransform

    @property
    def path(self):
        """The file it was read from, or None."""
        return self._impl.path or None

    def write(self, path):
        """Writes the scene as a ris scene GeoTIFF (as ``ris scene build -o``)."""
        self._impl.write(str(path))

    def __repr__(self):
        return f"<ris.Scene {self.shape[1]} x {self.shape[0]} cells of {self.cell_size_m[0]:g} m>"


def load_scene(path, category_path=None, cell_size_m=None, crs=None, category=21):
    """A scene from a file: a description (.toml), a ris scene GeoTIFF, or a
    DEM (any GDAL raster). A DEM in a geographic CRS is reprojected into UTM
    as ``ris scene import`` does (cell_size_m, crs and category are its
    options; category defaults to 21, grass of
    data/backscatter/generic-terrain.toml, as in ``ris scene import``);
    category_path: a category raster on the DEM's grid."""
    return Scene(_ris._load_scene(str(path), category_path, cell_size_m, crs, int(category)))


def _toml_value(v, key):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, numbers.Integral):
        return str(int(v))
    if isinstance(v, numbers.Real):
        f = float(v)
        if not math.isfinite(f):
            raise _error(key, f"{key}: expected a finite number, got {v!r}")
        return repr(f)
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{k} = {_toml_value(x, key + '.' + k)}" for k, x in v.items()) + " }"
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(x, key) for x in v) + "]"
    raise _error(key, f"{key}: cannot be written as TOML ({type(v).__name__})")


def _dict_to_toml(d, prefix=""):
    """TOML text of a dict: scalars first, then sub-tables ([a.b]) and lists
    of tables ([[a]])."""
    lines, tables = [], []
    for k, v in d.items():
        if not isinstance(k, str):
            raise _error(str(k), f"keys must be strings, got {k!r}")
        full = prefix + k
        if isinstance(v, dict):
            tables.append(f"\n[{full}]\n" + _dict_to_toml(v, full + "."))
        elif isinstance(v, (list, tuple)) and v and all(isinstance(x, dict) for x in v):
            for x in v:
                tables.append(f"\n[[{full}]]\n" + _dict_to_toml(x, full + "."))
        else:
            lines.append(f"{k} = {_toml_value(v, full)}")
    return "\n".join(lines) + "\n" + "".join(tables)


class Radar:
    """A checked radar description (docs/radar-format.md)."""

    def __init__(self, _impl):
        self._impl = _impl

    @classmethod
    def from_toml(cls, text, source="<string>"):
        """A radar from TOML text (the radar file format); ``source`` names it in errors."""
        return cls(_ris._radar_from_toml(str(text), source))

    @classmethod
    def from_dict(cls, d):
        """A radar from a dict with the radar file's keys, e.g.
        ``{"frequency": "8.6 GHz", "track": {"altitude": "40000 ft"}}``
        (written as TOML and read by the same parser)."""
        if not isinstance(d, dict):
            raise _error("", f"expected a dict of radar keys, got {type(d).__name__}")
        return cls.from_toml(_dict_to_toml(d), "<dict>")

    def info(self):
        """The derived quantities of ``ris radar info`` (SI units in the key names)."""
        return self._impl.derived()

    def params(self):
        """Every input as used, SI units in the key names (metadata.json's ``radar``)."""
        return self._impl.params()

    @property
    def path(self):
        return self._impl.source or None

    def __repr__(self):
        return f"<ris.Radar {self.path or ''}>"


def load_radar(path):
    """A radar from its TOML file (``ris simulate --radar``)."""
    return Radar(_ris._load_radar(str(path)))


_FILM_KEYS = ("density_range", "gamma", "k1", "k2", "m1", "m2")


class Result:
    """One simulation. Products are numpy arrays: slant-range ones are
    lines x bins (near range first), ground-range ones lines x ground bins,
    scene-grid ones rows x cols of the scene. Powers in watts."""

    def __init__(self, impl, scene):
        self._impl = impl
        self.scene = scene

    kind = property(lambda self: self._impl.kind, doc="'slar', 'sar', 'coherent_sar' or 'ppi'.")
    seed = property(lambda self: self._impl.seed, doc="The fading seed of the pictures.")
    warnings = property(lambda self: list(self._impl.warnings), doc="The run's warnings.")
    mean_power_w = property(lambda self: self._impl.mean_power_w(),
                            doc="Mean received power (W), NaN where no data (mean_power_slant.tif).")
    speckled_power_w = property(lambda self: self._impl.speckled_power_w(),
                                doc="Power after fading (W) (speckled_power_slant.tif).")
    slant_grey = property(lambda self: self._impl.slant_grey(),
                          doc="Greytones 0..255, slant range (slant_range.png).")
    ground_grey = property(lambda self: self._impl.ground_grey(),
                           doc="Greytones 0..255, ground range (ground_range.png).")
    ground_power_w = property(lambda self: self._impl.ground_power_w(),
                              doc="Power after fading (W) resampled to ground range.")
    ground_mask = property(lambda self: self._impl.ground_mask(),
                           doc="Pixel flags of the ground-range image.")
    ground_range_m = property(lambda self: self._impl.ground_range_m(),
                              doc="Ground range (m) of each ground-range column's centre.")
    slant_range_m = property(lambda self: self._impl.slant_range_m(),
                             doc="Slant range (m) of each slant-range bin's centre.")
    mask_slant = property(lambda self: self._impl.mask_slant(),
                          doc="Pixel flags, slant range (mask_slant.tif; read-only view).")
    scene_mask = property(lambda self: self._impl.scene_mask(),
                          doc="Shadow/layover/... flags on the scene grid (scene_mask.tif).")
    local_incidence_deg = property(lambda self: self._impl.local_incidence_deg(),
                                   doc="Local incidence (deg) on the scene grid, NaN where unseen.")
    geocoded_power_w = property(lambda self: self._impl.geocoded_power_w(),
                                doc="Power after fading (W) on the scene grid (geocoded_power.tif).")
    geocoded_grey = property(lambda self: self._impl.geocoded_grey(),
                             doc="Slant greytones on the scene grid (geocoded_grey.tif).")

    @property
    def metadata(self):
        """metadata.json's content as a dict."""
        return self._impl.metadata()

    @property
    def film(self):
        """Equation 15's film constants in use, as a dict."""
        return dict(zip(_FILM_KEYS, self._impl.film()))

    def rerender(self, seed, film=None):
        """Fading and greytones again with another seed and, when given, other
        film constants (a dict with any of density_range, gamma, k1, k2, m1,
        m2); the geometry and mean power are kept. Returns self."""
        values = None
        if film is not None:
            current = self.film
            unknown = set(film) - set(_FILM_KEYS)
            if unknown:
                raise _error("film", f"film: unknown keys {sorted(unknown)}; expected {list(_FILM_KEYS)}")
            current.update({k: float(v) for k, v in film.items()})
            values = [current[k] for k in _FILM_KEYS]
        self._impl.rerender(_seed(seed), values)
        return self

    def write(self, out_dir):
        """Writes the products ``ris simulate --out`` writes into out_dir
        (one folder, written as a whole); returns the seconds taken."""
        return self._impl.write(str(out_dir))


def _seed(seed):
    if isinstance(seed, bool) or not isinstance(seed, numbers.Integral) or seed < 0:
        raise _error("seed", f"seed: expected a whole number >= 0, got {seed!r}")
    return int(seed)


def simulate(scene, radar, backscatter=None, seed=1, threads=0, targets=None, progress=None):
    """Runs one simulation, as ``ris simulate`` does, with the GIL released.

    scene: a Scene (or a path, loaded with load_scene).
    radar: a Radar (or a path, or a dict for Radar.from_dict).
    backscatter: a category library (.toml) or sigma0 table (.csv) path;
        None: the standard library.
    seed: fading seed; threads: OpenMP threads (0: all cores).
    targets: a point-target file (TOML, [[target]] tables), or None.
    progress: optional callable(stage: str, fraction_done: float).
    """
    if not isinstance(scene, Scene):
        scene = load_scene(scene)
    if isinstance(radar, dict):
        radar = Radar.from_dict(radar)
    elif not isinstance(radar, Radar):
        radar = load_radar(radar)
    if isinstance(threads, bool) or not isinstance(threads, numbers.Integral) or threads < 0:
        raise _error("threads", f"threads: expected 0 (all cores) or more, got {threads!r}")
    impl = _ris._simulate(scene._impl, radar._impl, "" if backscatter is None else str(backscatter),
                          _seed(seed), int(threads), "" if targets is None else str(targets),
                          progress)
    for w in impl.warnings:
        _warnings.warn(w, stacklevel=2)
    return Result(impl, scene)


_sources = {}


def _source(library):
    key = "" if library is None else str(library)
    if key not in _sources:
        _sources[key] = _ris._load_sigma0_source(key)
    return _sources[key]


def sigma0(model_or_category, angles_deg, frequency_hz, polarisation="HH", library=None,
           allow_extrapolation=False):
    """sigma0 (linear, per unit surface area) over numpy arrays.

    model_or_category: a category of ``library`` (id or name; the standard
        library when None), or a model as a dict of its parameters, e.g.
        ``{"name": "oh1992", "rms_height": "1 cm", "permittivity": "15 - 4j"}``
        (``ris sigma0 --model``).
    angles_deg: local incidence in degrees, 0..90 (any shape).
    frequency_hz, polarisation ("HH", "VV", "HV", "VH"): scalars or arrays,
        broadcast against the angles.
    Returns an array of the broadcast shape; 10*log10 gives dB.
    """
    angles = np.asarray(angles_deg, dtype=np.float64)
    freq = np.asarray(frequency_hz, dtype=np.float64)
    pol = np.asarray(polarisation)
    if not np.issubdtype(pol.dtype, np.str_):
        raise _error("polarisation", f"polarisation: expected strings such as 'HH', got {pol.dtype}")
    try:
        angles, freq, pol = np.broadcast_arrays(angles, freq, pol)
    except ValueError as e:
        raise _error("angles_deg", f"angles_deg, frequency_hz and polarisation do not broadcast: {e}")
    if np.any(~np.isfinite(angles)) or np.any((angles < 0.0) | (angles > 90.0)):
        raise _error("angles_deg", "angles_deg: expected angles in [0, 90] deg")
    flat_a = np.ascontiguousarray(np.deg2rad(angles), dtype=np.float64).reshape(-1)
    flat_f = freq.reshape(-1)
    flat_p = pol.reshape(-1)
    out = np.empty(flat_a.size, dtype=np.float64)
    if isinstance(model_or_category, dict):
        body = ", ".join(f"{k} = {_toml_value(v, k)}" for k, v in model_or_category.items())
        def curve(a, f, p):
            return _ris._model_sigma0(body, a, f, p, bool(allow_extrapolation))
    elif isinstance(model_or_category, (str, numbers.Integral)) and not isinstance(model_or_category, bool):
        src = _source(library)
        cat = model_or_category if isinstance(model_or_category, str) else int(model_or_category)
        def curve(a, f, p):
            return _ris._category_sigma0(src, cat, a, f, p)
    else:
        raise _error("category", f"expected a category id or name, or a model dict, got {model_or_category!r}")
    # One call per band (frequency, polarisation): the model is looked up once.
    for f in np.unique(flat_f):
        for p in np.unique(flat_p[flat_f == f]):
            m = (flat_f == f) & (flat_p == p)
            out[m] = curve(np.ascontiguousarray(flat_a[m]), float(f), str(p))
    return out.reshape(angles.shape)


def list_models():
    """The backscatter models: a dict name -> one-line summary."""
    return dict(_ris._list_models())
