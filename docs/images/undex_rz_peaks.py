"""Doc figure for docs/undex.md: the RZ 1 kg TNT sphere's gauge peaks and decay constants against
Cole's similitude laws. Reads docs/images/undex_rz_peaks.csv (R_m, peak_Pa, peak_Pa_reference,
theta_s, theta_s_reference) and writes docs/images/undex_rz_peaks.png.
Run from the repository root: /usr/bin/python3 docs/images/undex_rz_peaks.py
"""
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
R0 = 0.0527  # charge radius [m], 1 kg at 1630 kg/m^3

rows = list(csv.DictReader(open(os.path.join(HERE, "undex_rz_peaks.csv"))))
R = [float(r["R_m"]) for r in rows]
peak = [float(r["peak_Pa"]) / 1e6 for r in rows]
theta = [float(r["theta_s"]) * 1e6 for r in rows]

# Reference lines, W = 1 kg (docs/undex.md cites them):
#   Cole (1948) / Swisdak (1978): P = 52.4 (W^1/3/R)^1.13 MPa, theta = 0.084 W^1/3 (W^1/3/R)^-0.23 ms
#   Cole's imperial constants in SI: theta = 92.5 W^1/3 (W^1/3/R)^-0.22 us
#   Zamyshlyayev's near field as usually quoted (6 < R/R0 < 12): 44.1 (W^1/3/R)^1.5 MPa
rr = [0.2 + 0.01 * k for k in range(91)]
cole = [52.4 * (1 / r) ** 1.13 for r in rr]
near = [44.1 * (1 / r) ** 1.5 for r in rr if 6 * R0 <= r <= 12 * R0]
swisdak_theta = [84.0 * (1 / r) ** -0.23 for r in rr]
cole_theta = [92.5 * (1 / r) ** -0.22 for r in rr]

fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
a.plot(rr, cole, "k--", label="Cole / Swisdak, 52.4 (W$^{1/3}$/R)$^{1.13}$ MPa")
a.plot([r for r in rr if 6 * R0 <= r <= 12 * R0], near, "k:",
       label="Zamyshlyayev near field, 44.1 (W$^{1/3}$/R)$^{1.5}$ MPa")
far = [r for r in rr if r >= 12 * R0]
a.fill_between(far, [0.9 * 52.4 * (1 / r) ** 1.13 for r in far], [1.1 * 52.4 * (1 / r) ** 1.13 for r in far],
               color="0.85", label="Cole $\\pm$10%, where it applies (R > 12 R$_0$)")
a.plot(R, peak, "o", color="C0", label="ejecta, scenes/undex_rz.toml")
a.axvline(12 * R0, color="0.7", lw=0.8)
a.text(12 * R0 * 1.02, 300, "R = 12 R$_0$", color="0.4", fontsize=8)
a.set_xscale("log")
a.set_yscale("log")
a.set_xticks([0.25, 0.5, 0.75, 1.0])
a.set_xticklabels(["0.25", "0.5", "0.75", "1.0"])
a.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
a.yaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
a.set_yticks([30, 50, 100, 200, 300])
a.set_yticklabels(["30", "50", "100", "200", "300"])
a.set_xlabel("R [m]")
a.set_ylabel("peak pressure [MPa]")
a.legend(fontsize=8)
a.grid(True, which="both", alpha=0.3)

b.plot(rr, swisdak_theta, "k--", label="Swisdak, 0.084 W$^{1/3}$ (W$^{1/3}$/R)$^{-0.23}$ ms")
b.plot(rr, cole_theta, "k-.", label="Cole (SI), 92.5 W$^{1/3}$ (W$^{1/3}$/R)$^{-0.22}$ $\\mu$s")
ok = [(r, t) for r, t in zip(R, theta) if not math.isnan(t)]
b.plot([r for r, _ in ok], [t for _, t in ok], "o", color="C0", label="ejecta, time to P$_{max}$/e")
b.set_xlabel("R [m]")
b.set_ylabel("decay constant $\\theta$ [$\\mu$s]")
b.set_ylim(0, 110)
b.legend(fontsize=8)
b.grid(True, alpha=0.3)
fig.suptitle("1 kg TNT sphere in water (RZ): shock peak and decay constant")
fig.tight_layout()
fig.savefig(os.path.join(HERE, "undex_rz_peaks.png"), dpi=110)
