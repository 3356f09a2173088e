"""How many digits the K.E.D. results keep: the conditioning of the four-bar near a toggle.

At a toggle (coupler and follower in line: the transmission angle mu is 0 or 180 deg) the
position equations' discriminants vanish and the positions lose digits as 1/sin^2(mu); every
speed, acceleration and pin force then divides by sin(mu).  ``condition`` estimates this at
each input angle from the links alone, ``expected_error`` bounds the relative error of the
deflections it allows, and ``check_precision`` says so: a PrecisionWarning where fewer than
half the digits of the results' storage can be promised, a SingularPositionError where none
can.  ``closes_within_rounding`` tells a toggle from a loop that cannot close.  Shared by the
port and the legacy faces (one rule for every engine).  Lengths in inches, input angles in
degrees.
"""
from __future__ import annotations

import math
import warnings

import numpy as np

from ...errors import PrecisionWarning, SingularPositionError

#: unit roundoff of IEEE double, and of the listings' REAL*4 storage
DOUBLE_UNIT, REAL4_UNIT = 2.0 ** -53, 2.0 ** -24
#: the error bound's constants (see ``expected_error``): measured, scene ali1977-conditioning
CONDITION_FACTOR, STORAGE_FACTOR = 2048.0, 64.0


def transmission_sine_squared(deg, pi: float, l1: float, l3: float, l4: float, l5: float) -> np.ndarray:
    """sin^2 of the transmission angle mu (between coupler and follower) at each input angle
    ``deg`` (deg, turned into radians with the engine's ``pi``), from the links alone (in):
    with d the distance from the crank pin to the follower's pivot,
    sin^2 mu = (d^2 - (l3 - l4)^2) ((l3 + l4)^2 - d^2) / (2 l3 l4)^2, each factor a product of
    a sum and a difference so that it keeps its digits at a toggle (mu = 0 or 180 deg, where it
    is 0).  Negative where the loop cannot close."""
    t2 = (np.asarray(deg, dtype=np.float64) * 2.0 * pi) / 360.0
    d = np.hypot(l1 * np.cos(t2) - l5, l1 * np.sin(t2))
    folded, stretched = abs(l3 - l4), l3 + l4
    return ((d - folded) * (d + folded)) * ((stretched - d) * (stretched + d)) / (2.0 * l3 * l4) ** 2


def spread(lengths) -> float:
    """The largest of ``lengths`` (in) over the smallest: links of very different lengths lose
    more digits in every sum of the analysis."""
    lengths = np.abs(np.asarray(lengths, dtype=np.float64))
    return float(lengths.max() / lengths.min())


def condition(deg, pi: float, loops, link_spread: float) -> np.ndarray:
    """The K.E.D. results' condition at each input angle: ``link_spread`` / sin^2(mu), the
    worst over ``loops`` (each the l1, l3, l4, l5 of a four-bar the program solves, in); inf
    where a loop is at (or past) a toggle.  Near a toggle the positions lose digits as
    1/sin^2(mu) (the half-angle discriminants vanish there) and every speed, acceleration and
    pin force divides by sin(mu)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        worst = np.min([transmission_sine_squared(deg, pi, *loop) for loop in loops], axis=0)
        return np.where(worst > 0.0, link_spread / worst, np.inf)


def expected_error(kappa, link_spread: float, real4: bool) -> np.ndarray:
    """A bound on the relative error of the deflections (the vector dx, dy, l2 * rot) at
    condition ``kappa``: STORAGE_FACTOR units of the results' storage (REAL*4 in the listings'
    arithmetic) per unit of ``link_spread``, plus CONDITION_FACTOR u kappa (u the double's unit
    roundoff, in which every engine computes the positions).  The constants bound every error
    measured against a 60-digit evaluation of the same equations (scene ali1977-conditioning)."""
    storage = REAL4_UNIT if real4 else DOUBLE_UNIT
    return (STORAGE_FACTOR * storage * link_spread
            + CONDITION_FACTOR * DOUBLE_UNIT * np.asarray(kappa, dtype=np.float64))


def check_precision(deg, kappa, link_spread: float, real4: bool, who: str, stacklevel: int = 3) -> None:
    """Where the bound reaches 1 no digit can be promised: ValueError if the links' lengths
    differ too much for the engine's storage at any position (the storage term alone reaches
    1), else SingularPositionError at the first such input angle (a toggle to working
    precision).  Where the bound passes half the digits the results' storage holds (sqrt of
    its unit roundoff: 8 digits of a double, 3.6 of a REAL*4), a PrecisionWarning at the first
    such angle."""
    kappa = np.asarray(kappa, dtype=np.float64)
    bound = expected_error(kappa, link_spread, real4)
    if (bound >= 1.0).any():
        i = int(np.argmax(bound >= 1.0))
        if expected_error(0.0, link_spread, real4) < 1.0:
            raise SingularPositionError(f"{who}: at a toggle to working precision (transmission angle within "
                                        "rounding of 0 or 180 deg): no digit of the deflections can be trusted",
                                        float(deg[i]), condition=float(kappa[i]))
        raise ValueError(f"{who}: the links' lengths differ by a factor {link_spread:.3g}: no digit of the "
                         f"deflections can be promised in this arithmetic (condition {kappa[i]:.3g} at input "
                         f"angle {float(deg[i]):g} deg)")
    claim = math.sqrt(REAL4_UNIT if real4 else DOUBLE_UNIT)
    if (bound > claim).any():
        i = int(np.argmax(bound > claim))
        warnings.warn(PrecisionWarning(f"{who}: the deflections keep fewer than half the digits they are "
                                       f"stored with (near a toggle, or links' lengths {link_spread:.3g} apart)",
                                       float(deg[i]), condition=float(kappa[i]), relative_error=float(bound[i])),
                      stacklevel=stacklevel)


def closes_within_rounding(deg: float, pi: float, l1: float, l3: float, l4: float, l5: float) -> bool:
    """True where the loop closes, or misses closing by no more than rounding: the distance d
    from the crank pin to the follower's pivot within a few units of the double of
    |l3 - l4| <= d <= l3 + l4 (in; ``deg`` turned into radians with the engine's ``pi``)."""
    t2 = (deg * 2.0 * pi) / 360.0
    d = math.hypot(l1 * math.cos(t2) - l5, l1 * math.sin(t2))
    slack = 8.0 * DOUBLE_UNIT * (l1 + l5 + l3 + l4)
    return abs(l3 - l4) - slack <= d <= l3 + l4 + slack
