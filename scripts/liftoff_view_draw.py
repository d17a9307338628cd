"""The parts of scripts/liftoff_view.py's pictures beyond the plate: the
marks of the loads and instruments (liftoff_view_marks) drawn on the warped
plate, engineering units for an SI run, a colour bar range rounded to the
field's, where a world point lands in the picture, and a GIF of the frames.
Runs in ParaView's pvpython."""

import math

import paraview.simple as pv
from vtkmodules.vtkCommonCore import vtkPoints, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkProbeFilter
from vtkmodules.vtkFiltersSources import vtkConeSource

# Colours of the marks (0-255), none of them on the cool-to-warm map.
COLOURS = {"arrow": (255, 0, 255), "outline": (0, 0, 0), "line": (0, 0, 0),
           "path": (40, 40, 40), "heading": (40, 40, 40), "sensor": (0, 160, 0),
           "probe": (255, 160, 0), "contact": (0, 0, 0)}

# An SI field's unit as engineers read it: (unit of the files, factor,
# unit drawn); pascals as MPa from 1 MPa up, else kPa.
ENGINEERING = {"m": (1e3, "mm"), "m/s": (1e3, "mm/s"),
               "N m/m": (1e-3, "kN m/m"), "N/m": (1e-3, "kN/m")}


def engineering_unit(unit, largest):
    """(factor, unit) that turn the files' `unit` into an engineer's."""
    if unit == "Pa":
        return (1e-6, "MPa") if largest >= 1e6 else (1e-3, "kPa")
    return ENGINEERING.get(unit, (1.0, unit))


def rounded_range(low, high):
    """[low, high] widened to round numbers: two significant digits of the
    larger end, so that round-off (2.4e-09 for a 0) reads as 0."""
    span = max(abs(low), abs(high))
    if span == 0:
        return 0.0, 1.0
    step = 10 ** (math.floor(math.log10(span)) - 1)
    low, high = math.floor(low / step) * step, math.ceil(high / step) * step
    return (low, high) if high > low else (low, low + step)


def heights(plate, points, vector, scale, extent):
    """z of the warped plate at the flat `points` (x, y): the plate's
    `vector` resampled there, times -scale. A point beyond the plate's box
    (a tyre over the edge) takes the height at the box's nearest point."""
    cloud = vtkPolyData()
    cloud_points = vtkPoints()
    inset = 1e-9 * (extent[1] - extent[0])
    for x, y in points:
        cloud_points.InsertNextPoint(
            min(max(x, extent[0] + inset), extent[1] - inset),
            min(max(y, extent[2] + inset), extent[3] - inset), 0.0)
    cloud.SetPoints(cloud_points)
    # The plate as the pipeline holds it at the current time (pvpython's
    # built-in session: no copy), probed by VTK directly; a ParaView
    # resampling filter per picture cost about 1 s each.
    probe = vtkProbeFilter()
    probe.SetInputData(cloud)
    probe.SetSourceData(plate.GetClientSideObject().GetOutputDataObject(0))
    probe.Update()
    values = probe.GetOutput().GetPointData().GetArray(vector)
    z = [-scale * values.GetTuple(i)[-1] for i in range(len(points))]
    return z


def dashes(points, n_dashes=40):
    """A polyline as n_dashes dashes of equal length, gaps between."""
    lengths = [0.0]
    for a, b in zip(points, points[1:]):
        lengths.append(lengths[-1] + math.hypot(b[0] - a[0], b[1] - a[1]))
    total = lengths[-1]
    if total == 0:
        return []

    def at(s):
        for k in range(1, len(points)):
            if lengths[k] >= s:
                f = (s - lengths[k - 1]) / max(lengths[k] - lengths[k - 1],
                                               1e-300)
                a, b = points[k - 1], points[k]
                return a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])
        return points[-1]
    step = total / n_dashes
    return [[at(k * step), at((k + 0.6) * step)] for k in range(n_dashes)]


class MarkLayer:
    """The marks of one picture as three ParaView sources: lines, points
    and arrow heads, each coloured by its own RGB (no colour map)."""

    def __init__(self, view, extent):
        self.extent = extent
        self.size = extent[1] - extent[0]
        self.sources, self.displays = [], []
        for style in ("lines", "points", "surfaces"):
            source = pv.PVTrivialProducer()
            source.GetClientSideObject().SetOutput(vtkPolyData())
            display = pv.Show(source, view)
            display.MapScalars = 0
            display.Ambient, display.Diffuse = 1.0, 0.0
            if style == "lines":
                display.LineWidth = 3.0
            if style == "points":
                display.PointSize = 12.0
                display.RenderPointsAsSpheres = 1
            self.sources.append(source)
            self.displays.append(display)

    def update(self, marks, plate, vector, scale):
        """Draw `marks` on the plate warped by `vector` times -scale; returns
        the arrow tips in 3D (where the point loads act)."""
        flat = [p for kind, points in marks if kind != "path"
                for p in points]
        paths = [d for kind, points in marks if kind == "path"
                 for d in dashes(points)]
        flat += [p for d in paths for p in d]
        z = iter(heights(plate, flat, vector, scale, self.extent)
                 if flat else [])
        lift = 0.01 * self.size
        lines, points, tips = _Polys(), _Polys(), []
        for kind, shape in [m for m in marks if m[0] != "path"] + [
                ("path", d) for d in paths]:
            where = [(x, y, next(z) + lift) for x, y in shape]
            if kind == "arrow":
                tips.append(where[0])
                top = (where[0][0], where[0][1], where[0][2] + 0.12 *
                       self.size)
                lines.add([where[0], top], COLOURS[kind])
            elif kind in ("sensor", "probe"):
                points.add(where, COLOURS[kind], vertex=True)
            else:
                lines.add(where + (where[:1] if kind == "outline" else []),
                          COLOURS[kind])
        for source, display, data, centring in zip(
                self.sources, self.displays, (lines.data(), points.data(),
                                              self.heads(tips)),
                ("CELLS", "CELLS", "POINTS")):
            source.GetClientSideObject().SetOutput(data)
            source.MarkModified(source)
            if data.GetNumberOfPoints():
                pv.ColorBy(display, (centring, "rgb"))
                display.MapScalars = 0
        return tips

    def heads(self, tips):
        """A cone per arrow whose point is the tip."""
        append = vtkAppendPolyData()
        height = 0.05 * self.size
        for x, y, z in tips:
            cone = vtkConeSource()
            cone.SetResolution(24)
            cone.SetHeight(height)
            cone.SetRadius(0.4 * height)
            cone.SetDirection(0, 0, -1)
            cone.SetCenter(x, y, z + height / 2)
            cone.Update()
            append.AddInputData(_coloured(cone.GetOutput(), COLOURS["arrow"]))
        if not tips:
            return vtkPolyData()
        append.Update()
        return append.GetOutput()


class _Polys:
    """Polylines or vertices with one RGB per cell."""

    def __init__(self):
        self.points, self.cells = vtkPoints(), vtkCellArray()
        self.colours = vtkUnsignedCharArray()
        self.colours.SetNumberOfComponents(3)
        self.colours.SetName("rgb")
        self.vertex = False

    def add(self, where, colour, vertex=False):
        self.vertex = vertex
        for p in where:
            k = self.points.InsertNextPoint(*p)
            if vertex:
                self.cells.InsertNextCell(1, [k])
                self.colours.InsertNextTuple3(*colour)
        if not vertex:
            first = self.points.GetNumberOfPoints() - len(where)
            self.cells.InsertNextCell(len(where), range(first, first + len(
                where)))
            self.colours.InsertNextTuple3(*colour)

    def data(self):
        data = vtkPolyData()
        data.SetPoints(self.points)
        if self.vertex:
            data.SetVerts(self.cells)
        else:
            data.SetLines(self.cells)
        data.GetCellData().SetScalars(self.colours)
        return data


def _coloured(data, colour):
    colours = vtkUnsignedCharArray()
    colours.SetNumberOfComponents(3)
    colours.SetName("rgb")
    for _ in range(data.GetNumberOfPoints()):
        colours.InsertNextTuple3(*colour)
    data.GetPointData().SetScalars(colours)
    return data


def pixel_of(view, point):
    """Where the world `point` lands in the saved picture: (column, row),
    row 0 at the top."""
    renderer = view.GetRenderer()
    renderer.SetWorldPoint(point[0], point[1], point[2], 1.0)
    renderer.WorldToDisplay()
    x, y, _ = renderer.GetDisplayPoint()
    return x, view.ViewSize[1] - 1 - y


def write_gif(pngs, path, seconds_per_frame=0.2):
    """The pictures as one looping GIF (PIL, which matplotlib brings), in
    a palette of 64 colours to keep it small."""
    from PIL import Image
    frames = [Image.open(p).convert("RGB").quantize(64) for p in pngs]
    frames[0].save(path, save_all=True, append_images=frames[1:],
                   duration=int(1000 * seconds_per_frame), loop=0,
                   optimize=True)
