"""The source four-bar of Ali (1977): its motion and its path point's force transformation.

The source listing's statements 13-52 (positions, speeds and accelerations at each input
angle: ``_source_motion``) and 53-106 (the path point and beta of eqs. 9-18:
``_source_beta``), compiled as ``linkage`` describes; ``SourceLinkage`` is the four-bar's
motion over the input angles (``source_linkage``), and ``path_point`` puts the path point on
it at any distance along the extender; ``source_mechanics`` is the path point at the
extender's end, a ``structure.Mechanics``.  Arguments and errors as in ``ali1977.case1``.

Units: inch, pound-force, second; ``alp`` in radians, input angles ``deg`` in degrees,
``rpm`` in rev/min.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from ...checks import angles_deg, parameter, speed_rpm
from .data import ALP_SOURCE_LISTING, EXAMPLE, _pi, expect
from .fourbar import Lengths, freudenstein_constants, half_angle_roots, raise_if_cannot_close
from .linkage import Linkage, _extender_lengths, _finite, _inverse_rows, _path_points
from .quirks import PRINTED, Quirks
from .structure import Mechanics


@njit(cache=True, error_model="numpy")
def _source_motion(deg, pi, k1, k2, k3, k4, k5, l1, l3, l4, alp, om2, omega3_sign, b_sign):
    """Source listing, statements 13-52, at each input angle ``deg`` (deg): the rows t2, t3, t4,
    alp + t3 (rad), om3 (rad/s), alph3 (rad/s^2), cos and sin of t2, t3, t4 and alp + t3,
    cot(t4 - t3), the accelerations (in/s^2) of the crank pin A, XAA, YAA, and of the follower
    pin B, XBA, YBA (the Case II listing's; ``b_sign`` the sign of L3*ALPH3*SIN(T3) in XBA, D032),
    and the two discriminants."""
    out = np.empty((21, deg.size))
    for n in range(deg.size):
        t2 = (deg[n] * 2.0 * pi) / 360.0
        c2, s2 = math.cos(t2), math.sin(t2)
        t3, t4, disc3, disc4 = half_angle_roots(c2, s2, k1, k2, k3, k4, k5)
        ext_angle = alp + t3
        c3, s3, c4, s4 = math.cos(t3), math.sin(t3), math.cos(t4), math.sin(t4)
        ce, se = math.cos(ext_angle), math.sin(ext_angle)
        s43 = math.sin(t4 - t3)
        s_om3 = s43 if omega3_sign else math.sin(t4 - t2)                               # D013
        om3 = (l1 * om2 * s_om3) / (l3 * math.sin(t3 - t4))
        om4 = (l1 * om2 * math.sin(t2 - t3)) / (l4 * s43)
        aj, bj = l4 * s4, l3 * s3
        cj = (l1 * om2 * om2 * c2) + (l3 * om3 * om3 * c3) - (l4 * om4 * om4 * c4)
        dj, ej = l4 * c4, l3 * c3
        fj = (l4 * om4 * om4 * s4) - (l1 * om2 * om2 * s2) - (l3 * om3 * om3 * s3)
        alph3 = (cj * dj - aj * fj) / (aj * ej - bj * dj)           # input speed constant: ALPH2 = 0
        ctx = math.cos(t4 - t3) / s43
        xaa, yaa = -(l1 * c2 * om2 * om2), -(l1 * s2 * om2 * om2)
        xba = -(l1 * om2 * om2 * c2) - (l3 * om3 * om3 * c3) + b_sign * (l3 * alph3 * s3)
        yba = -(l1 * om2 * om2 * s2) - (l3 * om3 * om3 * s3) + (l3 * alph3 * c3)
        row = (t2, t3, t4, ext_angle, om3, alph3, c2, s2, c3, s3, c4, s4, ce, se, ctx, xaa, yaa, xba, yba,
               disc3, disc4)
        for i in range(21):
            out[i, n] = row[i]
    return out


@njit(cache=True, error_model="numpy")
def _source_beta(l2, l1, l3, c2, s2, c3, s3, c4, s4, ce, se, ctx, g_coefficient, i_coefficient):
    """Source listing, statements 53-106: beta (len(l2), N, 8, 3) of the path point at each
    extender length ``l2`` (in) and input angle, and G1, H1, I1 of its coupler equilibrium
    (eqs. 10-13: P = [a b c; d e f; g h i] for f4, f5, f6), (3, len(l2), N)."""
    beta = np.zeros((l2.size, c2.size, 8, 3))
    ghi = np.empty((3, l2.size, c2.size))
    for j in range(l2.size):
        r = l2[j]
        for n in range(c2.size):
            g_trig = c2[n] if g_coefficient else s2[n]                                   # D014
            g1 = -(r * ce[n] * g_trig) + (r * se[n] * c2[n])
            h1 = -(r * ce[n] * c2[n]) - (r * se[n] * s2[n])
            i_len = r if i_coefficient else l3                                          # D015
            i1 = s4[n] * ((i_len * c3[n]) - (r * ce[n])) + c4[n] * ((r * se[n]) - (l3 * s3[n]))
            beta[j, n, 0, 0], beta[j, n, 0, 1] = ce[n], se[n]
            beta[j, n, 1, 0], beta[j, n, 1, 1] = -se[n], ce[n]
            beta[j, n, 2, 2] = 1.0
            _inverse_rows(beta, j, n, c2[n], -s2[n], c4[n], s2[n], c2[n], s4[n], g1, h1, i1)
            beta[j, n, 6, 0] = ctx[n] * se[n] * (r / l3)
            beta[j, n, 6, 1] = -ce[n] * ctx[n] * (r / l3)
            beta[j, n, 6, 2] = -ctx[n] / l3
            beta[j, n, 7, 0], beta[j, n, 7, 1], beta[j, n, 7, 2] = -se[n] * r, ce[n] * r, 1.0
            ghi[0, j, n], ghi[1, j, n], ghi[2, j, n] = g1, h1, i1
    return beta, ghi


@dataclass
class SourceLinkage(Linkage):
    """The source four-bar over the input angles (listing statements 13-52), a Linkage:
    ``ext_angle`` = alp + t3, ``ctx`` = cot(t4 - t3)."""
    alp: float
    ctx: np.ndarray
    DETERMINANT_BUGS = (("g_coefficient", "D014"), ("i_coefficient", "D015"))

    def loops(self) -> tuple[list, list]:
        lengths = self.lengths
        loop = (lengths.l1, lengths.l3, lengths.l4, lengths.l5)
        return [loop], [lengths.l2, *loop]

    def _point(self, l2):
        return _path_points(_extender_lengths(l2), self.lengths.l1, self.om2, self.om3, self.alph3,
                            self.c2, self.s2, self.ce, self.se, self.ce, self.se, False)

    def path_point(self, l2) -> Mechanics:
        """The path point ``l2`` (in) along the extender (statements 53-106): its position,
        acceleration and beta.  ``l2`` a number, or an (n, 1) array for n points at once."""
        l1, l3, quirks = self.lengths.l1, self.lengths.l3, self.quirks
        position, acc = self._point(l2)
        beta, ghi = _source_beta(_extender_lengths(l2), l1, l3, self.c2, self.s2, self.c3, self.s3, self.c4,
                                 self.s4, self.ce, self.se, self.ctx, quirks.g_coefficient, quirks.i_coefficient)
        if not np.ndim(l2):
            position, acc, beta, ghi = position[:, 0], acc[0], beta[0], ghi[:, 0]
        g1, h1, i1 = ghi
        coefficients = (self.c2, -self.s2, self.c4, self.s2, self.c2, self.s4, g1, h1, i1)
        return Mechanics(position[0], position[1], acc, beta, (l2, l1, l3, self.lengths.l4),
                         extra={"t2": self.t2, "t3": self.t3, "t4": self.t4, "om2": self.om2, "om3": self.om3,
                                "alph3": self.alph3, "alp": self.alp, "ext_angle": self.ext_angle,
                                "ctx": self.ctx, "coefficients": coefficients, "linkage": self})


def source_linkage(deg, lengths: Lengths = EXAMPLE.lengths, alp: float | None = None,
                   rpm: float | None = None, quirks: Quirks = PRINTED,
                   speed_type: str = "INTEGER") -> SourceLinkage:
    """The source four-bar's motion over ``deg`` (listing statements 13-52), arguments and
    defaults as source_mechanics; ``lengths.l2`` is not used (see ``path_point``)."""
    return _source_linkage(angles_deg("deg", deg), lengths, alp, rpm, quirks, speed_type)


def _source_linkage(deg: np.ndarray, lengths: Lengths, alp: float | None, rpm: float | None, quirks: Quirks,
                    speed_type: str) -> SourceLinkage:
    """source_linkage of checked angles ``deg``."""
    expect("lengths", lengths, Lengths)
    expect("quirks", quirks, Quirks)
    if speed_type not in ("INTEGER", "REAL"):
        raise ValueError(f"speed_type must be 'INTEGER' or 'REAL', got {speed_type!r}")
    pi = _pi(quirks)
    if alp is None:
        alp = ALP_SOURCE_LISTING if quirks.source_alpha_101 else pi / 3.0
    if rpm is None:
        rpm = 400.0 if quirks.source_rpm_400 else EXAMPLE.rpm
    alp, rpm = parameter("alp", alp), speed_rpm(rpm)
    if quirks.real4_storage:
        rpm = float(np.trunc(rpm)) if speed_type == "INTEGER" else float(np.float32(rpm))
    l1, l3, l4, l5 = lengths.l1, lengths.l3, lengths.l4, lengths.l5
    om2 = (2.0 * pi * rpm) / 60.0
    motion = _source_motion(deg, pi, *freudenstein_constants(l1, l3, l4, l5), l1, l3, l4, alp, om2,
                            quirks.omega3_sign, 1.0 if quirks.joint_b_acceleration_sign else -1.0)
    t2, t3, t4, ext_angle, om3, alph3, c2, s2, c3, s3, c4, s4, ce, se, ctx = motion[:15]
    raise_if_cannot_close(deg, "source", *motion[19:], toggle=None if quirks.toggle_as_open else (pi, l1, l3, l4, l5))
    return SourceLinkage(deg=deg, lengths=lengths, quirks=quirks, t2=t2, t3=t3, t4=t4, ext_angle=ext_angle, om2=om2,
                         om3=om3, alph3=alph3, c2=c2, s2=s2, c3=c3, s3=s3, c4=c4, s4=s4, ce=ce, se=se,
                         pins=motion[15:19], alp=alp, ctx=ctx)


def source_mechanics(deg, lengths: Lengths = EXAMPLE.lengths, alp: float | None = None,
                     rpm: float | None = None, quirks: Quirks = PRINTED,
                     speed_type: str = "INTEGER") -> Mechanics:
    """Kinematics and beta of the source four-bar (listing statements 20-106).

    ``alp`` (rad) and ``rpm`` default to the example data (60 deg, 300 rpm), or
    to the listing's 101 deg and 400 rpm where the quirks D012 and D017 are on.
    ``speed_type`` is how the listing stores the speed: the Case I listing in the
    INTEGER N, Cases II and III in a REAL*4 variable.  ``extra["linkage"]`` is the
    SourceLinkage (``pin_accelerations``: the crank and follower pins', Case II).
    SingularPositionError where a position, acceleration or beta is not finite (a change
    point, a dead centre), as the programs report it.
    """
    return _finite(source_linkage(deg, lengths, alp, rpm, quirks, speed_type).path_point(lengths.l2), "source")
