"""Exact kinematics of the spatial slider crank both Rahman theses solve (1991: the method,
1996: the CSSP example), numpy, vectorised over crank angles.  Units: inch, second;
angles in radians (degrees only in ``Geometry.alpha4_deg`` and in error messages).  Frame
{1} is fixed; the crank turns about z1 at constant speed omega (theta1'' = 0).

Geometry (eqs. 2.3, 2.4, 2.6).  Crank pin P = (a1 cos th1, a1 sin th1, s1); crank frame
{2} at P with axes M1R = Rz(th1).  Slider point Q = (-a4, -s4 sin alpha4, -s4 cos alpha4):
the slider moves along k4 = (0, sin alpha4, cos alpha4) without rotating.  |Q - P| = a2 is
s4^2 + 2 b s4 + c = 0; we keep the root s4 = -b + sqrt(b^2 - c) at every angle (``branch``
+1, the default): it is the one the listing's first estimate sqrt(a2^2 - (a1 + a4)^2) = 7.416
converges to at th1 = 0 for the default data (7.544; the other root, ``branch`` -1, is
-7.270), and the one Rahman's (1991) example runs on.  The two roots meet only where
b^2 = c, i.e. where the rod is perpendicular to k4 (the edge of assembly).
Rod frame {3} at Q: R2 = M1R Rz(theta2) Ry(eta2) with first column u = (Q - P)/a2,
theta2 in [0, 2 pi), cos(eta2) > 0.  The crank pin is read as a Hooke joint (axes k1 and
M1R Rz(theta2) j): it fixes the rod's spin that the thesis neglects; the joint at Q is
spherical.  Velocities and accelerations are exact: second-order Taylor jets
(value, d/dt, d2/dt2) pushed through the position formulas.
"""
from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from ...errors import AssemblyError, SingularPositionError
from ...checks import angles_rad, real_array
from .geometry import CsspInputs, LoopConstants

TINY = 1e-9  # relative distance to a singular position below which we refuse


# ---- second-order jets: arrays whose axis 0 holds (value, d/dt, d2/dt2) ----
def _bil(op, a, b):
    """Jet of a bilinear product op(a, b) (Leibniz rule)."""
    return np.stack([op(a[0], b[0]), op(a[1], b[0]) + op(a[0], b[1]),
                     op(a[2], b[0]) + 2.0 * op(a[1], b[1]) + op(a[0], b[2])])


def _mul(a, b):
    return _bil(np.multiply, a, b)


def _chain(a, f, df, ddf):
    """Jet of f(a) for a scalar function f with derivatives df, ddf."""
    return np.stack([f(a[0]), df(a[0]) * a[1], ddf(a[0]) * a[1] ** 2 + df(a[0]) * a[2]])


def _cos(a):
    return _chain(a, np.cos, lambda x: -np.sin(x), lambda x: -np.cos(x))


def _sin(a):
    return _chain(a, np.sin, np.cos, lambda x: -np.sin(x))


def _sqrt(a):
    return _chain(a, np.sqrt, lambda x: 0.5 / np.sqrt(x), lambda x: -0.25 * x ** -1.5)


def _atan2(y, x):
    """Jet of atan2(y, x)."""
    r2 = x[0] ** 2 + y[0] ** 2
    n1, n2 = x[0] * y[1] - y[0] * x[1], x[0] * y[2] - y[0] * x[2]
    return np.stack([np.arctan2(y[0], x[0]), n1 / r2,
                     n2 / r2 - 2.0 * n1 * (x[0] * x[1] + y[0] * y[1]) / r2 ** 2])


def _matrix(rows):
    """Stack a 3x3 nested list of jets (3, n) into a jet (3, n, 3, 3)."""
    return np.stack([np.stack(row, axis=-1) for row in rows], axis=-2)


def _rz(c, s, zero, one):
    return _matrix([[c, -s, zero], [s, c, zero], [zero, zero, one]])


#: link dimensions (in), ground twist (deg), crank offset (in), speed (rpm): the example's inputs
Geometry = CsspInputs


def kinematics(geom: Geometry, theta1_rad, s1_jet=None, branch: int = 1) -> SimpleNamespace:
    """Positions (in), velocities (in/s), accelerations (in/s^2) over crank angles (rad).

    ``geom``: the loop's inputs (``CsspInputs``) or its numbers as one precision holds them
    (``LoopConstants``): a1, a2, a4, s1 (in), alpha4 (rad), omega (rad/s), k4.

    ``s1_jet``: the crank's axial offset S1 and its first two time derivatives (3, n), for a
    crank that slides as it turns (Rahman 1991, eq. 28); by default the constant geom.s1.

    ``branch``: the root of |Q - P| = a2 kept, s4 = -b + branch sqrt(b^2 - c) (+1 or -1).

    Attributes X, Xd, Xdd for X in P, Q, s4, u, M1R, R2, theta2, eta2; w2, alpha2 (rad/s,
    rad/s^2, rod angular velocity and acceleration); n2; ``jets`` holds them as (3, n, ...);
    ``condition``: the 2-norm condition number of the loop's velocity equations (the closure's
    Jacobian in s4 and the rod's angles per unit rod length, [k4, k1 x u, du/deta2]), which
    grows as 2/|u.k4| towards a toggle and as 1/cos(eta2) towards a locked Hooke joint.
    """
    if not isinstance(geom, (CsspInputs, LoopConstants)):
        raise TypeError(f"geom must be CsspInputs or LoopConstants, got {type(geom).__name__}")
    if isinstance(branch, bool) or branch not in (1, -1):
        raise ValueError(f"branch must be +1 or -1, got {branch!r}")
    th = angles_rad("theta1_rad", theta1_rad)
    deg, n = np.degrees(th), th.size
    one, zero = np.zeros((3, n)), np.zeros((3, n))
    one[0] = 1.0
    t = np.stack([th, np.full(n, geom.omega), np.zeros(n)])
    cth, sth = _cos(t), _sin(t)
    sa, ca = np.sin(geom.alpha4), np.cos(geom.alpha4)
    s1 = geom.s1 * one if s1_jet is None else _s1_jet(s1_jet, n)
    P = np.stack([geom.a1 * cth, geom.a1 * sth, s1], axis=-1)
    b = geom.a1 * sa * sth + ca * s1
    c = 2.0 * geom.a1 * geom.a4 * cth + _mul(s1, s1) + (geom.a4 ** 2 + geom.a1 ** 2 - geom.a2 ** 2) * one
    disc = _mul(b, b) - c
    if np.any(disc[0] < 0.0):
        i = int(np.argmax(disc[0] < 0.0))
        raise AssemblyError("CSSP: the rod cannot reach the slider line", float(deg[i]),
                            discriminant=float(disc[0, i]))
    _refuse(np.sqrt(disc[0]) / geom.a2, deg, "the rod is perpendicular to the slider axis")
    s4 = (_sqrt(disc) if branch == 1 else -_sqrt(disc)) - b
    Q = np.stack([-geom.a4 * one, -sa * s4, -ca * s4], axis=-1)
    u = (Q - P) / geom.a2
    vx, vy = _mul(cth, u[..., 0]) + _mul(sth, u[..., 1]), _mul(cth, u[..., 1]) - _mul(sth, u[..., 0])
    rho2 = _mul(vx, vx) + _mul(vy, vy)
    _refuse(np.sqrt(rho2[0]), deg, "the rod lies along the crank axis (Hooke joint locked)")
    rho = _sqrt(rho2)   # = cos(eta2) > 0
    theta2, eta2 = _atan2(vy, vx), _atan2(-u[..., 2], rho)
    theta2[0] %= 2.0 * np.pi
    M1R = _rz(cth, sth, zero, one)
    A = _bil(np.matmul, M1R, _rz(_cos(theta2), _sin(theta2), zero, one))
    ce, se = _cos(eta2), _sin(eta2)
    R2 = _bil(np.matmul, A, _matrix([[ce, zero, se], [zero, one, zero], [-se, zero, ce]]))
    e, k = A[..., :, 1], np.array([0.0, 0.0, 1.0])
    # the velocity equations' matrix: d(Q - P - a2 u)/d(s4, a2 theta2, a2 eta2) = -[k4, k x u, -R2 k]
    closure_jacobian = np.stack([np.broadcast_to(geom.k4, (n, 3)), np.cross(k, u[0]),
                                 -R2[0, :, :, 2]], axis=-1)
    kin = SimpleNamespace(theta1=th, omega=geom.omega, n2=-A[0, :, :, 0], condition=np.linalg.cond(closure_jacobian),
                          w2=(geom.omega + theta2[1])[:, None] * k + eta2[1][:, None] * e[0],
                          alpha2=theta2[2][:, None] * k + eta2[2][:, None] * e[0]
                          + eta2[1][:, None] * e[1],
                          jets=dict(P=P, Q=Q, s4=s4, u=u, M1R=M1R, R2=R2, theta2=theta2, eta2=eta2))
    for name, jet in kin.jets.items():
        for order, suffix in enumerate(("", "d", "dd")):
            setattr(kin, name + suffix, jet[order])
    return kin


def _s1_jet(value, n: int) -> np.ndarray:
    """The crank's axial offset and its two time derivatives (3, n): in, in/s, in/s^2."""
    jet = real_array("s1_jet", value)
    if jet.size != 3 * n or not np.all(np.isfinite(jet)):
        raise ValueError(f"s1_jet must hold 3 x {n} finite numbers (S1 and its rates), got shape {jet.shape}")
    return jet.reshape(3, n)


def _refuse(distance, deg, why):
    """SingularPositionError at the first angle whose distance to the singularity is tiny."""
    bad = distance <= TINY
    if np.any(bad):
        i = int(np.argmax(bad))
        raise SingularPositionError(f"CSSP: {why}", float(deg[i]), distance=float(distance[i]))
