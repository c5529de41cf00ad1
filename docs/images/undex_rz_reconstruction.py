"""Doc figure and table for docs/undex.md ("The reconstructed viscosity"): the pressure pulses of
scenes/undex_rz.toml's four gauges from SPH runs with the plain and the reconstructed viscosity,
against the converged 1D reference (`ejecta undex-reference`).

Two steps, run from the repository root:
  1. collect (needs the runs; commands in docs/undex.md):
     /usr/bin/python3 docs/images/undex_rz_reconstruction.py collect REF_DIR LABEL=RUN_DIR ...
     reads REF_DIR/gauges_reference.csv and each RUN_DIR/gauges.csv and writes
     docs/images/undex_rz_reconstruction.csv: per gauge, the overpressure [MPa] every 0.5 us from
     20 us before to 300 us after each record's own arrival (the rise through half its peak);
  2. draw (from the CSV alone):
     /usr/bin/python3 docs/images/undex_rz_reconstruction.py
     writes docs/images/undex_rz_reconstruction.png and prints, per gauge and run, the peak and
     the impulse over the reference's first two decay constants, each over the reference's.
"""
import csv
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CSV = os.path.join(HERE, "undex_rz_reconstruction.csv")
GAUGES = ["g025", "g050", "g075", "g100"]
RADIUS = {"g025": 0.25, "g050": 0.5, "g075": 0.75, "g100": 1.0}
AMBIENT = 101325.0  # Pa, the scene's water pressure
STEP_US, BEFORE_US, AFTER_US = 0.5, 20.0, 300.0


def read_gauges(path):
    rows = list(csv.DictReader(open(path)))
    t = [float(r["time_s"]) * 1e6 for r in rows]
    out = {}
    for g in GAUGES:
        column = g + "_pressure_Pa"
        if column not in rows[0]:
            continue
        out[g] = [(float(r[column]) - AMBIENT) / 1e6 if r[column] != "nan" else 0.0 for r in rows]
    return t, out


def arrival(t, p):
    """Last rise through half the peak before the peak, linearly interpolated."""
    k = max(range(len(p)), key=lambda i: p[i])
    half = 0.5 * p[k]
    i = k
    while i > 0 and p[i - 1] >= half:
        i -= 1
    if i == 0:
        return t[0]
    return t[i - 1] + (half - p[i - 1]) * (t[i] - t[i - 1]) / (p[i] - p[i - 1])


def sample(t, p, at):
    """Linear interpolation of the record at time `at` (0 outside it)."""
    lo, hi = 0, len(t) - 1
    if at <= t[lo] or at >= t[hi]:
        return 0.0
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if t[mid] <= at:
            lo = mid
        else:
            hi = mid
    f = (at - t[lo]) / (t[hi] - t[lo])
    return p[lo] + f * (p[hi] - p[lo])


def collect(reference_dir, runs):
    records = [("reference", os.path.join(reference_dir, "gauges_reference.csv"))]
    for item in runs:
        label, directory = item.split("=", 1)
        records.append((label, os.path.join(directory, "gauges.csv")))
    grid = [-BEFORE_US + STEP_US * k for k in range(int((BEFORE_US + AFTER_US) / STEP_US) + 1)]
    columns = {}
    for label, path in records:
        t, gauges = read_gauges(path)
        for g, p in gauges.items():
            ta = arrival(t, p)
            columns[f"{g}_{label}_MPa"] = [sample(t, p, ta + s) for s in grid]
    with open(CSV + ".tmp", "w", newline="") as f:
        w = csv.writer(f)
        names = sorted(columns, key=lambda c: (c.split("_")[0], c != f"{c.split('_')[0]}_reference_MPa"))
        w.writerow(["t_after_arrival_us"] + names)
        for k, s in enumerate(grid):
            w.writerow([f"{s:.1f}"] + [f"{columns[c][k]:.5g}" for c in names])
    os.replace(CSV + ".tmp", CSV)
    print("wrote", CSV)


def one_over_e(t, p):
    k = max(range(len(p)), key=lambda i: p[i])
    target = p[k] / math.e
    for i in range(k, len(p) - 1):
        if p[i + 1] <= target:
            return t[i] + (p[i] - target) * (t[i + 1] - t[i]) / (p[i] - p[i + 1]) - t[k]
    return float("nan")


def draw():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = list(csv.DictReader(open(CSV)))
    t = [float(r["t_after_arrival_us"]) for r in rows]
    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5))
    print(f"{'gauge':6} {'run':22} {'peak MPa':>9} {'peak/ref':>9} {'impulse/ref':>12}")
    for ax, g in zip(axes.flat, GAUGES):
        names = [c for c in rows[0] if c.startswith(g + "_")]
        ref = [float(r[f"{g}_reference_MPa"]) for r in rows]
        theta = one_over_e(t, ref)
        window = [i for i, s in enumerate(t) if s <= 2.0 * theta]
        impulse_ref = sum(ref[i] for i in window) * STEP_US
        for k, c in enumerate(names):
            label = c[len(g) + 1:-len("_MPa")]
            p = [float(r[c]) for r in rows]
            style = dict(color="k", lw=1.6) if label == "reference" else dict(color=f"C{k}", lw=1.1)
            ax.plot(t, p, label=label.replace("_", " "), **style)
            impulse = sum(p[i] for i in window) * STEP_US
            print(f"{g:6} {label:22} {max(p):9.1f} {max(p) / max(ref):9.3f} "
                  f"{impulse / impulse_ref:12.3f}")
        ax.set_title(f"{g}: {RADIUS[g]} m")
        ax.set_xlim(-BEFORE_US, min(AFTER_US, 3.0 * theta))
        ax.set_xlabel("time after arrival [us]")
        ax.set_ylabel("overpressure [MPa]")
        ax.grid(alpha=0.3)
    axes.flat[0].legend(fontsize=8)
    fig.suptitle("undex_rz: SPH gauges against the converged 1D reference")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "undex_rz_reconstruction.png"), dpi=90)


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] == "collect":
        collect(sys.argv[2], sys.argv[3:])
    else:
        draw()
