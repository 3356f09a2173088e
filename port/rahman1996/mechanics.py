"""Exact rigid-body mechanics of Rahman's (1996) generalized slider crank (CSSP), corrected.

Chapters 2-4 of the thesis rebuilt as one physically consistent model (not the listing):
numpy, vectorised over crank angles.  Units: inch, lbf, second; masses lbf*s^2/in; angles
in radians (degrees only in ``Geometry.alpha4_deg`` and in error messages).  Frame {1} is
fixed; the crank turns about z1 at constant speed omega (theta1'' = 0).

Geometry and exact kinematics: ``linkrepro.port.slider_crank.kinematics`` (shared with the
1991 method).

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

from ...checks import angles_deg, refuse_singular_position
from ..dual import skew
from ..slider_crank.kinematics import Geometry, _refuse, kinematics


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


def closed_loop_loads(c, crank_deg):
    """This model's loads in the form the objective takes (``rahman1996.objective.UnitLoads``)
    at the crank angles ``crank_deg`` (deg).

    ``c``: a ``rahman1996.data.Constants`` (lengths, speed, masses as one precision holds them;
    its loop's numbers are the geometry).  Bearing moments: M1 without its z-component (T0),
    M2 of the Hooke joint, M3 = 0 of the ball joint, M4 of the slider's guide.  Raises
    SingularPositionError at the first angle where the loop is ill-conditioned
    (``linkrepro.checks.refuse_singular_position``, register D150).
    """
    from .data import GRAVITY, Constants
    from .objective import UnitLoads as ObjectiveLoads
    if not isinstance(c, Constants):
        raise TypeError(f"c must be rahman1996.data.Constants, got {type(c).__name__}")
    deg = angles_deg("crank_deg", crank_deg)
    masses = np.asarray(c.masses)
    radii = tuple(tuple(np.sqrt(np.asarray(i) / m)) for i, m in ((c.inertia_crank, masses[0]),
                                                                  (c.inertia_rod, masses[1])))
    model = MassModel(weights=tuple(masses * GRAVITY), cg=c.cg, radii=radii, g=GRAVITY)
    loads = unit_loads(c, model, np.radians(deg))
    refuse_singular_position(deg, loads.kin.condition)
    m1 = loads.M1.copy()
    m1[..., 2] = 0.0
    return ObjectiveLoads(shaking_force=loads.force, shaking_moment=loads.moment,
                          reactions=(loads.F1, loads.F2, loads.F3, loads.F4),
                          moments=(m1, loads.M2, np.zeros_like(m1), loads.M4), input_torque=loads.T0)
