"""Inputs of Rahman's (1991) generalized slider crank (GSC), section 3.1 of the thesis.

Units as printed: inch, lbf, second; masses lbf*s^2/in; angles in degrees at the interface,
radians inside.  The link-joint table (Table 1): crank a1 turning (theta1) and sliding (S1)
on joint 1; ball joints 2 and 3 (theta2, eta2; theta3, eta3); the slider S4 on joint 4,
whose axis k4 is twisted alpha4 from k1 and offset a4 from it.

The crank's axial motion is either constant, S1 = s1 (alpha = 0), or harmonic,
S1 = s1 sin(alpha theta1) (eqs. 27-28, alpha cycles of sliding per turn).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...checks import parameter
from ..slider_crank.geometry import CsspInputs

#: g (in/s^2), the example's weight density (lbf/in^3, "specific gravity d = 0.28")
GRAVITY = 386.4
DENSITY = 0.28


@dataclass(frozen=True)
class GscInputs(CsspInputs):
    """One configuration of section 3.1: lengths and offsets (in), twist (deg), crank speed
    (rpm), constant input torque T1k (lbf*in), section radii r1, r2 and slider side r3 (in),
    axial-motion ratio alpha of eq. (27) (0: S1 constant).  The slider crank's inputs
    (``CsspInputs``) with the 1991 example's values and the 1991 additions."""
    a1: float = 12.0
    a2: float = 50.0
    a4: float = 0.0
    alpha4_deg: float = 270.0
    s1: float = 0.0
    rpm: float = 50.0
    torque: float = 100.0
    r1: float = 1.5
    r2: float = 1.0
    r3: float = 3.0
    alpha: float = 0.0

    def __post_init__(self):
        super().__post_init__()
        for name in ("r1", "r2", "r3", "torque", "alpha"):
            object.__setattr__(self, name, parameter(name, getattr(self, name), positive=name.startswith("r")))

    def axial(self, theta1) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """S1, S1', S1'' (in, in/s, in/s^2) at crank angles theta1 (rad): eqs. (28), (28a),
        (28b) with theta1'' = 0; constant s1 when alpha = 0."""
        th = np.asarray(theta1, dtype=float)
        if self.alpha == 0.0:
            return np.full(th.shape, self.s1), np.zeros(th.shape), np.zeros(th.shape)
        arg, w = self.alpha * th, self.omega
        return (self.s1 * np.sin(arg), self.alpha * self.s1 * np.cos(arg) * w,
                -self.s1 * (self.alpha * w) ** 2 * np.sin(arg))


@dataclass(frozen=True)
class MassModel:
    """Masses (lbf*s^2/in), centre-of-mass offsets g (in, along each link's i axis from its
    distal frame), squared radii of gyration K^2 (in^2) about that frame, as section 3.1."""
    m: tuple
    g: tuple
    k2: tuple

    @classmethod
    def of(cls, inputs: GscInputs, com_beyond_joint: bool) -> "MassModel":
        """Section 3.1's solid links.  The thesis sets g1 = a1/2, g2 = a2/2 (its frames put
        the centre of mass beyond the distal joint); ``com_beyond_joint=False`` puts it on
        the link, g = -a/2 (register D086).  K^2 about the distal end is the same either way."""
        a1, a2, r1, r2, r3 = inputs.a1, inputs.a2, inputs.r1, inputs.r2, inputs.r3
        m = (math.pi * r1 ** 2 * a1 * DENSITY / GRAVITY, math.pi * r2 ** 2 * a2 * DENSITY / GRAVITY,
             r3 ** 3 * DENSITY / GRAVITY)
        sign = 1.0 if com_beyond_joint else -1.0
        k_end = lambda r, a: (r * r / 2.0, r * r / 4.0 + a * a / 3.0, r * r / 4.0 + a * a / 3.0)
        return cls(m=m, g=(sign * a1 / 2.0, sign * a2 / 2.0, 0.0),
                   k2=(k_end(r1, a1), k_end(r2, a2), (r3 * r3 / 6.0,) * 3))
