"""What the tests of a slab on a base it can lift off check alike."""

from checks import check


def compare(what, value, reference, tolerance):
    """A PASS/FAIL line for value against reference, relative."""
    error = abs(value / reference - 1)
    check(error < tolerance, f"{what}: {value:.8e} against {reference:.8e}: "
          f"{error:.1e} < {tolerance:.0e}")


def check_equilibrium(row, load, slab_weight, base_weight):
    """A static history row: the bed carries the load and both weights,
    the interface the load and the slab's weight, to 1e-9."""
    compare("equilibrium: the bed's resultant against the load and both "
            "weights", row["resultant"], load + slab_weight + base_weight,
            1e-9)
    compare("equilibrium: the interface's resultant against the load and "
            "the slab's weight", row["interface_resultant"],
            load + slab_weight, 1e-9)
