"""The arrows of the point loads drawn where the scene puts them: for each
row of PICTURES/loads.csv (the load's point on the warped plate and where
the camera projects it), the picture holds the arrow's colour within 2
pixels of that spot, and none 12 pixels below it (the arrow comes from
above: its tip ends there). Prints one line per arrow; exit 1 if one is
astray, or if there is none.
    arrow_pixels.py PICTURES"""
import csv
import os
import sys

from PIL import Image


def magenta(pixel):
    r, g, b = pixel[:3]
    return r > 200 and g < 90 and b > 200


def near(image, column, row, radius):
    return any(magenta(image.getpixel((c, r)))
               for c in range(column - radius, column + radius + 1)
               for r in range(row - radius, row + radius + 1)
               if 0 <= c < image.width and 0 <= r < image.height)


folder = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(folder, "loads.csv"))))
bad = 0
for row in rows:
    image = Image.open(os.path.join(folder, row["picture"])).convert("RGB")
    column, line = round(float(row["column"])), round(float(row["row"]))
    at_tip = near(image, column, line, 2)
    below = near(image, column, line + 12, 2)
    ok = at_tip and not below
    bad += not ok
    print("%s arrow at (%s, %s) -> pixel (%d, %d): tip %s, below %s: %s" % (
        row["picture"], row["x"], row["y"], column, line, at_tip, below,
        "ok" if ok else "ASTRAY"))
sys.exit(1 if bad or not rows else 0)
