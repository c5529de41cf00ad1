"""Read ejecta's run outputs from Python.

    import ejecta
    run = ejecta.load_run("runs/demo")          # a run directory
    snap = run.series[-1]                       # the last snapshot (ejecta.Snapshot)
    snap.density, snap.density.units            # a UnitArray per particle field
    snap.r, snap.z, snap.material_name          # coordinates and materials by name
    ejecta.load_summary("runs/demo")["status"]  # summary.json
    ejecta.load_grids("runs/demo/fields/fields_0003.vdb")["density"].values

Every reader raises ejecta.EjectaFileError naming the file, the object and the reason.
The guide: docs/python.md.
"""
from .errors import EjectaFileError
from .grids import Grid, Grids, load_grids
from .run import Run, load_run
from .series import Series, load_series
from .snapshot import Material, Snapshot, load_snapshot
from .tables import load_crater_profile, load_csv, load_energy, load_summary
from .units import UnitArray

__version__ = "0.1.0"

__all__ = [
    "EjectaFileError", "Grid", "Grids", "Material", "Run", "Series", "Snapshot", "UnitArray",
    "load_crater_profile", "load_csv", "load_energy", "load_grids", "load_run", "load_series",
    "load_snapshot", "load_summary",
]
