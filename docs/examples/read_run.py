"""Read an ejecta run from Python and draw its common pictures (docs/python.md).

    ejecta run impact_rz --set "time.t_end=0.5 ms" --out runs/impact_rz_short
    python3 docs/examples/read_run.py runs/impact_rz_short [OUT_DIR]

Prints what the run holds and writes particles.png (the last snapshot's density),
crater.png (the crater profile, depth downward) and energy.png (the energy error) to OUT_DIR
(default: the run directory).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import ejecta  # noqa: E402  (after the path: runs from a source tree without pip install)


def main(run_dir, out_dir):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from ejecta.plotting import plot_crater_profile, plot_energy, plot_particles

    run = ejecta.load_run(run_dir)
    summary = run.summary
    print("%s: %s after %d steps (%s)" % (summary["scene"], summary["status"], summary["steps"], run_dir))
    series = run.series
    print("snapshots at t = %s s" % ", ".join("%.4g" % t for t in series.times))
    last = series[-1]
    for material in last.materials:
        mine = last.select(material=material.name)
        if not mine.any():
            continue
        print("  %-12s %6d particles, %.4g kg, peak pressure %.4g %s" % (
            material.name, mine.sum(), np.sum(last.mass[mine]), np.max(last.pressure[mine]),
            last.pressure.units))
    extras = summary.get("extras", {})
    if extras.get("crater_found"):
        print("  crater: depth %.4g m, diameter %.4g m" % (extras["crater_depth_m"], extras["crater_apparent_diameter_m"]))

    fig, ax = plt.subplots(figsize=(7, 5))
    plot_particles(last, "density", ax=ax)
    fig.savefig(os.path.join(out_dir, "particles.png"), dpi=120)
    if os.path.exists(os.path.join(run_dir, "crater_profile.csv")):
        fig, ax = plt.subplots(figsize=(7, 4))
        plot_crater_profile(run.crater_profile, ax=ax)
        fig.savefig(os.path.join(out_dir, "crater.png"), dpi=120)
    fig, ax = plt.subplots(figsize=(7, 4))
    plot_energy(run.energy, ax=ax)
    fig.savefig(os.path.join(out_dir, "energy.png"), dpi=120)
    print("pictures in %s" % out_dir)


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2] if len(sys.argv) == 3 else sys.argv[1])
