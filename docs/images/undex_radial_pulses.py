"""Doc figure for docs/undex.md ("The converged 1D reference"): the 1 kg TNT sphere's pressure
pulses at the four gauges of scenes/undex_rz.toml from the 1D Lagrangian reference
(`ejecta undex-reference scenes/undex_rz.toml --zones N`) at several zone widths, against Cole's
similitude pulse P_max exp(-t/theta) and the SPH peaks of the page's RZ table (5 and 3.5 mm).
Reads docs/images/undex_radial_pulses.csv (t_after_arrival_us, then <gauge>_<zone width>_MPa:
overpressure, time from the finest run's arrival at half its peak) and writes
docs/images/undex_radial_pulses.png.
Run from the repository root: /usr/bin/python3 docs/images/undex_radial_pulses.py
"""
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
W = 0.9993  # charge mass [kg]: 5.27 cm at 1630 kg/m^3
R0 = 0.0527

rows = list(csv.DictReader(open(os.path.join(HERE, "undex_radial_pulses.csv"))))
t = [float(r["t_after_arrival_us"]) for r in rows]
columns = [c for c in rows[0].keys() if c != "t_after_arrival_us"]

# The SPH RZ peaks (docs/undex.md, "Results"): 5 mm and 3.5 mm particle spacing.
sph = {"g025": (255.7, 274.8), "g050": (91.1, 98.9), "g075": (50.6, 55.1), "g100": (33.7, 36.7)}
radius = {"g025": 0.25, "g050": 0.5, "g075": 0.75, "g100": 1.0}

fig, axes = plt.subplots(2, 2, figsize=(11, 7.5))
for ax, g in zip(axes.flat, ["g025", "g050", "g075", "g100"]):
    R = radius[g]
    for k, c in enumerate(col for col in columns if col.startswith(g + "_")):
        label = c[len(g) + 1:-len("_MPa")].replace("mm", " mm")
        p = [float(r[c]) for r in rows]
        ax.plot(t, p, color=f"C{k}", lw=1.2, label=f"1D reference, {label} zones")
    # Cole (1948) in SI (docs/undex.md): P = 52.39 (W^1/3/R)^1.13 MPa, theta = 92.5 W^1/3 (W^1/3/R)^-0.22 us
    pc = 52.39 * (W ** (1 / 3) / R) ** 1.13
    tc = 92.5 * W ** (1 / 3) * (W ** (1 / 3) / R) ** -0.22
    applies = R > 12 * R0
    tt = [s for s in t if s >= 0.0]
    ax.plot(tt, [pc * math.exp(-s / tc) for s in tt], "k--" if applies else "k:", lw=1.0,
            label="Cole, P$_{max}$ e$^{-t/\\theta}$" + ("" if applies else " (outside its range)"))
    for (value, name, style) in [(sph[g][0], "SPH 5 mm peak", "-."), (sph[g][1], "SPH 3.5 mm peak", ":")]:
        ax.axhline(value, color="0.45", ls=style, lw=1.0, label=name)
    ax.set_title(f"{g}: R = {R} m ({R / R0:.1f} R$_0$)", fontsize=10)
    ax.set_xlim(-10, 250)
    ax.set_ylim(0, 1.15 * max(pc, max(float(r[c]) for r in rows for c in columns if c.startswith(g + "_"))))
    ax.set_xlabel("time after arrival [$\\mu$s]")
    ax.set_ylabel("overpressure [MPa]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
fig.suptitle("1 kg TNT sphere in water: converged 1D reference (JWL, programmed burn, Mie-Grüneisen water)",
             fontsize=11)
fig.tight_layout()
fig.savefig(os.path.join(HERE, "undex_radial_pulses.png"), dpi=110)
