"""Rahman (1991): displacement, velocity, acceleration and joint-force analysis of the
generalized slider crank, one configuration (``analyse``) or the example's grid (``sweep``).

A result is a pandas DataFrame, one row per crank angle, columns ``COLUMNS``: the
configuration (a4 in, alpha4 deg, s1 in), crank_deg, converged, S4 (in), theta2, eta2,
theta3, eta3 (deg; theta in [0, 360), eta in [-180, 180): an elevation; a converged row's
eta2 lies in (-90, 90)), and the 18 joint-force components of ``gsc_forces.COMPONENTS``
(lbf, lbf*in, each in its thesis frame).  Diagnostics follow: status, closure (||M1 L2 L3 M4
- I|| at the answer), iterations (Newton steps; 0 for the closed-form corrected model) and
branch (the answer's assembly, sign(S4 + b): +1 the example's, -1 the other, 0 where both
meet; ``position``).

``converged`` is True where the row is a position of the mechanism on the asked branch: the
printed model's loop closes there (closure <= ``position.CLOSURE_RTOL`` of the loop's size;
statuses ``position.CONVERGED``), the corrected model's always closes ("closed", or "dead
centre" where a constant crank torque cannot be balanced and the forces are NaN).  Rows whose
printed Newton stopped short of that ("...: loop open", "...: other branch") hold its answer
all the same (the thesis's numbers, D085); rows that did not converge at all ("not
converged", "cannot assemble") hold NaN (empty in CSV) after ``converged``.
"""
from __future__ import annotations

import itertools

import numpy as np
import pandas as pd

from ...checks import angles_deg
from ...errors import AssemblyError, ConvergenceError, SingularPositionError
from . import forces as gsc_forces, position, printed_rates as gsc_printed_rates, rates as gsc_rates
from ..slider_crank.kinematics import kinematics
from .data import GscInputs
from .quirks import GSC_PRINTED, GscQuirks

KINEMATICS = ["s4", "theta2", "eta2", "theta3", "eta3"]
COLUMNS = (["a4", "alpha4_deg", "s1", "crank_deg", "converged"] + KINEMATICS + gsc_forces.COMPONENTS)
CLOSED, DEAD_CENTRE = "closed", "dead centre"
#: statuses of a row that is a position of the mechanism on the asked branch
CONVERGED = position.CONVERGED + (CLOSED, DEAD_CENTRE)
#: statuses of a row that holds its engine's answer (converged, or the printed Newton's stop)
ANSWERED = position.STOPPED + (CLOSED, DEAD_CENTRE)
#: the example's grid (section 3.1, 3.2)
GRID_A4 = (0.0, 10.0, 20.0, 30.0)
GRID_ALPHA4 = (232.0, 270.0, 310.0)
GRID_S1 = (0.0, 3.0, 3.5, 6.0, 9.0)
CRANK_DEG = np.arange(0.0, 361.0, 1.0)


def printed_rates(q, inputs: GscInputs, theta1, sine_denominators: bool):
    """q', q'' (n, 5 each, q's order) of the five-variable loop: the printed closed forms or
    least squares (``gsc_rates``)."""
    _, s1_d, s1_dd = inputs.axial(theta1)
    w = inputs.omega
    if not sine_denominators:
        return gsc_rates.rates(q, w, 0.0, s1_d, s1_dd, inputs.a1, inputs.a2)
    t2, e2, t3, e3, _ = q.T
    with np.errstate(divide="ignore", invalid="ignore"):
        v = gsc_printed_rates.velocities(t2, e2, t3, e3, w, s1_d, inputs.a1, inputs.a2)
        a = gsc_printed_rates.accelerations(t2, e2, t3, e3, v, w, 0.0, s1_d, s1_dd, inputs.a1, inputs.a2)
    order = list(gsc_rates.ORDER)
    return np.stack(v, axis=1)[:, order], np.stack(a, axis=1)[:, order]


def _five_variable(inputs: GscInputs, th: np.ndarray, quirks: GscQuirks, branch, run=None):
    run = run if run is not None else position.positions(inputs, th, branch=branch)
    ok = run.stopped
    forces = {name: np.full(th.size, np.nan) for name in gsc_forces.COMPONENTS}
    if np.any(ok):
        q_d, q_dd = printed_rates(run.q[ok], inputs, th[ok], quirks.sine_denominator_rates)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            got = gsc_forces.printed_forces(inputs, th[ok], run.q[ok], q_d, q_dd,
                                            com_beyond_joint=quirks.com_beyond_joint,
                                            action_reaction=not quirks.joint_force_signs)
        for name in gsc_forces.COMPONENTS:
            forces[name][ok] = got[name]
    return run.q, run.status.astype(str), run.closure, forces, run.iterations, run.branch


def ball_angles(kin) -> tuple[np.ndarray, np.ndarray]:
    """theta3, eta3 (rad) of the exact loop: the slider's i4 (= i1) seen from the rod frame,
    i4 = R2 (c th3 c eta3, s th3 c eta3, -s eta3) as the first column of L3 (eq. 3)."""
    v = kin.R2[:, 0, :]                    # R2' e1: row 0 of R2
    return np.mod(np.arctan2(v[:, 1], v[:, 0]), 2.0 * np.pi), -np.arcsin(np.clip(v[:, 2], -1.0, 1.0))


def wrapped_deg(rad, signed: bool) -> np.ndarray:
    """Angles (rad) in degrees, in [0, 360), or in [-180, 180) if ``signed``; an angle already
    in the range keeps its bits."""
    rad = np.asarray(rad, dtype=float)
    turn = 2.0 * np.pi
    with np.errstate(invalid="ignore"):
        deg = np.degrees(rad - turn * np.floor((rad + np.pi) / turn) if signed else np.mod(rad, turn))
        top = 180.0 if signed else 360.0
        return np.where(deg >= top, deg - 360.0, np.where(deg < top - 360.0, deg + 360.0, deg))


def _closed_loop(inputs: GscInputs, th: np.ndarray, branch):
    n = th.size
    q, status, closure = np.full((n, 5), np.nan), np.full(n, position.CANNOT_ASSEMBLE, dtype=object), np.full(n, np.nan)
    forces = {name: np.full(n, np.nan) for name in gsc_forces.COMPONENTS}
    ok = position.assembles(inputs, th, inputs.axial(th)[0])
    if np.any(ok):
        kin = kinematics(inputs, th[ok], np.stack(inputs.axial(th[ok])), branch=branch or position.EXAMPLE_BRANCH)
        theta3, eta3 = ball_angles(kin)
        q[ok] = np.stack([kin.theta2, kin.eta2, theta3, eta3, kin.s4], axis=1)
        closure[ok] = 0.0
        with np.errstate(divide="ignore", invalid="ignore"):
            got = gsc_forces.corrected_forces(inputs, kin, strict=False)
        dead = gsc_forces.dead_centre(kin)
        status[ok] = np.where(dead, DEAD_CENTRE, CLOSED)
        for name in gsc_forces.COMPONENTS:
            forces[name][ok] = np.where(dead, np.nan, got[name])
    sign = np.where(ok, float(branch or position.EXAMPLE_BRANCH), np.nan)
    return q, status.astype(str), closure, forces, np.zeros(n, dtype=int), sign


def analyse(inputs: GscInputs = GscInputs(), crank_deg=CRANK_DEG, quirks: GscQuirks = GSC_PRINTED,
            strict: bool = False, positions=None, branch: int | None = position.EXAMPLE_BRANCH) -> pd.DataFrame:
    """One configuration over crank angles (deg, in sweep order).  ``strict``: raise the typed
    error of the first angle that did not converge (AssemblyError, ConvergenceError,
    SingularPositionError) instead of returning it.  ``positions``: a ``position.PositionRun``
    already solved for these angles (the printed model only).  ``crank_deg``: a non-empty
    1-D array of finite angles (ValueError otherwise, TypeError if not numbers).  ``branch``:
    the assembly asked for, +1 (the thesis's example's, S4 = -b + sqrt(b^2 - c)) or -1; None:
    the printed Newton unchecked (``position.positions``; the corrected model then takes +1)."""
    if not isinstance(inputs, GscInputs):
        raise TypeError(f"inputs must be GscInputs, got {type(inputs).__name__}")
    if not isinstance(quirks, GscQuirks):
        raise TypeError(f"quirks must be GscQuirks (GSC_PRINTED, GSC_CORRECTED, ...), got {type(quirks).__name__}")
    position.branch_asked(branch)
    deg = angles_deg("crank_deg", crank_deg)       # as asked: radians(48) * 180 / pi is 48.00000000000001
    th = np.radians(deg)
    if quirks.five_variable_loop:
        q, status, closure, forces, iterations, sign = _five_variable(inputs, th, quirks, branch, positions)
    else:
        q, status, closure, forces, iterations, sign = _closed_loop(inputs, th, branch)
    if strict:
        _raise_first(status, deg, closure, sign)
    n = th.size                      # built in one go (a column set at a time costs more than the analysis)
    return pd.DataFrame({"a4": np.full(n, inputs.a4), "alpha4_deg": np.full(n, inputs.alpha4_deg),
                         "s1": np.full(n, inputs.s1), "crank_deg": deg,
                         "converged": np.isin(status, CONVERGED), "s4": q[:, 4],
                         "theta2": wrapped_deg(q[:, 0], False), "eta2": wrapped_deg(q[:, 1], True),
                         "theta3": wrapped_deg(q[:, 2], False), "eta3": wrapped_deg(q[:, 3], True),
                         **{name: forces[name] for name in gsc_forces.COMPONENTS},
                         "status": status.astype(object), "closure": closure, "iterations": iterations,
                         "branch": sign})


def _raise_first(status: np.ndarray, deg: np.ndarray, closure: np.ndarray, sign: np.ndarray) -> None:
    errors = {position.CANNOT_ASSEMBLE: (AssemblyError, "GSC: the rod cannot reach the slider axis"),
              position.NOT_CONVERGED: (ConvergenceError, "GSC: Newton-Raphson and DFP did not converge"),
              position.LOOP_OPEN: (ConvergenceError, "GSC: the Newton stopped where the loop does not close "
                                   "(off the plane five joint variables cannot close it, D085; in it, a poor start)"),
              position.OTHER_BRANCH: (ConvergenceError, "GSC: the Newton closed the loop on the other assembly"),
              DEAD_CENTRE: (SingularPositionError, "GSC: dead centre, the crank torque cannot be balanced")}
    for i, s in enumerate(status):
        if s not in CONVERGED or s == DEAD_CENTRE:
            kind, message = errors[str(s).split(": ")[-1]]
            found = {"closure": float(closure[i]), "branch": float(sign[i])}
            raise kind(message, float(deg[i]), **{k: v for k, v in found.items() if np.isfinite(v)})


def sweep(quirks: GscQuirks = GSC_PRINTED, a4=GRID_A4, alpha4_deg=GRID_ALPHA4, s1=GRID_S1,
          crank_deg=CRANK_DEG) -> pd.DataFrame:
    """Every grid point of section 3.1 (a4 x alpha4 x S1), each over the crank angles; the
    printed model's positions are solved for all grid points together."""
    configs = [GscInputs(a4=x, alpha4_deg=y, s1=z) for x, y, z in itertools.product(a4, alpha4_deg, s1)]
    runs = [None] * len(configs)
    if quirks.five_variable_loop:
        runs = position.positions_batch(configs, np.radians(np.asarray(crank_deg, dtype=float)))
    frames = [analyse(inputs, crank_deg, quirks, positions=run) for inputs, run in zip(configs, runs)]
    return pd.concat(frames, ignore_index=True)
