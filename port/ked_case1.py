"""Case I of Ali (1977): lumped mass at the path point, flexibility method.

delta = beta^T F beta P  (eq. 6), for the source four-bar (eqs. 9-18) and its
crossed coupler cognate (eqs. 19-28), with the 8x8 element flexibility F of
eq. (29) and the inertia load P of the path-point mass.

Units: inch, pound-force, second; ``alp`` in radians; input angles ``deg`` in
degrees; ``rpm`` in rev/min; ``mass_lbf`` a weight in lbf (mass = W/g,
g = 32.178*12 in/s^2 as the listings divide).  Deflections come out in inches,
rotations in radians.  Everything is vectorised over the input angles.

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

from dataclasses import dataclass, field

import numpy as np

from ..checks import angles_deg, as_real4, parameter, speed_rpm, weight_lbf
from . import libm
from .fourbar import (Cognate, Lengths, cannot_close, check_finite, freudenstein_constants,
                      half_angle_positions, raise_first_assembly_failure)
from .quirks import CORRECTED, PRINTED, Quirks
from .real4 import product, store

#: The listings' PI=3.142857143 (22/7) as the REAL*4 literal holds it (D011).
PI_22_7 = float(np.float32(3.142857143))
#: The source listing's ALP=1.762782545 rad (101 deg) as REAL*4 holds it (D012).
ALP_SOURCE_LISTING = float(np.float32(1.762782545))
#: g in in/s^2 as the listings write it (12.0*32.178).
GRAVITY_IN = 12.0 * 32.178

__all__ = ["Section", "EXAMPLE", "Mechanics", "source_mechanics", "cognate_mechanics", "case1_deflection",
           "source_case1", "cognate_case1", "PRINTED", "CORRECTED", "Quirks"]


@dataclass(frozen=True)
class Section:
    """Uniform cross-section of every link: area (in^2), Young's modulus (psi),
    second moment of area (in^4)."""
    area: float
    modulus: float
    inertia: float

    def __post_init__(self):
        for name in ("area", "modulus", "inertia"):
            object.__setattr__(self, name, parameter(f"section {name}", getattr(self, name), positive=True,
                                                     largest=None))

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


def _pi(quirks: Quirks) -> float:
    return PI_22_7 if quirks.pi_22_7 else np.pi


def expect(name: str, value, kind: type):
    """TypeError unless ``value`` is a ``kind`` (Lengths, Section, Quirks)."""
    if not isinstance(value, kind):
        raise TypeError(f"{name} must be a {kind.__name__}, got {type(value).__name__} {value!r}")
    return value


def input_angles(deg, quirks: Quirks) -> np.ndarray:
    """T2 (rad) as the listings form it: (P2*2.0*PI)/360.0; ``deg`` as ``linkrepro.checks.angles_deg``."""
    return (angles_deg("deg", deg) * 2.0 * _pi(quirks)) / 360.0


def inertia_load(acc_x, acc_y, mass_lbf, quirks: Quirks):
    """System forces P1, P2 (lbf) of a point mass of weight ``mass_lbf`` with
    acceleration (acc_x, acc_y) in/s^2; P3 = 0 (no rotary inertia).

    The listings store the acceleration and the force in REAL*4 and use +m*a;
    the inertia (d'Alembert) force is -m*a (D018).
    """
    real4 = quirks.real4_storage
    sign = 1.0 if quirks.inertia_sign else -1.0
    ax, ay = store(acc_x, real4), store(acc_y, real4)
    if real4:
        m, g = np.float32(mass_lbf), np.float32(12.0) * np.float32(32.178)
    else:
        m, g = float(mass_lbf), GRAVITY_IN
    zero = np.zeros_like(ax)
    return np.stack([sign * (ax * m / g), sign * (ay * m / g), zero], axis=-1)


def flexibility(l_ext, l_in, l_cpl, l_fol, section: Section, quirks: Quirks,
                modulus_first: bool = False) -> np.ndarray:
    """Element flexibility F (8x8) of eq. (29): extender (axial; bending 2x2),
    input link (axial, bending), follower (axial), coupler (axial, end moment).

    ``modulus_first``: the input link's bending term written (L1*L1*L1)/(3.0*CE*CI), as
    the Case III source listing has it, instead of 3.0*CA*ME (or 3.0*CMI*CME): the same
    number in exact arithmetic, the listing's own rounding here."""
    ca, me, mi = section.area, section.modulus, section.inertia
    f = np.zeros((8, 8))
    f[0, 0] = l_ext / (ca * me)
    f[1, 1] = (l_ext * l_ext * l_ext) / (3.0 * me * mi)
    f[2, 1] = f[1, 2] = (l_ext * l_ext) / (2.0 * me * mi)
    f[2, 2] = l_ext / (me * mi)
    f[3, 3] = l_in / (ca * me)
    bending = ca if quirks.input_link_bending_area else mi          # D016
    f[4, 4] = (l_in * l_in * l_in) / ((3.0 * me * bending) if modulus_first else (3.0 * bending * me))
    f[5, 5] = l_fol / (ca * me)
    f[6, 6] = l_cpl / (ca * me)
    f[7, 7] = l_cpl / (3.0 * me * mi)
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


def _three_by_three_inverse_rows(a, b, c, d, e, f, g, h, i):
    """Rows f4, f5, f6 of beta by Cramer's rule (eq. 14), in the listing's order."""
    r = cramer_determinant(a, b, c, d, e, f, g, h, i)
    return np.stack([
        np.stack([((e * i) - (f * h)) / r, ((c * h) - (b * i)) / r, ((b * f) - (c * e)) / r], -1),
        np.stack([((f * g) - (d * i)) / r, ((a * i) - (c * g)) / r, ((c * d) - (a * f)) / r], -1),
        np.stack([((d * h) - (e * g)) / r, ((b * g) - (a * h)) / r, ((a * e) - (b * d)) / r], -1),
    ], axis=-2)


@dataclass(frozen=True)
class Mechanics:
    """One mechanism's Case I state over the input angles, in its own frame.

    ``acc`` (N, 2) is the path point's acceleration (in/s^2) as the listing forms
    it; ``beta`` (N, 8, 3) the force-transformation matrix; ``flex_lengths`` the
    (extender, input, coupler, follower) lengths of F; ``frame_angle`` (rad) turns
    the mechanism's frame into the source's (0 for the source).
    """
    xp: np.ndarray
    yp: np.ndarray
    acc: np.ndarray
    beta: np.ndarray
    flex_lengths: tuple
    frame_angle: float = 0.0
    extra: dict = field(default_factory=dict)


def source_mechanics(deg, lengths: Lengths = EXAMPLE.lengths, alp: float | None = None,
                     rpm: float | None = None, quirks: Quirks = PRINTED,
                     speed_type: str = "INTEGER") -> Mechanics:
    """Kinematics and beta of the source four-bar (listing statements 20-106).

    ``alp`` (rad) and ``rpm`` default to the example data (60 deg, 300 rpm), or
    to the listing's 101 deg and 400 rpm where the quirks D012 and D017 are on.
    ``speed_type`` is how the listing stores the speed: the Case I listing in the
    INTEGER N, Cases II and III in a REAL*4 variable.  ``extra`` also holds the
    crank-pin and follower-pin accelerations ``acc_a``, ``acc_b`` (in/s^2).
    """
    deg = angles_deg("deg", deg)
    expect("lengths", lengths, Lengths)
    expect("quirks", quirks, Quirks)
    if speed_type not in ("INTEGER", "REAL"):
        raise ValueError(f"speed_type must be 'INTEGER' or 'REAL', got {speed_type!r}")
    pi = _pi(quirks)
    if alp is None:
        alp = ALP_SOURCE_LISTING if quirks.source_alpha_101 else pi / 3.0
    if rpm is None:
        rpm = 400.0 if quirks.source_rpm_400 else EXAMPLE.rpm
    alp, rpm = parameter("alp", alp, largest=None), speed_rpm(rpm)
    if quirks.real4_storage:
        rpm = float(np.trunc(rpm)) if speed_type == "INTEGER" else float(np.float32(rpm))
    l1, l2, l3, l4, l5 = lengths.l1, lengths.l2, lengths.l3, lengths.l4, lengths.l5

    t2 = input_angles(deg, quirks)
    t3, t4 = half_angle_positions(t2, freudenstein_constants(l1, l3, l4, l5), deg, "source")
    om2 = (2.0 * pi * rpm) / 60.0
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        ctx = libm.cos(t4 - t3) / libm.sin(t4 - t3)
        xp = (l1 * libm.cos(t2)) + (l2 * libm.cos(alp + t3))
        yp = (l1 * libm.sin(t2)) + (l2 * libm.sin(alp + t3))
        om3 = (l1 * om2 * libm.sin(t4 - t3 if quirks.omega3_sign else t4 - t2)) / (l3 * libm.sin(t3 - t4))
        om4 = (l1 * om2 * libm.sin(t2 - t3)) / (l4 * libm.sin(t4 - t3))
        aj, bj = l4 * libm.sin(t4), l3 * libm.sin(t3)
        cj = (l1 * om2 * om2 * libm.cos(t2)) + (l3 * om3 * om3 * libm.cos(t3)) - (l4 * om4 * om4 * libm.cos(t4))
        dj, ej = l4 * libm.cos(t4), l3 * libm.cos(t3)
        fj = (l4 * om4 * om4 * libm.sin(t4)) - (l1 * om2 * om2 * libm.sin(t2)) - (l3 * om3 * om3 * libm.sin(t3))
        alph3 = (cj * dj - aj * fj) / (aj * ej - bj * dj)           # input speed constant: ALPH2 = 0
        xpa = -(l1 * om2 * om2 * libm.cos(t2)) - (l2 * om3 * om3 * libm.cos(alp + t3)) - (l2 * alph3 * libm.sin(alp + t3))
        ypa = -(l1 * om2 * om2 * libm.sin(t2)) + (l2 * alph3 * libm.cos(alp + t3)) - (l2 * om3 * om3 * libm.sin(alp + t3))
        # Crank pin A and follower pin B (Case II listing, XAA..YBA).
        xaa, yaa = -(l1 * libm.cos(t2) * om2 * om2), -(l1 * libm.sin(t2) * om2 * om2)
        b_sign = 1.0 if quirks.joint_b_acceleration_sign else -1.0                    # D032
        xba = -(l1 * om2 * om2 * libm.cos(t2)) - (l3 * om3 * om3 * libm.cos(t3)) + b_sign * (l3 * alph3 * libm.sin(t3))
        yba = -(l1 * om2 * om2 * libm.sin(t2)) - (l3 * om3 * om3 * libm.sin(t3)) + (l3 * alph3 * libm.cos(t3))

        # Coupler equilibrium, eqs. (10)-(13): P = [a b c; d e f; g h i] (f4, f5, f6).
        g_trig = libm.cos(t2) if quirks.g_coefficient else libm.sin(t2)                   # D014
        g1 = -(l2 * libm.cos(alp + t3) * g_trig) + (l2 * libm.sin(alp + t3) * libm.cos(t2))
        h1 = -(l2 * libm.cos(alp + t3) * libm.cos(t2)) - (l2 * libm.sin(alp + t3) * libm.sin(t2))
        i_len = l2 if quirks.i_coefficient else l3                                    # D015
        i1 = libm.sin(t4) * ((i_len * libm.cos(t3)) - (l2 * libm.cos(alp + t3))) \
            + libm.cos(t4) * ((l2 * libm.sin(alp + t3)) - (l3 * libm.sin(t3)))
        abc_def = (libm.cos(t2), -libm.sin(t2), libm.cos(t4), libm.sin(t2), libm.cos(t2), libm.sin(t4))
        rows456 = _three_by_three_inverse_rows(*abc_def, g1, h1, i1)
        s, c = libm.sin(t3 + alp), libm.cos(t3 + alp)
        zero, one = np.zeros_like(t2), np.ones_like(t2)
        beta = np.concatenate([
            np.stack([np.stack([c, s, zero], -1), np.stack([-s, c, zero], -1),
                      np.stack([zero, zero, one], -1)], -2),
            rows456,
            np.stack([np.stack([ctx * s * (l2 / l3), -c * ctx * (l2 / l3), -ctx / l3], -1),
                      np.stack([-s * l2, c * l2, one], -1)], -2),
        ], axis=-2)
    return Mechanics(xp, yp, np.stack([xpa, ypa], -1), beta, (l2, l1, l3, l4),
                     extra={"t2": t2, "t3": t3, "t4": t4, "om2": om2, "om3": om3, "alph3": alph3, "alp": alp,
                            "ext_angle": t3 + alp, "ctx": ctx, "coefficients": abc_def + (g1, h1, i1),
                            "acc_a": np.stack([xaa, yaa], -1), "acc_b": np.stack([xba, yba], -1)})


def case1_deflection(mech: Mechanics, mass_lbf: float, section: Section, quirks: Quirks):
    """dx, dy (in, in the source frame unless D025 is on) and rot (rad) of the path point."""
    mass_lbf = weight_lbf("mass_lbf", mass_lbf)
    expect("section", section, Section)
    flex = flexibility(*mech.flex_lengths, section.as_listing_holds(quirks.real4_storage), quirks)
    with np.errstate(invalid="ignore", over="ignore"):   # singular positions: check_finite reports them
        load = inertia_load(mech.acc[:, 0], mech.acc[:, 1], mass_lbf, quirks)
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
    mech = source_mechanics(deg, lengths, alp, rpm, quirks)
    dx, dy, rot = case1_deflection(mech, mass_lbf, section, quirks)
    out = {"xp": mech.xp, "yp": mech.yp, "dx": dx, "dy": dy, "rot": rot}
    check_finite(deg, "source", **out)
    return out


def cognate_mechanics(deg, lengths: Lengths = EXAMPLE.lengths, alp: float | None = None,
                      rpm: float = EXAMPLE.rpm, quirks: Quirks = PRINTED,
                      extender: float | None = None) -> Mechanics:
    """Kinematics and beta of the crossed coupler cognate of the source four-bar
    (``lengths``, ``alp``), in the cognate's own frame (listing statements 20-110).

    ``extra`` holds the source's coupler point ``xp, yp`` as this listing computes it
    (the rigid-mode columns of Table I) and the cognate's ``cxp, cyp`` turned into
    the source frame.  ``extender`` (in) puts the path point at that distance from the
    crank pin along the cognate's extender (default: the whole extender, CL2); Case III
    uses it for its nodes.  ``extra["ext_angle"]`` is the extender's direction (rad).
    """
    deg = angles_deg("deg", deg)
    expect("lengths", lengths, Lengths)
    expect("quirks", quirks, Quirks)
    real4 = quirks.real4_storage
    pi = _pi(quirks)
    if alp is None:
        alp = pi / 3.0
    alp, rpm = parameter("alp", alp, largest=None), speed_rpm(rpm)
    if extender is not None:
        extender = parameter("extender", extender, largest=None)
    speed = float(np.float32(rpm)) if real4 else float(rpm)       # S is REAL*4 in the listing
    l1, l2, l3, l4, l5 = lengths.l1, lengths.l2, lengths.l3, lengths.l4, lengths.l5

    t2 = input_angles(deg, quirks)
    source_k = freudenstein_constants(l1, l3, l4, l5)
    cog = Cognate.of(lengths, alp, pi)
    cognate_k = cog.constants()
    # The listing tests the source loop, then the cognate's, at each angle before the next.
    raise_first_assembly_failure(deg, source=cannot_close(t2, source_k), cognate=cannot_close(t2, cognate_k))
    t3, _ = half_angle_positions(t2, source_k, deg, "source")
    with np.errstate(invalid="ignore", over="ignore"):
        xp = (l1 * libm.cos(t2)) + (l2 * libm.cos(alp + t3))
        yp = (l1 * libm.sin(t2)) + (l2 * libm.sin(alp + t3))

    cl1, cl2, cl3, cl4, cl5 = cog.cl1, cog.cl2 if extender is None else extender, cog.cl3, cog.cl4, cog.cl5
    ct3, ct4 = half_angle_positions(t2, cognate_k, deg, "cognate")
    om2 = (2.0 * pi * speed) / 60.0
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        gam = cog.calp - ct3
        xpp = (cl1 * libm.cos(t2)) + (cl2 * libm.cos(pi - (cog.calp - ct3)))
        ypp = (cl1 * libm.sin(t2)) + (cl2 * libm.sin(pi - (cog.calp - ct3)))
        om3 = (cl1 * om2 * libm.sin(t2 - ct4)) / (cl3 * libm.sin(ct3 - ct4))
        om4 = (cl1 * om2 * libm.sin(ct3 - t2)) / (cl4 * libm.sin(ct4 - ct3))
        aj, bj = cl4 * libm.sin(ct4), cl3 * libm.sin(ct3)
        cj = -(cl1 * om2 * om2 * libm.cos(t2)) + (cl3 * om3 * om3 * libm.cos(ct3)) - (cl4 * om4 * om4 * libm.cos(ct4))
        dj, ej = cl4 * libm.cos(ct4), cl3 * libm.cos(ct3)
        fj = (cl1 * om2 * om2 * libm.sin(t2)) - (cl3 * om3 * om3 * libm.sin(ct3)) + (cl4 * om4 * om4 * libm.sin(ct4))
        alph3 = (cj * dj - aj * fj) / (aj * ej - bj * dj)
        xpa = -(cl1 * om2 * om2 * libm.cos(t2)) + (cl2 * om3 * om3 * libm.cos(gam)) - (cl2 * alph3 * libm.sin(gam))
        ypa = -(cl1 * om2 * om2 * libm.sin(t2)) - (cl2 * om3 * om3 * libm.sin(gam)) - (cl2 * alph3 * libm.cos(gam))

        # Coupler equilibrium of the crossed cognate, eqs. (20)-(24): the pin forces
        # f4, f5 act at A along (-cos t2, -sin t2), (sin t2, -cos t2); f6 at B along
        # (cos t4, sin t4); the loop is CL1 e^{i t2} - CL3 e^{i t3} + CL4 e^{i t4} = CL5.
        if quirks.cognate_moment_row:                                                  # D026
            g1 = (cl2 * libm.cos(t2) * libm.sin(gam)) + (cl2 * libm.sin(t2) * libm.cos(gam))
            h1 = (cl2 * libm.cos(t2) * libm.cos(gam)) - (cl2 * libm.sin(t2) * libm.sin(gam))
            i1 = (cl2 * libm.cos(t2) * libm.sin(gam)) + (cl3 * libm.cos(ct3) * libm.cos(ct4)) \
                + (cl2 * libm.sin(ct4) * libm.cos(gam)) + (cl3 * libm.sin(ct4) * libm.sin(ct3))
        else:   # moments about P, (pin - P) x direction, as rows 7-8 take them
            ax, ay = cl2 * libm.cos(gam), -cl2 * libm.sin(gam)                 # A - P
            bx, by = ax - cl3 * libm.cos(ct3), ay - cl3 * libm.sin(ct3)        # B - P
            g1 = -ax * libm.sin(t2) + ay * libm.cos(t2)
            h1 = -ax * libm.cos(t2) - ay * libm.sin(t2)
            i1 = bx * libm.sin(ct4) - by * libm.cos(ct4)
        rows456 = _three_by_three_inverse_rows(-libm.cos(t2), libm.sin(t2), libm.cos(ct4), -libm.sin(t2),
                                               -libm.cos(t2), libm.sin(ct4), g1, h1, i1)
        cctx = libm.cos(ct3 - ct4) / libm.sin(ct3 - ct4)
        s, c = libm.sin(gam), libm.cos(gam)
        zero, one = np.zeros_like(t2), np.ones_like(t2)
        beta = np.concatenate([
            np.stack([np.stack([-c, s, zero], -1), np.stack([-s, -c, zero], -1),
                      np.stack([zero, zero, one], -1)], -2),
            rows456,
            np.stack([np.stack([-cl2 * s * cctx / cl3, -cl2 * c * cctx / cl3, cctx / cl3], -1),
                      np.stack([-cl2 * s, -cl2 * c, one], -1)], -2),
        ], axis=-2)
        xdp = store(xpp - cl5, real4).astype(np.float64)                      # XDP is REAL*4
        cxp = store((xdp * libm.cos(-cog.beta)) - (ypp * libm.sin(-cog.beta)), real4).astype(np.float64) + l5
        cyp = (xdp * libm.sin(-cog.beta)) + (ypp * libm.cos(-cog.beta))
    return Mechanics(xpp, ypp, np.stack([xpa, ypa], -1), beta, (cl2, cl1, cl3, cl4), -cog.beta,
                     extra={"xp": xp, "yp": yp, "cxp": cxp, "cyp": cyp, "t2": t2, "t3": ct3, "t4": ct4,
                            "om2": om2, "om3": om3, "alph3": alph3, "cognate": cog, "ext_angle": pi - gam})


def cognate_case1(deg, lengths: Lengths = EXAMPLE.lengths, alp: float | None = None,
                  rpm: float = EXAMPLE.rpm, mass_lbf: float = 2.0,
                  section: Section = EXAMPLE.section, quirks: Quirks = PRINTED) -> dict:
    """Case I, crossed coupler cognate: ``xp, yp`` (the source's coupler point as the
    cognate listing computes it), ``cxp, cyp`` (the cognate's, in the source frame),
    ``dx, dy`` (in) and ``rot`` (rad) over ``deg``; see cognate_mechanics."""
    deg = angles_deg("deg", deg)
    mass_lbf = weight_lbf("mass_lbf", mass_lbf)
    expect("section", section, Section)
    mech = cognate_mechanics(deg, lengths, alp, rpm, quirks)
    dx, dy, rot = case1_deflection(mech, mass_lbf, section, quirks)
    out = {"xp": mech.extra["xp"], "yp": mech.extra["yp"], "cxp": mech.extra["cxp"],
           "cyp": mech.extra["cyp"], "dx": dx, "dy": dy, "rot": rot}
    check_finite(deg, "cognate", **out)
    return out
