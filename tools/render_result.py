"""Render a Grout result with ParaView: the deformed mesh coloured by a nodal field (default
contact_pressure), at one time step, to a PNG.

    tools/render results.e picture.png \
        [--field contact_pressure] [--time T] [--scale S] [--zoom-contact] [--size 1200 800]

Debian 12: python3-paraview provides `paraview.simple` for /usr/bin/python3 (and pvpython);
rendering off-screen needs an X server: tools/render starts Xvfb (package xvfb) and runs this
script under it; by hand, `xvfb-run -a /usr/bin/python3 tools/render_result.py ...` works too.

The file is read with the ExodusIIReader, which moves the nodes by the displacement field
itself (ApplyDisplacements, scaled by DisplacementMagnitude): no Warp By Vector filter, which
would apply the displacement a second time. --scale magnifies the displacement (default 1,
true scale: a magnified picture shows the bodies in contact overlapping). --zoom-contact
frames the nodes where the field is non-zero (the contact zone) instead of the whole mesh.
"""
import argparse
import sys

try:
    from paraview import servermanager as sm
    from paraview import simple
    from vtkmodules.numpy_interface import dataset_adapter as dsa
except ImportError as e:
    sys.exit("render_result: ParaView's Python modules are missing (Debian: apt-get install "
             "python3-paraview): %s" % e)

import numpy as np


def fetch(reader, time):
    merge = simple.MergeBlocks(Input=reader)
    merge.UpdatePipeline(time)
    data = dsa.WrapDataObject(sm.Fetch(merge))
    simple.Delete(merge)
    return data


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("exodus")
    parser.add_argument("png")
    parser.add_argument("--field", default="contact_pressure")
    parser.add_argument("--time", type=float, help="time value (default: the last step)")
    parser.add_argument("--scale", type=float, help="displacement magnification")
    parser.add_argument("--zoom-contact", action="store_true")
    parser.add_argument("--size", type=int, nargs=2, default=[1200, 800])
    args = parser.parse_args()

    reader = simple.ExodusIIReader(FileName=[args.exodus])
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues) or [0.0]
    time = times[-1] if args.time is None else min(times, key=lambda t: abs(t - args.time))
    if args.field not in reader.PointVariables.Available:
        sys.exit("render_result: %s has no nodal variable '%s' (has %s)"
                 % (args.exodus, args.field, list(reader.PointVariables.Available)))
    reader.PointVariables = reader.PointVariables.Available
    reader.ElementVariables = reader.ElementVariables.Available
    reader.ApplyDisplacements = 1

    # Reference geometry and displacement at `time`, for the framing.
    reader.DisplacementMagnitude = 0.0
    data = fetch(reader, time)
    xyz = np.array(data.Points)
    u = np.array(data.PointData["displ_"]) if "displ_" in data.PointData.keys() else 0 * xyz
    size = np.linalg.norm(xyz.max(axis=0) - xyz.min(axis=0))
    scale = 1.0 if args.scale is None else args.scale
    reader.DisplacementMagnitude = scale
    values = np.array(data.PointData[args.field])
    three_d = np.ptp(xyz[:, 2]) > 1e-12 * size

    view = simple.CreateRenderView()
    view.ViewSize = args.size
    view.ViewTime = time
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 0
    display = simple.Show(reader, view)
    display.SetRepresentationType("Surface With Edges")
    display.EdgeColor = [0.35, 0.35, 0.35]
    simple.ColorBy(display, ("POINTS", args.field))
    lut = simple.GetColorTransferFunction(args.field)
    lut.ApplyPreset("Cool to Warm", True)
    lo, hi = float(values.min()), float(values.max())
    lut.RescaleTransferFunction(lo, hi if hi > lo else lo + 1.0)
    bar = simple.GetScalarBar(lut, view)
    bar.Title = args.field
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    display.SetScalarBarVisibility(view, True)
    label = simple.Text(Text="%s at t = %g, displacements x %.3g" % (args.field, time, scale))
    text = simple.Show(label, view)
    text.Color = [0.0, 0.0, 0.0]
    text.WindowLocation = "Upper Center"

    simple.Render(view)  # the first render resets the camera: set ours after it
    # Frame the deformed mesh, or the deformed contact zone with a margin of its own width on
    # every side.
    frame = xyz + scale * u
    in_zone = np.abs(values) > 1e-6 * np.abs(values).max(initial=0.0)
    if args.zoom_contact and np.any(in_zone):
        zone = frame[in_zone]
        width = max(np.max(zone.max(axis=0) - zone.min(axis=0)), 1e-3 * size)
        frame = np.vstack([zone.min(axis=0) - width, zone.max(axis=0) + width])
    lo_box, hi_box = frame.min(axis=0), frame.max(axis=0)
    centre, extent = 0.5 * (lo_box + hi_box), hi_box - lo_box
    if three_d:
        distance = 2.5 * np.linalg.norm(extent)
        view.CameraFocalPoint = list(centre)
        view.CameraPosition = list(centre + distance * np.array([0.45, -0.75, 0.5]))
        view.CameraViewUp = [0.0, 0.0, 1.0]
        view.CameraViewAngle = 30.0
    else:
        aspect = args.size[0] / args.size[1]
        view.CameraParallelProjection = 1
        view.CameraFocalPoint = [centre[0], centre[1], 0.0]
        view.CameraPosition = [centre[0], centre[1], 1.0 + np.linalg.norm(extent)]
        view.CameraViewUp = [0.0, 1.0, 0.0]
        view.CameraParallelScale = 0.6 * max(extent[1], extent[0] / aspect)
    if data.GetNumberOfCells() > 5000 and not args.zoom_contact:
        display.SetRepresentationType("Surface")  # edges of a fine mesh hide the colours
    simple.Render(view)
    simple.SaveScreenshot(args.png, view, ImageResolution=args.size)
    print("render_result: %s (%s at t = %g, displacements x %.3g)" % (args.png, args.field, time, scale))


if __name__ == "__main__":
    main()
