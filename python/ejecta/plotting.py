"""The common pictures of a run with matplotlib (imported only when a helper is called).

Each helper draws into `ax` (a new figure's axes when None) and returns what it drew, so a
report's figure can combine several.
"""
import numpy as np


def _axes(ax):
    if ax is None:
        import matplotlib.pyplot as plt
        _, ax = plt.subplots(figsize=(6, 5))
    return ax


def time_scale(seconds):
    """A display unit for times spanning `seconds`: ("ms", 1e3), ("us", 1e6) or ("s", 1)."""
    span = float(np.max(np.abs(seconds))) if np.size(seconds) else 0.0
    if 0 < span < 2e-3:
        return "us", 1e6
    if 0 < span < 2.0:
        return "ms", 1e3
    return "s", 1.0


def plot_particles(snapshot, field="density", ax=None, log=False, cmap="viridis", mirror=None,
                   vmin=None, vmax=None, mask=None):
    """The particles of a 2D, RZ or 1D snapshot coloured by `field`, each drawn as a disc of its
    smoothing length (no moire of single pixels). RZ is mirrored about the axis unless
    mirror=False. Returns the scatter; its colour bar is labelled with the field's units."""
    from matplotlib.colors import LogNorm, Normalize

    ax = _axes(ax)
    values = np.asarray(snapshot[field], dtype=float)
    if values.ndim != 1:
        raise ValueError("%s: '%s' has %d components; plot a component or a derived scalar"
                         % (snapshot.path, field, values.shape[1]))
    position = np.asarray(snapshot["position"])
    h = np.asarray(snapshot["smoothing_length"])
    keep = np.ones(len(values), dtype=bool) if mask is None else np.asarray(mask)
    x, y = position[keep, 0], position[keep, 1] if snapshot.dimension > 1 else np.zeros(keep.sum())
    values, h = values[keep], h[keep]
    if not len(values):
        raise ValueError("%s: no particles to draw (the mask selects none)" % snapshot.path)
    if mirror is None:
        mirror = snapshot.geometry == "rz"
    if mirror:
        x, y, values, h = np.concatenate([x, -x]), np.concatenate([y, y]), np.tile(values, 2), np.tile(h, 2)
    low = vmin if vmin is not None else np.nanmin(values[values > 0]) if log and np.any(values > 0) else vmin
    norm = LogNorm(vmin=low, vmax=vmax) if log else Normalize(vmin=vmin, vmax=vmax)
    ax.set_aspect("equal")
    pad = float(np.max(h)) if len(h) else 0.0
    ax.set_xlim(x.min() - pad, x.max() + pad)
    ax.set_ylim(y.min() - pad, y.max() + pad)
    drawn = ax.scatter(x, y, c=values, s=1.0, cmap=cmap, norm=norm, linewidths=0)
    units = getattr(snapshot[field], "units", "1")
    bar = ax.figure.colorbar(drawn, ax=ax)
    bar.set_label("%s [%s]%s" % (field, units, " (log)" if log else ""))
    # Marker areas in points^2 from the smoothing length in data units, once the colour bar
    # and the equal aspect have set the axes' final size (a disc of diameter h).
    ax.figure.canvas.draw()
    box = ax.get_window_extent()
    x0, x1 = ax.get_xlim()
    points_per_metre = box.width * 72.0 / ax.figure.dpi / max(x1 - x0, 1e-300)
    drawn.set_sizes((points_per_metre * h) ** 2)
    names = snapshot.coordinates
    ax.set_xlabel("%s [m]" % names[0])
    if len(names) > 1:
        ax.set_ylabel("%s [m]" % names[1])
    unit, factor = time_scale(snapshot.time)
    ax.set_title("%s, t = %.4g %s" % (snapshot.scene, snapshot.time * factor, unit))
    return drawn


def plot_crater_profile(profile, ax=None, label=None):
    """A crater profile (load_crater_profile) with depth downward below the pre-impact surface
    (the dashed line at 0), mirrored about the centre."""
    ax = _axes(ax)
    r = np.asarray(profile["distance_m"])
    depth = np.asarray(profile["depth_mean_m"])
    x = np.concatenate([-r[::-1], r])
    z = -np.concatenate([depth[::-1], depth])
    line, = ax.plot(x, z, label=label)
    if "depth_min_m" in profile and "depth_max_m" in profile:
        low = -np.concatenate([profile["depth_max_m"][::-1], profile["depth_max_m"]])
        high = -np.concatenate([profile["depth_min_m"][::-1], profile["depth_min_m"]])
        ax.fill_between(x, low, high, color=line.get_color(), alpha=0.25, linewidth=0)
    ax.axhline(0.0, color="0.5", linestyle="--", linewidth=1, label="pre-impact surface")
    ax.set_xlabel("distance from the crater centre [m]")
    ax.set_ylabel("height relative to the pre-impact surface [m]")
    ax.set_aspect("equal", adjustable="datalim")
    return line


def plot_energy(energy, ax=None):
    """The relative energy error of every step (load_energy) against time, in ms or us."""
    ax = _axes(ax)
    t = np.asarray(energy["time_s"])
    unit, factor = time_scale(t)
    line, = ax.plot(t * factor, np.asarray(energy["relative_error"]))
    ax.set_xlabel("time [%s]" % unit)
    ax.set_ylabel("relative energy error")
    return line
