"""Arrays that carry their SI units: what every reader in this package returns.

A `UnitArray` is a numpy array with two extra attributes, `units` (SI, as ejecta writes them:
"kg/m^3", "Pa", "1" for dimensionless) and `description`. Arithmetic gives plain results
with the units of the left operand only where numpy keeps the subclass, so treat `units` as a
label for plots and checks, not as a unit system (convert with `to`).
"""
import numpy as np

# Factors from SI to the few display units the plotting helpers use.
_SCALE = {
    ("s", "ms"): 1e3, ("s", "us"): 1e6, ("m", "mm"): 1e3, ("m", "km"): 1e-3,
    ("Pa", "GPa"): 1e-9, ("Pa", "MPa"): 1e-6, ("Pa", "kPa"): 1e-3,
    ("kg/m^3", "g/cm^3"): 1e-3, ("J/kg", "MJ/kg"): 1e-6, ("m/s", "km/s"): 1e-3,
    ("J", "kt"): 1.0 / 4.184e12,  # 1 kt TNT = 4.184e12 J (the convention ejecta's scenes use)
}


class UnitArray(np.ndarray):
    """A numpy array with `units` and `description` attributes."""

    def __new__(cls, values, units="1", description=""):
        array = np.asarray(values).view(cls)
        array.units = str(units)
        array.description = str(description)
        return array

    def __array_finalize__(self, source):
        self.units = getattr(source, "units", "1")
        self.description = getattr(source, "description", "")

    def to(self, units):
        """The values in `units` (one of the display units in _SCALE), as a new UnitArray."""
        if units == self.units:
            return self.copy()
        try:
            factor = _SCALE[(self.units, units)]
        except KeyError:
            raise ValueError("cannot convert %s to %s" % (self.units, units)) from None
        return UnitArray(np.asarray(self) * factor, units, self.description)

    def __repr__(self):
        return "UnitArray(%s, units=%r)" % (np.array2string(np.asarray(self), threshold=6), self.units)

    def __reduce__(self):
        # Keep the units through pickling (multiprocessing, caches).
        constructor, args, state = super().__reduce__()
        return constructor, args, (state, self.units, self.description)

    def __setstate__(self, state):
        array_state, self.units, self.description = state
        super().__setstate__(array_state)


def units_from_column(name):
    """The units a CSV column name spells with its suffix: depth_m -> m, time_s -> s."""
    suffixes = [("_m3", "m^3"), ("_kg", "kg"), ("_m", "m"), ("_s", "s"), ("_J", "J"),
                ("_Pa", "Pa"), ("_K", "K"), ("_W_m2", "W/m^2"), ("_kg_m3", "kg/m^3"),
                ("_m_s", "m/s")]
    for suffix, units in sorted(suffixes, key=lambda s: -len(s[0])):
        if name.endswith(suffix):
            return units
    return "1"
