"""The crossed coupler cognate of Ali's (1977) source four-bar: its motion and its path
point's force transformation, in its own frame.

The cognate listing's statements 13-60 (the source's coupler point, then the cognate's
positions, speeds and accelerations at each input angle: ``_cognate_motion``) and 61-110 (the
path point and beta of eqs. 19-28: ``_cognate_beta``), compiled as ``linkage`` describes;
``CognateLinkage`` is the cognate's motion over the input angles (``cognate_linkage``), and
``path_point`` puts the path point on it at any distance along its extender;
``cognate_mechanics`` is a path point of it, a ``structure.Mechanics``.  The cognate's links and
its turn into the source frame are ``fourbar.Cognate``'s.  Arguments and errors as in
``ali1977.case1``.

Units: inch, pound-force, second; ``alp`` in radians, input angles ``deg`` in degrees,
``rpm`` in rev/min.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from ...checks import angles_deg, parameter, speed_rpm
from .. import libm
from .data import EXAMPLE, _pi, expect
from .fourbar import (Cognate, Lengths, cannot_close, construction_factor, freudenstein_constants,
                      half_angle_roots, raise_first_assembly_failure, warn_listing_beta)
from .linkage import Linkage, _extender_lengths, _finite, _inverse_rows, _path_points, ieee
from .quirks import PRINTED, Quirks
from ..real4 import store
from .structure import Mechanics


@njit(cache=True, error_model="numpy")
def _cognate_motion(deg, pi, source_k, cognate_k, l1, l2, alp, cl1, cl3, cl4, calp, om2):
    """Cognate listing, statements 13-60, at each input angle ``deg`` (deg): the rows t2 (rad),
    the source's coupler point XP, YP (in) and its loop's two discriminants; the cognate's t3,
    t4, gam = gamma - t3, pi - gam (rad), om3 (rad/s), alph3 (rad/s^2), cos and sin of t2, t3,
    t4, gam and pi - gam, cot(t3 - t4), the accelerations (in/s^2) of its crank pin
    A' = CL1 e^{i t2}, XAA, YAA, and follower pin B' = A' - CL3 e^{i t3}, XBA, YBA (Case II's
    cognate loads, a RECONSTRUCTION: D037, the listing's page is missing), and its loop's two
    discriminants."""
    k1, k2, k3, k4, k5 = source_k
    ck1, ck2, ck3, ck4, ck5 = cognate_k
    out = np.empty((28, deg.size))
    for n in range(deg.size):
        t2 = (deg[n] * 2.0 * pi) / 360.0
        c2, s2 = math.cos(t2), math.sin(t2)
        t3, _, disc3, disc4 = half_angle_roots(c2, s2, k1, k2, k3, k4, k5)
        xp = (l1 * c2) + (l2 * math.cos(alp + t3))
        yp = (l1 * s2) + (l2 * math.sin(alp + t3))
        ct3, ct4, cdisc3, cdisc4 = half_angle_roots(c2, s2, ck1, ck2, ck3, ck4, ck5)
        gam = calp - ct3
        ext_angle = pi - (calp - ct3)
        c3, s3, c4, s4 = math.cos(ct3), math.sin(ct3), math.cos(ct4), math.sin(ct4)
        cg, sg, ce, se = math.cos(gam), math.sin(gam), math.cos(ext_angle), math.sin(ext_angle)
        s34 = math.sin(ct3 - ct4)
        om3 = (cl1 * om2 * math.sin(t2 - ct4)) / (cl3 * s34)
        om4 = (cl1 * om2 * math.sin(ct3 - t2)) / (cl4 * math.sin(ct4 - ct3))
        aj, bj = cl4 * s4, cl3 * s3
        cj = -(cl1 * om2 * om2 * c2) + (cl3 * om3 * om3 * c3) - (cl4 * om4 * om4 * c4)
        dj, ej = cl4 * c4, cl3 * c3
        fj = (cl1 * om2 * om2 * s2) - (cl3 * om3 * om3 * s3) + (cl4 * om4 * om4 * s4)
        alph3 = (cj * dj - aj * fj) / (aj * ej - bj * dj)
        cctx = math.cos(ct3 - ct4) / s34
        xaa, yaa = -(cl1 * c2 * om2 * om2), -(cl1 * s2 * om2 * om2)
        xba = xaa + (cl3 * om3 * om3 * c3) + (cl3 * alph3 * s3)
        yba = yaa + (cl3 * om3 * om3 * s3) - (cl3 * alph3 * c3)
        row = (t2, xp, yp, disc3, disc4, ct3, ct4, gam, ext_angle, om3, alph3,
               c2, s2, c3, s3, c4, s4, cg, sg, ce, se, cctx, xaa, yaa, xba, yba, cdisc3, cdisc4)
        for i in range(28):
            out[i, n] = row[i]
    return out


@njit(cache=True, error_model="numpy")
def _cognate_beta(cl2, cl3, c2, s2, c3, s3, c4, s4, c, s, cctx, moment_row):
    """Cognate listing, statements 61-110: beta (len(cl2), N, 8, 3) of the path point at each
    extender length ``cl2`` (in) and input angle (c, s: cos, sin of gam), and CG1, CH1, CI1 of
    its Cramer matrix, (3, len(cl2), N).  Coupler equilibrium of
    the crossed cognate, eqs. (20)-(24): the pin forces f4, f5 act at A along (-cos t2, -sin t2),
    (sin t2, -cos t2); f6 at B along (cos t4, sin t4); the loop is
    CL1 e^{i t2} - CL3 e^{i t3} + CL4 e^{i t4} = CL5."""
    beta = np.zeros((cl2.size, c2.size, 8, 3))
    ghi = np.empty((3, cl2.size, c2.size))
    for j in range(cl2.size):
        r = cl2[j]
        for n in range(c2.size):
            if moment_row:                                                              # D026
                g1 = (r * c2[n] * s[n]) + (r * s2[n] * c[n])
                h1 = (r * c2[n] * c[n]) - (r * s2[n] * s[n])
                i1 = (r * c2[n] * s[n]) + (cl3 * c3[n] * c4[n]) + (r * s4[n] * c[n]) + (cl3 * s4[n] * s3[n])
            else:   # moments about P, (pin - P) x direction, as rows 7-8 take them
                ax, ay = r * c[n], -r * s[n]                                             # A - P
                bx, by = ax - cl3 * c3[n], ay - cl3 * s3[n]                              # B - P
                g1 = -ax * s2[n] + ay * c2[n]
                h1 = -ax * c2[n] - ay * s2[n]
                i1 = bx * s4[n] - by * c4[n]
            beta[j, n, 0, 0], beta[j, n, 0, 1] = -c[n], s[n]
            beta[j, n, 1, 0], beta[j, n, 1, 1] = -s[n], -c[n]
            beta[j, n, 2, 2] = 1.0
            _inverse_rows(beta, j, n, -c2[n], s2[n], c4[n], -s2[n], -c2[n], s4[n], g1, h1, i1)
            beta[j, n, 6, 0] = -r * s[n] * cctx[n] / cl3
            beta[j, n, 6, 1] = -r * c[n] * cctx[n] / cl3
            beta[j, n, 6, 2] = cctx[n] / cl3
            beta[j, n, 7, 0], beta[j, n, 7, 1], beta[j, n, 7, 2] = -r * s[n], -r * c[n], 1.0
            ghi[0, j, n], ghi[1, j, n], ghi[2, j, n] = g1, h1, i1
    return beta, ghi


@dataclass
class CognateLinkage(Linkage):
    """The crossed coupler cognate of the source four-bar over the input angles (cognate
    listing, statements 13-60), in its own frame, a Linkage: ``cognate`` its links (Cognate);
    ``gam`` = gamma - t3, ``ext_angle`` = pi - gam; ``cg, sg`` cos and sin of gam; ``cctx`` =
    cot(t3 - t4); ``turn_cos``, ``turn_sin`` of -beta (the turn into the source frame).
    ``xp, yp`` (in): the source's coupler point as this listing computes it (the rigid-mode
    columns of Table I); ``alp`` (rad) the source's coupler angle.
    """
    cognate: Cognate
    gam: np.ndarray
    cg: np.ndarray
    sg: np.ndarray
    cctx: np.ndarray
    turn_cos: float
    turn_sin: float
    xp: np.ndarray
    yp: np.ndarray
    alp: float
    DETERMINANT_BUGS = (("cognate_moment_row", "D026"),)

    def loops(self) -> tuple[list, list]:
        lengths, cog = self.lengths, self.cognate
        loops = [(lengths.l1, lengths.l3, lengths.l4, lengths.l5), (cog.cl1, cog.cl3, cog.cl4, cog.cl5)]
        return loops, [lengths.l2, cog.cl2, *loops[0], *loops[1]]

    def construction(self) -> float:
        """The rounding the cognate carries from its construction (``fourbar.construction_factor``)."""
        return construction_factor(self.lengths.l2, self.lengths.l3, self.alp, self.quirks.cognate_beta_quadrant)

    def _point(self, cl2):
        return _path_points(_extender_lengths(cl2), self.cognate.cl1, self.om2, self.om3, self.alph3,
                            self.c2, self.s2, self.ce, self.se, self.cg, self.sg, True)

    @ieee
    def path_point(self, extender=None) -> Mechanics:
        """The path point ``extender`` (in; default the whole extender, CL2) along the cognate's
        extender from the crank pin (statements 61-110): position, acceleration and beta, and
        ``extra["cxp"], ["cyp"]`` the point turned into the source frame.  ``extender`` a number
        or an (n, 1) array for n points at once."""
        cog, real4 = self.cognate, self.quirks.real4_storage
        cl2 = cog.cl2 if extender is None else extender
        position, acc = self._point(cl2)
        beta, ghi = _cognate_beta(_extender_lengths(cl2), cog.cl3, self.c2, self.s2, self.c3, self.s3, self.c4,
                                  self.s4, self.cg, self.sg, self.cctx, self.quirks.cognate_moment_row)
        if not np.ndim(cl2):
            position, acc, beta, ghi = position[:, 0], acc[0], beta[0], ghi[:, 0]
        xpp, ypp = position
        xdp = store(xpp - cog.cl5, real4).astype(np.float64)                  # XDP is REAL*4
        cxp = store((xdp * self.turn_cos) - (ypp * self.turn_sin), real4).astype(np.float64) + self.lengths.l5
        cyp = (xdp * self.turn_sin) + (ypp * self.turn_cos)
        return Mechanics(xpp, ypp, acc, beta, (cl2, cog.cl1, cog.cl3, cog.cl4), -cog.beta,
                         extra={"xp": self.xp, "yp": self.yp, "cxp": cxp, "cyp": cyp, "t2": self.t2,
                                "t3": self.t3, "t4": self.t4, "om2": self.om2, "om3": self.om3,
                                "alph3": self.alph3, "cognate": cog, "ext_angle": self.ext_angle,
                                "coefficients": (-self.c2, self.s2, self.c4, -self.s2, -self.c2, self.s4, *ghi),
                                "linkage": self})


def cognate_linkage(deg, lengths: Lengths = EXAMPLE.lengths, alp: float | None = None,
                    rpm: float = EXAMPLE.rpm, quirks: Quirks = PRINTED) -> CognateLinkage:
    """The crossed cognate's motion over ``deg`` (cognate listing, statements 13-60); arguments
    as cognate_mechanics."""
    return _cognate_linkage(angles_deg("deg", deg), lengths, alp, rpm, quirks)


def _cognate_linkage(deg: np.ndarray, lengths: Lengths, alp: float | None, rpm: float,
                     quirks: Quirks, warn_beta: bool = True) -> CognateLinkage:
    """cognate_linkage of checked angles ``deg``; ``warn_beta``: warn D141 where it bites."""
    expect("lengths", lengths, Lengths)
    expect("quirks", quirks, Quirks)
    pi = _pi(quirks)
    if alp is None:
        alp = pi / 3.0
    alp, rpm = parameter("alp", alp), speed_rpm(rpm)
    speed = float(np.float32(rpm)) if quirks.real4_storage else float(rpm)       # S is REAL*4 in the listing
    l1, l2, l3, l4, l5 = lengths.l1, lengths.l2, lengths.l3, lengths.l4, lengths.l5
    if quirks.cognate_beta_quadrant and warn_beta:
        warn_listing_beta("the port with cognate_beta_quadrant on", lengths.l2, lengths.l3, alp, stacklevel=4)
    cog = Cognate.of(lengths, alp, pi, signed_beta=not quirks.cognate_beta_quadrant)
    om2 = (2.0 * pi * speed) / 60.0
    motion = _cognate_motion(deg, pi, freudenstein_constants(l1, l3, l4, l5), cog.constants(), l1, l2, alp,
                             cog.cl1, cog.cl3, cog.cl4, cog.calp, om2)
    (t2, xp, yp, disc3, disc4, t3, t4, gam, ext_angle, om3, alph3,
     c2, s2, c3, s3, c4, s4, cg, sg, ce, se, cctx) = motion[:22]
    cdisc3, cdisc4 = motion[26:]
    # The listing tests the source loop, then the cognate's, at each angle before the next.
    toggles = None if quirks.toggle_as_open else {"source": (pi, l1, l3, l4, l5),                   # D142
                                                  "cognate": (pi, cog.cl1, cog.cl3, cog.cl4, cog.cl5)}
    raise_first_assembly_failure(deg, toggles, source=cannot_close(disc3, disc4), cognate=cannot_close(cdisc3, cdisc4))
    with np.errstate(invalid="ignore"):
        turn_cos, turn_sin = libm.cos(-cog.beta), libm.sin(-cog.beta)
    return CognateLinkage(deg=deg, lengths=lengths, quirks=quirks, t2=t2, t3=t3, t4=t4, ext_angle=ext_angle, om2=om2,
                          om3=om3, alph3=alph3, c2=c2, s2=s2, c3=c3, s3=s3, c4=c4, s4=s4, ce=ce, se=se,
                          pins=motion[22:26], cognate=cog, gam=gam, cg=cg, sg=sg, cctx=cctx, turn_cos=turn_cos,
                          turn_sin=turn_sin, xp=xp, yp=yp, alp=alp)


def cognate_mechanics(deg, lengths: Lengths = EXAMPLE.lengths, alp: float | None = None,
                      rpm: float = EXAMPLE.rpm, quirks: Quirks = PRINTED,
                      extender: float | None = None) -> Mechanics:
    """Kinematics and beta of the crossed coupler cognate of the source four-bar
    (``lengths``, ``alp``), in the cognate's own frame (listing statements 20-110).

    ``extra`` holds the source's coupler point ``xp, yp`` as this listing computes it
    (the rigid-mode columns of Table I) and the cognate's ``cxp, cyp`` turned into
    the source frame.  ``extender`` (in) puts the path point at that distance from the
    crank pin along the cognate's extender (default: the whole extender, CL2); Case III
    uses it for its nodes.  ``extra["ext_angle"]`` is the extender's direction (rad),
    ``extra["linkage"]`` the CognateLinkage.
    """
    linkage = cognate_linkage(deg, lengths, alp, rpm, quirks)
    if extender is not None:
        extender = parameter("extender", extender, largest=None)
    return _finite(linkage.path_point(extender), "cognate")
