"""The K.E.D. method in 60-digit arithmetic (mpmath): the references against which the engines'
rounding error is measured.

``listing``: any program (Cases I-III, source and cognate) under any quirks, the port's formulas
(the listing's, or the thesis's with a quirk off) evaluated in ``digits`` digits from the inputs
the port takes (the listing's pi, speed and REAL*4 literals): the reference of the error bound's
calibration (``calibration``, ``linkrepro ked-bound``), of the listing poles
(tests/ali1977/test_poles.py, the fuzz) and of the scene's checks.

``case1_source``: Case I of the source four-bar, corrected, in 60 digits: the reference against
which the engines' rounding error is measured near a toggle (scene ``ali1977-conditioning``)
and the corrected port is checked (tests/ali1977/test_conditioning.py).

The thesis's corrected equations (every quirk off), written from the geometry rather than from
the listing: the follower pin B where the coupler's and the follower's circles meet (in the
assembly branch the listings' half-angle root takes, sin(t4 - t3) > 0); the angular speeds and
accelerations from the loop A + l3 e^{i t3} = l5 + l4 e^{i t4} differentiated once and twice
at constant input speed; the path point P = A + l2 e^{i(t3 + alp)}, its load -m a_P; beta from
the extender's axes and the coupler's equilibrium (eqs. 10-14, 20-25: the pin forces f4, f5 at
A along and across the input link and f6 along the follower, the coupler's axial force and end
moment); F of eq. (29); delta = beta^T F beta P (eq. 6).  Lengths in inches, angles in
degrees at the interface, speed in rpm, the weight in lbf (mass = W/g, g = 12 * 32.178 in/s^2).
"""
from __future__ import annotations

import math

import mpmath
import numpy as np

from ....port.ali1977.data import ALP_SOURCE_LISTING, EXAMPLE, PI_22_7
from ....port.ali1977.fourbar import Lengths
from ....port.ali1977.structure import GRAVITY_IN, GRAVITY_REAL4, Section

DIGITS = 60


def _solve(rows, rhs):
    return mpmath.lu_solve(mpmath.matrix(rows), mpmath.matrix(rhs))


def case1_source(deg: float, lengths: Lengths = EXAMPLE.lengths, alp_deg: float = EXAMPLE.alpha_deg,
                 rpm: float = EXAMPLE.rpm, mass_lbf: float = EXAMPLE.mass_lbf,
                 section: Section = EXAMPLE.section, digits: int = DIGITS) -> dict:
    """xp, yp (in), dx, dy (in) and rot (rad) of the source's path point at input angle ``deg``
    (each a float rounded from ``digits`` digits), and ``sin_mu``, the sine of the transmission
    angle; None where the loop cannot close."""
    with mpmath.workdps(digits):
        mp = mpmath.mp
        l1, l2, l3, l4, l5 = (mp.mpf(v) for v in (lengths.l1, lengths.l2, lengths.l3, lengths.l4, lengths.l5))
        t2, alp = mp.radians(mp.mpf(deg)), mp.radians(mp.mpf(alp_deg))
        om2 = 2 * mp.pi * mp.mpf(rpm) / 60
        a = l1 * mp.expj(t2)
        to_pivot = l5 - a
        d = abs(to_pivot)
        along = (l3 * l3 - l4 * l4 + d * d) / (2 * d)
        if along * along > l3 * l3:
            return None
        across = mp.sqrt(l3 * l3 - along * along)
        unit = to_pivot / d
        for side in (1, -1):
            b = a + unit * (along + side * 1j * across)
            t3, t4 = mp.arg(b - a), mp.arg(b - l5)
            if mp.sin(t4 - t3) > 0:
                break
        e2, e3, e4 = mp.expj(t2), mp.expj(t3), mp.expj(t4)
        # loop: l1 e2 + l3 e3 = l5 + l4 e4; once in time: i (l1 om2 e2 + l3 om3 e3 - l4 om4 e4) = 0
        om3, om4 = _solve([[-l3 * e3.real, l4 * e4.real], [-l3 * e3.imag, l4 * e4.imag]],
                          [l1 * om2 * e2.real, l1 * om2 * e2.imag])
        # twice: -l1 om2^2 e2 + l3 (i alph3 - om3^2) e3 - l4 (i alph4 - om4^2) e4 = 0
        known = -l1 * om2 ** 2 * e2 - l3 * om3 ** 2 * e3 + l4 * om4 ** 2 * e4
        alph3, _ = _solve([[-l3 * e3.imag, l4 * e4.imag], [l3 * e3.real, -l4 * e4.real]],
                          [-known.real, -known.imag])
        ext = mp.expj(t3 + alp)
        p = a + l2 * ext
        acc = -l1 * om2 ** 2 * e2 + l2 * (1j * alph3 - om3 ** 2) * ext
        weight = mp.mpf(mass_lbf)
        load = [-weight * acc.real / (12 * mp.mpf("32.178")), -weight * acc.imag / (12 * mp.mpf("32.178")), 0]

        def moment(at, direction):                      # of a unit force along ``direction`` at ``at``, about P
            arm = at - p
            return arm.real * direction.imag - arm.imag * direction.real

        across2 = 1j * e2
        pins = mpmath.matrix([[e2.real, across2.real, e4.real], [e2.imag, across2.imag, e4.imag],
                              [moment(a, e2), moment(a, across2), moment(a + l3 * e3, e4)]])
        inverse = pins ** -1
        cot = mp.cos(t4 - t3) / mp.sin(t4 - t3)
        beta = mpmath.matrix(8, 3)
        beta[0, 0], beta[0, 1] = ext.real, ext.imag                           # extender: axial
        beta[1, 0], beta[1, 1] = -ext.imag, ext.real                          # shear
        beta[2, 2] = 1                                                        # moment
        for i in range(3):
            for j in range(3):
                beta[3 + i, j] = inverse[i, j]                                # f4, f5, f6
        beta[6, 0], beta[6, 1], beta[6, 2] = cot * ext.imag * l2 / l3, -cot * ext.real * l2 / l3, -cot / l3
        beta[7, 0], beta[7, 1], beta[7, 2] = -ext.imag * l2, ext.real * l2, 1
        ca, me, mi = (mp.mpf(v) for v in (section.area, section.modulus, section.inertia))
        flex = mpmath.zeros(8, 8)
        flex[0, 0], flex[1, 1] = l2 / (ca * me), l2 ** 3 / (3 * me * mi)
        flex[1, 2] = flex[2, 1] = l2 ** 2 / (2 * me * mi)
        flex[2, 2], flex[3, 3], flex[4, 4] = l2 / (me * mi), l1 / (ca * me), l1 ** 3 / (3 * mi * me)
        flex[5, 5], flex[6, 6], flex[7, 7] = l4 / (ca * me), l3 / (ca * me), l3 / (3 * me * mi)
        delta = beta.T * flex * beta * mpmath.matrix(load)
        return {"xp": float(p.real), "yp": float(p.imag), "dx": float(delta[0]), "dy": float(delta[1]),
                "rot": float(delta[2]), "sin_mu": float(abs(mp.sin(t4 - t3)))}


# --- The listings' own equations, any quirks, Cases I-III, source and cognate ---------------

def _transpose(a):
    return [list(row) for row in zip(*a)]


def _half_angle(m, c2, s2, k1, k2, k3, k4, k5):
    """The listings' half-angle roots (statements 14-21): t3, t4 (rad), or None where a
    discriminant is negative."""
    aa, bb, cc = c2 + k3 - k1 - k2 * c2, -2 * s2, k1 + k3 - (1 + k2) * c2
    dd, ee, ff = k4 * c2 + c2 + k5 - k1, -2 * s2, k4 * c2 - c2 + k5 + k1
    disc3, disc4 = ee * ee - 4 * dd * ff, bb * bb - 4 * aa * cc
    if disc3 < 0 or disc4 < 0:
        return None
    return 2 * m.atan((-ee - m.sqrt(disc3)) / (2 * dd)), 2 * m.atan((-bb - m.sqrt(disc4)) / (2 * aa))


def _cognate_links(m, l1, l2, l3, l4, l5, alp, pi, signed):
    """Cognate.of in ``m``'s arithmetic: cl1..cl5, beta, calp."""
    k = l2 / l3
    if signed:
        along, across = l3 - l2 * m.cos(alp), l2 * m.sin(alp)
        cl4 = m.sqrt(along * along + across * across)
        cl5 = l5 * cl4 / l3
        beta = m.atan2(across, along)
    else:
        cl4 = m.sqrt(l2 * l2 + l3 * l3 - 2 * l2 * l3 * m.cos(alp))
        cl5 = m.sqrt((k * l5) ** 2 + l5 * l5 - 2 * l5 * l5 * k * m.cos(alp))
        cbta = (l3 * l3 + cl4 * cl4 - l2 * l2) / (2 * l3 * cl4)
        beta = m.atan(m.sqrt(1 - cbta * cbta) / cbta)
    return l1 * cl4 / l3, k * l4, l4 * cl4 / l3, cl4, cl5, beta, pi - (beta + alp)


class _Motion:
    """One input angle of a listing's four-bar (source or crossed cognate) in ``digits``:
    the attributes the port's linkages hold (t2, t3, t4, om2, om3, alph3, cosines, sines,
    the extender's direction, the pins' accelerations) and ``point(r)``: the path point r (in)
    along the extender, its acceleration and beta (8 x 3), with the Cramer matrix it solves."""

    def __init__(self, m, deg, lengths, alp, om2, pi, quirks, cognate):
        self.m, self.quirks, self.cognate = m, quirks, cognate
        l1, l2, l3, l4, l5 = lengths
        t2 = (deg * 2 * pi) / 360
        c2, s2 = m.cos(t2), m.sin(t2)
        if cognate:
            cl1, cl2, cl3, cl4, cl5, beta, calp = _cognate_links(m, l1, l2, l3, l4, l5, alp, pi,
                                                                 not quirks.cognate_beta_quadrant)
            self.links, self.frame_angle = (cl1, cl2, cl3, cl4, cl5), -beta
            k = (cl5 / cl1, -cl5 / cl4, (cl3 ** 2 - cl1 ** 2 - cl4 ** 2 - cl5 ** 2) / (2 * cl1 * cl4), -cl5 / cl3,
                 (cl1 ** 2 + cl3 ** 2 + cl5 ** 2 - cl4 ** 2) / (2 * cl1 * cl3))
        else:
            self.links, self.frame_angle = tuple(lengths), 0
            k = (l5 / l1, l5 / l4, (l1 * l1 - l3 * l3 + l4 * l4 + l5 * l5) / (2 * l1 * l4), l5 / l3,
                 (l4 * l4 - l5 * l5 - l1 * l1 - l3 * l3) / (2 * l1 * l3))
        roots = _half_angle(m, c2, s2, *k)
        if roots is None:
            raise ArithmeticError("cannot close")
        t3, t4 = roots
        a1, _, a3, a4, _ = self.links
        c3, s3, c4, s4 = m.cos(t3), m.sin(t3), m.cos(t4), m.sin(t4)
        if cognate:
            ext = pi - (calp - t3)
            om3 = a1 * om2 * m.sin(t2 - t4) / (a3 * m.sin(t3 - t4))
            om4 = a1 * om2 * m.sin(t3 - t2) / (a4 * m.sin(t4 - t3))
            cj = -(a1 * om2 ** 2 * c2) + a3 * om3 ** 2 * c3 - a4 * om4 ** 2 * c4
            fj = a1 * om2 ** 2 * s2 - a3 * om3 ** 2 * s3 + a4 * om4 ** 2 * s4
            self.cot = m.cos(t3 - t4) / m.sin(t3 - t4)
            self.cg, self.sg = m.cos(calp - t3), m.sin(calp - t3)
        else:
            ext = alp + t3
            s_om3 = m.sin(t4 - t3) if quirks.omega3_sign else m.sin(t4 - t2)                 # D013
            om3 = l1 * om2 * s_om3 / (l3 * m.sin(t3 - t4))
            om4 = l1 * om2 * m.sin(t2 - t3) / (l4 * m.sin(t4 - t3))
            cj = l1 * om2 ** 2 * c2 + l3 * om3 ** 2 * c3 - l4 * om4 ** 2 * c4
            fj = l4 * om4 ** 2 * s4 - l1 * om2 ** 2 * s2 - l3 * om3 ** 2 * s3
            self.cot = m.cos(t4 - t3) / m.sin(t4 - t3)
        aj, bj, dj, ej = a4 * s4, a3 * s3, a4 * c4, a3 * c3
        alph3 = (cj * dj - aj * fj) / (aj * ej - bj * dj)
        xaa, yaa = -(a1 * c2 * om2 ** 2), -(a1 * s2 * om2 ** 2)
        if cognate:
            xba, yba = xaa + a3 * om3 ** 2 * c3 + a3 * alph3 * s3, yaa + a3 * om3 ** 2 * s3 - a3 * alph3 * c3
        else:
            b_sign = 1 if quirks.joint_b_acceleration_sign else -1                            # D032
            xba = -(l1 * om2 ** 2 * c2) - l3 * om3 ** 2 * c3 + b_sign * l3 * alph3 * s3
            yba = -(l1 * om2 ** 2 * s2) - l3 * om3 ** 2 * s3 + l3 * alph3 * c3
        self.t2, self.t3, self.t4, self.om2, self.om3, self.alph3 = t2, t3, t4, om2, om3, alph3
        self.c2, self.s2, self.c3, self.s3, self.c4, self.s4 = c2, s2, c3, s3, c4, s4
        self.ce, self.se, self.pins = m.cos(ext), m.sin(ext), (xaa, yaa, xba, yba)

    def point(self, r):
        """(xp, yp), (xpa, ypa), beta (8 x 3 lists), Cramer matrix [[a b c] [d e f] [g h i]]."""
        c2, s2, c3, s3, c4, s4, ce, se = self.c2, self.s2, self.c3, self.s3, self.c4, self.s4, self.ce, self.se
        a1, a3, om2, om3, alph3, q = self.links[0], self.links[2], self.om2, self.om3, self.alph3, self.quirks
        position = (a1 * c2 + r * ce, a1 * s2 + r * se)
        if self.cognate:
            c, s = self.cg, self.sg
            acc = (-(a1 * om2 ** 2 * c2) + r * om3 ** 2 * c - r * alph3 * s,
                   -(a1 * om2 ** 2 * s2) - r * om3 ** 2 * s - r * alph3 * c)
            if q.cognate_moment_row:                                                          # D026
                g = r * c2 * s + r * s2 * c
                h = r * c2 * c - r * s2 * s
                i = r * c2 * s + a3 * c3 * c4 + r * s4 * c + a3 * s4 * s3
            else:
                ax, ay = r * c, -r * s
                bx, by = ax - a3 * c3, ay - a3 * s3
                g, h, i = -ax * s2 + ay * c2, -ax * c2 - ay * s2, bx * s4 - by * c4
            cramer = [[-c2, s2, c4], [-s2, -c2, s4], [g, h, i]]
            head = [[-c, s, 0], [-s, -c, 0], [0, 0, 1]]
            tail = [[-r * s * self.cot / a3, -r * c * self.cot / a3, self.cot / a3], [-r * s, -r * c, 1]]
        else:
            l3 = a3
            acc = (-(a1 * om2 ** 2 * c2) - r * om3 ** 2 * ce - r * alph3 * se,
                   -(a1 * om2 ** 2 * s2) + r * alph3 * ce - r * om3 ** 2 * se)
            g_trig = c2 if q.g_coefficient else s2                                            # D014
            g = -(r * ce * g_trig) + r * se * c2
            h = -(r * ce * c2) - r * se * s2
            i_len = r if q.i_coefficient else l3                                              # D015
            i = s4 * (i_len * c3 - r * ce) + c4 * (r * se - l3 * s3)
            cramer = [[c2, -s2, c4], [s2, c2, s4], [g, h, i]]
            head = [[ce, se, 0], [-se, ce, 0], [0, 0, 1]]
            tail = [[self.cot * se * r / l3, -ce * self.cot * r / l3, -self.cot / l3], [-se * r, ce * r, 1]]
        inverse = _cramer_rows(*(x for row in cramer for x in row))
        return position, acc, head + inverse + tail, cramer


def _cramer_rows(a, b, c, d, e, f, g, h, i):
    """Rows f4, f5, f6 of beta by Cramer's rule (eq. 14), as the listings write them."""
    r = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    return [[(e * i - f * h) / r, (c * h - b * i) / r, (b * f - c * e) / r],
            [(f * g - d * i) / r, (a * i - c * g) / r, (c * d - a * f) / r],
            [(d * h - e * g) / r, (b * g - a * h) / r, (a * e - b * d) / r]]


def _flexibility(r, l_in, l_cpl, l_fol, area, modulus, inertia, quirks):
    """F (8 x 8) of eq. (29); D016's bending term."""
    f = [[0] * 8 for _ in range(8)]
    f[0][0], f[1][1] = r / (area * modulus), r ** 3 / (3 * modulus * inertia)
    f[1][2] = f[2][1] = r ** 2 / (2 * modulus * inertia)
    f[2][2], f[3][3] = r / (modulus * inertia), l_in / (area * modulus)
    f[4][4] = l_in ** 3 / (3 * (area if quirks.input_link_bending_area else inertia) * modulus)     # D016
    f[5][5], f[6][6], f[7][7] = l_fol / (area * modulus), l_cpl / (area * modulus), l_cpl / (3 * modulus * inertia)
    return f


def _product(left, flex, right, load):
    """left^T F right P (left 8 x 3, right 8 x k, load k), a 3-vector, and the same product of the
    entries' magnitudes (the deflection's size before cancellation); from the right, as
    matrix-vector products."""
    def apply(matrix, vector):
        return [mpmath.fsum(x * v for x, v in zip(row, vector) if x and v) for row in matrix]

    def chain(left, flex, right, load):
        return apply(_transpose(left), apply(flex, apply(right, load)))

    def magnitudes(matrix):
        return [[abs(x) for x in row] for row in matrix]

    return (chain(left, flex, right, load),
            chain(magnitudes(left), magnitudes(flex), magnitudes(right), [abs(p) for p in load]))


def _engine_inputs(program: str, alp, rpm, weight, section: Section, quirks):
    """What the port's program takes for pi, alp, the speed, the weight (or density) and the
    section under ``quirks`` (the listing's REAL*4 literals and INTEGER speed where
    ``real4_storage``): the inputs of the listing's equations, as floats."""
    real4 = quirks.real4_storage
    pi = PI_22_7 if quirks.pi_22_7 else math.pi
    source = program.endswith("source")
    if alp is None:
        alp = ALP_SOURCE_LISTING if program == "case1_source" and quirks.source_alpha_101 else pi / 3.0
    if rpm is None:
        rpm = 400.0 if quirks.source_rpm_400 else EXAMPLE.rpm
    if real4:
        rpm = float(np.trunc(rpm)) if program == "case1_source" else float(np.float32(rpm))
        weight = float(np.float32(weight))
        section = section.as_listing_holds(True)
    gravity = GRAVITY_REAL4 if real4 else GRAVITY_IN
    return pi, alp, rpm, weight, section, gravity, source


def listing(program: str, deg: float, lengths: Lengths, alp: float | None, rpm: float | None, weight: float,
            section: Section, quirks, n: int = 5, digits: int = DIGITS) -> dict:
    """The K.E.D. program ``program`` ("case1_source", "case1_cognate", ..., "case3_cognate") at one
    input angle ``deg`` (deg) with the port's ``quirks`` (any switches), its formulas (the listing's
    with the quirks on, the thesis's with them off) evaluated in ``digits`` digits from the same
    inputs as the port takes them (the listing's pi, speed, REAL*4 literals): the reference for the
    engines' rounding error.  ``weight`` the path point's weight (Case I, lbf) or the density
    (Cases II, III, lbf/in^3); ``n`` Case III's nodes.  Returns dx, dy (in, the source frame unless
    D025 is on), rot (rad), ``extender`` (the program's extender length, in: l2, or the cognate's
    CL2), ``xp, yp`` (in: the path point in the program's own frame, the source's coupler point
    for a source program), ``rho``: for each Cramer matrix the program solves, |det| over the sum
    of its six terms' magnitudes, and ``magnitude``: the length of the deflection vector's terms
    before they cancel (the same products of the entries' magnitudes, in).  ArithmeticError where
    the loop cannot close."""
    case, cognate = int(program[4]), program.endswith("cognate")
    pi, alp, rpm, weight, section, gravity, _ = _engine_inputs(program, alp, rpm, weight, section, quirks)
    with mpmath.workdps(digits):
        mp = mpmath.mp
        f = [mp.mpf(v) for v in (*vars(lengths).values(), alp, rpm, weight, pi, gravity,
                                 section.area, section.modulus, section.inertia)]
        links, (alp_, rpm_, weight_, pi_, g, area, modulus, inertia) = f[:5], f[5:]
        om2 = 2 * pi_ * rpm_ / 60
        motion = _Motion(mp, mp.mpf(deg), links, alp_, om2, pi_, quirks, cognate)
        a1, a2, a3, a4, _ = motion.links
        sign = 1 if quirks.inertia_sign else -1                                               # D018
        solved, points = [], []

        def at(r):
            position, acc, beta, cramer = motion.point(r)
            solved.append(cramer)
            points.append(position)
            return position, acc, beta

        def load(acc, w):
            return [sign * acc[0] * w / g, sign * acc[1] * w / g, 0]

        if case == 1:
            _, acc, beta = at(a2)
            delta = _product(beta, _flexibility(a2, a1, a3, a4, area, modulus, inertia, quirks), beta,
                             load(acc, weight_))
        elif case == 2:
            _, acc, beta = at(a2)
            delta = _product(beta, _flexibility(a2, a1, a3, a4, area, modulus, inertia, quirks),
                             _beta2(mp, motion, beta, quirks), _joint_loads(motion, acc, weight_ * area, g, sign, quirks))
        else:
            delta = _case3(mp, motion, at, load, weight_ * area, area, modulus, inertia, n, quirks)
        delta, magnitude = delta
        if cognate and not quirks.cognate_frame:                                             # D025
            c, s = mp.cos(motion.frame_angle), mp.sin(motion.frame_angle)
            delta = [delta[0] * c - delta[1] * s, delta[0] * s + delta[1] * c, delta[2]]
            magnitude = [magnitude[0] * abs(c) + magnitude[1] * abs(s), magnitude[0] * abs(s) + magnitude[1] * abs(c),
                         magnitude[2]]
        rho = [float(abs(_det(m)) / _det(m, absolute=True)) for m in solved]
        return {"dx": float(delta[0]), "dy": float(delta[1]), "rot": float(delta[2]), "extender": float(a2),
                "xp": float(points[0][0]), "yp": float(points[0][1]),
                "rho": rho, "magnitude": float(mpmath.sqrt(magnitude[0] ** 2 + magnitude[1] ** 2
                                                           + (a2 * magnitude[2]) ** 2))}


def _det(m, absolute: bool = False):
    """The listings' R1 of a 3 x 3 matrix, or the sum of its six terms' magnitudes."""
    (a, b, c), (d, e, f), (g, h, i) = m
    terms = (a * e * i, -a * f * h, -b * d * i, b * f * g, c * d * h, -c * e * g)
    return mpmath.fsum(abs(t) for t in terms) if absolute else mpmath.fsum(terms)


def _beta2(m, motion, beta, quirks):
    """Case II's beta2 (8 x 8): beta1, then P4..P8 into f4, f5, f6, (f4, f5, f7), f8 (eqs. 30, 31)."""
    right = [list(row) + [0] * 5 for row in beta]
    for k in range(3, 8):
        right[k][k] = 1
    turn = motion.t3 - motion.t2 if motion.cognate else motion.t2 - motion.t3
    right[3][6] = m.cos(turn) if motion.cognate else -m.cos(turn)
    right[4][6] = m.sin(turn)
    if not quirks.coupler_load_in_f7:                                                          # D144
        right[6][6] = 0
    return right


def _joint_loads(motion, acc, density_area, g, sign, quirks):
    """Case II's P1..P8 (lbf) as joint_loads forms them (D031, D145, D018)."""
    xaa, yaa, xba, yba = motion.pins
    c2, s2, c3, s3, c4, s4 = motion.c2, motion.s2, motion.c3, motion.s3, motion.c4, motion.s4
    m1, m2, m3, m4 = (density_area * length for length in motion.links[:4])
    crank, coupler = 1, 1
    if motion.cognate:
        crank, coupler = (1, -1) if quirks.cognate_joint_load_signs else (-1, 1)               # D145
    if quirks.joint_load_components:                                                          # D031
        p5, p6, p7 = m1 * (yaa * s2 - xaa * c2), m4 * (yba * s4 - xba * c4), m3 * (yaa * s3 - xaa * c3)
    else:
        p5, p6, p7 = m1 * (-xaa * s2 + yaa * c2), m4 * (xba * c4 + yba * s4), m3 * (-xaa * c3 - yaa * s3)
    p4 = crank * m1 * (xaa * c2 + yaa * s2)
    row = [m2 * acc[0], m2 * acc[1], 0, p4, crank * p5, p6, coupler * p7, 0]
    return [sign * v / g for v in row]


def _case3(m, motion, at, load, density_area, area, modulus, inertia, n, quirks):
    """Case III's tip deflection: the listing's uncoupled blocks (D033-D036) or the coupled
    n-segment model, for the source or the cognate (case3.py)."""
    a1, length, a3, a4, _ = motion.links
    listing_model = quirks.uncoupled_nodes                                                    # D034
    step = (m.mpf(10) if listing_model and not motion.cognate else length) / n
    positions = [length - k * step for k in range(n)]
    if quirks.node_mass_from_pin:                                                             # D033
        weights = [density_area * r for r in positions]
    else:
        weights = [density_area * length / n] * n
    if listing_model and motion.cognate:
        _, acc, beta = at(length)
        return _product(beta, _flexibility(length, a1, a3, a4, area, modulus, inertia, quirks), beta,
                        load(acc, weights[0]))
    nodes = [at(r) for r in positions]
    loads = [load(acc, w) for (_, acc, _), w in zip(nodes, weights)]
    flex = [_flexibility(r, a1, a3, a4, area, modulus, inertia, quirks) for r in positions]
    if listing_model:
        left, right = [b for _, _, b in nodes], [[list(row) for row in b] for _, _, b in nodes]
        left = [[list(row) for row in b] for b in left]
        if n > 3 and quirks.u470_operands:                                                    # D036
            (a, b, _), (d, e, _), (_, _, i_tip) = _cramer_of(motion, positions[0])
            r4 = _det(_cramer_of(motion, positions[3]))
            left[3][5][2], right[3][5][2] = (a * d - b * i_tip) / r4, (a * d - b * e) / r4
        tip = _product(left[0], flex[0], right[0], loads[0])
        if n > 1 and quirks.tip_rotation_node_2:                                              # D035
            rotation = _product([[row[2]] * 3 for row in left[0]], flex[1], right[1], loads[1])
            for part, turned in zip(tip, rotation):
                part[2] = turned[0]
        return tip
    return tuple(_coupled(m, motion, nodes, loads, positions, area, modulus, inertia, quirks, absolute)
                 for absolute in (False, True))


def _cramer_of(motion, r):
    return motion.point(r)[3]


def _coupled(m, motion, nodes, loads, positions, ca, me, mi, quirks, absolute=False):
    """case3._coupled_tip at one angle: the extender as n segments in series, every node
    loaded, by unit loads at the tip (virtual work); with ``absolute`` of the magnitudes of the
    directions, loads and beta (the deflection's size before cancellation)."""
    a1, _, a3, a4, _ = motion.links
    c, s = motion.ce, motion.se
    moment_sign = -1
    if absolute:
        c, s, moment_sign = abs(c), abs(s), 1
        loads = [[abs(p) for p in load] for load in loads]
        nodes = [(None, None, [[abs(x) for x in row] for row in b]) for _, _, b in nodes]
    reactions = [mpmath.fsum(b[e][j] * p[j] for (_, _, b), p in zip(nodes, loads) for j in range(2))
                 for e in range(3, 8)]
    order = sorted(range(len(positions)), key=lambda k: positions[k])
    r = [positions[k] for k in order]
    h = [r[0]] + [r[k] - r[k - 1] for k in range(1, len(r))]
    axial = [loads[k][0] * c + loads[k][1] * s for k in order]
    shear = [moment_sign * loads[k][0] * s + loads[k][1] * c for k in order]
    n_force = [mpmath.fsum(axial[j:]) for j in range(len(r))]
    v_force = [mpmath.fsum(shear[j:]) for j in range(len(r))]
    m_force = [mpmath.fsum(shear[k] * r[k] for k in range(j, len(r))) + moment_sign * r[j] * v_force[j]
               for j in range(len(r))]
    arm = [r[-1] - x for x in r]
    axial_work = mpmath.fsum(h[j] / (ca * me) * n_force[j] for j in range(len(r)))
    shear_work = mpmath.fsum(h[j] ** 3 / (3 * me * mi) * v_force[j] + h[j] ** 2 / (2 * me * mi) * m_force[j]
                             for j in range(len(r)))
    moment_work = mpmath.fsum(h[j] ** 2 / (2 * me * mi) * v_force[j] + h[j] / (me * mi) * m_force[j]
                              for j in range(len(r)))
    arm_work = mpmath.fsum(arm[j] * h[j] ** 2 / (2 * me * mi) * v_force[j] + arm[j] * h[j] / (me * mi) * m_force[j]
                           for j in range(len(r)))
    e_flex = [a1 / (ca * me), a1 ** 3 / (3 * (ca if quirks.input_link_bending_area else mi) * me),
              a4 / (ca * me), a3 / (ca * me), a3 / (3 * me * mi)]
    tip_beta = nodes[0][2]
    delta = []
    for i, (un, uv, um) in enumerate(((c, moment_sign * s, 0), (s, c, 0), (0, 0, 1))):
        value = un * axial_work + uv * (shear_work + arm_work) + um * moment_work
        delta.append(value + mpmath.fsum(tip_beta[3 + e][i] * e_flex[e] * reactions[e] for e in range(5)))
    return delta
