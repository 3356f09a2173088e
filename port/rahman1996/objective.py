"""The quantities of Tables 5.2-5.7 and the objective of eqs. (4.2)-(4.3), from unit loads.

Every inertia-induced force and moment is linear in the nine point masses x (eq. 4.4),
so each model (the listing's, ``rahman1996.listing``; the closed-loop one, ``rahman1996.mechanics``)
gives them per unit of each x_k: ``UnitLoads``.  From those this module builds the
per-position quadratic form F (x'Fx = G at one position), the shaking force, shaking
moment, bearing force, bearing torque and input torque for any masses x.
Units: lbf, lbf*in per unit mass (lb*s^2/in); G is dimensionless.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .data import Constants
from .quirks import CsspQuirks


@dataclass
class UnitLoads:
    """Per unit of each design variable, arrays (n positions, 9, 3)."""
    shaking_force: np.ndarray        # F of eq. (3.10)
    shaking_moment: np.ndarray       # T of eq. (3.11)
    reactions: tuple                 # R1, R2, R3, R4 (eq. 3.16)
    moments: tuple                   # M1 - T0 k, M2, M3, M4 (eq. 4.1): their squares enter M-bar
    input_torque: np.ndarray         # T0 (n, 9), eq. (3.18)


def _gram(v: np.ndarray) -> np.ndarray:
    """sum over components of v_i . v_j: (n, 9, 3) -> (n, 9, 9) (the listing's SQUARE, summed)."""
    return np.einsum("nic,njc->nij", v, v)


def position_forms(loads: UnitLoads, c: Constants, quirks: CsspQuirks, positions: int) -> np.ndarray:
    """F at each position, eq. (4.2) with W1..W5 = 1: (n, 9, 9).

    ``positions`` is L of eq. (4.2) (the listing's 37, D070).  The listing leaves R4z
    out of R-bar (D065).
    """
    w2 = c.omega * c.omega
    c1 = positions * (c.masses[0] * c.masses[0]) * c.a1_sq * (w2 * w2)    # C1=37*(M1**2)*(A1**2)*(THT1D**4)
    c2, c3 = c1 * c.a1_sq, c1 * c.bearing_length_sq
    reactions = _without_r4z(loads.reactions, quirks)
    return (_gram(loads.shaking_force) / c1 + _gram(loads.shaking_moment) / c2
            + sum(_gram(r) for r in reactions) / c1 + sum(_gram(m) for m in loads.moments) / c3
            + np.einsum("ni,nj->nij", loads.input_torque, loads.input_torque) / c2)


def _without_r4z(reactions: tuple, quirks: CsspQuirks) -> tuple:
    if not quirks.bearing_force_no_z:
        return reactions
    r4 = reactions[3].copy()
    r4[..., 2] = 0.0
    return (*reactions[:3], r4)


def objective(forms: np.ndarray, x: np.ndarray, quirks: CsspQuirks, single: bool = False) -> np.ndarray:
    """G = x'Fx at each position; the listing doubles F's off-diagonal first (D064).

    ``single``: x is REAL*4 and the listing's sol(I4)*sol(J4) is a REAL*4 product.
    """
    if quirks.objective_offdiag_doubling:
        forms = 2.0 * forms - forms * np.eye(forms.shape[-1])
    xx = np.outer(x.astype(np.float32), x.astype(np.float32)).astype(float) if single else np.outer(x, x)
    return np.einsum("ij,nij->n", xx, forms)


def table_quantities(loads: UnitLoads, x: np.ndarray, quirks: CsspQuirks) -> dict:
    """Shaking force, shaking moment, bearing force, bearing torque, input torque for masses x.

    Bearing force = |R1 + R2 + R3 + R4| (eq. 3.16).  Bearing torque: as the listing sums it
    |M1 + M2 + M3 + M4| (eq. 3.17, M1 with its z-component, the input torque T0); without
    ``bearing_torque_with_input_torque`` (D132) |(M1 - T0) + M2 + M3 + M4|, the bearing
    moment of eq. (4.1) that section 5.3 names for Table 5.6 (T0 is Table 5.7's).
    """
    weigh = lambda v: np.einsum("k,nkc->nc", x, v)                         # noqa: E731
    reaction_sum = sum(weigh(r) for r in _without_r4z(loads.reactions, quirks))
    moment_sum = sum(weigh(m) for m in loads.moments)
    if quirks.bearing_torque_with_input_torque:
        moment_sum[:, 2] += loads.input_torque @ x
    return {"5_3": np.linalg.norm(weigh(loads.shaking_force), axis=1),
            "5_4": np.linalg.norm(weigh(loads.shaking_moment), axis=1),
            "5_5": np.linalg.norm(reaction_sum, axis=1),
            "5_6": np.linalg.norm(moment_sum, axis=1),
            "5_7": loads.input_torque @ x}
