"""Joint forces and torques of Rahman's (1991) generalized slider crank, section 2.8.

Units: inch, lbf, second; masses lbf*s^2/in.  Every array is batched over crank angles (n,).
Result: a dict of the 18 components of the thesis's joint vectors (65)-(68), each in its own
frame: 1F1 and 1T1 (about the origin of {1}) in {1}, 2F2 in {2} (the crank pin), 3F3 in
{3} (the rod), 4F4 and 4T4 (about the slider's ball) in {4}.

``printed_forces`` follows the thesis step by step: inertia binors (46)-(48), the mixed-path
velocities (33a), (36a), (32b), momenta and their rates (49a), (52a), (53a), (54), (57),
(58), the dual Euler vectors (59)-(61), and the solution (69a)-(69q) with the iterative
correction (69h)-(69k).  ``corrected_forces`` solves Newton-Euler for the exact, closed loop
(``slider_crank.kinematics.kinematics``), spin-free rod, centres of mass on the links, action equal to
reaction, and the crank's axial (thrust) force as an unknown.  Sign convention of both: each
vector is the load the link nearer the crank exerts at that joint (1F1, 1T1: the crank on the
frame; 2F2: the crank on the rod; 3F3: the rod on the slider; 4F4, 4T4: the slider on the
frame), which is the reading that makes the crank's equation (62) true; T1k = +100 lbf*in.
"""
from __future__ import annotations

import numpy as np

from ...errors import SingularPositionError
from .data import GscInputs, MassModel

COMPONENTS = ["F1i", "F1j", "F1k", "T1i", "T1j", "T1k", "F2i", "F2j", "F2k", "F3i", "F3j", "F3k",
              "F4i", "F4j", "F4k", "T4i", "T4j", "T4k"]
CORRECTION_TOL = 1e-9      # lbf: eq. (62a) "approximately satisfied"
CORRECTION_STEPS = 50


def binor(m: float, g: float, k2: tuple) -> np.ndarray:
    """Inertia binor (46)-(48): [[S', m I], [J, S]] with S = m [g i]x, J = m diag(K^2)."""
    s = m * np.array([[0.0, 0.0, 0.0], [0.0, 0.0, -g], [0.0, g, 0.0]])
    return np.block([[s.T, m * np.eye(3)], [m * np.diag(k2), s]])


def dual_euler(phi: np.ndarray, v: np.ndarray, v_dot: np.ndarray) -> np.ndarray:
    """f = H' + V x H, dual cross product (59)-(61); v, v_dot (n, 6) = (primary, dual)."""
    h, h_dot = v @ phi.T, v_dot @ phi.T
    vp, vd, hp, hd = v[:, :3], v[:, 3:], h[:, :3], h[:, 3:]
    return h_dot + np.concatenate([np.cross(vp, hp), np.cross(vp, hd) + np.cross(vd, hp)], axis=1)


def printed_forces(inputs: GscInputs, theta1, q, rates, accel, com_beyond_joint: bool = True,
                   action_reaction: bool = False) -> dict:
    """Eqs. (46)-(69q).  q (n, 5) = theta2, eta2, theta3, eta3, S4; rates, accel the same
    order's first and second derivatives; theta1'' = 0 (section 3.1).  ``action_reaction``:
    the rod's equations (63) take -2F2 and the slider's (64) -3F3 (register D088), which
    changes the signs in (69h), (69l)-(69o).  Returns the 18 components, ``eq62a`` (the
    residual left after the correction loop, lbf) and ``corrections`` (passes of 69k)."""
    th1 = np.asarray(theta1, dtype=float)
    n, w, a1, a2 = th1.size, inputs.omega, inputs.a1, inputs.a2
    s1, s1_d, s1_dd = inputs.axial(th1)
    mass = MassModel.of(inputs, com_beyond_joint)
    (m1, m2, m3), (g1, g2, g3) = mass.m, mass.g
    t2, e2, t3, e3, s4 = q.T
    _, _, t3_d, e3_d, s4_d = rates.T
    _, _, t3_dd, e3_dd, s4_dd = accel.T
    zero, c1, sn1, c2, sn2, c3, sn3 = (np.zeros(n), np.cos(th1), np.sin(th1), np.cos(t2),
                                       np.sin(t2), np.cos(t3), np.sin(t3))
    ce2, se2, ce3, se3 = np.cos(e2), np.sin(e2), np.cos(e3), np.sin(e3)
    col = lambda *xs: np.stack(xs, axis=1)
    v1 = col(zero, zero, zero + w, zero, a1 * w + zero, s1_d)                       # (33a)
    v1_dot = col(zero, zero, zero, zero, zero, s1_dd)
    v2 = col(zero, -e3_d, -t3_d, -s4_d * sn3, s4_d * c3, zero)                      # (36a)
    v2_dot = col(zero, -e3_dd, -t3_dd, -s4_dd * sn3 - s4_d * c3 * t3_d,
                 s4_dd * c3 - s4_d * sn3 * t3_d, zero)
    v3, v3_dot = col(*[zero] * 5, -s4_d), col(*[zero] * 5, -s4_dd)                 # (32b)
    f1 = dual_euler(binor(m1, g1, mass.k2[0]), v1, v1_dot)
    f2 = dual_euler(binor(m2, g2, mass.k2[1]), v2, v2_dot)
    f3 = dual_euler(binor(m3, g3, mass.k2[2]), v3, v3_dot)
    (f1xp, f1yp, f1zp, f1xd, f1yd, f1zd), (f2xp, f2yp, f2zp, _, f2yd, f2zd) = f1.T, f2.T
    f3xp, f3yp, f3zp, f3xd, f3yd, f3zd = f3.T
    t1k, f1k, sign = inputs.torque + zero, m1 * s1_dd, (-1.0 if action_reaction else 1.0)
    f2k = -(f1k + f1zp)                                                             # (69a)
    f3j = -(f2yp + f2zd / a2)                                                       # (69b)
    f3k = f2yd / a2 - f2zp                                                          # (69c)
    t4i, t4j, t4k = -f3xd, -f3yd, -f3zd                                             # (69d-f)
    f2j = -f1yp - (f1zd + t1k) / a1                                                 # (69g)
    with np.errstate(divide="ignore", invalid="ignore"):
        f2i = (f2j * a2 * c2 - sign * f2zd) / (a2 * sn2)                            # (69h)
    for passes in range(CORRECTION_STEPS):
        f1i = -(f2i + f1xp) * c1 - (t1k + f1zd) * sn1 / a1                          # (69i)
        f1j = -(f2i + f1xp) * sn1 + (t1k + f1zd) * c1 / a1                          # (69j)
        eq62a = f1i * c1 + f1j * sn1 + f2i + f1xp
        if np.all(np.abs(eq62a[np.isfinite(eq62a)]) <= CORRECTION_TOL):
            break
        f2i = -f1i * c1 - f1j * sn1 - f1xp                                          # (69k)
    f3i = -sign * (f2i * c2 * ce2 + f2j * sn2 * ce2 - f2k * se2) - f2xp             # (69l)
    f4k = sign * (f3j * c3 - f3i * sn3) - f3zp                                      # (69m)
    f4j = -(sign * (f3i * c3 * se3 + f3j * sn3 * se3 + f3k * ce3) + f3yp)           # (69n)
    f4i = -(sign * (f3i * c3 * ce3 + f3j * sn3 * ce3 - f3k * se3) + f3xp)           # (69o)
    t1j = f1i * s1 - f1xd * sn1 - (f1k * a1 + f1yd) * c1                            # (69p)
    t1i = -f1j * s1 - f1xd * c1 + (f1k * a1 + f1yd) * sn1                           # (69q)
    values = [f1i, f1j, f1k, t1i, t1j, t1k, f2i, f2j, f2k, f3i, f3j, f3k, f4i, f4j, f4k, t4i, t4j, t4k]
    return dict(zip(COMPONENTS, values), eq62a=eq62a, corrections=passes)


def corrected_forces(inputs: GscInputs, kin, strict: bool = True) -> dict:
    """Newton-Euler in {1} for the closed loop ``kin`` (``slider_crank.kinematics.kinematics``).

    Crank: turns at constant speed about k1 (no inertia moment about its centre of mass);
    rod: spin-free (omega = u x u'), so its moment about the centre of mass is
    I_t u x u''; slider: translates.  The rod fixes the crank-pin force normal to u, the
    crank's torque balance (T1k given) fixes its component along u; the slider's moment
    4T4 comes out zero.  At a dead centre, where T1k cannot be balanced ((P x u)_z = 0),
    raises SingularPositionError (``strict``) or returns inf/NaN there.
    """
    mass = MassModel.of(inputs, com_beyond_joint=False)
    (m1, m2, m3), kt2 = mass.m, mass.k2[1][1]
    P, Q, u, a_p, a_q, u_dd = kin.P, kin.Q, kin.u, kin.Pdd, kin.Qdd, kin.udd
    g1 = np.stack([P[:, 0] / 2.0, P[:, 1] / 2.0, P[:, 2]], axis=1)       # crank centre of mass
    a_g1 = np.stack([a_p[:, 0] / 2.0, a_p[:, 1] / 2.0, a_p[:, 2]], axis=1)
    g2, a_g2 = (P + Q) / 2.0, (a_p + a_q) / 2.0
    i_t = m2 * (kt2 - inputs.a2 ** 2 / 4.0)                              # about the rod's centre
    rhs = np.cross(g2 - Q, m2 * a_g2) + i_t * np.cross(u, u_dd)          # (P - Q) x F2 = rhs
    f2_normal = np.cross(-rhs / inputs.a2, u)
    lever = np.cross(P, u)[:, 2]
    if strict and np.any(dead_centre(kin)):
        i = int(np.argmax(dead_centre(kin)))
        raise SingularPositionError("GSC: dead centre, the constant crank torque cannot be balanced",
                                    float(np.degrees(kin.theta1[i])), lever=float(lever[i]))
    target = -inputs.torque - np.cross(g1, m1 * a_g1)[:, 2]             # (P x F2)_z
    f2 = f2_normal + ((target - np.cross(P, f2_normal)[:, 2]) / lever)[:, None] * u
    f1 = -f2 - m1 * a_g1
    t1 = -np.cross(P, f2) - np.cross(g1, m1 * a_g1)                     # its z is T1k
    f3 = f2 - m2 * a_g2
    f4 = f3 - m3 * a_q
    t4 = np.cross(Q, f3 - f4 - m3 * a_q)
    c1, s1 = np.cos(kin.theta1), np.sin(kin.theta1)
    f2_crank = np.stack([c1 * f2[:, 0] + s1 * f2[:, 1], -s1 * f2[:, 0] + c1 * f2[:, 1], f2[:, 2]], axis=1)
    f3_rod = np.einsum("nji,nj->ni", kin.R2, f3)
    ca, sa = np.cos(inputs.alpha4), np.sin(inputs.alpha4)
    x4 = np.array([[1.0, 0.0, 0.0], [0.0, ca, -sa], [0.0, sa, ca]])     # frame {1} -> {4}, eq. (4)
    values = np.concatenate([f1, t1, f2_crank, f3_rod, f4 @ x4.T, t4 @ x4.T], axis=1)
    return dict(zip(COMPONENTS, values.T))


def dead_centre(kin) -> np.ndarray:
    """True where crank and rod are collinear in plan, (P x u)_z = 0 to rounding (1e-12 a1)."""
    return np.abs(np.cross(kin.P, kin.u)[:, 2]) <= 1e-12 * np.abs(kin.P[:, :2]).max()
