"""ris.sensor: optical and thermal images of a scene (``ris sensor``,
docs/sensors.md) from Python, through the code the command line runs: the
arrays hold the values of its GeoTIFFs."""

import os

import numpy as np

from . import _ris


def _error(key, message):
    err = _ris.InputError(message)
    err.file = ""
    err.key = key
    return err


class SensorImage:
    """An optical or thermal image on the scene's grid, and a frame camera's
    picture when the sensor file has a ``[camera]``.

    bands: {band name: (rows, cols) float32 array} (W m-2 sr-1 um-1 for
    optical bands, K for thermal: ``unit``), NaN off the scene's data;
    geotransform and crs_wkt: the scene's; sun: zenith, azimuth, elevation
    (deg) and the Earth-Sun distance (au); camera: None, or a dict of its
    bands, range_m, footprint_area_m2 and digital_numbers arrays, its GCPs
    ((pixel, line, x, y, z) tuples in the scene's CRS) and empty_pixels."""

    def __init__(self, d):
        self.bands = d["bands"]
        self.unit = d["unit"]
        self.latitude_deg = d["latitude_deg"]
        self.longitude_deg = d["longitude_deg"]
        self.sun = d["sun"]
        self.night = d["night"]
        self.shadowed_cells = d["shadowed_cells"]
        self.geotransform = tuple(d["geotransform"])
        self.crs_wkt = d["crs_wkt"]
        self.camera = d["camera"]

    def to_numpy(self):
        """The grid's bands as one (band, rows, cols) array, in the sensor
        file's band order."""
        return np.stack(list(self.bands.values()))

    def __repr__(self):
        rows, cols = next(iter(self.bands.values())).shape
        cam = "" if self.camera is None else ", with a camera picture"
        return (f"SensorImage({', '.join(self.bands)} in {self.unit}, {cols} x {rows}{cam})")


def sensor(scene, sensor, table=None, threads=0):
    """Renders ``ris sensor``'s images: scene, a scene file (a description or
    a ris scene GeoTIFF; a Scene loaded from a file is taken by its path);
    sensor, a sensor TOML (data/sensors_eo/optical.toml, thermal.toml, ...);
    table, the per-category surface table (default, as the command line's:
    data/sensors_eo/<the scene's backscatter library>-eo.csv when it exists,
    else generic-terrain-eo.csv). Returns a SensorImage."""
    path = getattr(scene, "path", scene)
    if path is None or path == "":
        raise _error("scene", "sensor(): the scene must come from a file (a Scene built from "
                              "arrays has none): save it with `ris scene build` first")
    if not isinstance(path, (str, os.PathLike)):
        raise _error("scene", f"sensor(): scene: expected a file path or a Scene, got {scene!r}")
    if not isinstance(sensor, (str, os.PathLike)):
        raise _error("sensor", f"sensor(): sensor: expected a sensor TOML path, got {sensor!r}")
    if isinstance(threads, bool) or not isinstance(threads, int) or threads < 0:
        raise _error("threads", f"sensor(): threads: expected an integer >= 0, got {threads!r}")
    return SensorImage(_ris._sensor(os.fspath(path), os.fspath(sensor),
                                    "" if table is None else os.fspath(table),
                                    threads))
