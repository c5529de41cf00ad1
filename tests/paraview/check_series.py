"""Opens a run's snapshots.xdmf with ParaView's own readers and checks what a user sees.

Run by pvbatch (Debian's paraview + python3-paraview, under xvfb-run):
    pvbatch check_series.py RUN_DIR OUT_PNG
For each of ParaView's XDMF readers (Xdmf3ReaderS, Xdmf3ReaderT, the legacy XDMFReader): one
vertex cell per particle, every /particles dataset of the snapshots as a point array, the times exactly those stored in the snapshots. Then one frame is
drawn with the Points representation coloured by density, and its pixels are checked: particles
must cover part of the picture. Exits non-zero with the reason on the first failure.
"""
import os
import sys

import h5py
from paraview import servermanager
from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetDisplayProperties, Render,
                             SaveScreenshot, Show, UpdatePipeline, XDMFReader, Xdmf3ReaderS,
                             Xdmf3ReaderT)


def fail(message):
    print("check_series: FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def expected_arrays(snapshot):
    """The point arrays the XDMF promises: every /particles dataset but position (the points)."""
    with h5py.File(snapshot, "r") as f:
        names = {name for name in f["particles"] if name != "position"}
        return names, f["particles/position"].shape[0], float(f.attrs["time"])


def main():
    run_dir, png = sys.argv[1], sys.argv[2]
    xdmf = os.path.join(run_dir, "snapshots.xdmf")
    snapshots = sorted(os.listdir(os.path.join(run_dir, "snapshots")))
    stored = [expected_arrays(os.path.join(run_dir, "snapshots", s)) for s in snapshots]
    times = [t for _, _, t in stored]
    arrays, particles, _ = stored[-1]
    for make in (Xdmf3ReaderS, Xdmf3ReaderT, XDMFReader):
        label = make.__name__
        reader = make(FileNames=[xdmf]) if make is XDMFReader else make(FileName=[xdmf])
        seen = list(reader.TimestepValues) if len(times) > 1 else [times[0]]
        if seen != times:
            fail("%s: times %r, the snapshots hold %r" % (label, seen, times))
        reader.UpdatePipeline(times[-1])
        data = servermanager.Fetch(reader)
        if data.IsA("vtkMultiBlockDataSet"):
            data = data.GetBlock(0)
        if data.GetNumberOfPoints() != particles or data.GetNumberOfCells() != particles:
            fail("%s: %d points and %d cells, the last snapshot has %d particles"
                 % (label, data.GetNumberOfPoints(), data.GetNumberOfCells(), particles))
        pd = data.GetPointData()
        names = {pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays())}
        if not arrays <= names:
            fail("%s: arrays missing: %s" % (label, sorted(arrays - names)))
        print("check_series: %s: %d particles, %d times, arrays %s"
              % (label, particles, len(seen), ", ".join(sorted(arrays))))
    # One frame, as the docs tell a user to look: Points, coloured by density.
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [400, 400]
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.Background = [0, 0, 0]
    view.OrientationAxesVisibility = 0
    reader = Xdmf3ReaderS(FileName=[xdmf])
    display = Show(reader, view)
    display.SetRepresentationType("Points")
    display.PointSize = 8
    ColorBy(display, ("POINTS", "density"))
    view.ResetCamera()
    Render(view)
    SaveScreenshot(png, view, ImageResolution=[400, 400])
    from vtkmodules.vtkIOImage import vtkPNGReader
    image = vtkPNGReader()
    image.SetFileName(png)
    image.Update()
    scalars = image.GetOutput().GetPointData().GetScalars()
    background = scalars.GetTuple(0)[:3]  # a corner: the view is fitted to the particles
    lit = sum(1 for i in range(scalars.GetNumberOfTuples())
              if scalars.GetTuple(i)[:3] != background)
    share = lit / float(scalars.GetNumberOfTuples())
    print("check_series: frame %s: %.1f%% of the pixels drawn" % (png, 100 * share))
    # The test run's ~160 particles as 8-pixel points cover ~5% of a 400 x 400 frame fitted
    # to them; an empty frame (no cells, nothing drawn) covers 0.
    if share < 0.01:
        fail("the rendered frame is empty (%.3f%% of the pixels drawn)" % (100 * share))


if __name__ == "__main__":
    main()
