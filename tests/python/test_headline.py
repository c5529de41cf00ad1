"""bench/headline.py: the headline table of converged answers (issue 23). The manifest shipped,
the rows made from a study's convergence.json, the refusals (a changed study, a missing
quantity, a file without markers) and, with EJECTA_BINARY, one study run end to end on a
problem with an exact answer."""
import importlib.util
import json
import os

import pytest

pytest.importorskip("tomllib", reason="bench/headline.py reads its manifest with tomllib (Python 3.11)")

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))
_spec = importlib.util.spec_from_file_location("headline", os.path.join(SOURCE, "bench", "headline.py"))
headline = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(headline)


def write_manifest(path, text):
    path.write_text(text)
    return str(path)


STUDY = """
[[study]]
id = "crater"
scene = "impact_rz"
factors = [1.4142, 1, 0.7071]
set = ["time.t_end=1 ms"]
  [[study.answer]]
  label = "crater depth"
  quantity = "crater_depth_m"
  unit = "m"
  [[study.answer]]
  label = "share"
  quantity = "target_share_of_impactor_energy"
  unit = "%"
  scale = 100
[[open]]
label = "end of growth"
why = "the crater does not stop"
"""


def fake_study(out, study, quantities, threads=2):
    """A study folder as bench/headline.py and `ejecta converge` leave it."""
    folder = out / study["id"]
    folder.mkdir(parents=True)
    (folder / "study.json").write_text(json.dumps({"definition": headline.definition(study), "threads": threads}))
    levels = [{"factor": f, "spacing_m": 0.25 * f, "particles": int(1000 / f ** 2), "wall_seconds": 10.0 / f ** 3,
               "values": {"crater_depth_m": 7.0 + f, "target_share_of_impactor_energy": 0.9 + 0.01 * f}}
              for f in study["factors"]]
    (folder / "convergence.json").write_text(json.dumps({"scene": study["scene"], "levels": levels,
                                                         "quantities": quantities}))


def test_the_shipped_manifest_names_shipped_scenes_and_three_levels():
    manifest = headline.load_manifest(os.path.join(SOURCE, "bench", "headline.toml"))
    assert manifest["study"], "no study in bench/headline.toml"
    for study in manifest["study"]:
        assert os.path.exists(os.path.join(SOURCE, "scenes", study["scene"] + ".toml")), study["scene"]
        assert len(study["factors"]) >= 3
    assert manifest["open"], "the answers that cannot be converged yet are stated"


def test_rows_from_a_study_that_ran(tmp_path):
    manifest = headline.load_manifest(write_manifest(tmp_path / "m.toml", STUDY))
    study = manifest["study"][0]
    fake_study(tmp_path / "out", study, [
        {"quantity": "crater_depth_m", "finest": 7.712, "valid": True, "observed_order": 0.87,
         "extrapolated": 8.41, "gci": 0.11, "uncertainty": 0.85},
        {"quantity": "target_share_of_impactor_energy", "finest": 0.9204, "valid": False,
         "note": "oscillatory convergence"}])
    (tmp_path / "out" / "crater" / "level_1").mkdir()
    (tmp_path / "out" / "crater" / "level_1" / "summary.json").write_text('{"threads": 1}')
    text = headline.table(manifest, str(tmp_path / "out"))
    rows = text.splitlines()
    # The band is Celik et al.'s: about the finest value; the extrapolation beside it.
    assert rows[2].startswith("| crater depth | 7.71 m ± 0.850 m | 8.41 m | 0.87 |"), rows[2]
    # The finest level is the last one: 0.25 * 0.7071 m, 1000 / 0.7071^2 particles; the cost is
    # every level's wall time times its threads, together: 3.5 x 2 + 10 x 1 (its own summary
    # says 1 thread) + 28.3 x 2 (study.json's 2 where a level has no summary).
    assert "| 0.177 m; 2,000 |" in rows[2]
    assert "| 74 s (3 levels: 0.354, 0.25, 0.177 m) |" in rows[2]
    # A result the procedure flags claims no extrapolation: the three finest levels' spread.
    assert rows[3].startswith("| share | 92.0% (not settled: 90.7% to 91.4% over the three finest) | — | — | "
                              "oscillatory convergence |"), rows[3]
    assert rows[4] == "| end of growth | — | — | — | the crater does not stop | | |"


def test_a_study_not_run_says_how_to_run_it(tmp_path):
    manifest = headline.load_manifest(write_manifest(tmp_path / "m.toml", STUDY))
    text = headline.table(manifest, str(tmp_path / "nothing"))
    assert "| crater depth | not run yet (`bench/headline.py --only crater`) |" in text


def test_a_changed_study_is_stale_not_read_back(tmp_path):
    manifest = headline.load_manifest(write_manifest(tmp_path / "m.toml", STUDY))
    fake_study(tmp_path / "out", manifest["study"][0], [
        {"quantity": "crater_depth_m", "finest": 7.7, "valid": False, "note": "two equal values"},
        {"quantity": "target_share_of_impactor_energy", "finest": 0.9, "valid": False, "note": "x"}])
    changed = write_manifest(tmp_path / "m2.toml", STUDY.replace('"time.t_end=1 ms"', '"time.t_end=2 ms"'))
    text = headline.table(headline.load_manifest(changed), str(tmp_path / "out"))
    assert "| crater depth | stale: its set changed since it ran (`bench/headline.py --only crater`) |" in text
    # Other factors are the same study (its level folders are per factor): its rows say how many
    # of the levels asked for are still to run.
    finer = headline.load_manifest(write_manifest(tmp_path / "m3.toml", STUDY.replace("0.7071]", "0.7071, 0.5]")))
    text = headline.table(finer, str(tmp_path / "out"))
    assert "two equal values; 1 of the 4 levels asked for has not run yet" in text
    # A study folder without its study.json: what ran is unknown.
    os.remove(tmp_path / "out" / "crater" / "study.json")
    assert "stale: " in headline.table(manifest, str(tmp_path / "out"))


def test_a_scene_edited_since_its_levels_ran_is_refused(tmp_path):
    scene = tmp_path / "blast.toml"
    scene.write_text("[scene]\nname = \"blast\"\n")
    manifest = headline.load_manifest(write_manifest(tmp_path / "m.toml", STUDY.replace('"impact_rz"', '"%s"' % scene)))
    fake_study(tmp_path / "out", manifest["study"][0], [])
    assert headline.read_study(str(tmp_path / "out"), manifest["study"][0]) is not None
    scene.write_text("# a comment is no change\n[scene]\nname   = \"blast\"  # nor is layout\n")
    assert headline.read_study(str(tmp_path / "out"), manifest["study"][0]) is not None
    scene.write_text("[scene]\nname = \"blast\"\ndescription = \"edited\"\n")
    assert headline.read_study(str(tmp_path / "out"), manifest["study"][0]) == {
        "stale": "its scene_sha256 changed since it ran"}
    with pytest.raises(headline.HeadlineError, match="neither a file nor scenes/no_such_scene.toml"):
        headline.definition({"scene": "no_such_scene"})


def test_a_quantity_the_study_lacks_says_so(tmp_path):
    manifest = headline.load_manifest(write_manifest(tmp_path / "m.toml", STUDY))
    fake_study(tmp_path / "out", manifest["study"][0], [
        {"quantity": "crater_depth_m", "finest": 7.7, "valid": False, "note": "two equal values"}])
    assert "| share | not run yet: the study ran without 'target_share_of_impactor_energy'" in headline.table(
        manifest, str(tmp_path / "out"))


def test_odd_numbers_and_files(tmp_path):
    assert headline.number(float("nan"), "m") == "nan m" and headline.number(float("inf")) == "inf"
    (tmp_path / "bad.json").write_text("{")
    with pytest.raises(headline.HeadlineError, match="bad.json"):
        headline.read_json(str(tmp_path / "bad.json"))


@pytest.mark.parametrize("text, message", [
    ('[[study]]\nid = "a"\nscene = "s"\nfactors = [1, 0.5]\n[[study.answer]]\nlabel = "x"\nquantity = "q"\n',
     "three or more"),
    ('[[study]]\nid = "a"\nscene = "s"\nfactors = [1, 0.7, 0.5]\n', "no 'answer'"),
    ('[[study]]\nid = "a"\nscene = "s"\nfactors = [1, 0.7, 0.7]\n[[study.answer]]\nlabel = "x"\nquantity = "q"\n',
     "distinct"),
    ('[[study]]\nid = "a"\nscene = "s"\nfactors = 1\n[[study.answer]]\nlabel = "x"\nquantity = "q"\n',
     "three or more"),
    ('[[study]]\nid = "a"\nscene = "s"\nfactors = [1, 0.7, 0.5]\nset = "x=1"\n[[study.answer]]\nlabel = "x"\n'
     'quantity = "q"\n', "set: an array of texts"),
    ('[[study]]\nid = "a"\nscene = "s"\nfactors = [1, 0.7, 0.5]\n[[study.answer]]\nlabel = "x"\n', "no 'quantity'"),
    ('[[open]]\nlabel = "x"\n', "no 'why'"),
    ('[[study]\n', "m.toml"),
])
def test_bad_manifests_name_the_file_and_the_key(tmp_path, text, message):
    with pytest.raises(headline.HeadlineError, match=message):
        headline.load_manifest(write_manifest(tmp_path / "m.toml", text))


def test_the_table_goes_between_the_markers_and_nothing_else_moves(tmp_path):
    doc = tmp_path / "doc.md"
    doc.write_text("# Title\n\n%s\nold table\n%s\n\nafter\n" % (headline.BEGIN, headline.END))
    headline.write_between_markers(str(doc), "| new |\n")
    assert doc.read_text() == "# Title\n\n%s\n| new |\n%s\n\nafter\n" % (headline.BEGIN, headline.END)
    bare = tmp_path / "bare.md"
    bare.write_text("no markers\n")
    with pytest.raises(headline.HeadlineError, match="bare.md"):
        headline.write_between_markers(str(bare), "| new |\n")
    assert bare.read_text() == "no markers\n"


def test_the_shipped_documents_have_the_markers():
    for name in headline.TABLE_FILES:
        content = open(os.path.join(SOURCE, name)).read()
        assert headline.BEGIN in content and headline.END in content, name


def test_a_study_end_to_end_on_the_1d_sedov_blast(tmp_path, capfd):
    """bench/headline.py drives `ejecta converge` on the 1D Sedov problem (docs/convergence.md):
    its shock radius has the exact value 0.35 m, which the finest run's GCI band must hold (the
    property the band claims; the command's own test checks the numbers)."""
    binary = os.environ.get("EJECTA_BINARY")
    if not binary:
        pytest.skip("EJECTA_BINARY is not set (CTest sets it)")
    manifest = write_manifest(tmp_path / "m.toml", """
[[study]]
id = "sedov"
scene = "verify:sedov_1d"
factors = [4, 2, 1.4142, 1]
  [[study.answer]]
  label = "1D Sedov shock radius"
  quantity = "shock_radius"
  unit = "m"
""")
    headline.main(["--manifest", manifest, "--ejecta", binary, "--out", str(tmp_path / "out"), "--threads", "1"])
    result = headline.read_study(str(tmp_path / "out"), headline.load_manifest(manifest)["study"][0])
    q = result["quantities"][0]
    assert q["valid"]
    assert abs(q["finest"] - 0.35) <= q["uncertainty"]  # the band, about the finest value
    rows = [line for line in capfd.readouterr().out.splitlines() if line.startswith("| 1D Sedov")]
    assert len(rows) == 1
    assert rows[0].startswith("| 1D Sedov shock radius | %s ± %s | %s | %.2f |" % (
        headline.number(q["finest"], "m"), headline.number(q["uncertainty"], "m"),
        headline.number(q["extrapolated"], "m"), q["observed_order"])), rows[0]
    assert "| 0.0025 m; 400 |" in rows[0]  # the 1D problem's finest level: 400 particles
    assert rows[0].endswith("(4 levels: 0.01, 0.005, 0.00354, 0.0025 m) |"), rows[0]
    # One more level is the same study (a scene's levels would be read back; a verification
    # problem runs again, in a second).
    finer = write_manifest(tmp_path / "m2.toml", open(manifest).read().replace("1.4142, 1]", "1.4142, 1, 0.7071]"))
    headline.main(["--manifest", finer, "--ejecta", binary, "--out", str(tmp_path / "out"), "--threads", "1"])
    levels = headline.read_study(str(tmp_path / "out"), headline.load_manifest(finer)["study"][0])["levels"]
    assert [l["particles"] for l in levels] == [100, 200, 283, 400, 566]
    # A study whose scene keys changed is refused before any run.
    changed = write_manifest(tmp_path / "m3.toml", open(manifest).read().replace(
        "factors", 'set = ["time.t_end=0.01 s"]\nfactors'))
    with pytest.raises(SystemExit, match="changed since its levels ran"):
        headline.main(["--manifest", changed, "--ejecta", binary, "--out", str(tmp_path / "out")])
