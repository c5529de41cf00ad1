"""A run's snapshots in time order: from its snapshots.xdmf, or from the files themselves."""
import glob
import os
import xml.etree.ElementTree as ElementTree

import numpy as np

from .errors import EjectaFileError
from .snapshot import Snapshot
from .units import UnitArray


class Series:
    """The snapshots of one run, in time order, opened when first asked for.

    `len(series)`, `series[i]` (a Snapshot; negative indices count from the end),
    `series.times` (a UnitArray in s), `series.at(t)` (the snapshot nearest time t [s]).
    """

    def __init__(self, entries, source):
        self.source = source
        self._files = [path for path, _ in entries]
        self.times = UnitArray(np.array([t for _, t in entries], dtype=float), "s", "snapshot times")
        self._open = {}

    def __len__(self):
        return len(self._files)

    def __getitem__(self, index):
        if isinstance(index, slice):
            return [self[i] for i in range(*index.indices(len(self)))]
        if index < 0:
            index += len(self)
        if not 0 <= index < len(self):
            raise IndexError("%s: snapshot %d of %d" % (self.source, index, len(self)))
        if index not in self._open:
            self._open[index] = Snapshot(self._files[index])
        return self._open[index]

    def __iter__(self):
        return (self[i] for i in range(len(self)))

    def __repr__(self):
        if not len(self):
            return "<ejecta.Series %s: empty>" % self.source
        return "<ejecta.Series %s: %d snapshots, t = %.6g .. %.6g s>" % (
            self.source, len(self), self.times[0], self.times[-1])

    @property
    def files(self):
        return list(self._files)

    def at(self, time):
        """The snapshot nearest `time` [s]."""
        if not len(self):
            raise IndexError("%s: no snapshots" % self.source)
        return self[int(np.argmin(np.abs(np.asarray(self.times) - float(time))))]


def _from_xdmf(path):
    try:
        root = ElementTree.parse(path).getroot()
    except (ElementTree.ParseError, OSError) as error:
        raise EjectaFileError(path, "cannot read as XDMF (%s)" % error) from None
    folder = os.path.dirname(os.path.abspath(path))
    entries = []
    for grid in root.iter("Grid"):
        if grid.get("GridType") != "Uniform":
            continue
        time = grid.find("Time")
        item = grid.find("Geometry/DataItem")
        if time is None or item is None or ":" not in (item.text or ""):
            raise EjectaFileError(path, "a grid without a time or an HDF5 geometry", grid.get("Name"))
        h5 = item.text.strip().rsplit(":", 1)[0]
        entries.append((os.path.join(folder, h5), float(time.get("Value"))))
    return entries


def _from_files(folder):
    entries = []
    for path in sorted(glob.glob(os.path.join(folder, "snap_*.h5"))):
        entries.append((path, Snapshot(path).time))
    return entries


def load_series(path):
    """The snapshots of a run: `path` is a run directory, its snapshots.xdmf, or its snapshots/.

    A run directory's snapshots.xdmf is read when there is one (its times are the snapshots'
    exact times); otherwise the snapshots/snap_*.h5 files are opened for their times.
    """
    path = os.fspath(path)
    if os.path.isfile(path):
        entries = _from_xdmf(path)
    elif os.path.isdir(path):
        xdmf = os.path.join(path, "snapshots.xdmf")
        folder = os.path.join(path, "snapshots") if os.path.isdir(os.path.join(path, "snapshots")) else path
        entries = _from_xdmf(xdmf) if os.path.isfile(xdmf) else _from_files(folder)
    else:
        raise EjectaFileError(path, "no such file or directory")
    entries.sort(key=lambda e: e[1])
    return Series(entries, path)
