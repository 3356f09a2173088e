"""Closed-form kinematics of the four-bar and of its crossed coupler cognate.

As the 1977 listings do it (chapter IV, "complex number approach"): the coupler
and follower angles from the half-angle (Freudenstein) quadratic, then angular
velocities and accelerations at constant input speed.  Lengths in inches,
angles in radians, speeds in rad/s.  ``half_angle_roots`` is the listing's statements at
one input angle (compiled by numba into the K.E.D. port's loops over the angles).

The argument checks (``TypeError`` for a value of the wrong type, ``ValueError`` for a value
outside the programs' domain) are ``linkrepro.checks``, shared with the legacy face.
"""
from __future__ import annotations

import functools
import math
import warnings
from dataclasses import dataclass

import numpy as np
from numba import njit

from ...checks import link_length
from ...errors import AssemblyError, ListingBugWarning, SingularPositionError
from .. import libm
from .conditioning import closes_within_rounding


@dataclass(frozen=True)
class Lengths:
    """Link lengths (in): input, extender, coupler, follower, ground."""
    l1: float
    l2: float
    l3: float
    l4: float
    l5: float

    def __post_init__(self):
        for name in ("l1", "l2", "l3", "l4", "l5"):
            object.__setattr__(self, name, link_length(f"link length {name}", getattr(self, name)))


def freudenstein_constants(l1, l3, l4, l5):
    """K1..K5 of the source listing (statements 8-12)."""
    k1 = l5 / l1
    k2 = l5 / l4
    k3 = (l1 * l1 - l3 * l3 + l4 * l4 + l5 * l5) / (2.0 * l1 * l4)
    k4 = l5 / l3
    k5 = (l4 * l4 - l5 * l5 - l1 * l1 - l3 * l3) / (2.0 * l1 * l3)
    return k1, k2, k3, k4, k5


@njit(cache=True, error_model="numpy")
def half_angle_roots(c2, s2, k1, k2, k3, k4, k5):
    """The listings' two half-angle quadratics at one input angle (statements 14-21), from
    ``c2``, ``s2`` (cos, sin of T2) and K1..K5: DD x^2 + EE x + FF = 0 in x = tan(T3/2),
    AA x^2 + BB x + CC = 0 in x = tan(T4/2).  Returns T3, T4 (rad) and the two discriminants
    (where one is negative the loop cannot close and the roots are NaN; constants may be inf
    or NaN, a degenerate cognate: IEEE arithmetic throughout, as in the listing)."""
    aa = c2 + k3 - k1 - (k2 * c2)
    bb = -2.0 * s2
    cc = k1 + k3 - (1.0 + k2) * c2
    dd = (k4 * c2) + c2 + k5 - k1
    ee = -2.0 * s2
    ff = (k4 * c2) - c2 + k5 + k1
    disc3 = ee * ee - 4.0 * dd * ff
    disc4 = bb * bb - 4.0 * aa * cc
    t3 = 2.0 * math.atan((-ee - math.sqrt(disc3)) / (2.0 * dd))
    t4 = 2.0 * math.atan((-bb - math.sqrt(disc4)) / (2.0 * aa))
    return t3, t4, disc3, disc4


def cannot_close(disc3, disc4) -> np.ndarray:
    """True at each input angle where the listing's test fails: a negative discriminant
    (``EE*EE-4.0*DD*FF.LT.0.0.OR.BB*BB-4.0*AA*CC.LT.0.0``; NaN compares false, as there)."""
    return (disc3 < 0.0) | (disc4 < 0.0)


def raise_first_assembly_failure(deg, toggles: dict | None = None, **loops) -> None:
    """AssemblyError at the first input angle where any of the named loops (``who=mask``)
    cannot close: the listings test every loop at one angle before going on to the next.
    ``toggles`` (who -> (pi, l1, l3, l4, l5), the corrected engines): a loop that closes
    within rounding there is at a toggle, SingularPositionError, not open."""
    first = None
    for who, bad in loops.items():
        if bad.any():
            i = int(np.argmax(bad))
            if first is None or i < first[0]:
                first = (i, who)
    if first is None:
        return
    i, who = first
    if toggles and who in toggles and closes_within_rounding(float(deg[i]), *toggles[who]):
        raise SingularPositionError(f"{who}: at a toggle (coupler and follower in line), where the loop "
                                    "closes but rounding makes the position equations' discriminant negative",
                                    float(deg[i]))
    raise AssemblyError(f"{who}: the four-bar cannot close", float(deg[i]))


def raise_if_cannot_close(deg, who, disc3, disc4, toggle: tuple | None = None) -> None:
    """AssemblyError at the first input angle where a discriminant is negative (with the
    smaller of the two); ``toggle`` as raise_first_assembly_failure's."""
    bad = cannot_close(disc3, disc4)
    if bad.any():
        i = int(np.argmax(bad))
        if toggle is not None:
            raise_first_assembly_failure(deg, {who: toggle}, **{who: bad})
        raise AssemblyError(f"{who}: the four-bar cannot close", float(deg[i]),
                            discriminant=float(min(disc3[i], disc4[i])))


def check_finite(deg, who, **arrays):
    """Raise SingularPositionError where a result is not finite: the quantities are taken in
    the order given, and for the first one that is non-finite anywhere, its first input angle
    (with any non-finite entry along the trailing axes), as the legacy face reports it."""
    if np.isfinite(np.concatenate([values.ravel() for values in arrays.values()])).all():
        return
    for name, values in arrays.items():
        bad = ~np.isfinite(values)
        if bad.any():
            i = int(np.argmax(bad.reshape(len(deg), -1).any(axis=1)))
            raise SingularPositionError(f"{who}: non-finite {name}", float(deg[i]))


#: how many units of rounding of l3 - l2 cos(alp) the listing's CBTA may carry (its law of
#: cosines: 2 u (l2 + l3)^2 / l3, D165), with a margin
CBTA_ROUNDING = 16.0


def listing_beta_is_wrong(l2: float, l3: float, alp: float) -> bool:
    """True where the cognate listings' BETA = ATAN(SQRT(1 - CBTA**2)/CBTA) (register D141) is
    not the cognate frame's turn: the coupler point on the other side of the coupler
    (sin(alp) < 0) or the coupler triangle obtuse at the follower pin B (l2 cos(alp) > l3), or
    within the rounding of the listing's CBTA of that (CBTA = (l3 - l2 cos(alp)) / CL4 within
    its rounding of 0: which quadrant the listing takes is decided by rounding, D165).
    Lengths in inches, ``alp`` in radians."""
    margin = CBTA_ROUNDING * 2.0 ** -53 * (l2 + l3) ** 2 / l3
    return math.sin(alp) < 0.0 or l2 * math.cos(alp) > l3 - margin


def warn_listing_beta(who: str, l2: float, l3: float, alp: float, stacklevel: int = 3) -> None:
    """A ListingBugWarning (D141) where ``listing_beta_is_wrong``: the listing's cognate is then
    turned into the wrong place (or, at the obtuse triangle's edge, into a place rounding
    decides) and its coupler point leaves the source's coupler curve."""
    if listing_beta_is_wrong(l2, l3, alp):
        warnings.warn(ListingBugWarning(
            f"{who}: with alp = {math.degrees(alp):g} deg (l2 = {l2:g}, l3 = {l3:g} in) the listing's "
            "BETA drops the sign or quadrant of the coupler triangle's angle at B (or rounding decides it), so "
            "the cognate is turned into the wrong place", "D141"), stacklevel=stacklevel)


def construction_factor(l2: float, l3: float, alp: float, listing_beta: bool) -> float:
    """How many units of rounding (relative) the crossed cognate's links and angles carry from
    their construction out of the source's l2, l3 (in) and ``alp`` (rad) (``Cognate.of``), at
    least 1: the listing's law of cosines loses (l2 + l3)^2 / CL4^2 as the coupler point nears
    the follower pin B, and its BETA = ATAN(SQRT(1 - CBTA**2)/CBTA) (l2 + l3)^2 / (l2 l3 sin(alp))
    as the coupler point nears the coupler's line (at most a square root of the rounding: the
    sine's half digits); the corrected construction (components, atan2) (l2 + l3) / CL4."""
    along, across = l3 - l2 * math.cos(alp), l2 * math.sin(alp)
    cl4 = math.hypot(along, across)
    with np.errstate(divide="ignore"):
        if not listing_beta:
            return max(1.0, (l2 + l3) / cl4) if cl4 > 0.0 else math.inf
        links = (l2 + l3) ** 2 / cl4 ** 2 if cl4 > 0.0 else math.inf
        angle = min((l2 + l3) ** 2 / (l2 * l3 * abs(math.sin(alp))) if across else math.inf,
                    math.sqrt(2.0 * (l2 + l3) ** 2 / (2.0 ** -53 * l3 * cl4)) if cl4 > 0.0 else math.inf)
    return max(1.0, links, angle)


@dataclass(frozen=True)
class Cognate:
    """The crossed coupler cognate derived from the source (cognate listing, 32-47).

    ``beta`` (rad) is the angle by which the cognate's frame is turned against the
    source's: the coupler triangle's signed angle at the follower pin B, atan2(l2 sin alp,
    l3 - l2 cos alp); the listing's ATAN(SBTA/CBTA) with SBTA = SQRT(1 - CBTA**2) >= 0
    keeps it only in [0, 90) deg (D141, ``signed_beta=False``); with ``signed_beta`` CL4 and CL5
    come from the same components, not the law of cosines, which loses digits as the coupler
    point nears B.  ``calp`` is the cognate's
    rigid coupler angle (gamma, about 101 deg in the example).
    """
    cl1: float
    cl2: float
    cl3: float
    cl4: float
    cl5: float
    beta: float
    calp: float

    @classmethod
    @functools.lru_cache(maxsize=256)      # a pure function of its (immutable) arguments, asked for on every call
    def of(cls, lengths: Lengths, alp: float, pi: float, signed_beta: bool = False) -> "Cognate":
        l1, l2, l3, l4, l5 = (np.float64(v) for v in (lengths.l1, lengths.l2, lengths.l3, lengths.l4, lengths.l5))
        # IEEE arithmetic as in the listing: a degenerate cognate (CL4 = 0 when L2 = L3 and
        # ALP = 0, or 1 - CBTA**2 < 0 by rounding) gives inf or NaN here, not an exception;
        # the caller then reports the input angle where the results stop being finite.
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            k = l2 / l3
            if signed_beta:     # B -> P from its components: no law of cosines to lose digits as P nears B
                along, across = l3 - l2 * math.cos(alp), l2 * math.sin(alp)
                cl4 = np.float64(math.hypot(along, across))
                cl5 = l5 * cl4 / l3
            else:
                cl4 = np.sqrt((l2 * l2) + (l3 * l3) - (2.0 * l2 * l3 * libm.cos(alp)))
                cl5 = np.sqrt(((k * l5) * (k * l5)) + (l5 * l5) - (2.0 * l5 * l5 * k * libm.cos(alp)))
            cl3 = l4 * cl4 / l3
            cl2 = k * l4
            cl1 = l1 * cl4 / l3
            if signed_beta:
                beta = math.atan2(across, along)
            else:
                cbta = ((l3 * l3) + (cl4 * cl4) - (l2 * l2)) / (2.0 * l3 * cl4)
                sbta = np.sqrt(1.0 - cbta * cbta)
                beta = libm.arctan(sbta / cbta)
            calp = pi - (beta + alp)
        return cls(float(cl1), float(cl2), float(cl3), float(cl4), float(cl5), float(beta), float(calp))

    @functools.lru_cache(maxsize=256)
    def constants(self):
        """CK1..CK5 (cognate listing, 43-47): the crossed loop's half-angle constants."""
        cl1, cl3, cl4, cl5 = (np.float64(v) for v in (self.cl1, self.cl3, self.cl4, self.cl5))
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            return (cl5 / cl1, -cl5 / cl4,
                    (cl3 * cl3 - cl1 * cl1 - cl4 * cl4 - cl5 * cl5) / (2.0 * cl1 * cl4),
                    -cl5 / cl3,
                    (cl1 * cl1 + cl3 * cl3 + cl5 * cl5 - cl4 * cl4) / (2.0 * cl1 * cl3))
