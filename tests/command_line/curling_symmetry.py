#!/usr/bin/env python3
"""The curled slab of prm/si-slab-curling.prm (dT = -15 K, night, on a
tensionless bed with self-weight) modelled as a quarter, a half and the
full plate, and the full plate on 2 ranks: the same deflection at the
probes (centre, corner, edge midpoints) and the same contact fraction.

    curling_symmetry.py LIFTOFF

The meshes are the same cells (the quarter's 8 x 8 cells of the full
plate's 16 x 16), so the answers agree to the active set's and the
solver's tolerance: w within 1e-6 of the largest |w|, the contact fraction
within 1e-9 (measured: 6.5e-13 for the half, 0 for the quarter and 2 ranks;
contact fractions identical, 0.4453).
"""

import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "scripts"))
from liftoff_runs import read_csv, run_scene, scene_with_overrides  # noqa

SCENE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                     "prm", "si-slab-curling.prm")
CASES = (("quarter", 8, 8, 1), ("half", 8, 16, 1), ("full", 16, 16, 1),
         ("full", 16, 16, 2))
COLUMNS = ("w(0;0) [m]", "w(2.25;1.8) [m]", "w(2.25;0) [m]", "w(0;1.8) [m]")


def main(liftoff):
    folder = tempfile.mkdtemp(prefix="curling_symmetry_")
    results = []
    for symmetry, nx, ny, ranks in CASES:
        out = "%s/%s_np%d" % (folder, symmetry, ranks)
        text = scene_with_overrides(SCENE, [
            "Discretization/Symmetry=" + symmetry,
            "Discretization/Cells along x=%d" % nx,
            "Discretization/Cells along y=%d" % ny,
            "Discretization/Polynomial degree=1",
            "Time integration/End time=0.001"], out)
        run_scene(liftoff, text, out, ranks=ranks)
        results.append(read_csv(out + "/history.csv")[-1])
    reference = results[-2]
    scale = max(abs(reference[c]) for c in COLUMNS)
    worst_w = worst_f = 0.0
    for (symmetry, _, _, ranks), row in zip(CASES, results):
        dw = max(abs(row[c] - reference[c]) for c in COLUMNS) / scale
        df = abs(row["contact_fraction"] - reference["contact_fraction"])
        print("%-7s %d rank(s): w differs by %.2e of max |w|, contact "
              "fraction %.6f (full plate %.6f)" % (symmetry, ranks, dw,
              row["contact_fraction"], reference["contact_fraction"]))
        worst_w, worst_f = max(worst_w, dw), max(worst_f, df)
    if worst_w > 1e-6 or worst_f > 1e-9:
        sys.exit("curling_symmetry: the models of the curled slab differ "
                 "(w by %.2e of max |w|, contact fraction by %.2e)"
                 % (worst_w, worst_f))


if __name__ == "__main__":
    main(sys.argv[1])
