"""ejecta.load_snapshot against the file as h5py reads it, and on damaged files."""
import glob
import os

import h5py
import numpy as np
import pytest

import ejecta


def last_snapshot(run_dir):
    return sorted(glob.glob(os.path.join(run_dir, "snapshots", "snap_*.h5")))[-1]


def test_every_particle_dataset_reads_with_its_units(run_dir):
    path = last_snapshot(run_dir)
    snap = ejecta.load_snapshot(path)
    with h5py.File(path, "r") as f:
        names = sorted(f["particles"].keys())
        assert snap.fields == names
        assert snap.time == f.attrs["time"]  # exactly: the same double
        assert len(snap) == f["particles/position"].shape[0]
        for name in names:
            values = snap[name]
            assert isinstance(values, ejecta.UnitArray)
            np.testing.assert_array_equal(np.asarray(values), f["particles"][name][()])
            stored = f["particles"][name].attrs["units"]
            assert values.units == (stored.decode() if isinstance(stored, bytes) else stored)
    assert snap.density.units == "kg/m^3"
    assert snap.pressure.units == "Pa"
    assert snap.stress.shape == (len(snap), 4)  # RZ deviatoric stress: rr, zz, tt, rz
    assert snap.geometry == "rz" and snap.dimension == 2 and snap.scene == "outputs_test"
    assert snap.version


def test_coordinates_follow_the_geometry(run_dir):
    snap = ejecta.load_snapshot(last_snapshot(run_dir))
    assert snap.coordinates == ("r", "z")
    np.testing.assert_array_equal(snap.r, np.asarray(snap.position)[:, 0])
    np.testing.assert_array_equal(snap.z, np.asarray(snap.position)[:, 1])
    assert snap.r.units == "m" and np.all(np.asarray(snap.r) >= 0)
    with pytest.raises(AttributeError):
        snap.y  # RZ has no y


def test_materials_by_name(run_dir):
    snap = ejecta.load_snapshot(last_snapshot(run_dir))
    assert [m.name for m in snap.materials] == ["granite", "aluminium"]
    granite = snap.materials[0]
    assert granite.id == 0
    assert granite.eos == "tillotson (granite)"
    assert granite.strength == "von_mises" and granite.fracture == "grady_kipp"
    assert snap.materials[1].strength == "none"
    names = snap.material_name
    assert set(names) == {"granite", "aluminium"}
    mask = snap.select(material="aluminium")
    assert mask.sum() == np.sum(np.asarray(snap.material) == 1) > 0
    np.testing.assert_array_equal(mask, snap.select(material=1))
    assert snap.select().all()


def test_the_scene_source_travels_with_the_snapshot(run_dir):
    snap = ejecta.load_snapshot(last_snapshot(run_dir))
    assert 'name = "outputs_test"' in snap.scene_source


def test_a_missing_field_names_the_file_and_the_fields(run_dir):
    snap = ejecta.load_snapshot(last_snapshot(run_dir))
    with pytest.raises(KeyError) as caught:
        snap["densty"]
    assert "densty" in str(caught.value) and "density" in str(caught.value)


def test_missing_truncated_and_foreign_files_are_refused_by_name(copy_of_run, tmp_path):
    with pytest.raises(ejecta.EjectaFileError) as caught:
        ejecta.load_snapshot(tmp_path / "nothing.h5")
    assert "nothing.h5" in str(caught.value) and "no such file" in str(caught.value)
    truncated = tmp_path / "truncated.h5"
    data = open(last_snapshot(str(copy_of_run)), "rb").read()
    truncated.write_bytes(data[: len(data) // 3])
    with pytest.raises(ejecta.EjectaFileError) as caught:
        ejecta.load_snapshot(truncated)
    assert "truncated.h5" in str(caught.value)
    foreign = tmp_path / "foreign.h5"
    with h5py.File(foreign, "w") as f:
        f["x"] = np.arange(3)
    with pytest.raises(ejecta.EjectaFileError) as caught:
        ejecta.load_snapshot(foreign)
    assert "not an ejecta snapshot" in str(caught.value)


def test_a_flipped_byte_in_an_array_is_caught_by_its_checksum(copy_of_run):
    # The arrays carry HDF5's Fletcher-32 (docs/robustness.md): h5py verifies it on read.
    path = last_snapshot(str(copy_of_run))
    with h5py.File(path, "r") as f:
        offset = f["particles/density"].id.get_offset()
        if offset is None:  # chunked: the first chunk's place
            offset = f["particles/density"].id.get_chunk_info(0).byte_offset
    with open(path, "r+b") as f:
        f.seek(offset + 3)
        byte = f.read(1)
        f.seek(offset + 3)
        f.write(bytes([byte[0] ^ 0x40]))
    snap = ejecta.load_snapshot(path)
    with pytest.raises(OSError):
        snap.density
