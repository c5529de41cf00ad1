"""The plotting helpers draw what they say (matplotlib's Agg back end, no display)."""
import numpy as np
import pytest

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import ejecta  # noqa: E402
from ejecta.plotting import plot_crater_profile, plot_energy, plot_particles, time_scale  # noqa: E402


def test_particles_are_mirrored_in_rz_and_labelled_with_units(run_dir, tmp_path):
    snap = ejecta.load_run(run_dir).series[-1]
    fig, ax = plt.subplots()
    drawn = plot_particles(snap, "pressure", ax=ax)
    assert len(drawn.get_offsets()) == 2 * len(snap)
    assert "[Pa]" in fig.axes[-1].get_ylabel()  # the colour bar
    assert ax.get_xlabel() == "r [m]" and "us" in ax.get_title()
    sizes = drawn.get_sizes()
    assert np.all(sizes > 1.0)  # discs, not single pixels
    fig.savefig(tmp_path / "p.png")
    plt.close(fig)


def test_the_crater_profile_is_drawn_downward(run_dir):
    fig, ax = plt.subplots()
    line = plot_crater_profile(ejecta.load_crater_profile(run_dir), ax=ax)
    assert np.min(line.get_ydata()) < 0  # depth below the surface
    plot_energy(ejecta.load_energy(run_dir), ax=plt.subplots()[1])
    plt.close("all")


def test_time_axes_pick_ms_or_us():
    assert time_scale([0.0, 3e-5]) == ("us", 1e6)
    assert time_scale([0.0, 3e-3]) == ("ms", 1e3)
    assert time_scale([0.0, 30.0]) == ("s", 1.0)
