"""The standard view of a liftoff run, one picture per output time.

    scripts/liftoff-view OUTPUT_DIRECTORY [--pictures FOLDER] [--scale S]
                         [--field NAME]

(scripts/liftoff-view runs this file with ParaView's pvpython, under
xvfb-run when there is no display.) Reads OUTPUT_DIRECTORY/solution.pvd and
used_parameters.prm (a run of a scene in SI units has its files in m, s,
Pa, ...: the colour bar names the field's unit, the label the time in s),
reflects a half or quarter model into the whole plate,
warps it by the deflection (w > 0 is into the foundation, drawn downwards)
and colours it by the contact status (the fraction of each cell's Gauss
points in contact: 1 in contact, 0 lifted off). Writes
FOLDER/view_NNNNN.png (default OUTPUT_DIRECTORY/pictures), one per output
time, and view.csv there: per picture tau, the largest w, the bounds of
the warped plate, the range of the field and its unit, which
tests/command_line/liftoff_view.sh checks. `--field` colours by any field
of the files (M_xx, sigma_max, ...); fields that change sign under a
reflection (Q_x, Q_y, M_xy, sigma_xy, M_1_angle) get that sign on the
reflected parts.
"""

import argparse
import math
import os
import re
import sys
from types import SimpleNamespace

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liftoff_runs import used_parameters  # noqa: E402
import liftoff_view_marks as marks_of  # noqa: E402
import liftoff_view_draw as draw  # noqa: E402

import paraview.simple as pv  # noqa: E402


def whole_plate(source, symmetry):
    """The modelled part reflected into the whole plate: about x = 0 for a
    half model (x >= 0), then about y = 0 for a quarter (x, y >= 0)."""
    planes = {"full": [], "half": ["X"], "quarter": ["X", "Y"]}[symmetry]
    for plane in planes:
        source = pv.Reflect(Input=source, Plane=plane, Center=0.0,
                            CopyInput=1)
    return pv.MergeBlocks(Input=source) if planes else source


# Fields that change sign under a reflection: across the plane x = 0 ("X")
# or y = 0 ("Y"). A reflected copy holds the modelled part's values, so
# these get the sign of the reflection (doc/model.md, "Probes, extremes and
# envelopes").
ODD_FIELDS = {"Q_x": "X", "Q_y": "Y", "M_xy": "XY", "sigma_xy": "XY",
              "M_1_angle": "XY"}


def with_reflection_signs(plate, field, symmetry, factor=1.0):
    """The plate and the name of the array to draw: `field` times `factor`
    (an SI field in engineering units), with the signs of the reflections
    applied where the field is odd under them."""
    planes = {"full": "", "half": "X", "quarter": "XY"}[symmetry]
    axes = [a for a in ODD_FIELDS.get(field, "") if a in planes]
    if not axes and factor == 1.0:
        return plate, field
    terms = ["sign(coords%s)" % a for a in axes]
    if factor != 1.0:
        terms.append("%.17g" % factor)
    name = field + (" (whole plate)" if axes else " (drawn)")
    return pv.Calculator(Input=plate, ResultArrayName=name,
                         Function="*".join([field] + terms)), name


def field_unit(directory, field):
    """The unit the files give `field` (their `units` attribute: "m" in a
    scene in SI units, "F0*L^2/D" in a dimensionless one), or ""."""
    pvd = open(os.path.join(directory, "solution.pvd")).read()
    first = re.search(r'file="([^"]+)"', pvd)
    if not first:
        return ""
    record = open(os.path.join(directory, first.group(1))).read()
    unit = re.search(r'Name="%s"[^>]*units="([^"]*)"' % re.escape(field),
                     record)
    return unit.group(1) if unit else ""


def largest_deflection(source, times):
    """max |w| over every output time."""
    largest = 0.0
    for t in times:
        source.UpdatePipeline(t)
        low, high = source.PointData["w"].GetRange()
        largest = max(largest, abs(low), abs(high))
    return largest


def field_range(source, field, times):
    """The range of `field` over every output time."""
    low, high = float("inf"), -float("inf")
    for t in times:
        source.UpdatePipeline(t)
        a, b = source.PointData[field].GetRange()
        low, high = min(low, a), max(high, b)
    return low, high


def arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("directory", help="a run's Output/Directory")
    parser.add_argument("--pictures", help="folder for the pictures "
                        "(default: DIRECTORY/pictures)")
    parser.add_argument("--scale", type=float,
                        help="drawn z per unit of w (default: the largest "
                        "|w| over the run drawn as 0.15 of the plate's "
                        "length)")
    parser.add_argument("--size", default="1000,600",
                        help="picture size in pixels, width,height")
    parser.add_argument("--field", default="contact_status",
                        help="the point or cell field that colours the "
                        "plate (default contact_status; refinement_level "
                        "shows an adaptive mesh)")
    parser.add_argument("--top", action="store_true",
                        help="a top view of the flat plate with the "
                        "outline of the contact zone")
    parser.add_argument("--animation", action="store_true",
                        help="also FOLDER/view.gif: the pictures in turn, "
                        "0.2 s each")
    parser.add_argument("--no-loads", action="store_true",
                        help="draw the plate alone, without the loads, "
                        "sensors, probes and joints")
    return parser.parse_args()


def open_run(args):
    """The reader, its times, the run's parameters and history."""
    pvd = os.path.join(args.directory, "solution.pvd")
    if not os.path.exists(pvd):
        sys.exit("liftoff-view: error: %s does not exist (set Output/VTU "
                 "interval > 0)" % pvd)
    reader = pv.PVDReader(FileName=pvd)
    fields = list(reader.PointData.keys())
    if args.field not in fields:
        sys.exit("liftoff-view: error: --field %s: the files have no such "
                 "field; they have %s" % (args.field, ", ".join(fields)))
    history = os.path.join(args.directory, "history.csv")
    history = marks_of.History(history) if os.path.exists(history) else None
    return (reader, list(reader.TimestepValues) or [0.0],
            used_parameters(args.directory), history)


def colour_scale(view, display, plate, field, times, args, unit):
    """The colour map and bar: the field's range over the run rounded, its
    title with the unit drawn; returns the range."""
    pv.ColorBy(display, ("POINTS", field))
    lut = pv.GetColorTransferFunction(field)
    lut.ApplyPreset("Cool to Warm", True)
    if args.field == "contact_status":
        low, high = 0.0, 1.0
        title = "contact (fraction of Gauss points)"
    else:
        low, high = draw.rounded_range(*field_range(plate, field, times))
        title = args.field + (" [%s]" % unit if unit else "")
    lut.RescaleTransferFunction(low, high)
    lut.AutomaticRescaleRangeMode = "Never"
    bar = pv.GetScalarBar(lut, view)
    bar.Title = title
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    bar.RangeLabelFormat = "%-#.3g"
    bar.LabelFormat = "%-#.3g"
    display.SetScalarBarVisibility(view, True)


def place_camera(view, top, bounds):
    """A view from the front right and above, or from above; the plate
    filling the picture: its box's corners, projected, centred and spanning
    0.8 of the width or height (three rounds of pan and zoom)."""
    if top:
        view.CameraPosition = [0, 0, 10]
        view.CameraViewUp = [0, 1, 0]
        view.CameraParallelProjection = 1
    else:
        view.CameraPosition = [1.3, -1.6, 1.0]
        view.CameraViewUp = [0, 0, 1]
    view.CameraFocalPoint = [0, 0, 0]
    view.ResetCamera(*bounds)
    camera = view.GetActiveCamera()
    width, height = view.ViewSize
    corners = [(x, y, z) for x in bounds[0:2] for y in bounds[2:4]
               for z in bounds[4:6]]
    for _ in range(3):
        pv.Render(view)
        pixels = [draw.pixel_of(view, c) for c in corners]
        columns, rows = [p[0] for p in pixels], [p[1] for p in pixels]
        # Pan: the box's centre in the picture's centre (world units per
        # pixel at the focal point from the view angle or parallel scale).
        span = (2 * camera.GetParallelScale() if top else 2 * camera
                .GetDistance() * math.tan(math.radians(
                    camera.GetViewAngle() / 2)))
        per_pixel = span / height
        dx = (sum(columns) / len(columns) - width / 2) * per_pixel
        dy = (height / 2 - sum(rows) / len(rows)) * per_pixel
        right = _cross(camera.GetDirectionOfProjection(),
                       camera.GetViewUp())
        shift = [dx * r + dy * u for r, u in zip(right, camera.GetViewUp())]
        camera.SetFocalPoint(*[f + d for f, d in zip(camera.GetFocalPoint(),
                                                     shift)])
        camera.SetPosition(*[p + d for p, d in zip(camera.GetPosition(),
                                                   shift)])
        zoom = (0.72 if top else 0.8) * min(width / (max(columns) - min(columns)),
                         height / (max(rows) - min(rows)))
        camera.Zoom(zoom) if top else camera.Dolly(zoom)


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def contact_outline(view, plate, lift, times):
    """The line between contact and lift-off: where the uplift (g - w)^+,
    continuous unlike the cells' contact status, leaves 0 (1e-3 of its
    largest value over the run)."""
    high = field_range(plate, "uplift", times)[1]
    contour = pv.Contour(Input=plate, ContourBy=["POINTS", "uplift"],
                         Isosurfaces=[1e-3 * high if high > 0 else 1e300])
    raised = pv.Transform(Input=contour)
    raised.Transform.Translate = [0, 0, lift]
    shown = pv.Show(raised, view)
    shown.ColorArrayName = ["POINTS", ""]
    shown.AmbientColor = shown.DiffuseColor = [0, 0, 0]
    shown.LineWidth = 3.0


def make_view(args):
    try:
        width, height = (int(v) for v in args.size.split(","))
    except ValueError:
        sys.exit("liftoff-view: error: --size %s: give width,height in "
                 "pixels (e.g. 1000,600)" % args.size)
    if width < 50 or height < 50:
        sys.exit("liftoff-view: error: --size %s: at least 50,50 pixels"
                 % args.size)
    view = pv.CreateView("RenderView")
    view.ViewSize = [width, height]
    view.OrientationAxesVisibility = 1
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    return view


def build_pipeline(args):
    """The run's plate reflected, coloured and warped, with what the
    pictures need to know about it."""
    reader, times, used, history = open_run(args)
    run = SimpleNamespace(times=times, used=used, history=history)
    symmetry = used.get("Discretization/Symmetry", "full")
    plate = whole_plate(reader, symmetry)
    largest = largest_deflection(plate, times)
    # The plate's length is 1 in a dimensionless scene, metres in SI.
    plate.UpdatePipeline(times[0])
    run.extent = plate.GetDataInformation().GetBounds()[0:4]
    run.length = run.extent[1] - run.extent[0]
    scale = args.scale or (0.15 * run.length / largest if largest > 0
                           else 1.0)
    run.si = used.get("Units/System") == "SI"
    # z = -scale w: w > 0 is into the foundation, which lies below the
    # plate. Outputs of liftoff before the displacement vector are warped
    # by one made from w.
    if "displacement" in reader.PointData.keys():
        run.vector = "displacement"
    else:
        plate = pv.Calculator(Input=plate, ResultArrayName="w_vector",
                              Function="w*kHat")
        run.vector = "w_vector"
    run.unit = field_unit(args.directory, args.field)
    factor = 1.0
    if run.si and args.field != "contact_status":
        raw = field_range(plate, args.field, times)
        factor, run.unit = draw.engineering_unit(run.unit,
                                                 max(map(abs, raw)))
    run.coloured, run.field = with_reflection_signs(plate, args.field,
                                                    symmetry, factor)
    run.plate, run.has_uplift = plate, "uplift" in reader.PointData.keys()
    run.scale = 0.0 if args.top else scale
    run.warped = pv.WarpByVector(Input=run.coloured,
                                 Vectors=["POINTS", run.vector],
                                 ScaleFactor=-run.scale)
    return run


def time_label(view, run, directory):
    """The text in the upper left corner."""
    label = pv.Text(Text="")
    shown = pv.Show(label, view)
    shown.Color = [0, 0, 0]
    shown.WindowLocation = "Upper Left Corner"
    shown.FontSize = 14
    w_factor, w_unit = (1e3, " mm") if run.si else (1.0, "")
    name = os.path.basename(os.path.normpath(directory))

    def at(t, max_w):
        label.Text = ("%s   %s = %.5g%s   max w = %.3g%s   w drawn x %.3g,"
                      " down" % (name, "t" if run.si else "tau", t,
                                 " s" if run.si else "", w_factor * max_w,
                                 w_unit, run.scale))
    return at


def draw_pictures(args, run, view, pictures):
    """One picture per output time; returns the rows of view.csv and
    loads.csv and the pictures' paths."""
    display = pv.Show(run.warped, view)
    colour_scale(view, display, run.coloured, run.field, run.times, args,
                 run.unit)
    if args.top and run.has_uplift:
        contact_outline(view, run.warped, 0.005 * run.length, run.times)
    layer = None if args.no_loads else draw.MarkLayer(view, run.extent)
    label = time_label(view, run, args.directory)
    rows = ["picture,tau,max_w,x_min,x_max,y_min,y_max,z_min,z_max,"
            "field_min,field_max,field_unit"]
    load_rows = ["picture,mark,x,y,z,column,row"]
    pngs = []
    for k, t in enumerate(run.times):
        view.ViewTime = t
        run.warped.UpdatePipeline(t)
        run.plate.UpdatePipeline(t)
        max_w = run.plate.PointData["w"].GetRange()[1]
        label(t, max_w)
        tips = layer.update(marks_of.scene_marks(
            run.used, run.history, t, run.extent), run.plate, run.vector,
            run.scale) if layer else []
        if k == 0:
            place_camera(view, args.top,
                         run.warped.GetDataInformation().GetBounds())
        name = "view_%05d.png" % k
        pngs.append(os.path.join(pictures, name))
        pv.Render(view)
        pv.SaveScreenshot(pngs[-1], view, ImageResolution=view.ViewSize)
        for tip in tips:
            load_rows.append("%s,arrow,%.9g,%.9g,%.9g,%.2f,%.2f" % (
                (name,) + tuple(tip) + draw.pixel_of(view, tip)))
        bounds = run.warped.GetDataInformation().GetBounds()
        run.coloured.UpdatePipeline(t)
        rows.append("%s,%.17g,%.17g,%s,%s" % (name, t, max_w, ",".join(
            "%.17g" % b for b in bounds + run.coloured.PointData[run.field]
            .GetRange()), run.unit))
    return rows, load_rows, pngs


def main():
    args = arguments()
    view = make_view(args)
    run = build_pipeline(args)
    pictures = args.pictures or os.path.join(args.directory, "pictures")
    os.makedirs(pictures, exist_ok=True)
    rows, load_rows, pngs = draw_pictures(args, run, view, pictures)
    for name, lines in (("view.csv", rows), ("loads.csv", load_rows)):
        with open(os.path.join(pictures, name), "w") as f:
            f.write("\n".join(lines) + "\n")
    if args.animation:
        draw.write_gif(pngs, os.path.join(pictures, "view.gif"))
    print("liftoff-view: %d picture(s) in %s, warped by %s%s"
          % (len(run.times), pictures, run.vector,
             ", view.gif" if args.animation else ""))


if __name__ == "__main__":
    main()
