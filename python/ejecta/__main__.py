"""`python3 -m ejecta RUN_DIR`: what a run holds, in a few lines (a check that Python reads it)."""
import sys

from . import EjectaFileError, load_run


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 1 or argv[0] in ("-h", "--help"):
        print("usage: python3 -m ejecta RUN_DIR", file=sys.stderr)
        return 2
    try:
        run = load_run(argv[0])
        series = run.series
        print("%s: %d snapshots" % (run.path, len(series)), end="")
        if len(series):
            print(", t = %.6g .. %.6g s" % (series.times[0], series.times[-1]))
            last = series[-1]
            print("  last: %d particles, %s, fields: %s" % (len(last), last.geometry, ", ".join(last.fields)))
            for m in last.materials:
                print("  material %d: %s (eos %s, strength %s, fracture %s)" % m)
        else:
            print()
        try:
            summary = run.summary
            print("  summary: %s, %s steps, %.3g s wall" % (summary["status"], summary.get("steps"),
                                                            summary.get("wall_seconds", float("nan"))))
        except EjectaFileError as error:
            print("  summary: %s" % error.reason)
        for path in run.grid_files[-1:]:
            print("  grids (%d files), last %s" % (len(run.grid_files), path))
    except EjectaFileError as error:
        print("ejecta: error: %s" % error, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
