#!/usr/bin/python3
"""Measured peak memory of liftoff against the estimate that refuses scenes
too large for the machine (MemoryEstimate, doc/reliability.md).

    /usr/bin/python3 benchmarks/memory_estimate.py build/liftoff [--quick] [--fit]

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

# Must equal the constants in source/fem/discretization.cc.
BYTES_PER_CELL, BYTES_PER_DOF, BYTES_PER_ENTRY = 510, 1480, 33
# Per N log2(N) of a symmetric (Cholesky) and of an LU factor.
BYTES_PER_FACTOR_UNIT = {"cholesky": 32, "lu": 113}
RANK_IMBALANCE = 1.2
START_UP_MB = 161.5

# ranks, degree, cells per side, refinements, solver type, package. The
# default package is CHOLMOD's Cholesky factor on one rank and MUMPS's on
# several.
CASES = [
    (1, 1, 64, 0, "direct", "cholmod"), (1, 1, 128, 0, "direct", "cholmod"),
    (1, 1, 256, 0, "direct", "cholmod"), (1, 1, 400, 0, "direct", "cholmod"),
    (1, 2, 32, 0, "direct", "cholmod"), (1, 2, 64, 0, "direct", "cholmod"),
    (1, 2, 128, 0, "direct", "cholmod"), (1, 2, 200, 0, "direct", "cholmod"),
    (1, 3, 64, 0, "direct", "cholmod"), (1, 3, 128, 0, "direct", "cholmod"),
    (1, 1, 32, 3, "direct", "cholmod"),
    (1, 1, 64, 0, "cg", "cholmod"), (1, 1, 256, 0, "cg", "cholmod"),
    (1, 1, 400, 0, "cg", "cholmod"), (1, 2, 128, 0, "cg", "cholmod"),
    (1, 2, 200, 0, "cg", "cholmod"), (1, 3, 64, 0, "cg", "cholmod"),
    (1, 1, 256, 0, "direct", "mumps lu"), (1, 2, 128, 0, "direct", "mumps lu"),
    (1, 1, 400, 0, "direct", "mumps lu"),
    (1, 1, 256, 0, "direct", "mumps"),
    (1, 1, 256, 0, "direct", "klu"),
    (2, 1, 256, 0, "direct", "cholmod"), (2, 2, 128, 0, "direct", "cholmod"),
    (2, 1, 256, 0, "direct", "mumps lu"), (2, 1, 256, 0, "cg", "cholmod"),
    (2, 1, 256, 0, "direct", "klu"),
]
QUICK = [CASES[0], CASES[5], CASES[11]]


def factor_kind(solver, package):
    """The factor the estimate charges: none, a Cholesky or an LU factor."""
    if solver == "cg":
        return None
    return "lu" if package in ("mumps lu", "klu") else "cholesky"


def counts(p, n, refinements):
    nx = n * 2**refinements
    cells = nx * nx
    dofs = 3 * (p * nx + 1) ** 2
    couplings = ((2*p + 1)**2 + 2*(p - 1)*(2*p + 1)*(p + 1) + (p - 1)**2*(p + 1)**2) / p**2
    return cells, dofs, dofs * 3 * couplings


def estimate_mb(ranks, p, n, refinements, solver, package):
    cells, dofs, entries = counts(p, n, refinements)
    shared = BYTES_PER_CELL * cells + BYTES_PER_DOF * dofs + BYTES_PER_ENTRY * entries
    kind = factor_kind(solver, package)
    factor = 0 if kind is None else BYTES_PER_FACTOR_UNIT[kind] * dofs * math.log2(dofs)
    share = 1 if ranks == 1 or package == "klu" and kind else RANK_IMBALANCE / ranks
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
    one_rank = []
    with tempfile.TemporaryDirectory() as directory:
        for case in cases:
            ranks, p, n, refinements, solver, package = case
            estimate, dofs = estimate_mb(*case)
            measured = measure(liftoff, pathlib.Path(directory), *case)
            total = START_UP_MB + estimate
            print(f"| {ranks} | {p} | {n}x{n} | {refinements} | "
                  f"{'cg' if solver == 'cg' else package} | {dofs} | {measured:.0f} | "
                  f"{total:.0f} | {100 * (total / measured - 1):+.0f} % |", flush=True)
            if ranks == 1:
                one_rank.append((case, measured))
    if "--fit" in sys.argv:
        fit(one_rank)


def fit(runs):
    """Least squares of the one-rank peaks (less start-up) in relative
    terms, so small and large scenes weigh alike: bytes per cell, unknown,
    matrix entry, and per N log2 N of a Cholesky and of an LU factor."""
    import numpy
    rows, targets = [], []
    for (ranks, p, n, refinements, solver, package), measured in runs:
        cells, dofs, entries = counts(p, n, refinements)
        kind = factor_kind(solver, package)
        unit = dofs * math.log2(dofs)
        row = [cells, dofs, entries, unit if kind == "cholesky" else 0,
               unit if kind == "lu" else 0]
        target = (measured - START_UP_MB) * 2**20
        rows.append([x / target for x in row])
        targets.append(1.0)
    constants, *_ = numpy.linalg.lstsq(numpy.array(rows), numpy.array(targets), rcond=None)
    print("fit: bytes per cell, unknown, matrix entry, Cholesky and LU factor unit:",
          " ".join(f"{c:.0f}" for c in constants))


if __name__ == "__main__":
    main()
