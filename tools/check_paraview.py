#!/usr/bin/env pvpython
"""Check that ParaView reads a run directory's particles.xmf as written, and draws it.

Usage (ParaView's Python; Debian's ParaView is built against X only, so even an
offscreen render needs an X display, and `--force-offscreen-rendering` alone crashes):

    xvfb-run -a -s "-noreset -screen 0 1280x1024x24" pvpython tools/check_paraview.py RUN_DIR [--png FILE] [--step K]

`-noreset` matters: without it Xvfb resets when its last client disconnects, and
pvpython's second connection, opened just after its first closed, is then refused
about half the time ("bad X server connection ... Aborting", exit 134).

RUN_DIR holds particles.h5 + particles.xmf (`moorsph run` with output.particles_interval
> 0). Both XDMF readers ParaView 5.11 offers for .xmf (Xdmf3ReaderS, the one
OpenDataFile picks, and the older Xdmf2 XDMFReader) must give:
  - one time step per /snapshots group, at the group's `time` attribute;
  - one point and one vertex cell per particle (without cells nothing is drawn in the
    default Surface representation);
  - point arrays velocity (3 components), pressure, density, type, id (1 each), and
    points equal to `position`, all equal to particles.h5 (read with h5py) at the first
    and the last snapshot.
Then snapshot K (default: the last) is rendered coloured by pressure in the default
Surface representation and the PNG (default RUN_DIR/paraview_pressure.png) must show
particles (pixels differing from the background).

Exit code 0 when every check passes, 1 otherwise (each failure printed), 2 on bad usage.
Verified with ParaView 5.11.0 and its Python (Debian: apt-get install paraview
python3-paraview xvfb) and h5py importable from pvpython.
"""
import argparse
import os
import sys

import h5py
import numpy as np
from paraview import servermanager
from paraview import simple
from vtkmodules.numpy_interface import dataset_adapter as dsa
from vtkmodules.vtkIOImage import vtkPNGReader

ARRAYS = {"velocity": 3, "pressure": 1, "density": 1, "type": 1, "id": 1}
failures = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what)
    if not ok:
        failures.append(what)


def read_h5(path):
    """Times and arrays of every snapshot, in the order the writer numbered them."""
    with h5py.File(path, "r") as f:
        keys = sorted(f["snapshots"].keys())
        times = [float(f["snapshots"][k].attrs["time"]) for k in keys]
        snaps = [{name: f["snapshots"][k][name][...] for name in list(ARRAYS) + ["position"]} for k in keys]
    return times, snaps


def open_reader(name, xmf):
    if name == "XDMFReader":
        return simple.XDMFReader(registrationName=name, FileNames=[xmf])
    return getattr(simple, name)(registrationName=name, FileName=[xmf])


def fetch(reader, time):
    """The reader's output at `time` as a numpy-wrapped single dataset."""
    reader.UpdatePipeline(time)
    data = servermanager.Fetch(reader)
    if data.IsA("vtkMultiBlockDataSet") or data.IsA("vtkPartitionedDataSetCollection"):
        it = data.NewIterator()
        it.InitTraversal()
        data = it.GetCurrentDataObject()
    return dsa.WrapDataObject(data)


def compare(label, got, want):
    got = np.asarray(got).reshape(want.shape)
    diff = float(np.max(np.abs(got - want))) if want.size else 0.0
    check(diff <= 1e-12 * max(1.0, float(np.max(np.abs(want)))), f"{label}: max |ParaView - h5py| = {diff:.3g}")


def check_reader(name, xmf, times, snaps):
    print(f"--- {name}")
    reader = open_reader(name, xmf)
    reader.UpdatePipelineInformation()
    pv_times = list(reader.TimestepValues or [])
    check(len(pv_times) == len(times), f"{len(pv_times)} time steps, {len(times)} snapshots in particles.h5")
    if len(pv_times) == len(times):
        check(np.allclose(pv_times, times, rtol=0, atol=1e-12), "time values equal the snapshots' time attributes")
    for k in sorted({0, len(times) - 1}):
        data, want = fetch(reader, times[k]), snaps[k]
        n = len(want["pressure"])
        check(data.GetNumberOfPoints() == n, f"t = {times[k]:.4g} s: {data.GetNumberOfPoints()} points, {n} particles")
        check(data.GetNumberOfCells() == n, f"t = {times[k]:.4g} s: {data.GetNumberOfCells()} vertex cells, {n} particles")
        if data.GetNumberOfPoints() != n:
            continue
        compare(f"t = {times[k]:.4g} s: points vs position", data.Points, want["position"])
        for array, comps in ARRAYS.items():
            got = data.PointData[array]
            if got is None or isinstance(got, dsa.VTKNoneArray):
                check(False, f"point array {array} present")
                continue
            check(data.GetPointData().GetArray(array).GetNumberOfComponents() == comps, f"{array}: {comps} component(s)")
            compare(f"t = {times[k]:.4g} s: {array}", got, want[array])
    return reader


def render(reader, time, png, fluid_pressure):
    """Draw the snapshot at `time` coloured by pressure (default representation); the
    colour range spans the 1st to 99th percentile of the fluid's pressure, so a few
    outliers do not wash the picture out."""
    view = simple.CreateRenderView()
    view.OrientationAxesVisibility = 0
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.ViewTime = time
    display = simple.Show(reader, view)
    display.PointSize = 4.0
    simple.ColorBy(display, ("POINTS", "pressure"))
    lut = simple.GetColorTransferFunction("pressure")
    lut.RescaleTransferFunction(*(float(v) for v in np.percentile(fluid_pressure, [1, 99])))
    lut.AutomaticRescaleRangeMode = "Never"
    bounds = reader.GetDataInformation().GetBounds()
    if bounds[5] - bounds[4] > 1e-12:  # 3D: look from the front, a little from above and the side
        view.CameraPosition = [0.5 * (bounds[0] + bounds[1]) + 0.6, bounds[3] + 0.5, bounds[5] + 1.2]
        view.CameraFocalPoint = [0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5])]
        view.CameraViewUp = [0, 1, 0]
    simple.ResetCamera(view)
    if bounds[5] - bounds[4] <= 1e-12:
        view.GetActiveCamera().Dolly(1.3)  # 2D: the reset leaves a wide margin
    # Count drawn pixels before the colour bar is added (the bar alone is not a display).
    simple.SaveScreenshot(png, view, ImageResolution=[800, 500], FontScaling="Do not scale fonts")
    image = vtkPNGReader()
    image.SetFileName(png)
    image.Update()
    rgb = np.asarray(dsa.WrapDataObject(image.GetOutput()).PointData[0])[:, :3]
    drawn = int(np.sum(np.any(rgb < 250, axis=1)))
    check(drawn > 0, f"t = {time:.4g} s rendered coloured by pressure: {drawn} of {len(rgb)} pixels drawn")
    display.SetScalarBarVisibility(view, True)
    bar = simple.GetScalarBar(lut, view)
    bar.Title, bar.ComponentTitle = "pressure [Pa]", ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    bar.WindowLocation = "Any Location"
    bar.Orientation = "Vertical"
    bar.Position = [0.84, 0.1]
    bar.HorizontalTitle = 1
    bar.ScalarBarLength = 0.8
    bar.TitleFontSize = bar.LabelFontSize = 12
    bar.RangeLabelFormat = bar.LabelFormat = "%-.0f"
    simple.SaveScreenshot(png, view, ImageResolution=[800, 500], FontScaling="Do not scale fonts")
    print(f"image: {png}")
    simple.Delete(display)
    simple.Delete(view)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("run_dir")
    parser.add_argument("--png", help="rendered image (default RUN_DIR/paraview_pressure.png)")
    parser.add_argument("--step", type=int, default=-1, help="snapshot to render (default: the last)")
    args = parser.parse_args()
    xmf, h5 = (os.path.join(args.run_dir, name) for name in ("particles.xmf", "particles.h5"))
    if not (os.path.isfile(xmf) and os.path.isfile(h5)):
        print(f"{args.run_dir}: no particles.xmf + particles.h5 (run with output.particles_interval > 0)")
        return 2
    print(servermanager.vtkSMProxyManager.GetParaViewSourceVersion())
    times, snaps = read_h5(h5)
    if not times:
        print(f"{h5}: no snapshot")
        return 1
    readers = [check_reader(name, xmf, times, snaps) for name in ("Xdmf3ReaderS", "XDMFReader")]
    shown = snaps[args.step]
    render(readers[0], times[args.step], args.png or os.path.join(args.run_dir, "paraview_pressure.png"),
           shown["pressure"][shown["type"] == 0])
    if failures:
        print(f"FAILED: {len(failures)} check(s)")
        return 1
    print("all ParaView checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
