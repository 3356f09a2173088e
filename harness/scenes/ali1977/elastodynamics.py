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
  quasi-static answer; over a sweep of speeds, where the quasi-static answer's error passes
  10 % of its peak deflection;
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
pinned metal linkages show (1-5 %).  At 2 % the massless links' run diverges in the start-up at
300 rpm; with the links given 1 % of their mass it runs (both shown).

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
from .structure_dynamics import (CASE, ERROR_LEVEL, LINEAR_STEPS, RPM, SIDES, ZETA, ZETA_LOW, crossing, damping_beta,
                                 error_of, frequencies_of, linear_periodic, linear_sweep, port_stiffness, quasi_static,
                                 rigid_path_point)

NAME = "ali1977-elastodynamics"
TITLE = "Ali (1977): the quasi-static K.E.D. deflections against the four-bar's elastodynamics (Exudyn)"
GROUP = NAME
#: the longest scene: it starts first
START = 0
#: beam elements per link (every link alike): measured, 8 -> 16 moves the 300 rpm steady state
#: by 0.004 in, 0.1 % of its peak (``convergence.csv``)
ELEMENTS = 8
#: the beams' shear stiffness, the builder's ``shear_per_element``: 12 EI / h^2 per element, with
#: which its linear elements move at their nodes as Euler-Bernoulli beams (MacNeal), so that the
#: frozen structure's stiffness at the path point is the port's to rounding on any mesh; the
#: builder's default stiff shear (1e4 EA) makes Exudyn's time integration fail (Newton diverges
#: about one revolution in, measured)
SHEAR_PER_ELEMENT = 1.0
#: time steps per revolution from 120 to 300 rpm; below, 360 ceil(120 / rpm), so that a step is
#: never longer than 1/60 of the highest first-mode period; above, 360 ceil(rpm / 300), so that it
#: is never longer than at 300 rpm (at 400 rpm with 360 steps Exudyn's Newton iteration diverges in
#: the start-up, measured)
STEPS_PER_REV = 360
#: successive revolutions agree to this (in, largest difference of the path point over a
#: revolution): a steady state; MAX_REVOLUTIONS at most
PERIODICITY_IN = 1e-6
MAX_REVOLUTIONS = 40
#: Exudyn's implicit generalized-alpha: spectral radius (1.0 gives noise in the massless links'
#: accelerations), Newton's relative tolerance (the builder's: its residual's rounding floor)
SPECTRAL_RADIUS = 0.8
NEWTON_TOLERANCE = 1e-6
#: the frozen structure's frequencies: every 10 deg in Exudyn (the port: every degree)
FREQUENCY_ANGLES = np.arange(0.0, 360.0, 10.0)
#: the nonlinear static solve: every 10 deg, in LOAD_STEPS load steps (measured: 1 to 10 agree to
#: Newton's tolerance); twice the mesh and twice the load steps every 30 deg
STATIC_ANGLES = np.arange(0.0, 360.0, 10.0)
LOAD_STEPS = 4
STATIC_CHECK_EVERY = 3
#: the speed sweep in Exudyn, rev/min
SWEEP_RPM = (30.0, 40.0, 50.0, 55.0, 60.0, 65.0, 70.0, 80.0, 90.0, 100.0, 120.0, 150.0, 200.0, 250.0, 300.0,
             350.0, 400.0)
#: the cognate's sweep in Exudyn (fewer speeds: the cost)
COGNATE_SWEEP_RPM = (40.0, 50.0, 60.0, 70.0, 80.0, 100.0, 150.0, 200.0, 300.0, 400.0)
#: the speed of the step and mesh checks near the limit, rev/min
LIMIT_CHECK_RPM = 60.0
#: the links' mass, as a fraction of their own (aluminium, ``case2.DENSITY``), given them where the
#: massless links' run diverges (at ZETA_LOW): every node then has inertia, and generalized-alpha's
#: numerical damping has high-frequency modes to act on instead of undetermined accelerations
REGULARIZING_MASS = 0.01
#: the name of the ZETA_LOW run with REGULARIZING_MASS in convergence.csv
LOW_NAME = f"zeta {ZETA_LOW:g}, links at {REGULARIZING_MASS:.0%} of their mass"


def steps_per_rev(rpm: float) -> int:
    """Time steps per revolution at ``rpm``: STEPS_PER_REV, more below 120 and above 300 rpm."""
    return STEPS_PER_REV * max(1, math.ceil(120.0 / rpm), math.ceil(rpm / RPM))


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


def exudyn_static(deg: float, elements: int = ELEMENTS, load_steps: int = LOAD_STEPS,
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


@dataclass
class SteadyState:
    """A driven run: the path point's deflection (steps, 2) over its last revolution at the crank
    angles ``deg`` (deg), the revolutions run, the largest difference (in) between the last two
    revolutions (``periodicity``) and between the last and the one before it (``period2``), and
    the steady state's period in revolutions (1, 2, or 0: none within MAX_REVOLUTIONS);
    ``failed_at`` the time (s) where Exudyn's Newton iteration diverged (its deflection then NaN),
    NaN where it did not; ``moments`` the links' bending moments over the last revolution
    (``stress.exudyn_moments``: {member: (steps, its nodes)}, lbf in; None where it diverged)."""
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


def steady_state(rpm: float, elements: int = ELEMENTS, steps: int | None = None, zeta: float = ZETA,
                 start_deg: float = 0.0, link_mass: float = 0.0, side: str = "source",
                 cached: bool = True) -> SteadyState:
    """``_steady_state``, each run once per process (the sweep and the checks share runs);
    ``cached=False`` runs it afresh (the bench times runs)."""
    run = _steady_state if cached else _steady_state.__wrapped__
    return run(float(rpm), int(elements), int(steps or steps_per_rev(rpm)), float(zeta), float(start_deg),
               float(link_mass), side)


@functools.lru_cache(maxsize=64)
def _steady_state(rpm: float, elements: int, steps: int, zeta: float, start_deg: float,
                  link_mass: float, side: str) -> SteadyState:
    """The elastodynamic steady state at ``rpm``: the builder's driven linkage (started at
    ``start_deg`` with the rigid linkage's velocities, undeformed), the beams damped
    (``damping_beta(zeta)``), the crank speed set to ``rpm``; Exudyn's generalized-alpha in
    ``steps`` steps per revolution, revolution after revolution until two successive ones (or,
    a period-2 motion, the last and the one two before) agree to PERIODICITY_IN.  ``link_mass``:
    the beams' mass as a fraction of the links' own (0: Case I's massless links); ``side`` the
    source four-bar or its cognate."""
    exu = multibody.require()
    model = mb.build(side, float(start_deg), CASE, elements, mode="driven", shear_per_element=SHEAR_PER_ELEMENT)
    model.damp(damping_beta(zeta))
    if link_mass:
        model.give_mass(link_mass)
    model.set_speed(rpm)
    mbs, node = model.mbs, model.path_node
    positions: list = []
    states = collections.deque(maxlen=2 * steps)         # (step, ODE2 coordinates): the last two revolutions
    found = {"period": 0, "diffs": (math.inf, math.inf)}

    def each_step(mbs_, t):
        positions.append(mbs_.GetNodeOutput(node, exu.OutputVariableType.Position)[:2])
        states.append((len(positions) - 1, mbs_.systemData.GetODE2Coordinates()))
        n = len(positions) - 1
        if n and n % steps == 0 and n >= 3 * steps:
            track = np.asarray(positions[n - 3 * steps:n]).reshape(3, steps, 2)
            one, two = float(np.abs(track[2] - track[1]).max()), float(np.abs(track[2] - track[0]).max())
            found["diffs"] = (one, two)
            if one < PERIODICITY_IN or two < PERIODICITY_IN:
                found["period"] = 1 if one < PERIODICITY_IN else 2
                return False
        return True

    mbs.SetPreStepUserFunction(each_step)
    mbs.Assemble()
    period_s = 60.0 / rpm
    settings = model.settings
    settings.linearSolver.solverType = exu.LinearSolverType.EigenSparse
    settings.timeIntegration.numberOfSteps = MAX_REVOLUTIONS * steps + 1
    settings.timeIntegration.endTime = (MAX_REVOLUTIONS * steps + 1) * period_s / steps
    settings.timeIntegration.adaptiveStep = False
    settings.timeIntegration.newton.useModifiedNewton = False
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
                       link_mass=link_mass, side=side, moments=stress.exudyn_moments(model, [q for k, q in states if n - steps <= k < n]))


# --- the study ------------------------------------------------------------------------------------

def frequencies() -> tuple[pd.DataFrame, pd.DataFrame]:
    """The frozen structure's two natural frequencies, per side: Exudyn at FREQUENCY_ANGLES
    (ELEMENTS and 2 ELEMENTS per link), the port's structure at every degree."""
    rows, port_rows = [], []
    deg = np.arange(0.0, 360.0, 1.0)
    for side in SIDES:
        for angle in FREQUENCY_ANGLES:
            k8, check = exudyn_stiffness(angle, ELEMENTS, side)
            k16, _ = exudyn_stiffness(angle, 2 * ELEMENTS, side)
            (f1, f2), (g1, g2) = frequencies_of(k8), frequencies_of(k16)
            (p1, p2) = frequencies_of(port_stiffness([angle], side)[0])
            rows.append({"side": side, "crank_deg": angle, "f1_exudyn": f1, "f2_exudyn": f2, "f1_exudyn_fine": g1,
                         "f2_exudyn_fine": g2, "f1_port": p1, "f2_port": p2, "condensation_check_in": check})
        port = frequencies_of(port_stiffness(deg, side))
        port_rows.append(pd.DataFrame({"side": side, "crank_deg": deg, "f1_port": port[:, 0], "f2_port": port[:, 1]}))
    return pd.DataFrame(rows), pd.concat(port_rows, ignore_index=True)


def statics() -> pd.DataFrame:
    """At STATIC_ANGLES, per side, the 300 rpm Case I load: the port's deflection, Exudyn's linear
    and nonlinear ones (dx, dy, in), the nonlinear one also on twice the mesh and in twice the load
    steps (every STATIC_CHECK_EVERY-th angle; NaN elsewhere)."""
    rows = []
    for side in SIDES:
        port = quasi_static(STATIC_ANGLES, RPM, side)
        for k, deg in enumerate(STATIC_ANGLES):
            linear, nonlinear, moments = exudyn_static(deg, side=side, moments=True)
            fine = stepped = np.full(2, math.nan)
            if k % STATIC_CHECK_EVERY == 0:
                _, fine = exudyn_static(deg, 2 * ELEMENTS, side=side)
                _, stepped = exudyn_static(deg, load_steps=2 * LOAD_STEPS, side=side)
            rows.append({"side": side, "crank_deg": deg, "port_dx": port[k, 0], "port_dy": port[k, 1],
                         "exudyn_linear_dx": linear[0], "exudyn_linear_dy": linear[1],
                         "nonlinear_dx": nonlinear[0], "nonlinear_dy": nonlinear[1],
                         "nonlinear_fine_mesh_change": float(np.hypot(*(fine - nonlinear))),
                         "nonlinear_load_steps_change": float(np.hypot(*(stepped - nonlinear))),
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


def _row(kind: str, run: SteadyState, reference: tuple[str, SteadyState] | None) -> dict:
    qs = quasi_static(run.deg, run.rpm, run.side)
    peak_qs, peak, error = error_of(run.deflection, qs)
    change = math.nan if reference is None else orbit_change(run, reference[1])
    return {"side": run.side, "study": kind, "rpm": run.rpm, "elements": run.elements, "steps_per_rev": run.steps, "zeta": run.zeta,
            "start_deg": run.start_deg, "revolutions": run.revolutions, "period": run.period,
            "periodicity_in": run.periodicity, "period2_in": run.period2, "quasi_static_peak": peak_qs,
            "dynamic_peak": peak, "max_error": error, "error_over_peak": error / peak_qs,
            "link_mass": run.link_mass, "compared_with": "" if reference is None else reference[0],
            "change": change, "newton_diverged_at_s": run.failed_at}


def study_300() -> tuple[SteadyState, SteadyState, pd.DataFrame]:
    """The 300 rpm steady state (ELEMENTS, STEPS_PER_REV, ZETA, from 0 deg) and its checks: half
    the step, half and twice the mesh's element length, another start, the links given
    REGULARIZING_MASS of their mass; the lower damping ZETA_LOW, massless and with that mass (and
    then half the step and another start); at LIMIT_CHECK_RPM, near the speed limit, half the step
    and twice the mesh; the cognate's steady state, with half the step and twice the mesh."""
    progress.note(NAME, "300 rpm steady state")
    standard = steady_state(RPM)
    low_name, low = LOW_NAME, None
    rows = [_row("standard", standard, None)]
    for kind, kwargs in (("half step", dict(steps=2 * STEPS_PER_REV)), ("coarse mesh", dict(elements=ELEMENTS // 2)),
                         ("fine mesh", dict(elements=2 * ELEMENTS)), ("start at 180 deg", dict(start_deg=180.0)),
                         (f"links at {REGULARIZING_MASS:.0%} of their mass", dict(link_mass=REGULARIZING_MASS)),
                         (f"zeta {ZETA_LOW:g}, massless links", dict(zeta=ZETA_LOW)),
                         (low_name, dict(zeta=ZETA_LOW, link_mass=REGULARIZING_MASS)),
                         (f"{low_name}, half step", dict(zeta=ZETA_LOW, link_mass=REGULARIZING_MASS,
                                                         steps=2 * STEPS_PER_REV)),
                         (f"{low_name}, start at 180 deg", dict(zeta=ZETA_LOW, link_mass=REGULARIZING_MASS,
                                                                 start_deg=180.0))):
        progress.note(NAME, f"300 rpm: {kind}")
        run = steady_state(RPM, **kwargs)
        rows.append(_row(kind, run, (low_name, low) if low is not None else ("standard", standard)))
        if kind == low_name:
            low = run
    near_name = f"{LIMIT_CHECK_RPM:g} rpm"
    near = steady_state(LIMIT_CHECK_RPM)
    rows.append(_row(near_name, near, None))
    for kind, kwargs in (("half step", dict(steps=2 * steps_per_rev(LIMIT_CHECK_RPM))),
                         ("fine mesh", dict(elements=2 * ELEMENTS))):
        progress.note(NAME, f"{LIMIT_CHECK_RPM:g} rpm: {kind}")
        rows.append(_row(f"{near_name}, {kind}", steady_state(LIMIT_CHECK_RPM, **kwargs), (near_name, near)))
    progress.note(NAME, "300 rpm: the cognate")
    cognate = steady_state(RPM, side="cognate")
    rows.append(_row("standard", cognate, None))
    for kind, kwargs in (("half step", dict(steps=2 * STEPS_PER_REV)), ("fine mesh", dict(elements=2 * ELEMENTS))):
        progress.note(NAME, f"300 rpm, the cognate: {kind}")
        rows.append(_row(kind, steady_state(RPM, side="cognate", **kwargs), ("standard", cognate)))
    return standard, cognate, pd.DataFrame(rows)


def sweep() -> pd.DataFrame:
    """Exudyn's steady state at SWEEP_RPM (the cognate: COGNATE_SWEEP_RPM; ELEMENTS,
    ``steps_per_rev``, ZETA) against the quasi-static answer, with the linear dynamics of the
    thesis's structure at the same speeds."""
    rows = []
    deg = np.arange(LINEAR_STEPS) * 360.0 / LINEAR_STEPS
    for side, speeds in zip(SIDES, (SWEEP_RPM, COGNATE_SWEEP_RPM)):
        linear, _ = linear_periodic(speeds, ZETA, side=side)
        for k, rpm in enumerate(speeds):
            progress.note(NAME, f"sweep, {side}, {rpm:g} rpm")
            row = _row("sweep", steady_state(rpm, side=side), None)
            _, lin_peak, lin_error = error_of(linear[k], quasi_static(deg, rpm, side))
            row.update({"linear_peak": lin_peak, "linear_error_over_peak": lin_error / row["quasi_static_peak"]})
            rows.append(row)
    return pd.DataFrame(rows).drop(columns=["study", "link_mass", "compared_with", "change", "newton_diverged_at_s"])


# --- the scene ------------------------------------------------------------------------------------

def run(out_dir: Path) -> dict:
    """out/ali1977-elastodynamics/: frequencies.csv (Exudyn and the port every 10 deg),
    frequencies_port.csv (every degree), statics.csv (the 300 rpm load: port, Exudyn linear and
    nonlinear), steady_300.csv (the 300 rpm steady state over the revolution), convergence.csv
    (its checks), sweep.csv (Exudyn's speed sweep), linear_sweep.csv (the thesis's structure with
    the deflection's inertia, every rev/min), stress.csv (the links' peak bending stresses,
    ``stress.table``), summary.csv, elastodynamics.png, cycle.png,
    report.md."""
    multibody.require()
    target = out_dir / NAME
    target.mkdir(parents=True, exist_ok=True)
    progress.note(NAME, "frozen frequencies")
    freq, freq_port = frequencies()
    progress.note(NAME, "nonlinear statics")
    static = statics()
    standard, cognate, convergence = study_300()
    cycles = []
    for run in (standard, cognate):
        linear300, _ = linear_periodic([RPM], ZETA, STEPS_PER_REV, run.side)
        qs300 = quasi_static(run.deg, RPM, run.side)
        cycles.append(pd.DataFrame({"side": run.side, "crank_deg": run.deg, "quasi_static_dx": qs300[:, 0],
                                    "quasi_static_dy": qs300[:, 1], "dynamic_dx": run.deflection[:, 0],
                                    "dynamic_dy": run.deflection[:, 1], "linear_dynamic_dx": linear300[0, :, 0],
                                    "linear_dynamic_dy": linear300[0, :, 1]}))
    cycle = pd.concat(cycles, ignore_index=True)
    table = sweep()
    progress.note(NAME, "linear dynamics, every rev/min")
    linear = linear_sweep()
    summary = summarise(freq, freq_port, static, convergence, table, linear)
    limits = {side: summary[("" if side == "source" else "cognate_") + "speed_limit_rpm"] for side in SIDES}
    near = [steady_state(min(speeds, key=lambda rpm: abs(rpm - limits[side])), side=side)       # runs made: the sweep's
            for side, speeds in zip(SIDES, (SWEEP_RPM, COGNATE_SWEEP_RPM))]
    stresses = stress.table(static, [standard, cognate, *near], limits)
    write_csv(stresses, target / "stress.csv", FULL_PRECISION)
    write_csv(freq, target / "frequencies.csv", FULL_PRECISION)
    write_csv(freq_port, target / "frequencies_port.csv", FULL_PRECISION)
    write_csv(static, target / "statics.csv", FULL_PRECISION)
    write_csv(cycle, target / "steady_300.csv", FULL_PRECISION)
    write_csv(convergence, target / "convergence.csv", FULL_PRECISION)
    write_csv(table, target / "sweep.csv", FULL_PRECISION)
    write_csv(linear, target / "linear_sweep.csv", FULL_PRECISION)
    write_csv(pd.DataFrame([summary]), target / "summary.csv", FULL_PRECISION)
    progress.note(NAME, "figures")
    plot_overview(freq, freq_port, table, linear, summary, target / "elastodynamics.png")
    plot_cycle(cycle, static, convergence, summary, target / "cycle.png")
    (target / "report.md").write_text(report(freq, static, convergence, table, summary, stresses))
    return summary


def harmonics(count: int = 5) -> dict:
    """The source path point's rigid acceleration over a revolution (the port, every degree): the
    size of its n-th harmonic (the two components' Fourier amplitudes, root of the sum of their
    squares) over the first's, n = 2..count."""
    acc = source_mechanics(np.arange(0.0, 360.0, 1.0), quirks=CORRECTED).acc
    size = np.hypot(*np.abs(np.fft.rfft(acc, axis=0)).T)
    return {f"harmonic_{n}": float(size[n] / size[1]) for n in range(2, count + 1)}


def summarise(freq, freq_port, static, convergence, table, linear) -> dict:
    """The scene's numbers, one record (every one measured above): the source's, then the
    cognate's (``cognate_...``)."""
    out = {"crank_hz": RPM / 60.0, **harmonics()}
    for side in SIDES:
        prefix = "" if side == "source" else "cognate_"
        f, fp, st, lin = (frame[frame["side"] == side] for frame in (freq, freq_port, static, linear))
        std = convergence[convergence["side"] == side].set_index("study")
        sw = table[table["side"] == side]
        peak_static = np.hypot(st["port_dx"], st["port_dy"])
        nonlinear_gap = np.hypot(st["nonlinear_dx"] - st["port_dx"], st["nonlinear_dy"] - st["port_dy"])
        exudyn_linear_gap = np.hypot(st["exudyn_linear_dx"] - st["port_dx"], st["exudyn_linear_dy"] - st["port_dy"])
        low, high = lin[lin["zeta"] == ZETA_LOW], lin[lin["zeta"] == ZETA]
        out.update({f"{prefix}{key}": value for key, value in {
            "f1_min_hz": float(fp["f1_port"].min()), "f1_max_hz": float(fp["f1_port"].max()),
            "f2_min_hz": float(fp["f2_port"].min()), "f2_max_hz": float(fp["f2_port"].max()),
            "f1_exudyn_over_port_max": float((f["f1_exudyn"] / f["f1_port"] - 1.0).abs().max()),
            "f1_exudyn_fine_over_port_max": float((f["f1_exudyn_fine"] / f["f1_port"] - 1.0).abs().max()),
            "quasi_static_peak": float(std.loc["standard", "quasi_static_peak"]),
            "nonlinear_peak": float(np.hypot(st["nonlinear_dx"], st["nonlinear_dy"]).max()),
            "nonlinear_gap_max": float(nonlinear_gap.max()),
            "nonlinear_gap_over_peak": float(nonlinear_gap.max() / peak_static.max()),
            "nonlinear_fine_mesh_change": float(st["nonlinear_fine_mesh_change"].max()),
            "nonlinear_load_steps_change": float(st["nonlinear_load_steps_change"].max()),
            "exudyn_linear_gap_over_peak": float(exudyn_linear_gap.max() / peak_static.max()),
            "dynamic_peak": float(std.loc["standard", "dynamic_peak"]),
            "dynamic_error": float(std.loc["standard", "max_error"]),
            "dynamic_error_over_peak": float(std.loc["standard", "error_over_peak"]),
            "dynamic_revolutions": int(std.loc["standard", "revolutions"]),
            "dynamic_periodicity_in": float(std.loc["standard", "periodicity_in"]),
            "half_step_change": float(std.loc["half step", "change"]),
            "fine_mesh_change": float(std.loc["fine mesh", "change"]),
            "linear_dynamic_peak_300": float(high.loc[high["rpm"] == RPM, "dynamic_peak"].iloc[0]),
            "linear_dynamic_peak_300_low": float(low.loc[low["rpm"] == RPM, "dynamic_peak"].iloc[0]),
            "speed_limit_rpm": crossing(sw["rpm"], sw["error_over_peak"]),
            "speed_limit_linear_rpm": crossing(high["rpm"], high["error_over_peak"]),
            "speed_limit_linear_low_zeta_rpm": crossing(low["rpm"], low["error_over_peak"])}.items()})
    std = convergence[convergence["side"] == "source"].set_index("study")
    out.update({
        "coarse_mesh_change": float(std.loc["coarse mesh", "change"]),
        "start_180_change": float(std.loc["start at 180 deg", "change"]),
        "regularizing_mass_change": float(std.loc[f"links at {REGULARIZING_MASS:.0%} of their mass", "change"]),
        "massless_low_zeta_diverged_at_s": float(std.loc[f"zeta {ZETA_LOW:g}, massless links", "newton_diverged_at_s"]),
        "low_zeta_peak": float(std.loc[LOW_NAME, "dynamic_peak"]),
        "low_zeta_error": float(std.loc[LOW_NAME, "max_error"]),
        "low_zeta_half_step_change": float(std.loc[f"{LOW_NAME}, half step", "change"]),
        "limit_check_error_over_peak": float(std.loc[f"{LIMIT_CHECK_RPM:g} rpm", "error_over_peak"]),
        "limit_check_half_step": float(std.loc[f"{LIMIT_CHECK_RPM:g} rpm, half step", "error_over_peak"]),
        "limit_check_fine_mesh": float(std.loc[f"{LIMIT_CHECK_RPM:g} rpm, fine mesh", "error_over_peak"])})
    return out


def _limit_words(summary: dict) -> str:
    limit = summary["speed_limit_rpm"]
    return (f"{limit:.0f} rpm (a crank frequency of {limit / 60.0:.2f} Hz, 1/{summary['f1_min_hz'] / (limit / 60.0):.0f} "
            f"of the lowest first natural frequency, {summary['f1_min_hz']:.1f} Hz)")


def report(freq, static, convergence, table, summary, stresses=None) -> str:
    """report.md: for a mechanism designer, what the 1977 method gets right, where it fails, why,
    and the speed limit that follows; then the measurements (with ``stresses``, stress.csv: whether
    the links stay elastic)."""
    s = summary
    lines = [f"# {TITLE}", "",
             "## In short", "",
             f"- **What the 1977 method gets right.** The structure. Exudyn's beam model of the frozen linkage, "
             f"solved linearly, gives the corrected port's deflection to {s['exudyn_linear_gap_over_peak']:.0e} of "
             f"the peak, and its natural frequencies to {s['f1_exudyn_over_port_max']:.0e}: the thesis's "
             "flexibility matrix (eq. 29) is the linear statics of its links. At low speed the full elastodynamic answer is the "
             f"quasi-static one: within 10 % of the peak deflection up to about {_limit_words(s)}.",
             f"- **Where it fails: resonance.** The frozen linkage's first natural frequency runs from "
             f"{s['f1_min_hz']:.1f} to {s['f1_max_hz']:.1f} Hz over the cycle. At the design speed, {RPM:g} rpm, the crank "
             f"turns at {s['crank_hz']:g} Hz, and the path point's acceleration has harmonics of "
             f"{s['harmonic_2']:.0%}, {s['harmonic_3']:.0%} and {s['harmonic_4']:.0%} of the first at 2, 3 and 4 times "
             f"that: the second, {2 * s['crank_hz']:g} Hz, lies inside the first mode's band. The quasi-static method "
             f"cannot see this. In the steady state at {RPM:g} rpm (damping ratio {ZETA:.0%}) the path point "
             f"deflects up to {s['dynamic_peak']:.2f} in, against the quasi-static {s['quasi_static_peak']:.2f} in; "
             f"the quasi-static curve is off by up to {s['dynamic_error']:.2f} in, {s['dynamic_error_over_peak']:.1f} "
             f"times its own peak. The thesis's own structure with the deflection's inertia kept "
             f"(small-deflection theory) resonates further, to {s['linear_dynamic_peak_300']:.1f} in; Exudyn's "
             "beams are geometrically exact, and at these deflections that matters (next point). The steady "
             f"state is converged: half the step moves it by {s['half_step_change']:.3f} in, twice the mesh by "
             f"{s['fine_mesh_change']:.3f} in, a start half a revolution later by {s['start_180_change']:.0e} in.",
             f"- **Where it fails: geometric nonlinearity.** Even as a static problem, the {RPM:g} rpm load "
             f"deflects the linkage so far ({s['quasi_static_peak']:.1f} in on links of 10-30 in) that the "
             f"nonlinear solution differs from the linear one by up to {s['nonlinear_gap_max']:.2f} in, "
             f"{s['nonlinear_gap_over_peak']:.0%} of the peak (twice the mesh moves it by at most "
             f"{s['nonlinear_fine_mesh_change']:.0e} in, twice the load steps by {s['nonlinear_load_steps_change']:.0e} in). "
             "The linkage stiffens as it deflects: the nonlinear peak is the smaller.",
             f"- **The speed limit.** With the 10 % criterion, the quasi-static K.E.D. answer holds up to about "
             f"{s['speed_limit_rpm']:.0f} rpm in Exudyn ({s['speed_limit_linear_rpm']:.0f} rpm for the thesis's "
             f"structure run dynamically; {s['speed_limit_linear_low_zeta_rpm']:.0f} rpm with {ZETA_LOW:.0%} "
             f"damping): about a fifth of the design speed. At {LIMIT_CHECK_RPM:g} rpm the error is "
             f"{s['limit_check_error_over_peak']:.3f} of the peak ({s['limit_check_half_step']:.3f} with half the "
             f"step, {s['limit_check_fine_mesh']:.3f} with twice the mesh). Below the limit the error grows as the "
             "speed squared "
             "(the low harmonics' dynamic amplification, (n f_crank / f1)^2); above it the harmonics of the "
             "crank pass through the first mode one after another and the error jumps from resonance to "
             f"resonance (at {RPM:g} rpm, the second harmonic). A designer who wants the 1977 method to hold "
             "keeps the frozen linkage's lowest first natural frequency above about ten times the crank frequency "
             f"(at the limit: {s['f1_min_hz'] * 60.0 / s['speed_limit_rpm']:.1f} times for the source, "
             f"{s['cognate_f1_min_hz'] * 60.0 / s['cognate_speed_limit_rpm']:.1f} for the cognate).",
             f"- **The cognate.** The crossed cognate traces the same path with other links (the thesis's "
             f"other mechanism). Its frozen first mode runs from {s['cognate_f1_min_hz']:.1f} to "
             f"{s['cognate_f1_max_hz']:.1f} Hz, above the second harmonic at {RPM:g} rpm and just under the third; "
             f"quasi-statically it deflects up to {s['cognate_quasi_static_peak']:.2f} in, dynamically "
             f"{s['cognate_dynamic_peak']:.2f} in (off by up to {s['cognate_dynamic_error']:.2f} in, "
             f"{s['cognate_dynamic_error_over_peak']:.1f} times its quasi-static peak; half the step moves it by "
             f"{s['cognate_half_step_change']:.3f} in, twice the mesh by {s['cognate_fine_mesh_change']:.3f} in); "
             f"nonlinear statics differ by {s['cognate_nonlinear_gap_over_peak']:.0%} of its peak. Its quasi-static "
             f"answer holds to 10 % up to {s['cognate_speed_limit_rpm']:.0f} rpm in Exudyn "
             f"({s['cognate_speed_limit_linear_rpm']:.0f} rpm for its structure run dynamically).",
             f"- **Less damping.** At {ZETA_LOW:.0%} damping and {RPM:g} rpm the runs are fragile: "
             + "; ".join(f"{r.study}: " + (f"Newton diverged {r.newton_diverged_at_s:.2f} s after the start"
                                           if not math.isnan(r.newton_diverged_at_s) else
                                           f"steady, peak {r.dynamic_peak:.2f} in, off the quasi-static answer by up to "
                                           f"{r.max_error:.2f} in")
                         for r in convergence[convergence["zeta"] == ZETA_LOW].itertuples())
             + f". Half the step moves the {ZETA_LOW:.0%} steady state by {s['low_zeta_half_step_change']:.2f} in, "
             f"so it is known to about that, not to the {ZETA:.0%} state's {s['half_step_change']:.3f} in. With massless "
             "nodes generalized-alpha's accelerations there are undetermined; the links given "
             f"{REGULARIZING_MASS:.0%} of their mass (which moves the {ZETA:.0%} steady state by "
             f"{s['regularizing_mass_change']:.3f} in) get further. Less damping gives a smaller peak but a larger "
             "error: not what a linear resonance does; the thesis's structure run dynamically at "
             f"{ZETA_LOW:.0%} peaks at {s['linear_dynamic_peak_300_low']:.1f} in. Either way the quasi-static "
             "answer is off by more than its own peak.",
             *([] if stresses is None else stress.report_lines(stresses, s["speed_limit_rpm"])),
             "", "## The model", "", __doc__.split("\n\n", 1)[1].rsplit("\n\nUnits", 1)[0].strip(), "",
             f"Exudyn {multibody.version()}: {ELEMENTS} ObjectBeamGeometricallyExact2D elements per link (shear "
             f"stiffness {SHEAR_PER_ELEMENT:g} x 12 EI / h^2 per element), generalized-alpha (spectral radius {SPECTRAL_RADIUS}), Newton to a "
             f"relative {NEWTON_TOLERANCE:g}, {STEPS_PER_REV} steps per revolution (360 ceil(120/rpm) below 120 rpm); "
             f"a steady state when two successive revolutions agree to {PERIODICITY_IN:g} in (at most "
             f"{MAX_REVOLUTIONS}). The runs start undeformed with the rigid linkage's velocities.",
             "", f"## The {RPM:g} rpm steady state and its checks", "",
             "| side | run | elements | steps/rev | zeta | link mass | start (deg) | revolutions | period | last two "
             "revs differ (in) | dynamic peak (in) | quasi-static error (in) | error / quasi-static peak | "
             "largest distance from another run (in) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    lines += [f"| {r.side} | {r.study} | {r.elements} | {r.steps_per_rev} | {r.zeta:g} | {r.link_mass:g} | {r.start_deg:g} | "
              f"{r.revolutions} | {_period_words(r)} | {r.periodicity_in:.1e} | {r.dynamic_peak:.4f} | {r.max_error:.4f} | "
              f"{r.error_over_peak:.3f} | {'' if math.isnan(r.change) else f'{r.change:.2e} ({r.compared_with})'} |"
              for r in convergence.itertuples()]
    lines += ["", f"## The speed sweep (Exudyn, zeta {ZETA:g})", "",
              "| side | rpm | steps/rev | revolutions | last two revs differ (in) | quasi-static peak (in) | "
              "dynamic peak (in) | error / peak | thesis's structure, dynamic: error / peak |",
              "|---|---|---|---|---|---|---|---|---|"]
    lines += [f"| {r.side} | {r.rpm:g} | {r.steps_per_rev} | {r.revolutions} | {r.periodicity_in:.1e} | {r.quasi_static_peak:.4f} | "
              f"{r.dynamic_peak:.4f} | {r.error_over_peak:.3f} | {r.linear_error_over_peak:.3f} |"
              for r in table.itertuples()]
    lines += ["", "## The frozen linkage's natural frequencies", "",
              f"First mode {s['f1_min_hz']:.2f}-{s['f1_max_hz']:.2f} Hz, second {s['f2_min_hz']:.1f}-{s['f2_max_hz']:.0f} Hz "
              f"over the cycle (the port's structure, every degree); Exudyn's ({ELEMENTS} elements per link, its "
              "Jacobian condensed onto the path point: exact for massless links) within "
              f"{s['f1_exudyn_over_port_max']:.0e} ({s['f1_exudyn_fine_over_port_max']:.0e} with {2 * ELEMENTS}). "
              f"The drive's harmonics at {RPM:g} rpm: {s['crank_hz']:g}, {2 * s['crank_hz']:g}, {3 * s['crank_hz']:g} Hz. "
              f"The cognate: first mode {s['cognate_f1_min_hz']:.2f}-{s['cognate_f1_max_hz']:.2f} Hz, second "
              f"{s['cognate_f2_min_hz']:.1f}-{s['cognate_f2_max_hz']:.0f} Hz; Exudyn within "
              f"{s['cognate_f1_exudyn_over_port_max']:.0e}.",
              "", "![frequencies and speed sweep](elastodynamics.png)", "", "![the 300 rpm cycle](cycle.png)", ""]
    return "\n".join(lines)


def _period_words(row) -> str:
    """A run's period in words: 1, 2, none, or where Exudyn's Newton iteration diverged."""
    if not math.isnan(row.newton_diverged_at_s):
        return f"diverged at {row.newton_diverged_at_s:.3f} s"
    return str(row.period) if row.period else "none"


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
        sw, lin = table[table["side"] == side], linear[linear["side"] == side]
        color = looks[side]["color"]
        handles[f"{side}: Exudyn, zeta {ZETA:g}"], = right.semilogy(
            sw["rpm"], sw["error_over_peak"], "s" if side == "source" else "^", color=color, ms=4.5, ls="none")
        for zeta, style in ((ZETA, "-"), (ZETA_LOW, "--")):
            if side == "cognate" and zeta == ZETA_LOW:
                continue
            one = lin[lin["zeta"] == zeta]
            handles[f"{side}: thesis's, zeta {zeta:g}"], = right.semilogy(
                one["rpm"], one["error_over_peak"], color="tab:green" if side == "source" and zeta == ZETA
                else "tab:orange" if side == "source" else "tab:brown", lw=1.2 if zeta == ZETA else 0.9, ls=style)
    handles[f"source: Exudyn, zeta {ZETA_LOW:g}, link mass {REGULARIZING_MASS:.0%}"], = right.semilogy(
        [RPM], [summary["low_zeta_error"] / summary["quasi_static_peak"]], "D", color="tab:orange", ms=5, mfc="none",
        ls="none")
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
               f"quasi-static deflection, against the crank speed: Exudyn ({ELEMENTS} elements per link, markers) and the "
               f"thesis's structure with the deflection's inertia kept (lines, \"thesis's\"); the diamond is Exudyn at {ZETA_LOW:g} with the links given "
               f"{REGULARIZING_MASS:.0%} of their mass. The source passes 10 % at {summary['speed_limit_rpm']:.0f} rpm "
               f"(dotted), the cognate at {summary['cognate_speed_limit_rpm']:.0f} rpm, in Exudyn.")
    save(fig, path, caption, **margins)


def plot_cycle(cycle, static, convergence, summary, path: Path) -> None:
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
