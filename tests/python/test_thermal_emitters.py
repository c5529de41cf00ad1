"""bench/thermal_emitters.py (issue 23, which emitter representation converges): what it reads
back from a study that ran, and what it refuses: a series folder made with other scene keys (its
levels would be read back as the new series'), voxel emitters without filled fractions (made
before fields/grid_voxels read the runs' 'capped' fractions), a study without side0."""
import importlib.util
import json
import os

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))
_spec = importlib.util.spec_from_file_location("thermal_emitters",
                                               os.path.join(SOURCE, "bench", "thermal_emitters.py"))
thermal_emitters = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(thermal_emitters)


def write_thermal(folder, fill_weighted=True, patch="side0"):
    os.makedirs(folder, exist_ok=True)
    doc = {"emitters": 12, "emitter_volume_m3": 3.5,
           "grid_file": {"fill_weighted": fill_weighted},
           "patches": [{"patch": patch, "peak_flux_W_m2": 2.5e6, "peak_flux_se_W_m2": 1.0e3,
                        "steady_temperature_K": 2800.0,
                        "wall": {"layers": [{"material": "tungsten", "peak_K": 300.0},
                                            {"material": "aluminium", "peak_K": 293.4}]}}]}
    with open(os.path.join(folder, "thermal.json"), "w") as f:
        json.dump(doc, f)


def test_a_finished_pass_is_read_back_not_run(tmp_path):
    out = str(tmp_path / "thermal_voxels")
    write_thermal(out)
    # No binary: a pass that ran is read back, side0's numbers and the aluminium layer by name.
    r = thermal_emitters.thermal("/nonexistent/ejecta", "unused", out, "voxels", 1)
    assert r == {"flux": 2.5e6, "se": 1.0e3, "steady": 2800.0, "aluminium": 293.4, "emitters": 12,
                 "volume": 3.5}


def test_voxels_as_full_voxels_are_refused(tmp_path):
    out = str(tmp_path / "thermal_voxels")
    write_thermal(out, fill_weighted=False)
    with pytest.raises(SystemExit, match="without filled fractions"):
        thermal_emitters.thermal("/nonexistent/ejecta", "unused", out, "voxels", 1)
    # The particles' pass has no grid to be wrong about.
    assert thermal_emitters.thermal("/nonexistent/ejecta", "unused", out, "particles", 1)["flux"] == 2.5e6


def test_a_study_without_side0_says_so(tmp_path):
    out = str(tmp_path / "thermal_particles")
    write_thermal(out, patch="front")
    with pytest.raises(SystemExit, match="no patch side0"):
        thermal_emitters.thermal("/nonexistent/ejecta", "unused", out, "particles", 1)


def test_a_series_made_with_other_keys_is_refused(tmp_path):
    series = tmp_path / "phase_changes"
    series.mkdir()
    (series / "definition.json").write_text(json.dumps(["time.t_end=1 ms"]))
    with pytest.raises(SystemExit, match="made with other --set keys"):
        thermal_emitters.impact_levels("/nonexistent/ejecta", str(series), [1.0],
                                       ["materials[0].thermal.phase_changes=true"], 1)
