#!/usr/bin/python3
"""Where a run's start-up goes: the process start, MPI_Init, and the set-up
before the first step of the S scene.

    benchmarks/start_up.py [--executable NEW] [--baseline OLD] [--repeat 5]

Each measurement is the median of --repeat whole processes, the binaries
alternating so that both see the same load. Prints a table and writes it to
benchmarks/start_up.md. Rows:

- `liftoff --version`: the dynamic loading of the libraries deal.II links
  (and, for binaries before the change, a singleton MPI_Init).
- a bare C program that calls MPI_Init and MPI_Finalize, with Open MPI's
  defaults and with the settings liftoff uses for a run started alone
  (pml ob1, btl self, ess_singleton_isolated): the MPI part of the above.
- S to its first step: the S scene (benchmarks/scenes/S-gamma1.prm) ended
  after one step; "before the first step" is the process's wall time less
  the run's own wall time, plus the run's set-up sections (setup, assembly,
  factorisation, initial acceleration) from summary.txt.

CPU times (user + system) are given beside wall times: on a loaded machine
the wall time waits for a core, the CPU time does not.
"""

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from liftoff_runs import parse_summary, scene_with_overrides  # noqa: E402

# What liftoff sets for a run started without a launcher (source/main.cc).
SINGLETON_SETTINGS = {"OMPI_MCA_pml": "ob1", "OMPI_MCA_btl": "self",
                      "OMPI_MCA_ess_singleton_isolated": "1"}
SETUP_SECTIONS = ("setup", "assembly", "factorisation",
                  "initial acceleration")


def timed(command, env=None):
    """Wall and CPU seconds of one process (its children included)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(command, env=env, check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime
                                                - before.ru_stime)
    return wall, cpu


def bare_mpi_init(work):
    source = os.path.join(work, "mpi_init.c")
    with open(source, "w") as f:
        f.write("#include <mpi.h>\nint main(int argc, char **argv)\n"
                "{ MPI_Init(&argc, &argv); MPI_Finalize(); return 0; }\n")
    program = os.path.join(work, "mpi_init")
    subprocess.run(["mpicc", source, "-o", program], check=True)
    return program


def without_singleton_settings():
    env = dict(os.environ)
    for key in SINGLETON_SETTINGS:
        env.pop(key, None)
    return env


def s_to_first_step(executable, work, label):
    """Process wall, CPU, and the wall time before the first step."""
    directory = os.path.join(work, label)
    text = scene_with_overrides(
        os.path.join(HERE, "scenes", "S-gamma1.prm"),
        ["Time integration/End time=5e-4"], directory)
    scene = os.path.join(work, label + ".prm")
    with open(scene, "w") as f:
        f.write(text)
    wall, cpu = timed([executable, "--overwrite", "--quiet", scene])
    values, sections = parse_summary(os.path.join(directory, "summary.txt"))
    own = float(values["wall time [s]"])
    setup = sum(sections.get(s, 0.0) for s in SETUP_SECTIONS)
    return wall, cpu, wall - own + setup


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--executable",
                        default=os.path.join(ROOT, "build", "liftoff"))
    parser.add_argument("--baseline", help="an older liftoff to compare")
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    binaries = [("new", os.path.abspath(args.executable))]
    if args.baseline:
        binaries.insert(0, ("old", os.path.abspath(args.baseline)))

    rows = []
    with tempfile.TemporaryDirectory() as work:
        program = bare_mpi_init(work)
        plain = without_singleton_settings()
        tuned = dict(plain, **SINGLETON_SETTINGS)
        samples = {}
        for _ in range(args.repeat):
            for label, exe in binaries:
                samples.setdefault(("version", label), []).append(
                    timed([exe, "--version"], env=plain))
                samples.setdefault(("S", label), []).append(
                    s_to_first_step(exe, work, label))
            samples.setdefault(("mpi", "Open MPI defaults"), []).append(
                timed([program], env=plain))
            samples.setdefault(("mpi", "liftoff's singleton settings"),
                               []).append(timed([program], env=tuned))
        for (kind, label), values in samples.items():
            medians = [statistics.median(c) for c in zip(*values)]
            name = {"version": "liftoff --version (%s)" % label,
                    "mpi": "bare MPI_Init + MPI_Finalize, %s" % label,
                    "S": "S to its first step (%s)" % label}[kind]
            before_step = "%.3f" % medians[2] if kind == "S" else ""
            rows.append((name, "%.3f" % medians[0], "%.3f" % medians[1],
                         before_step))

    header = ("| what | wall [s] | CPU [s] | before the first step [s] |\n"
              "|---|---|---|---|\n")
    table = header + "".join("| %s | %s | %s | %s |\n" % r for r in rows)
    load = os.getloadavg()[0]
    text = ("# Start-up\n\nMedians of %d processes each, binaries alternating; "
            "load average %.2f at the end (2 cores). Made by "
            "`benchmarks/start_up.py%s`.\n\n%s"
            % (args.repeat, load,
               " --baseline OLD" if args.baseline else "", table))
    print(text)
    with open(os.path.join(HERE, "start_up.md"), "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
