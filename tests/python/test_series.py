"""ejecta.load_series: from the XDMF, from the files, and the times exactly the snapshots'."""
import os
import shutil

import numpy as np
import pytest

import ejecta


def test_the_series_from_the_run_directory_and_from_the_xdmf_agree(run_dir):
    from_dir = ejecta.load_series(run_dir)
    from_xdmf = ejecta.load_series(os.path.join(run_dir, "snapshots.xdmf"))
    assert len(from_dir) == len(from_xdmf) == 4  # t = 0, 10, 20, 30 us
    np.testing.assert_array_equal(from_dir.times, from_xdmf.times)
    assert from_dir.times.units == "s"
    for snap, t in zip(from_dir, from_dir.times):
        assert snap.time == t  # the XDMF's times read back as the stored doubles
    assert np.all(np.diff(from_dir.times) > 0)
    assert from_dir[-1].path == from_dir.files[-1]


def test_without_the_xdmf_the_files_give_the_series(copy_of_run):
    os.remove(copy_of_run / "snapshots.xdmf")
    series = ejecta.load_series(copy_of_run)
    assert len(series) == 4
    assert series.at(21e-6).time == pytest.approx(20e-6)
    assert series.at(1.0).time == series.times[-1]
    assert len(series[1:3]) == 2


def test_a_damaged_xdmf_is_refused_by_name(copy_of_run):
    (copy_of_run / "snapshots.xdmf").write_text("<Xdmf><Domain><Grid")
    with pytest.raises(ejecta.EjectaFileError) as caught:
        ejecta.load_series(copy_of_run)
    assert "snapshots.xdmf" in str(caught.value)
    with pytest.raises(ejecta.EjectaFileError):
        ejecta.load_series(copy_of_run / "no_such_dir")
