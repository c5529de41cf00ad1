"""ejecta.load_grids over the run's VDB files (Debian's python3-openvdb)."""
import numpy as np
import pytest

import ejecta

pytest.importorskip("pyopenvdb", reason="Debian's python3-openvdb is not installed")


def test_the_grids_of_the_last_file(run_dir):
    run = ejecta.load_run(run_dir)
    grids = run.grids(-1)
    last = run.series[-1]
    assert grids.time == last.time
    assert {"density", "temperature", "pressure", "damage", "surface"} <= set(grids)
    density = grids["density"]
    assert density.units == "kg/m^3" and density.values.units == "kg/m^3"
    assert density.grid_class == "fog volume"
    assert density.voxel_size == pytest.approx(0.04)
    assert grids["surface"].grid_class == "level set"
    # The grid of an RZ run is the revolved body: its density integrates to the particles' mass
    # (RZ particle masses are whole rings). The deposit conserves mass up to the voxelisation
    # of the kernel's edge: 0.6% at this 0.04 m voxel; 3% leaves room for platform rounding.
    grid_mass = float(np.sum(density.values, dtype=np.float64)) * density.voxel_size ** 3
    assert grid_mass == pytest.approx(float(np.sum(last.mass)), rel=0.03)
    # Voxel centres span the active box.
    assert density.axis(0)[0] == pytest.approx(density.origin[0])
    assert len(density.axis(1)) == density.values.shape[1]


def test_asking_for_a_grid_the_file_lacks_names_the_grids(run_dir):
    path = ejecta.load_run(run_dir).grid_files[-1]
    with pytest.raises(ejecta.EjectaFileError) as caught:
        ejecta.load_grids(path, names=["densty"])
    assert "densty" in str(caught.value) and "density" in str(caught.value)
    assert set(ejecta.load_grids(path, names=["density"])) == {"density"}


def test_a_file_that_is_not_a_grid_file_is_refused(tmp_path):
    bad = tmp_path / "bad.vdb"
    bad.write_bytes(b"not a vdb file at all")
    with pytest.raises(ejecta.EjectaFileError) as caught:
        ejecta.load_grids(bad)
    assert "bad.vdb" in str(caught.value)
