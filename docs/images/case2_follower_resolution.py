"""Doc figure for docs/asteroid_studies.md, "Resolution check of the real-crater study": Case 2 in
the real crater (scenes/case2_rz_follower.toml) at 0.5 m and 0.25 m spacing. Reads
docs/images/case2_follower_resolution.csv (one row per station; the 0.25 m columns are empty
where that run stopped before it had a share to report) and writes
docs/images/case2_follower_resolution.png.
Run from the repository root: /usr/bin/python3 docs/images/case2_follower_resolution.py
"""
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
rows = list(csv.DictReader(open(os.path.join(HERE, "case2_follower_resolution.csv"))))


def series(column):
    """(height, value) pairs of the rows where `column` has a value."""
    return [(float(r["height_above_floor_m"]), float(r[column])) for r in rows if r[column]]


def plot(ax, column, style, label, **kw):
    pts = series(column)
    ax.plot([h for h, _ in pts], [v for _, v in pts], style, label=label, **kw)


C05, C025 = "C0", "C1"  # one colour per resolution in both panels


fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.4), sharey=True)
plot(a, "share_pct_0p5m", "o--", "0.5 m (6 device particles)", color=C05)
plot(a, "share_pct_0p25m", "s-", "0.25 m (26 device particles)", color=C025)
a.set_title("target's share of the yield (the ledger)")
plot(b, "body_pct_0p5m", "o--", "body, 0.5 m", color=C05)
plot(b, "body_pct_0p25m", "s-", "body, 0.25 m", color=C025)
plot(b, "above_pct_0p5m", "o:", "above the surface at 3 ms, 0.5 m", color=C05, mfc="white")
plot(b, "above_pct_0p25m", "s:", "above the surface at 3 ms, 0.25 m", color=C025, mfc="white")
b.set_title("split by where the target's particles were at 3 ms")

# The 0.25 m runs that stopped early: say so on the chart.
for r in rows:
    if r["status_0p25m"] != "completed" and r["share_pct_0p25m"]:
        h = float(r["height_above_floor_m"])
        a.annotate(f"0.25 m run {r['status_0p25m']}", (h, float(r["share_pct_0p25m"])),
                   xytext=(h - 3.2, float(r["share_pct_0p25m"]) + 9), fontsize=8,
                   arrowprops=dict(arrowstyle="->", color="0.4"))
missing = [r for r in rows if not r["share_pct_0p25m"]]
for r in missing:
    h = float(r["height_above_floor_m"])
    a.annotate(f"{r['station']}: 0.25 m run {r['status_0p25m']},\n0.26 ms after the burst",
               (h, float(r["share_pct_0p5m"])), xytext=(h + 0.6, float(r["share_pct_0p5m"]) + 4),
               fontsize=8, arrowprops=dict(arrowstyle="->", color="0.4"))

for ax in (a, b):
    ax.axvline(0.0, color="0.7", lw=0.8)
    ax.axvline(6.47, color="0.7", lw=0.8, ls="--")
    ax.set_xlabel("station: device centre above the void crater's floor [m]")
    ax.set_ylim(0, 100)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="upper right")
a.text(0.1, 2, "floor", color="0.4", fontsize=8)
a.text(6.57, 2, "original surface", color="0.4", fontsize=8)
a.set_ylabel("% of the 100 kt yield, 5 ms after the burst")
fig.suptitle("Case 2 in the real crater (RZ, fired at 3 ms): 0.5 m against 0.25 m")
fig.tight_layout()
fig.savefig(os.path.join(HERE, "case2_follower_resolution.png"), dpi=110)
