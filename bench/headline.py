#!/usr/bin/env python3
"""The headline answers, converged (issue 23): every study of bench/headline.toml run with
`ejecta converge` (each level at successively finer spacing; a study resumes where it stopped),
then one table of the answers: the finest run's value, the Richardson-extrapolated value with
its Grid Convergence Index band, the observed order, the finest spacing and particle count, and
what the study cost (wall time times threads, summed over its levels).

  bench/headline.py [--ejecta build/apps/ejecta] [--out runs/headline] [--threads N]
                    [--only ID ...] [--table-only] [--write]

--only runs those studies only (the table still shows every row; a study not run says so).
--table-only runs nothing. --write puts the table into README.md and docs/asteroid_studies.md
between their `<!-- headline:begin -->` and `<!-- headline:end -->` lines.
A study whose scene (its name or its file's text) or --set keys changed since its levels ran is
refused: its old levels would be read back as if they were the new study's. New factors are
welcome: the levels it has are reused.
"""
import argparse
import hashlib
import json
import math
import os
import subprocess
import sys
import tomllib

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BEGIN = "<!-- headline:begin -->"
END = "<!-- headline:end -->"
TABLE_FILES = ("README.md", os.path.join("docs", "asteroid_studies.md"))


class HeadlineError(Exception):
    pass


def load_manifest(path):
    """The studies and open rows, checked: every study has an id, a scene, three or more factors
    and answers that name a quantity."""
    try:
        with open(path, "rb") as f:
            manifest = tomllib.load(f)
    except (OSError, tomllib.TOMLDecodeError) as e:
        raise HeadlineError("%s: %s" % (path, e))
    studies = manifest.get("study", [])
    seen = set()
    for i, study in enumerate(studies):
        where = "%s: study[%d]" % (path, i)
        for key in ("id", "scene", "factors", "answer"):
            if key not in study:
                raise HeadlineError("%s: no '%s'" % (where, key))
        if study["id"] in seen:
            raise HeadlineError("%s: id '%s' is used twice" % (where, study["id"]))
        seen.add(study["id"])
        if len(study["factors"]) < 3 or any(not (f > 0) for f in study["factors"]):
            raise HeadlineError("%s ('%s'): factors %s: three or more, each > 0"
                                % (where, study["id"], study["factors"]))
        for j, answer in enumerate(study["answer"]):
            for key in ("label", "quantity"):
                if key not in answer:
                    raise HeadlineError("%s ('%s'): answer[%d] has no '%s'" % (where, study["id"], j, key))
    for i, row in enumerate(manifest.get("open", [])):
        for key in ("label", "why"):
            if key not in row:
                raise HeadlineError("%s: open[%d] has no '%s'" % (path, i, key))
    return manifest


def converge_command(ejecta, study, out, threads):
    command = [ejecta, "converge", study["scene"], "--factors", ",".join("%g" % f for f in study["factors"]),
               "--out", out]
    for answer in study["answer"]:
        command += ["-q", answer["quantity"]]
    if threads:
        command += ["--threads", str(threads)]
    for key in study.get("key", []):
        command += ["--key", key]
    if study.get("set"):
        command += ["--set"] + list(study["set"])
    return command


def scene_file(scene):
    """The file a study's scene names: a path, or a shipped scene's name (scenes/**/NAME.toml);
    None for a verification problem (verify:NAME), which has no file."""
    if scene.startswith("verify:"):
        return None
    if os.path.isfile(scene):
        return scene
    name = scene if scene.endswith(".toml") else scene + ".toml"
    for folder, _, files in sorted(os.walk(os.path.join(SOURCE, "scenes"))):
        if name in files:
            return os.path.join(folder, name)
    raise HeadlineError("scene '%s': neither a file nor a shipped scene (scenes/**/%s)" % (scene, name))


def definition(study):
    """What makes a study's levels what they are: the scene's text (its SHA-256: a shipped scene
    edited since is another study), the keys set and scaled; not the threads, the quantities asked
    or the factors (each level has its own folder, level_<factor>/, so a study given a finer
    factor reuses the levels it has and runs the new one)."""
    path = scene_file(study["scene"])
    digest = None
    if path:
        with open(path, "rb") as f:
            digest = hashlib.sha256(f.read()).hexdigest()
    return {"scene": study["scene"], "scene_sha256": digest, "set": list(study.get("set", [])),
            "key": list(study.get("key", []))}


def run_study(ejecta, study, out_root, threads):
    out = os.path.join(out_root, study["id"])
    os.makedirs(out, exist_ok=True)
    marker = os.path.join(out, "study.json")
    wanted = definition(study)
    if os.path.exists(marker):
        with open(marker) as f:
            had = json.load(f).get("definition")
        if had != wanted:
            raise HeadlineError("%s: the study '%s' changed since its levels ran (was %s, now %s); remove %s to "
                                "run it afresh" % (marker, study["id"], had, wanted, out))
    command = converge_command(ejecta, study, out, threads)
    with open(marker + ".tmp", "w") as f:
        json.dump({"definition": wanted, "threads": threads or os.cpu_count(), "command": command}, f, indent=2)
    os.replace(marker + ".tmp", marker)
    print("headline: %s: %s" % (study["id"], " ".join(command)), flush=True)
    subprocess.run(command, check=True)


def read_study(out_root, study):
    """convergence.json and study.json of a study that ran, or None; refused if its definition
    differs from the manifest's."""
    out = os.path.join(out_root, study["id"])
    path = os.path.join(out, "convergence.json")
    if not os.path.exists(path):
        return None
    with open(os.path.join(out, "study.json")) as f:
        meta = json.load(f)
    if meta.get("definition") != definition(study):
        raise HeadlineError("%s: ran as %s, the manifest now says %s; rerun it (remove the folder)"
                            % (out, meta.get("definition"), definition(study)))
    with open(path) as f:
        result = json.load(f)
    # Each level's threads from its own summary (levels of one study may have run with different
    # counts); a verification problem keeps no level folders: the study's count then.
    for level in result["levels"]:
        summary = os.path.join(out, "level_%.6g" % level["factor"], "summary.json")
        threads = meta.get("threads") or 1
        if os.path.exists(summary):
            with open(summary) as f:
                threads = json.load(f).get("threads", threads)
        level["threads"] = threads
    return result


def number(value, unit=""):
    """Three significant figures, thousands separated; the unit after a space (none for %)."""
    if value == 0:
        text = "0"
    else:
        digits = max(0, 2 - math.floor(math.log10(abs(value))))
        text = "{:,.{}f}".format(value, digits)
    if not unit:
        return text
    return text + ("%" if unit == "%" else " " + unit)


def duration(seconds):
    if seconds < 90:
        return "%.0f s" % seconds
    if seconds < 5400:
        return "%.0f min" % (seconds / 60)
    return "%.1f h" % (seconds / 3600)


def answer_row(study, answer, result):
    """One Markdown row: the answer, the finest value, extrapolated +- band, order, note, finest
    spacing and particles, cost of all levels."""
    if result is None:
        return "| %s | not run yet (`bench/headline.py --only %s`) | | | | | |" % (answer["label"], study["id"])
    scale = answer.get("scale", 1.0)
    unit = answer.get("unit", "")
    found = [q for q in result["quantities"] if q["quantity"] == answer["quantity"]]
    if not found:
        raise HeadlineError("study '%s' has no quantity '%s': rerun it (its levels are read back)"
                            % (study["id"], answer["quantity"]))
    q = found[0]
    levels = result["levels"]
    finest = levels[-1]
    note = q.get("note", "")
    order = "%.2f" % q["observed_order"] if q.get("valid") else "—"
    if q.get("valid") and not note:
        extrapolated = "%s ± %s" % (number(q["extrapolated"] * scale, unit), number(q["uncertainty"] * scale, unit))
    else:
        # Where the procedure does not apply (oscillation, an order out of range, no order) an
        # extrapolation claims nothing: the spread of the three finest levels is what is known.
        last = sorted(l["values"][answer["quantity"]] * scale for l in levels[-3:])
        extrapolated = "not settled: %s to %s (three finest)" % (number(last[0], unit), number(last[-1], unit))
    core_seconds = sum(l["wall_seconds"] * l["threads"] for l in levels)
    spacings = ", ".join("%.3g" % l["spacing_m"] for l in levels)
    return "| %s | %s | %s | %s | %s | %.3g m; %s | %s (%d levels: %s m) |" % (
        answer["label"], number(q["finest"] * scale, unit), extrapolated, order, note,
        finest["spacing_m"], "{:,}".format(finest["particles"]), duration(core_seconds), len(levels), spacings)


def table(manifest, out_root):
    lines = ["| answer | finest run | extrapolated ± GCI band | observed order | note | finest spacing; particles "
             "| cost (core time, all levels) |",
             "|---|---|---|---|---|---|---|"]
    for study in manifest.get("study", []):
        result = read_study(out_root, study)
        for answer in study["answer"]:
            lines.append(answer_row(study, answer, result))
    for row in manifest.get("open", []):
        lines.append("| %s | — | — | — | %s | | |" % (row["label"], row["why"]))
    return "\n".join(lines) + "\n"


def write_between_markers(path, text):
    """Replaces what lies between the headline markers of `path` (written to a temporary name,
    then renamed: a failure leaves the file as it was)."""
    with open(path) as f:
        content = f.read()
    start, stop = content.find(BEGIN), content.find(END)
    if start < 0 or stop < start:
        raise HeadlineError("%s: no '%s' ... '%s' lines to write the table between" % (path, BEGIN, END))
    content = content[:start + len(BEGIN)] + "\n" + text + content[stop:]
    with open(path + ".tmp", "w") as f:
        f.write(content)
    os.replace(path + ".tmp", path)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--manifest", default=os.path.join(SOURCE, "bench", "headline.toml"))
    parser.add_argument("--ejecta", default=os.path.join(SOURCE, "build", "apps", "ejecta"))
    parser.add_argument("--out", default=os.path.join(SOURCE, "runs", "headline"))
    parser.add_argument("--threads", type=int, default=0, help="OpenMP threads per run (default: all)")
    parser.add_argument("--only", nargs="+", metavar="ID", help="run these studies only")
    parser.add_argument("--table-only", action="store_true", help="run nothing; the table from what ran")
    parser.add_argument("--write", action="store_true", help="write the table into " + ", ".join(TABLE_FILES))
    args = parser.parse_args(argv)
    try:
        manifest = load_manifest(args.manifest)
        ids = [s["id"] for s in manifest.get("study", [])]
        unknown = [i for i in (args.only or []) if i not in ids]
        if unknown:
            raise HeadlineError("no study %s in %s (its studies: %s)"
                                % (", ".join(unknown), args.manifest, ", ".join(ids)))
        if not args.table_only:
            if not os.access(args.ejecta, os.X_OK):
                raise HeadlineError("%s: no ejecta binary there (build it, or give --ejecta)" % args.ejecta)
            for study in manifest.get("study", []):
                if args.only and study["id"] not in args.only:
                    continue
                run_study(args.ejecta, study, args.out, args.threads)
        text = table(manifest, args.out)
        sys.stdout.write(text)
        if args.write:
            for name in TABLE_FILES:
                write_between_markers(os.path.join(SOURCE, name), text)
    except HeadlineError as e:
        sys.exit("headline: " + str(e))
    except subprocess.CalledProcessError as e:
        sys.exit("headline: %s failed (exit %d)" % (" ".join(e.cmd[:3]), e.returncode))


if __name__ == "__main__":
    main()
