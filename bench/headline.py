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
between their `<!-- headline:begin -->` and `<!-- headline:end -->` lines; there a study with no
levels on this machine keeps the row the document has for it (runs/ is not in the repository,
so a machine that re-ran some studies does not blank the others).
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
# A Whipple shield's verdicts (summary.json's shield_verdict): perforated, not perforated.
VERDICTS = ("P", "NP")


class HeadlineError(Exception):
    pass


def load_manifest(path):
    """The studies and open rows, checked: every study has an id, a scene, three or more distinct
    factors and answers that name a quantity; keys of the types the driver uses."""
    try:
        with open(path, "rb") as f:
            manifest = tomllib.load(f)
    except (OSError, tomllib.TOMLDecodeError) as e:
        raise HeadlineError("%s: %s" % (path, e))

    def need(ok, where, what):
        if not ok:
            raise HeadlineError("%s: %s" % (where, what))

    studies = manifest.get("study", [])
    need(isinstance(studies, list), path, "'study' must be an array of tables ([[study]])")
    seen = set()
    for i, study in enumerate(studies):
        where = "%s: study[%d]" % (path, i)
        for key in ("id", "scene", "factors", "answer"):
            need(key in study, where, "no '%s'" % key)
        where += " ('%s')" % study["id"]
        need(isinstance(study["id"], str) and study["id"] not in seen, where, "id: a text, used once")
        seen.add(study["id"])
        need(isinstance(study["scene"], str), where, "scene: a text (a shipped scene's name or a path)")
        factors = study["factors"]
        need(isinstance(factors, list) and len(factors) >= 3 and len(set(factors)) == len(factors) and
             all(isinstance(f, (int, float)) and f > 0 for f in factors),
             where, "factors %s: three or more distinct numbers, each > 0" % (factors,))
        for key in ("set", "key"):
            value = study.get(key, [])
            need(isinstance(value, list) and all(isinstance(v, str) for v in value), where,
                 "%s: an array of texts" % key)
        need(isinstance(study["answer"], list) and study["answer"], where, "answer: [[study.answer]] tables")
        for j, answer in enumerate(study["answer"]):
            for key in ("label", "quantity"):
                need(key in answer, where, "answer[%d] has no '%s'" % (j, key))
            need(isinstance(answer.get("scale", 1), (int, float)), where, "answer[%d]: scale is a number" % j)
            for key in ("minimum", "maximum"):
                need(isinstance(answer.get(key, 0), (int, float)), where,
                     "answer[%d]: %s is a number (in the row's unit, after scale)" % (j, key))
            need(answer.get("minimum", -math.inf) < answer.get("maximum", math.inf), where,
                 "answer[%d]: minimum must be below maximum" % j)
            need(answer.get("verdict", "P") in VERDICTS, where,
                 "answer[%d]: verdict is the experiment's, one of %s" % (j, ", ".join(VERDICTS)))
    for i, row in enumerate(manifest.get("open", [])):
        for key in ("label", "why"):
            need(key in row, "%s: open[%d]" % (path, i), "no '%s'" % key)
    return manifest


def converge_command(ejecta, study, out, threads):
    command = [ejecta, "converge", study["scene"], "--factors", ",".join(repr(float(f)) for f in study["factors"]),
               "--out", out]
    ranged = set()
    for answer in study["answer"]:
        command += ["-q", answer["quantity"]]
        # What the quantity can be, in its own unit (the manifest's is the row's, after scale), so
        # that the charts clip the band as the table does.
        if ("minimum" in answer or "maximum" in answer) and answer["quantity"] not in ranged:
            ranged.add(answer["quantity"])
            scale = answer.get("scale", 1.0)
            low, high = answer.get("minimum", -math.inf) / scale, answer.get("maximum", math.inf) / scale
            low, high = min(low, high), max(low, high)
            command += ["--range", "%s=%s:%s" % (answer["quantity"], "" if math.isinf(low) else repr(low),
                                                 "" if math.isinf(high) else repr(high))]
    if threads:
        command += ["--threads", str(threads)]
    for key in study.get("key", []):
        command += ["--key", key]
    if study.get("set"):
        command += ["--set"] + list(study["set"])
    return command


def scene_text(scene, ejecta):
    """The text a study's scene names, as ejecta would run it: a file's, or a shipped scene's as
    the binary holds it (`ejecta scenes show NAME`, which resolves names as `ejecta run` does;
    an edited scene not yet rebuilt into the binary is then the old one, which is what runs).
    Without a binary, scenes/NAME.toml from the source tree. None for a verification problem."""
    if scene.startswith("verify:"):
        return None
    if os.path.isfile(scene):
        with open(scene, "rb") as f:
            return f.read()
    if ejecta and os.access(ejecta, os.X_OK):
        shown = subprocess.run([ejecta, "scenes", "show", scene], capture_output=True)
        if shown.returncode != 0:
            raise HeadlineError("scene '%s': %s" % (scene, shown.stderr.decode(errors="replace").strip()))
        return shown.stdout
    name = scene if scene.endswith(".toml") else scene + ".toml"
    path = os.path.join(SOURCE, "scenes", name)
    if not os.path.isfile(path):
        raise HeadlineError("scene '%s': neither a file nor scenes/%s (and no ejecta binary to ask)" % (scene, name))
    with open(path, "rb") as f:
        return f.read()


def definition(study, ejecta=None):
    """What makes a study's levels what they are: the scene's content (the SHA-256 of its parsed
    document: a shipped scene whose values changed since is another study), the keys set and scaled; not the threads, the quantities asked
    or the factors (each level has its own folder, level_<factor>/, so a study given a finer
    factor reuses the levels it has and runs the new one)."""
    text = scene_text(study["scene"], ejecta)
    digest = None
    if text is not None:
        # Of the parsed document: a comment or layout edit is the same study, a value is not.
        try:
            document = tomllib.loads(text.decode())
        except (UnicodeDecodeError, tomllib.TOMLDecodeError) as e:
            raise HeadlineError("scene '%s': %s" % (study["scene"], e))
        canonical = json.dumps(document, sort_keys=True, default=str)
        digest = hashlib.sha256(canonical.encode()).hexdigest()
    return {"scene": study["scene"], "scene_sha256": digest, "set": list(study.get("set", [])),
            "key": list(study.get("key", []))}


def read_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        raise HeadlineError("%s: %s" % (path, e))


def run_study(ejecta, study, out_root, threads):
    out = os.path.join(out_root, study["id"])
    os.makedirs(out, exist_ok=True)
    marker = os.path.join(out, "study.json")
    wanted = definition(study, ejecta)
    if os.path.exists(marker):
        had = read_json(marker).get("definition")
        if had != wanted:
            raise HeadlineError("%s: the study '%s' changed since its levels ran (was %s, now %s); remove %s to "
                                "run it afresh" % (marker, study["id"], had, wanted, out))
    command = converge_command(ejecta, study, out, threads)
    with open(marker + ".tmp", "w") as f:
        json.dump({"definition": wanted, "threads": threads or os.cpu_count(), "command": command}, f, indent=2)
    os.replace(marker + ".tmp", marker)
    print("headline: %s: %s" % (study["id"], " ".join(command)), flush=True)
    subprocess.run(command, check=True)


def read_study(out_root, study, ejecta=None):
    """convergence.json of a study that ran, with each level's threads; None when it has not
    run. A study that ran as another definition than the manifest's (or left no study.json)
    comes back as {"stale": why}: its row says so rather than showing another study's numbers."""
    out = os.path.join(out_root, study["id"])
    path = os.path.join(out, "convergence.json")
    if not os.path.exists(path):
        return None
    marker = os.path.join(out, "study.json")
    if not os.path.exists(marker):
        return {"stale": "%s has no study.json: what it ran is unknown" % out}
    meta = read_json(marker)
    had, wanted = meta.get("definition") or {}, definition(study, ejecta)
    if had != wanted:
        changed = [k for k, v in wanted.items() if had.get(k) != v]
        return {"stale": "its %s changed since it ran" % ", ".join(changed)}
    result = read_json(path)
    # Each level's threads from its own summary (levels of one study may have run with different
    # counts); a verification problem keeps no level folders: the study's count then.
    for level in result["levels"]:
        summary = os.path.join(out, "level_%.6g" % level["factor"], "summary.json")
        level["threads"] = meta.get("threads") or 1
        level["extras"] = None  # no summary: nothing to read a verdict from
        if os.path.exists(summary):
            run = read_json(summary)
            level["threads"] = run.get("threads", level["threads"])
            # Only a completed run's analysis (as `ejecta converge` reuses only those): a level
            # re-run by hand and stopped is not the level convergence.json recorded.
            level["extras"] = (run.get("extras") or {}) if run.get("status") == "completed" else None
    return result


def number(value, unit=""):
    """Three significant figures, thousands separated; the unit after a space (none for %)."""
    if not math.isfinite(value):
        text = "%g" % value
    elif value == 0:
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


def level_verdict(level):
    """A level's shield verdict as the row shows it, with what it rests on: the hole's diameter
    (a perforation) or the rear face's peak bulge (none); None where its run did not analyse a
    shield (not a Whipple scene, or a level without a completed run's summary)."""
    extras = level.get("extras") or {}
    verdict = extras.get("shield_verdict")
    if verdict not in VERDICTS:
        return None
    if verdict == "P":
        hole = extras.get("shield_hole_diameter_m") or 0.0
        what = "a %.1f mm hole" % (hole * 1e3) if hole > 0 else extras.get("shield_reason") or "perforated"
    else:
        what = "%.1f mm bulge" % ((extras.get("shield_peak_deflection_m") or 0.0) * 1e3)
    return verdict, what


def verdict_row(study, answer, result):
    """One Markdown row for a verdict (a Whipple shot's P or NP): a verdict is not a number to
    extrapolate, so the row gives each level's verdict, the finest first in its value column, and
    how many levels agree with the experiment's (answer["verdict"])."""
    expected = answer["verdict"]
    levels = result["levels"]
    seen = [(l, level_verdict(l)) for l in levels]
    unread = [l for l, v in seen if v is None]
    if unread:
        return ("| %s | no shield verdict for level %s (no completed run's summary.json there, or not a Whipple "
                "scene: `bench/headline.py --only %s`) | | | | | |") % (
            answer["label"], ", ".join("%.6g" % l["factor"] for l in unread), study["id"])
    agree = sum(1 for _, (v, _) in seen if v == expected)
    verdict, what = seen[-1][1]
    mark = "" if verdict == expected else "**"
    value = "%s%s%s (%s); the experiment: %s" % (mark, verdict, mark, what, expected)
    each = "; ".join("%.3g mm %s (%s)" % (l["spacing_m"] * 1e3, v, w) for l, (v, w) in seen)
    notes = ["the experiment's verdict at %d of %d spacings: %s" % (agree, len(levels), each)]
    missing = len(set(study["factors"]) - {l["factor"] for l in levels})
    if missing:
        notes.append("%d of the %d levels asked for %s not run yet (`bench/headline.py --only %s`)" % (
            missing, len(study["factors"]), "has" if missing == 1 else "have", study["id"]))
    finest = levels[-1]
    core_seconds = sum(l["wall_seconds"] * l["threads"] for l in levels)
    return "| %s | %s | — | — | %s | %.3g mm; %s | %s (%d levels) |" % (
        answer["label"], value, "; ".join(notes), finest["spacing_m"] * 1e3, "{:,}".format(finest["particles"]),
        duration(core_seconds), len(levels))


def band_name(own, q):
    """The band's name as the row gives it: its own (Roache's fallback, the least-squares fit), or
    half the three finest's spread where ejecta converge found that wider (an oscillation's half
    amplitude, Stern et al. 2001), so that the row does not quote a factor of safety it did not use."""
    if q.get("band_at_half_spread"):
        return "half the three finest's spread, wider than the %s" % own
    return own


def clipped(q, answer):
    """Where the band runs past what the quantity can be (the answer's minimum and maximum in the
    row's unit: a share lies between 0 and 100%), the interval it leaves, as "; clipped to ..."."""
    scale = answer.get("scale", 1.0)
    unit = answer.get("unit", "")
    fine = q["finest"] * scale
    band = q["uncertainty"] * scale
    low = max(fine - band, answer.get("minimum", -math.inf))
    high = min(fine + band, answer.get("maximum", math.inf))
    if (low, high) == (fine - band, fine + band):
        return ""
    return "; the band clipped to what the quantity can be: %s to %s" % (number(low, unit), number(high, unit))


def answer_row(study, answer, result):
    """One Markdown row: the answer; the finest value with its GCI band (Celik et al. 2008 put
    the band about the finest solution) or, where the levels are not in the asymptotic range,
    Roache's fallback band and the spread of the three finest levels (with four or more levels,
    Eca & Hoekstra's least-squares band where ejecta converge found it wider); the extrapolated value;
    the order; the note; the finest spacing and particles; the core time of all levels."""
    rerun = "`bench/headline.py --only %s`" % study["id"]
    if result is None:
        return "| %s | not run yet (%s) | | | | | |" % (answer["label"], rerun)
    if "stale" in result:
        return "| %s | stale: %s (%s) | | | | | |" % (answer["label"], result["stale"], rerun)
    if "verdict" in answer:
        return verdict_row(study, answer, result)
    scale = answer.get("scale", 1.0)
    unit = answer.get("unit", "")
    found = [q for q in result["quantities"] if q["quantity"] == answer["quantity"]]
    if not found:
        return "| %s | not run yet: the study ran without '%s' (%s) | | | | | |" % (
            answer["label"], answer["quantity"], rerun)
    q = found[0]
    levels = result["levels"]
    finest = levels[-1]
    notes = [q["note"]] if q.get("note") else []
    missing = len(set(study["factors"]) - {l["factor"] for l in levels})
    if missing:
        notes.append("%d of the %d levels asked for %s not run yet (%s)" % (
            missing, len(study["factors"]), "has" if missing == 1 else "have", rerun))
    order = "%.2f" % q["observed_order"] if q.get("valid") else "—"
    fine = number(q["finest"] * scale, unit)
    # In the asymptotic range: convergence.json says so; one written before it did (2026-12-07)
    # is judged as ejecta converge now judges it (an order of at most twice the formal order 1).
    asymptotic = q.get("asymptotic", q.get("valid") and not q.get("note") and q.get("observed_order", 0) <= 2.0)
    least_squares = q.get("uncertainty_basis") == "least squares"
    if asymptotic:
        value = "%s ± %s" % (fine, number(q["uncertainty"] * scale, unit))
        # Eca & Hoekstra's band over all levels where it is wider than Celik's on the three finest.
        remarks = ["least squares, %d levels" % len(levels)] if least_squares else []
        clip = clipped(q, answer)
        remarks += [clip[2:]] if clip else []
        if remarks:
            value += " (%s)" % "; ".join(remarks)
        extrapolated = number(q["extrapolated"] * scale, unit)
    else:
        # Where the procedure does not apply (oscillation, an order out of range, no order) an
        # extrapolation claims nothing: the spread of the three finest levels is what is known.
        # Where ejecta converge gave Roache's fallback band (the formal order, factor of safety
        # 3), it is the uncertainty to quote, beside the spread.
        last = sorted(l["values"][answer["quantity"]] * scale for l in levels[-3:])
        spread = "%s to %s over the three finest" % (number(last[0], unit), number(last[-1], unit))
        if q.get("uncertainty_basis") == "formal-order fallback":
            value = "%s ± %s (%s; not settled: %s%s)" % (
                fine, number(q["uncertainty"] * scale, unit),
                band_name("fallback band, order %.3g, factor of safety 3" % q["band_order"], q), spread,
                clipped(q, answer))
        elif least_squares:
            value = "%s ± %s (%s; not settled: %s%s)" % (
                fine, number(q["uncertainty"] * scale, unit),
                band_name("least-squares band over %d levels, factor of safety %.3g" % (
                    len(levels), q["least_squares"]["safety_factor"]), q), spread, clipped(q, answer))
        else:
            value = "%s (not settled: %s)" % (fine, spread)
        extrapolated = "—"
    core_seconds = sum(l["wall_seconds"] * l["threads"] for l in levels)
    spacings = ", ".join("%.3g" % l["spacing_m"] for l in levels)
    return "| %s | %s | %s | %s | %s | %.3g m; %s | %s (%d levels: %s m) |" % (
        answer["label"], value, extrapolated, order, "; ".join(notes), finest["spacing_m"],
        "{:,}".format(finest["particles"]), duration(core_seconds), len(levels), spacings)


def table(manifest, out_root, ejecta=None, kept=None):
    """The Markdown table; `kept` (label -> a document's row) gives the row of an answer whose
    study has not run here."""
    lines = ["| answer | finest run ± GCI band | extrapolated | observed order | note | finest spacing; particles "
             "| cost (core time, all levels) |",
             "|---|---|---|---|---|---|---|"]
    for study in manifest.get("study", []):
        result = read_study(out_root, study, ejecta)
        for answer in study["answer"]:
            if result is None and kept and answer["label"] in kept:
                lines.append(kept[answer["label"]])
            else:
                lines.append(answer_row(study, answer, result))
    for row in manifest.get("open", []):
        lines.append("| %s | — | — | — | %s | | |" % (row["label"], row["why"]))
    return "\n".join(lines) + "\n"


def rows_between_markers(path):
    """The rows of the table between the headline markers of `path`, by their first cell."""
    with open(path) as f:
        content = f.read()
    start, stop = content.find(BEGIN), content.find(END)
    if start < 0 or stop < start:
        return {}
    rows = {}
    for line in content[start + len(BEGIN):stop].splitlines():
        cells = line.split(" | ")
        if line.startswith("| ") and not line.startswith("|---") and len(cells) > 1:
            rows[cells[0][2:]] = line
    return rows


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
        text = table(manifest, args.out, args.ejecta)
        sys.stdout.write(text)
        if args.write:
            for name in TABLE_FILES:
                path = os.path.join(SOURCE, name)
                write_between_markers(path, table(manifest, args.out, args.ejecta, rows_between_markers(path)))
    except HeadlineError as e:
        sys.exit("headline: " + str(e))
    except subprocess.CalledProcessError as e:
        sys.exit("headline: %s failed (exit %d)" % (" ".join(e.cmd[:3]), e.returncode))


if __name__ == "__main__":
    main()
