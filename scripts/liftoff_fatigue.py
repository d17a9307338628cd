"""From a stress history to fatigue damage: rainflow counting (ASTM
E1049-85, rainflow counting, section 5.4.4), a fatigue law N(sigma) and
Miner's sum. Used by scripts/liftoff-damage; plain numpy, no liftoff.

Stresses are in Pa, tension positive (liftoff's sign: doc/model.md,
"Moments, shear forces and stresses").
"""

import ast
import math

import numpy as np


class LawError(ValueError):
    """A fatigue law that cannot be used, with a one-line reason."""


# ----------------------------------------------------------------------------
# Rainflow counting


def reversals(series):
    """The peaks and valleys of a series: its first and last values and
    every value where the slope changes sign (a run of equal values counts
    once). ASTM E1049 counts on these alone; the points between them lie
    inside the ranges they span and change no count."""
    values = np.asarray(series, dtype=float)
    if values.size == 0:
        return values
    # Repeated values carry no reversal and would hide a slope's sign.
    keep = np.concatenate(([True], np.diff(values) != 0))
    values = values[keep]
    if values.size < 3:
        return values
    slope = np.sign(np.diff(values))
    turning = np.flatnonzero(slope[1:] != slope[:-1]) + 1
    return values[np.concatenate(([0], turning, [values.size - 1]))]


def rainflow(series):
    """The cycles of a series by ASTM E1049-85's rainflow counting (5.4.4),
    as a list of (range, mean, count) with count 1.0 for a full cycle and
    0.5 for a half, in the order they are counted.

    The standard's steps on the reversals: with X the range of the two most
    recent points and Y the one before, X < Y reads the next point; else if
    Y holds the starting point S (the oldest point kept), Y is a half cycle
    and S is discarded (the next point becomes S); else Y is a full cycle
    and its two points are discarded. The ranges left at the end are half
    cycles."""
    stack, cycles = [], []
    for point in reversals(series):
        stack.append(point)
        while len(stack) >= 3:
            x = abs(stack[-1] - stack[-2])
            y = abs(stack[-2] - stack[-3])
            if x < y:
                break
            if len(stack) == 3:
                cycles.append(cycle(stack[0], stack[1], 0.5))
                stack.pop(0)
            else:
                cycles.append(cycle(stack[-3], stack[-2], 1.0))
                del stack[-3:-1]
    cycles += [cycle(a, b, 0.5) for a, b in zip(stack, stack[1:])]
    return cycles


def cycle(a, b, count):
    return (abs(b - a), (a + b) / 2, count)


def peaks(cycles):
    """The largest stress of each cycle (mean + range / 2), as an array."""
    return np.array([mean + r / 2 for r, mean, _ in cycles], dtype=float)


# ----------------------------------------------------------------------------
# Fatigue laws

# The MEPDG's law for the slab's flexural fatigue (NCHRP 1-37A, Guide for
# Mechanistic-Empirical Design, 2004, Part 3 Chapter 4, "Fatigue model" of
# JPCP transverse cracking; AASHTO's Mechanistic-Empirical Pavement Design
# Guide, 2008, the same calibration): log10 N = C1 (MR / sigma)^C2.
MEPDG_C1 = 2.0
MEPDG_C2 = 1.22

# What an expression of the stress may use: numbers, the stress sigma and
# the modulus of rupture MR (Pa), + - * / and ^ or ** (power), and these
# functions (numpy's, element-wise), as muParser offers them.
FUNCTIONS = {"log10": np.log10, "log": np.log, "ln": np.log, "exp": np.exp,
             "sqrt": np.sqrt, "abs": np.abs, "pow": np.power,
             "min": np.minimum, "max": np.maximum}
CONSTANTS = {"pi": math.pi, "e": math.e}
OPERATORS = (ast.Add, ast.Sub, ast.Mult, ast.Div, ast.Pow, ast.USub,
             ast.UAdd)


class Law:
    """log10 N(sigma), the cycles to failure at the peak stress sigma > 0:
    the MEPDG's C1 (MR / sigma)^C2, or an expression in sigma and MR."""

    def __init__(self, modulus_of_rupture, c1=MEPDG_C1, c2=MEPDG_C2,
                 expression=None):
        for name, value in (("MR", modulus_of_rupture), ("C1", c1),
                            ("C2", c2)):
            if not (isinstance(value, (int, float))
                    and math.isfinite(value) and value > 0):
                raise LawError("%s wants a number > 0, got %r"
                               % (name, value))
        self.mr, self.c1, self.c2 = float(modulus_of_rupture), c1, c2
        self.expression = expression
        self.tree = None if expression is None else parse_law(expression)

    def log10_cycles(self, sigma):
        """log10 N at each sigma > 0 (an array)."""
        sigma = np.asarray(sigma, dtype=float)
        if self.tree is None:
            return self.c1 * (self.mr / sigma) ** self.c2
        with np.errstate(all="ignore"):
            value = evaluate(self.tree, {"sigma": sigma, "MR": self.mr})
        return np.broadcast_to(np.asarray(value, dtype=float), sigma.shape)

    def describe(self):
        if self.tree is None:
            return ("log10 N = %g (MR / sigma)^%g, MR = %g Pa (MEPDG)"
                    % (self.c1, self.c2, self.mr))
        return "log10 N = %s, MR = %g Pa" % (self.expression, self.mr)


def parse_law(expression):
    """The expression's syntax tree, refused unless it holds only what
    FUNCTIONS, CONSTANTS, sigma, MR, numbers and OPERATORS allow: it is
    evaluated, so nothing else (attributes, other names, calls) may pass."""
    if not isinstance(expression, str) or not expression.strip():
        raise LawError("the law's expression wants text, got %r"
                       % (expression,))
    # muParser's power is ^; Python's ^ is a bitwise xor.
    text = expression.replace("^", "**")
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except SyntaxError:
        raise LawError("the law's expression '%s' is not an expression"
                       % expression)
    allowed = sorted(["sigma", "MR"] + list(CONSTANTS) + list(FUNCTIONS))
    for node in ast.walk(tree):
        if isinstance(node, ast.Name):
            if node.id not in allowed:
                raise LawError("the law's expression uses '%s'; allowed: "
                               "numbers, + - * / ^, %s"
                               % (node.id, ", ".join(allowed)))
        elif isinstance(node, ast.Call):
            if not (isinstance(node.func, ast.Name)
                    and node.func.id in FUNCTIONS) or node.keywords:
                raise LawError("the law's expression calls something other "
                               "than %s" % ", ".join(sorted(FUNCTIONS)))
        elif isinstance(node, ast.Constant):
            if isinstance(node.value, bool) or not isinstance(
                    node.value, (int, float)):
                raise LawError("the law's expression holds %r; only numbers "
                               "are allowed" % (node.value,))
        elif not isinstance(node, (ast.Expression, ast.BinOp, ast.UnaryOp,
                                   ast.Load) + OPERATORS):
            raise LawError("the law's expression uses %s; allowed: numbers, "
                           "+ - * / ^, %s" % (type(node).__name__,
                                              ", ".join(allowed)))
    return tree


def evaluate(node, names):
    """The value of a tree that parse_law() accepted."""
    if isinstance(node, ast.Expression):
        return evaluate(node.body, names)
    if isinstance(node, ast.Constant):
        return float(node.value)
    if isinstance(node, ast.Name):
        return names[node.id] if node.id in names else CONSTANTS[node.id]
    if isinstance(node, ast.UnaryOp):
        value = evaluate(node.operand, names)
        return -value if isinstance(node.op, ast.USub) else value
    if isinstance(node, ast.Call):
        return FUNCTIONS[node.func.id](*[evaluate(a, names)
                                         for a in node.args])
    left, right = evaluate(node.left, names), evaluate(node.right, names)
    return {ast.Add: np.add, ast.Sub: np.subtract, ast.Mult: np.multiply,
            ast.Div: np.divide, ast.Pow: np.power}[type(node.op)](left,
                                                                 right)


# ----------------------------------------------------------------------------
# Miner's sum


def damage(peak_stresses, counts, law):
    """Miner's sum of count / N(peak) over cycles whose peak is a tension.

    A cycle whose largest stress is not a tension does no damage: the law
    is the flexural fatigue of concrete in tension, the ratio of the
    tensile stress to the modulus of rupture, with which the MEPDG (NCHRP
    1-37A, Part 3 Chapter 4) takes the tensile stress at the slab's bottom
    (bottom-up cracking) or top (top-down) under the load and the curl
    together; a compression (sigma <= 0) has no N. A cycle's stress in the
    law is its peak, the load's stress on top of the curl's, as the MEPDG
    takes it; its range or mean does not enter (no mean-stress
    correction)."""
    peak_stresses = np.asarray(peak_stresses, dtype=float)
    counts = np.asarray(counts, dtype=float)
    tension = peak_stresses > 0
    if not tension.any():
        return 0.0
    log_n = law.log10_cycles(peak_stresses[tension])
    if not np.all(np.isfinite(log_n)):
        bad = peak_stresses[tension][~np.isfinite(log_n)][0]
        raise LawError("the law gives no number for log10 N at sigma = %g "
                       "Pa" % bad)
    # 10^-log10 N underflows to 0 for a small stress, where N would
    # overflow.
    with np.errstate(over="ignore", under="ignore"):
        return float(np.sum(counts[tension] * np.power(10.0, -log_n)))


def pass_damage(series, law):
    """What one pass does at a point and face, from its stress history:
    (Miner's sum over its rainflow cycles, its peak tension (the largest
    stress, 0 if it never pulls), the damage of the peak alone as one
    cycle: the MEPDG's count of one load application per pass)."""
    cycles = rainflow(series)
    values = np.asarray(series, dtype=float)
    peak = max(0.0, float(values.max())) if values.size else 0.0
    counts = np.array([c for _, _, c in cycles], dtype=float)
    return (damage(peaks(cycles), counts, law), peak,
            damage([peak], [1.0], law))
