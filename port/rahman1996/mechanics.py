"""Exact rigid-body mechanics of Rahman's (1996) generalized slider crank (CSSP), corrected.

Chapters 2-4 of the thesis rebuilt as one physically consistent model (not the listing):
numpy, vectorised over crank angles.  Units: inch, lbf, second; masses lbf*s^2/in; angles
in radians (degrees only in ``Geometry.alpha4_deg`` and in error messages).  Frame {1} is
fixed; the crank turns about z1 at constant speed omega (theta1'' = 0).

Geometry (eqs. 2.3, 2.4, 2.6).  Crank pin P = (a1 cos th1, a1 sin th1, s1); crank frame
{2} at P with axes M1R = Rz(th1).  Slider point Q = (-a4, -s4 sin alpha4, -s4 cos alpha4):
the slider moves along k4 = (0, sin alpha4, cos alpha4) without rotating.  |Q - P| = a2 is
s4^2 + 2 b s4 + c = 0; we keep the root s4 = -b + sqrt(b^2 - c) at every angle: it is the
one the listing's first estimate sqrt(a2^2 - (a1 + a4)^2) = 7.416 converges to at th1 = 0
for the default data (7.544; the other root is -7.270).  The two roots meet only where
b^2 = c, i.e. where the rod is perpendicular to k4 (the edge of assembly).
Rod frame {3} at Q: R2 = M1R Rz(theta2) Ry(eta2) with first column u = (Q - P)/a2,
theta2 in [0, 2 pi), cos(eta2) > 0.  The crank pin is read as a Hooke joint (axes k1 and
M1R Rz(theta2) j): it fixes the rod's spin that the thesis neglects; the joint at Q is
spherical.  Velocities and accelerations are exact: second-order Taylor jets
(value, d/dt, d2/dt2) pushed through the position formulas.

Mass model (section 2.2): each link by four point masses at the design distances of
eq. 2.12 (m_i = M/4); the nine design variables x (eq. 4.4) are masses at fixed points, so
every load is linear in x and is given per unit of each x_k.  A unit mass is two halves at
CG +- d (d = 0 for x4, x8 and the slider x9).

Reactions (Newton-Euler in {1}, moments about its origin), signs: F1, M1 act on the crank
from the frame at the origin (T0 = M1z drives it); F2 and M2 = mu2 n2 act on the rod from
the crank at P (n2 = M1R Rz(theta2) (-1, 0, 0), normal to both Hooke axes); F3 acts on the
slider from the rod at Q; F4 (normal to k4) and M4 act on the slider from the frame at Q.
"""
from __future__ import annotations

from dataclasses import dataclass
from types import SimpleNamespace

import numpy as np

from ...errors import AssemblyError, SingularPositionError
from .data import CsspInputs
from ..dual import skew

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


@dataclass(frozen=True)
class MassModel:
    """Weights (lbf) of crank, rod, slider; CG x-offsets (in) in frames {2}, {3}; radii of
    gyration (in) about the CG along the link axes; g (in/s^2)."""
    weights: tuple = (1.9, 7.6, 6.0)
    cg: tuple = (-1.0, -4.0)
    radii: tuple = ((0.2041241, 0.595119, 0.595119), (0.2041241, 2.3139072, 2.3139072))
    g: float = 386.4
    body = np.array([0, 0, 0, 0, 1, 1, 1, 1, 2])  # link of each design variable x1..x9

    @classmethod
    def default(cls) -> "MassModel":
        return cls()

    @property
    def M(self) -> np.ndarray:
        """Link masses M1, M2, M3 (lbf*s^2/in)."""
        return np.asarray(self.weights) / self.g

    @property
    def inertia(self) -> np.ndarray:
        """(2, 3) principal moments about the CG (lbf*s^2*in) of crank and rod."""
        return self.M[:2, None] * np.asarray(self.radii) ** 2

    @property
    def distances(self) -> np.ndarray:
        """(2, 3) X, Y, Z of eq. 2.12 with m1 = m2 = m3 = M/4 (in)."""
        ix, iy, iz = self.inertia.T
        sq = np.stack([iy + iz - ix, ix + iz - iy, ix + iy - iz], axis=-1)
        if np.any(sq < 0.0):
            raise ValueError("the principal moments violate the triangle inequality")
        return np.sqrt(sq / (2.0 * self.M[:2, None] / 4.0))

    @property
    def m(self) -> np.ndarray:
        """Original point masses x1..x9 (lbf*s^2/in)."""
        return np.repeat(self.M / [4.0, 4.0, 1.0], [4, 4, 1])

    def local_points(self) -> np.ndarray:
        """(9, 2, 3) the two halves of each unit mass in its link frame (in)."""
        pts = np.zeros((9, 2, 3))
        for link in (0, 1):
            offsets = np.vstack([np.diag(self.distances[link]), np.zeros(3)])
            centre = np.array([self.cg[link], 0.0, 0.0])
            pts[4 * link:4 * link + 4] = centre + np.stack([offsets, -offsets], axis=1)
        return pts


def kinematics(geom: Geometry, theta1_rad, s1_jet=None) -> SimpleNamespace:
    """Positions (in), velocities (in/s), accelerations (in/s^2) over crank angles (rad).

    ``s1_jet``: the crank's axial offset S1 and its first two time derivatives (3, n), for a
    crank that slides as it turns (Rahman 1991, eq. 28); by default the constant geom.s1.

    Attributes X, Xd, Xdd for X in P, Q, s4, u, M1R, R2, theta2, eta2; w2, alpha2 (rad/s,
    rad/s^2, rod angular velocity and acceleration); n2; ``jets`` holds them as (3, n, ...).
    """
    th = np.atleast_1d(np.asarray(theta1_rad, dtype=float))
    deg, n = np.degrees(th), th.size
    one, zero = np.zeros((3, n)), np.zeros((3, n))
    one[0] = 1.0
    t = np.stack([th, np.full(n, geom.omega), np.zeros(n)])
    cth, sth = _cos(t), _sin(t)
    sa, ca = np.sin(geom.alpha4), np.cos(geom.alpha4)
    s1 = geom.s1 * one if s1_jet is None else np.asarray(s1_jet, dtype=float).reshape(3, n)
    P = np.stack([geom.a1 * cth, geom.a1 * sth, s1], axis=-1)
    b = geom.a1 * sa * sth + ca * s1
    c = 2.0 * geom.a1 * geom.a4 * cth + _mul(s1, s1) + (geom.a4 ** 2 + geom.a1 ** 2 - geom.a2 ** 2) * one
    disc = _mul(b, b) - c
    if np.any(disc[0] < 0.0):
        i = int(np.argmax(disc[0] < 0.0))
        raise AssemblyError("CSSP: the rod cannot reach the slider line", float(deg[i]),
                            discriminant=float(disc[0, i]))
    _refuse(np.sqrt(disc[0]) / geom.a2, deg, "the rod is perpendicular to the slider axis")
    s4 = _sqrt(disc) - b
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
    kin = SimpleNamespace(theta1=th, omega=geom.omega, n2=-A[0, :, :, 0],
                          w2=(geom.omega + theta2[1])[:, None] * k + eta2[1][:, None] * e[0],
                          alpha2=theta2[2][:, None] * k + eta2[2][:, None] * e[0]
                          + eta2[1][:, None] * e[1],
                          jets=dict(P=P, Q=Q, s4=s4, u=u, M1R=M1R, R2=R2, theta2=theta2, eta2=eta2))
    for name, jet in kin.jets.items():
        for order, suffix in enumerate(("", "d", "dd")):
            setattr(kin, name + suffix, jet[order])
    return kin


def _refuse(distance, deg, why):
    """SingularPositionError at the first angle whose distance to the singularity is tiny."""
    bad = distance <= TINY
    if np.any(bad):
        i = int(np.argmax(bad))
        raise SingularPositionError(f"CSSP: {why}", float(deg[i]), distance=float(distance[i]))


def _point_jets(model: MassModel, kin) -> np.ndarray:
    """Jets (3, n, 9, 2, 3) of the absolute positions of both halves of every unit mass."""
    J = kin.jets
    still = np.zeros_like(J["R2"])
    still[0] = np.eye(3)
    local = model.local_points()
    parts = [origin[:, :, None, None, :] + np.einsum("onij,khj->onkhi", rot, local[model.body == link])
             for link, (origin, rot) in enumerate([(J["P"], J["M1R"]), (J["Q"], J["R2"]), (J["Q"], still)])]
    return np.concatenate(parts, axis=2)


def _reactions(geom: Geometry, model: MassModel, kin, force, moment):
    """Solve the 18 Newton-Euler equations per angle for every unit mass: (n, 9, 18).

    Unknowns: F1, M1, F2, mu2, F3, F4 along (i1, k4 x i1), M4.  Rows: crank, rod, slider,
    each 3 force then 3 moment equations."""
    n, E = kin.theta1.size, np.eye(3)
    Px, Qx, n2 = skew(kin.P), skew(kin.Q), kin.n2
    e4 = np.stack([E[0], np.cross(geom.k4, E[0])], axis=-1)  # (3, 2)
    A = np.zeros((n, 18, 18))
    A[:, 0:3, 0:3], A[:, 0:3, 6:9] = E, -E
    A[:, 3:6, 3:6], A[:, 3:6, 6:9], A[:, 3:6, 9] = E, -Px, -n2
    A[:, 6:9, 6:9], A[:, 6:9, 10:13] = E, -E
    A[:, 9:12, 6:9], A[:, 9:12, 9], A[:, 9:12, 10:13] = Px, n2, -Qx
    A[:, 12:15, 10:13], A[:, 12:15, 13:15] = E, e4
    A[:, 15:18, 10:13], A[:, 15:18, 13:15], A[:, 15:18, 15:18] = Qx, Qx @ e4, E
    B = np.zeros((n, 18, 9))
    for k, link in enumerate(model.body):
        B[:, 6 * link:6 * link + 3, k], B[:, 6 * link + 3:6 * link + 6, k] = force[:, k], moment[:, k]
    try:
        z = np.linalg.solve(A, B)
    except np.linalg.LinAlgError:
        _refuse(1.0 / np.linalg.cond(A), np.degrees(kin.theta1), "singular joint equations")
        raise
    z = np.swapaxes(z, 1, 2)
    return dict(F1=z[..., 0:3], M1=z[..., 3:6], F2=z[..., 6:9], mu2=z[..., 9],
                M2=z[..., 9, None] * n2[:, None, :], F3=z[..., 10:13],
                F4=z[..., 13:15] @ e4.T, M4=z[..., 15:18])


@dataclass(frozen=True)
class RigidBodyLoads:
    """Per unit of each design variable (axis 1, k = 0..8 for x1..x9), over angles (axis 0).

    r_half, v_half, a_half (n, 9, 2, 3): the two halves (in, in/s, in/s^2); r their centre;
    force = mean of a (the thesis's P per unit mass, lbf per lbf*s^2/in); moment = mean of
    r x a about the origin of {1}; ke = mean |v|^2 / 2; reactions F1..M4 as documented in the
    module (mu2 (n, 9) the Hooke moment along n2)."""
    kin: SimpleNamespace
    r_half: np.ndarray
    v_half: np.ndarray
    a_half: np.ndarray
    r: np.ndarray
    force: np.ndarray
    moment: np.ndarray
    ke: np.ndarray
    F1: np.ndarray
    M1: np.ndarray
    F2: np.ndarray
    mu2: np.ndarray
    M2: np.ndarray
    F3: np.ndarray
    F4: np.ndarray
    M4: np.ndarray

    @property
    def T0(self) -> np.ndarray:
        """Input torque per unit mass (lbf*in per lbf*s^2/in), (n, 9)."""
        return self.M1[..., 2]

    def total(self, name: str, x) -> np.ndarray:
        """The quantity ``name`` for the point masses x (9,), summed over them: (n, ...)."""
        return np.einsum("nk...,k->n...", getattr(self, name), np.asarray(x, dtype=float))


def unit_loads(geom: Geometry, model: MassModel, theta1_rad) -> RigidBodyLoads:
    """Inertia loads and joint reactions per unit point mass at crank angles (rad)."""
    kin = kinematics(geom, theta1_rad)
    r, v, a = _point_jets(model, kin)
    force, moment = a.mean(axis=2), np.cross(r, a).mean(axis=2)
    return RigidBodyLoads(kin=kin, r_half=r, v_half=v, a_half=a, r=r.mean(axis=2), force=force,
                     moment=moment, ke=0.5 * (v * v).sum(axis=-1).mean(axis=-1),
                     **_reactions(geom, model, kin, force, moment))


def kinetic_energy(geom: Geometry, model: MassModel, theta1_rad, x) -> np.ndarray:
    """Kinetic energy (lbf*in) per crank angle of the point masses x (9,)."""
    v = _point_jets(model, kinematics(geom, theta1_rad))[1]
    return 0.5 * np.einsum("nkh,k->n", (v * v).sum(axis=-1), np.asarray(x, dtype=float)) / 2.0


def closed_loop_loads(c, theta1_rad):
    """This model's loads in the form the objective takes (``cssp_objective.UnitLoads``).

    ``c``: a ``cssp_data.Constants`` (lengths, speed, masses as one precision holds them).
    Bearing moments: M1 without its z-component (T0), M2 of the Hooke joint, M3 = 0 of the
    ball joint, M4 of the slider's guide.
    """
    from .data import GRAVITY
    from .objective import UnitLoads as ObjectiveLoads
    masses = np.asarray(c.masses)
    radii = tuple(tuple(np.sqrt(np.asarray(i) / m)) for i, m in ((c.inertia_crank, masses[0]),
                                                                  (c.inertia_rod, masses[1])))
    geom = Geometry(a1=c.a1, a2=c.a2, a4=c.a4, alpha4_deg=float(np.degrees(c.alpha4)), s1=c.s1,
                    rpm=c.omega * 30.0 / np.pi)
    model = MassModel(weights=tuple(masses * GRAVITY), cg=c.cg, radii=radii, g=GRAVITY)
    loads = unit_loads(geom, model, theta1_rad)
    m1 = loads.M1.copy()
    m1[..., 2] = 0.0
    return ObjectiveLoads(shaking_force=loads.force, shaking_moment=loads.moment,
                          reactions=(loads.F1, loads.F2, loads.F3, loads.F4),
                          moments=(m1, loads.M2, np.zeros_like(m1), loads.M4), input_torque=loads.T0)
