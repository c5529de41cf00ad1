#!/usr/bin/env python3
"""Which representation of the hot crater material converges (issue 23, 'the thermal answer's
representation'): the follower's flux from the particles and from the grid's voxels, as the
particle spacing and the voxel size fall.

  bench/thermal_emitters.py [--ejecta build/apps/ejecta] [--out runs/thermal_emitters]
                            [--factors 2,1.4142,1,0.7071,0.5,0.3536,0.25]
                            [--voxel-factor 0.5] [--voxels 0.3,0.212,0.15,0.106,0.075,0.053]
                            [--set KEY=VALUE ...] [--series NAME] [--threads N]
                            [--chart FILE.png [--compare SERIES]]

1. The kinetic impact (scenes/impact_rz.toml) to 1 ms at each spacing factor (`ejecta converge`,
   resumable; the grid's voxel is the median smoothing length, so it falls with the spacing).
2. At each level, the study scenes/thermal/follower.toml (`ejecta thermal`, the frozen 1 ms
   material, no occluder: the follower sees everything hot on its axis, docs/thermal.md) on the
   particles and on the voxels.
3. At the spacing factor --voxel-factor, the same impact with the voxel set to each of --voxels
   (the particles fixed, the grid alone refined), on the voxels.
Prints one table per series (side0's peak flux, its standard error, the eq. 4.8 steady
temperature, the aluminium's peak, emitters and their volume) and, with --chart, draws side0's
peak flux against the spacing (docs/thermal.md, 'Which representation converges').
--set (repeatable) changes the scene at every level; --series names the folder of that series
under --out (default: spacing). docs/thermal.md's tables and chart came from:
  bench/thermal_emitters.py --threads 2
  bench/thermal_emitters.py --threads 2 --series phase_changes --voxels "" \
      --set materials[0].thermal.phase_changes=true --set materials[1].thermal.phase_changes=true \
      --set materials[2].thermal.phase_changes=true
  bench/thermal_emitters.py --compare phase_changes --chart docs/images/thermal_emitters.png
"""
import argparse
import csv
import json
import os
import subprocess
import sys

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STUDY = os.path.join(SOURCE, "scenes", "thermal", "follower.toml")
# The grids only where the hot material is at 1 ms (r < 6 m, 34 to 41 m high at 0.125 m), so that
# the finest levels' grids stay small; the voxel emitters are the same as the shipped region's.
REGION = ['fields.region_min=["-10 m", "26 m", "-10 m"]', 'fields.region_max=["10 m", "46 m", "10 m"]']


def run(cmd, log, threads=0):
    env = dict(os.environ)
    if threads:
        env["OMP_NUM_THREADS"] = str(threads)
    with open(log, "w") as f:
        done = subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT, env=env)
    if done.returncode != 0:
        sys.exit("failed (%d): %s\n  see %s" % (done.returncode, " ".join(cmd), log))


def thermal(ejecta, source, out, emitters, threads):
    """side0's answer from `ejecta thermal` on `source` (a run directory), read back if done."""
    result = os.path.join(out, "thermal.json")
    if not os.path.exists(result):
        os.makedirs(out, exist_ok=True)
        run([ejecta, "thermal", STUDY, "--from", source, "--emitters", emitters, "--no-occlude", "--no-charts",
             "--out", out], os.path.join(out, "thermal.log"), threads)
    with open(result) as f:
        doc = json.load(f)
    if emitters == "voxels" and not doc["grid_file"]["fill_weighted"]:
        sys.exit("%s: voxel emitters without filled fractions (full voxels): made before the fix of "
                 "fields/grid_voxels (2026-12-06)? Remove the folder and run again" % result)
    side0 = [p for p in doc["patches"] if p["patch"] == "side0"]
    if not side0:
        sys.exit("%s: no patch side0 (is %s the follower study?)" % (result, STUDY))
    side0 = side0[0]
    aluminium = [l["peak_K"] for l in side0.get("wall", {}).get("layers", []) if l["material"] == "aluminium"]
    return {"flux": side0["peak_flux_W_m2"], "se": side0["peak_flux_se_W_m2"],
            "steady": side0["steady_temperature_K"], "aluminium": aluminium[0] if aluminium else float("nan"),
            "emitters": doc["emitters"], "volume": doc["emitter_volume_m3"]}


def impact_levels(ejecta, out, factors, extra_set, threads):
    """Runs (or reads back) impact_rz to 1 ms at each factor; returns {factor: (dir, spacing, particles)}.
    A folder made with other --set keys is refused: its levels would be read back as these."""
    overrides = ["time.t_end=1 ms"] + REGION + list(extra_set)
    os.makedirs(out, exist_ok=True)
    definition = os.path.join(out, "definition.json")
    if os.path.exists(definition):
        with open(definition) as f:
            if json.load(f) != overrides:
                sys.exit("%s: made with other --set keys; remove it or choose another --series" % out)
    else:
        with open(definition, "w") as f:
            json.dump(overrides, f, indent=1)
    cmd = [ejecta, "converge", "impact_rz", "--factors", ",".join("%.6g" % f for f in factors),
           "--quantity", "crater_depth_m", "--out", out]
    for s in overrides:
        cmd += ["--set", s]
    if threads:
        cmd += ["--threads", str(threads)]
    run(cmd, os.path.join(out, "converge.log"))
    levels = {}
    with open(os.path.join(out, "levels.csv"), newline="") as f:
        for row in csv.DictReader(f):
            factor = float(row["factor"])
            # coupling/convergence_study.cpp names each level's folder level_%.6g
            levels[factor] = (os.path.join(out, "level_%.6g" % factor), float(row["spacing_m"]),
                              int(row["particles"]))
    return levels


def print_table(title, first_column, rows):
    print("\n" + title)
    print("| %s | emitters | spheres | volume m³ | side0 peak W/m² (± se) | steady K | Al peak K |" % first_column)
    print("|---|---|---|---|---|---|---|")
    for label, kind, r in rows:
        print("| %s | %s | %d | %.1f | %.4g ± %.2g | %.0f | %.1f |" % (
            label, kind, r["emitters"], r["volume"], r["flux"], r["se"], r["steady"], r["aluminium"]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--ejecta", default=os.path.join(SOURCE, "build", "apps", "ejecta"))
    parser.add_argument("--out", default=os.path.join(SOURCE, "runs", "thermal_emitters"))
    parser.add_argument("--factors", default="2,1.4142,1,0.7071,0.5,0.3536,0.25")
    parser.add_argument("--voxel-factor", type=float, default=0.5,
                        help="the spacing factor at which the voxel alone is refined")
    parser.add_argument("--voxels", default="0.3,0.212,0.15,0.106,0.075,0.053",
                        help="voxel sizes [m] at --voxel-factor; empty: none")
    parser.add_argument("--set", action="append", default=[], dest="overrides")
    parser.add_argument("--series", default="spacing")
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--chart", default="")
    parser.add_argument("--compare", action="append", default=[],
                        help="another series (a folder under --out made before) drawn dashed")
    args = parser.parse_args()
    factors = [float(x) for x in args.factors.split(",") if x]
    voxels = [float(x) for x in args.voxels.split(",") if x]

    levels = impact_levels(args.ejecta, os.path.join(args.out, args.series), factors, args.overrides, args.threads)
    spacing_rows = []
    for factor in sorted(levels, reverse=True):
        directory, spacing, particles = levels[factor]
        for kind in ("particles", "voxels"):
            r = thermal(args.ejecta, directory, os.path.join(directory, "thermal_" + kind), kind, args.threads)
            r["spacing"] = spacing
            spacing_rows.append(("%.4g m (%d particles)" % (spacing, particles), kind, r))
    print_table("Both refined (the voxel is the median smoothing length):", "spacing", spacing_rows)

    # The voxel alone refined: the same run again with [fields] voxel set (a grid of the snapshot
    # would cover the whole 35 m body at these voxels); the runs are deterministic, so where the
    # voxel is the level's own the row equals the both-refined one.
    voxel_rows = []
    sweep_spacing = None
    for voxel in voxels:
        out = os.path.join(args.out, args.series, "voxel_%g_at_%g" % (voxel, args.voxel_factor))
        level = impact_levels(args.ejecta, out, [args.voxel_factor], args.overrides + ["fields.voxel=%g m" % voxel],
                              args.threads)[args.voxel_factor]
        sweep_spacing = level[1]
        r = thermal(args.ejecta, level[0], os.path.join(level[0], "thermal_voxels"), "voxels", args.threads)
        r["voxel"] = voxel
        voxel_rows.append(("%g m" % voxel, "voxels", r))
    if voxel_rows:
        print_table("The particles at %.4g m (factor %g), the voxel refined:" % (sweep_spacing, args.voxel_factor),
                    "voxel", voxel_rows)

    with open(os.path.join(args.out, args.series, "thermal_rows.json"), "w") as f:
        json.dump({"overrides": args.overrides, "rows": [[k, r] for _, k, r in spacing_rows],
                   "voxel_sweep": {"spacing_m": sweep_spacing, "rows": [r for _, _, r in voxel_rows]}}, f, indent=1)
    if args.chart:
        chart(args, spacing_rows, voxel_rows, sweep_spacing)


# How the chart names the documented series (others by their folder's name).
SERIES_LABELS = {"spacing": "seed's T = T0 + u/c_v", "phase_changes": "latent heats"}


def chart(args, spacing_rows, voxel_rows, sweep_spacing):
    """side0's peak flux against the spacing: this series, each --compare series (read back from
    its thermal_rows.json) dashed, and the voxel sweep against the voxel size."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7.5, 6))
    series = [(args.series, spacing_rows, "-")]
    for name in args.compare:
        with open(os.path.join(args.out, name, "thermal_rows.json")) as f:
            series.append((name, [("", k, r) for k, r in json.load(f)["rows"]], "--"))
    for name, rows, style in series:
        for kind, marker in (("particles", "o"), ("voxels", "s")):
            pts = sorted((r["spacing"], r["flux"], r["se"]) for _, k, r in rows if k == kind)
            ax.errorbar([p[0] for p in pts], [p[1] for p in pts], yerr=[2 * p[2] for p in pts],
                        marker=marker, linestyle=style, capsize=3,
                        label="%s: %s" % (SERIES_LABELS.get(name, name), kind))
    if voxel_rows:
        pts = sorted((r["voxel"], r["flux"]) for _, _, r in voxel_rows)
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="^", linestyle=":", color="black",
                label="%s: voxels at %.3g m particles (x: the voxel)" % (SERIES_LABELS.get(args.series, args.series),
                                                                          sweep_spacing))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("particle spacing [m] (their voxel: the median h, 1.2 spacings); the sweep: the voxel [m]")
    ax.set_ylabel("side0 peak flux [W/m²] (± 2 se)")
    ax.set_title("The follower's crater-facing face over impact_rz's 1 ms material")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=2)
    fig.tight_layout()
    fig.savefig(args.chart + ".tmp.png", dpi=110)
    os.replace(args.chart + ".tmp.png", args.chart)
    print("\nchart: " + args.chart)


if __name__ == "__main__":
    main()
