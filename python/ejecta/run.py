"""A whole run directory: its series, summary, logs, grids and crater, each read when asked for."""
import glob
import os

from .errors import EjectaFileError
from .grids import load_grids
from .series import load_series
from .tables import load_crater_profile, load_csv, load_energy, load_summary


class Run:
    """What `ejecta run --out DIR` wrote into DIR.

    `run.series` (the snapshots), `run.summary` (summary.json), `run.energy` (energy.csv),
    `run.crater_profile` (crater_profile.csv), `run.grid_files` (fields/*.vdb, in order) and
    `run.grids(i)` (the i-th of them; -1: the last), `run.csv(name)` (any other CSV).
    """

    def __init__(self, path):
        self.path = os.fspath(path)
        if not os.path.isdir(self.path):
            raise EjectaFileError(self.path, "no such run directory")
        if not (os.path.exists(os.path.join(self.path, "summary.json"))
                or os.path.isdir(os.path.join(self.path, "snapshots"))):
            raise EjectaFileError(self.path, "not a run directory (no summary.json, no snapshots/)")
        self._series = None

    def __repr__(self):
        return "<ejecta.Run %s>" % self.path

    @property
    def series(self):
        if self._series is None:
            self._series = load_series(self.path)
        return self._series

    @property
    def summary(self):
        return load_summary(self.path)

    @property
    def energy(self):
        return load_energy(self.path)

    @property
    def crater_profile(self):
        return load_crater_profile(self.path)

    @property
    def grid_files(self):
        return sorted(glob.glob(os.path.join(self.path, "fields", "fields_*.vdb")))

    def grids(self, index=-1, names=None):
        files = self.grid_files
        if not files:
            raise EjectaFileError(self.path, "no grid files (the scene has no [fields] table)", "fields/")
        return load_grids(files[index], names)

    def csv(self, name):
        return load_csv(os.path.join(self.path, name))


def load_run(path):
    """Opens the run directory `path`."""
    return Run(path)
