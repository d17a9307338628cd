#!/usr/bin/python3
"""Measured peak memory of liftoff against the estimate that refuses scenes
too large for the machine (Discretization::estimate_size, doc/reliability.md).

    /usr/bin/python3 benchmarks/memory_estimate.py build/liftoff [--quick]

Runs a free square plate under a central point force (full model, 2 steps,
no VTU) over meshes, degrees, solvers and rank counts, reads "peak memory
per rank" from summary.txt and prints a markdown table with the estimate,
computed here with the same formula and constants as the C++ code, plus
the ~160 MB a rank holds at start-up (libraries, MPI), which the check does
not count because it is already in use when the check runs.
"""
import math
import pathlib
import subprocess
import sys
import tempfile

# Must equal the constants in source/discretization.cc.
BYTES_PER_CELL, BYTES_PER_DOF, BYTES_PER_ENTRY, BYTES_PER_FACTOR_UNIT = 2550, 170, 88, 120
RANK_IMBALANCE = 1.2
START_UP_MB = 161.5

CASES = [  # ranks, degree, cells per side, refinements, solver type, package
    (1, 1, 32, 0, "direct", "mumps"), (1, 1, 64, 0, "direct", "mumps"),
    (1, 1, 128, 0, "direct", "mumps"), (1, 1, 256, 0, "direct", "mumps"),
    (1, 1, 400, 0, "direct", "mumps"), (1, 2, 16, 0, "direct", "mumps"),
    (1, 2, 32, 0, "direct", "mumps"), (1, 2, 64, 0, "direct", "mumps"),
    (1, 2, 128, 0, "direct", "mumps"), (1, 2, 200, 0, "direct", "mumps"),
    (1, 3, 64, 0, "direct", "mumps"), (1, 3, 128, 0, "direct", "mumps"),
    (1, 1, 64, 0, "cg", "mumps"), (1, 1, 256, 0, "cg", "mumps"),
    (1, 2, 128, 0, "cg", "mumps"), (1, 1, 32, 3, "direct", "mumps"),
    (1, 1, 400, 0, "cg", "mumps"), (1, 3, 64, 0, "cg", "mumps"),
    (1, 2, 200, 0, "cg", "mumps"), (2, 1, 256, 0, "direct", "mumps"),
    (2, 2, 128, 0, "direct", "mumps"), (2, 1, 256, 0, "cg", "mumps"),
    (1, 1, 256, 0, "direct", "klu"), (2, 1, 256, 0, "direct", "klu"),
]
QUICK = [CASES[1], CASES[6], CASES[12]]


def estimate_mb(ranks, p, n, refinements, solver, package):
    nx = n * 2**refinements
    cells = nx * nx
    dofs = 3 * (p * nx + 1) ** 2
    couplings = ((2*p + 1)**2 + 2*(p - 1)*(2*p + 1)*(p + 1) + (p - 1)**2*(p + 1)**2) / p**2
    entries = dofs * 3 * couplings
    shared = BYTES_PER_CELL * cells + BYTES_PER_DOF * dofs + BYTES_PER_ENTRY * entries
    factor = 0 if solver == "cg" else BYTES_PER_FACTOR_UNIT * dofs * math.log2(dofs)
    share = 1 if ranks == 1 or (solver == "direct" and package == "klu") else RANK_IMBALANCE / ranks
    return (shared + factor) * share / 2**20, dofs


def measure(liftoff, work, ranks, p, n, refinements, solver, package):
    name = f"np{ranks}_p{p}_n{n}_r{refinements}_{solver}_{package}"
    scene = work / f"{name}.prm"
    scene.write_text(f"""subsection Discretization
  set Cells along x = {n}
  set Cells along y = {n}
  set Global refinements = {refinements}
  set Polynomial degree = {p}
end
subsection Linear solver
  set Type = {solver}
  set Direct solver package = {package}
end
subsection Loads
  subsection Point load 1
    set Magnitude = 1
  end
end
subsection Time integration
  set Time step = 0.001
  set End time = 0.002
end
subsection Output
  set Directory = {work / name}
  set VTU interval = 0
end
""")
    command = [liftoff, str(scene)]
    if ranks > 1:
        command = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + command
    subprocess.run(command, check=True, capture_output=True)
    for line in (work / name / "summary.txt").read_text().splitlines():
        if line.startswith("peak memory per rank"):
            return float(line.split(":")[1])
    raise RuntimeError(f"{name}: no peak memory in summary.txt")


def main():
    liftoff = str(pathlib.Path(sys.argv[1]).resolve())
    cases = QUICK if "--quick" in sys.argv else CASES
    print("| ranks | p | cells | refinements | solver | unknowns | measured peak [MB] "
          "| start-up + estimate [MB] | deviation |")
    print("|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as directory:
        for case in cases:
            ranks, p, n, refinements, solver, package = case
            estimate, dofs = estimate_mb(*case)
            measured = measure(liftoff, pathlib.Path(directory), *case)
            total = START_UP_MB + estimate
            print(f"| {ranks} | {p} | {n}x{n} | {refinements} | "
                  f"{'cg' if solver == 'cg' else package} | {dofs} | {measured:.0f} | "
                  f"{total:.0f} | {100 * (total / measured - 1):+.0f} % |", flush=True)


if __name__ == "__main__":
    main()
