"""The K.E.D. listings' own poles: where a listing's Cramer determinant R1 (eq. 14, the pin
forces f4-f6 of the path point) vanishes because of its bugs, not at a toggle.

The source listings' G1 (D014) and I1 (D015), and the cognate listings' moment row (D026), make
R1 vanish at positions the mechanism does not have (the thesis's R1 vanishes only at a toggle).
``pole_alps`` finds, at one input angle, the coupler angles alp (rad) where the program's R1,
computed by the port with the listing's bugs (legacy's arithmetic, bit for bit), changes sign,
each to adjacent doubles: the geometry driven onto the pole.  Used by the calibration sample
(``calibration``), the fuzz's "listing poles" class and tests/ali1977/test_poles.py.  Lengths
in inches, input angles in degrees.
"""
from __future__ import annotations

import math
import warnings

import numpy as np

from ....errors import LinkageError, LinkreproWarning
from ....port.ali1977 import case2, case3
from ....port.ali1977.cognate import _cognate_linkage
from ....port.ali1977.fourbar import Lengths
from ....port.ali1977.linkage import cramer_determinant
from ....port.ali1977.quirks import PRINTED
from ....port.ali1977.source import _source_linkage

#: R1 over its terms' size at a pole the bisection found (a jump stays far larger)
POLE = 1e-9
#: each program's listing: its quirks, and whether it solves the cognate's Cramer matrix
LISTINGS = {"case1_source": (PRINTED, False), "case1_cognate": (PRINTED, True),
            "case2_source": (case2.LISTING, False), "case2_cognate": (case2.COGNATE_LISTING, True),
            "case3_source": (case3.LISTING, False), "case3_cognate": (case3.COGNATE_LISTING, True)}


def determinant(program: str, deg: float, lengths: Lengths, alp: float, quirks=None) -> float:
    """R1 of ``program``'s path point at input angle ``deg`` (deg) with coupler angle ``alp``
    (rad), as the port with ``quirks`` (default: the listing's) computes it, over the sum of its
    six terms' magnitudes (signed ``conditioning.relative_determinant``); NaN where the loop
    cannot close or the cognate is degenerate."""
    listing, cognate = LISTINGS[program]
    quirks = listing if quirks is None else quirks
    deg_array = np.array([float(deg)])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", LinkreproWarning)
        try:
            if cognate:
                mech = _cognate_linkage(deg_array, lengths, alp, 300.0, quirks).path_point()
            else:
                mech = _source_linkage(deg_array, lengths, alp, 300.0, quirks, "REAL").path_point(lengths.l2)
        except LinkageError:
            return math.nan
    a, b, c, d, e, f, g, h, i = (float(np.ravel(x)[0]) for x in mech.extra["coefficients"])
    terms = (a * e * i, -(a * f * h), -(b * d * i), b * f * g, c * d * h, -(c * e * g))
    with np.errstate(all="ignore"):
        return float(np.float64(cramer_determinant(a, b, c, d, e, f, g, h, i)) / sum(abs(t) for t in terms))


def pole_alps(program: str, deg: float, lengths: Lengths, quirks=None, grid: int = 361) -> list[float]:
    """The coupler angles alp in [-pi, pi) (rad) where ``program``'s R1 at ``deg`` changes sign
    (``determinant``), each bisected to adjacent doubles: of the two, the one with the smaller
    |R1|.  A sign change across a NaN (the loop open between) is not a pole, nor one where R1
    jumps (the cognate listings' BETA turns its quadrant, D141): at a pole R1 comes within
    POLE of zero, relative to its terms."""
    alps = np.linspace(-math.pi, math.pi, grid)
    values = [determinant(program, deg, lengths, float(a), quirks) for a in alps]
    poles = []
    for lo, hi, f_lo, f_hi in zip(alps[:-1], alps[1:], values[:-1], values[1:]):
        if not (f_lo * f_hi < 0.0):
            continue
        lo, hi = float(lo), float(hi)
        while math.isfinite(f_lo) and (mid := 0.5 * (lo + hi)) not in (lo, hi):
            f_mid = determinant(program, deg, lengths, mid, quirks)
            if (f_mid < 0.0) == (f_lo < 0.0):
                lo, f_lo = mid, f_mid
            else:
                hi, f_hi = mid, f_mid
        if math.isfinite(f_lo) and min(abs(f_lo), abs(f_hi)) < POLE:
            poles.append(lo if abs(f_lo) <= abs(f_hi) else hi)
    return poles


def nudged(alp: float, ulps: int) -> float:
    """``alp`` moved by ``ulps`` units in the last place (negative: down)."""
    for _ in range(abs(ulps)):
        alp = float(np.nextafter(alp, math.inf if ulps > 0 else -math.inf))
    return alp
