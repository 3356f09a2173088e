"""Displacement analysis of Rahman's (1991) generalized slider crank, section 2.6.

The printed method: Newton-Raphson on the dual-number loop closure M1 L2 L3 M4 = I
(eqs. 5-26): six equations, five joint variables q = (theta2, eta2, theta3, eta3, S4), the
step Delta = (A'A)^-1 A' V.  The 1996 program by the same author runs exactly this
iteration; its port (``cssp_listing.newton_step``, equal to the legacy build to 1e-14) is
reused here with the 1996 program's stopping rule (every |Delta| <= 1e-7, at most 150
steps), since the 1991 thesis gives none.  When Newton fails, Hall, Root and Sandgren's
fallback (section 2.6.1) minimises the loop-closure error ||B - I||^2 by
Davidon-Fletcher-Powell from the last good position and hands the result back to Newton.

Units: inch and radian.  Positions run in order, each starting from the previous answer
(the first from the plane-geometry estimate of section 2.6.2).  Nothing here raises for a
single bad position: each gets a status, so that one sweep reports where and why it failed.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from .cssp_data import Constants, CsspInputs
from .cssp_listing import MAX_ITERATIONS, initial_estimate, loop_operators, newton_step
from .gsc_data import GscInputs

NEWTON_TOL = 1e-7      # the 1996 program's limit on every |Delta| (in, rad)
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


def constants(inputs: GscInputs, s1: float) -> Constants:
    """The 1996 port's constants for this geometry (its mass data are not used here)."""
    return replace(Constants.of(CsspInputs(a1=inputs.a1, a2=inputs.a2, a4=inputs.a4,
                                           alpha4_deg=inputs.alpha4_deg, s1=1.0, rpm=inputs.rpm),
                                False), s1=float(s1))


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


def newton(theta1: float, q: np.ndarray, c: Constants) -> tuple[np.ndarray, bool, int]:
    """The printed iteration from q: (answer, converged, steps).  Non-finite steps fail."""
    for step in range(1, MAX_ITERATIONS + 1):
        with np.errstate(all="ignore"):
            try:
                delta = newton_step(theta1, q, c, printed=False)
            except np.linalg.LinAlgError:
                return q, False, step
        if not np.all(np.isfinite(delta)):
            return q, False, step
        if np.all(np.abs(delta) <= NEWTON_TOL):
            return q, True, step
        q = q + delta
    return q, False, MAX_ITERATIONS


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


def positions(inputs: GscInputs, theta1, use_dfp: bool = True) -> PositionRun:
    """Solve every crank angle theta1 (rad, in sweep order) by the printed method."""
    th = np.asarray(theta1, dtype=float)
    s1 = inputs.axial(th)[0]
    n = th.size
    out, status = np.full((n, 5), np.nan), np.full(n, NOT_CONVERGED, dtype=object)
    closure, steps = np.full(n, np.nan), np.zeros(n, dtype=int)
    ok = assembles(inputs, th, s1)
    base = constants(inputs, s1[0])
    guess = initial_estimate(base, real4=False)
    for i in range(n):
        if not ok[i]:
            status[i] = CANNOT_ASSEMBLE
            continue
        c = base if s1[i] == base.s1 else replace(base, s1=float(s1[i]))
        q, done, steps[i] = newton(th[i], guess, c)
        if done:
            status[i] = NEWTON
        elif use_dfp and np.all(np.isfinite(guess)):
            q, done, steps[i] = newton(th[i], dfp(th[i], guess, c), c)
            status[i] = DFP_THEN_NEWTON if done else NOT_CONVERGED
        if done:
            out[i], guess = q, q
            closure[i] = np.linalg.norm(residual(th[i], q, c)[0])
    return PositionRun(out, status, closure, steps)
