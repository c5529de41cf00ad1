"""One HDF5 snapshot of a run (docs/output_format.md): the particles, with units, and what they are."""
import os
from collections import namedtuple

import h5py
import numpy as np

from .errors import EjectaFileError
from .units import UnitArray

# One row of the snapshot's /materials table: what a particle's `material` id means.
Material = namedtuple("Material", "id name eos strength fracture")

# The coordinates each geometry uses, by column of /particles/position.
_COORDINATES = {
    "line": ("x",),
    "planar": ("x", "y"),
    "rz": ("r", "z"),
    "3d": ("x", "y", "z"),
}


def _text(value):
    """An HDF5 string attribute or dataset entry as str (fixed-length strings read as bytes)."""
    if isinstance(value, bytes):
        return value.decode("utf-8")
    if isinstance(value, np.ndarray) and value.shape == ():
        return _text(value[()])
    return str(value)


class Snapshot:
    """The state of a run at one time. Particle arrays are read when first asked for.

    `snap.density`, `snap["density"]`: a UnitArray per /particles dataset (`snap.fields` lists
    them); `snap.r`, `snap.z` (RZ) or `snap.x`, `snap.y`, `snap.z`: the coordinates the geometry
    uses; `snap.materials`: the material table; `snap.material_name`: each particle's material
    by name; `snap.select(material="granite")`: a boolean mask.
    """

    def __init__(self, path):
        self.path = os.fspath(path)
        if not os.path.exists(self.path):
            raise EjectaFileError(self.path, "no such file")
        try:
            with h5py.File(self.path, "r") as f:
                self._read_header(f)
        except OSError as error:
            raise EjectaFileError(self.path, "cannot open as HDF5 (%s)" % error) from None
        except KeyError as error:  # a group without a dataset ejecta writes into it
            raise EjectaFileError(self.path, "missing (%s)" % error, "/materials") from None
        self._cache = {}

    def _read_header(self, f):
        for key in ("time", "step", "geometry", "dimension", "scene"):
            if key not in f.attrs:
                raise EjectaFileError(self.path, "missing root attribute '%s': not an ejecta snapshot" % key)
        self.time = float(f.attrs["time"])
        self.step = int(f.attrs["step"])
        self.geometry = _text(f.attrs["geometry"])
        self.dimension = int(f.attrs["dimension"])
        self.scene = _text(f.attrs["scene"])
        self.version = _text(f.attrs.get("ejecta_version", ""))
        if self.geometry not in _COORDINATES:
            raise EjectaFileError(self.path, "unknown geometry '%s'" % self.geometry, "/")
        if "particles" not in f or "position" not in f["particles"]:
            raise EjectaFileError(self.path, "missing", "/particles/position")
        self.fields = sorted(f["particles"].keys())
        self.num_particles = int(f["particles/position"].shape[0])
        self.materials = []
        if "materials" in f:
            group = f["materials"]
            names = [_text(v) for v in group["name"][()]]
            columns = [[_text(v) for v in group[key][()]] for key in ("eos", "strength", "fracture")]
            self.materials = [Material(i, names[i], columns[0][i], columns[1][i], columns[2][i])
                              for i in range(len(names))]

    def __len__(self):
        return self.num_particles

    def __repr__(self):
        return "<ejecta.Snapshot %s: t = %.6g s, step %d, %d particles, %s>" % (
            os.path.basename(self.path), self.time, self.step, self.num_particles, self.geometry)

    def __getitem__(self, name):
        if name not in self._cache:
            if name not in self.fields:
                raise KeyError("%s: no particle field '%s' (fields: %s)"
                               % (self.path, name, ", ".join(self.fields)))
            with h5py.File(self.path, "r") as f:
                dataset = f["particles"][name]
                self._cache[name] = UnitArray(dataset[()], _text(dataset.attrs.get("units", "1")),
                                              _text(dataset.attrs.get("description", "")))
        return self._cache[name]

    def __getattr__(self, name):
        # Only called for names that are not attributes: particle fields and coordinates.
        if name.startswith("_"):
            raise AttributeError(name)
        coordinates = _COORDINATES.get(self.__dict__.get("geometry", ""), ())
        if name in coordinates:
            column = coordinates.index(name)
            position = self["position"]
            return UnitArray(np.asarray(position)[:, column], "m", "position, %s" % name)
        if name in self.__dict__.get("fields", ()):
            return self[name]
        raise AttributeError("%s has no field or coordinate '%s'" % (self.__dict__.get("path"), name))

    @property
    def coordinates(self):
        """The names of the coordinates this geometry uses: ('r', 'z') in RZ."""
        return _COORDINATES[self.geometry]

    @property
    def material_name(self):
        """Each particle's material by name (from /materials; ids as text if the file has none)."""
        ids = np.asarray(self["material"])
        if not self.materials:
            return ids.astype(str)
        names = np.array([m.name for m in self.materials], dtype=object)
        if ids.size and (ids.min() < 0 or ids.max() >= len(names)):
            raise EjectaFileError(self.path, "material ids beyond the material table", "/particles/material")
        return names[ids]

    def select(self, material=None):
        """A boolean mask of the particles of `material` (a name or an id); all when None."""
        if material is None:
            return np.ones(self.num_particles, dtype=bool)
        if isinstance(material, str):
            return self.material_name == material
        return np.asarray(self["material"]) == int(material)

    @property
    def scene_source(self):
        """The text of the scene the run started from (with the overrides it was given)."""
        with h5py.File(self.path, "r") as f:
            if "restart/scene_source" not in f:
                return ""
            return _text(f["restart/scene_source"][()])


def load_snapshot(path):
    """Opens snapshot `path` (an .h5 file a run wrote under snapshots/)."""
    return Snapshot(path)
