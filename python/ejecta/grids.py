"""Sparse OpenVDB grid files (fields/fields_NNNN.vdb; docs/fields.md) as numpy arrays.

Needs OpenVDB's Python module (Debian: python3-openvdb; it is not on PyPI).
"""
import os

import numpy as np

from .errors import EjectaFileError
from .units import UnitArray


def _openvdb():
    try:
        import pyopenvdb
    except ImportError:
        try:
            import openvdb as pyopenvdb
        except ImportError:
            raise ImportError("ejecta.load_grids needs OpenVDB's Python module "
                              "(Debian: apt install python3-openvdb)") from None
    return pyopenvdb


class Grid:
    """One grid: `values` over its active bounding box (a dense UnitArray, the background where
    inactive), `origin` (world position of values[0, 0, 0], m), `voxel_size` (m), `units`,
    `grid_class` ("fog volume" or "level set"), `metadata` (everything the file stores)."""

    def __init__(self, vdb_grid):
        self.name = vdb_grid.name
        self.metadata = dict(vdb_grid.metadata)
        self.grid_class = self.metadata.get("class", "")
        self.units = self.metadata.get("units", "1")
        self.background = vdb_grid.background
        self.active_voxels = vdb_grid.activeVoxelCount()
        voxel = vdb_grid.transform.voxelSize()
        self.voxel_size = float(voxel[0])
        low, high = vdb_grid.evalActiveVoxelBoundingBox()
        self.index_min = tuple(int(i) for i in low)
        shape = tuple(max(0, int(h) - int(l) + 1) for l, h in zip(low, high))
        dense = np.full(shape, self.background, dtype=np.float32)
        if self.active_voxels:
            vdb_grid.copyToArray(dense, ijk=self.index_min)
        self.values = UnitArray(dense, self.units, self.name)
        self.origin = tuple(float(c) for c in vdb_grid.transform.indexToWorld(self.index_min))

    def __repr__(self):
        return "<ejecta.Grid %s (%s, %s): %d active voxels of %.4g m>" % (
            self.name, self.grid_class, self.units, self.active_voxels, self.voxel_size)

    def axis(self, k):
        """World coordinates [m] of the voxel centres along axis k (0, 1, 2) of `values`."""
        return UnitArray(self.origin[k] + self.voxel_size * np.arange(self.values.shape[k]), "m")


class Grids(dict):
    """The grids of one file by name, with the file's metadata (time, step, scene) as `info`."""

    def __init__(self, path, grids, info):
        super().__init__((g.name, g) for g in grids)
        self.path = path
        self.info = info
        self.time = float(info.get("time", float("nan")))

    def __repr__(self):
        return "<ejecta.Grids %s: t = %.6g s, %s>" % (os.path.basename(self.path), self.time, ", ".join(sorted(self)))


def load_grids(path, names=None):
    """The grids of an ejecta grid file (`names`: only these), by name."""
    path = os.fspath(path)
    if not os.path.isfile(path):
        raise EjectaFileError(path, "no such file")
    vdb = _openvdb()
    try:
        vdb_grids, info = vdb.readAll(path)
    except Exception as error:  # OpenVDB raises plain RuntimeError/IOError with its own text
        raise EjectaFileError(path, "cannot read as an OpenVDB file (%s)" % error) from None
    if "creator" in info and not str(info["creator"]).startswith("ejecta"):
        raise EjectaFileError(path, "written by %s, not by ejecta" % info["creator"])
    chosen = [Grid(g) for g in vdb_grids if names is None or g.name in names]
    if names is not None:
        missing = sorted(set(names) - {g.name for g in chosen})
        if missing:
            raise EjectaFileError(path, "no grid named %s (grids: %s)"
                                  % (", ".join(missing), ", ".join(sorted(g.name for g in vdb_grids))))
    return Grids(path, chosen, dict(info))
