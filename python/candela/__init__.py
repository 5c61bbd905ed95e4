"""candela from Python: cases, scenes, luminaires, the sun and skies, results as NumPy arrays.

The engine is the command line's (same inputs and seed, same numbers); docs/python.md documents
every name here. Units: metres, degrees, lux, candela, lumen; times are local standard time at
the site unless they carry an offset.
"""

import datetime
import functools
import json
import os
import struct
import warnings
from collections import namedtuple

import numpy as np

from . import _candela
from .errors import CandelaWarning, InputError

__version__ = _candela.version

__all__ = [
    "CandelaWarning", "Case", "Grid", "InputError", "Luminaire", "LuminaireData", "Results", "Scene",
    "Site", "Sky", "SunPosition", "illuminance", "load_case", "read_luminaire", "sun_position",
]


def _warn(found, stacklevel):
    """Each warning dict of the engine as a CandelaWarning, issued through `warnings`."""
    out = []
    for w in found:
        cw = CandelaWarning(w["text"], w["code"], w["file"], w["line"], w["message"])
        warnings.warn(cw, stacklevel=stacklevel + 1)
        out.append(cw)
    return out


def _time_text(time):
    """A time as the engine reads it: ISO 8601 text, or a datetime (an aware one keeps its offset)."""
    if isinstance(time, datetime.datetime):
        return time.isoformat(timespec="seconds")
    if isinstance(time, str):
        return time
    raise TypeError("time must be an ISO 8601 string or a datetime.datetime")


class Site:
    """A place on the earth.

    latitude, longitude: degrees, north and east positive. timezone: hours of local standard
    time from UTC (-8 for PST). elevation: metres above sea level. north: degrees, true north
    measured clockwise from the model's +Y (the sun and sky are rotated, not the geometry).
    """

    def __init__(self, latitude, longitude, timezone=0.0, elevation=0.0, north=0.0):
        self.latitude = float(latitude)
        self.longitude = float(longitude)
        self.timezone = float(timezone)
        self.elevation = float(elevation)
        self.north = float(north)

    def __repr__(self):
        return (f"Site(latitude={self.latitude}, longitude={self.longitude}, timezone={self.timezone}, "
                f"elevation={self.elevation}, north={self.north})")


SunPosition = namedtuple("SunPosition", "altitude_deg azimuth_deg zenith_deg sunrise_hour transit_hour sunset_hour")
SunPosition.__doc__ = """The sun seen from a site (NREL SPA): altitude above the horizon and azimuth
clockwise from true north, in degrees; sunrise, transit and sunset of that local day in hours of
local standard time (NaN when the sun does not rise or set)."""


def sun_position(site, time):
    """The sun's position at `site` (a Site) at `time` (ISO 8601 text or datetime, local standard time)."""
    d = _candela.sun_position(site.latitude, site.longitude, site.timezone, site.elevation, _time_text(time))
    return SunPosition(d["altitude_deg"], d["azimuth_deg"], d["zenith_deg"], d["sunrise_hour"],
                       d["transit_hour"], d["sunset_hour"])


class Sky:
    """A point-in-time sky (and sun) over the scene; make one with the class methods.

    Illuminances are in lux on the open horizontal plane (diffuse) or normal to the sun (direct),
    irradiances in W/m²; ground_reflectance is the ground's albedo (0..1).
    """

    def __init__(self, sky_type, **fields):
        self.type = sky_type
        self.fields = {k: v for k, v in fields.items() if v is not None}

    def __repr__(self):
        args = ", ".join(f"{k}={v!r}" for k, v in self.fields.items())
        return f"Sky({self.type!r}{', ' if args else ''}{args})"

    def _spec(self):
        d = dict(self.fields)
        d["type"] = self.type
        return d

    @staticmethod
    def _place(site, time, sun_altitude, sun_azimuth):
        d = {"sun_altitude": sun_altitude, "sun_azimuth": sun_azimuth}
        if site is not None:
            d.update(latitude=site.latitude, longitude=site.longitude, timezone=site.timezone,
                     elevation=site.elevation, north=site.north)
        if time is not None:
            d["time"] = _time_text(time)
        return d

    @classmethod
    def uniform(cls, diffuse_horizontal_illuminance=10000.0, ground_reflectance=0.2):
        """A sky of one luminance everywhere."""
        return cls("uniform", diffuse_horizontal_illuminance=diffuse_horizontal_illuminance,
                   ground_reflectance=ground_reflectance)

    @classmethod
    def cie_overcast(cls, diffuse_horizontal_illuminance=10000.0, ground_reflectance=0.2):
        """The CIE standard overcast sky (Moon & Spencer), as for daylight factors."""
        return cls("cie-overcast", diffuse_horizontal_illuminance=diffuse_horizontal_illuminance,
                   ground_reflectance=ground_reflectance)

    @classmethod
    def cie(cls, sky_type, site=None, time=None, *, sun=True, diffuse_horizontal_illuminance=None,
            direct_normal_illuminance=None, ground_reflectance=0.2, sun_altitude=None, sun_azimuth=None):
        """One of the 15 CIE general skies (ISO 15469), `sky_type` 1..15, or "clear" for the CIE clear sky.

        The sun's position comes from `site` and `time`, or from sun_altitude and sun_azimuth
        (degrees; azimuth clockwise from north). The sun disc of skies 7..15 and "clear" carries
        direct_normal_illuminance (lux); without it, it carries no light. The sky is scaled to
        diffuse_horizontal_illuminance (lux; default 10 000).
        """
        name = "cie-clear" if sky_type == "clear" else f"cie:{int(sky_type)}"
        return cls(name, sun=sun, diffuse_horizontal_illuminance=diffuse_horizontal_illuminance,
                   direct_normal_illuminance=direct_normal_illuminance, ground_reflectance=ground_reflectance,
                   **cls._place(site, time, sun_altitude, sun_azimuth))

    @classmethod
    def cie_clear(cls, site=None, time=None, **kwargs):
        """The CIE clear sky with its sun (give direct_normal_illuminance: without it the sun carries no light); see cie()."""
        return cls.cie("clear", site, time, **kwargs)

    @classmethod
    def perez(cls, site, time, direct_normal_irradiance, diffuse_horizontal_irradiance, *, sun=True,
              ground_reflectance=0.2, sun_altitude=None, sun_azimuth=None):
        """The Perez all-weather sky from an hour's direct normal and diffuse horizontal irradiance (W/m²)."""
        return cls("perez", sun=sun, direct_normal_irradiance=direct_normal_irradiance,
                   diffuse_horizontal_irradiance=diffuse_horizontal_irradiance, ground_reflectance=ground_reflectance,
                   **cls._place(site, time, sun_altitude, sun_azimuth))


class Luminaire:
    """A luminaire placed in a scene, as a case's [[luminaire]] entry (docs/case-format.md).

    file: IES LM-63 or EULUMDAT. position: photometric centre, m. aim: direction of the
    photometric nadir. spin: degrees about the aim (0: C0 plane towards +X). multiplier and
    maintenance_factor scale the intensities.
    """

    def __init__(self, file, position, aim=(0.0, 0.0, -1.0), spin=0.0, multiplier=1.0, maintenance_factor=1.0,
                 name=None):
        self.file = os.fspath(file)
        self.position = tuple(float(v) for v in position)
        self.aim = tuple(float(v) for v in aim)
        self.spin = float(spin)
        self.multiplier = float(multiplier)
        self.maintenance_factor = float(maintenance_factor)
        self.name = name

    def _spec(self):
        return {"file": self.file, "position": list(self.position), "aim": list(self.aim), "spin": self.spin,
                "multiplier": self.multiplier, "maintenance_factor": self.maintenance_factor, "name": self.name}


class Scene:
    """Radiance scene files (and OBJ files), read in order; checked when made (InputError at the bad line)."""

    def __init__(self, files=()):
        if isinstance(files, (str, os.PathLike)):
            files = [files]
        self.files = [os.fspath(f) for f in files]
        _candela.check_scene(self.files)

    def __repr__(self):
        return f"Scene(files={self.files!r})"


def illuminance(scene, points, *, sky=None, luminaires=(), quality="normal", seed=1, threads=0, method=None,
                progress=None, strict=False):
    """Illuminance at sensor points, as `candela points`: returns (lux, error), two arrays of N.

    scene: a Scene (or None: only the sky). points: an (N, 6) array of x y z dx dy dz (m; the
    direction is the sensor's normal). sky: a Sky or None. luminaires: Luminaire objects.
    quality: "draft", "normal" or "high"; method: None (the path tracer, as `candela points`),
    "path" or "cache"; threads: 0 = all cores. error is each value's Monte Carlo standard error
    in lux. progress(step, done, total), if given, is called on this thread while it runs.
    Warnings go through `warnings` (CandelaWarning); strict=True makes the first an InputError.
    """
    files = scene.files if scene is not None else []
    pts = np.ascontiguousarray(points, dtype=np.float64)
    lux, error, found = _candela.illuminance(files, pts, sky._spec() if sky is not None else None,
                                             [l._spec() for l in luminaires], quality, int(seed), int(threads),
                                             method, bool(strict), progress)
    _warn(found, stacklevel=2)
    return lux, error


class LuminaireData:
    """A photometric file read: its summary (as `candela luminaire` prints it) and its web.

    Attributes: file, format, luminaire, manufacturer, photometric_type ("C" or "B"),
    total_lumens, lamp_lumens (None for absolute photometry), light_output_ratio, max_intensity_cd
    and its direction (max_intensity_c_deg, max_intensity_gamma_deg), beam and field angles in the
    C0 and C90 planes (degrees), zonal_lumens (10° zones from nadir), downward_lumens,
    upward_lumens, input_watts and efficacy_lm_per_w (None when unknown), opening_m (width,
    length, height); the web: plane_angles_deg (C, expanded to the full circle), polar_angles_deg
    (gamma) and intensity_cd[plane, polar] (every multiplier applied).
    """

    def __init__(self, fields):
        self.__dict__.update(fields)

    def __repr__(self):
        return f"LuminaireData({self.file!r}, {self.total_lumens:.1f} lm, peak {self.max_intensity_cd:.1f} cd)"


def read_luminaire(path):
    """Reads an IES LM-63 or EULUMDAT file (InputError at the bad line)."""
    return LuminaireData(_candela.read_luminaire(os.fspath(path)))


_HOURLY_HEADER = struct.Struct("<8sIIII16s8s")


def _hourly_memmap(path):
    """A read-only memmap (sensors × hours, float32 lux) of an _hourly.f32 file (docs/annual-outputs.md), and its stamps."""
    with open(path, "rb") as f:
        head = f.read(_HOURLY_HEADER.size)
    if len(head) < _HOURLY_HEADER.size:
        raise InputError(f"{path}: truncated header", path, 0, "truncated header")
    magic, version, offset, sensors, hours, layout, units = _HOURLY_HEADER.unpack(head)
    if magic != b"CNDLHRLY" or version != 1 or layout.rstrip(b"\0") != b"sensor-major" or units.rstrip(b"\0") != b"lux":
        raise InputError(f"{path}: not a version 1 candela hourly results file", path, 0,
                         "not a version 1 candela hourly results file")
    if os.path.getsize(path) != offset + 4 * sensors * hours:
        raise InputError(f"{path}: the file's size does not match its header", path, 0,
                         "the file's size does not match its header")
    stamps = np.fromfile(path, dtype=np.uint8, count=4 * hours, offset=_HOURLY_HEADER.size).reshape(hours, 4)[:, :3]
    values = np.memmap(path, dtype="<f4", mode="r", offset=offset, shape=(sensors, hours))
    return values, stamps


def _read_csv(path):
    """A results CSV as {column: float array}."""
    with open(path, encoding="utf-8") as f:
        header = f.readline().strip().split(",")
    data = np.genfromtxt(path, delimiter=",", skip_header=1, dtype=np.float64, ndmin=2)
    if data.size == 0:
        data = np.empty((0, len(header)))
    return {name: data[:, k].copy() for k, name in enumerate(header)}


class Grid:
    """One grid of a run's results, read from its files on first use.

    positions, normals: (N, 3) arrays (m, unit). illuminance: (N,) its value column (lux, or the
    grid's quantity); error: (N,) Monte Carlo standard errors in lux (None where the run has
    none). columns: every column of <grid>.csv by name. Annual runs: hourly, a read-only
    numpy.memmap (N, hours) of float32 lux over <grid>_hourly.f32 (no copy), hour_stamps (hours,
    3) month, day, hour ending; direct_sun_hourly likewise; annual, the per-sensor metrics of
    <grid>_annual.csv by name.
    """

    def __init__(self, out_dir, name):
        self.name = name
        self._stem = os.path.join(out_dir, _candela.file_stem(name))

    def __repr__(self):
        return f"Grid({self.name!r})"

    @functools.cached_property
    def columns(self):
        return _read_csv(self._stem + ".csv")

    @property
    def positions(self):
        c = self.columns
        return np.column_stack([c["x"], c["y"], c["z"]])

    @property
    def normals(self):
        c = self.columns
        return np.column_stack([c["dx"], c["dy"], c["dz"]])

    @property
    def illuminance(self):
        return self.columns[list(self.columns)[6]]

    @property
    def error(self):
        return self.columns.get("error_lux")

    @functools.cached_property
    def _hourly(self):
        path = self._stem + "_hourly.f32"
        return _hourly_memmap(path) if os.path.exists(path) else (None, None)

    @property
    def hourly(self):
        return self._hourly[0]

    @property
    def hour_stamps(self):
        return self._hourly[1]

    @functools.cached_property
    def direct_sun_hourly(self):
        path = self._stem + "_direct_sun_hourly.f32"
        return _hourly_memmap(path)[0] if os.path.exists(path) else None

    @functools.cached_property
    def annual(self):
        path = self._stem + "_annual.csv"
        return _read_csv(path) if os.path.exists(path) else None


class Results:
    """A finished run: out_dir, summary (summary.json as a dict), warnings (CandelaWarning list),
    grids (name -> Grid, in the case's order) and annual (bool)."""

    def __init__(self, out_dir, warnings_found=(), annual=False):
        self.out_dir = out_dir
        self.warnings = list(warnings_found)
        self.annual = annual
        with open(os.path.join(out_dir, "summary.json"), encoding="utf-8") as f:
            self.summary = json.load(f)
        self.grids = {g["name"]: Grid(out_dir, g["name"]) for g in self.summary.get("grids", [])}

    def __repr__(self):
        return f"Results({self.out_dir!r}, grids={list(self.grids)})"


class Case:
    """A case file read and checked (docs/case-format.md): name, path, annual, grids (names), out_dir."""

    def __init__(self, path):
        info = _candela.load_case(os.fspath(path))
        self.path = info["path"]
        self.name = info["name"]
        self.description = info["description"]
        self.annual = info["annual"]
        self.grids = info["grids"]
        self.out_dir = info["out_dir"]

    def __repr__(self):
        return f"Case({self.path!r})"

    def run(self, out=None, quality=None, threads=None, seed=None, progress=None, strict=False):
        """Runs the case as `candela run` does and returns its Results.

        out: the results folder (None: the case's [output] dir); quality, threads and seed
        override the case's (None: the case's). progress(step, done, total) is called on this
        thread while it runs. Ctrl-C stops the run and leaves no partial output (the folder keeps
        its previous result). Warnings go through `warnings`; strict=True makes the first an
        InputError before anything is written.
        """
        r = _candela.run_case(self.path, None if out is None else os.fspath(out), quality,
                              None if threads is None else int(threads), None if seed is None else int(seed),
                              bool(strict), progress)
        found = _warn(r["warnings"], stacklevel=2)
        return Results(r["out_dir"], found, r["annual"])


def load_case(path):
    """Reads and checks a case file (InputError at the bad line)."""
    return Case(path)
