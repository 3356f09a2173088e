"""Closed-form kinematics of the four-bar and of its crossed coupler cognate.

As the 1977 listings do it (chapter IV, "complex number approach"): the coupler
and follower angles from the half-angle (Freudenstein) quadratic, then angular
velocities and accelerations at constant input speed.  Lengths in inches,
angles in radians, speeds in rad/s.  Every function is vectorised over the input
angle ``t2``; ``pi`` is the value of pi the caller uses (the listings use 22/7).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import AssemblyError, SingularPositionError


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
            value = float(getattr(self, name))
            if not np.isfinite(value) or value <= 0.0:
                raise ValueError(f"link length {name} must be finite and positive, got {value!r}")


def freudenstein_constants(l1, l3, l4, l5):
    """K1..K5 of the source listing (statements 8-12)."""
    k1 = l5 / l1
    k2 = l5 / l4
    k3 = (l1 * l1 - l3 * l3 + l4 * l4 + l5 * l5) / (2.0 * l1 * l4)
    k4 = l5 / l3
    k5 = (l4 * l4 - l5 * l5 - l1 * l1 - l3 * l3) / (2.0 * l1 * l3)
    return k1, k2, k3, k4, k5


def half_angle_positions(t2, k, deg, who):
    """Coupler and follower angles T3, T4 (rad) from the half-angle quadratics.

    ``k`` holds K1..K5; ``deg`` the input angles (for error messages).
    Raises AssemblyError where a discriminant is negative (the loop cannot close).
    """
    k1, k2, k3, k4, k5 = k
    c, s = np.cos(t2), np.sin(t2)
    aa = c + k3 - k1 - (k2 * c)
    bb = -2.0 * s
    cc = k1 + k3 - (1.0 + k2) * c
    dd = (k4 * c) + c + k5 - k1
    ee = -2.0 * s
    ff = (k4 * c) - c + k5 + k1
    disc3 = ee * ee - 4.0 * dd * ff
    disc4 = bb * bb - 4.0 * aa * cc
    bad = (disc3 < 0.0) | (disc4 < 0.0)
    if np.any(bad):
        i = int(np.argmax(bad))
        raise AssemblyError(f"{who}: the four-bar cannot close", float(deg[i]),
                            discriminant=float(min(disc3[i], disc4[i])))
    with np.errstate(divide="ignore", invalid="ignore"):
        t3 = 2.0 * np.arctan((-ee - np.sqrt(disc3)) / (2.0 * dd))
        t4 = 2.0 * np.arctan((-bb - np.sqrt(disc4)) / (2.0 * aa))
    return t3, t4


def check_finite(deg, who, **arrays):
    """Raise SingularPositionError at the first input angle with a non-finite value."""
    for name, values in arrays.items():
        bad = ~np.isfinite(values)
        if np.any(bad):
            i = int(np.argmax(bad.reshape(len(deg), -1).any(axis=1)))
            raise SingularPositionError(f"{who}: non-finite {name}", float(deg[i]))


@dataclass(frozen=True)
class Cognate:
    """The crossed coupler cognate derived from the source (cognate listing, 32-47).

    ``beta`` (rad) is the angle by which the cognate's frame is turned against the
    source's; ``calp`` the cognate's rigid coupler angle (gamma, about 101 deg).
    """
    cl1: float
    cl2: float
    cl3: float
    cl4: float
    cl5: float
    beta: float
    calp: float

    @classmethod
    def of(cls, lengths: Lengths, alp: float, pi: float) -> "Cognate":
        l1, l2, l3, l4, l5 = lengths.l1, lengths.l2, lengths.l3, lengths.l4, lengths.l5
        k = l2 / l3
        cl4 = np.sqrt((l2 * l2) + (l3 * l3) - (2.0 * l2 * l3 * np.cos(alp)))
        cl3 = l4 * cl4 / l3
        cl2 = k * l4
        cl5 = np.sqrt(((k * l5) * (k * l5)) + (l5 * l5) - (2.0 * l5 * l5 * k * np.cos(alp)))
        cl1 = l1 * cl4 / l3
        cbta = ((l3 * l3) + (cl4 * cl4) - (l2 * l2)) / (2.0 * l3 * cl4)
        sbta = np.sqrt(1.0 - cbta * cbta)
        beta = np.arctan(sbta / cbta)
        calp = pi - (beta + alp)
        return cls(float(cl1), float(cl2), float(cl3), float(cl4), float(cl5), float(beta), float(calp))

    def constants(self):
        """CK1..CK5 (cognate listing, 43-47): the crossed loop's half-angle constants."""
        cl1, cl3, cl4, cl5 = self.cl1, self.cl3, self.cl4, self.cl5
        return (cl5 / cl1, -cl5 / cl4,
                (cl3 * cl3 - cl1 * cl1 - cl4 * cl4 - cl5 * cl5) / (2.0 * cl1 * cl4),
                -cl5 / cl3,
                (cl1 * cl1 + cl3 * cl3 + cl5 * cl5 - cl4 * cl4) / (2.0 * cl1 * cl3))
