"""Case II of Ali (1977): each link's mass lumped at a joint, eight system forces.

delta = beta1^T F beta2 P (eq. 32): beta1 the Case I force transformation (8x3),
beta2 (8x8) = [beta1 | the columns of eq. (30)], F the Case I flexibility, P the
inertia loads: the extender's mass at the path point (P1, P2), the input link's
at the crank pin (P4 along, P5 across the link), the follower's at its pin (P6,
along), the coupler's at the crank pin (P7, along the coupler).  Each P4..P7 is the
load's component along its element coordinate as beta1 orients it: the crossed cognate's
crank coordinates f4, f5 run along -e2, -n2 (eqs. 20-21), the source's along +e2, +n2;
P7 is the component along -e3 in both (the direction column 7's f4, f5 entries carry).
Masses are density * area * length (density in lbf/in^3, a weight).
The thesis keeps only the coupler's and the follower's inertia loads along their links (P7, P6):
a modelling choice, not a bug, which the corrected engine keeps (D185); ``lumped="full"`` adds
the two components it leaves out (``transverse``), the masses' whole inertia forces.
Units: inch, pound-force, second; degrees for ``deg``.  Arguments and errors as in
``ali1977.case1`` (the density, like the section, is the listing's REAL*4 literal).
"""
from __future__ import annotations

import functools
from types import SimpleNamespace

import numpy as np
from numba import njit

from ...checks import angles_deg, as_real4, weight_lbf
from .. import libm
from .fourbar import Lengths
from .cognate import _cognate_linkage
from .data import EXAMPLE, _pi, expect
from .source import _source_linkage
from .structure import GRAVITY_IN, GRAVITY_REAL4, Section, deflection, flexibility, magnitude
from .quirks import PRINTED, Quirks
from ..real4 import store

#: The bugs the Case II source listing has (those of Case I's source listing but the
#: 101 deg coupler angle and the 400 rpm, which are the Case I listing's alone).
LISTING = PRINTED.without("source_alpha_101", "source_rpm_400", "cognate_frame", "cognate_moment_row",
                          "node_mass_from_pin", "uncoupled_nodes", "cognate_joint_load_signs")
#: The cognate listing's (and reconstruction's) bugs: the Case I cognate's plus the joint loads.
COGNATE_LISTING = PRINTED.without("source_alpha_101", "source_rpm_400", "i_coefficient", "g_coefficient",
                                  "omega3_sign", "node_mass_from_pin", "uncoupled_nodes")
DENSITY = 0.098          # lbf/in^3, aluminium (DNTY)
#: The crossed cognate's crank coordinates f4, f5 run along -e2, -n2 (eqs. 20-21): P4, P5 are
#: the components along them (the source's along +e2, +n2).
COGNATE_CRANK = -1.0
#: The reconstruction's signs for the cognate's loads (D037, D145): P4, P5 along the source's
#: +e2, +n2, and P7 reversed (the coupler's axis from the crank pin, -e3, B' = A' - CL3 e3): the
#: sign Table II prefers, against the cognate's own f4, f5 and column 7.
RECONSTRUCTION_CRANK, RECONSTRUCTION_COUPLER = 1.0, -1.0
#: How the coupler's mass (at the crank pin A) and the follower's (at its pin B) load the
#: structure: "axial", the thesis's (eq. 30: their components along the coupler, P7, and the
#: follower, P6), or "full", their whole inertia forces (``transverse`` adds P9, P10; D185)
LUMPED = ("axial", "full")
#: the quirks that shape the joint loads; "full" adds the corrected loads' missing components, so
#: it takes these off
LOAD_QUIRKS = ("inertia_sign", "joint_load_components", "joint_b_acceleration_sign", "coupler_load_in_f7",
               "cognate_joint_load_signs")


_P4_TO_P8 = np.arange(3, 8)


def beta2(mech, quirks: Quirks, cognate: bool = False) -> np.ndarray:
    """beta2 (N, 8, 8): beta1, then P4..P8 into f4, f5, f6, (f4, f5, f7), f8: eq. (30),
    or for the crossed cognate eq. (31), with cos, sin(t3* - t2) in column 7; REAL*4 as the
    listing stores it where ``quirks.real4_storage``.  Column 7 is the coupler's load at the
    crank pin: f7 = P7 only where ``quirks.coupler_load_in_f7`` (the listings' B(55)=1.0,
    U(55)=1.0, D144); a load at the pin carries no coupler force, f7 = 0."""
    t2, t3 = mech.extra["t2"], mech.extra["t3"]
    right = np.zeros(mech.beta.shape[:-1] + (8,), np.float32 if quirks.real4_storage else np.float64)
    right[..., :3] = mech.beta
    right[..., _P4_TO_P8, _P4_TO_P8] = 1.0
    turn = t3 - t2 if cognate else t2 - t3
    right[..., 3, 6] = libm.cos(turn) if cognate else -libm.cos(turn)
    right[..., 4, 6] = libm.sin(turn)
    if not quirks.coupler_load_in_f7:                                               # D144
        right[..., 6, 6] = 0.0
    return right


def joint_loads(mech, lengths: Lengths, density: float, area: float, quirks: Quirks,
                cognate: bool = False) -> np.ndarray:
    """P1..P8 (N, 8) in lbf, as the listing forms them (statements 56-72); the pins'
    accelerations are the linkage's (``mech.extra["linkage"].pin_accelerations()``).
    ``cognate``: the crossed cognate's loads (a RECONSTRUCTION, D037): P4, P5 along its crank
    coordinates -e2, -n2 (COGNATE_CRANK) and P7 along -e3 as the source's, or, where
    ``quirks.cognate_joint_load_signs``, the reconstruction's signs (D145)."""
    link = mech.extra["linkage"]
    (xaa, yaa), (xba, yba) = link.pin_accelerations()
    m1, m2, m3, m4 = (density * (area * length) for length in (lengths.l1, lengths.l2, lengths.l3, lengths.l4))
    crank, coupler = 1.0, 1.0
    if cognate:
        crank, coupler = ((RECONSTRUCTION_CRANK, RECONSTRUCTION_COUPLER) if quirks.cognate_joint_load_signs  # D145
                          else (COGNATE_CRANK, 1.0))
    return _joint_loads(np.ascontiguousarray(mech.acc), xaa, yaa, xba, yba, link.c2, link.s2, link.c3, link.s3,
                        link.c4, link.s4, m1, m2, m3, m4, GRAVITY_REAL4 if quirks.real4_storage else GRAVITY_IN,
                        quirks.real4_storage, quirks.joint_load_components, quirks.inertia_sign, crank, coupler)


@njit(cache=True, error_model="numpy")
def _joint_loads(acc, xaa, yaa, xba, yba, c2, s2, c3, s3, c4, s4, m1, m2, m3, m4, g_const, real4, components,
                 plus_m_a, crank, coupler):
    """joint_loads at each input angle (compiled as ali1977.linkage's kernels are): the path point's
    XPA, YPA (in/s^2, REAL*4 with ``real4``), the pins' XAA..YBA, the cos and sin of t2, t3, t4,
    the links' weights m1..m4 (lbf), g (in/s^2) and the signs of P4, P5 (``crank``) and of P7
    (``coupler``), +1 or -1 (joint_loads)."""
    loads = np.empty((c2.size, 8))
    for n in range(c2.size):
        xpa, ypa = acc[n, 0], acc[n, 1]
        if real4:                                                                   # XPA, YPA are REAL*4
            xpa, ypa = np.float64(np.float32(xpa)), np.float64(np.float32(ypa))
        if components:                                                              # D031
            p5 = m1 * (yaa[n] * s2[n] - xaa[n] * c2[n])
            p6 = m4 * (yba[n] * s4[n] - xba[n] * c4[n])
            p7 = m3 * (yaa[n] * s3[n] - xaa[n] * c3[n])
        else:   # along the element coordinates: f5 across the crank, f6 along the follower, -e3 (eq. 30)
            p5 = m1 * (-xaa[n] * s2[n] + yaa[n] * c2[n])
            p6 = m4 * (xba[n] * c4[n] + yba[n] * s4[n])
            p7 = m3 * (-xaa[n] * c3[n] - yaa[n] * s3[n])
        p4 = crank * (m1 * (xaa[n] * c2[n] + yaa[n] * s2[n]))                        # exact: signs
        p5, p7 = crank * p5, coupler * p7
        row = ((m2 * xpa) / g_const, (m2 * ypa) / g_const, 0.0, p4 / g_const, p5 / g_const, p6 / g_const,
               p7 / g_const, 0.0)
        for i in range(8):
            loads[n, i] = row[i] if plus_m_a else -row[i]                          # D018
    return loads


def transverse(mech, lengths, density: float, area: float, quirks: Quirks,
               cognate: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """The two inertia loads the thesis leaves out (D185) and their columns of beta2: P9, P10
    (N, 2) in lbf, the coupler's inertia force across the coupler at the crank pin A (along
    n3 = (-sin t3, cos t3)) and the follower's across the follower at its pin B (along
    n4 = (-sin t4, cos t4)), each -(m/g) a . n; and (N, 8, 2) the element forces of a unit load
    each.  A load at A goes into the crank's coordinates f4, f5 (along d4, d5: +-e2, +-n2); one
    at B into the follower's axial force f6 (along u4) and, for the rest, which lies along the
    coupler (pinned at A and B, it takes no moment from a load at its pin), the coupler's axial
    force f7 and through it f4, f5: f6 = (b x n4) / (b x u4), the rest n4 - f6 u4 = f7 b, b the
    coupler's direction from A to B (e3 for the source, -e3 for the crossed cognate, whose
    B' = A' - CL3 e3 and crank coordinates run along -e2, -n2)."""
    link = mech.extra["linkage"]
    (xaa, yaa), (xba, yba) = link.pin_accelerations()
    side = -1.0 if cognate else 1.0
    d4, d5 = side * np.array([link.c2, link.s2]), side * np.array([-link.s2, link.c2])
    b, u4 = side * np.array([link.c3, link.s3]), np.array([link.c4, link.s4])
    n3, n4 = np.array([-link.s3, link.c3]), np.array([-link.s4, link.c4])
    dot = lambda p, q: p[0] * q[0] + p[1] * q[1]                    # noqa: E731
    f6 = (b[0] * n4[1] - b[1] * n4[0]) / (b[0] * u4[1] - b[1] * u4[0])
    rest = n4 - f6 * u4
    columns = np.zeros(link.c2.shape + (8, 2))
    columns[..., 3, 0], columns[..., 4, 0] = dot(n3, d4), dot(n3, d5)
    columns[..., 3, 1], columns[..., 4, 1], columns[..., 5, 1], columns[..., 6, 1] = (
        dot(rest, d4), dot(rest, d5), f6, dot(rest, b))
    g = GRAVITY_REAL4 if quirks.real4_storage else GRAVITY_IN
    m3, m4 = (density * (area * length) / g for length in (lengths.l3, lengths.l4))
    loads = np.stack([-m3 * dot(np.array([xaa, yaa]), n3), -m4 * dot(np.array([xba, yba]), n4)], axis=-1)
    return loads, columns


def _lumped(lumped, quirks: Quirks) -> bool:
    """Whether ``lumped`` (LUMPED) asks for the whole inertia forces; TypeError, ValueError for
    another value, ValueError for "full" with a quirk of LOAD_QUIRKS on."""
    if not isinstance(lumped, str):
        raise TypeError(f"lumped must be one of {LUMPED}, got {type(lumped).__name__} {lumped!r}")
    if lumped not in LUMPED:
        raise ValueError(f"lumped must be one of {LUMPED}, got {lumped!r}")
    on = [name for name in LOAD_QUIRKS if getattr(quirks, name)]
    if lumped == "full" and on:
        raise ValueError(f"lumped='full' completes the corrected joint loads: switch off the quirks {on}")
    return lumped == "full"


def _with_transverse(mech, lengths, density: float, area: float, quirks: Quirks, cognate: bool,
                     loads: np.ndarray, right: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``loads`` (N, 8) and beta2 ``right`` (N, 8, 8) with ``transverse``'s P9, P10 and columns added."""
    more, columns = transverse(mech, lengths, density, area, quirks, cognate)
    return (np.concatenate([loads, store(more, quirks.real4_storage)], axis=-1),
            np.concatenate([right, store(columns, quirks.real4_storage)], axis=-1))


def case2_source(deg, lengths: Lengths = EXAMPLE.lengths, alp: float | None = None,
                 rpm: float = EXAMPLE.rpm, density: float = DENSITY,
                 section: Section = EXAMPLE.section, quirks: Quirks = LISTING, lumped: str = "axial") -> dict:
    """Case II, source four-bar: ``xp, yp`` (in), ``dx, dy`` (in) and ``rot`` (rad); ``lumped``
    (LUMPED): the thesis's axial loads of the coupler's and the follower's masses, or their whole
    inertia forces (D185; the corrected loads only)."""
    out, finish = run_case2_source(angles_deg("deg", deg), lengths, alp, rpm, density, section, quirks, lumped)
    return finish(out, "case II source")


def run_case2_source(deg: np.ndarray, lengths: Lengths, alp: float | None, rpm: float, density: float,
                     section: Section, quirks: Quirks, lumped: str = "axial"):
    """case2_source of checked angles ``deg``, before its precision check (as
    ``case1.run_source_case1``)."""
    density = weight_lbf("density", density)
    expect("section", section, Section)
    expect("quirks", quirks, Quirks)
    full = _lumped(lumped, quirks)
    real4 = quirks.real4_storage
    alp = _pi(quirks) / 3.0 if alp is None else alp
    mech = _source_linkage(deg, lengths, alp, rpm, quirks, "REAL").path_point(lengths.l2)
    sec = section.as_listing_holds(real4)
    dens = as_real4("density", density) if real4 else density
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        loads = store(joint_loads(mech, lengths, dens, sec.area, quirks), real4)
        flex = flexibility(lengths.l2, lengths.l1, lengths.l3, lengths.l4, sec, quirks)
        right = beta2(mech, quirks)
        if full:
            loads, right = _with_transverse(mech, lengths, dens, sec.area, quirks, False, loads, right)
        delta = deflection(mech.beta, flex, loads, quirks, right=right)
    out = {"xp": mech.xp, "yp": mech.yp, "dx": delta[:, 0].astype(np.float64),
           "dy": delta[:, 1].astype(np.float64), "rot": delta[:, 2].astype(np.float64)}
    link = mech.extra["linkage"]
    return out, functools.partial(link.finish, rho=link.pole_distance(mech),
                                  size=magnitude(mech.beta, flex, loads, right), extender=lengths.l2)


def case2_cognate(deg, lengths: Lengths = EXAMPLE.lengths, alp: float | None = None,
                  rpm: float = EXAMPLE.rpm, density: float = DENSITY,
                  section: Section = EXAMPLE.section, quirks: Quirks = COGNATE_LISTING,
                  lumped: str = "axial") -> dict:
    """Case II, crossed cognate: a RECONSTRUCTION (D037).  The listing's page with the loads
    is missing; its loads are the source listing's (joint_loads) on the cognate's links
    (density * area * CLk) and joints (crank pin A' = CL1 e^{i t2}, follower pin
    B' = A' - CL3 e^{i t3*}), in the cognate's frame; P4, P5, P7 along the cognate's own element
    coordinates (joint_loads), or with the reconstruction's signs where
    ``quirks.cognate_joint_load_signs`` (D145); ``lumped`` as case2_source's.  Returns ``xp, yp``
    (source), ``cxp, cyp``, ``dx, dy`` (in) and ``rot`` (rad)."""
    out, finish = run_case2_cognate(angles_deg("deg", deg), lengths, alp, rpm, density, section, quirks,
                                    lumped=lumped)
    return finish(out, "case II cognate")


def run_case2_cognate(deg: np.ndarray, lengths: Lengths, alp: float | None, rpm: float, density: float,
                      section: Section, quirks: Quirks, warn_beta: bool = True, lumped: str = "axial"):
    """case2_cognate of checked angles ``deg``, before its precision check (as
    ``case1.run_cognate_case1``)."""
    density = weight_lbf("density", density)
    expect("section", section, Section)
    expect("quirks", quirks, Quirks)
    full = _lumped(lumped, quirks)
    real4 = quirks.real4_storage
    mech = _cognate_linkage(deg, lengths, alp, rpm, quirks, warn_beta).path_point()
    cog, e = mech.extra["cognate"], mech.extra
    sec = section.as_listing_holds(real4)
    dens = as_real4("density", density) if real4 else density
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        # the cognate's links as they are (a degenerate cognate may have zero or NaN lengths)
        cog_lengths = SimpleNamespace(l1=cog.cl1, l2=cog.cl2, l3=cog.cl3, l4=cog.cl4, l5=cog.cl5)
        loads = store(joint_loads(mech, cog_lengths, dens, sec.area, quirks, cognate=True), real4)
        flex = flexibility(cog.cl2, cog.cl1, cog.cl3, cog.cl4, sec, quirks)
        right = beta2(mech, quirks, cognate=True)
        if full:
            loads, right = _with_transverse(mech, cog_lengths, dens, sec.area, quirks, True, loads, right)
        delta = deflection(mech.beta, flex, loads, quirks, right=right)
        size = magnitude(mech.beta, flex, loads, right)
    dx, dy = delta[:, 0].astype(np.float64), delta[:, 1].astype(np.float64)
    if not quirks.cognate_frame:                                                     # D025
        c, s = libm.cos(mech.frame_angle), libm.sin(mech.frame_angle)
        dx, dy = dx * c - dy * s, dx * s + dy * c
    out = {"xp": e["xp"], "yp": e["yp"], "cxp": e["cxp"], "cyp": e["cyp"], "dx": dx, "dy": dy,
           "rot": delta[:, 2].astype(np.float64)}
    link = mech.extra["linkage"]
    return out, functools.partial(link.finish, rho=link.pole_distance(mech), size=size, extender=cog.cl2)


__all__ = ["LISTING", "COGNATE_LISTING", "DENSITY", "COGNATE_CRANK", "RECONSTRUCTION_CRANK", "RECONSTRUCTION_COUPLER",
           "LUMPED", "LOAD_QUIRKS", "beta2", "joint_loads", "transverse", "case2_source", "case2_cognate"]
