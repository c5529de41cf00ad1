"""Summary, energy log and crater profile, checked against each other and the snapshots."""
import json
import os

import numpy as np
import pytest

import ejecta


def test_the_summary_matches_the_last_snapshot(run_dir):
    summary = ejecta.load_summary(run_dir)
    assert summary["status"] == "completed"
    last = ejecta.load_run(run_dir).series[-1]
    assert summary["particles"] == len(last)
    assert summary["steps"] == last.step
    assert summary["t_end"] == pytest.approx(last.time, rel=1e-12)


def test_the_energy_log_carries_units_from_its_header(run_dir):
    energy = ejecta.load_energy(run_dir)
    assert energy["time_s"].units == "s"
    assert energy["kinetic_J"].units == "J"
    assert energy["relative_error"].units == "1"
    assert energy["step"][-1] == ejecta.load_summary(run_dir)["steps"]
    total = np.asarray(energy["kinetic_J"]) + np.asarray(energy["internal_J"])
    np.testing.assert_allclose(total, energy["total_J"], rtol=1e-9)


def test_the_crater_profile_agrees_with_the_summary(run_dir):
    profile = ejecta.load_crater_profile(run_dir)
    assert profile["distance_m"].units == "m"
    extras = ejecta.load_summary(run_dir)["extras"]
    assert extras["crater_found"]
    # The summary's depth is the profile's deepest point (docs/crater.md).
    assert np.max(profile["depth_max_m"]) == pytest.approx(extras["crater_depth_m"], rel=1e-12)
    assert np.all(np.diff(profile["distance_m"]) > 0)


def test_damaged_tables_are_refused_by_name(copy_of_run):
    (copy_of_run / "summary.json").write_text("{ not json")
    with pytest.raises(ejecta.EjectaFileError) as caught:
        ejecta.load_summary(copy_of_run)
    assert "summary.json" in str(caught.value)
    (copy_of_run / "summary.json").write_text(json.dumps([1, 2]))
    with pytest.raises(ejecta.EjectaFileError):
        ejecta.load_summary(copy_of_run)
    with open(copy_of_run / "crater_profile.csv", "a") as f:
        f.write("1,2\n")
    with pytest.raises(ejecta.EjectaFileError) as caught:
        ejecta.load_crater_profile(copy_of_run)
    assert "crater_profile.csv" in str(caught.value) and "line" in str(caught.value)
    with pytest.raises(ejecta.EjectaFileError):
        ejecta.load_run(copy_of_run / "missing")
