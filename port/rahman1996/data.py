"""Inputs and constants of Rahman's (1996) CSSP example (section 5.2, Appendix B).

Units as printed: inch, lbf, second; masses lb*s^2/in, inertias lb*s^2*in; angles in
degrees at the interface, radians inside.  ``Constants.of(inputs, real4)`` gives every
number the listing computes with: with ``real4`` they are what its REAL*4 arguments,
literals and single-precision expressions hold (S1 = 0.4 is 0.4000000059604645) and its
radii of gyration as the 1996 compiler read them (a literal assigned to a REAL*8 variable
taken as double, register D180); without it they are the decimal values.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..slider_crank.geometry import CsspInputs, LoopConstants, single

#: g (in/s^2) and the weights (lbf) of crank, connecting rod and slider
GRAVITY = 386.4
WEIGHTS = (1.9, 7.6, 6.0)
#: CG of crank and rod on their x axes, from the distal frame (in): G1, G2
CG_OFFSETS = (-1.0, -4.0)
#: radii of gyration about the CG (in): crank (x, y, z), rod (x, y, z)
RADII_CRANK = (0.2041241, 0.595119, 0.595119)
RADII_ROD = (0.2041241, 2.3139072, 2.3139072)
#: the rod's radii about its distal frame, used by the listing's original-link forces
RADII_ROD_DISTAL = (0.2041241, 4.6210569, 4.6210569)
#: bearing length B1 (in), eq. (4.2)
BEARING_LENGTH = 0.4
#: QP constraint right-hand sides (DATA b): x1+x2+x3, x5+x6+x7, x9; lower bounds of x1..x8
QP_BOUNDS = (0.003688, 0.01475, 0.01553, 0.001168, 0.001168, 0.001168, 0.001168,
             0.00467, 0.00467, 0.00467, 0.00467)
#: rows of the constraint matrix (DATA aa, register D081): 3 equalities, then x1..x8 >= b
QP_ROWS = np.vstack([[1, 1, 1, 0, 0, 0, 0, 0, 0], [0, 0, 0, 0, 1, 1, 1, 0, 0],
                     [0, 0, 0, 0, 0, 0, 0, 0, 1], np.eye(9)[:8]]).astype(float)
QP_EQUALITIES = 3
#: w' of eq. (4.5): "allowed to decrease by five percent" (section 5.2)
MASS_DECREASE = 0.05


@dataclass(frozen=True)
class Constants(LoopConstants):
    """Every number the CSSP computation uses, as one precision regime holds it: the loop's
    (``LoopConstants``) and the example's masses, inertias and QP data."""
    masses: tuple              # M1, M2, M3 (lb s^2/in)
    inertia_crank: tuple       # I1X, I1Y, I1Z about the CG (lb s^2 in)
    inertia_rod: tuple         # I2X, I2Y, I2Z
    rod_radii_distal: tuple    # K2X, K2Y, K2Z about frame {3}
    cg: tuple                  # G1, G2
    crank_arms: tuple          # X1, Y1, Z1: point-mass distances (eq. 2.12)
    rod_arms: tuple            # X2, Y2, Z2
    point_masses: np.ndarray   # the nine design variables before balancing (eq. 4.4)
    bearing_length_sq: float   # BL**2
    a1_sq: float               # A1**2 (a REAL*4 square in the listing's C1, C2)
    qp_bounds: np.ndarray

    @classmethod
    def of(cls, inputs: CsspInputs, real4: bool) -> "Constants":
        s = lambda x: single(x, real4)                                   # noqa: E731
        loop = LoopConstants.of(inputs, real4)
        g = s(GRAVITY)
        # M1=1.9/G: a single-precision division in the listing
        masses = tuple(float(np.float32(s(w)) / np.float32(g)) if real4 else w / g for w in WEIGHTS)
        # K1XCG=0.2041241 etc.: REAL*8 variables given their literals in double (D180), in both regimes
        crank_k, rod_k = RADII_CRANK, RADII_ROD
        inertia_crank = tuple(masses[0] * k ** 2 for k in crank_k)
        inertia_rod = tuple(masses[1] * k ** 2 for k in rod_k)
        quarter = (masses[0] / 4.0, masses[1] / 4.0)
        crank_arms, rod_arms = (_arms(i, q) for i, q in ((inertia_crank, quarter[0]), (inertia_rod, quarter[1])))
        point_masses = np.array([*[quarter[0]] * 3, masses[0] - 3 * quarter[0],
                                 *[quarter[1]] * 3, masses[1] - 3 * quarter[1], masses[2]])
        bl = s(BEARING_LENGTH)
        return cls(**vars(loop), masses=masses,
                   inertia_crank=inertia_crank, inertia_rod=inertia_rod,
                   rod_radii_distal=RADII_ROD_DISTAL, cg=CG_OFFSETS,
                   crank_arms=crank_arms, rod_arms=rod_arms, point_masses=point_masses,
                   bearing_length_sq=float(np.float32(bl) * np.float32(bl)) if real4 else bl * bl,
                   a1_sq=float(np.float32(inputs.a1) * np.float32(inputs.a1)) if real4 else inputs.a1 ** 2,
                   qp_bounds=np.array([s(b) for b in QP_BOUNDS]))


def _arms(inertia, m) -> tuple:
    """X, Y, Z of eq. (2.12): half point masses m/2 at +-X on x, +-Y on y, +-Z on z."""
    ix, iy, iz = inertia
    return (((iy + iz - ix) / (2.0 * m)) ** 0.5, ((ix + iz - iy) / (2.0 * m)) ** 0.5,
            ((ix + iy - iz) / (2.0 * m)) ** 0.5)


def qp_constraints(c: "Constants", cg_masses_free: bool, data_rounded: bool, real4: bool):
    """The balancing QP's constraints: (rows, right-hand sides, number of equalities).

    As printed (``cg_masses_free``, register D130): x1+x2+x3 = b(1), x5+x6+x7 = b(2),
    x9 = b(3), x1..x8 >= b(4..11), so the masses at the centres of mass, x4 and x8, may
    fall to their bounds and the links lose mass.  Off: x4 and x8 keep their values
    (m14, m24; equalities), so each link's mass stays constant as section 5.2 states.
    ``data_rounded`` (D131): b is the listing's DATA b, typed to three or four digits
    (x9 = 0.01553 where M3 = 6.0/386.4 = 0.0155280); off: b from the point masses and
    w' of eq. (4.5).  ``real4``: b is REAL (the listing's QPROG entry is single precision).
    """
    pm = c.point_masses
    if data_rounded:
        b = np.array(QP_BOUNDS, dtype=float)
    else:
        b = np.concatenate([[pm[0:3].sum(), pm[4:7].sum(), pm[8]], (1.0 - MASS_DECREASE) * pm[:8]])
    if real4:
        b = b.astype(np.float32).astype(float)
    if cg_masses_free:
        return QP_ROWS, b, QP_EQUALITIES
    unit = np.eye(9)
    cg = np.array([pm[3], pm[7]])
    if real4:
        cg = cg.astype(np.float32).astype(float)
    kept = [0, 1, 2, 4, 5, 6]                       # the pair masses keep their lower bounds
    rows = np.vstack([QP_ROWS[:3], unit[[3, 7]], unit[kept]])
    return rows, np.concatenate([b[:3], cg, b[3:][kept]]), QP_EQUALITIES + 2
