"""How many digits the K.E.D. results keep: the rule every engine ends with (legacy's faces and
the port alike).

At a toggle (coupler and follower in line: the transmission angle mu is 0 or 180 deg) the
position equations' discriminants vanish and the positions lose digits as 1/sin^2(mu); every
speed, acceleration and pin force then divides by sin(mu): ``condition`` estimates this at each
input angle from the links alone.  A listing's own algebra has poles too: its bugs (D014, D015
in the source listings' G1 and I1, D026 in the cognate listings' moment row) make the Cramer
determinant R1 of the pin forces vanish where the mechanism has no toggle
(``relative_determinant``).  And a deflection whose terms cancel keeps fewer digits than they
do (``cancellation``).  ``expected_error`` bounds the relative error of the deflection vector
from these, per input angle, and ``check_precision`` says so: a SingularPositionError where no
digit can be promised, a ListingBugWarning near a listing's pole, a PrecisionWarning where
fewer than half the digits of the results' storage can be promised.  ``closes_within_rounding``
tells a toggle from a loop that cannot close.  Lengths in inches, input angles in degrees.
"""
from __future__ import annotations

import math
import warnings

import numpy as np

from ...errors import ListingBugWarning, PrecisionWarning, SingularPositionError

#: unit roundoff of IEEE double, and of the listings' REAL*4 storage
DOUBLE_UNIT, REAL4_UNIT = 2.0 ** -53, 2.0 ** -24
#: the error bound's constants (see ``expected_error``): measured, scene ali1977-conditioning
CONDITION_FACTOR, STORAGE_FACTOR, POLE_FACTOR = 2048.0, 8.0, 1024.0
#: the listing's determinant, relative to its terms' size (``relative_determinant``), below which
#: an engine with the listing's bugs is near the bug's own pole: a ListingBugWarning
POLE_NEAR = 1e-3


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


def relative_determinant(a, b, c, d, e, f, g, h, i) -> np.ndarray:
    """|R1| of the Cramer matrix [a b c; d e f; g h i] (the listings' eq. 14, arrays broadcast)
    over the sum of its six terms' magnitudes: 1 for a well-conditioned matrix, 0 at a zero of
    the determinant; near it the listing's pin forces f4-f6 grow as 1/rho, its deflections as
    1/rho^2, and the rounding error of R1, computed in double, is some units of u/rho."""
    terms = (a * e * i, -(a * f * h), -(b * d * i), b * f * g, c * d * h, -(c * e * g))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        return np.abs(np.sum(terms, axis=0)) / np.sum(np.abs(terms), axis=0)


def cancellation(dx, dy, rot, extender: float, size) -> np.ndarray:
    """How many times the deflection vector (dx, dy, extender * rot) (in) is smaller than its
    terms before they cancel, ``size`` (.., 3: ``structure.magnitude``, or Case III's coupled
    sum): at least 1; 1 where both vanish (no load), inf where only the deflection does."""
    size = np.asarray(size, dtype=np.float64)
    terms = np.hypot(np.hypot(size[..., 0], size[..., 1]), extender * size[..., 2])
    value = np.hypot(np.hypot(dx, dy), extender * np.asarray(rot))
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(terms > 0.0, np.maximum(terms / value, 1.0), 1.0)


def expected_error(kappa, real4: bool, rho=None, cancelled=1.0, construction=1.0) -> np.ndarray:
    """The bound on the error of the deflection vector (dx, dy, extender * rot), relative to its
    own length, at each input angle (a per-point promise, no absolute floor).

    Relative to the deflection's terms before they cancel (its size, ``cancelled`` times its
    length: ``cancellation``) the error is at most STORAGE_FACTOR units of the results' storage
    (REAL*4 in the listings' arithmetic: every stored matrix entry, load and product sum), plus
    CONDITION_FACTOR u kappa (u the double's unit roundoff, in which every engine computes the
    positions; ``kappa`` the condition near a toggle, ``condition``), plus, where the engine
    solves a listing's faulty Cramer matrix, POLE_FACTOR u / ``rho`` (``relative_determinant``:
    the bug's own pole), the last two ``construction`` times (the rounding the links carry from
    their construction: the crossed cognate's, ``fourbar.construction_factor``).  Relative to the
    deflection itself it is ``cancelled`` times that: a deflection that nearly vanishes keeps
    fewer digits.  The constants bound every error measured against a 60-digit evaluation of the
    same equations (the calibration sample of the scene ali1977-conditioning: random geometries
    and sections, Cases I-III, source and cognate, the listings' and the corrected equations,
    REAL*4 and double; the links' spread enters through ``kappa`` alone)."""
    storage = REAL4_UNIT if real4 else DOUBLE_UNIT
    positions = CONDITION_FACTOR * np.asarray(kappa, dtype=np.float64)
    if rho is not None:
        with np.errstate(divide="ignore"):
            positions = positions + POLE_FACTOR / np.asarray(rho, dtype=np.float64)
    with np.errstate(invalid="ignore", over="ignore"):
        return (STORAGE_FACTOR * storage + DOUBLE_UNIT * construction * positions) * cancelled


def check_precision(deg, kappa, real4: bool, who: str, stacklevel: int = 3, rho=None, bugs: tuple = (),
                    cancelled=1.0, construction=1.0) -> np.ndarray:
    """The precision rule every K.E.D. engine ends with, per input angle ``deg`` (deg); returns
    the bound per angle (``expected_error``).

    Where no digit can be promised even of the deflection's terms (``expected_error`` with
    ``cancelled`` = 1 reaches 1): SingularPositionError at the first such angle, at a toggle or,
    where ``rho`` (the listing's Cramer matrix, ``relative_determinant``) makes it, at a zero of
    the listing's determinant, naming ``bugs`` (register ids).  Near such a zero (``rho`` <
    POLE_NEAR) a ListingBugWarning at the first such angle, with the bugs, ``rho`` and the
    expected error there: the listing's pin forces and deflections there are the bug's (1/rho and
    1/rho^2 times a well-conditioned position's).  Elsewhere, where the bound passes half the
    digits the results' storage holds (sqrt of its unit roundoff: 8 digits of a double, 3.6 of a
    REAL*4), a PrecisionWarning at the first such angle, with the bound there: near a toggle, or
    where the deflection nearly vanishes (``cancelled``)."""
    kappa = np.asarray(kappa, dtype=np.float64)
    base = expected_error(kappa, real4, rho, construction=construction)
    if (base >= 1.0).any():
        i = int(np.argmax(base >= 1.0))
        if rho is not None and POLE_FACTOR / rho[i] >= CONDITION_FACTOR * kappa[i]:
            raise_at_pole(who, deg, rho, bugs, i, always=True)
        raise SingularPositionError(f"{who}: at a toggle to working precision (transmission angle within "
                                    "rounding of 0 or 180 deg): no digit of the deflections can be trusted",
                                    float(deg[i]), condition=float(kappa[i]))
    with np.errstate(invalid="ignore", over="ignore"):
        bound = base * cancelled
    near = np.zeros(bound.shape, bool) if rho is None else np.asarray(rho) < POLE_NEAR
    if near.any():
        i = int(np.argmax(near))
        warnings.warn(ListingBugWarning(
            f"{who}: at input angle {float(deg[i]):g} deg the listing's Cramer determinant R1 is "
            f"{rho[i]:.2g} of its terms' size ({_named(bugs)}): its pin forces and deflections there are the "
            f"bug's, not the mechanism's (expected relative error {bound[i]:.2g})", ", ".join(bugs),
            angle_deg=float(deg[i]), relative_error=float(bound[i])), stacklevel=stacklevel)
    claim = math.sqrt(REAL4_UNIT if real4 else DOUBLE_UNIT)
    over = (bound > claim) & ~near
    if over.any():
        i = int(np.argmax(over))
        why = (f"a deflection {bound[i] / base[i]:.3g} times smaller than its terms, which cancel"
               if base[i] <= claim else "near a toggle")
        warnings.warn(PrecisionWarning(f"{who}: the deflections keep fewer than half the digits they are "
                                       f"stored with ({why})", float(deg[i]), condition=float(kappa[i]),
                                       relative_error=float(bound[i])), stacklevel=stacklevel)
    return bound


def raise_at_pole(who: str, deg, rho, bugs: tuple, i: int, always: bool = False) -> None:
    """SingularPositionError at input angle ``deg[i]`` (deg) naming the listing's bugs, if
    ``always`` or if no digit is left there of the listing's Cramer determinant (``rho[i]``
    within POLE_FACTOR units of rounding of 0: a result that is not finite there is the pole's);
    nothing where ``rho`` is None (no bug of the listing in the matrix)."""
    if rho is not None and (always or POLE_FACTOR * DOUBLE_UNIT >= rho[i]):
        raise SingularPositionError(f"{who}: at a zero of the listing's Cramer determinant R1 ({_named(bugs)}): "
                                    "no digit of the deflections can be trusted", float(deg[i]),
                                    relative_determinant=float(rho[i]))


def _named(bugs) -> str:
    """The listing's faulty coefficients, by register id."""
    what = {"D014": "G1, D014", "D015": "I1, D015", "D026": "CG1, CH1, CI1, D026"}
    return "its " + "; ".join(what.get(b, b) for b in bugs) if bugs else "the listing's coefficients"


def closes_within_rounding(deg: float, pi: float, l1: float, l3: float, l4: float, l5: float) -> bool:
    """True where the loop closes, or misses closing by no more than rounding: the distance d
    from the crank pin to the follower's pivot within a few units of the double of
    |l3 - l4| <= d <= l3 + l4 (in; ``deg`` turned into radians with the engine's ``pi``)."""
    t2 = (deg * 2.0 * pi) / 360.0
    d = math.hypot(l1 * math.cos(t2) - l5, l1 * math.sin(t2))
    slack = 8.0 * DOUBLE_UNIT * (l1 + l5 + l3 + l4)
    return abs(l3 - l4) - slack <= d <= l3 + l4 + slack
