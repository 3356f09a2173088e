"""Ali's (1977) flexible four-bar and its crossed cognate in Exudyn: the structure the corrected
port computes by the flexibility method, rebuilt from beam finite elements by code not written here.

The thesis (chapter III, Figure 4; eq. 29) freezes the linkage at an input angle and treats it
as a structure of Euler-Bernoulli members with axial and bending flexibility, no shear:

- the input link (crank) a cantilever clamped at the ground pivot (its input rotation held),
  pinned to the coupler at the crank pin A;
- the coupler AB and the extender AP one body, rigidly joined at A at the angle alpha (the
  cognate: gamma), the coupler pinned to the follower at B;
- the follower pinned at B and at its ground pivot (a two-force member: axial only, as eq. 29).

Here every link is ``elements`` Exudyn ``ObjectBeamGeometricallyExact2D`` (axial EA, bending EI
from ``data.EXAMPLE.section``) on ``NodeRigidBody2D`` nodes.  Shear stiffness: ``SHEAR_FACTOR``
* EA (stiff: Euler-Bernoulli up to the linear elements' mesh error c h^2), or, with
``shear_per_element`` = 1, 12 EI / h^2 per element, which cancels that error (MacNeal's residual
bending flexibility): the nodes then move as Euler-Bernoulli beams' on any mesh (the scene
``quasi_static`` measures both).  The coupler and
the extender share their node at A (a rigid joint), the pins are two coordinate constraints
(x, y), the supports coordinate constraints to ground.  The rigid configuration at the angle and
the accelerations behind the inertia loads are the corrected port's (``quirks=CORRECTED``).

Two modes:

- ``mode="frozen"``: the crank's root held in x, y and rotation: the instantaneous structure.
  ``Model.linear_deflection()`` is Exudyn's linear static answer (one Newton step of Exudyn's
  static solver from the unloaded reference: its tangent stiffness with the constraints, its
  load vector, the residual with the loads less the residual without; exact for a linear
  problem, so no load factor enters); ``mbs.SolveStatic`` gives
  the geometrically nonlinear one, ``mbs.ComputeODE2Eigenvalues`` the frozen structure's
  frequencies (with ``masses``).
- ``mode="driven"``: the crank's root rotation prescribed, phi = om2 * t (a coordinate
  constraint with a time offset), initial velocities the rigid linkage's, no applied loads:
  the masses' inertia loads the links (time integration with ``mbs.SolveDynamic``);
  ``Model.set_speed`` turns it at another speed, ``Model.damp`` damps the beams,
  ``Model.give_mass`` gives them a fraction of the links' mass.

Loads (frozen mode; the corrected port's, one physical force each, lbf):

- Case I: -(W/g) a_P at the path point P (W = EXAMPLE.mass_lbf, g = structure.GRAVITY_IN);
- Case II (the links' weights density * area * L, ``case2.DENSITY``): the extender's -(m2/g) a_P
  at P; the crank's -(m1/g) a_A at A; the follower's component along the follower,
  -(m4/g)(a_B . e4) e4, at B; the coupler's component along the coupler, -(m3/g)(a_A . e3) e3,
  at the crank pin A, where the thesis lumps it (``coupler_load_at``="B" puts it at B): the
  thesis's eight system forces P1..P8 of eq. (30), components it drops dropped here too, or with
  ``lumped``="full" the follower's and the coupler's whole inertia forces, -(m4/g) a_B and
  -(m3/g) a_A (the alternative to the thesis's choice that register entry D185 measures);
- Case III: the extender's weight in n equal parts (``case3``: density * area * L2 / n) at
  L2, L2 - L2/n, ..., L2/n from A, each -(w/g) a at its node (``n_nodes``).

Masses (for ``ComputeODE2Eigenvalues`` and the driven mode): ``masses="lumped"`` puts the
case's masses (as above: Case II's coupler mass at A, where the thesis lumps it) as point masses
on the nodes and leaves the beams massless; ``masses="distributed"`` gives every beam its mass per
length density * area / g (and rotary inertia density * I / g), plus Case I's point mass at P;
``masses="none"``.

Everything is in the source four-bar's frame (the cognate turned and moved as the port turns its
deflections, D025): x, y in inches, rotations in radians, forces in lbf, masses in lbf s^2/in,
time in s; crank angles ``deg`` in degrees.
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

import numpy as np

from ...multibody import require
from ....port.ali1977 import case2 as _case2, case3 as _case3
from ....port.ali1977.case1 import cognate_case1, source_case1
from ....port.ali1977.cognate import cognate_linkage
from ....port.ali1977.data import EXAMPLE
from ....port.ali1977.quirks import CORRECTED
from ....port.ali1977.source import source_linkage
from ....port.ali1977.structure import GRAVITY_IN

SIDES = ("source", "cognate")
CASES = (1, 2, 3)
#: the beams' shear stiffness by default, a multiple of their axial stiffness EA: the thesis's
#: members have no shear flexibility (eq. 29); the quasi-static scene measures what is left
SHEAR_FACTOR = 1.0e4
#: the listing's Case III nodes (n = 5)
CASE3_NODES = 5
MODES = ("frozen", "driven")
#: Newton's relative tolerance in Model.simulation_settings
NEWTON_TOLERANCE = 1e-6
MASSES = ("lumped", "distributed", "none")


def _unit(angle):
    """(cos, sin) of ``angle`` (rad), as an array (2,) or (2, N)."""
    return np.array([np.cos(angle), np.sin(angle)])


def _rotation(angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s], [s, c]])


@dataclass(frozen=True)
class Rigid:
    """The rigid linkage over the crank angles ``deg`` (deg), from the corrected port, in the
    source frame: joint positions (2, N) in inches: ``o2`` the crank's ground pivot, ``a`` the
    crank pin, ``b`` the follower pin, ``o4`` the follower's ground pivot, ``p`` the path point;
    accelerations (2, N) in in/s^2 of ``a``, ``b`` and ``p`` (``acc_p``); ``om2`` (rad/s) the
    crank speed, ``om3`` (N,) the coupler's angular velocity; ``lengths`` (crank, extender,
    coupler, follower) in inches; ``turn`` (rad) the mechanism's own frame's turn into the
    source frame (0 for the source), ``shift`` (2,) its move; ``linkage`` the port's Linkage
    (its own frame), for accelerations of points along the extender (``extender_acceleration``)."""
    side: str
    deg: np.ndarray
    o2: np.ndarray
    a: np.ndarray
    b: np.ndarray
    o4: np.ndarray
    p: np.ndarray
    acc_a: np.ndarray
    acc_b: np.ndarray
    acc_p: np.ndarray
    om2: float
    om3: np.ndarray
    lengths: tuple
    turn: float
    shift: np.ndarray
    linkage: object = field(repr=False)

    def to_source(self, own: np.ndarray, point: bool = True) -> np.ndarray:
        """Vectors (2, ...) of the mechanism's own frame into the source frame (a point is also moved)."""
        own = np.asarray(own, dtype=float)
        out = np.tensordot(_rotation(self.turn), own, axes=1)
        return out + self.shift.reshape((2,) + (1,) * (own.ndim - 1)) if point else out

    def extender_acceleration(self, r) -> np.ndarray:
        """Accelerations (n, 2, N) in in/s^2 (source frame) of the points ``r`` (n,) inches along
        the extender from A."""
        acc = self.linkage.acceleration(np.asarray(r, dtype=float)[:, None])        # (n, N, 2), own frame
        return np.stack([self.to_source(a.T, point=False) for a in acc])

    def extender_point(self, r) -> np.ndarray:
        """Positions (n, 2, N) in inches (source frame) of the points ``r`` (n,) along the extender."""
        x, y = self.linkage.position(np.asarray(r, dtype=float)[:, None])
        return np.stack([self.to_source(np.array([x[k], y[k]])) for k in range(len(x))])


def rigid(side: str, deg) -> Rigid:
    """The rigid linkage of ``side`` ("source" or "cognate") at the crank angles ``deg`` (deg, a
    1-D array), as the corrected port computes it (example data: 60 deg, 300 rpm)."""
    deg = np.atleast_1d(np.asarray(deg, dtype=float))
    if side == "source":
        link = source_linkage(deg, quirks=CORRECTED)
        l1, l2, l3, l4, l5 = (EXAMPLE.lengths.l1, EXAMPLE.lengths.l2, EXAMPLE.lengths.l3, EXAMPLE.lengths.l4,
                              EXAMPLE.lengths.l5)
        coupler, turn, shift = 1.0, 0.0, np.zeros(2)
    elif side == "cognate":
        link = cognate_linkage(deg, quirks=CORRECTED)
        cog = link.cognate
        l1, l2, l3, l4, l5 = cog.cl1, cog.cl2, cog.cl3, cog.cl4, cog.cl5
        coupler, turn = -1.0, -cog.beta                 # B' = A' - CL3 e3; the port's frame turn (D025)
        shift = np.array([EXAMPLE.lengths.l5, 0.0]) - _rotation(turn) @ np.array([l5, 0.0])
    else:
        raise ValueError(f"side must be one of {SIDES}, got {side!r}")
    a = l1 * _unit(link.t2)
    b = a + coupler * l3 * _unit(link.t3)
    p = a + l2 * _unit(link.ext_angle)
    o4 = np.array([l5, 0.0])[:, None] * np.ones(len(deg))
    (xaa, yaa), (xba, yba) = link.pin_accelerations()
    acc_p = link.acceleration(l2).T
    partial = Rigid(side, deg, np.zeros((2, len(deg))), a, b, o4, p, np.array([xaa, yaa]), np.array([xba, yba]),
                    acc_p, float(link.om2), np.asarray(link.om3), (l1, l2, l3, l4), turn, shift, link)
    if side == "source" and not np.allclose(b - l4 * _unit(link.t4), o4, rtol=0, atol=1e-9):
        raise AssertionError("the source loop does not close")      # the port's t4 convention changed
    return Rigid(side, deg, *(partial.to_source(v) for v in (partial.o2, a, b, o4, p)),
                 *(partial.to_source(v, point=False) for v in (partial.acc_a, partial.acc_b, acc_p)),
                 partial.om2, partial.om3, partial.lengths, turn, shift, link)


def point_loads(rig: Rigid, case: int, n_nodes: int = CASE3_NODES, coupler_load_at: str = "A",
                lumped: str = "axial") -> dict:
    """The case's loads (the corrected port's, see the module's docstring) as physical forces:
    {where: (2, N) lbf, source frame}, where "P", "A", "B" or ("extender", r) for Case III's node
    r inches from A; ``lumped`` (Case II): "axial" or "full" (``case2.LUMPED``)."""
    g = GRAVITY_IN
    if case == 1:
        return {"P": -(EXAMPLE.mass_lbf / g) * rig.acc_p}
    if case == 2:
        l1, l2, l3, l4 = rig.lengths
        m1, m2, m3, m4 = (_case2.DENSITY * (EXAMPLE.section.area * length) / g for length in (l1, l2, l3, l4))
        e3 = (rig.b - rig.a) / l3
        e4 = (rig.o4 - rig.b) / l4
        if lumped not in _case2.LUMPED:
            raise ValueError(f"lumped must be one of {_case2.LUMPED}, got {lumped!r}")

        def along(acc, e):        # the component along e (the thesis's), or the whole vector
            return acc if lumped == "full" else np.sum(acc * e, axis=0) * e
        loads = {"P": -m2 * rig.acc_p, "A": -m1 * rig.acc_a, "B": -m4 * along(rig.acc_b, e4)}
        coupler = -m3 * along(rig.acc_a, e3)
        if coupler_load_at not in ("A", "B"):
            raise ValueError(f"coupler_load_at must be 'A' or 'B', got {coupler_load_at!r}")
        loads[coupler_load_at] = loads[coupler_load_at] + coupler
        return loads
    if case == 3:
        l2 = rig.lengths[1]
        r = l2 - np.arange(n_nodes) * (l2 / n_nodes)
        w = _case3.DENSITY * EXAMPLE.section.area * (l2 / n_nodes) / g
        acc = rig.extender_acceleration(r)
        return {("extender", float(rk)): -w * acc[k] for k, rk in enumerate(r)}
    raise ValueError(f"case must be one of {CASES}, got {case!r}")


def port_deflections(side: str, case: int, deg, n_nodes: int = CASE3_NODES, quirks=CORRECTED,
                     lumped: str = "axial") -> dict:
    """The port's path-point deflections: ``dx``, ``dy`` (in, source frame), ``rot`` (rad) over
    ``deg`` (deg), with ``quirks`` (CORRECTED by default) and the example's data; ``lumped``
    Case II's (``case2.LUMPED``)."""
    deg = np.atleast_1d(np.asarray(deg, dtype=float))
    calls = {(1, "source"): lambda: source_case1(deg, mass_lbf=EXAMPLE.mass_lbf, quirks=quirks),
             (1, "cognate"): lambda: cognate_case1(deg, mass_lbf=EXAMPLE.mass_lbf, quirks=quirks),
             (2, "source"): lambda: _case2.case2_source(deg, quirks=quirks, lumped=lumped),
             (2, "cognate"): lambda: _case2.case2_cognate(deg, quirks=quirks, lumped=lumped),
             (3, "source"): lambda: _case3.case3_source(deg, n_nodes, quirks=quirks),
             (3, "cognate"): lambda: _case3.case3_cognate(deg, n_nodes, quirks=quirks)}
    if (case, side) not in calls:
        raise ValueError(f"no port for case {case!r}, side {side!r}")
    out = calls[case, side]()
    return {"dx": np.asarray(out["dx"]), "dy": np.asarray(out["dy"]), "rot": np.asarray(out["rot"])}


@dataclass
class Model:
    """One Exudyn model of the flexible linkage at one crank angle (``build``).

    ``sc``, ``mbs`` Exudyn's SystemContainer and MainSystem (assembled); ``nodes`` the node
    numbers per link, from the link's first joint: "crank" (O2 -> A), "coupler" (A -> B),
    "extender" (A -> P; its first node is the coupler's), "follower" (B -> O4); ``path_node``
    the node at P; ``crank_root`` the node at O2; ``crank_constraint`` the object holding (frozen)
    or driving (driven) the crank's rotation; ``loads`` the applied loads as (node, (fx, fy))
    in lbf, ``load_numbers`` their Exudyn load numbers; ``rigid`` the port's rigid linkage at this
    angle (``Rigid`` over one angle); ``settings`` ``simulation_settings()``."""
    side: str
    case: int
    deg: float
    mode: str
    elements: int
    sc: object
    mbs: object
    nodes: dict
    path_node: int
    crank_root: int
    crank_constraint: int
    loads: list
    rigid: Rigid
    settings: object = None
    load_numbers: list = field(default_factory=list)
    #: build's load arguments (n_nodes, coupler_load_at, lumped, load_scale), for ``move``
    load_options: dict = field(default_factory=dict)

    def simulation_settings(self):
        """Exudyn SimulationSettings for deterministic solves (one thread, dense solver); Newton's
        relative tolerance 1e-6 (the stiff shear, SHEAR_FACTOR, puts the residual's rounding floor
        near 1e-7 of the loads: tighter does not converge)."""
        exu = require()
        ss = exu.SimulationSettings()
        ss.staticSolver.newton.relativeTolerance = NEWTON_TOLERANCE
        ss.timeIntegration.newton.relativeTolerance = NEWTON_TOLERANCE
        ss.parallel.numberOfThreads = 1
        ss.linearSolver.solverType = exu.LinearSolverType.EXUdense
        ss.staticSolver.verboseMode = 0
        ss.timeIntegration.verboseMode = 0
        ss.solution.file.write = False
        return ss

    def move(self, deg: float) -> None:
        """A frozen model moved to the crank angle ``deg`` (deg): its nodes' reference positions and
        its loads set to the rigid linkage's there, and reassembled: the model ``build`` makes at
        ``deg`` (the same numbers, without adding every item again)."""
        if self.mode != "frozen":
            raise ValueError("move needs the frozen structure (mode='frozen')")
        rig = _rigid_at(self.side, float(deg).hex())
        for link, points in _node_positions(rig, self.elements, len(self.nodes["extender"]) - 1).items():
            for node, x in zip(self.nodes[link][-len(points):], points):
                self.mbs.SetNodeParameter(node, "referenceCoordinates", [float(x[0]), float(x[1]), 0.0])
        self.loads = [(node, force) for (node, _), force in zip(self.loads, _load_values(rig, self.case,
                                                                                        **self.load_options))]
        for number, (_, (fx, fy)) in zip(self.load_numbers, self.loads):
            self.mbs.SetLoadParameter(number, "loadVector", [fx, fy, 0.0])
        self.mbs.Assemble()
        self.deg, self.rigid = float(deg), rig

    def _residuals(self, solver, settings) -> tuple[np.ndarray, np.ndarray]:
        """Exudyn's static residual at the current state with the loads, and without them (the
        loads set to zero for the call, then restored)."""
        solver.ComputeNewtonResidual(self.mbs, settings)
        loaded = np.array(solver.GetSystemResidual())
        vectors = [self.mbs.GetLoadParameter(n, "loadVector") for n in self.load_numbers]
        for n in self.load_numbers:
            self.mbs.SetLoadParameter(n, "loadVector", [0.0, 0.0, 0.0])
        solver.ComputeNewtonResidual(self.mbs, settings)
        unloaded = np.array(solver.GetSystemResidual())
        for n, vector in zip(self.load_numbers, vectors):
            self.mbs.SetLoadParameter(n, "loadVector", list(vector))
        return loaded, unloaded

    def _static_system(self) -> tuple[np.ndarray, np.ndarray]:
        """Exudyn's static Jacobian (ODE2 and constraint rows) at the unloaded reference and its
        load vector: the residual with the loads minus the residual without them (the latter is
        the reference's rounding, a few 1e-6 lbf where the shear is stiff, not a load)."""
        if self.mode != "frozen":
            raise ValueError("a static solve needs the frozen structure (mode='frozen')")
        exu = require()
        settings = self.settings or self.simulation_settings()
        solver = exu.MainSolverStatic()
        solver.InitializeSolver(self.mbs, settings)
        loaded, unloaded = self._residuals(solver, settings)
        solver.ComputeNewtonJacobian(self.mbs, settings)
        jacobian = np.array(solver.GetSystemJacobian())
        solver.FinalizeSolver(self.mbs, settings)
        return jacobian, loaded - unloaded

    def jacobian(self) -> np.ndarray:
        """Exudyn's static Jacobian (ODE2 and constraint rows) at the unloaded reference (frozen mode)."""
        return self._static_system()[0]

    def linear_solution(self) -> np.ndarray:
        """The linear static displacement of every ODE2 coordinate (in, rad): the Newton step of
        Exudyn's static solver from the unloaded reference, u = -J^-1 r (J its Jacobian with the
        constraints, r its residual's load part: ``load_vector``).  Frozen mode only."""
        jacobian, residual = self._static_system()
        return -np.linalg.solve(jacobian, residual)[:self.mbs.systemData.ODE2Size()]

    def load_vector(self) -> np.ndarray:
        """The loads as Exudyn's static residual holds them at the unloaded reference (lbf, per
        ODE2 coordinate): a check that the model carries the loads ``loads`` says."""
        return self._static_system()[1][:self.mbs.systemData.ODE2Size()]

    def node_displacement(self, node: int, solution: np.ndarray | None = None) -> np.ndarray:
        """(dx, dy, rotation) of ``node`` (in, in, rad): of ``solution`` (linear_solution's) or of
        the current state."""
        if solution is None:
            return np.array(self.mbs.GetNodeOutput(node, require().OutputVariableType.Coordinates))
        index = self.mbs.GetNodeODE2Index(node)
        return np.array(solution[index:index + 3])

    def linear_deflection(self) -> np.ndarray:
        """The path point's linear quasi-static deflection (dx, dy in inches, source frame; rotation
        in radians): what the port's dx, dy, rot compute."""
        return self.node_displacement(self.path_node, self.linear_solution())

    def path_point(self) -> np.ndarray:
        """The path point's current position (x, y, in inches, source frame) in Exudyn's state."""
        return np.array(self.mbs.GetNodeOutput(self.path_node, require().OutputVariableType.Position))[:2]

    def _beams(self):
        """The numbers of the model's beam elements."""
        return [item for item in range(self.mbs.systemData.NumberOfObjects())
                if self.mbs.GetObject(item)["objectType"] == "BeamGeometricallyExact2D"]

    def damp(self, beta: float) -> None:
        """Every beam damped: its bending, axial and shear damping ``beta`` (s) times its stiffness
        (stiffness-proportional, Kelvin-Voigt)."""
        for item in self._beams():
            beam = self.mbs.GetObject(item)
            for what in ("bending", "axial", "shear"):
                self.mbs.SetObjectParameter(item, f"{what}Damping", beta * beam[f"{what}Stiffness"])

    def give_mass(self, fraction: float) -> None:
        """Every beam given ``fraction`` of the links' own mass per length and rotary inertia
        (``case2.DENSITY`` * A / g, * I / g; lbf s^2/in^2, lbf s^2)."""
        sec = EXAMPLE.section
        for item in self._beams():
            self.mbs.SetObjectParameter(item, "massPerLength", fraction * _case2.DENSITY * sec.area / GRAVITY_IN)
            self.mbs.SetObjectParameter(item, "crossSectionInertia", fraction * _case2.DENSITY * sec.inertia / GRAVITY_IN)

    def set_speed(self, rpm: float) -> None:
        """A driven model (built at the example's speed) turned at ``rpm``: its nodes' initial
        velocities and its crank drive scaled by rpm / EXAMPLE.rpm (at constant crank speed every
        rigid velocity is proportional to it)."""
        if self.mode != "driven":
            raise ValueError("set_speed needs the driven linkage (mode='driven')")
        scale = rpm / EXAMPLE.rpm
        if not math.isclose(self.rigid.om2, 2.0 * math.pi * EXAMPLE.rpm / 60.0, rel_tol=1e-12):
            raise ValueError(f"the model's crank speed {self.rigid.om2} rad/s is not the example's {EXAMPLE.rpm} rpm")
        for node in range(self.mbs.systemData.NumberOfNodes()):
            data = self.mbs.GetNode(node)
            if data["nodeType"] == "RigidBody2D":
                self.mbs.SetNodeParameter(node, "initialVelocities", [scale * v for v in data["initialVelocities"]])
        om2 = scale * self.rigid.om2
        self.mbs.SetObjectParameter(self.crank_constraint, "offsetUserFunction", lambda mbs, t, item, offset: om2 * t)


@functools.lru_cache(maxsize=4096)
def _rigid_at(side: str, deg_hex: str) -> Rigid:
    """``rigid`` at one crank angle, given as ``float.hex`` (so that -0.0 is not 0.0), cached:
    the scene solves the structure at the same angles for many meshes and shear models."""
    return rigid(side, [float.fromhex(deg_hex)])


def rigid_path_point(side: str, deg) -> np.ndarray:
    """The rigid path point (2, N) in inches, source frame, at the crank angles ``deg`` (deg):
    the corrected port's kinematics (subtract it from ``Model.path_point`` for the deflection)."""
    return rigid(side, deg).p


def crank_angle(rig: Rigid, t: float, deg0: float) -> float:
    """The crank angle (deg) at time ``t`` (s) of a run driven from ``deg0`` at the port's speed."""
    return deg0 + math.degrees(rig.om2 * t)


def _node_positions(rig: Rigid, elements: int, ext_elements: int) -> dict:
    """Where each link's nodes lie (in, source frame) at the rigid linkage's (one) angle, with
    ``elements`` per link (the extender ``ext_elements``): {link: positions from its first
    joint}, the extender's without its first (the coupler's, at A)."""
    o2, a, b, o4, p = (v[:, 0] for v in (rig.o2, rig.a, rig.b, rig.o4, rig.p))

    def along(start, end, count, first=True):
        return [start] * first + [start + (end - start) * (k / count) for k in range(1, count + 1)]
    return {"crank": along(o2, a, elements), "coupler": along(a, b, elements),
            "extender": along(a, p, ext_elements, first=False), "follower": along(b, o4, elements)}


def _load_values(rig: Rigid, case: int, n_nodes: int, coupler_load_at: str, lumped: str,
                 load_scale: float) -> list:
    """The case's loads (``point_loads``) at the rigid linkage's one angle, each times
    ``load_scale``: [(fx, fy)] in lbf, in ``point_loads``' order."""
    return [(load_scale * float(force[0, 0]), load_scale * float(force[1, 0]))
            for force in point_loads(rig, case, n_nodes, coupler_load_at, lumped).values()]


def build(side: str, deg: float, case: int = 1, elements: int = 8, *, mode: str = "frozen",
          n_nodes: int = CASE3_NODES, masses: str = "lumped", shear_factor: float = SHEAR_FACTOR,
          coupler_load_at: str = "A", loads: bool | None = None, load_scale: float = 1.0,
          shear_per_element: float | None = None, lumped: str = "axial") -> Model:
    """The flexible linkage of ``side`` at the crank angle ``deg`` (deg) with ``elements`` beam
    elements per link (Case III: the extender's the least common multiple of ``elements`` and
    ``n_nodes``, so that its nodes carry the loads and doubling ``elements`` halves every element),
    assembled.  ``mode`` "frozen" (crank held; the case's loads applied
    unless ``loads`` is False) or "driven" (crank rotation om2 * t from ``deg``; no loads unless
    ``loads``), every load times ``load_scale``.  ``masses`` see the module's docstring.
    Shear stiffness: ``shear_factor`` * EA, or where ``shear_per_element`` (kappa) is given,
    kappa * 12 EI / h^2 for elements of length h (a shear flexibility that vanishes with h^2, as
    the linear element's own error does: see the scene ``quasi_static``).  ``lumped``: Case II's
    loads (``point_loads``)."""
    exu = require()
    from exudyn.itemInterface import (CoordinateConstraint, LoadForceVector, MarkerNodeCoordinate, MarkerNodePosition,
                                      NodePointGround, NodeRigidBody2D, ObjectBeamGeometricallyExact2D,
                                      ObjectMassPoint2D)
    if mode not in MODES:
        raise ValueError(f"mode must be one of {MODES}, got {mode!r}")
    if masses not in MASSES:
        raise ValueError(f"masses must be one of {MASSES}, got {masses!r}")
    if int(elements) != elements or elements < 1:
        raise ValueError(f"elements must be a positive integer, got {elements!r}")
    rig = rigid(side, [deg])
    applied = point_loads(rig, case, n_nodes, coupler_load_at, lumped)          # checks case
    load_options = dict(n_nodes=n_nodes, coupler_load_at=coupler_load_at, lumped=lumped, load_scale=load_scale)
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    sec = EXAMPLE.section
    ea, ei = sec.area * sec.modulus, sec.modulus * sec.inertia
    mass_per_length = _case2.DENSITY * sec.area / GRAVITY_IN if masses == "distributed" else 0.0
    rotary = _case2.DENSITY * sec.inertia / GRAVITY_IN if masses == "distributed" else 0.0
    # rigid-body velocities (driven mode's initial state): crank om2 about O2, coupler body om3
    om2, om3 = rig.om2, float(rig.om3[0])
    o2, a, b, o4, p = (v[:, 0] for v in (rig.o2, rig.a, rig.b, rig.o4, rig.p))
    perp = lambda v: np.array([-v[1], v[0]])                      # noqa: E731  k x v
    v_a = om2 * perp(a - o2)
    v_b = v_a + om3 * perp(b - a)
    arm = b - o4
    om4 = float((arm[0] * v_b[1] - arm[1] * v_b[0]) / np.dot(arm, arm))         # v_B = om4 k x (B - O4)
    driven = mode == "driven"

    def velocity(x, link):
        if link == "crank":
            return [*(om2 * perp(x - o2)), om2]
        if link in ("coupler", "extender"):
            return [*(v_a + om3 * perp(x - a)), om3]
        return [*(om4 * perp(x - o4)), om4]

    def add_node(x, link):
        return mbs.AddNode(NodeRigidBody2D(referenceCoordinates=[float(x[0]), float(x[1]), 0.0],
                                           initialVelocities=velocity(x, link) if driven else [0.0, 0.0, 0.0]))

    l1, l2, l3, l4 = rig.lengths
    ext_elements = elements if case != 3 else math.lcm(int(elements), int(n_nodes))
    points = _node_positions(rig, int(elements), ext_elements)

    def add_link(link, length, first=None):
        nodes = ([] if first is None else [first]) + [add_node(x, link) for x in points[link]]
        h = length / (len(nodes) - 1)
        shear = shear_factor * ea if shear_per_element is None else shear_per_element * 12.0 * ei / (h * h)
        for n0, n1 in zip(nodes[:-1], nodes[1:]):
            mbs.AddObject(ObjectBeamGeometricallyExact2D(
                nodeNumbers=[n0, n1], length=h, massPerLength=mass_per_length, crossSectionInertia=rotary,
                bendingStiffness=ei, axialStiffness=ea, shearStiffness=shear, includeReferenceRotations=False))
        return nodes

    nodes = {"crank": add_link("crank", l1)}
    nodes["coupler"] = add_link("coupler", l3)
    nodes["extender"] = add_link("extender", l2, first=nodes["coupler"][0])
    nodes["follower"] = add_link("follower", l4)

    ground = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=mbs.AddNode(NodePointGround()), coordinate=0))

    def coordinate(node, c):
        return mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=node, coordinate=c))

    root = nodes["crank"][0]
    for c in (0, 1):
        mbs.AddObject(CoordinateConstraint(markerNumbers=[ground, coordinate(root, c)]))        # O2
        mbs.AddObject(CoordinateConstraint(markerNumbers=[coordinate(nodes["crank"][-1], c),
                                                          coordinate(nodes["coupler"][0], c)]))   # pin A
        mbs.AddObject(CoordinateConstraint(markerNumbers=[coordinate(nodes["coupler"][-1], c),
                                                          coordinate(nodes["follower"][0], c)]))  # pin B
        mbs.AddObject(CoordinateConstraint(markerNumbers=[ground, coordinate(nodes["follower"][-1], c)]))  # O4
    if driven:
        crank_constraint = mbs.AddObject(CoordinateConstraint(
            markerNumbers=[ground, coordinate(root, 2)],
            offsetUserFunction=lambda mbs_, t, item, offset: om2 * t))
    else:
        crank_constraint = mbs.AddObject(CoordinateConstraint(markerNumbers=[ground, coordinate(root, 2)]))

    where = {"P": nodes["extender"][-1], "A": nodes["crank"][-1], "B": nodes["follower"][0]}
    step = l2 / ext_elements
    for key in applied:
        if isinstance(key, tuple):                                    # Case III: the extender's node r from A
            where[key] = nodes["extender"][int(round(key[1] / step))]
    load_list, load_numbers = [], []
    if loads if loads is not None else not driven:
        for key, (fx, fy) in zip(applied, _load_values(rig, case, **load_options)):
            load_numbers.append(mbs.AddLoad(LoadForceVector(
                markerNumber=mbs.AddMarker(MarkerNodePosition(nodeNumber=where[key])), loadVector=[fx, fy, 0.0])))
            load_list.append((where[key], (fx, fy)))
    if masses != "none":
        for node, m in _point_masses(rig, case, n_nodes, where, masses):
            mbs.AddObject(ObjectMassPoint2D(nodeNumber=node, mass=m))
    mbs.Assemble()
    model = Model(side, case, float(deg), mode, int(elements), sc, mbs, nodes, nodes["extender"][-1], root,
                  crank_constraint, load_list, rig, load_numbers=load_numbers, load_options=load_options)
    model.settings = model.simulation_settings()
    return model


def _point_masses(rig: Rigid, case: int, n_nodes: int, where: dict, masses: str) -> list:
    """(node, mass in lbf s^2/in) of the case's lumped masses; with distributed beam masses
    only Case I's path-point mass."""
    g = GRAVITY_IN
    if case == 1:
        return [(where["P"], EXAMPLE.mass_lbf / g)]
    if masses == "distributed":
        return []
    if case == 2:
        l1, l2, l3, l4 = rig.lengths
        m1, m2, m3, m4 = (_case2.DENSITY * (EXAMPLE.section.area * length) / g for length in (l1, l2, l3, l4))
        return [(where["P"], m2), (where["A"], m1 + m3), (where["B"], m4)]
    l2 = rig.lengths[1]
    w = _case3.DENSITY * EXAMPLE.section.area * (l2 / n_nodes) / g
    return [(node, w) for key, node in where.items() if isinstance(key, tuple)]


def quasi_static(side: str, case: int, deg, elements: int = 8, n_nodes: int = CASE3_NODES,
                 shear_factor: float = SHEAR_FACTOR, coupler_load_at: str = "A",
                 shear_per_element: float | None = None, lumped: str = "axial") -> dict:
    """Exudyn's linear quasi-static path-point deflections over ``deg`` (deg): ``dx``, ``dy`` (in,
    source frame), ``rot`` (rad), of the frozen model built at the first angle and moved to each
    (``Model.move``)."""
    deg = np.atleast_1d(deg)
    model = build(side, float(deg[0]), case, elements, n_nodes=n_nodes, shear_factor=shear_factor,
                  coupler_load_at=coupler_load_at, masses="none", shear_per_element=shear_per_element, lumped=lumped)
    rows = []
    for k, d in enumerate(deg):
        if k:
            model.move(float(d))
        rows.append(model.linear_deflection())
    rows = np.array(rows)
    return {"dx": rows[:, 0], "dy": rows[:, 1], "rot": rows[:, 2]}
