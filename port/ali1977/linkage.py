"""What the source four-bar of Ali (1977) and its crossed cognate share.

``Linkage``: a four-bar over the input angles up to its coupler (``source.SourceLinkage``,
``cognate.CognateLinkage``), with the precision check every program ends with (``finish``,
see ``conditioning``); the compiled kernels both use: the path points' positions and
accelerations (``_path_points``) and the rows f4-f6 of beta by Cramer's rule (eq. 14,
``_inverse_rows``); ``_finite``, the check that a path point's Mechanics is finite; ``ieee``,
numpy's floating-point warnings off.

Units: inch, pound-force, second; angles in radians inside.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numba import njit

from ...errors import SingularPositionError
from .conditioning import cancellation, check_precision, condition, raise_at_pole, relative_determinant, spread
from .data import _pi
from .fourbar import Lengths, check_finite
from .quirks import Quirks
from .structure import Mechanics


#: numpy's floating-point warnings off (a decorator): at a singular position the listings
#: compute on through IEEE infinities and NaN, and check_finite reports where a result is not finite.
ieee = np.errstate(divide="ignore", invalid="ignore", over="ignore")


def cramer_determinant(a, b, c, d, e, f, g, h, i):
    """R1 of the listings: the determinant of [a b c; d e f; g h i], in their order."""
    return (a * (e * i - f * h)) - (b * (d * i - f * g)) + (c * (d * h - e * g))


# --- The listings' statements at each input angle, compiled ---------------------------------
# The listings loop over the input angle; so do these kernels (numba, without fastmath: every
# operation IEEE double in the listing's order, no multiply-add fused; sin, cos, atan the C
# library's, as DCOS, DSIN, DATAN; a division by zero gives inf or NaN, as there).  Numpy
# would take some two hundred calls on the short arrays of a table; here it is one per block.


_determinant = njit(cramer_determinant, cache=True)


@njit(cache=True, error_model="numpy")
def _inverse_rows(beta, j, n, a, b, c, d, e, f, g, h, i):
    """Rows f4, f5, f6 of beta by Cramer's rule (eq. 14) into ``beta[j, n, 3:6, :]``, in the
    listing's order."""
    r = _determinant(a, b, c, d, e, f, g, h, i)
    beta[j, n, 3, 0] = ((e * i) - (f * h)) / r
    beta[j, n, 3, 1] = ((c * h) - (b * i)) / r
    beta[j, n, 3, 2] = ((b * f) - (c * e)) / r
    beta[j, n, 4, 0] = ((f * g) - (d * i)) / r
    beta[j, n, 4, 1] = ((a * i) - (c * g)) / r
    beta[j, n, 4, 2] = ((c * d) - (a * f)) / r
    beta[j, n, 5, 0] = ((d * h) - (e * g)) / r
    beta[j, n, 5, 1] = ((b * g) - (a * h)) / r
    beta[j, n, 5, 2] = ((a * e) - (b * d)) / r


@njit(cache=True, error_model="numpy")
def _path_points(lengths, l1, om2, om3, alph3, c2, s2, ce, se, cg, sg, cognate):
    """The path point at each extender length ``lengths`` (in) and input angle, in the
    mechanism's frame: XP, YP (in), (2, len(lengths), N), and XPA, YPA (in/s^2),
    (len(lengths), N, 2), as the source listing writes them, or with ``cognate`` the cognate
    listing (cg, sg: cos, sin of gam; unused for the source)."""
    position, acc = np.empty((2, lengths.size, c2.size)), np.empty((lengths.size, c2.size, 2))
    for j in range(lengths.size):
        r = lengths[j]
        for n in range(c2.size):
            position[0, j, n] = (l1 * c2[n]) + (r * ce[n])
            position[1, j, n] = (l1 * s2[n]) + (r * se[n])
            if cognate:
                acc[j, n, 0] = -(l1 * om2 * om2 * c2[n]) + (r * om3[n] * om3[n] * cg[n]) - (r * alph3[n] * sg[n])
                acc[j, n, 1] = -(l1 * om2 * om2 * s2[n]) - (r * om3[n] * om3[n] * sg[n]) - (r * alph3[n] * cg[n])
            else:
                acc[j, n, 0] = -(l1 * om2 * om2 * c2[n]) - (r * om3[n] * om3[n] * ce[n]) - (r * alph3[n] * se[n])
                acc[j, n, 1] = -(l1 * om2 * om2 * s2[n]) + (r * alph3[n] * ce[n]) - (r * om3[n] * om3[n] * se[n])
    return position, acc


def _extender_lengths(length) -> np.ndarray:
    """A path point's distance (in) along the extender, or an (n, 1) array of them, as the
    kernels take it: a 1-D float64 array."""
    return np.ascontiguousarray(length, dtype=np.float64).reshape(-1)


@dataclass
class Linkage:
    """A four-bar over the input angles up to its coupler: all that does not depend on where
    the path point sits on the extender (the source's and the cognate's: ``source.SourceLinkage``,
    ``cognate.CognateLinkage``).

    ``t2`` (rad) the input angle, ``t3``, ``t4`` the coupler's and follower's, ``ext_angle`` the
    extender's direction; ``om2``, ``om3`` (rad/s), ``alph3`` (rad/s^2); the cosines and sines
    the listing takes: ``c2, s2`` of t2, ``c3, s3`` of t3, ``c4, s4`` of t4, ``ce, se`` of the
    extender's direction; ``pins``: XAA, YAA, XBA, YBA (see pin_accelerations).  Lengths in the
    mechanism's own frame; ``path_point`` puts the path point on it.
    """
    deg: np.ndarray
    lengths: Lengths
    quirks: Quirks
    t2: np.ndarray
    t3: np.ndarray
    t4: np.ndarray
    ext_angle: np.ndarray
    om2: float
    om3: np.ndarray
    alph3: np.ndarray
    c2: np.ndarray
    s2: np.ndarray
    c3: np.ndarray
    s3: np.ndarray
    c4: np.ndarray
    s4: np.ndarray
    ce: np.ndarray
    se: np.ndarray
    pins: np.ndarray

    def _point(self, length):
        """Position (2, n, N) and acceleration (n, N, 2) of the path points ``length``: the kernel's."""
        raise NotImplementedError

    def position(self, length):
        """XP, YP (in, the mechanism's frame) of the path point ``length`` (in) along the extender
        from the crank pin (a number, or an (n, 1) array: n points)."""
        position, _ = self._point(length)
        return tuple(position if np.ndim(length) else position[:, 0])

    def acceleration(self, length) -> np.ndarray:
        """XPA, YPA (in/s^2, last axis; the mechanism's frame) of the path point ``length`` (in)."""
        _, acc = self._point(length)
        return acc if np.ndim(length) else acc[0]

    def loops(self) -> tuple[list, list]:
        """The four-bars this linkage solves (each l1, l3, l4, l5, in) and all its links."""
        raise NotImplementedError

    #: the quirks that put a listing's bug into its path points' Cramer matrix, with their
    #: register ids (the source's G1 and I1, the cognate's moment row)
    DETERMINANT_BUGS: ClassVar[tuple] = ()

    def construction(self) -> float:
        """The rounding (in units) the links carry from their construction: 1 (the cognate's more)."""
        return 1.0

    def determinant_bugs(self) -> tuple:
        """The register ids of the bugs (switched on) in the Cramer matrix this linkage solves."""
        return tuple(entry for quirk, entry in self.DETERMINANT_BUGS if getattr(self.quirks, quirk))

    def pole_distance(self, *mechs: Mechanics) -> np.ndarray | None:
        """Per input angle, the smallest ``conditioning.relative_determinant`` of the Cramer
        matrices of the path points ``mechs`` (of this linkage; any number of points each), or
        None where no bug of the listing is in them (the thesis's matrix vanishes only at a
        toggle, which ``condition`` covers)."""
        if not self.determinant_bugs():
            return None
        rho = [relative_determinant(*np.broadcast_arrays(*m.extra["coefficients"])).reshape(-1, len(self.deg))
               for m in mechs]
        return np.concatenate(rho).min(axis=0)

    def finish(self, out: dict, who: str, stacklevel: int = 4, rho=None, size=None, extender: float = 1.0,
               finite: dict | None = None) -> dict:
        """A program's results ``out`` checked: a SingularPositionError at the first input angle
        where a result (``finite``: the arrays to check, in order; default every array of
        ``out`` but ``deg``) is not finite, naming the listing's bug where its Cramer determinant
        vanishes there (``conditioning.raise_at_pole``); then the precision rule
        (``conditioning.check_precision``: raise at a toggle or a listing's pole to working
        precision, warn near a listing's pole and where half the digits are gone).  Adds the
        per-angle ``condition`` and ``error_bound`` (the bound on the relative error of the
        deflection vector, ``conditioning.expected_error``).  ``rho`` (``pole_distance``) and
        ``size`` (the deflection's terms, (N, 3), ``structure.magnitude``) of the path point,
        whose extender is ``extender`` (in).  The links' construction (``construction``) and,
        beyond a turn, the input angle's own rounding (|deg| / 360 turns) scale the positions'
        terms of the bound."""
        finite = {k: v for k, v in out.items() if k != "deg"} if finite is None else finite
        try:
            check_finite(self.deg, who, **finite)
        except SingularPositionError as error:
            raise_at_pole(who, self.deg, rho, self.determinant_bugs(), self.deg.tolist().index(error.angle_deg))
            raise
        loops, links = self.loops()
        link_spread = spread(links)
        kappa = condition(self.deg, _pi(self.quirks), loops, link_spread)
        cancelled = 1.0 if size is None else cancellation(out["dx"], out["dy"], out["rot"], extender, size)
        bound = check_precision(self.deg, kappa, self.quirks.real4_storage, who, stacklevel=stacklevel,
                                rho=rho, bugs=self.determinant_bugs(), cancelled=cancelled,
                                construction=self.construction() * np.maximum(1.0, np.abs(self.deg) / 360.0))
        out["condition"], out["error_bound"] = kappa, bound
        return out

    def pin_accelerations(self):
        """Accelerations (in/s^2, the mechanism's frame) of the crank pin A, (XAA, YAA), and of the
        follower pin B, (XBA, YBA), as Case II's listing forms them (the source's with D032, a
        sign in XBA; the cognate's a RECONSTRUCTION, D037: that page of the listing is missing)."""
        xaa, yaa, xba, yba = self.pins
        return (xaa, yaa), (xba, yba)


def _finite(mech: Mechanics, who: str) -> Mechanics:
    """``mech``, or SingularPositionError at the first input angle where its position,
    acceleration or beta is not finite."""
    deg, axis = mech.extra["linkage"].deg, np.ndim(mech.xp) - 1        # the angles' axis: 1 for n points

    def by_angle(values):
        return np.moveaxis(np.asarray(values), axis, 0).reshape(len(deg), -1)

    check_finite(deg, who, xp=by_angle(mech.xp), yp=by_angle(mech.yp),
                 acceleration_and_beta=np.concatenate([by_angle(mech.acc), by_angle(mech.beta)], axis=1))
    return mech
