#!/usr/bin/env python3
"""The face stresses in the field files against the moments in the same
files: with `Face stress fields`, each point of a .vtu piece carries
sigma_1_bottom, the largest principal stress at the bed-side face, and
sigma_1_top at the face away from the bed. Without a temperature profile
the bending stress at the bed-side face is 6 M / H^2 and at the other face
-6 M / H^2 (doc/model.md, "Moments, shear forces and stresses"), so

    sigma_1_bottom = 6 / H^2 * lambda_max(M),
    sigma_1_top    = -6 / H^2 * lambda_min(M),

lambda the eigenvalues of the moment tensor [[M_xx, M_xy], [M_xy, M_yy]]
written beside them, with H each slab's own thickness. Checked on an SI
scene (Pa against N m/m) of two slabs of 0.25 and 0.20 m under a wheel
crossing the joint, at every point of every piece off the joint, to 1e-5
of the largest stress (the ASCII files keep about 7 digits); and the
fields' units.

    face_stress_fields.py LIFTOFF
"""

import glob
import os
import sys
import tempfile

import meshio
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import run_scene_or_fail, scene_text  # noqa: E402

LIFTOFF = os.path.abspath(sys.argv[1])
THICKNESSES = (0.25, 0.20)   # slab 1 at x < 0, slab 2 at x > 0


def main():
    text = scene_text(
        {"Units": {"System": "SI", "Length": 4, "Width": 2,
                   "Thickness": THICKNESSES[0], "Young's modulus": 30e9,
                   "Density": 2400, "Subgrade modulus": 50e6},
         "Plate": {"Poisson ratio": 0.15},
         "Discretization": {"Cells along x": 8, "Cells along y": 4,
                            "Polynomial degree": 2},
         "Slabs": {"Slabs along x": 2,
                   "Thicknesses": ", ".join(map(str, THICKNESSES)),
                   "Shear stiffness": 5e8},
         "Loads": {"Patch load 1": {"Shape": "disc", "Size": 0.3,
                                    "Magnitude": 0.7e6,
                                    "Path": "-1 + 20*t; 0.3"}},
         "Time integration": {"Time step": 2e-3, "End time": 0.1},
         "Output": {"VTU interval": 25, "Face stress fields": "true"}})
    with tempfile.TemporaryDirectory() as work:
        folder = run_scene_or_fail(LIFTOFF, work, "faces", text)
        pieces = sorted(glob.glob(os.path.join(folder, "*.vtu")))
        check(len(pieces) >= 2, f"{len(pieces)} field files written")
        worst, largest, n_points = 0.0, 0.0, 0
        for piece in pieces:
            mesh = meshio.read(piece)
            data = mesh.point_data
            x = mesh.points[:, 0]
            off_joint = np.abs(x) > 1e-9
            h = np.where(x < 0, *THICKNESSES)[off_joint]
            m = np.stack([data[k][off_joint] for k in ("M_xx", "M_yy", "M_xy")])
            mean = 0.5 * (m[0] + m[1])
            radius = np.hypot(0.5 * (m[0] - m[1]), m[2])
            bottom = 6 / h ** 2 * (mean + radius)
            top = -6 / h ** 2 * (mean - radius)
            for name, expected in (("sigma_1_bottom", bottom),
                                   ("sigma_1_top", top)):
                written = data[name][off_joint]
                worst = max(worst, np.max(np.abs(written - expected)))
                largest = max(largest, np.max(np.abs(expected)))
            n_points += int(off_joint.sum())
        check(largest > 1e5, f"the largest face stress is {largest:.4g} Pa "
              "(the wheel bends the slabs)")
        check(worst <= 1e-5 * largest,
              f"sigma_1_bottom, sigma_1_top against 6 lambda(M) / H^2 of "
              f"each slab at {n_points} points: largest difference "
              f"{worst:.2e} Pa, {worst / largest:.1e} of the largest")
        pvtu = sorted(glob.glob(os.path.join(folder, "*.pvtu")))[-1]
        with open(pvtu) as f:
            header = f.read()
        check('Name="sigma_1_top" format="ascii" units="Pa"' in header
              and 'Name="sigma_1_bottom" format="ascii" units="Pa"' in header,
              "sigma_1_top and sigma_1_bottom carry the unit Pa")
    finish()


if __name__ == "__main__":
    main()
