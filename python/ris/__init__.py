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

import json
import math
import os
import pathlib
import re
import numbers
import warnings as _warnings

import numpy as np


def _installed_data_dir():
    """<prefix>/share/ris/data for a package installed by ``cmake --install``
    into <prefix>/lib/python3/dist-packages/ris, when that folder exists."""
    package = pathlib.Path(__file__).resolve().parent
    site = package.parent
    if (site.name, site.parent.name, site.parent.parent.name) != ("dist-packages", "python3", "lib"):
        return None
    data = site.parents[2] / "share" / "ris" / "data"
    return data if data.is_dir() else None


# The installed tool finds its data beside itself (<prefix>/bin/../share);
# an installed package does the same from its own place, unless RIS_DATA says.
if not os.environ.get("RIS_DATA") and _installed_data_dir() is not None:
    os.environ["RIS_DATA"] = str(_installed_data_dir())

from . import _ris  # noqa: E402 (after RIS_DATA is set)
from ._ris import InputError, InputFileNotFoundError  # noqa: E402

__version__ = _ris.__version__
__all__ = [
    "InputError",
    "InputFileNotFoundError",
    "Scene",
    "Radar",
    "Result",
    "load_scene",
    "load_radar",
    "data_dir",
    "simulate",
    "simulate_acquisition",
    "study",
    "StudyResult",
    "sensor",
    "SensorImage",
    "sigma0",
    "list_models",
    "DIELECTRIC_MODELS",
    "permittivity",
    "Greytones",
    "greytone",
    "TopoLayers",
    "topo",
    "quality",
    "compare",
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


def _xarray():
    """The xarray module, or an ImportError saying how to get it."""
    try:
        import xarray
    except ImportError as e:
        raise ImportError(
            "ris: to_xarray() needs xarray, which is not installed (Debian: apt-get install "
            "python3-xarray, or make deps); the numpy arrays (result.mean_power_w, "
            "scene.elevation_m, ...) work without it") from e
    return xarray


def _xy_coords(x, y):
    return {"x": ("x", x, {"units": "m", "long_name": "x (east) of the cell centre"}),
            "y": ("y", y, {"units": "m", "long_name": "y (north) of the cell centre"})}


def _crs_attrs(crs):
    return {"crs_wkt": crs or ""}


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

    @property
    def backscatter_library(self):
        """The backscatter library the scene's category ids belong to (that a
        ``ris scene import``/``fractal`` GeoTIFF names, or generic-terrain.toml
        for a DEM loaded here), which simulate() uses when given none; None:
        the standard library."""
        return self._impl.library or None

    def xy_m(self):
        """(x, y): the cell centres' coordinates in metres (x east along a
        row, y north down the rows), from the geotransform."""
        x0, dx, _, y0, _, dy = self.geotransform
        rows, cols = self.shape
        return x0 + (np.arange(cols) + 0.5) * dx, y0 + (np.arange(rows) + 0.5) * dy

    def to_xarray(self):
        """The scene as an ``xarray.Dataset`` (elevation_m, category, valid on
        dims y, x; coordinates in metres; the CRS as WKT in attrs["crs_wkt"]).
        Needs Debian's python3-xarray (ImportError otherwise)."""
        xr = _xarray()
        x, y = self.xy_m()
        data = {"elevation_m": (("y", "x"), self.elevation_m, {"units": "m"}),
                "category": (("y", "x"), self.category, {"no_data": 65535}),
                "valid": (("y", "x"), self.valid, {"meaning": "1 data, 0 no data"})}
        return xr.Dataset(data, coords=_xy_coords(x, y), attrs=_crs_attrs(self.crs))

    def write(self, path):
        """Writes the scene as a ris scene GeoTIFF (as ``ris scene build -o``)."""
        self._impl.write(str(path))

    def __repr__(self):
        return f"<ris.Scene {self.shape[1]} x {self.shape[0]} cells of {self.cell_size_m[0]:g} m>"


def load_scene(path, category_path=None, cell_size_m=None, crs=None, category=None):
    """A scene from a file: a description (.toml), a ris scene GeoTIFF, or a
    DEM (any GDAL raster). A DEM in a geographic CRS is reprojected into UTM
    as ``ris scene import`` does (cell_size_m, crs and category are its
    options; category: an id or a name of data/backscatter/generic-terrain.toml,
    default 21, its grass, as the command line); category_path: a category
    raster on the DEM's grid. Such a scene (and a scene GeoTIFF that names
    its library) is simulated with that library unless simulate() is given
    another (Scene.backscatter_library), as ``ris simulate``."""
    if category is not None and (isinstance(category, bool)
                                 or not isinstance(category, (str, numbers.Integral))):
        raise _error("category", f"category: expected an id or a name, got {category!r}")
    return Scene(_ris._load_scene(str(path), category_path, cell_size_m, crs,
                                  None if category is None else str(category)))


_BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")


def _toml_key(k, prefix=""):
    """A dict key as a TOML key: every ris key is a bare name, so anything
    else (a quote, a bracket, a newline: text that would be pasted into the
    TOML as structure) is refused, never written."""
    if not isinstance(k, str):
        raise _error(prefix + str(k), f"{prefix}{k!r}: keys must be strings")
    if not _BARE_KEY.fullmatch(k):
        raise _error(prefix + k, f"{prefix}{k!r}: not a key name (letters, digits, '_' and '-' "
                                 "only, as in the radar file format)")
    return k


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
        # JSON's string escapes (\\, \", \n, \uXXXX) are TOML's basic-string ones.
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{_toml_key(k, key + '.')} = {_toml_value(x, key + '.' + k)}"
                                for k, x in v.items()) + " }"
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(x, key) for x in v) + "]"
    raise _error(key, f"{key}: cannot be written as TOML ({type(v).__name__})")


def _dict_to_toml(d, prefix=""):
    """TOML text of a dict: scalars first, then sub-tables ([a.b]) and lists
    of tables ([[a]])."""
    lines, tables = [], []
    for k, v in d.items():
        full = prefix + _toml_key(k, prefix)
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
        """The derived quantities of ``ris radar info``, in its units: lengths
        in metres (``_m``), angles in degrees (``_deg``: depression and
        incidence near / far), as the command line prints them."""
        return self._impl.derived()

    def params(self):
        """Every input as used, SI units in the key names (metadata.json's ``radar``)."""
        return self._impl.params()

    @property
    def path(self):
        return self._impl.source or None

    def __repr__(self):
        return f"<ris.Radar {self.path or ''}>"


def data_dir():
    """The folder of ris's shipped data (radars/, scenes/, backscatter/, ...):
    $RIS_DATA, else <prefix>/share/ris/data of an installed package, else the
    source tree's data/."""
    return _ris._data_dir()


def load_radar(path):
    """A radar from its TOML file (``ris simulate --radar``)."""
    return Radar(_ris._load_radar(str(path)))


_FILM_KEYS = ("density_range", "gamma", "k1", "k2", "m1", "m2")


def _film_values(current, film):
    """The six film constants (a list in _FILM_KEYS order) with those of the
    dict `film` replaced; None when film is None (keep the current ones)."""
    if film is None:
        return None
    if not isinstance(film, dict):
        raise _error("film", f"film: expected a dict with any of {list(_FILM_KEYS)}, got {film!r}")
    unknown = set(film) - set(_FILM_KEYS)
    if unknown:
        raise _error("film", f"film: unknown keys {sorted(unknown)}; expected {list(_FILM_KEYS)}")
    values = dict(zip(_FILM_KEYS, current))
    for k, v in film.items():
        try:
            values[k] = float(v)
        except (TypeError, ValueError):
            raise _error("film", f"film.{k}: expected a number, got {v!r}")
        if not math.isfinite(values[k]):
            raise _error("film", f"film.{k}: expected a finite number, got {v!r}")
    return [values[k] for k in _FILM_KEYS]


class Result:
    """One simulation. Products are numpy arrays: slant-range ones are
    lines x bins (near range first), ground-range ones lines x ground bins,
    scene-grid ones rows x cols of the scene. Powers in watts. A PPI run has
    the bscope_* and scope_* arrays instead; an acquisition run the
    slant-range ones and its radar-grid layers; a streamed run none (its
    products are the files in out_dir)."""

    def __init__(self, impl, scene):
        self._impl = impl
        self.scene = scene  #: the Scene simulated (None: streamed or acquisition run)

    kind = property(lambda self: self._impl.kind,
                    doc="'slar', 'sar', 'coherent_sar', 'ppi' or 'streamed'.")
    summary = property(lambda self: self._impl.summary,
                       doc="The run's report, as `ris simulate` prints it: a dict of mode, "
                           "strategy ('in_memory' or 'streamed'), ranks, lines (each its text "
                           "and values: key, value, unit), warnings and products (file stems).")
    channels = property(lambda self: list(self._impl.channels),
                        doc="A multi-channel run's channel names ([[channel]] tables; empty "
                            "for a one-channel run).")
    acquisition = property(lambda self: self._impl.acquisition,
                           doc="Whether the run was on an acquisition's radar grid.")
    out_dir = property(lambda self: self._impl.out_dir or None,
                       doc="The folder the run wrote its products into (out=), or None.")
    stream_summary = property(lambda self: self._impl.stream_summary(),
                              doc="A streamed run's blocks, block_lines and stage_seconds.")
    layover_shadow_mask = property(lambda self: self._impl.layover_shadow_mask(),
                                   doc="Acquisition run: 0 none, 1 shadow, 2 layover, 3 both on "
                                       "the radar grid (layover_shadow_mask.tif; read-only view).")
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
                                   doc="Local incidence (deg) on the scene grid, NaN where unseen "
                                       "(an acquisition run: on the radar grid, "
                                       "local_incidence.tif).")
    geocoded_power_w = property(lambda self: self._impl.geocoded_power_w(),
                                doc="Power after fading (W) on the scene grid (geocoded_power.tif).")
    geocoded_grey = property(lambda self: self._impl.geocoded_grey(),
                             doc="Slant greytones on the scene grid (geocoded_grey.tif).")

    # PPI runs (B-scope: rays x slant-range bins, rays clockwise from the
    # scan start; scope: the Cartesian picture centred on the radar, north up).
    bscope_mean_power_w = property(lambda self: self._impl.bscope_mean_power_w(),
                                   doc="PPI: mean power (W), rays x bins, NaN where no data "
                                       "(mean_power_bscope.tif).")
    bscope_speckled_power_w = property(lambda self: self._impl.bscope_speckled_power_w(),
                                       doc="PPI: power after fading (W), rays x bins "
                                           "(speckled_power_bscope.tif).")
    bscope_grey = property(lambda self: self._impl.bscope_grey(),
                           doc="PPI: greytones 0..255, rays x bins (bscope.png).")
    bscope_mask = property(lambda self: self._impl.bscope_mask(),
                           doc="PPI: pixel flags, rays x bins (mask_bscope.tif; read-only view).")
    scope_power_w = property(lambda self: self._impl.scope_power_w(),
                             doc="PPI: speckled power (W) on the scope, NaN outside "
                                 "(ppi_scope_power.tif).")
    scope_mask = property(lambda self: self._impl.scope_mask(),
                          doc="PPI: pixel flags on the scope (ppi_scope_mask.tif).")
    scope_grey = property(lambda self: self._impl.scope_grey(),
                          doc="PPI: greytones on the scope, range rings drawn (ppi_scope.png).")
    ray_azimuth_deg = property(lambda self: self._impl.ray_azimuth_deg(),
                               doc="PPI: azimuth (deg clockwise from north) of each B-scope "
                                   "row's ray centre.")

    @property
    def scope_axes_m(self):
        """PPI: (east, north) in metres from the radar of the scope's column
        and row centres (slant or ground radius, per scope_presentation)."""
        return self._impl.scope_axes_m()

    @property
    def scope_presentation(self):
        """PPI: 'slant' (radius = slant range) or 'ground' (a map, georeferenced)."""
        return self._impl.scope_presentation()

    @property
    def site_m(self):
        """PPI: the radar site's (x, y) in the scene's frame, metres."""
        return self._impl.site_m()

    def channel(self, name):
        """One channel of a multi-channel run as a one-channel Result (its
        arrays are that channel's; write() writes it alone, unsuffixed)."""
        return Result(self._impl.channel(name), self.scene)

    @property
    def slc(self):
        """A quad-pol run ([sar] quad_pol = true): the four single-look complex
        images, complex64 of shape (4, line, bin) in the order HH, HV, VH, VV
        (transmit first; sqrt(W): abs(z)**2 is the pixel's power in watts,
        NaN for no data). Other runs: InputError naming sar.quad_pol."""
        return self._impl.quad_pol_slc()

    def polarimetric_matrix(self, kind="c3", window=7):
        """A quad-pol run's C3 (lexicographic, [HH, sqrt2 HV, VV]) or T3
        (Pauli) per pixel, averaged over a window x window boxcar (odd; cut at
        the edges) as ``ris polsar`` does: complex64, shape (3, 3, line, bin)."""
        return self._impl.quad_pol_matrix(kind, int(window))

    def polsar_xarray(self, window=7):
        """A quad-pol run as an ``xarray.Dataset``: slc on (polarisation, line,
        bin), c3 and t3 on (row, col, line, bin) at the boxcar window, with
        to_xarray()'s line and bin coordinates (needs Debian's python3-xarray)."""
        xr = _xarray()
        import json
        slc = self.slc
        lines = slc.shape[1]
        hh = self.channel("hh")  # the geometry's channel: line and bin coordinates
        spacing = hh._impl.line_spacing_m()
        coords = dict(polarisation=("polarisation", ["HH", "HV", "VH", "VV"],
                                    {"long_name": "transmit, receive"}),
                      line=("line", (np.arange(lines) + 0.5) * spacing,
                            {"units": "m", "long_name": "along-track distance of the line centre"}),
                      bin=("bin", hh.slant_range_m,
                           {"units": "m", "long_name": "slant range of the bin centre"}))
        m = ("row", "col", "line", "bin")
        data = {"slc": (("polarisation", "line", "bin"), slc, {"units": "sqrt(W)"}),
                "c3": (m, self.polarimetric_matrix("c3", window), {"units": "W"}),
                "t3": (m, self.polarimetric_matrix("t3", window), {"units": "W"})}
        return xr.Dataset(data, coords=coords,
                          attrs=dict(kind=self.kind, seed=self.seed, window=int(window),
                                     basis="C3: [HH, sqrt2 HV, VV]; T3: [HH+VV, HH-VV, 2HV]/sqrt2",
                                     metadata=json.dumps(self.metadata)))

    @property
    def metadata(self):
        """metadata.json's content as a dict."""
        return self._impl.metadata()

    @property
    def film(self):
        """Equation 15's film constants in use, as a dict."""
        return dict(zip(_FILM_KEYS, self._impl.film()))

    def to_xarray(self):
        """The products as an ``xarray.Dataset`` (needs Debian's python3-xarray;
        ImportError otherwise, the numpy attributes need nothing more).

        SLAR/SAR: slant products on dims (line, bin), ground-range ones on
        (line, ground_bin), scene-grid ones on (y, x). PPI: the B-scope on
        (ray, bin), the scope on (y, x). Coordinates: line = along-track
        distance of the line centre (m), bin = slant range (m), ground_bin =
        ground range (m), x/y = scene coordinates of cell centres (m), ray =
        azimuth (deg). attrs: crs_wkt (the scene's CRS, "" for a local
        frame), kind, seed, metadata (metadata.json as a JSON string).
        """
        xr = _xarray()
        if self.scene is None:
            raise _error("to_xarray", "to_xarray: for runs on a scene only (an acquisition run: "
                                      "use the numpy arrays; a streamed run: the files in out_dir)")
        import json
        attrs = dict(_crs_attrs(self.scene.crs), kind=self.kind, seed=self.seed,
                     metadata=json.dumps(self.metadata))
        slant = self.slant_range_m
        bin_coord = ("bin", slant, {"units": "m", "long_name": "slant range of the bin centre"})
        w = {"units": "W"}
        if self.kind == "ppi":
            return self._ppi_xarray(xr, bin_coord, attrs)
        lines = self.mean_power_w.shape[0]
        spacing = self._impl.line_spacing_m()
        x, y = self.scene.xy_m()
        coords = dict(_xy_coords(x, y),
                      line=("line", (np.arange(lines) + 0.5) * spacing,
                            {"units": "m", "long_name": "along-track distance of the line centre"}),
                      bin=bin_coord,
                      ground_bin=("ground_bin", self.ground_range_m,
                                  {"units": "m", "long_name": "ground range of the bin centre"}))
        lb, lg, yx = ("line", "bin"), ("line", "ground_bin"), ("y", "x")
        data = {"mean_power_w": (lb, self.mean_power_w, w),
                "speckled_power_w": (lb, self.speckled_power_w, w),
                "slant_grey": (lb, self.slant_grey),
                "mask_slant": (lb, self.mask_slant),
                "ground_power_w": (lg, self.ground_power_w, w),
                "ground_grey": (lg, self.ground_grey),
                "ground_mask": (lg, self.ground_mask),
                "scene_mask": (yx, self.scene_mask),
                "local_incidence_deg": (yx, self.local_incidence_deg, {"units": "deg"}),
                "geocoded_power_w": (yx, self.geocoded_power_w, w),
                "geocoded_grey": (yx, self.geocoded_grey)}
        return xr.Dataset(data, coords=coords, attrs=attrs)

    def _ppi_xarray(self, xr, bin_coord, attrs):
        east, north = self.scope_axes_m
        if self.scope_presentation == "ground":  # a map in the scene's frame
            sx, sy = self.site_m
            coords = _xy_coords(sx + east, sy + north)
        else:  # radius = slant range: not a map, metres from the radar
            coords = _xy_coords(east, north)
            attrs["crs_wkt"] = ""
        attrs["scope_presentation"] = self.scope_presentation
        coords["bin"] = bin_coord
        coords["ray"] = ("ray", self.ray_azimuth_deg,
                         {"units": "deg", "long_name": "azimuth of the ray centre, clockwise from north"})
        rb, yx, w = ("ray", "bin"), ("y", "x"), {"units": "W"}
        data = {"bscope_mean_power_w": (rb, self.bscope_mean_power_w, w),
                "bscope_speckled_power_w": (rb, self.bscope_speckled_power_w, w),
                "bscope_grey": (rb, self.bscope_grey),
                "bscope_mask": (rb, self.bscope_mask),
                "scope_power_w": (yx, self.scope_power_w, w),
                "scope_mask": (yx, self.scope_mask),
                "scope_grey": (yx, self.scope_grey)}
        return xr.Dataset(data, coords=coords, attrs=attrs)

    def rerender(self, seed, film=None):
        """Fading and greytones again with another seed and, when given, other
        film constants (a dict with any of density_range, gamma, k1, k2, m1,
        m2); the geometry and mean power are kept. Returns self."""
        self._impl.rerender(_seed(seed), _film_values(self._impl.film(), film))
        return self

    def write(self, out_dir):
        """Writes the products ``ris simulate --out`` writes into out_dir
        (one folder, written as a whole); returns the seconds taken."""
        return self._impl.write(str(out_dir))


def _seed(seed):
    if isinstance(seed, bool) or not isinstance(seed, numbers.Integral) or seed < 0:
        raise _error("seed", f"seed: expected a whole number >= 0, got {seed!r}")
    return int(seed)


def _as_radar(radar):
    """A Radar from a Radar, a dict (Radar.from_dict) or a path; None: the
    command line's default radar (data/radars/seed-fig4-5.toml)."""
    if radar is None:
        return Radar(_ris._default_radar())
    if isinstance(radar, Radar):
        return radar
    if isinstance(radar, dict):
        return Radar.from_dict(radar)
    return load_radar(radar)


def _count(name, value, what):
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < 0:
        raise _error(name, f"{name}: expected {what}, got {value!r}")
    return int(value)


def _run_options(backscatter, seed, threads, targets, out, stream, block_lines, products,
                 compress, overviews):
    """The options every run takes (``ris simulate``'s), checked."""
    o = _ris._RunOptions()
    o.backscatter = "" if backscatter is None else str(backscatter)
    o.seed = _seed(seed)
    o.threads = _count("threads", threads, "0 (all cores) or more")
    o.targets = "" if targets is None else str(targets)
    o.block_lines = _count("block_lines", block_lines, "a number of lines (0: from the memory budget)")
    o.stream = bool(stream) or o.block_lines > 0
    if o.stream and out is None:
        raise _error("out", "out: a streamed run writes its products while it runs: give out, "
                            "the folder (as ris simulate --out)")
    o.out_dir = "" if out is None else str(out)
    if products is not None:
        if isinstance(products, str) or not all(isinstance(p, str) for p in products):
            raise _error("products", f"products: expected a list of file stems such as "
                                     f"['mean_power_slant'], got {products!r}")
        o.products = list(products)
    o.compress = str(compress)
    o.overviews = bool(overviews)
    return o


def _finish(impl, scene):
    for w in impl.warnings:
        _warnings.warn(w, stacklevel=3)
    return Result(impl, scene)


def simulate(scene, radar, backscatter=None, seed=1, threads=0, targets=None, progress=None,
             out=None, stream=False, block_lines=0, products=None, compress="fast",
             overviews=True, calibrated=False):
    """Runs one simulation, as ``ris simulate`` does, with the GIL released.

    scene: a Scene (or a path, loaded with load_scene); a streamed run
        reads a scene raster (a path, or a Scene loaded from one) in blocks.
    radar: a Radar (or a path, or a dict for Radar.from_dict).
    backscatter: a category library (.toml) or sigma0 table (.csv) path;
        None: the library the scene names (scene.backscatter_library), else
        the standard library, as ``ris simulate``.
    seed: fading seed; threads: OpenMP threads (0: all cores).
    targets: a point-target file (TOML, [[target]] tables), or None.
    progress: optional callable(stage: str, fraction_done: float).
    out: a folder to write the products into as the run ends (``--out``);
        None: none written (``result.write(folder)`` later).
    stream, block_lines: stream the scene raster from its file in blocks of
        azimuth lines (``--stream``, ``--block-lines N``; block_lines > 0
        implies stream): bounded memory, the same bytes; needs ``out``, and
        the result then holds no arrays (kind "streamed": read the files,
        ``result.metadata``, ``result.stream_summary``).
    products, compress, overviews: ``--products`` (a list of file stems),
        ``--compress`` (fast, small, none), ``--no-overviews`` (False).
    calibrated: also write sigma0, beta0 and gamma0, linear and in dB
        (``--calibrated``; docs/outputs.md, "Calibrated products").
    """
    o = _run_options(backscatter, seed, threads, targets, out, stream, block_lines, products,
                     compress, overviews)
    o.calibrated = bool(calibrated)
    radar = _as_radar(radar)
    if o.stream:
        path = scene.path if isinstance(scene, Scene) else scene
        if path is None or isinstance(path, (dict, Scene)):
            raise _error("scene", "scene: a streamed run reads a scene raster from its file: give "
                                  "its path (a Scene from arrays: write() it first)")
        o.scene_path = str(path)
        return _finish(_ris._run(None, radar._impl, o, progress), None)
    if not isinstance(scene, Scene):
        scene = load_scene(scene)
    return _finish(_ris._run(scene._impl, radar._impl, o, progress), scene)


def simulate_acquisition(acquisition, dem, radar=None, frequency="A", burst=None, swath="",
                         land_cover=None, category=1, full_grid=False, earth=None,
                         backscatter=None, seed=1, threads=0, progress=None, out=None,
                         stream=False, block_lines=0, products=None, compress="fast",
                         overviews=True):
    """A simulation on an acquisition's own radar grid, as ``ris simulate
    --acquisition A --dem D`` (docs/geometry.md): the DEM's terrain imaged
    with the product's orbit, lines and range bins.

    acquisition: a NISAR RSLC .h5, a Sentinel-1 .SAFE (or its annotation
        .xml) or a ris acquisition .toml; frequency ("A"/"B"), burst, swath:
        which part of it (``--frequency``, ``--burst``, ``--swath``).
    dem: the terrain, a DEM in geographic WGS 84 (``--dem``).
    radar: a Radar, path or dict for the power, antenna, mode, film...
        (None: the command line's default, seed-fig4-5.toml).
    land_cover: a ris scene (.toml or raster) whose categories the terrain
        takes; category: the terrain's one category otherwise (``--category``).
    full_grid: the product's whole grid, not the DEM's window.
    earth: "flat" or "ellipsoid" (None: the radar file's earth key, else the
        ellipsoid).
    The other arguments are simulate()'s. The result has the slant-range
    arrays (mean_power_w, speckled_power_w, slant_grey, mask_slant, ground_*)
    on the grid window and its radar-grid layers local_incidence_deg
    (local_incidence.tif) and layover_shadow_mask; ``write()`` writes the
    command line's files.
    """
    o = _run_options(backscatter, seed, threads, None, out, stream, block_lines, products,
                     compress, overviews)
    o.acquisition = str(acquisition)
    o.dem = str(dem)
    o.frequency = str(frequency)
    if burst is not None:
        o.burst = _count("burst", burst, "a burst number from 0")
    o.swath = str(swath)
    o.land_cover = "" if land_cover is None else str(land_cover)
    o.category = _count("category", category, "a category id")
    o.full_grid = bool(full_grid)
    o.earth = "" if earth is None else str(earth)
    return _finish(_ris._run(None, _as_radar(radar)._impl, o, progress), None)


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
        body = ", ".join(f"{_toml_key(k)} = {_toml_value(v, k)}"
                         for k, v in model_or_category.items())
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


# The library's registry of dielectric models (ris/backscatter/dielectric.h),
# the names `ris dielectric --model` takes.
DIELECTRIC_MODELS = tuple(_ris._dielectric_models())


def _fraction(name, value):
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise _error(name, f"{name}: expected a number, got {value!r}")
    if not (0.0 <= v <= 1.0):
        raise _error(name, f"{name}: expected a fraction in [0, 1], got {value!r}")
    return v


def permittivity(model, moisture_m3_m3, frequency_hz, clay=0.2, sand=0.4, bulk_density_g_cm3=1.5,
                 temperature_c=20.0, conductivity="dobson1985", allow_extrapolation=False):
    """Soil relative permittivity from a dielectric model, as ``ris dielectric``.

    model: "dobson1985", "hallikainen1985" or "mironov2009" (DIELECTRIC_MODELS).
    moisture_m3_m3: volumetric water content mv in [0, 1] (any shape).
    frequency_hz: scalar or array, broadcast against the moisture.
    clay, sand: mass fractions, 0..1 (mironov2009 does not use sand).
    bulk_density_g_cm3, temperature_c: dry bulk density (g/cm3) and soil
        temperature (deg C), used by dobson1985.
    conductivity: dobson1985's effective-conductivity fit, "dobson1985"
        (1.4-18 GHz) or "peplinski1995" (0.3-1.3 GHz).
    allow_extrapolation: outside a model's validity range, warn
        (``warnings.warn``) instead of raising InputError.
    Returns complex128 of the broadcast shape, eps = eps' - j eps'' (imaginary
    part -eps'' <= 0; ``ris dielectric`` prints eps' and eps'').
    """
    if not isinstance(model, str):
        raise _error("model", f"model: expected one of {list(DIELECTRIC_MODELS)}, got {model!r}")
    try:
        mv = np.asarray(moisture_m3_m3, dtype=np.float64)
        freq = np.asarray(frequency_hz, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise _error("moisture_m3_m3", f"moisture_m3_m3, frequency_hz: expected numbers: {e}")
    try:
        mv, freq = np.broadcast_arrays(mv, freq)
    except ValueError as e:
        raise _error("moisture_m3_m3", f"moisture_m3_m3 and frequency_hz do not broadcast: {e}")
    if np.any(~np.isfinite(mv)) or np.any((mv < 0.0) | (mv > 1.0)):
        raise _error("moisture_m3_m3", "moisture_m3_m3: expected volumetric moisture in [0, 1] m3/m3")
    if np.any(~np.isfinite(freq)) or np.any(freq <= 0.0):
        raise _error("frequency_hz", "frequency_hz: expected frequencies > 0 Hz")
    clay, sand = _fraction("clay", clay), _fraction("sand", sand)
    if clay + sand > 1.0 + 1e-9:
        raise _error("sand", "sand: clay + sand exceeds 1 (mass fractions of the same soil)")
    rho = float(bulk_density_g_cm3)
    if not (0.0 < rho < 2.66):
        raise _error("bulk_density_g_cm3",
                     "bulk_density_g_cm3: expected a dry bulk density in (0, 2.66) g/cm3")
    temp = float(temperature_c)
    if not math.isfinite(temp):
        raise _error("temperature_c", "temperature_c: expected a finite temperature in deg C")
    eps, problems = _ris._permittivity(model, np.ascontiguousarray(mv).reshape(-1),
                                       np.ascontiguousarray(freq).reshape(-1), clay, sand, rho,
                                       temp, str(conductivity), bool(allow_extrapolation))
    for w in problems:
        _warnings.warn(w, stacklevel=2)
    return eps.reshape(mv.shape)


class Greytones:
    """What ris.greytone returns: the picture and the greytone map used."""

    def __init__(self, d):
        self.grey = d["grey"]  #: uint8 greytones, lines x bins (greytone.png)
        self.speckled_power_w = d["speckled_power_w"]  #: float32 W after fading (--speckled)
        self.looks_per_bin = d["looks_per_bin"]  #: N per range bin
        self.reference_power_w = d["reference_power_w"]  #: P_ref (W)
        self.reference_greytone = d["reference_greytone"]  #: G_ref
        self.greytones_per_decade = d["greytones_per_decade"]  #: 255 gamma / X
        self.film = dict(zip(_FILM_KEYS, d["film"]))  #: equation 15's constants used
        self.fading = d["fading"]  #: whether fading was applied (the radar's switch)

    def __repr__(self):
        return (f"<ris.Greytones {self.grey.shape[1]} x {self.grey.shape[0]}, "
                f"P_ref {self.reference_power_w:.4g} W -> G_ref {self.reference_greytone:.0f}>")


def greytone(mean_power_w, radar=None, seed=1, film=None, looks=None):
    """Fading and equation 15's greytones from a mean-power array, without
    geometry: ``ris greytone POWER.tif --radar R --seed N`` on an array.

    mean_power_w: 2-D mean power in watts, lines x range bins (near range
        first), NaN = no data (greytone 0), e.g. Result.mean_power_w or
        mean_power_slant.tif's pixels (converted to float32).
    radar: a Radar (or path or dict) giving the film, reference, fading law
        and switches; None: ``ris greytone``'s default (seed-fig4-5.toml).
    seed: fading seed (as ``--seed``).
    film: a dict with any of density_range, gamma, k1, k2, m1, m2 replacing
        the radar's film constants.
    looks: independent samples N per range bin: a number or one per column
        (> 0); None: from the radar's range bins at their ranges, and then
        the array needs the radar's number of range bins (as the CLI).
    Returns a Greytones (grey, speckled_power_w, reference_power_w, ...).
    """
    if radar is None:
        impl = _ris._default_radar()
    elif isinstance(radar, Radar):
        impl = radar._impl
    elif isinstance(radar, dict):
        impl = Radar.from_dict(radar)._impl
    else:
        impl = load_radar(radar)._impl
    p = np.asarray(mean_power_w)
    if p.ndim != 2:
        raise _error("mean_power_w", f"mean_power_w: expected a 2-D array (lines, bins), got {p.ndim} dimensions")
    if not (np.issubdtype(p.dtype, np.floating) or np.issubdtype(p.dtype, np.integer)):
        raise _error("mean_power_w", f"mean_power_w: expected powers in watts, got {p.dtype}")
    p = np.ascontiguousarray(p, dtype=np.float32)
    if np.any(np.isinf(p)) or np.any(p < 0):
        raise _error("mean_power_w", "mean_power_w: expected powers >= 0 W (NaN = no data)")
    n = None
    if looks is not None:
        n = np.broadcast_to(np.asarray(looks, dtype=np.float64), (p.shape[1],)) \
            if np.ndim(looks) == 0 else np.asarray(looks, dtype=np.float64)
        if n.shape != (p.shape[1],):
            raise _error("looks", f"looks: expected a number or one per column ({p.shape[1]}), got shape {n.shape}")
        if not np.all(np.isfinite(n) & (n > 0)):
            raise _error("looks", "looks: expected finite numbers of looks > 0")
        n = [float(v) for v in n]
    return Greytones(_ris._greytone(impl, p, _seed(seed), _film_values(impl.film(), film), n))


class TopoLayers(dict):
    """What ris.topo returns: a dict of the layers by the names of the files
    ``ris topo`` writes, plus the unit (lat_deg: lat.tif, hgt_m: hgt.tif,
    simamp: simamp.tif, ...).

    The former keys ``simulated_amplitude`` (simamp) and ``height_m``
    (hgt_m) still read their layer with a DeprecationWarning; they are not
    listed among the keys."""

    _RENAMED = {"simulated_amplitude": "simamp", "height_m": "hgt_m"}

    def __missing__(self, key):
        new = self._RENAMED.get(key)
        if new is None:
            raise KeyError(key)
        _warnings.warn(f"ris.topo: the key {key!r} is now {new!r} (the file "
                       f"{new.removesuffix('_m')}.tif)",
                       DeprecationWarning, stacklevel=2)
        return self[new]


def topo(acquisition, dem, oversample=0, full_grid=False, threads=0, frequency="A", burst=None,
         swath=""):
    """``ris topo --acquisition A --dem D``'s layers as numpy arrays.

    ``acquisition`` is a NISAR RSLC ``.h5``, a Sentinel-1 ``.SAFE`` (or its
    annotation ``.xml``) or a ris acquisition ``.toml``; ``dem`` a DEM in
    geographic WGS 84 (docs/geometry.md). Returns a dict of arrays shaped
    (lines, bins) of the window of the radar grid the DEM covers (the whole
    grid with ``full_grid=True``), the files ``ris topo`` writes: ``lat_deg``,
    ``lon_deg`` (lat.tif, lon.tif, float64), ``hgt_m`` (hgt.tif),
    ``incidence_deg``, ``incidence_geocentric_deg``, ``local_incidence_deg``,
    ``look_deg``, ``heading_deg``, ``gamma_area_m2`` (gamma_area.tif),
    ``simamp`` (simamp.tif), all float32 with NaN for no data,
    and ``layover_shadow_mask`` (uint8: 0 none, 1 shadow, 2 layover, 3 both);
    plus ``window`` (first line, lines, first bin, bins), ``grid_shape``
    (lines, bins of the whole grid), ``oversample``, ``beta_area_m2``,
    ``unconverged``, ``dem_facets`` and ``mission``.
    """
    if burst is not None and (not isinstance(burst, numbers.Integral) or burst < 0):
        raise _error("burst", f"burst: expected a burst number from 0, got {burst!r}")
    return TopoLayers(_ris._topo(str(acquisition), str(dem), str(frequency),
                                 -1 if burst is None else int(burst), str(swath), int(oversample),
                                 bool(full_grid), int(threads)))


def _optional_grid(value):
    return None if value is None else np.asarray(value, dtype=np.float64)


def quality(power_w, mask=None, categories=None, regions=None, window=16, mask_bit=1, targets=None,
            line_spacing_m=1.0, range_bin_m=1.0):
    """``ris quality``'s measures of a power image (rows, cols), as a dict.

    The keys and numbers of ``ris quality --json`` (docs/quality.md) without
    its ``image`` entry: ``speckle`` (ENL, CV, radiometric resolution over
    ``regions``, boxes ``(col0, row0, cols, rows)``, or the automatic
    homogeneous ``window`` x ``window`` windows), ``histogram``; with
    ``categories`` (an array of the image's shape) ``categories`` and
    ``pairs``; with ``mask`` (mask_slant.tif's values: non-zero pixels left
    out, edges of ``mask_bit`` measured) ``edges``; with ``targets``
    (``(line, bin)`` pairs) ``targets``, their impulse responses with pixels
    ``line_spacing_m`` x ``range_bin_m``.
    """
    regions = [tuple(int(v) for v in r) for r in (regions or [])]
    if any(len(r) != 4 for r in regions):
        raise _error("regions", "regions: expected boxes (col0, row0, cols, rows)")
    targets = [tuple(int(v) for v in t) for t in (targets or [])]
    if any(len(t) != 2 for t in targets):
        raise _error("target", "targets: expected (line, bin) pairs")
    return _ris._quality(np.asarray(power_w, dtype=np.float32), _optional_grid(mask),
                         _optional_grid(categories), regions, int(window), int(mask_bit), targets,
                         float(line_spacing_m), float(range_bin_m))


def compare(simulated_w, real_w, register=True, max_shift_px=16, mask=None, categories=None,
            local_incidence_deg=None, return_aligned=False):
    """``ris compare``'s measures of a simulated and a real power image on one
    grid (rows, cols), as a dict.

    The keys and numbers of ``ris compare --json`` (docs/quality.md) without
    its ``simulated`` and ``real`` entries: ``registration`` (unless
    ``register=False``), ``agreement``, ``histogram_hellinger``; with
    ``categories`` ``category_bias``, with ``mask`` (the simulation's
    mask_slant.tif values) ``masks``, with ``local_incidence_deg``
    ``baselines``. ``return_aligned=True`` returns ``(measures, real_aligned)``,
    the real image moved onto the simulation's grid.
    """
    measures, aligned = _ris._compare(np.asarray(simulated_w, dtype=np.float32),
                                      np.asarray(real_w, dtype=np.float32), bool(register),
                                      int(max_shift_px), _optional_grid(mask),
                                      _optional_grid(categories),
                                      _optional_grid(local_incidence_deg))
    return (measures, aligned) if return_aligned else measures


from ._study import StudyResult, study  # noqa: E402 (uses Scene, Radar, _xarray)
from ._sensor import SensorImage, sensor  # noqa: E402
