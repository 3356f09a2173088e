"""Ali (1977): how right was the quasi-static K.E.D. method?  The Case I source four-bar's full
elastodynamics in Exudyn (scene ali1977-elastodynamics).

Ali computes the path point's deflection quasi-statically: at each crank angle the rigid
linkage's acceleration gives the path-point mass's inertia load, and the links, frozen into a
structure at that angle, deflect statically and linearly under it (the corrected port,
``source_case1(quirks=CORRECTED)``).  Three things that method leaves out are measured here on
the same linkage (the example: links 10, 10, 30, 25, 30 in, the 2 lbf path-point mass, the 0.5 in
round section of E = 1e7 psi, massless links, Case I), in Exudyn's beam model of it
(``multibody``: the frozen structure at an angle, or the crank driven at constant speed):

- the structure's own dynamics: the frozen linkage's first natural frequencies over the cycle,
  against the drive's harmonics;
- the deflection's inertia: the elastodynamic steady state (the crank turned at constant speed,
  the deflections integrated in time until successive revolutions agree), against the
  quasi-static answer; by bracketing, the speed where the quasi-static answer's error passes
  10 % of its peak deflection, and that error's harmonics there;
- geometric nonlinearity: the same load on the frozen structure, solved nonlinearly.

Beside Exudyn, the thesis's own structure is run dynamically (``linear_periodic``): the path
point's 2x2 stiffness from the port's flexibility (beta^T F beta, eq. 6; massless links, so the
point carries all the inertia), m u'' + c u' + K(theta) u = -m a(theta), its periodic solution
found directly (the one-revolution map's fixed point): the 1977 structure with the inertia of its
deflection kept, small-deflection theory.  Where deflections are small it and Exudyn agree, and
their difference grows with the deflection: geometric nonlinearity.

Damping: the thesis gives none.  Stiffness-proportional (Kelvin-Voigt) damping, the beams' bending,
axial and shear damping beta times their stiffnesses, beta = 2 zeta / (2 pi 10 Hz): a modal
damping ratio zeta at 10 Hz, about the first mode (zeta f1 / 10 Hz for a mode of frequency f1).
Stiffness-proportional, because mass-proportional damping would act on the links' absolute
velocities, a drag on the rigid motion itself; zeta = 5 %, the upper end of what bolted and
pinned metal linkages show (1-5 %).  At 2 % the massless links' run at 300 rpm fails in
Exudyn's start-up (shown); with the links' own mass it converges from any start.

Units: inch, pound-force, second; masses lbf s^2/in; crank angles in degrees; frequencies in Hz.
"""
from __future__ import annotations

import collections
import functools
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from ....port.ali1977.case1 import source_mechanics
from ....port.ali1977.quirks import CORRECTED
from ... import multibody, progress
from ...csv_output import FULL_PRECISION, write_csv
from ...scene import ReportScene
from . import multibody as mb, stress
from .structure_dynamics import (CASE, ERROR_LEVEL, RPM, SIDES, ZETA, ZETA_LOW, ZETA_LOWEST, damping_beta,
                                 error_of, frequencies_of, linear_limit, linear_periodic, linear_sweep, port_stiffness,
                                 quasi_static, speed_limit,
                                 rigid_path_point)

NAME = "ali1977-elastodynamics"
TITLE = "Ali (1977): the quasi-static K.E.D. deflections against the four-bar's elastodynamics (Exudyn)"
GROUP = NAME
#: one of the two longest groups (with the Ali tables'): it starts first
START = 0
#: beam elements per link (every link alike) in the driven runs; the frozen frequencies' (exact
#: for massless links on any mesh, the shear below; their check on twice as many).  Chosen
#: by ``linkrepro bench`` (``bench.elastodynamic_knobs``): every headline number within 1 % of a
#: converged reference (16 elements, 1440 steps, periodicity 1e-8, full Newton)
ELEMENTS = 4
FREQUENCY_ELEMENTS = 2
#: the nonlinear statics' (4 puts the cognate's nonlinear gap 1.4 % under the reference's, 6 0.6 %)
STATIC_ELEMENTS = 6
#: the beams' shear stiffness, the builder's ``shear_per_element``: 12 EI / h^2 per element, with
#: which its linear elements move at their nodes as Euler-Bernoulli beams (MacNeal), so that the
#: frozen structure's stiffness at the path point is the port's to rounding on any mesh; the
#: builder's default stiff shear (1e4 EA) makes Exudyn's time integration fail (Newton diverges
#: about one revolution in, measured)
SHEAR_PER_ELEMENT = 1.0
#: time steps per revolution from 30 to 300 rpm; below, 360 ceil(30 / rpm); above, 360 ceil(rpm /
#: 300), so that a step is never longer than at 300 rpm (at 400 rpm with 360 steps Exudyn's Newton
#: iteration diverges in the start-up, measured)
STEPS_PER_REV = 360
#: successive revolutions agree to this (in, largest difference of the path point over a
#: revolution): a steady state; MAX_REVOLUTIONS at most
PERIODICITY_IN = 1e-4
MAX_REVOLUTIONS = 40
#: Exudyn's implicit generalized-alpha: spectral radius (1.0 gives noise in the massless links'
#: accelerations), Newton's relative tolerance (the builder's: its residual's rounding floor)
SPECTRAL_RADIUS = 0.8
NEWTON_TOLERANCE = 1e-6
#: Exudyn's Newton variant in the driven runs: modified (the Jacobian kept while it converges),
#: the Jacobian updated at every step's start (JACOBIAN_PER_STEP: the crank turns a degree a
#: step, so a kept one converges slowly: 6.4 iterations and 1.1 Jacobians a step at 300 rpm)
MODIFIED_NEWTON = True
JACOBIAN_PER_STEP = True
#: the frozen structure's frequencies: every 10 deg in Exudyn (the port: every degree)
FREQUENCY_ANGLES = np.arange(0.0, 360.0, 10.0)
#: the nonlinear static solve: every 10 deg, in LOAD_STEPS load steps
STATIC_ANGLES = np.arange(0.0, 360.0, 10.0)
LOAD_STEPS = 1
#: the links' own mass (a fraction of it: 1, aluminium, ``case2.DENSITY``): the real linkage beside
#: Case I's massless links
LINK_MASS = 1.0
#: the damping ratios of the limit-speed study (at 300 rpm: ZETA and ZETA_LOW; ZETA_LOWEST's 300 rpm
#: run reaches no steady state within MAX_REVOLUTIONS, measured)
ZETAS = (ZETA, ZETA_LOW, ZETA_LOWEST)
#: a model's own quasi-static answer, where the port has none (the links' mass): its steady state
#: at QUASI_STATIC_RPM, to QUASI_STATIC_PERIODICITY_IN, times (rpm / QUASI_STATIC_RPM)^2 (at
#: constant crank speed every inertia load scales so)
QUASI_STATIC_RPM = 10.0
QUASI_STATIC_PERIODICITY_IN = 1e-7
#: the harmonics of the quasi-static answer's error shown at the limit speed
ERROR_HARMONICS = 15


def steps_per_rev(rpm: float) -> int:
    """Time steps per revolution at ``rpm``: STEPS_PER_REV, more below 30 and above 300 rpm."""
    return STEPS_PER_REV * max(1, math.ceil(30.0 / rpm), math.ceil(rpm / RPM))


# --- Exudyn, on the builder's model -------------------------------------------------------------

def exudyn_stiffness(deg: float, elements: int = ELEMENTS, side: str = "source") -> tuple[np.ndarray, float]:
    """The frozen structure's stiffness at the path point (2x2, lbf/in) in Exudyn: its Jacobian
    condensed onto the path point's x, y (the links are massless, so this is exact for the
    frequencies); and, as a check of the condensation, the largest difference (in) between the
    compliance times the Case I load and the builder's own linear deflection under it."""
    model = mb.build(side, float(deg), CASE, elements, masses="none", shear_per_element=SHEAR_PER_ELEMENT)
    jacobian = model.jacobian()
    index = model.mbs.GetNodeODE2Index(model.path_node)
    unit = np.zeros((len(jacobian), 2))
    unit[index, 0] = unit[index + 1, 1] = 1.0
    # Exudyn's static residual holds an applied force f as +f: u = -J^-1 r = -J^-1 f
    columns = -np.linalg.solve(jacobian, unit)
    compliance = columns[index:index + 2]
    load = np.array(model.loads[0][1])
    check = float(np.abs(compliance @ load - model.linear_deflection()[:2]).max())
    return np.linalg.inv(compliance), check


def exudyn_static(deg: float, elements: int = STATIC_ELEMENTS, load_steps: int = LOAD_STEPS,
                  side: str = "source", moments: bool = False) -> tuple:
    """The path point's deflection (dx, dy), in, under the Case I load at ``deg`` (300 rpm):
    Exudyn's linear answer and its geometrically nonlinear static solve (``load_steps`` load
    steps, Newton to NEWTON_TOLERANCE); with ``moments``, also the two solves' bending moments
    (``stress.exudyn_moments``: {"linear": ..., "nonlinear": ...})."""
    model = mb.build(side, float(deg), CASE, elements, masses="none", shear_per_element=SHEAR_PER_ELEMENT)
    solution = model.linear_solution()
    linear = model.node_displacement(model.path_node, solution)[:2]
    settings = model.settings
    settings.staticSolver.numberOfLoadSteps = load_steps
    settings.staticSolver.newton.relativeTolerance = NEWTON_TOLERANCE
    model.mbs.SolveStatic(settings)
    nonlinear = model.node_displacement(model.path_node)[:2]
    if not moments:
        return linear, nonlinear
    state = model.mbs.systemData.GetODE2Coordinates()
    return linear, nonlinear, {"linear": stress.exudyn_moments(model, solution), "nonlinear": stress.exudyn_moments(model, state)}


@dataclass(eq=False)
class SteadyState:
    """A driven run: the path point's deflection (steps, 2) over its last revolution at the crank
    angles ``deg`` (deg), the revolutions run, the largest difference (in) between the last two
    revolutions (``periodicity``) and between the last and the one before it (``period2``), and
    the steady state's period in revolutions (1, 2, or 0: none within MAX_REVOLUTIONS);
    ``failed_at`` the time (s) where Exudyn's Newton iteration diverged (its deflection then NaN),
    NaN where it did not; ``moments`` the links' bending moments over the last revolution
    (``stress.exudyn_moments``: {member: (steps, its nodes)}, lbf in; None where it diverged);
    ``end`` its last state (ODE2 coordinates and their velocities, at the start angle: a ``seed``
    for a neighbouring run; None where it diverged), ``seed_rpm`` the speed of the run it was
    seeded from (NaN: started undeformed)."""
    rpm: float
    elements: int
    steps: int
    zeta: float
    start_deg: float
    deg: np.ndarray
    deflection: np.ndarray
    revolutions: int
    periodicity: float
    period2: float
    period: int
    failed_at: float = math.nan
    link_mass: float = 0.0
    side: str = "source"
    moments: dict | None = None
    end: tuple | None = None
    seed_rpm: float = math.nan


def steady_state(rpm: float, elements: int = ELEMENTS, steps: int | None = None, zeta: float = ZETA,
                 start_deg: float = 0.0, link_mass: float = 0.0, side: str = "source",
                 cached: bool = True, periodicity: float = PERIODICITY_IN,
                 modified_newton: bool = MODIFIED_NEWTON, seed: SteadyState | None = None) -> SteadyState:
    """``_steady_state``, each run once per process (the bisection and the report share runs);
    ``cached=False`` runs it afresh (the bench times runs)."""
    run = _steady_state if cached else _steady_state.__wrapped__
    return run(float(rpm), int(elements), int(steps or steps_per_rev(rpm)), float(zeta), float(start_deg),
               float(link_mass), side, float(periodicity), bool(modified_newton), seed)


def _seeded(mbs, seed: SteadyState, rpm: float) -> None:
    """Start ``mbs`` (assembled, its initial velocities the rigid linkage's at ``rpm``) from
    ``seed``'s last state instead of undeformed: the seed's deflections (its coordinates, the
    rotations' whole turns taken off) times (rpm / seed.rpm)^2, as the quasi-static deflection
    scales, and its velocities' elastic part (beyond the rigid ones) times (rpm / seed.rpm)^3."""
    exu = multibody.require()
    q, v, a, ae = (np.array(a, dtype=float) for a in seed.end)
    ratio, initial = rpm / seed.rpm, exu.ConfigurationType.Initial
    rigid_v = np.asarray(mbs.systemData.GetODE2Coordinates_t(configuration=initial))
    rotations = np.zeros(len(q), dtype=bool)
    for node in range(mbs.systemData.NumberOfNodes()):
        if mbs.GetNode(node)["nodeType"] == "RigidBody2D":
            rotations[mbs.GetNodeODE2Index(node) + 2] = True
    q[rotations] -= 2.0 * math.pi * np.round(q[rotations] / (2.0 * math.pi))
    mbs.systemData.SetODE2Coordinates(list(q * ratio ** 2), configuration=initial)
    mbs.systemData.SetODE2Coordinates_t(list(rigid_v + (v - rigid_v / ratio) * ratio ** 3), configuration=initial)
    mbs.systemData.SetODE2Coordinates_tt(list(a * ratio ** 2), configuration=initial)
    mbs.systemData.SetAECoordinates(list(ae * ratio ** 2), configuration=initial)


@functools.lru_cache(maxsize=64)
def _steady_state(rpm: float, elements: int, steps: int, zeta: float, start_deg: float,
                  link_mass: float, side: str, periodicity: float = PERIODICITY_IN,
                  modified_newton: bool = MODIFIED_NEWTON, seed: SteadyState | None = None) -> SteadyState:
    """The elastodynamic steady state at ``rpm``: the builder's driven linkage (started at
    ``start_deg`` with the rigid linkage's velocities, undeformed), the beams damped
    (``damping_beta(zeta)``), the crank speed set to ``rpm``; Exudyn's generalized-alpha in
    ``steps`` steps per revolution, revolution after revolution until two successive ones (or,
    a period-2 motion, the last and the one two before) agree to PERIODICITY_IN.  ``link_mass``:
    the beams' mass as a fraction of the links' own (0: Case I's massless links); ``side`` the
    source four-bar or its cognate; ``seed`` a converged run of the same model at a neighbouring
    speed to start from (``_seeded``) instead of undeformed: fewer revolutions to the same test."""
    exu = multibody.require()
    model = mb.build(side, float(start_deg), CASE, elements, mode="driven", shear_per_element=SHEAR_PER_ELEMENT)
    model.damp(damping_beta(zeta))
    if link_mass:
        model.give_mass(link_mass)
    model.set_speed(rpm)
    mbs, node = model.mbs, model.path_node
    positions: list = []
    states = collections.deque(maxlen=2 * steps)         # (step, ODE2 coordinates): the last two revolutions
    found = {"period": 0, "diffs": (math.inf, math.inf), "end": None}

    def each_step(mbs_, t):
        positions.append(mbs_.GetNodeOutput(node, exu.OutputVariableType.Position)[:2])
        states.append((len(positions) - 1, mbs_.systemData.GetODE2Coordinates()))
        n = len(positions) - 1
        if n and n % steps == 0 and n >= 3 * steps:
            track = np.asarray(positions[n - 3 * steps:n]).reshape(3, steps, 2)
            one, two = float(np.abs(track[2] - track[1]).max()), float(np.abs(track[2] - track[0]).max())
            found["diffs"] = (one, two)
            if one < periodicity or two < periodicity:
                found["period"] = 1 if one < periodicity else 2
                found["end"] = (states[-1][1], mbs_.systemData.GetODE2Coordinates_t(),
                                mbs_.systemData.GetODE2Coordinates_tt(), mbs_.systemData.GetAECoordinates())   # at the start angle
                return False
        return True

    mbs.SetPreStepUserFunction(each_step)
    mbs.Assemble()
    if seed is not None:
        if seed.end is None or (seed.side, seed.elements, seed.start_deg, seed.link_mass) != (side, elements, start_deg, link_mass):
            raise ValueError(f"steady_state: the seed (the run at {seed.rpm:g} rpm) is no converged run of this model")
        _seeded(mbs, seed, rpm)
    period_s = 60.0 / rpm
    settings = model.settings
    settings.linearSolver.solverType = exu.LinearSolverType.EigenSparse
    settings.timeIntegration.numberOfSteps = MAX_REVOLUTIONS * steps + 1
    settings.timeIntegration.endTime = (MAX_REVOLUTIONS * steps + 1) * period_s / steps
    settings.timeIntegration.adaptiveStep = False
    settings.timeIntegration.newton.useModifiedNewton = modified_newton
    settings.timeIntegration.newton.modifiedNewtonJacUpdatePerStep = modified_newton and JACOBIAN_PER_STEP
    settings.timeIntegration.newton.relativeTolerance = NEWTON_TOLERANCE
    settings.timeIntegration.generalizedAlpha.spectralRadius = SPECTRAL_RADIUS
    settings.timeIntegration.generalizedAlpha.computeInitialAccelerations = False   # massless links
    settings.solution.sensors.writePeriod = period_s
    settings.show.statistics = False
    settings.show.computationTime = False
    deg = start_deg + np.arange(steps) * 360.0 / steps
    printing = exu.config.printToConsole
    exu.config.printToConsole = False     # a diverged run is a result here (``failed_at``), not a console message
    try:
        mbs.SolveDynamic(settings)
    except exu.SolverError:
        nan = np.full((steps, 2), math.nan)
        return SteadyState(rpm, elements, steps, zeta, start_deg, deg, nan, len(positions) // steps, math.nan, math.nan,
                           0, (len(positions) - 1) * period_s / steps, link_mass, side)
    finally:
        exu.config.printToConsole = printing
    n = (len(positions) - 1) // steps * steps
    last = np.asarray(positions[n - steps:n]) - rigid_path_point(deg, rpm, side)
    one, two = found["diffs"]
    return SteadyState(rpm, elements, steps, zeta, start_deg, deg, last, n // steps, one, two, found["period"],
                       link_mass=link_mass, side=side, moments=stress.exudyn_moments(model, [q for k, q in states if n - steps <= k < n]),
                       end=found["end"], seed_rpm=math.nan if seed is None else seed.rpm)


# --- the study ------------------------------------------------------------------------------------

def frequencies() -> tuple[pd.DataFrame, pd.DataFrame]:
    """The frozen structure's two natural frequencies, per side: Exudyn at FREQUENCY_ANGLES
    (FREQUENCY_ELEMENTS per link; the finer meshes in ``linkrepro bench`` and the tests), the
    port's structure at every degree."""
    rows, port_rows = [], []
    deg = np.arange(0.0, 360.0, 1.0)
    for side in SIDES:
        for angle in FREQUENCY_ANGLES:
            k, check = exudyn_stiffness(angle, FREQUENCY_ELEMENTS, side)
            f1, f2 = frequencies_of(k)
            (p1, p2) = frequencies_of(port_stiffness([angle], side)[0])
            rows.append({"side": side, "crank_deg": angle, "f1_exudyn": f1, "f2_exudyn": f2, "f1_port": p1, "f2_port": p2, "condensation_check_in": check})
        port = frequencies_of(port_stiffness(deg, side))
        port_rows.append(pd.DataFrame({"side": side, "crank_deg": deg, "f1_port": port[:, 0], "f2_port": port[:, 1]}))
    return pd.DataFrame(rows), pd.concat(port_rows, ignore_index=True)


def statics() -> pd.DataFrame:
    """At STATIC_ANGLES, per side, the 300 rpm Case I load: the port's deflection, Exudyn's linear
    and nonlinear ones (dx, dy, in; the mesh and load steps checked in ``linkrepro bench`` and the
    tests)."""
    rows = []
    for side in SIDES:
        port = quasi_static(STATIC_ANGLES, RPM, side)
        for k, deg in enumerate(STATIC_ANGLES):
            linear, nonlinear, moments = exudyn_static(deg, side=side, moments=True)
            rows.append({"side": side, "crank_deg": deg, "port_dx": port[k, 0], "port_dy": port[k, 1],
                         "exudyn_linear_dx": linear[0], "exudyn_linear_dy": linear[1],
                         "nonlinear_dx": nonlinear[0], "nonlinear_dy": nonlinear[1],
                         **stress.static_columns("exudyn_linear", moments["linear"]),
                         **stress.static_columns("nonlinear", moments["nonlinear"])})
    return pd.DataFrame(rows)


def orbit_change(a: SteadyState, b: SteadyState) -> float:
    """The largest distance (in) between two steady states' deflections at the crank angles both
    sampled (every 360 / gcd(steps) deg from 0; the runs start at multiples of it)."""
    n = math.gcd(a.steps, b.steps)
    grid = np.arange(n) * 360.0 / n

    def on_grid(run):
        index = np.rint(((grid - run.start_deg) % 360.0) * run.steps / 360.0).astype(int) % run.steps
        return run.deflection[index]
    return float(np.hypot(*(on_grid(a) - on_grid(b)).T).max())


def own_quasi_static(deg, rpm: float, side: str = "source", link_mass: float = 0.0) -> np.ndarray:
    """A model's quasi-static deflection (N, 2), in, at ``deg`` (multiples of 360 / steps_per_rev(
    QUASI_STATIC_RPM)): the corrected port's for massless links (Case I); with ``link_mass`` (no
    port has its distributed inertia loads) its own steady state at QUASI_STATIC_RPM, to
    QUASI_STATIC_PERIODICITY_IN, times (rpm / QUASI_STATIC_RPM)^2."""
    if not link_mass:
        return quasi_static(deg, rpm, side)
    slow = steady_state(QUASI_STATIC_RPM, link_mass=link_mass, side=side, periodicity=QUASI_STATIC_PERIODICITY_IN)
    index = np.rint(np.asarray(deg) * slow.steps / 360.0).astype(int) % slow.steps
    return slow.deflection[index] * (rpm / QUASI_STATIC_RPM) ** 2


def _row(kind: str, run: SteadyState) -> dict:
    """A steady state's numbers, against its own model's quasi-static answer (``own_quasi_static``)."""
    peak_qs, peak, error = error_of(run.deflection, own_quasi_static(run.deg, run.rpm, run.side, run.link_mass))
    return {"side": run.side, "study": kind, "rpm": run.rpm, "elements": run.elements, "steps_per_rev": run.steps,
            "zeta": run.zeta, "link_mass": run.link_mass, "start_deg": run.start_deg, "revolutions": run.revolutions,
            "period": run.period, "periodicity_in": run.periodicity, "period2_in": run.period2,
            "quasi_static_peak": peak_qs, "dynamic_peak": peak, "max_error": error, "error_over_peak": error / peak_qs,
            "newton_diverged_at_s": run.failed_at, "seed_rpm": run.seed_rpm}


#: the 300 rpm steady states: (study, side, zeta, link mass); the massless links' run at ZETA_LOW is
#: left out: Exudyn's Newton diverges in its start-up whatever the variant, step or start
#: (``bench``), while with the links' own mass it converges from every start (a test)
RUNS_300 = (("Case I", "source", ZETA, 0.0), ("Case I", "cognate", ZETA, 0.0),
            ("links' own mass", "source", ZETA, LINK_MASS), ("links' own mass", "source", ZETA_LOW, LINK_MASS),
            ("Case I, full Newton, 720 steps/rev", "source", ZETA_LOW, 0.0))
#: the failing run's settings (the most favourable measured: either Newton variant, 360 or 720
#: steps, starts at 0, 90, 180, 270 deg all fail)
FAILING = dict(steps=2 * STEPS_PER_REV, modified_newton=False)


def runs_300() -> pd.DataFrame:
    """The steady states of RUNS_300 (ELEMENTS, STEPS_PER_REV, from 0 deg)."""
    rows = []
    for study, side, zeta, link_mass in RUNS_300:
        progress.note(NAME, f"{RPM:g} rpm steady state: {side}, {study}, zeta {zeta:g}")
        extra = FAILING if zeta == ZETA_LOW and not link_mass else {}
        run = steady_state(RPM, zeta=zeta, link_mass=link_mass, side=side, **extra)
        rows.append(_row(study, run) if math.isnan(run.failed_at) else
                    {"side": side, "study": study, "rpm": RPM, "elements": run.elements, "steps_per_rev": run.steps,
                     "zeta": zeta, "link_mass": link_mass, "start_deg": run.start_deg,
                     "revolutions": run.revolutions, "newton_diverged_at_s": run.failed_at})
    return pd.DataFrame(rows)


#: the limit speeds in Exudyn: (side, zeta, link mass); ZETA_LOWEST in the thesis's structure only
#: (Exudyn's massless runs near the limit need about 25 revolutions there: the cost)
LIMITS = (("source", ZETA, 0.0), ("cognate", ZETA, 0.0), ("source", ZETA, LINK_MASS), ("source", ZETA_LOW, 0.0))


def limits(linear: pd.DataFrame) -> tuple[pd.DataFrame, pd.DataFrame]:
    """Where the quasi-static answer's error passes ERROR_LEVEL of its peak: per LIMITS in Exudyn
    (``speed_limit`` from the thesis's structure's limit: a few runs), and the thesis's structure
    at every damping ratio of ZETAS; each Exudyn run seeded from the nearest converged run of the
    same model (``nearest``: the same damping first), a search's first, if none, undeformed.  Returns (the limits: side, zeta, link mass, model, rpm;
    every Exudyn run the search made; those runs by (side, zeta, link mass))."""
    rows, runs, searched = [], [], {}
    for side in SIDES:
        for zeta in ZETAS:
            rows.append({"side": side, "zeta": zeta, "link_mass": 0.0, "model": "thesis's structure, dynamic",
                         "limit_rpm": linear_limit(linear, side, zeta)})
    for side, zeta, link_mass in LIMITS:
        progress.note(NAME, f"limit speed: {side}, zeta {zeta:g}, link mass {link_mass:g}")
        guess = next(r["limit_rpm"] for r in rows if r["side"] == side and r["zeta"] == zeta)
        done = searched[side, zeta, link_mass] = []

        def ratio(rpm):
            model = [r for (s_, _, m), found in searched.items() if (s_, m) == (side, link_mass) for r in found]
            done.append(steady_state(rpm, zeta=zeta, link_mass=link_mass, side=side, seed=nearest(model, rpm, zeta)))
            runs.append(_row("limit search", done[-1]))
            return runs[-1]["error_over_peak"]
        rows.append({"side": side, "zeta": zeta, "link_mass": link_mass, "model": "Exudyn",
                     "limit_rpm": speed_limit(ratio, guess)})
    return (pd.DataFrame(rows), pd.DataFrame(runs).sort_values(["side", "zeta", "link_mass", "rpm"], ignore_index=True),
            searched)


def nearest(runs: list[SteadyState], rpm: float, zeta: float = ZETA) -> SteadyState | None:
    """The converged run of ``runs`` nearest ``rpm``, at ``zeta`` if any is (the seed of a run
    there), None if none."""
    return min((r for r in runs if r.end is not None), key=lambda r: (r.zeta != zeta, abs(math.log(r.rpm / rpm))),
               default=None)


def limit_of(table: pd.DataFrame, side: str = "source", zeta: float = ZETA, link_mass: float = 0.0,
             model: str = "Exudyn") -> float:
    """One limit speed (rpm) of ``limits``' table."""
    one = table[(table["side"] == side) & (table["zeta"] == zeta) & (table["link_mass"] == link_mass)
                & (table["model"] == model)]
    return float(one["limit_rpm"].iloc[0])


def at_limit(table: pd.DataFrame, side: str, searched: dict) -> "SteadyState":
    """The Exudyn steady state (ZETA, massless) at ``side``'s limit speed (``limits``' table and
    runs, the nearest seeding it): the error's harmonics and the stresses there, at the limit
    itself rather than at the search's nearest run (which the search may leave about 1 % of the
    speed away)."""
    rpm = limit_of(table, side)
    return steady_state(rpm, side=side, seed=nearest(searched[side, ZETA, 0.0], rpm))


def error_harmonics(run: SteadyState, count: int = ERROR_HARMONICS) -> pd.DataFrame:
    """The quasi-static error over the last revolution of ``run`` (a massless steady state, e.g.
    ``at_limit``'s), by harmonic of the crank: harmonic n's amplitude (in: the two components'
    Fourier amplitudes, root of the sum of their squares), its share of the largest, its frequency."""
    rpm = run.rpm
    error = run.deflection - quasi_static(run.deg, rpm, run.side)
    size = 2.0 * np.hypot(*np.abs(np.fft.rfft(error, axis=0)).T) / run.steps
    n = np.arange(1, count + 1)
    return pd.DataFrame({"rpm": rpm, "harmonic": n, "frequency_hz": n * rpm / 60.0, "amplitude_in": size[n],
                         "share_of_largest": size[n] / size[n].max()})


# --- the scene ------------------------------------------------------------------------------------

def run(out_dir: Path) -> dict:
    """out/ali1977-elastodynamics/: frequencies.csv (Exudyn and the port every 10 deg),
    frequencies_port.csv (every degree), statics.csv (the 300 rpm load: port, Exudyn linear and
    nonlinear), steady_300.csv (the 300 rpm steady state over the revolution), runs_300.csv (the
    300 rpm steady states: Case I, the links' own mass, the damping), limits.csv (the limit speeds),
    limit_runs.csv (Exudyn's runs that found them), error_harmonics.csv (the error's harmonics at
    the limit), linear_sweep.csv (the thesis's structure with the deflection's inertia, every 10
    rev/min), stress.csv (the links' peak bending stresses, ``stress.table``), summary.csv, elastodynamics.png, cycle.png, report.md.
    (``linkrepro`` runs it with one BLAS thread: ``harness/blas_threads.py``.)"""
    multibody.require()
    target = out_dir / NAME
    target.mkdir(parents=True, exist_ok=True)
    progress.note(NAME, "frozen frequencies")
    freq, freq_port = frequencies()
    progress.note(NAME, "nonlinear statics")
    static = statics()
    runs = runs_300()
    cycles = []
    for side in SIDES:
        one = steady_state(RPM, side=side)
        linear300, _ = linear_periodic([RPM], ZETA, STEPS_PER_REV, side)
        qs300 = quasi_static(one.deg, RPM, side)
        cycles.append(pd.DataFrame({"side": side, "crank_deg": one.deg, "quasi_static_dx": qs300[:, 0],
                                    "quasi_static_dy": qs300[:, 1], "dynamic_dx": one.deflection[:, 0],
                                    "dynamic_dy": one.deflection[:, 1], "linear_dynamic_dx": linear300[0, :, 0],
                                    "linear_dynamic_dy": linear300[0, :, 1]}))
    cycle = pd.concat(cycles, ignore_index=True)
    progress.note(NAME, "linear dynamics, every 10 rev/min")
    linear = linear_sweep()
    limit, limit_runs, searched = limits(linear)
    at = [at_limit(limit, side, searched) for side in SIDES]
    spectrum = error_harmonics(at[0])
    summary = summarise(freq, freq_port, static, runs, limit, spectrum, linear)
    stresses = stress.table(static, [steady_state(RPM, side=side) for side in SIDES] + at,
                            {side: limit_of(limit, side) for side in SIDES})
    for frame, name in ((freq, "frequencies"), (freq_port, "frequencies_port"), (static, "statics"),
                        (cycle, "steady_300"), (runs, "runs_300"), (limit, "limits"), (limit_runs, "limit_runs"),
                        (spectrum, "error_harmonics"), (linear, "linear_sweep"), (stresses, "stress"), (pd.DataFrame([summary]), "summary")):
        write_csv(frame, target / f"{name}.csv", FULL_PRECISION)
    progress.note(NAME, "figures")
    plot_overview(freq, freq_port, limit_runs, linear, summary, target / "elastodynamics.png")
    plot_cycle(cycle, static, summary, target / "cycle.png")
    (target / "report.md").write_text(report(runs, limit, limit_runs, spectrum, summary, stresses))
    return summary


def harmonics(count: int = 5) -> dict:
    """The source path point's rigid acceleration over a revolution (the port, every degree): the
    size of its n-th harmonic (the two components' Fourier amplitudes, root of the sum of their
    squares) over the first's, n = 2..count."""
    acc = source_mechanics(np.arange(0.0, 360.0, 1.0), quirks=CORRECTED).acc
    size = np.hypot(*np.abs(np.fft.rfft(acc, axis=0)).T)
    return {f"harmonic_{n}": float(size[n] / size[1]) for n in range(2, count + 1)}


def summarise(freq, freq_port, static, runs, limit, spectrum, linear) -> dict:
    """The scene's numbers, one record (every one measured above): the source's, then the
    cognate's (``cognate_...``), then the source's alone."""
    out = {"crank_hz": RPM / 60.0, **harmonics()}
    for side in SIDES:
        prefix = "" if side == "source" else "cognate_"
        f, fp, st, lin = (frame[frame["side"] == side] for frame in (freq, freq_port, static, linear))
        std = runs[(runs["side"] == side) & (runs["link_mass"] == 0.0) & (runs["zeta"] == ZETA)].iloc[0]
        peak_static = np.hypot(st["port_dx"], st["port_dy"])
        nonlinear_gap = np.hypot(st["nonlinear_dx"] - st["port_dx"], st["nonlinear_dy"] - st["port_dy"])
        exudyn_linear_gap = np.hypot(st["exudyn_linear_dx"] - st["port_dx"], st["exudyn_linear_dy"] - st["port_dy"])
        low, high = lin[lin["zeta"] == ZETA_LOW], lin[lin["zeta"] == ZETA]
        out.update({f"{prefix}{key}": value for key, value in {
            "f1_min_hz": float(fp["f1_port"].min()), "f1_max_hz": float(fp["f1_port"].max()),
            "f2_min_hz": float(fp["f2_port"].min()), "f2_max_hz": float(fp["f2_port"].max()),
            "f1_exudyn_over_port_max": float((f["f1_exudyn"] / f["f1_port"] - 1.0).abs().max()),
            "quasi_static_peak": float(std["quasi_static_peak"]),
            "nonlinear_peak": float(np.hypot(st["nonlinear_dx"], st["nonlinear_dy"]).max()),
            "nonlinear_gap_max": float(nonlinear_gap.max()),
            "nonlinear_gap_over_peak": float(nonlinear_gap.max() / peak_static.max()),
            "exudyn_linear_gap_over_peak": float(exudyn_linear_gap.max() / peak_static.max()),
            "dynamic_peak": float(std["dynamic_peak"]),
            "dynamic_error": float(std["max_error"]),
            "dynamic_error_over_peak": float(std["error_over_peak"]),
            "dynamic_revolutions": int(std["revolutions"]),
            "dynamic_periodicity_in": float(std["periodicity_in"]),
            "linear_dynamic_peak_300": float(high.loc[high["rpm"] == RPM, "dynamic_peak"].iloc[0]),
            "linear_dynamic_peak_300_low": float(low.loc[low["rpm"] == RPM, "dynamic_peak"].iloc[0]),
            "speed_limit_rpm": limit_of(limit, side),
            "speed_limit_linear_rpm": limit_of(limit, side, model="thesis's structure, dynamic"),
            "speed_limit_linear_low_zeta_rpm": limit_of(limit, side, ZETA_LOW, model="thesis's structure, dynamic"),
            "speed_limit_linear_lowest_zeta_rpm": limit_of(limit, side, ZETA_LOWEST,
                                                           model="thesis's structure, dynamic")}.items()})
    massy = runs[runs["link_mass"] == LINK_MASS].set_index("zeta")
    failed = runs[(runs["link_mass"] == 0.0) & (runs["zeta"] == ZETA_LOW)]
    resonant = spectrum[(spectrum["frequency_hz"] >= out["f1_min_hz"]) & (spectrum["frequency_hz"] <= out["f1_max_hz"])]
    top = spectrum.loc[spectrum["amplitude_in"].idxmax()]
    crank_at_limit = float(spectrum["rpm"].iloc[0]) / 60.0
    out.update({
        "link_mass_quasi_static_peak": float(massy.loc[ZETA, "quasi_static_peak"]),
        "link_mass_dynamic_peak": float(massy.loc[ZETA, "dynamic_peak"]),
        "link_mass_dynamic_error_over_peak": float(massy.loc[ZETA, "error_over_peak"]),
        "link_mass_speed_limit_rpm": limit_of(limit, link_mass=LINK_MASS),
        "low_zeta_peak": float(massy.loc[ZETA_LOW, "dynamic_peak"]),
        "low_zeta_error_over_peak": float(massy.loc[ZETA_LOW, "error_over_peak"]),
        "speed_limit_low_zeta_rpm": limit_of(limit, zeta=ZETA_LOW),
        "massless_low_zeta_diverged_at_s": float(failed["newton_diverged_at_s"].iloc[0]),
        "limit_error_top_harmonic": int(top["harmonic"]),
        "limit_resonant_harmonic_first": int(resonant["harmonic"].min()),
        "limit_resonant_harmonic_last": int(resonant["harmonic"].max()),
        "limit_resonant_share": float(resonant["share_of_largest"].min()),
        "limit_next_harmonic_share": float(spectrum.loc[spectrum["harmonic"] == resonant["harmonic"].max() + 1,
                                                        "share_of_largest"].iloc[0]),
        "limit_f1_min_over_crank": out["f1_min_hz"] / crank_at_limit,
        "limit_f1_max_over_crank": out["f1_max_hz"] / crank_at_limit})
    return out


def _limit_words(summary: dict) -> str:
    limit = summary["speed_limit_rpm"]
    return (f"{limit:.0f} rpm (a crank frequency of {limit / 60.0:.2f} Hz, 1/{summary['f1_min_hz'] / (limit / 60.0):.0f} "
            f"of the lowest first natural frequency, {summary['f1_min_hz']:.1f} Hz)")


def report(runs, limit, limit_runs, spectrum, summary, stresses=None) -> str:
    """report.md: for a mechanism designer, what the 1977 method gets right, where it fails, why,
    and the speed limit that follows; then the measurements (with ``stresses``, stress.csv: whether
    the links stay elastic)."""
    s = summary
    top = s["limit_error_top_harmonic"]
    lines = [f"# {TITLE}", "",
             "## In short", "",
             f"- **What the 1977 method gets right.** The structure. Exudyn's beam model of the frozen linkage, "
             f"solved linearly, gives the corrected port's deflection to {s['exudyn_linear_gap_over_peak']:.0e} of "
             f"the peak, and its natural frequencies to {s['f1_exudyn_over_port_max']:.0e}: the thesis's "
             "flexibility matrix (eq. 29) is the linear statics of its links. At low speed the full elastodynamic answer "
             f"is the quasi-static one: within 10 % of the peak deflection up to about {_limit_words(s)}.",
             f"- **Where it fails: resonance.** The frozen linkage's first natural frequency runs from "
             f"{s['f1_min_hz']:.1f} to {s['f1_max_hz']:.1f} Hz over the cycle. At the design speed, {RPM:g} rpm, the crank "
             f"turns at {s['crank_hz']:g} Hz, and the path point's acceleration has harmonics of "
             f"{s['harmonic_2']:.0%}, {s['harmonic_3']:.0%} and {s['harmonic_4']:.0%} of the first at 2, 3 and 4 times "
             f"that: the second, {2 * s['crank_hz']:g} Hz, lies inside the first mode's band. In the steady state at "
             f"{RPM:g} rpm (damping ratio {ZETA:.0%}) the path point deflects up to {s['dynamic_peak']:.2f} in, against the "
             f"quasi-static {s['quasi_static_peak']:.2f} in; the quasi-static curve is off by up to "
             f"{s['dynamic_error']:.2f} in, {s['dynamic_error_over_peak']:.1f} times its own peak. The thesis's own "
             f"structure with the deflection's inertia kept (small-deflection theory) resonates further, to "
             f"{s['linear_dynamic_peak_300']:.1f} in: at these deflections Exudyn's geometrically exact beams are the "
             "answer, and the linear model's figures hold only at low speed.",
             f"- **Where it fails: geometric nonlinearity.** Even as a static problem, the {RPM:g} rpm load "
             f"deflects the linkage so far ({s['quasi_static_peak']:.1f} in on links of 10-30 in) that the "
             f"nonlinear solution differs from the linear one by up to {s['nonlinear_gap_max']:.2f} in, "
             f"{s['nonlinear_gap_over_peak']:.0%} of the peak. "
             "The linkage stiffens as it deflects: the nonlinear peak is the smaller.",
             f"- **The speed limit, and why it is there.** With the 10 % criterion the quasi-static answer holds up to "
             f"{s['speed_limit_rpm']:.1f} rpm in Exudyn ({s['speed_limit_linear_rpm']:.1f} rpm for the thesis's structure "
             f"run dynamically). At that speed the error is spread over the crank's harmonics 1 to "
             f"{s['limit_resonant_harmonic_last']}, the largest the {top}th (error_harmonics.csv); the first mode lies at "
             f"{s['limit_f1_min_over_crank']:.1f} to {s['limit_f1_max_over_crank']:.1f} times the crank frequency over "
             f"the cycle, and harmonics {s['limit_resonant_harmonic_first']}-{s['limit_resonant_harmonic_last']}, inside "
             f"that band, still carry at least {s['limit_resonant_share']:.2f} of the largest while the next falls to "
             f"{s['limit_next_harmonic_share']:.2f}, although the rigid acceleration's harmonics fall fast (the 5th is "
             f"{s['harmonic_5']:.1%} of the first): the limit is where the high ""harmonics of the rigid acceleration, small as they are, meet the first mode. So it depends on the "
             f"damping, which the thesis does not give: {s['speed_limit_rpm']:.1f} rpm at {ZETA:.0%}, "
             f"{s['speed_limit_low_zeta_rpm']:.1f} at {ZETA_LOW:.0%} (Exudyn); the thesis's structure gives "
             f"{s['speed_limit_linear_rpm']:.1f}, {s['speed_limit_linear_low_zeta_rpm']:.1f} and "
             f"{s['speed_limit_linear_lowest_zeta_rpm']:.1f} rpm at {ZETA:.0%}, {ZETA_LOW:.0%} and {ZETA_LOWEST:.1%}. "
             f"A designer who wants the 1977 method to hold keeps the lowest first natural frequency above about ten "
             "times the crank frequency.",
             f"- **The real linkage beside Ali's model.** Case I's links are massless; the links' own mass (aluminium, "
             f"Case II/III's density) in Exudyn's beams raises the {RPM:g} rpm steady state's peak from "
             f"{s['dynamic_peak']:.2f} to {s['link_mass_dynamic_peak']:.2f} in "
             f"({s['link_mass_dynamic_peak'] / s['dynamic_peak'] - 1.0:+.0%}), and moves the limit speed from "
             f"{s['speed_limit_rpm']:.1f} to {s['link_mass_speed_limit_rpm']:.1f} rpm (its error measured against its own "
             f"quasi-static answer: its steady state at {QUASI_STATIC_RPM:g} rpm scaled by the speed squared, "
             f"peak {s['link_mass_quasi_static_peak']:.2f} in at {RPM:g} rpm).",
             f"- **Less damping.** At {ZETA_LOW:.0%} the massless links' {RPM:g} rpm run fails in Exudyn's start-up "
             f"(Newton diverges {s['massless_low_zeta_diverged_at_s']:.2f} s in, even with full Newton and half the step), "
             "so it is left out; with the links' own "
             f"mass it converges from any start (a test holds it) and peaks at {s['low_zeta_peak']:.2f} in, against "
             f"{s['link_mass_dynamic_peak']:.2f} in at {ZETA:.0%}: ordinary resonance, less damping a larger peak.",
             *([] if stresses is None else stress.report_lines(stresses, s["speed_limit_rpm"])),
             "", "## The model", "", __doc__.split("\n\n", 1)[1].rsplit("\n\nUnits", 1)[0].strip(), "",
             f"Exudyn {multibody.version()}: {ELEMENTS} ObjectBeamGeometricallyExact2D elements per link "
             f"({FREQUENCY_ELEMENTS} for the frozen frequencies; shear stiffness {SHEAR_PER_ELEMENT:g} x 12 EI / h^2 per "
             f"element; {STATIC_ELEMENTS} for the statics), generalized-alpha (spectral radius {SPECTRAL_RADIUS}), "
             f"{'modified' if MODIFIED_NEWTON else 'full'} Newton"
             f"{' (its Jacobian updated every step)' if MODIFIED_NEWTON and JACOBIAN_PER_STEP else ''} to a relative "
             f"{NEWTON_TOLERANCE:g}, {STEPS_PER_REV} steps "
             f"per revolution (360 ceil(30/rpm) below 30 rpm); a steady state when two successive revolutions agree to "
             f"{PERIODICITY_IN:g} in (at most {MAX_REVOLUTIONS}); statics in {LOAD_STEPS} load step(s). The runs start "
             "undeformed with the rigid linkage's velocities, those of the limit searches from the nearest converged run "
             "of the same model (its state scaled to the speed: fewer revolutions to the same test; a test holds the "
             "steady state the same from either start). These settings were chosen by `linkrepro bench` (the "
             "elastodynamic knobs): each headline number within 1 % of a converged reference (16 elements per link, "
             "1440 steps per revolution, periodicity 1e-8 in, full Newton); the step, mesh and start checks run in the "
             "bench and the tests, not here.",
             "", f"## The {RPM:g} rpm steady states", "",
             "| side | model | zeta | revolutions | last two revs differ (in) | quasi-static peak (in) | dynamic peak (in) | "
             "quasi-static error (in) | error / quasi-static peak |", "|---|---|---|---|---|---|---|---|---|"]
    lines += [f"| {r.side} | {r.study} | {r.zeta:g} | {r.revolutions} | "
              + (f"{r.periodicity_in:.1e} | {r.quasi_static_peak:.4f} | {r.dynamic_peak:.4f} | {r.max_error:.4f} | "
                 f"{r.error_over_peak:.3f} |" if math.isnan(r.newton_diverged_at_s) else
                 f"Newton diverged at {r.newton_diverged_at_s:.3f} s |  |  |  |  |") for r in runs.itertuples()]
    lines += ["", "## The limit speeds", "", "| side | model | zeta | link mass | error passes 10 % of the peak at (rpm, to the 0.1 rpm the settings resolve: `linkrepro bench`'s knob \"Exudyn settings (limit speed)\") |",
              "|---|---|---|---|---|"]
    lines += [f"| {r.side} | {r.model} | {r.zeta:g} | {r.link_mass:g} | {r.limit_rpm:.1f} |" for r in limit.itertuples()]
    lines += ["", "Exudyn's runs that found them (``speed_limit``: from the thesis's structure's limit, the secant in "
              "log error against log speed):", "", "| side | zeta | link mass | rpm | steps/rev | revolutions | error / peak |",
              "|---|---|---|---|---|---|---|"]
    lines += [f"| {r.side} | {r.zeta:g} | {r.link_mass:g} | {r.rpm:.2f} | {r.steps_per_rev} | {r.revolutions} | "
              f"{r.error_over_peak:.4f} |" for r in limit_runs.itertuples()]
    lines += ["", f"## The error's harmonics at the limit speed ({spectrum['rpm'].iloc[0]:.2f} rpm, source, zeta {ZETA:g})",
              "", f"The first mode: {s['f1_min_hz']:.2f}-{s['f1_max_hz']:.2f} Hz, {s['limit_f1_min_over_crank']:.1f} to "
              f"{s['limit_f1_max_over_crank']:.1f} times the crank frequency.", "",
              "| harmonic | frequency (Hz) | amplitude (in) | of the largest |", "|---|---|---|---|"]
    lines += [f"| {r.harmonic} | {r.frequency_hz:.2f} | {r.amplitude_in:.2e} | {r.share_of_largest:.2f} |"
              for r in spectrum.itertuples()]
    lines += ["", "## The frozen linkage's natural frequencies", "",
              f"First mode {s['f1_min_hz']:.2f}-{s['f1_max_hz']:.2f} Hz, second {s['f2_min_hz']:.1f}-{s['f2_max_hz']:.0f} Hz "
              f"over the cycle (the port's structure, every degree); Exudyn's ({FREQUENCY_ELEMENTS} elements per link, its "
              "Jacobian condensed onto the path point: exact for massless links) within "
              f"{s['f1_exudyn_over_port_max']:.0e}. "
              f"The drive's harmonics at {RPM:g} rpm: {s['crank_hz']:g}, {2 * s['crank_hz']:g}, {3 * s['crank_hz']:g} Hz. "
              f"The cognate: first mode {s['cognate_f1_min_hz']:.2f}-{s['cognate_f1_max_hz']:.2f} Hz, second "
              f"{s['cognate_f2_min_hz']:.1f}-{s['cognate_f2_max_hz']:.0f} Hz; Exudyn within "
              f"{s['cognate_f1_exudyn_over_port_max']:.0e}; at {RPM:g} rpm it deflects up to "
              f"{s['cognate_dynamic_peak']:.2f} in against the quasi-static {s['cognate_quasi_static_peak']:.2f} in, and its "
              f"limit speed is {s['cognate_speed_limit_rpm']:.1f} rpm.",
              "", "![frequencies and limit runs](elastodynamics.png)", "", "![the 300 rpm cycle](cycle.png)", ""]
    return "\n".join(lines)


def overview(summary: dict) -> list[str]:
    s = summary
    return [f"frozen linkage's first mode {s['f1_min_hz']:.1f}-{s['f1_max_hz']:.1f} Hz; {RPM:g} rpm's second harmonic "
            f"{2 * s['crank_hz']:g} Hz",
            f"{RPM:g} rpm steady state (zeta {ZETA:g}): peak {s['dynamic_peak']:.2f} in against the quasi-static "
            f"{s['quasi_static_peak']:.2f} in, off by up to {s['dynamic_error']:.2f} in; nonlinear statics off by "
            f"{s['nonlinear_gap_over_peak']:.0%} of the peak",
            f"the quasi-static answer within 10 % of its peak up to {s['speed_limit_rpm']:.0f} rpm"]


def plot_overview(freq, freq_port, table, linear, summary, path: Path) -> None:
    """Left: the frozen linkages' two natural frequencies (Hz) against the crank angle, with the
    300 rpm drive's first three harmonics; right: the quasi-static answer's error over its peak
    against the speed, Exudyn and the thesis's structure run dynamically; source and cognate."""
    from ...figures import save
    from ...report import panel_grid, top_legend
    fig, margins = panel_grid(11.0, 2, 1, 3.4, TITLE, legend_rows=6, gap_across=0.9)
    left, right = fig.subplots(1, 2)
    handles = {}
    looks = {"source": dict(color="tab:blue", marker="o"), "cognate": dict(color="tab:purple", marker="^")}
    for side in SIDES:
        port, exu = freq_port[freq_port["side"] == side], freq[freq["side"] == side]
        color = looks[side]["color"]
        handles[f"{side}: first mode (port)"], = left.plot(port["crank_deg"], port["f1_port"], color=color, lw=1.6)
        handles[f"{side}: second mode (port)"], = left.plot(port["crank_deg"], port["f2_port"], color=color, lw=1.1,
                                                                ls="--")
        handles[f"{side}: Exudyn"], = left.plot(
            np.r_[exu["crank_deg"], exu["crank_deg"]], np.r_[exu["f1_exudyn"], exu["f2_exudyn"]], looks[side]["marker"],
            color="k", ms=3.5, mfc="none", ls="none")
    for n, style in zip((1, 2, 3), (":", "-.", (0, (6, 2)))):
        handles[f"{n} x crank at {RPM:g} rpm"] = left.axhline(n * summary["crank_hz"], color="tab:red", lw=1.1, ls=style)
    left.set_ylim(0.0, 30.0)
    left.set_xlim(0.0, 360.0)
    left.set_xticks(np.arange(0.0, 361.0, 60.0))
    left.set_xlabel("crank angle (deg)")
    left.set_ylabel("natural frequency (Hz)")
    left.set_title("the frozen linkages' natural frequencies")
    for side in SIDES:
        sw = table[(table["side"] == side) & (table["zeta"] == ZETA) & (table["link_mass"] == 0.0)]
        lin = linear[linear["side"] == side]
        color = looks[side]["color"]
        handles[f"{side}: Exudyn, zeta {ZETA:g}"], = right.semilogy(
            sw["rpm"], sw["error_over_peak"], "s" if side == "source" else "^", color=color, ms=4.5, ls="none")
        for zeta, style in ((ZETA, "-"), (ZETA_LOW, "--")):
            if side == "cognate" and zeta != ZETA:
                continue
            one = lin[lin["zeta"] == zeta]
            handles[f"{side}: thesis's, zeta {zeta:g}"], = right.semilogy(
                one["rpm"], one["error_over_peak"], color="tab:green" if side == "source" and zeta == ZETA
                else "tab:orange" if side == "source" else "tab:brown", lw=1.2 if zeta == ZETA else 0.9, ls=style)
    handles[f"source: Exudyn, zeta {ZETA:g}, at {RPM:g} rpm"], = right.semilogy(
        [RPM], [summary["dynamic_error_over_peak"]], "D", color="k", ms=6, mfc="none", ls="none")
    handles["10 % of the peak"] = right.axhline(ERROR_LEVEL, color="tab:red", lw=1.0)
    right.axvline(summary["speed_limit_rpm"], color="tab:red", lw=1.0, ls=":")
    right.set_xlabel("crank speed (rev/min)")
    right.set_ylabel("quasi-static error / its peak deflection")
    right.set_title("the quasi-static answer's error over the speed")
    right.set_xlim(0.0, 410.0)
    for ax in (left, right):
        ax.grid(alpha=0.3, which="both")
    top_legend(fig, handles, rows=6)
    caption = (f"Left: the two natural frequencies of the path-point mass on the frozen linkage (Case I: massless links) "
               f"over the crank angle, from the corrected port's flexibility (lines) and Exudyn's beam model (markers, every "
               f"10 deg), for the source four-bar (first mode {summary['f1_min_hz']:.2f}-{summary['f1_max_hz']:.2f} Hz) and "
               f"its cognate ({summary['cognate_f1_min_hz']:.2f}-{summary['cognate_f1_max_hz']:.2f} Hz); the second modes "
               f"reach {summary['f2_max_hz']:.0f} and {summary['cognate_f2_max_hz']:.0f} Hz (cut off at 30 Hz); the red "
               f"lines are the first three harmonics of the crank at {RPM:g} rpm. Right: the largest distance between the "
               f"elastodynamic steady state and the quasi-static deflection over a revolution, divided by the peak "
               f"quasi-static deflection, against the crank speed: Exudyn ({ELEMENTS} elements per link, markers: the runs "
               f"that bracketed the limit, and {RPM:g} rpm) and the thesis's structure with the deflection's inertia kept "
               f"(lines, \"thesis's\"). The source passes 10 % at {summary['speed_limit_rpm']:.0f} rpm "
               f"(dotted), the cognate at {summary['cognate_speed_limit_rpm']:.0f} rpm, in Exudyn.")
    save(fig, path, caption, **margins)


def plot_cycle(cycle, static, summary, path: Path) -> None:
    """The path point's deflection dx, dy (in) over the crank angle at 300 rpm: quasi-static
    (the port), nonlinear static, the steady state (Exudyn), the thesis's structure run
    dynamically."""
    from ...figures import save
    from ...report import panel_grid, top_legend
    fig, margins = panel_grid(11.0, 2, 1, 3.2, f"The source four-bar's path point deflection over a revolution "
                              f"at {RPM:g} rpm", legend_rows=2, gap_across=0.9)
    cycle, static = cycle[cycle["side"] == "source"], static[static["side"] == "source"]
    axes = fig.subplots(1, 2, sharex=True)
    handles = {}
    for ax, c in zip(axes, ("dx", "dy")):
        handles["quasi-static (the corrected port)"], = ax.plot(cycle["crank_deg"], cycle[f"quasi_static_{c}"],
                                                                color="tab:blue", lw=1.8)
        handles["nonlinear static, same load (Exudyn)"], = ax.plot(static["crank_deg"], static[f"nonlinear_{c}"], "o",
                                                                   color="tab:purple", ms=3.5, mfc="none")
        handles[f"steady state, zeta {ZETA:g} (Exudyn)"], = ax.plot(cycle["crank_deg"], cycle[f"dynamic_{c}"],
                                                                    color="k", lw=1.4)
        handles[f"the thesis's structure, dynamic, zeta {ZETA:g}"], = ax.plot(
            cycle["crank_deg"], cycle[f"linear_dynamic_{c}"], color="tab:green", lw=1.0, ls="--")
        ax.set_xlabel("crank angle (deg)")
        ax.set_ylabel(f"{c} (in)")
        ax.set_title(f"{c}, the path point's deflection along {'x' if c == 'dx' else 'y'}")
        ax.set_xlim(0.0, 360.0)
        ax.set_xticks(np.arange(0.0, 361.0, 60.0))
        ax.grid(alpha=0.3)
    top_legend(fig, handles, rows=2)
    caption = (f"The path point's elastic deflection at {RPM:g} rpm (Case I source four-bar) over one revolution: "
               f"the quasi-static K.E.D. answer (peak {summary['quasi_static_peak']:.2f} in), the same load solved "
               f"geometrically nonlinearly in Exudyn (circles, up to {summary['nonlinear_gap_max']:.2f} in from it), "
               f"the elastodynamic steady state in Exudyn (peak {summary['dynamic_peak']:.2f} in, "
               f"{summary['dynamic_revolutions']} revolutions from an undeformed start, the last two differing by "
               f"{summary['dynamic_periodicity_in']:.0e} in), and the thesis's linear structure with the deflection's "
               f"inertia kept, which resonates (peak {summary['linear_dynamic_peak_300']:.1f} in).")
    save(fig, path, caption, **margins)


SCENE = ReportScene(name=NAME, title=TITLE, group=GROUP, start=START, produce=run, overview=overview)
