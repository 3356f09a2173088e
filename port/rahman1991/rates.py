"""Joint rates of the 1991 five-variable loop without sine denominators (corrected formulation).

The thesis equates the forward- and backward-path dual velocities of the rod (eq. 37): six
linear equations (37a)-(37f) in the five rates (theta2', theta3', eta2', eta3', S4'), matrix
system (38).  It then solves them by hand into closed forms (39)-(43), (38a)-(42a) with
s(theta3) and s(theta2) s(theta3) in the denominators, which is what loses digits near the
dead centres (``rahman1991.printed_rates``).  Here the same six equations are solved by least
squares (QR, numpy.linalg.lstsq): velocities from M(q) q' = b(q), accelerations from
M q'' = b' - M' q', with M' and b' taken exactly by a complex step along q' (M and b are
analytic).  Row 6 uses eq. (37f); the printed matrix (38) drops a factor s(eta2) there
(register D090).  Units: rad, in, s.
"""
from __future__ import annotations

import numpy as np

STEP = 1e-30   # complex step (exact first derivative, no subtraction)


ORDER = (0, 2, 1, 3, 4)   # system's unknowns (theta2', theta3', eta2', eta3', S4') -> q's order


def system(q, theta1_d, s1_d, a1: float, a2: float) -> tuple[np.ndarray, np.ndarray]:
    """M (n, 6, 5) and b (n, 6) of eqs. (37a)-(37f) for q (n, 5) = theta2, eta2, theta3,
    eta3, S4 (real or complex); unknowns in the order (theta2', theta3', eta2', eta3', S4')."""
    t2, e2, t3 = q[:, 0], q[:, 1], q[:, 2]
    c2, s2, ce, se, c3, s3 = np.cos(t2), np.sin(t2), np.cos(e2), np.sin(e2), np.cos(t3), np.sin(t3)
    o, z = np.ones_like(c2), np.zeros_like(c2)
    m = np.stack([np.stack(row, axis=-1) for row in (
        [-se, z, s2 * ce, z, z],                       # (37a)
        [z, z, z, z, s3],                              # (37b)
        [z, z, c2, o, z],                              # (37c)
        [a2 * ce, z, a2 * s2 * se, z, -c3],            # (37d)
        [ce, o, s2 * se, z, z],                        # (37e)
        [z, z, -a2 * c2, z, z])], axis=-2)             # (37f)
    b = np.stack([theta1_d * se, -theta1_d * a1 * s2 * ce + s1_d * se, z,
                  -theta1_d * (a1 * c2 + a2 * ce), -theta1_d * ce,
                  -theta1_d * a1 * s2 * se - s1_d * ce], axis=-1)
    return m, b


def _lstsq(m: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Least-squares solution per position (n, 5), in q's order."""
    x = np.stack([np.linalg.lstsq(mi, bi, rcond=None)[0] for mi, bi in zip(m, b)])
    return x[:, ORDER]


def rates(q, theta1_d, theta1_dd, s1_d, s1_dd, a1: float, a2: float) -> tuple[np.ndarray, np.ndarray]:
    """(q', q'') (n, 5) each, in q's order, from the six velocity equations by least squares."""
    q = np.asarray(q, dtype=float)
    n = q.shape[0]
    w, w_dot = np.broadcast_to(theta1_d, (n,)), np.broadcast_to(theta1_dd, (n,))
    m, b = system(q, w, s1_d, a1, a2)
    q_d = _lstsq(m, b)
    m_c, b_c = system(q + 1j * STEP * q_d, w, s1_d, a1, a2)   # d/dt along q' by a complex step
    b_rate = system(q, w_dot, s1_dd, a1, a2)[1]
    b_dot = b_c.imag / STEP + b_rate
    m_dot = m_c.imag / STEP
    q_d_sys = q_d[:, np.argsort(ORDER)]
    q_dd = _lstsq(m, b_dot - np.einsum("nij,nj->ni", m_dot, q_d_sys))
    return q_d, q_dd
