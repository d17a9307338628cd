"""liftoff processes kept as workers: `liftoff --overwrite --batch -` reads
scene file names on its standard input and answers each with one line
(main.cc's BatchClock: the name, the exit code, the scene's wall and CPU
seconds), so that the start-up of a process (0.3 to 0.5 s, mostly the
dynamic loader binding deal.II's libraries) is paid once per worker rather
than once per run. What liftoff prints while it runs a scene goes to that
run's own log file, as if the scene had been run alone.

A tool makes its runs through one Workers pool: run() takes an idle worker
or starts one (threads that run scenes side by side each get their own),
and gives it back afterwards. A worker that cannot start (an --executable
without `--batch -`, or MPI's start-up failing) leaves the scene to a
process of its own, as before the workers.
"""

import atexit
import os
import re
import subprocess
import threading
import time

from liftoff_runs import run_scene_timed

STARTED = re.compile(r"^liftoff: batch: started, cpu ([0-9.]+) s$")
ENDED = re.compile(r"^liftoff: batch: (.*): exit (-?\d+), wall ([0-9.]+) s, "
                   r"cpu ([0-9.]+) s$")


class Cost:
    """What a run cost: its scene's wall and CPU seconds (in a worker, as
    the worker reports them; alone, its process's) and the start-up of the
    process that ran it (0 when the run was its own process, whose times
    hold it)."""

    def __init__(self, code, wall, cpu, start_up=(0.0, 0.0)):
        self.code, self.wall, self.cpu = code, wall, cpu
        self.start_up_wall, self.start_up_cpu = start_up

    def process_wall(self):
        """What the run would cost as a process of its own: its scene's
        time and the start-up its worker paid once."""
        return self.start_up_wall + self.wall

    def process_cpu(self):
        return self.start_up_cpu + self.cpu


class Worker:
    """One `liftoff --batch -` process, used by one thread at a time."""

    def __init__(self, executable, ranks):
        command = [executable, "--overwrite", "--batch", "-"]
        if ranks > 1:
            command = ["mpirun", "--allow-run-as-root", "--oversubscribe",
                       "-np", str(ranks)] + command
        launch = time.perf_counter()
        self.process = subprocess.Popen(
            command, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT, text=True, errors="replace",
            bufsize=1)
        self.start_up = None
        for line in self.process.stdout:
            found = STARTED.match(line.rstrip("\n"))
            if found:
                self.start_up = (time.perf_counter() - launch,
                                 float(found.group(1)))
                break
        if self.start_up is None:
            self.close()

    def is_alive(self):
        return self.start_up is not None and self.process.poll() is None

    def run(self, prm, log_path):
        """Run the scene file prm; its output into log_path; a Cost."""
        sent = time.perf_counter()
        self.process.stdin.write(prm + "\n")
        self.process.stdin.flush()
        with open(log_path, "w") as log:
            for line in self.process.stdout:
                ended = ENDED.match(line.rstrip("\n"))
                if ended and ended.group(1) == prm:
                    return Cost(int(ended.group(2)), float(ended.group(3)),
                                float(ended.group(4)), self.start_up)
                log.write(line)
        # The process ended inside the scene (killed, crashed): its exit
        # code as a run alone would give it.
        code = self.close()
        self.start_up = None
        return Cost(code, time.perf_counter() - sent, 0.0)

    def close(self):
        """End the worker (at the end of its input) and wait for it."""
        try:
            self.process.stdin.close()
        except OSError:
            pass
        return self.process.wait()


class Workers:
    """The pool of a tool's workers; closed when the tool ends."""

    def __init__(self, executable, ranks=1):
        self.executable, self.ranks = executable, ranks
        self.idle = []
        self.lock = threading.Lock()
        # Whether workers start at all; if not, runs are processes alone.
        self.usable = True
        atexit.register(self.close)

    def take(self):
        """An idle worker, a new one, or None if workers do not start."""
        with self.lock:
            if self.idle:
                return self.idle.pop()
            if not self.usable:
                return None
        # Twice: Open MPI's start-up fails now and then on a loaded machine
        # (liftoff_batch.make, 2 times in 435 runs).
        for attempt in (1, 2):
            worker = Worker(self.executable, self.ranks)
            if worker.is_alive():
                return worker
        with self.lock:
            self.usable = False
        return None

    def run(self, text, directory, log_name="log.txt"):
        """Run the scene text (written to directory/scene.prm) in a worker,
        its output into directory/log_name; a Cost."""
        os.makedirs(directory, exist_ok=True)
        prm = os.path.join(directory, "scene.prm")
        # A line break would end the name early on the worker's input.
        worker = None if "\n" in prm else self.take()
        if worker is None:
            code, wall, cpu = run_scene_timed(self.executable, text,
                                              directory, self.ranks, log_name)
            return Cost(code, wall, cpu)
        with open(prm, "w") as f:
            f.write(text)
        try:
            cost = worker.run(prm, os.path.join(directory, log_name))
        except BaseException:
            worker.close()
            raise
        if worker.is_alive():
            with self.lock:
                self.idle.append(worker)
        return cost

    def close(self):
        """End the idle workers: each ends at the end of its input."""
        with self.lock:
            idle, self.idle = self.idle, []
        for worker in idle:
            worker.close()
