"""Displacement analysis of Rahman's (1991) generalized slider crank, section 2.6.

The printed method: Newton-Raphson on the dual-number loop closure M1 L2 L3 M4 = I
(eqs. 5-26): six equations, five joint variables q = (theta2, eta2, theta3, eta3, S4), the
step Delta = (A'A)^-1 A' V.  The 1996 program by the same author runs exactly this
iteration; its port (``cssp_listing.newton_step``, equal to the legacy build to 1e-14) is
reused here with the 1996 program's stopping rule (every |Delta| <= 1e-7, at most 150
steps), since the 1991 thesis gives none.  When Newton fails at a position that follows a
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
from types import SimpleNamespace

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
    return replace(_geometry_constants(inputs.a1, inputs.a2, inputs.a4, inputs.alpha4_deg, inputs.rpm),
                   s1=float(s1))


@functools.lru_cache(maxsize=256)
def _geometry_constants(a1: float, a2: float, a4: float, alpha4_deg: float, rpm: float) -> Constants:
    return Constants.of(CsspInputs(a1=a1, a2=a2, a4=a4, alpha4_deg=alpha4_deg, s1=1.0, rpm=rpm), False)


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
    """The printed iteration from q (5,) for one configuration: (answer, converged, steps)."""
    one = SimpleNamespace(**{k: np.array([getattr(c, k)], dtype=float) for k in ("a1", "a2", "a4", "alpha4", "s1")})
    q, done, steps = newton_batch(theta1, np.asarray(q, dtype=float)[None, :], one)
    return q[0], bool(done[0]), int(steps[0])


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


def _batch_constants(inputs: list[GscInputs], s1: np.ndarray) -> SimpleNamespace:
    """The fields newton_step reads, one value per configuration (arrays (B,))."""
    field = lambda f: np.array([f(x) for x in inputs], dtype=float)
    return SimpleNamespace(a1=field(lambda x: x.a1), a2=field(lambda x: x.a2), a4=field(lambda x: x.a4),
                           alpha4=field(lambda x: x.alpha4), s1=np.asarray(s1, dtype=float))


def _subset(c: SimpleNamespace, rows: np.ndarray) -> SimpleNamespace:
    return SimpleNamespace(**{k: v[rows] for k, v in vars(c).items()})


def _batch_step(theta1: float, q: np.ndarray, c: SimpleNamespace) -> np.ndarray:
    """newton_step for many configurations at once; NaN rows where A'A is singular."""
    try:
        return newton_step(theta1, q, c, printed=False)
    except np.linalg.LinAlgError:
        out = np.full(q.shape, np.nan)
        for k in range(q.shape[0]):
            try:
                out[k] = newton_step(theta1, q[k], _subset(c, np.array([k])), printed=False)[0]
            except np.linalg.LinAlgError:
                pass
        return out


def newton_batch(theta1: float, q: np.ndarray, c: SimpleNamespace) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The printed iteration for B configurations at once, q (B, 5), c's fields (B,): each
    stops when every |Delta| <= NEWTON_TOL (converged) or at a non-finite step or after
    MAX_ITERATIONS (failed).  Returns (answers, converged (B,), steps taken (B,))."""
    q = q.copy()
    nb = q.shape[0]
    done, failed, steps = np.zeros(nb, dtype=bool), np.zeros(nb, dtype=bool), np.full(nb, MAX_ITERATIONS)
    with np.errstate(all="ignore"):
        for step in range(1, MAX_ITERATIONS + 1):
            act = np.flatnonzero(~done & ~failed)
            if act.size == 0:
                break
            delta = _batch_step(theta1, q[act], _subset(c, act))
            bad = ~np.all(np.isfinite(delta), axis=1)
            small = ~bad & np.all(np.abs(delta) <= NEWTON_TOL, axis=1)
            failed[act[bad]], done[act[small]], steps[act[bad | small]] = True, True, step
            q[act[~bad & ~small]] += delta[~bad & ~small]
    return q, done, steps


def positions_batch(inputs: list[GscInputs], theta1, use_dfp: bool = True,
                    stop_at_failure: bool = False) -> list[PositionRun]:
    """Solve every crank angle theta1 (rad, in sweep order) by the printed method, for several
    configurations at once (the Newton steps of all of them in one array operation).

    A failed angle leaves the next one to start from the last answer, or
    (``stop_at_failure``) ends that configuration's sweep, as the thesis's program stops."""
    th = np.asarray(theta1, dtype=float)
    nb, n = len(inputs), th.size
    s1 = np.stack([x.axial(th)[0] for x in inputs])                     # (B, n)
    ok = np.stack([assembles(x, th, s) for x, s in zip(inputs, s1)])
    q_out, closure = np.full((nb, n, 5), np.nan), np.full((nb, n), np.nan)
    status, steps = np.full((nb, n), NOT_CONVERGED, dtype=object), np.zeros((nb, n), dtype=int)
    status[~ok] = CANNOT_ASSEMBLE
    guess = np.stack([initial_estimate(constants(x, s[0]), real4=False) for x, s in zip(inputs, s1)])
    alive = np.ones(nb, dtype=bool)
    with np.errstate(all="ignore"):
        for i in range(n):
            c = _batch_constants(inputs, s1[:, i])
            todo = ok[:, i] & alive & np.all(np.isfinite(guess), axis=1)
            q, done = guess.copy(), np.zeros(nb, dtype=bool)
            rows = np.flatnonzero(todo)
            q[rows], done[rows], steps[rows, i] = newton_batch(th[i], guess[rows], _subset(c, rows))
            status[done, i] = NEWTON
            retry = np.flatnonzero(todo & ~done) if use_dfp else np.array([], dtype=int)
            for k in retry:
                if i > 0 and status[k, i - 1] == NOT_CONVERGED:
                    continue                                   # DFP only after a converged position
                ck = constants(inputs[k], s1[k, i])
                qk, ok_k, steps[k, i] = newton(th[i], dfp(th[i], guess[k], ck), ck)
                if ok_k:
                    q[k], done[k], status[k, i] = qk, True, DFP_THEN_NEWTON
            for k in np.flatnonzero(done):
                q_out[k, i], guess[k] = q[k], q[k]
                closure[k, i] = np.linalg.norm(residual(th[i], q[k], constants(inputs[k], s1[k, i]))[0])
            if stop_at_failure:
                alive &= done | ~ok[:, i]
    return [PositionRun(q_out[k], status[k], closure[k], steps[k]) for k in range(nb)]


def positions(inputs: GscInputs, theta1, use_dfp: bool = True, stop_at_failure: bool = False) -> PositionRun:
    """One configuration's sweep (``positions_batch`` of one)."""
    return positions_batch([inputs], theta1, use_dfp, stop_at_failure)[0]
