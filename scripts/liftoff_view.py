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
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liftoff_runs import used_parameters  # noqa: E402

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


def with_reflection_signs(plate, field, symmetry):
    """The plate and the name of `field` with the signs of the reflections
    applied where the field is odd under them."""
    planes = {"full": "", "half": "X", "quarter": "XY"}[symmetry]
    axes = [a for a in ODD_FIELDS.get(field, "") if a in planes]
    if not axes:
        return plate, field
    factor = "*".join("sign(coords%s)" % a for a in axes)
    name = field + " (whole plate)"
    return pv.Calculator(Input=plate, ResultArrayName=name,
                         Function="%s*%s" % (field, factor)), name


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


def main():
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
    args = parser.parse_args()
    pvd = os.path.join(args.directory, "solution.pvd")
    if not os.path.exists(pvd):
        sys.exit("liftoff-view: error: %s does not exist (set Output/VTU "
                 "interval > 0)" % pvd)
    used = used_parameters(args.directory)
    symmetry = used.get("Discretization/Symmetry", "full")
    pictures = args.pictures or os.path.join(args.directory, "pictures")
    os.makedirs(pictures, exist_ok=True)

    reader = pv.PVDReader(FileName=pvd)
    times = list(reader.TimestepValues) or [0.0]
    fields = list(reader.PointData.keys())
    if args.field not in fields:
        sys.exit("liftoff-view: error: --field %s: the files have no such "
                 "field; they have %s" % (args.field, ", ".join(fields)))
    plate = whole_plate(reader, symmetry)
    largest = largest_deflection(plate, times)
    # The plate's length is 1 in a dimensionless scene, metres in SI.
    plate.UpdatePipeline(times[0])
    x_min, x_max = plate.GetDataInformation().GetBounds()[0:2]
    scale = args.scale or (0.15 * (x_max - x_min) / largest if largest > 0
                           else 1.0)
    si = used.get("Units/System") == "SI"
    # z = -scale w: w > 0 is into the foundation, which lies below the
    # plate. Outputs of liftoff before the displacement vector are warped
    # by one made from w.
    if "displacement" in reader.PointData.keys():
        vector = "displacement"
    else:
        plate = pv.Calculator(Input=plate, ResultArrayName="w_vector",
                              Function="w*kHat")
        vector = "w_vector"
    plate, field = with_reflection_signs(plate, args.field, symmetry)
    warped = pv.WarpByVector(Input=plate, Vectors=["POINTS", vector],
                             ScaleFactor=-scale)

    width, height = (int(v) for v in args.size.split(","))
    view = pv.CreateView("RenderView")
    view.ViewSize = [width, height]
    view.OrientationAxesVisibility = 1
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    warped.UpdatePipeline(times[-1])
    display = pv.Show(warped, view)
    # deal.II writes cell data as point data of each cell's own points.
    pv.ColorBy(display, ("POINTS", field))
    lut = pv.GetColorTransferFunction(field)
    lut.ApplyPreset("Cool to Warm", True)
    if args.field == "contact_status":
        lut.RescaleTransferFunction(0.0, 1.0)
        titles = "contact (fraction of Gauss points)"
    else:
        # The range over every output time, so that all pictures share it.
        low, high = float("inf"), -float("inf")
        for t in times:
            plate.UpdatePipeline(t)
            a, b = plate.PointData[field].GetRange()
            low, high = min(low, a), max(high, b)
        lut.RescaleTransferFunction(low, high if high > low else low + 1)
        titles = field
    unit = field_unit(args.directory, args.field)
    if args.field != "contact_status" and unit:
        titles += " [%s]" % unit
    lut.AutomaticRescaleRangeMode = "Never"
    bar = pv.GetScalarBar(lut, view)
    bar.Title = titles
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    display.SetScalarBarVisibility(view, True)
    label = pv.Text(Text="")
    label_display = pv.Show(label, view)
    label_display.Color = [0, 0, 0]
    label_display.WindowLocation = "Upper Left Corner"

    view.CameraPosition = [1.3, -1.6, 1.0]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 0, 1]
    rows = ["picture,tau,max_w,x_min,x_max,y_min,y_max,z_min,z_max,"
            "field_min,field_max,field_unit"]
    for k, t in enumerate(times):
        view.ViewTime = t
        warped.UpdatePipeline(t)
        label.Text = ("%s   %s = %.5g%s   w drawn x %.3g (down: into the "
                      "foundation)" % (os.path.basename(
                          os.path.normpath(args.directory)),
                          "t" if si else "tau", t, " s" if si else "",
                          scale))
        if k == 0:
            view.ResetCamera()
        name = "view_%05d.png" % k
        pv.SaveScreenshot(os.path.join(pictures, name), view,
                          ImageResolution=[width, height])
        bounds = warped.GetDataInformation().GetBounds()
        plate.UpdatePipeline(t)
        max_w = plate.PointData["w"].GetRange()[1]
        rows.append("%s,%.17g,%.17g,%s,%s" % (name, t, max_w, ",".join(
            "%.17g" % b for b in bounds + plate.PointData[field].GetRange()),
            unit))
    with open(os.path.join(pictures, "view.csv"), "w") as f:
        f.write("\n".join(rows) + "\n")
    print("liftoff-view: %d picture(s) in %s, warped by %s"
          % (len(times), pictures, vector))


if __name__ == "__main__":
    main()
