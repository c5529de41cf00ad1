#!/usr/bin/python3
"""The figures of docs/impact.md from the runs listed there (Debian's python3 with matplotlib).

  impact_charts.py history RUN_DIR EJECTA
      crater_history.csv for a run made before `ejecta run` wrote one: `EJECTA crater --json`
      on every snapshot (the same measurement, fields/measure_crater.hpp, at the same default
      resolution), written to RUN_DIR/crater_history.csv in the same columns.
  impact_charts.py growth RUN_DIR OUT_DIR
      impact_growth.csv (t in ms) and impact_growth.png, impact_volume.png (with Holsapple's
      scaled crater and the seed's crater as reference lines) and impact_profile.png (the
      run's crater_profile.csv).
  impact_charts.py resolution OUT_DIR T_MS SPACING=RUN_DIR ...
      impact_resolution.csv (the crater at T_MS against the particle spacing, from each run's
      crater_history.csv), impact_resolution.png, and impact_resolution_growth.png (each run's
      growth up to T_MS); prints the observed order and Richardson estimate of each figure.
"""
import csv
import glob
import json
import math
import os
import subprocess
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# Holsapple (1993) strength-regime scaling for hard rock with Richardson's (2009) constants
# (K1 = 0.20, mu = 0.55, Ybar = 18 MPa, nu = 0.4), for the scene's 1 m radius, 11.7 t aluminium
# sphere at 10 km/s into 2680 kg/m^3 granite (worked in docs/impact.md).
HOLSAPPLE_VOLUME_M3 = 2430.0
HOLSAPPLE_DIAMETER_M = 2 * 1.1 * HOLSAPPLE_VOLUME_M3 ** (1 / 3)   # 29.6 m
HOLSAPPLE_DEPTH_M = 0.6 * HOLSAPPLE_VOLUME_M3 ** (1 / 3)          # 8.1 m
SEED_DEPTH_M = 6.0       # the seed's crater (sect. 2.2): ~6 m deep,
SEED_DIAMETER_M = 10.0   # ~10 m wide

COLUMNS = ["time_s", "found", "depth_m", "apparent_diameter_m", "rim_diameter_m",
           "rim_height_m", "volume_m3", "excavated_mass_kg", "elongation"]


def read_rows(path):
    with open(path, newline="") as handle:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(handle)]


def history(run_dir, ejecta):
    snaps = sorted(glob.glob(os.path.join(run_dir, "snapshots", "snap_*.h5")),
                   key=lambda p: int(os.path.basename(p)[5:-3]))
    rows = []
    for snap in snaps:
        out = subprocess.run([ejecta, "crater", "--json", snap], capture_output=True, text=True)
        if out.returncode not in (0, 3):  # 3: no crater found
            sys.exit("%s: %s" % (snap, out.stderr.strip()))
        j = json.loads(out.stdout)
        with h5py.File(snap, "r") as f:
            time = float(f.attrs["time"])
        rows.append([time, 1 if j["found"] else 0, j["depth_m"], j["apparent_diameter_m"],
                     j["rim_diameter_m"], j["rim_height_m"], j["volume_m3"],
                     j["excavated_mass_kg"], j["elongation"]])
        print("%s: t = %.4g s, depth %.3f m, diameter %.3f m, volume %.4g m^3"
              % (os.path.basename(snap), time, j["depth_m"], j["apparent_diameter_m"],
                 j["volume_m3"]))
    with open(os.path.join(run_dir, "crater_history.csv"), "w", newline="") as handle:
        w = csv.writer(handle)
        w.writerow(COLUMNS)
        w.writerows(rows)


def reference_line(ax, y, label, style):
    ax.axhline(y, color="black", linestyle=style, linewidth=1)
    ax.annotate(label, xy=(1.0, y), xycoords=("axes fraction", "data"), xytext=(-4, 3),
                textcoords="offset points", ha="right", va="bottom", fontsize=9)


def growth(run_dir, out_dir):
    rows = read_rows(os.path.join(run_dir, "crater_history.csv"))
    with open(os.path.join(out_dir, "impact_growth.csv"), "w", newline="") as handle:
        w = csv.writer(handle)
        w.writerow(["t_ms", "depth_m", "apparent_diameter_m", "rim_diameter_m", "volume_m3"])
        for r in rows:
            w.writerow(["%.6g" % (1e3 * r["time_s"]), "%.4f" % r["depth_m"],
                        "%.4f" % r["apparent_diameter_m"], "%.4f" % r["rim_diameter_m"],
                        "%.2f" % r["volume_m3"]])
    t = [1e3 * r["time_s"] for r in rows]

    fig, ax = plt.subplots(figsize=(9, 6), dpi=100)
    ax.plot(t, [r["depth_m"] for r in rows], "o-", color="tab:blue", label="depth")
    ax.plot(t, [r["apparent_diameter_m"] for r in rows], "s-", color="tab:orange",
            label="apparent diameter")
    reference_line(ax, HOLSAPPLE_DIAMETER_M, "Holsapple (1993) diameter %.0f m" % HOLSAPPLE_DIAMETER_M, "--")
    reference_line(ax, HOLSAPPLE_DEPTH_M, "Holsapple (1993) depth %.1f m" % HOLSAPPLE_DEPTH_M, "--")
    reference_line(ax, SEED_DIAMETER_M, "seed: ~10 m wide", ":")
    reference_line(ax, SEED_DEPTH_M, "seed: ~6 m deep", ":")
    ax.set_xlabel("t [ms]")
    ax.set_ylabel("length [m]")
    ax.set_title("impact_rz (0.25 m spacing): crater growth")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(loc="center right")
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "impact_growth.png"))
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(9, 6), dpi=100)
    ax.plot(t, [r["volume_m3"] for r in rows], "o-", color="tab:green", label="volume")
    reference_line(ax, HOLSAPPLE_VOLUME_M3, "Holsapple (1993) volume %.0f m$^3$" % HOLSAPPLE_VOLUME_M3, "--")
    ax.set_xlabel("t [ms]")
    ax.set_ylabel("crater volume [m$^3$]")
    ax.set_title("impact_rz (0.25 m spacing): crater volume")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right")
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "impact_volume.png"))
    plt.close(fig)

    profile = read_rows(os.path.join(run_dir, "crater_profile.csv"))
    fig, ax = plt.subplots(figsize=(9, 5), dpi=100)
    ax.plot([p["distance_m"] for p in profile], [-p["depth_mean_m"] for p in profile],
            color="tab:blue", label="t = %.0f ms (beyond ~14 m: the ejecta curtain)" % t[-1])
    half = HOLSAPPLE_DIAMETER_M / 2
    # The scaled crater drawn as a paraboloid of its depth and radius, for scale only.
    xs = [half * i / 50 for i in range(51)]
    ax.plot(xs, [-HOLSAPPLE_DEPTH_M * (1 - (x / half) ** 2) for x in xs], "k--", linewidth=1,
            label="Holsapple (1993) size, as a paraboloid")
    ax.axhline(0, color="grey", linewidth=0.8)
    ax.set_xlabel("distance from the axis along the original surface [m]")
    ax.set_ylabel("height above the original surface [m]")
    ax.set_title("impact_rz (0.25 m spacing): crater profile")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left")
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "impact_profile.png"))
    plt.close(fig)


def resolution(out_dir, t_ms, runs):
    table = []
    for item in runs:
        spacing, run_dir = item.split("=", 1)
        rows = read_rows(os.path.join(run_dir, "crater_history.csv"))
        match = [r for r in rows if abs(1e3 * r["time_s"] - t_ms) < 1e-6]
        if not match:
            sys.exit("%s: no row at %g ms" % (run_dir, t_ms))
        table.append((float(spacing), match[0]))
    table.sort()
    with open(os.path.join(out_dir, "impact_resolution.csv"), "w", newline="") as handle:
        w = csv.writer(handle)
        w.writerow(["spacing_m", "depth_m", "apparent_diameter_m", "rim_diameter_m", "volume_m3"])
        for s, r in table:
            w.writerow([s, "%.4f" % r["depth_m"], "%.4f" % r["apparent_diameter_m"],
                        "%.4f" % r["rim_diameter_m"], "%.2f" % r["volume_m3"]])
    # Observed order and Richardson extrapolation from three spacings halving each time:
    # p = log2((Q1 - Q2) / (Q2 - Q3)), Q_inf = Q3 + (Q3 - Q2) / (2^p - 1). Meaningful only when
    # the differences shrink monotonically (same sign, ratio > 1).
    richardson = {}
    if len(table) == 3 and abs(table[1][0] / table[0][0] - 2) < 1e-9 and abs(table[2][0] / table[1][0] - 2) < 1e-9:
        for key in ("depth_m", "apparent_diameter_m", "volume_m3"):
            q3, q2, q1 = (r[key] for _, r in table)  # fine, medium, coarse
            d1, d2 = q1 - q2, q2 - q3
            if d2 != 0 and d1 / d2 > 1:
                order = math.log2(d1 / d2)
                print("%s: %.4g (%.3g m), %.4g (%.3g m), %.4g (%.3g m): observed order %.2f, "
                      "Richardson %.4g" % (key, q1, table[2][0], q2, table[1][0], q3, table[0][0],
                                           order, q3 + (q3 - q2) / (2 ** order - 1)))
                richardson[key] = q3 + (q3 - q2) / (2 ** order - 1)
            else:
                print("%s: %.4g, %.4g, %.4g (coarse to fine): not monotonically converging "
                      "(difference ratio %.3g)" % (key, q1, q2, q3, d1 / d2 if d2 else float("inf")))
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 5), dpi=100)
    s = [x for x, _ in table]
    ax.plot(s, [r["depth_m"] for _, r in table], "o-", label="depth")
    ax.plot(s, [r["apparent_diameter_m"] for _, r in table], "s-", label="apparent diameter")
    for key, colour in (("depth_m", "tab:blue"), ("apparent_diameter_m", "tab:orange")):
        if key in richardson:
            ax.axhline(richardson[key], color=colour, linestyle="--", linewidth=1,
                       label="Richardson estimate %.1f m" % richardson[key])
    ax.set_xscale("log", base=2)
    ax.set_xticks(s, ["%g" % x for x in s])
    ax.set_xlabel("particle spacing [m]")
    ax.set_ylabel("length [m]")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend()
    bx.plot(s, [r["volume_m3"] for _, r in table], "o-", color="tab:green", label="volume")
    if "volume_m3" in richardson:
        bx.axhline(richardson["volume_m3"], color="tab:green", linestyle="--", linewidth=1,
                   label="Richardson estimate %.0f m$^3$" % richardson["volume_m3"])
    bx.set_xscale("log", base=2)
    bx.set_xticks(s, ["%g" % x for x in s])
    bx.set_xlabel("particle spacing [m]")
    bx.set_ylabel("crater volume [m$^3$]")
    bx.set_ylim(bottom=0)
    bx.grid(alpha=0.3)
    bx.legend()
    fig.suptitle("impact_rz: crater at %g ms against resolution" % t_ms)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "impact_resolution.png"))
    plt.close(fig)

    # The growth at each spacing, every output up to T_MS.
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 5), dpi=100)
    for item in runs:
        spacing, run_dir = item.split("=", 1)
        rows = [r for r in read_rows(os.path.join(run_dir, "crater_history.csv"))
                if 1e3 * r["time_s"] <= t_ms + 1e-9]
        t = [1e3 * r["time_s"] for r in rows]
        ax.plot(t, [r["depth_m"] for r in rows], "o-", label="depth, %s m" % spacing)
        ax.plot(t, [r["apparent_diameter_m"] for r in rows], "s--", label="diameter, %s m" % spacing)
        bx.plot(t, [r["volume_m3"] for r in rows], "o-", label="%s m" % spacing)
    ax.set_xlabel("t [ms]")
    ax.set_ylabel("length [m]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    bx.set_xlabel("t [ms]")
    bx.set_ylabel("crater volume [m$^3$]")
    bx.grid(alpha=0.3)
    bx.legend()
    fig.suptitle("impact_rz: crater growth at three particle spacings")
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "impact_resolution_growth.png"))
    plt.close(fig)


if __name__ == "__main__":
    if len(sys.argv) >= 4 and sys.argv[1] == "history":
        history(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 4 and sys.argv[1] == "growth":
        growth(sys.argv[2], sys.argv[3])
    elif len(sys.argv) >= 5 and sys.argv[1] == "resolution":
        resolution(sys.argv[2], float(sys.argv[3]), sys.argv[4:])
    else:
        sys.exit(__doc__)
