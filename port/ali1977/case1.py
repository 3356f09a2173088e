"""Case I of Ali (1977): lumped mass at the path point, flexibility method.

delta = beta^T F beta P  (eq. 6), for the source four-bar (eqs. 9-18) and its
crossed coupler cognate (eqs. 19-28), with the 8x8 element flexibility F of
eq. (29) and the inertia load P of the path-point mass.

Units: inch, pound-force, second; ``alp`` in radians; input angles ``deg`` in
degrees; ``rpm`` in rev/min; ``mass_lbf`` a weight in lbf (mass = W/g,
g = 32.178*12 in/s^2 as the listings divide).  Deflections come out in inches,
rotations in radians.  Everything is vectorised over the input angles: the statements the
listings execute at each angle (positions, speeds, accelerations, beta) are loops over the
angles compiled by numba (below, "The listings' statements at each input angle"), the
matrices' products MPRD's (``real4.product``), the rest numpy.  A ``SourceLinkage`` or
``CognateLinkage`` is the four-bar's motion over the angles, once; ``path_point`` puts the
path point on it at any distance along the extender (Case III's nodes).

Arguments (every public function of the Ali ports): ``deg`` a non-empty 1-D array of
finite input angles (a scalar or 0-D array is refused like a 2-D one: ValueError; a
non-numeric dtype: TypeError); ``lengths`` a ``Lengths``, ``section`` a ``Section``,
``quirks`` a ``Quirks`` (TypeError otherwise); ``alp`` finite; ``rpm`` finite with
|rpm| <= 2**31 - 1; a weight or density finite, >= 0 and representable in REAL*4.
Section values and densities are the listings' REAL*4 literals: with ``real4_storage``
they are rounded to single precision first (ValueError if that gives 0 or infinity), so
``Section(a, e, i)`` here is the legacy build called with ``area=float32(a)``, ....
A linkage that cannot close raises AssemblyError at the first input angle where the
listing's test fails (source and cognate loops tested angle by angle); a result that is not
finite raises SingularPositionError at the first angle where the first non-finite quantity
(in the order the results are returned) is not finite: both as the legacy face does.

With ``quirks=PRINTED`` the formulas, the order of operations and the REAL*4
storage are the listings', and the results equal the legacy build's.  Each
quirk switched off removes one bug of the original (see ``quirks.py``).
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

import numpy as np
from numba import njit

from ...checks import angles_deg, as_real4, parameter, speed_rpm, weight_lbf
from .. import libm
from .conditioning import check_precision, condition, spread
from .fourbar import (Cognate, Lengths, cannot_close, check_finite, freudenstein_constants, half_angle_roots,
                      raise_first_assembly_failure, raise_if_cannot_close, warn_listing_beta)
from .quirks import CORRECTED, PRINTED, Quirks
from ..real4 import product, store

#: The listings' PI=3.142857143 (22/7) as the REAL*4 literal holds it (D011).
PI_22_7 = float(np.float32(3.142857143))
#: The source listing's ALP=1.762782545 rad (101 deg) as REAL*4 holds it (D012).
ALP_SOURCE_LISTING = float(np.float32(1.762782545))
#: g in in/s^2 as the listings write it (12.0*32.178), and as Cases II and III compute it
#: (GC=32.178*12.0 in REAL*4).
GRAVITY_IN = 12.0 * 32.178
GRAVITY_REAL4 = float(np.float32(32.178) * np.float32(12.0))

__all__ = ["Section", "EXAMPLE", "Mechanics", "Linkage", "SourceLinkage", "CognateLinkage", "source_linkage",
           "cognate_linkage", "source_mechanics", "cognate_mechanics", "case1_deflection", "source_case1",
           "cognate_case1", "PRINTED", "CORRECTED", "Quirks"]


@dataclass(frozen=True)
class Section:
    """Uniform cross-section of every link: area (in^2), Young's modulus (psi),
    second moment of area (in^4); each positive and within what the listings' REAL*4 literals
    hold (about 1.4e-45 to 3.4e38: a subnormal double modulus divided F by zero)."""
    area: float
    modulus: float
    inertia: float

    def __post_init__(self):
        for name in ("area", "modulus", "inertia"):     # positive, and what a REAL*4 literal can hold
            value = parameter(f"section {name}", getattr(self, name), positive=True, largest=None)
            as_real4(f"section {name}", value, positive=True)
            object.__setattr__(self, name, value)

    @functools.lru_cache(maxsize=256)      # a pure function of the (immutable) section, asked for on every call
    def as_listing_holds(self, real4: bool) -> "Section":
        """The listing assigns REAL*4 literals to its DOUBLE section variables (ValueError if
        a value is 0 or infinite in single precision)."""
        if not real4:
            return self
        return Section(*(as_real4(f"section {name}", getattr(self, name), positive=True)
                         for name in ("area", "modulus", "inertia")))


@dataclass(frozen=True)
class Example:
    """Chapter IV, "Data for Numerical Example" (and the listings' constants)."""
    lengths: Lengths = Lengths(10.0, 10.0, 30.0, 25.0, 30.0)
    alpha_deg: float = 60.0
    rpm: float = 300.0
    mass_lbf: float = 2.0
    section: Section = Section(0.1963495408, 10000000.0, 0.0030679615)


EXAMPLE = Example()


#: numpy's floating-point warnings off (a decorator): at a singular position the listings
#: compute on through IEEE infinities and NaN, and check_finite reports where a result is not finite.
ieee = np.errstate(divide="ignore", invalid="ignore", over="ignore")


def _pi(quirks: Quirks) -> float:
    return PI_22_7 if quirks.pi_22_7 else np.pi


def expect(name: str, value, kind: type):
    """TypeError unless ``value`` is a ``kind`` (Lengths, Section, Quirks)."""
    if not isinstance(value, kind):
        raise TypeError(f"{name} must be a {kind.__name__}, got {type(value).__name__} {value!r}")
    return value


def inertia_load(acc, mass_lbf, quirks: Quirks):
    """System forces P1, P2, P3 (lbf, last axis) of a point mass of weight ``mass_lbf`` with
    acceleration ``acc`` (.., 2) in/s^2; P3 = 0 (no rotary inertia).

    The listings store the acceleration and the force in REAL*4 and use +m*a;
    the inertia (d'Alembert) force is -m*a (D018).
    """
    real4 = quirks.real4_storage
    sign = 1.0 if quirks.inertia_sign else -1.0
    acc = store(acc, real4)
    if real4:
        m, g = np.float32(mass_lbf), np.float32(12.0) * np.float32(32.178)
    else:
        m, g = float(mass_lbf), GRAVITY_IN
    load = np.zeros(acc.shape[:-1] + (3,), acc.dtype)
    load[..., :2] = sign * (acc * m / g)
    return load


def flexibility(l_ext, l_in, l_cpl, l_fol, section: Section, quirks: Quirks,
                modulus_first: bool = False) -> np.ndarray:
    """Element flexibility F (8x8) of eq. (29): extender (axial; bending 2x2),
    input link (axial, bending), follower (axial), coupler (axial, end moment).

    ``l_ext`` may be an array of extender lengths (F then has its shape in front).
    ``modulus_first``: the input link's bending term written (L1*L1*L1)/(3.0*CE*CI), as
    the Case III source listing has it, instead of 3.0*CA*ME (or 3.0*CMI*CME): the same
    number in exact arithmetic, the listing's own rounding here."""
    ca, me, mi = section.area, section.modulus, section.inertia
    f = np.zeros(np.shape(l_ext) + (8, 8))
    f[..., 0, 0] = l_ext / (ca * me)
    f[..., 1, 1] = (l_ext * l_ext * l_ext) / (3.0 * me * mi)
    f[..., 2, 1] = f[..., 1, 2] = (l_ext * l_ext) / (2.0 * me * mi)
    f[..., 2, 2] = l_ext / (me * mi)
    f[..., 3, 3] = l_in / (ca * me)
    bending = ca if quirks.input_link_bending_area else mi          # D016
    f[..., 4, 4] = (l_in * l_in * l_in) / ((3.0 * me * bending) if modulus_first else (3.0 * bending * me))
    f[..., 5, 5] = l_fol / (ca * me)
    f[..., 6, 6] = l_cpl / (ca * me)
    f[..., 7, 7] = l_cpl / (3.0 * me * mi)
    return store(f, quirks.real4_storage)


def deflection(beta: np.ndarray, flex: np.ndarray, load: np.ndarray, quirks: Quirks,
               right: np.ndarray | None = None) -> np.ndarray:
    """delta = beta^T F right P (right = beta unless given: Case II's beta2), per angle;
    in the listings' MPRD order and precision."""
    real4 = quirks.real4_storage
    beta = store(beta, real4)
    right = beta if right is None else store(right, real4)
    left = product(np.swapaxes(beta, -1, -2), flex, real4)       # CALL GMTRA; MPRD(A,B,R,3,8,..,8)
    left = product(left, right, real4)                           # MPRD(A,B,R,3,8,..,3 or 8)
    return product(left, load[..., :, None], real4)[..., 0]      # MPRD(A,B,R,3,3 or 8,..,1)


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
    extender length ``cl2`` (in) and input angle (c, s: cos, sin of gam).  Coupler equilibrium of
    the crossed cognate, eqs. (20)-(24): the pin forces f4, f5 act at A along (-cos t2, -sin t2),
    (sin t2, -cos t2); f6 at B along (cos t4, sin t4); the loop is
    CL1 e^{i t2} - CL3 e^{i t3} + CL4 e^{i t4} = CL5."""
    beta = np.zeros((cl2.size, c2.size, 8, 3))
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
    return beta


def _extender_lengths(length) -> np.ndarray:
    """A path point's distance (in) along the extender, or an (n, 1) array of them, as the
    kernels take it: a 1-D float64 array."""
    return np.ascontiguousarray(length, dtype=np.float64).reshape(-1)


@dataclass(frozen=True)
class Mechanics:
    """One mechanism's Case I state over the input angles, in its own frame.

    ``acc`` (N, 2) is the path point's acceleration (in/s^2) as the listing forms
    it; ``beta`` (N, 8, 3) the force-transformation matrix; ``flex_lengths`` the
    (extender, input, coupler, follower) lengths of F; ``frame_angle`` (rad) turns
    the mechanism's frame into the source's (0 for the source).  For several path
    points at once (``path_point`` of an (n, 1) array of extender lengths) every array
    has the points' axis in front: (n, N), (n, N, 2), (n, N, 8, 3).
    """
    xp: np.ndarray
    yp: np.ndarray
    acc: np.ndarray
    beta: np.ndarray
    flex_lengths: tuple
    frame_angle: float = 0.0
    extra: dict = field(default_factory=dict)
@dataclass
class Linkage:
    """A four-bar over the input angles up to its coupler: all that does not depend on where
    the path point sits on the extender (the source's and the cognate's, below).

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

    def finish(self, out: dict, who: str, stacklevel: int = 4) -> dict:
        """A program's results ``out`` checked for their precision (``conditioning``: raise at
        a toggle to working precision, warn where half the digits are gone), with the per-angle
        ``condition`` added."""
        loops, links = self.loops()
        link_spread = spread(links)
        kappa = condition(self.deg, _pi(self.quirks), loops, link_spread)
        check_precision(self.deg, kappa, link_spread, self.quirks.real4_storage, who, stacklevel=stacklevel)
        out["condition"] = kappa
        return out

    def pin_accelerations(self):
        """Accelerations (in/s^2, the mechanism's frame) of the crank pin A, (XAA, YAA), and of the
        follower pin B, (XBA, YBA), as Case II's listing forms them (the source's with D032, a
        sign in XBA; the cognate's a RECONSTRUCTION, D037: that page of the listing is missing)."""
        xaa, yaa, xba, yba = self.pins
        return (xaa, yaa), (xba, yba)


@dataclass
class SourceLinkage(Linkage):
    """The source four-bar over the input angles (listing statements 13-52), a Linkage:
    ``ext_angle`` = alp + t3, ``ctx`` = cot(t4 - t3)."""
    alp: float
    ctx: np.ndarray

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


def _finite(mech: Mechanics, who: str) -> Mechanics:
    """``mech``, or SingularPositionError at the first input angle where its position,
    acceleration or beta is not finite."""
    deg, axis = mech.extra["linkage"].deg, np.ndim(mech.xp) - 1        # the angles' axis: 1 for n points

    def by_angle(values):
        return np.moveaxis(np.asarray(values), axis, 0).reshape(len(deg), -1)

    check_finite(deg, who, xp=by_angle(mech.xp), yp=by_angle(mech.yp),
                 acceleration_and_beta=np.concatenate([by_angle(mech.acc), by_angle(mech.beta)], axis=1))
    return mech


def case1_deflection(mech: Mechanics, mass_lbf: float, section: Section, quirks: Quirks):
    """dx, dy (in, in the source frame unless D025 is on) and rot (rad) of the path point;
    SingularPositionError where they are not finite."""
    expect("mech", mech, Mechanics)
    mass_lbf = weight_lbf("mass_lbf", mass_lbf)
    expect("section", section, Section)
    expect("quirks", quirks, Quirks)
    dx, dy, rot = _case1_deflection(mech, mass_lbf, section, quirks)
    if "linkage" in mech.extra:
        check_finite(mech.extra["linkage"].deg, "case I", dx=dx, dy=dy, rot=rot)
    return dx, dy, rot


@ieee
def _case1_deflection(mech: Mechanics, mass_lbf: float, section: Section, quirks: Quirks):
    """case1_deflection of a checked weight and section."""
    flex = flexibility(*mech.flex_lengths, section.as_listing_holds(quirks.real4_storage), quirks)
    load = inertia_load(mech.acc, mass_lbf, quirks)
    delta = deflection(mech.beta, flex, load, quirks)
    dx, dy = delta[:, 0].astype(np.float64), delta[:, 1].astype(np.float64)
    if mech.frame_angle and not quirks.cognate_frame:       # D025: into the source frame
        turn = mech.frame_angle
        dx, dy = dx * libm.cos(turn) - dy * libm.sin(turn), dx * libm.sin(turn) + dy * libm.cos(turn)
    return dx, dy, delta[:, 2].astype(np.float64)


def source_case1(deg, lengths: Lengths = EXAMPLE.lengths, alp: float | None = None,
                 rpm: float | None = None, mass_lbf: float = 2.0,
                 section: Section = EXAMPLE.section, quirks: Quirks = PRINTED) -> dict:
    """Case I, source four-bar: coupler point ``xp, yp`` (in), its elastic deflection
    ``dx, dy`` (in) and rotation ``rot`` (rad) over ``deg``; see source_mechanics."""
    deg = angles_deg("deg", deg)
    mass_lbf = weight_lbf("mass_lbf", mass_lbf)
    expect("section", section, Section)
    mech = _source_linkage(deg, lengths, alp, rpm, quirks, "INTEGER").path_point(lengths.l2)
    dx, dy, rot = _case1_deflection(mech, mass_lbf, section, quirks)
    out = {"xp": mech.xp, "yp": mech.yp, "dx": dx, "dy": dy, "rot": rot}
    check_finite(deg, "source", **out)
    return mech.extra["linkage"].finish(out, "case I source")


@dataclass
class CognateLinkage(Linkage):
    """The crossed coupler cognate of the source four-bar over the input angles (cognate
    listing, statements 13-60), in its own frame, a Linkage: ``cognate`` its links (Cognate);
    ``gam`` = gamma - t3, ``ext_angle`` = pi - gam; ``cg, sg`` cos and sin of gam; ``cctx`` =
    cot(t3 - t4); ``turn_cos``, ``turn_sin`` of -beta (the turn into the source frame).
    ``xp, yp`` (in): the source's coupler point as this listing computes it (the rigid-mode
    columns of Table I).
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

    def loops(self) -> tuple[list, list]:
        lengths, cog = self.lengths, self.cognate
        loops = [(lengths.l1, lengths.l3, lengths.l4, lengths.l5), (cog.cl1, cog.cl3, cog.cl4, cog.cl5)]
        return loops, [lengths.l2, cog.cl2, *loops[0], *loops[1]]

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
        beta = _cognate_beta(_extender_lengths(cl2), cog.cl3, self.c2, self.s2, self.c3, self.s3, self.c4, self.s4,
                             self.cg, self.sg, self.cctx, self.quirks.cognate_moment_row)
        if not np.ndim(cl2):
            position, acc, beta = position[:, 0], acc[0], beta[0]
        xpp, ypp = position
        xdp = store(xpp - cog.cl5, real4).astype(np.float64)                  # XDP is REAL*4
        cxp = store((xdp * self.turn_cos) - (ypp * self.turn_sin), real4).astype(np.float64) + self.lengths.l5
        cyp = (xdp * self.turn_sin) + (ypp * self.turn_cos)
        return Mechanics(xpp, ypp, acc, beta, (cl2, cog.cl1, cog.cl3, cog.cl4), -cog.beta,
                         extra={"xp": self.xp, "yp": self.yp, "cxp": cxp, "cyp": cyp, "t2": self.t2,
                                "t3": self.t3, "t4": self.t4, "om2": self.om2, "om3": self.om3,
                                "alph3": self.alph3, "cognate": cog, "ext_angle": self.ext_angle,
                                "linkage": self})


def cognate_linkage(deg, lengths: Lengths = EXAMPLE.lengths, alp: float | None = None,
                    rpm: float = EXAMPLE.rpm, quirks: Quirks = PRINTED) -> CognateLinkage:
    """The crossed cognate's motion over ``deg`` (cognate listing, statements 13-60); arguments
    as cognate_mechanics."""
    return _cognate_linkage(angles_deg("deg", deg), lengths, alp, rpm, quirks)


def _cognate_linkage(deg: np.ndarray, lengths: Lengths, alp: float | None, rpm: float,
                     quirks: Quirks) -> CognateLinkage:
    """cognate_linkage of checked angles ``deg``."""
    expect("lengths", lengths, Lengths)
    expect("quirks", quirks, Quirks)
    pi = _pi(quirks)
    if alp is None:
        alp = pi / 3.0
    alp, rpm = parameter("alp", alp), speed_rpm(rpm)
    speed = float(np.float32(rpm)) if quirks.real4_storage else float(rpm)       # S is REAL*4 in the listing
    l1, l2, l3, l4, l5 = lengths.l1, lengths.l2, lengths.l3, lengths.l4, lengths.l5
    if quirks.cognate_beta_quadrant:
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
                          turn_sin=turn_sin, xp=xp, yp=yp)


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


def cognate_case1(deg, lengths: Lengths = EXAMPLE.lengths, alp: float | None = None,
                  rpm: float = EXAMPLE.rpm, mass_lbf: float = 2.0,
                  section: Section = EXAMPLE.section, quirks: Quirks = PRINTED) -> dict:
    """Case I, crossed coupler cognate: ``xp, yp`` (the source's coupler point as the
    cognate listing computes it), ``cxp, cyp`` (the cognate's, in the source frame),
    ``dx, dy`` (in) and ``rot`` (rad) over ``deg``; see cognate_mechanics."""
    deg = angles_deg("deg", deg)
    mass_lbf = weight_lbf("mass_lbf", mass_lbf)
    expect("section", section, Section)
    mech = _cognate_linkage(deg, lengths, alp, rpm, quirks).path_point()
    dx, dy, rot = _case1_deflection(mech, mass_lbf, section, quirks)
    out = {"xp": mech.extra["xp"], "yp": mech.extra["yp"], "cxp": mech.extra["cxp"],
           "cyp": mech.extra["cyp"], "dx": dx, "dy": dy, "rot": rot}
    check_finite(deg, "cognate", **out)
    return mech.extra["linkage"].finish(out, "case I cognate")
