"""Displacement analysis of Rahman's (1991) generalized slider crank, section 2.6.

The printed method: Newton-Raphson on the dual-number loop closure M1 L2 L3 M4 = I
(eqs. 5-26): six equations, five joint variables q = (theta2, eta2, theta3, eta3, S4), the
step Delta = (A'A)^-1 A' V.  The 1996 program by the same author runs exactly this
iteration; its compiled kernel (``spatial_newton.newton``, equal to the legacy build bit
for bit) serves here too, with the 1996 program's stopping rule (every |Delta| <= 1e-7, at
most 150 steps), since the 1991 thesis gives none, and A'A solved by LU with pivoting (the
thesis prints no inverse).  When Newton fails at a position that follows a
converged one, Hall, Root and Sandgren's fallback (section 2.6.1) minimises the loop-closure
error ||B - I||^2 by Davidon-Fletcher-Powell from that answer and hands the result back to
Newton.

Units: inch and radian.  Positions run in order, each starting from the previous answer
(the first from the plane-geometry estimate of section 2.6.2).  Nothing here raises for a
single bad position: each gets a status, so that one sweep reports where and why it failed.
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass, replace

import numpy as np

from . import spatial_newton as kernel
from .cssp_data import Constants, CsspInputs
from .cssp_listing import initial_estimate, loop_operators
from .gsc_data import GscInputs

DFP_ITERATIONS = 400
#: statuses of a position
NEWTON, DFP_THEN_NEWTON, NOT_CONVERGED, CANNOT_ASSEMBLE = "newton", "dfp+newton", "not converged", "cannot assemble"


@dataclass
class PositionRun:
    """Per crank angle: q (n, 5) = theta2, eta2, theta3, eta3 (rad), S4 (in), NaN where not
    converged; status (n,) of the statuses above; closure (n,) = ||B - I|| (real and dual
    parts together, dimensionless and in) at the answer; iterations (n,) Newton steps."""
    q: np.ndarray
    status: np.ndarray
    closure: np.ndarray
    iterations: np.ndarray

    @property
    def converged(self) -> np.ndarray:
        return np.isin(self.status, [NEWTON, DFP_THEN_NEWTON])


@dataclass(frozen=True)
class NewtonSetup:
    """What the 1991 thesis leaves open and the 1996 build of the same Newton fixes."""
    real4: bool = False            # lengths, pi and the tolerance 1e-7 as REAL*4 holds them
    printed_inverse: bool = False  # A'A inverted by the 1996 listing's INVERSE, else by LU
    check_assembly: bool = True    # skip the angles where the rod cannot reach the slider axis
    tol: float | None = None       # stop when every |Delta| <= tol; None: the 1996 listing's 1e-7
    max_iterations: int = kernel.MAX_ITERATIONS   # Newton evaluations before a position fails


#: the port of the 1991 method (double precision, LU, assembly checked first)
THESIS_1991 = NewtonSetup()
#: the 1996 build's Newton (its first pass is the 1991 method in the 1996 program's arithmetic)
BUILD_1996 = NewtonSetup(real4=True, printed_inverse=True, check_assembly=False)


def constants(inputs: GscInputs, s1: float, real4: bool = False) -> Constants:
    """The 1996 port's constants for this geometry (its mass data are not used here)."""
    geometry = _geometry_constants(inputs.a1, inputs.a2, inputs.a4, inputs.alpha4_deg, inputs.rpm, real4)
    return replace(geometry, s1=float(np.float32(s1)) if real4 else float(s1))


@functools.lru_cache(maxsize=256)
def _geometry_constants(a1: float, a2: float, a4: float, alpha4_deg: float, rpm: float, real4: bool) -> Constants:
    return Constants.of(CsspInputs(a1=a1, a2=a2, a4=a4, alpha4_deg=alpha4_deg, s1=1.0, rpm=rpm), real4)


def assembles(inputs: GscInputs, theta1, s1) -> np.ndarray:
    """True where a rod of length a2 reaches the slider line: the discriminant of
    |Q - P| = a2 in S4 is >= 0 (P the crank pin, Q on the slider axis)."""
    th = np.asarray(theta1, dtype=float)
    sa, ca = math.sin(inputs.alpha4), math.cos(inputs.alpha4)
    b = inputs.a1 * sa * np.sin(th) + s1 * ca
    c = (inputs.a1 * np.cos(th) + inputs.a4) ** 2 + (inputs.a1 * np.sin(th)) ** 2 + s1 ** 2 - inputs.a2 ** 2
    return b * b - c >= 0.0


def residual(theta1: float, q: np.ndarray, c: Constants) -> tuple[np.ndarray, np.ndarray]:
    """Loop-closure error r = (B - I real, B dual) (18,) and its Jacobian (18, 5): dB/dq_j = H_j B."""
    h, b = loop_operators(theta1, q, c)
    r = np.concatenate([(b.real - np.eye(3)).ravel(), b.dual.ravel()])
    hb = h @ type(h)(np.broadcast_to(b.real, (5, 3, 3)), np.broadcast_to(b.dual, (5, 3, 3)))
    return r, np.concatenate([hb.real.reshape(5, 9), hb.dual.reshape(5, 9)], axis=1).T


def newton(theta1: float, q: np.ndarray, c: Constants, setup: NewtonSetup = THESIS_1991) -> tuple[np.ndarray, bool, int]:
    """The printed iteration from q (5,) at one crank angle (rad): (answer, converged, steps).
    Every |Delta| <= tol (c.newton_tol, 1e-7, unless the setup says) stops it, 150 steps
    (setup.max_iterations) fail it; a singular A'A or a non-finite step fails at once."""
    tol = c.newton_tol if setup.tol is None else setup.tol
    q, status, steps = kernel.newton(float(theta1), np.asarray(q, dtype=float), c.a1, c.a2, c.a4, c.alpha4,
                                     c.s1, tol, setup.max_iterations, setup.printed_inverse)
    return q, status == kernel.OK, int(steps)


def dfp(theta1: float, q: np.ndarray, c: Constants) -> np.ndarray:
    """Davidon-Fletcher-Powell descent on f = ||r||^2 with a backtracking line search."""
    r, jac = residual(theta1, q, c)
    f, grad, hinv = r @ r, 2.0 * jac.T @ r, np.eye(5)
    for _ in range(DFP_ITERATIONS):
        direction = -hinv @ grad
        if grad @ direction >= 0.0:                      # not a descent direction: restart
            hinv, direction = np.eye(5), -grad
        step = 1.0
        while step > 1e-12:
            r_new, jac_new = residual(theta1, q + step * direction, c)
            if r_new @ r_new <= f + 1e-4 * step * (grad @ direction):
                break
            step *= 0.5
        else:
            return q
        s = step * direction
        q, f, grad_new = q + s, r_new @ r_new, 2.0 * jac_new.T @ r_new
        y = grad_new - grad
        grad = grad_new
        if np.linalg.norm(grad) < 1e-13 or np.max(np.abs(s)) < 1e-13:
            return q
        sy, hy = s @ y, hinv @ y
        if sy > 0.0 and y @ hy > 0.0:
            hinv = hinv + np.outer(s, s) / sy - np.outer(hy, hy) / (y @ hy)
    return q


def positions(inputs: GscInputs, theta1, use_dfp: bool = True, stop_at_failure: bool = False,
              setup: NewtonSetup = THESIS_1991) -> PositionRun:
    """Solve every crank angle theta1 (rad, in sweep order) by the printed method.

    A failed angle leaves the next one to start from the last answer, or
    (``stop_at_failure``) ends the sweep, as the thesis's program stops."""
    th = np.asarray(theta1, dtype=float)
    n = th.size
    s1 = inputs.axial(th)[0]
    ok = assembles(inputs, th, s1) if setup.check_assembly else np.ones(n, dtype=bool)
    q_out, closure = np.full((n, 5), np.nan), np.full(n, np.nan)
    status, steps = np.full(n, NOT_CONVERGED, dtype=object), np.zeros(n, dtype=int)
    status[~ok] = CANNOT_ASSEMBLE
    guess = initial_estimate(constants(inputs, s1[0], setup.real4), real4=setup.real4)
    with np.errstate(all="ignore"):
        for i in range(n):
            if not (ok[i] and np.all(np.isfinite(guess))):
                if stop_at_failure and ok[i]:
                    break
                continue
            c = constants(inputs, s1[i], setup.real4)
            q, done, steps[i] = newton(th[i], guess, c, setup)
            if done:
                status[i] = NEWTON
            elif use_dfp and (i == 0 or status[i - 1] != NOT_CONVERGED):   # DFP only after a converged position
                q, done, steps[i] = newton(th[i], dfp(th[i], guess, c), c, setup)
                status[i] = DFP_THEN_NEWTON if done else NOT_CONVERGED
            if done:
                q_out[i], guess = q, q
                closure[i] = np.linalg.norm(residual(th[i], q, c)[0])
            elif stop_at_failure:
                break
    return PositionRun(q_out, status, closure, steps)


def positions_batch(inputs: list[GscInputs], theta1, use_dfp: bool = True,
                    stop_at_failure: bool = False) -> list[PositionRun]:
    """``positions`` for several configurations."""
    return [positions(x, theta1, use_dfp, stop_at_failure) for x in inputs]
