"""Case I of the K.E.D. method, source four-bar, in 60-digit arithmetic (mpmath): the reference
against which the engines' rounding error is measured near a toggle (scene
``ali1977-conditioning``) and the corrected port is checked (tests/ali1977/test_conditioning.py).

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

import mpmath

from ....port.ali1977.data import EXAMPLE
from ....port.ali1977.fourbar import Lengths
from ....port.ali1977.structure import Section

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
