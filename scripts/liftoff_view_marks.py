"""Where a run's loads, sensors, probes and joints are, as flat shapes on
the full plate, for scripts/liftoff_view.py (plain Python: no ParaView).

Positions come from the run's outputs: a moving load's point at each step
from history.csv (its columns NAME_x, NAME_y, written by the run from its
own path), the probes from history.csv's column names, the plate's extent
from the field files (passed in); the shapes that do not move (a standing
load's position, a patch's size, a vehicle's wheel offsets, a
deflectometer's sensor offsets) from used_parameters.prm. Every length is
in the files' units (the scene's: metres in an SI scene).

A mark is (kind, points): "arrow" (a point load: one point, where it acts),
"outline" (a patch or tyre: a closed polygon), "line" (a line load, a
joint), "path" (where a moving load went: a polyline, drawn dashed), "heading"
(a chevron at the path's end on the plate, the way it went),
"sensor", "probe" (one point each).
"""

import csv
import math
import re

# The SHRP sensor set, a deflectometer's default in an SI scene (m).
SHRP_OFFSETS = [0, 0.203, 0.305, 0.457, 0.610, 0.914, 1.219, 1.524]
EDGES = {"Left": (0, 2, 0, 3), "Right": (1, 2, 1, 3),
         "Bottom": (0, 2, 1, 2), "Top": (0, 3, 1, 3)}


def numbers(text, separator=","):
    """'0.1, 0.2' as [0.1, 0.2]; None if a piece is not a number (a
    formula: the run's history.csv then gives where it is)."""
    try:
        return [float(v) for v in text.replace(";", separator).split(
            separator) if v.strip()]
    except ValueError:
        return None


class History:
    """history.csv: its rows by tau and the names of its columns."""

    def __init__(self, path):
        with open(path) as f:
            rows = list(csv.reader(f))
        self.header = [h.split(" [")[0] for h in rows[0]]
        # An empty cell: a joint's load transfer with the load far.
        self.rows = [[float(v) if v else math.nan for v in r]
                     for r in rows[1:] if r]

    def column(self, name):
        return self.header.index(name) if name in self.header else None

    def track(self, name):
        """A moving load's (x, y) at every step, or None."""
        ix, iy = self.column(name + "_x"), self.column(name + "_y")
        if ix is None or iy is None:
            return None
        return [(r[0], r[ix], r[iy]) for r in self.rows]

    def probes(self):
        return [(float(m.group(1)), float(m.group(2))) for m in
                (re.match(r"w\(([^;]+);([^)]+)\)$", h) for h in self.header)
                if m]


def inside(plate, x, y):
    return plate[0] <= x <= plate[1] and plate[2] <= y <= plate[3]


def at_time(track, tau):
    """The track's point at the step nearest tau."""
    row = min(track, key=lambda r: abs(r[0] - tau))
    return row[1], row[2]


def patch_outline(centre, shape, size):
    """A disc (size: its diameter) as a 48-gon, a rectangle as 4 corners."""
    x, y = centre
    if shape == "disc":
        r = size[0] / 2
        return [(x + r * math.cos(2 * math.pi * k / 48),
                 y + r * math.sin(2 * math.pi * k / 48)) for k in range(48)]
    a, b = size[0] / 2, size[1] / 2
    return [(x - a, y - b), (x + a, y - b), (x + a, y + b), (x - a, y + b)]


def sections(used, kind):
    """The numbers of the on sections 'Loads/KIND N' (Magnitude or Peak
    force not 0)."""
    found = set()
    for key in used:
        m = re.match(r"Loads/%s (\d+)/" % re.escape(kind), key)
        if m:
            found.add(int(m.group(1)))
    on = []
    for n in sorted(found):
        base = "Loads/%s %d/" % (kind, n)
        force = used.get(base + "Magnitude", used.get(base + "Peak force"))
        if numbers(force or "0") != [0.0]:
            on.append(n)
    return on


def where(used, history, base, name, tau, entry):
    """A load's point at tau: from history.csv if it moves, else its
    entry's numbers."""
    track = history.track(name) if history else None
    if track:
        return at_time(track, tau), track
    point = numbers(used.get(base + entry, ""))
    if not point:
        point = numbers(used.get(base + "Path", ""), ";")
    return (tuple(point[:2]) if point and len(point) >= 2 else None), None


def load_marks(used, history, tau, plate):
    """The marks of the point, patch, line loads and vehicles at tau."""
    marks = []
    for kind, slug in (("Point load", "point_load"), ("Patch load",
                                                     "patch_load"),
                       ("Vehicle", "vehicle"), ("Line load", "line_load")):
        for n in sections(used, kind):
            base, name = "Loads/%s %d/" % (kind, n), "%s_%d" % (slug, n)
            entry = "Position" if kind == "Point load" else "Path"
            point, track = where(used, history, base, name, tau, entry)
            if track:
                on_plate = [(x, y) for _, x, y in track
                            if inside(plate, x, y)]
                marks.append(("path", on_plate))
                marks.extend(heading(on_plate, plate))
            if kind == "Line load":
                marks.extend(line_marks(used, base, point, track, plate))
            elif point is not None:
                marks.extend(shape_marks(used, kind, base, point))
    return marks


def heading(path, plate):
    """A chevron at the end of a path on the plate, pointing the way the
    load went; none for a path that does not move there."""
    if len(path) < 2:
        return []
    (x0, y0), (x1, y1) = path[-2], path[-1]
    norm = math.hypot(x1 - x0, y1 - y0)
    if norm == 0:
        return []
    size = 0.04 * (plate[1] - plate[0])
    ux, uy = (x1 - x0) / norm, (y1 - y0) / norm
    back = [(x1 - size * (ux - s * uy), y1 - size * (uy + s * ux))
            for s in (0.6, -0.6)]
    return [("heading", [back[0], (x1, y1), back[1]])]


def shape_marks(used, kind, base, point):
    x, y = point
    if kind == "Point load":
        return [("arrow", [point])]
    if kind == "Patch load":
        return [("outline", patch_outline(point, used[base + "Shape"],
                                          numbers(used[base + "Size"])))]
    wheels = numbers(used.get(base + "Wheels", "0, 0, 1"), ",") or []
    offsets = [(wheels[i], wheels[i + 1]) for i in range(0, len(wheels), 3)]
    if used.get(base + "Wheel shape", "point") == "point":
        return [("arrow", [(x + dx, y + dy)]) for dx, dy in offsets]
    size = numbers(used[base + "Wheel size"])
    return [("outline", patch_outline((x + dx, y + dy),
                                      used[base + "Wheel shape"], size))
            for dx, dy in offsets]


def line_marks(used, base, point, track, plate):
    segment = numbers(used.get(base + "Segment", ""))
    if segment and len(segment) == 4:
        dx, dy = point if track else (0, 0)
        return [("line", [(segment[0] + dx, segment[1] + dy),
                          (segment[2] + dx, segment[3] + dy)])]
    i, j, k, m = EDGES.get(used.get(base + "Edge", "Right"), EDGES["Right"])
    return [("line", [(plate[i], plate[j]), (plate[k], plate[m])])]


def instrument_marks(used, history, plate):
    """Deflectometer plates and sensors, probes, joints."""
    marks = []
    si = used.get("Units/System") == "SI"
    for n in sections(used, "Deflectometer"):
        base = "Loads/Deflectometer %d/" % n
        x, y = numbers(used[base + "Position"])
        diameter = float(used[base + "Plate diameter"])
        marks.append(("outline", patch_outline((x, y), "disc",
                                               [diameter])))
        offsets = numbers(used.get(base + "Sensor offsets", "")) or (
            SHRP_OFFSETS if si else [])
        ux, uy = numbers(used.get(base + "Sensor direction", "1, 0"))
        norm = math.hypot(ux, uy)
        marks.extend(("sensor", [(x + d * ux / norm, y + d * uy / norm)])
                     for d in offsets)
    if history:
        marks.extend(("probe", [p]) for p in history.probes())
    x0, x1, y0, y1 = plate
    for axis, count in (("x", "Slabs/Slabs along x"),
                        ("y", "Slabs/Slabs along y")):
        n = int(used.get(count, "1"))
        for k in range(1, n):
            if axis == "x":
                c = x0 + k * (x1 - x0) / n
                marks.append(("line", [(c, y0), (c, y1)]))
            else:
                c = y0 + k * (y1 - y0) / n
                marks.append(("line", [(x0, c), (x1, c)]))
    return marks


def scene_marks(used, history, tau, plate):
    """Every mark at tau; `plate` is (x_min, x_max, y_min, y_max) of the
    whole plate as the files draw it."""
    return load_marks(used, history, tau, plate) + instrument_marks(
        used, history, plate)
