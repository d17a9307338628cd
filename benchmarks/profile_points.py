#!/usr/bin/python3
"""What a profile of many points costs to set up.

Runs one step of a full 100 x 100 Q1 plate (10 000 cells) with a diagonal
profile of N points and without one, with each executable given, and
prints the wall-time difference: the time to locate the points in the mesh
and to write one profile.

    /usr/bin/python3 benchmarks/profile_points.py build/liftoff OLD/liftoff
"""

import argparse
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))), "scripts"))
from liftoff_runs import override_text  # noqa: E402

SCENE = ["Discretization/Cells along x=100",
         "Discretization/Cells along y=100",
         "Discretization/Polynomial degree=1",
         "Loads/Point load 1/Magnitude=1",
         "Time integration/Time step=1e-3",
         "Time integration/End time=1e-3",
         "Output/VTU interval=0",
         "Output/Profile start=-0.5, -0.5",
         "Output/Profile end=0.5, 0.5",
         "Output/Profile times=1e-3"]


def wall_time(executable, n_points, ranks):
    with tempfile.TemporaryDirectory() as folder:
        scene = override_text(SCENE + [
            "Output/Directory=" + folder + "/out",
            "Output/Profile points=%d" % n_points])
        command = [executable, "-"]
        if ranks > 1:
            command = ["mpirun", "--allow-run-as-root", "--oversubscribe",
                       "-np", str(ranks)] + command
        start = time.monotonic()
        subprocess.run(command, input=scene, text=True, check=True,
                       stdout=subprocess.DEVNULL)
        return time.monotonic() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("executables", nargs="+")
    parser.add_argument("--points", type=int, default=100000)
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    print("executable,ranks,points,with profile [s],without [s],profile [s]")
    for executable in args.executables:
        # The fastest of a few runs: the machine is shared.
        with_profile = min(wall_time(executable, args.points, args.ranks)
                           for _ in range(args.repeat))
        without = min(wall_time(executable, 0, args.ranks)
                      for _ in range(args.repeat))
        print(f"{executable},{args.ranks},{args.points},{with_profile:.2f},"
              f"{without:.2f},{with_profile - without:.2f}")


if __name__ == "__main__":
    main()
