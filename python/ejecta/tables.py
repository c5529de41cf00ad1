"""The run's JSON and CSV outputs: summary.json, energy.csv, crater_profile.csv, gauges.csv ..."""
import csv
import json
import os

import numpy as np

from .errors import EjectaFileError
from .units import UnitArray, units_from_column

# Units of the columns whose names do not carry them (energy.csv; docs/output_format.md).
_KNOWN_UNITS = {
    "step": "1", "relative_error": "1", "target_share": "1",
    "momentum_x": "kg m/s", "momentum_y": "kg m/s", "momentum_z": "kg m/s",
}


def _resolve(path, name):
    """`path` itself if it is a file, else the file `name` in the run directory `path`."""
    path = os.fspath(path)
    if os.path.isdir(path):
        path = os.path.join(path, name)
    if not os.path.isfile(path):
        raise EjectaFileError(path, "no such file")
    return path


def load_summary(path):
    """summary.json of a run (`path`: the run directory or the file) as a dict.

    The keys are docs/output_format.md's: status ("completed", "failed", "interrupted"),
    message, particles, steps, t_end, wall_seconds, energy, momentum, extras (crater, coupling,
    thermal, ... as the run measured them).
    """
    path = _resolve(path, "summary.json")
    try:
        with open(path, encoding="utf-8") as f:
            summary = json.load(f)
    except (ValueError, OSError) as error:
        raise EjectaFileError(path, "cannot read as JSON (%s)" % error) from None
    if not isinstance(summary, dict) or "status" not in summary:
        raise EjectaFileError(path, "not an ejecta summary (no 'status' key)")
    return summary


def load_csv(path):
    """Any of a run's CSV files as a dict of column name -> UnitArray (units from the names)."""
    path = os.fspath(path)
    if not os.path.isfile(path):
        raise EjectaFileError(path, "no such file")
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise EjectaFileError(path, "empty (no header line)")
    header, body = rows[0], [r for r in rows[1:] if r]
    for number, row in enumerate(body, start=2):
        if len(row) != len(header):
            raise EjectaFileError(path, "line %d has %d values, the header %d" % (number, len(row), len(header)))
    columns = {}
    for k, name in enumerate(header):
        try:
            values = np.array([float(row[k]) for row in body])
        except ValueError:
            values = np.array([row[k] for row in body], dtype=object)
            columns[name] = values
            continue
        columns[name] = UnitArray(values, _KNOWN_UNITS.get(name, units_from_column(name)), name)
    return columns


def load_crater_profile(path):
    """crater_profile.csv (`path`: the run directory or the file): the radial crater profile.

    distance_m: distance from the crater's centre along the surface [m]; depth_mean_m,
    depth_min_m, depth_max_m: depth below the pre-impact surface [m] (positive downward), the
    mean and spread over azimuth (equal in RZ). docs/crater.md.
    """
    return load_csv(_resolve(path, "crater_profile.csv"))


def load_energy(path):
    """energy.csv (`path`: the run directory or the file): energy and momentum of every step."""
    return load_csv(_resolve(path, "energy.csv"))
