"""A study that stops at a target: scripts/liftoff-study --target TOL climbs
the ladder of its runs one run at a time and stops at the first run whose
estimated error meets TOL.

The error of a run is split by axis (time step, mesh, degree) and the
parts are added. Along one axis, with s the step that refines toward zero
(dtau, h, or 1/p for the degree) and r = s_coarse / s_fine the ratio of the
last two rungs, the part is Richardson's estimate of the finer rung's error

    e = d / (r^k - 1),

d the difference of the last two rungs (liftoff_qoi.difference: the
largest difference over the compared times, relative to the largest
magnitude of the finer rung, or absolute) and k the axis's order:
observed on the axis's last two steps, k = log(d1 / d2) / log(r), where
they join three successive rungs, else the assumed order. The parts are
taken as independent: an axis's part is carried over while other axes are
refined, and its two last steps may lie at different positions on the
other axes.

How sure ("agreement"): where an order is observed, the estimate with it
over the same estimate with the order observed a step earlier on the axis
(four successive rungs), or else with the assumed order. Near 1 the order
has settled (or matches the assumed one); far from 1 the rungs are not yet
in the asymptotic range, or the assumed order is not the axis's. A
difference that does not shrink along an axis (observed order <= 0) gives
no estimate: that axis is refined again.

The climb: first one step along each axis of the ladder (time step, mesh,
degree: two rungs each make an estimate), then, while the estimate exceeds
the target, the next rung along the axis that meets the target at the
least predicted cost, or else gives the largest predicted reduction of the
error per predicted added cost (a step along an axis divides its part by
r^k; a run costs its predecessor's wall time, as the run reports it, times
the ratio measured on the axis's last step).
"""

import csv
import io
import math

from liftoff_qoi import StudyError, difference, magnitude, qoi_values

# The order in which the climb first steps along the axes.
AXES = ("dtau", "h", "p")
NAMES = {"dtau": "time step", "h": "mesh", "p": "degree"}


class LadderOut(StudyError):
    """The ladder ran out before the target; the best estimate is known."""


class Climb:
    """The runs of a product ladder by position, the ones made so far and
    each axis's estimate of the error of the latest run."""

    def __init__(self, runs, qois, options, bring):
        self.grid = {tuple(r["axes"][a] for a in AXES): r for r in runs}
        self.extent = {a: 1 + max(r["axes"][a] for r in runs) for a in AXES}
        self.ladder = [a for a in AXES if self.extent[a] > 1]
        if not self.ladder:
            raise StudyError("--target needs a ladder: --time-steps, "
                             "--refine or --degrees with at least two "
                             "values")
        self.qois = qois
        self.target = options["target"]
        self.absolute = options["absolute"]
        self.assumed = options["assumed_order"]
        # With automatic steps the time axis is Error tolerance, its step
        # tol^(1/3) (scripts/liftoff-study, time_axis).
        self.tolerances = options.get("tolerances", False)
        self.names = dict(NAMES, dtau="tolerance") if self.tolerances \
            else NAMES
        self.bring = bring
        self.made = []
        self.times = None
        self.parts = {}          # axis -> qoi -> estimate (dict)
        self.steps = {}          # axis -> the steps made along it

    def run_at(self, position):
        return self.grid[tuple(position[a] for a in AXES)]

    def visit(self, position):
        """Make (or find) the run at position and read its quantities."""
        run = self.run_at(position)
        if "values" not in run:
            self.bring(run)
            if self.times is None:
                # The first run has the coarsest step: every run is
                # compared at its times.
                self.times = run["history"]["tau"].to_numpy()
            run["values"] = {q: qoi_values(run, q, self.times)
                             for q in self.qois}
            self.made.append(run)
        return run

    def scale(self, run, qoi):
        return 1.0 if self.absolute else magnitude(run["values"][qoi])

    def step(self, axis, coarse, fine):
        """Record a step along axis, from run coarse to run fine."""
        self.steps.setdefault(axis, []).append({
            "to": fine["axes"][axis], "ratio": ratio(coarse, fine, axis),
            "cost": (fine["run_wall"] / coarse["run_wall"]
                     if coarse["run_wall"] > 0 else None),
            "difference": {q: difference(fine["values"][q],
                                         coarse["values"][q],
                                         self.scale(fine, q))
                           for q in self.qois}})

    def order(self, axis, qoi, back=0):
        """The order observed on the axis's last two steps (back = 1: the
        two before), if they are successive rungs, else None."""
        steps = self.steps[axis]
        if len(steps) < 2 + back:
            return None
        last, before = steps[-1 - back], steps[-2 - back]
        if before["to"] != last["to"] - 1:
            return None
        d1, d2 = before["difference"][qoi], last["difference"][qoi]
        if d2 == 0:
            return math.inf
        if d1 == 0:
            return -math.inf
        return math.log(d1 / d2) / math.log(last["ratio"])

    def estimate(self, axis):
        """The axis's part of the error, from its last step."""
        last = self.steps[axis][-1]
        self.parts[axis] = {}
        for q in self.qois:
            d, r = last["difference"][q], last["ratio"]
            assumed = d / (r ** self.assumed - 1)
            k = self.order(axis, q)
            part = {"order": self.assumed, "observed": False,
                    "error": assumed, "agreement": None, "before": None}
            if k is not None:
                before = self.order(axis, q, back=1)
                part.update(order=k, observed=True, before=before)
                if d == 0 or k == math.inf:
                    part.update(error=0.0)
                elif k <= 0:
                    part.update(error=math.inf)
                else:
                    part.update(error=d / (r ** k - 1))
                    # The same estimate with the order seen a step earlier
                    # (or assumed): how settled the order is.
                    other = (before if before is not None and
                             0 < before < math.inf else self.assumed)
                    part["agreement"] = part["error"] / (d / (r ** other
                                                              - 1))
            self.parts[axis][q] = part

    def total(self, qoi):
        return sum(self.parts[a][qoi]["error"] for a in self.ladder)

    def worst(self):
        """The quantity whose estimate is largest, and that estimate."""
        q = max(self.qois, key=self.total)
        return q, self.total(q)

    def cost_ratio(self, axis, position):
        """A step's cost along axis: its last measured step's, else the
        ratio of the ladder's work (dofs x steps up to a factor)."""
        for step in reversed(self.steps.get(axis, [])):
            if step["cost"] is not None:
                return step["cost"]
        p = dict(position)
        here = self.run_at(p)["work"]
        p[axis] += 1
        return self.run_at(p)["work"] / here

    def next_axis(self, position, run):
        """The axis to refine next, or None when none can help."""
        q, total = self.worst()
        best, best_key = None, None
        for axis in self.ladder:
            if position[axis] + 1 >= self.extent[axis]:
                continue
            part = self.parts[axis][q]
            p = dict(position)
            p[axis] += 1
            r = ratio(run, self.run_at(p), axis)
            k = part["order"] if part["order"] > 0 else self.assumed
            after = (part["error"] / r ** k if math.isfinite(part["error"])
                     else 0.0)
            gain = part["error"] - after
            if not gain > 0:
                continue
            cost = max(run["run_wall"], 1e-3) * self.cost_ratio(axis,
                                                                  position)
            added = max(cost - run["run_wall"], 1e-3)
            # Meeting the target at all beats a larger gain per second.
            key = ((0, cost) if total - gain <= self.target
                   else (1, -gain / added))
            if best_key is None or key < best_key:
                best, best_key = axis, key
        return best

    def climb(self, report):
        """Run the ladder up to the target; the chosen run. report(run,
        climb) is called after every run."""
        position = {a: 0 for a in AXES}
        run = self.visit(position)
        self.record(run)
        report(run, self)
        for axis in self.ladder:
            run = self.advance(position, axis, run)
            report(run, self)
        while True:
            q, total = self.worst()
            if total <= self.target:
                return run
            axis = self.next_axis(position, run)
            if axis is None:
                best = min((r for r in self.made if r["worst"] is not None),
                           key=lambda r: r["worst"])
                raise LadderOut(
                    "the ladder ran out before the target %g: the best "
                    "estimate was %.3g, for %s at run %s (%s)"
                    % (self.target, best["worst"], best["worst_qoi"],
                       best["label"], best["parts"][best["worst_qoi"]]))
            run = self.advance(position, axis, run)
            report(run, self)

    def record(self, run):
        """Keep with the run the estimate known when it was made (None
        until each axis of the ladder has two rungs)."""
        ready = all(a in self.parts for a in self.ladder)
        run["estimate"] = {q: self.total(q) if ready else None
                           for q in self.qois}
        run["parts"] = {q: self.parts_text(q) for q in self.qois}
        run["worst_qoi"], run["worst"] = (self.worst() if ready
                                          else (self.qois[0], None))

    def advance(self, position, axis, run):
        """One rung along axis from run (at position, which moves)."""
        position[axis] += 1
        fine = self.visit(position)
        self.step(axis, run, fine)
        self.estimate(axis)
        self.record(fine)
        return fine

    def parts_text(self, qoi):
        return ", ".join("%s %s" % (self.names[a],
                                    part_text(self.parts[a][qoi]))
                         for a in self.ladder if a in self.parts)


def ratio(coarse, fine, axis):
    return coarse["size"][axis] / fine["size"][axis]


def part_text(part):
    """An axis's part of the estimate in words: the error, the order and
    where it comes from, the agreement."""
    if not part["observed"]:
        how = "order %g assumed" % part["order"]
    elif part["error"] == 0:
        how = "difference 0"
    elif part["error"] == math.inf:
        how = "not converging: observed order %.2f" % part["order"]
    else:
        before = part["before"]
        how = "order %.2f observed, agreement %.2f with %s" % (
            part["order"], part["agreement"],
            "order %.2f seen a step before" % before
            if before is not None and 0 < before < math.inf
            else "the assumed order")
    return "%.3g (%s)" % (part["error"], how)


def progress_line(run, climb):
    """One line per run made: the run, its cost, the estimate so far."""
    q, e = run["worst_qoi"], run["worst"]
    return ("[%d] %-20s dofs %7d  steps %5d  process %7.3f s  |  %s" % (
        len(climb.made), run["label"], run["dofs"], run["steps"],
        run["process_wall"],
        "%s: %.3g = %s  %s target %g" % (
            q, e, climb.parts_text(q), "<=" if e <= climb.target else ">",
            climb.target)
        if e is not None else "estimate after a step along each axis"))


def definitions(climb):
    return ("Estimated error: the sum over the ladder's axes of Richardson's "
            "estimate d / (r^k - 1) along each axis (d the difference of its "
            "last two rungs, %s; r their ratio of %s, h or 1/p; k the "
            "order observed on the axis's last two steps, else the assumed "
            "%g). Agreement: the estimate with the observed order over the "
            "same estimate with the order seen a step earlier on the axis, "
            "or else with the assumed order (near 1: the order has "
            "settled)."
            % ("the largest absolute difference over the times of the "
               "coarsest time step" if climb.absolute else
               "the largest difference over the times of the coarsest time "
               "step relative to the finer rung's largest magnitude",
               "Error tolerance^(1/3)" if climb.tolerances else "dtau",
               climb.assumed))


def summary_text(climb, chosen, command, ladder_size):
    """The study's result as markdown."""
    cost = sum(r["process_wall"] for r in climb.made)
    lines = ["# Target-driven study", "", "    " + command, "",
             definitions(climb), "",
             "Target %g met by run %s (cells %d, p %d, dofs %d, dtau %g, "
             "steps %d, process wall %.3f s)." % (
                 climb.target, chosen["label"], chosen["cells"], chosen["p"],
                 chosen["dofs"], chosen["dtau"], chosen["steps"],
                 chosen["process_wall"]),
             "Runs made: %d of the ladder's %d, process wall %.3f s in all."
             % (len(climb.made), ladder_size, cost), ""]
    for q in climb.qois:
        lines.append("- %s: estimated error %.3g = %s" % (
            q, climb.total(q), climb.parts_text(q)))
    lines += ["", "| rung | run | dofs | steps | process wall [s] | run's "
              "own wall [s] | " + " | ".join("estimate " + q
                                            for q in climb.qois) + " |",
              "|---|---|---|---|---|---|" + "---|" * len(climb.qois)]
    for k, r in enumerate(climb.made, 1):
        lines.append("| %d | %s | %d | %d | %.3f | %.3f | %s |" % (
            k, r["label"], r["dofs"], r["steps"], r["process_wall"],
            r["run_wall"], " | ".join(
                "%.3g" % r["estimate"][q] if r["estimate"][q] is not None
                else "" for q in climb.qois)))
    return "\n".join(lines) + "\n"


def csv_text(climb, chosen):
    """One row per run made, in the order made."""
    head = (["rung", "run", "chosen", "cells", "p", "dofs", "dtau", "steps",
             "process_wall", "run_wall"]
            + ["estimate:" + q for q in climb.qois])
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(head)
    for k, r in enumerate(climb.made, 1):
        writer.writerow(
            [str(k), r["label"], str(int(r is chosen))]
            + [str(r[c]) for c in ("cells", "p", "dofs")]
            + ["%r" % r["dtau"], str(r["steps"]), "%r" % r["process_wall"],
               "%r" % r["run_wall"]]
            + ["" if r["estimate"][q] is None else "%r" % r["estimate"][q]
               for q in climb.qois])
    return out.getvalue()
