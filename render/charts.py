#!/usr/bin/env python3
"""Line and bar charts of CSV columns for ejecta (render/charts.py).

The ejecta binaries carry this script inside them (render/chart_script.hpp) and run it with
/usr/bin/python3 and matplotlib's Agg backend: no display is needed. It also runs on its own:

  charts.py --spec chart.json
  charts.py --csv energy.csv --x time_s --y kinetic_J,internal_J [--labels kinetic,internal]
            [--reference exact_J] [--kind line|bar] [--xlog] [--ylog] [--xlabel TEXT]
            [--ylabel TEXT] [--title TEXT] [--width 900] [--height 600] --out chart.png

A spec file is JSON:
  {"csv": "energy.csv", "x": "time_s", "kind": "line",
   "series": [{"y": "kinetic_J", "label": "kinetic"},
              {"y": "exact_J", "label": "exact", "reference": true},
              {"csv": "other.csv", "x": "n", "y": "error", "markers": true}],
   "xlog": false, "ylog": false, "xlabel": "t [s]", "ylabel": "E [J]", "title": "...",
   "out": "energy.png", "width": 900, "height": 600}
A "ble" spec draws ballistic-limit curves of Whipple shields from the long-format CSV that
`ejecta whipple` writes (one row per rear wall and speed; docs/whipple.md):
  {"kind": "ble", "csv": "ble.csv", "out": "ble.png", "title": "...",
   "threat": {"speed_m_s": 10000, "diameter_m": 0.005}}
one line per wall_thickness_m (speed in km/s, critical diameter in mm), the regime boundaries
found in the regime column as dotted lines, and the threat, if given, as a marker. The column
names may be changed with "group", "x", "y" and "regime".
A series may name its own csv and x column; "negate": plot -y (a depth downward). The spec may add
"hlines" ([{"y": 0, "label": "pre-impact surface", "style": "dashed"}], grey; "style" dashed (the default),
dotted or solid), "vlines" ([{"x": 1e-3,
"label": "resolution"}], dotted grey) and "note" (a line of text in the middle of the axes, e.g. "no
coating needed" over all-zero bars). An x label ending in "[s]" is shown in ms or us (the
values scaled) when every time is below 2 s or 2 ms. "reference": a dashed black line (an exact
solution). "markers": points joined by lines (a convergence study). "points": small dots, no
line (every particle of a profile). "scatter": large markers, no line (a few measured points). For "bar" charts the x column
holds the category names and each series is one bar per category.
Relative csv paths are taken from the spec file's directory. The PNG is written to a temporary
name in the output's directory and renamed, so a reader never sees half a file. Errors (a
missing file or column, a value that is not a number) end the script with status 2 and a line
on stderr naming the file and the column.
"""
import argparse
import csv
import json
import os
import sys


LINE_STYLES = {"dashed": "--", "dotted": ":", "solid": "-"}


def fail(message):
    sys.stderr.write("charts.py: " + message + "\n")
    sys.exit(2)


def read_csv(path):
    """The columns of a CSV file with a header row, as lists of strings; '#' lines skipped."""
    try:
        with open(path, newline="") as handle:
            rows = [row for row in csv.reader(handle) if row and not row[0].lstrip().startswith("#")]
    except OSError as error:
        fail("cannot read '%s': %s" % (path, error.strerror))
    if not rows:
        fail("'%s' is empty (a header row is needed)" % path)
    header = [name.strip() for name in rows[0]]
    columns = {name: [] for name in header}
    for number, row in enumerate(rows[1:], start=2):
        if len(row) != len(header):
            fail("'%s' line %d has %d fields, the header has %d" % (path, number, len(row), len(header)))
        for name, value in zip(header, row):
            columns[name].append(value.strip())
    return header, columns


class Tables:
    """CSV files read once each."""

    def __init__(self, base):
        self.base = base
        self.files = {}

    def column(self, path, name, numeric=True):
        if not path:
            fail("no csv given for column '%s'" % name)
        full = path if os.path.isabs(path) else os.path.join(self.base, path)
        if full not in self.files:
            self.files[full] = read_csv(full)
        header, columns = self.files[full]
        if name not in columns:
            fail("'%s' has no column '%s' (columns: %s)" % (path, name, ", ".join(header)))
        if not numeric:
            return columns[name]
        values = []
        for number, text in enumerate(columns[name], start=2):
            try:
                values.append(float(text))
            except ValueError:
                fail("'%s' column '%s' row %d: '%s' is not a number" % (path, name, number, text))
        return values


def time_axis(spec, xs):
    """The factor and label for an x axis of times: "[s]" becomes "[ms]" or "[us]" when short."""
    label = spec.get("xlabel") or ""
    if not label.endswith("[s]") or spec.get("xlog"):
        return 1.0, label
    span = max((abs(v) for v in xs if v == v), default=0.0)
    if 0 < span < 2e-3:
        return 1e6, label[:-3] + "[\u00b5s]"
    if 0 < span < 2.0:
        return 1e3, label[:-3] + "[ms]"
    return 1.0, label


def draw(spec, base):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    kind = spec.get("kind", "line")
    if kind == "ble":
        draw_ble(spec, base)
        return
    if kind not in ("line", "bar"):
        fail("kind must be 'line', 'bar' or 'ble', not '%s'" % kind)
    series = spec.get("series") or []
    if not series:
        fail("the spec has no series")
    out = spec.get("out")
    if not out:
        fail("the spec has no 'out' file")
    width, height = int(spec.get("width", 900)), int(spec.get("height", 600))
    if width < 50 or height < 50:
        fail("width and height must be at least 50 pixels")
    tables = Tables(base)
    dpi = 100
    figure, axes = plt.subplots(figsize=(width / dpi, height / dpi), dpi=dpi)
    xfactor, xlabel = 1.0, spec.get("xlabel") or spec.get("x", "")
    if kind == "line":
        every_x = []
        for entry in series:
            path = entry.get("csv") or spec.get("csv")
            xname = entry.get("x") or spec.get("x")
            if xname and "y" in entry:
                every_x += tables.column(path, xname)
        xfactor, xlabel = time_axis(spec, every_x)
        if xfactor == 1.0:
            xlabel = spec.get("xlabel") or spec.get("x", "")
        for entry in series:
            if "y" not in entry:
                fail("a series has no 'y' column")
            path = entry.get("csv") or spec.get("csv")
            xname = entry.get("x") or spec.get("x")
            if not xname:
                fail("no 'x' column for series '%s'" % entry["y"])
            x = [v * xfactor for v in tables.column(path, xname)]
            y = tables.column(path, entry["y"])
            if entry.get("negate"):
                y = [-v for v in y]
            label = entry.get("label") or entry["y"]
            if entry.get("reference"):
                axes.plot(x, y, "k--", linewidth=1.5, label=label, zorder=3)
            elif entry.get("markers"):
                # Joined in order of x, whatever order the rows are in (a sweep's variants).
                order = sorted(range(len(x)), key=lambda k: x[k])
                axes.plot([x[k] for k in order], [y[k] for k in order], "o-", linewidth=1.5,
                          markersize=5, label=label)
            elif entry.get("scatter"):
                # A few measured points (a simulated limit): large markers, no line.
                axes.plot(x, y, "o", markersize=8, label=label, zorder=4)
            elif entry.get("points"):
                # Every particle of a profile: small dots, no line (they scatter about the curve).
                axes.plot(x, y, ".", markersize=2, alpha=0.6, label=label, rasterized=True)
            else:
                axes.plot(x, y, "-", linewidth=1.8, label=label)
    else:
        path = spec.get("csv")
        if not spec.get("x"):
            fail("a bar chart needs 'x', the column of category names")
        categories = tables.column(path, spec["x"], numeric=False)
        count = len(series)
        bar = 0.8 / count
        for k, entry in enumerate(series):
            if "y" not in entry:
                fail("a series has no 'y' column")
            y = tables.column(entry.get("csv") or path, entry["y"])
            if len(y) != len(categories):
                fail("column '%s' has %d values for %d categories" % (entry["y"], len(y), len(categories)))
            positions = [i - 0.4 + bar * (k + 0.5) for i in range(len(categories))]
            axes.bar(positions, y, width=bar, label=entry.get("label") or entry["y"])
        # Bars stand on zero; all-zero bars still get an axis a reader can read.
        values = [v for entry in series for v in tables.column(entry.get("csv") or path, entry["y"])
                  if v == v]
        if values and min(values) >= 0:
            axes.set_ylim(bottom=0, top=None if max(values) > 0 else 1)
        axes.set_xticks(range(len(categories)))
        axes.set_xticklabels(categories, rotation=30 if max(map(len, categories), default=0) > 8 else 0,
                             ha="right" if max(map(len, categories), default=0) > 8 else "center")
    if spec.get("xlog") and kind == "line":
        axes.set_xscale("log")
    if spec.get("ylog"):
        axes.set_yscale("log")
    for line in spec.get("hlines") or []:
        style = line.get("style") or "dashed"
        if style not in LINE_STYLES:
            fail(f"hlines: style \"{style}\" is not one of {', '.join(LINE_STYLES)}")
        axes.axhline(float(line.get("y", 0.0)), color="0.45", linestyle=LINE_STYLES[style], linewidth=1.2,
                     label=line.get("label") or None, zorder=1)
    for line in spec.get("vlines") or []:
        axes.axvline(float(line.get("x", 0.0)), color="0.45", linestyle=":", linewidth=1.4,
                     label=line.get("label") or None, zorder=1)
    if spec.get("note"):
        axes.text(0.5, 0.5, spec["note"], transform=axes.transAxes, ha="center", va="center",
                  fontsize=14, color="0.25",
                  bbox={"boxstyle": "round", "facecolor": "white", "edgecolor": "0.6"})
    axes.set_xlabel(xlabel)
    axes.set_ylabel(spec.get("ylabel", ""))
    if spec.get("title"):
        axes.set_title(spec["title"])
    axes.grid(True, which="major", alpha=0.3)
    if len(series) > 1 or any(entry.get("label") for entry in series) or spec.get("hlines") or spec.get("vlines"):
        axes.legend()
    figure.tight_layout()
    save_figure(figure, out, base, dpi)


def save_figure(figure, out, base, dpi):
    """Writes the PNG to a temporary name next to `out`, then renames it."""
    import matplotlib.pyplot as plt

    out = out if os.path.isabs(out) else os.path.join(base, out)
    directory = os.path.dirname(os.path.abspath(out))
    temporary = os.path.join(directory, ".%s.tmp-%d" % (os.path.basename(out), os.getpid()))
    try:
        figure.savefig(temporary, format="png", dpi=dpi)
        os.replace(temporary, out)
    except OSError as error:
        fail("cannot write '%s': %s" % (out, error.strerror))
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)
    plt.close(figure)


def regime_corners(speeds, regimes):
    """(speed, regime on the right) wherever the regime changes along a curve. ejecta's curves
    carry the corner speeds as rows: the last ballistic row and the first hypervelocity row."""
    corners = []
    for i in range(1, len(speeds)):
        if regimes[i] != regimes[i - 1]:
            at = speeds[i - 1] if regimes[i - 1] == "ballistic" else speeds[i]
            corners.append((at, regimes[i]))
    return corners


def draw_ble(spec, base):
    """Ballistic-limit curves: critical diameter [mm] against speed [km/s], one per rear wall."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out = spec.get("out")
    if not out:
        fail("the spec has no 'out' file")
    path = spec.get("csv")
    width, height = int(spec.get("width", 900)), int(spec.get("height", 600))
    if width < 50 or height < 50:
        fail("width and height must be at least 50 pixels")
    tables = Tables(base)
    groups = tables.column(path, spec.get("group", "wall_thickness_m"))
    speeds = tables.column(path, spec.get("x", "speed_m_s"))
    diameters = tables.column(path, spec.get("y", "critical_diameter_m"))
    regimes = tables.column(path, spec.get("regime", "regime"), numeric=False)
    if not speeds:
        fail("'%s' has no rows" % path)
    curves = {}
    for group, speed, diameter, regime in zip(groups, speeds, diameters, regimes):
        curves.setdefault(group, ([], [], []))
        curves[group][0].append(speed * 1e-3)
        curves[group][1].append(diameter * 1e3)
        curves[group][2].append(regime)
    dpi = 100
    figure, axes = plt.subplots(figsize=(width / dpi, height / dpi), dpi=dpi)
    for group, (x, y, _) in curves.items():
        axes.plot(x, y, "-", linewidth=1.8, label="t_w = %.3g mm" % (group * 1e3))
    first = next(iter(curves.values()))
    edges = [min(first[0])] + [at for at, _ in regime_corners(first[0], first[2])] + [max(first[0])]
    names = [first[2][0]] + [name for _, name in regime_corners(first[0], first[2])]
    for at in edges[1:-1]:
        axes.axvline(at, color="0.4", linestyle=":", linewidth=1.2)
    for left, right, name in zip(edges[:-1], edges[1:], names):
        axes.text((left + right) / 2, 0.02, name, transform=axes.get_xaxis_transform(), ha="center",
                  va="bottom", fontsize=9, color="0.3")
    threat = spec.get("threat")
    if threat:
        try:
            tx, ty = float(threat["speed_m_s"]) * 1e-3, float(threat["diameter_m"]) * 1e3
        except (KeyError, TypeError, ValueError):
            fail("'threat' needs numbers 'speed_m_s' and 'diameter_m'")
        axes.plot([tx], [ty], "kx", markersize=10, markeredgewidth=2,
                  label="threat %.3g mm at %.3g km/s" % (ty, tx), zorder=4)
    axes.set_ylim(bottom=0.0)
    axes.set_xlabel(spec.get("xlabel") or "impact speed [km/s]")
    axes.set_ylabel(spec.get("ylabel") or "critical projectile diameter [mm]")
    if spec.get("title"):
        axes.set_title(spec["title"])
    axes.grid(True, which="major", alpha=0.3)
    axes.legend()
    figure.tight_layout()
    save_figure(figure, out, base, dpi)


def spec_from_options(options):
    if not options.csv or not options.x or not options.y or not options.out:
        fail("give --spec FILE, or --csv, --x, --y and --out")
    names = options.y.split(",")
    labels = options.labels.split(",") if options.labels else names
    if len(labels) != len(names):
        fail("--labels has %d names for %d --y columns" % (len(labels), len(names)))
    series = [{"y": name, "label": label} for name, label in zip(names, labels)]
    if options.reference:
        series.append({"y": options.reference, "label": options.reference_label or options.reference,
                       "reference": True})
    return {"csv": options.csv, "x": options.x, "series": series, "kind": options.kind,
            "xlog": options.xlog, "ylog": options.ylog, "xlabel": options.xlabel,
            "ylabel": options.ylabel, "title": options.title, "out": options.out,
            "width": options.width, "height": options.height}


def main(argv):
    parser = argparse.ArgumentParser(description="Line and bar charts of CSV columns (ejecta).")
    parser.add_argument("--spec", help="a JSON chart spec")
    parser.add_argument("--csv")
    parser.add_argument("--x")
    parser.add_argument("--y", help="comma-separated columns")
    parser.add_argument("--labels", help="comma-separated legend labels for --y")
    parser.add_argument("--reference", help="a column drawn as the exact/reference curve")
    parser.add_argument("--reference-label")
    parser.add_argument("--kind", default="line", choices=["line", "bar"])
    parser.add_argument("--xlog", action="store_true")
    parser.add_argument("--ylog", action="store_true")
    parser.add_argument("--xlabel", default="")
    parser.add_argument("--ylabel", default="")
    parser.add_argument("--title", default="")
    parser.add_argument("--width", type=int, default=900)
    parser.add_argument("--height", type=int, default=600)
    parser.add_argument("--out")
    options = parser.parse_args(argv)
    if options.spec:
        try:
            with open(options.spec) as handle:
                spec = json.load(handle)
        except OSError as error:
            fail("cannot read '%s': %s" % (options.spec, error.strerror))
        except ValueError as error:
            fail("'%s' is not valid JSON: %s" % (options.spec, error))
        base = os.path.dirname(os.path.abspath(options.spec))
    else:
        spec = spec_from_options(options)
        base = os.getcwd()
    draw(spec, base)


if __name__ == "__main__":
    main(sys.argv[1:])
