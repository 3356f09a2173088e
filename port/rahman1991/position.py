"""Displacement analysis of Rahman's (1991) generalized slider crank, section 2.6.

The printed method: Newton-Raphson on the dual-number loop closure M1 L2 L3 M4 = I
(eqs. 5-26): six equations, five joint variables q = (theta2, eta2, theta3, eta3, S4), the
step Delta = (A'A)^-1 A' V.  The 1996 program by the same author runs exactly this
iteration; its compiled kernel (``slider_crank._newton.newton``, equal to the legacy build bit
for bit) serves here too, with the 1996 program's stopping rule (every |Delta| <= 1e-7, at
most 150 steps), since the 1991 thesis gives none, and A'A solved by LU with pivoting (the
thesis prints no inverse).  When Newton fails at a position that follows a
converged one, Hall, Root and Sandgren's fallback (section 2.6.1) minimises the loop-closure
error ||B - I||^2 by Davidon-Fletcher-Powell from that answer and hands the result back to
Newton.

Units: inch and radian.  Positions run in order, each starting from the previous answer
(the first from the plane-geometry estimate of section 2.6.2, made for theta1 = 0).  Nothing
here raises for a single bad position: each gets a status, so that one sweep reports where
and why it failed.

What a Newton that stops has found is checked (register D170):

- *closure*: the loop closes when ||B - I|| <= CLOSURE_RTOL (a1 + a2 + |a4| + |S1|), one part
  in 10^6 of the loop's size; where it stops with the loop open (a least-squares point of the
  six equations: always off the plane, where five variables cannot close the loop, D085, and
  in the plane from a poor start) the status says "loop open";
- *branch*: the rod reaches the slider axis at two points, S4 = -b +- sqrt(b^2 - c) (the roots
  of |Q - P| = a2); ``branch`` is the sign of S4 + b = (Q - P) . (-k4), the rod's reach along
  the slider's travel (+1: the root the thesis's example runs on and ``slider_crank.kinematics``
  keeps, -1 the other assembly; 0 where the two meet, to the closure tolerance).  The caller asks for one (default +1); a stopped Newton that is not a
  closed loop on it is tried again from the closed form on that branch where the
  five-variable loop closes there; what still misses it says "loop open" or "other branch".
  A closed loop on it is given in the closed form's angles (cos eta2 > 0; the other
  parameterization of the same matrices, theta2 + pi, pi - eta2, pi - theta3, pi + eta3, is
  mapped to them).  ``branch=None`` runs the printed method unchecked (the thesis's program,
  the 1996 build's Newton).

So a single crank angle, or a sweep started anywhere, gives the sweep from 0 deg's answer
wherever the loop closes on the branch.
"""
from __future__ import annotations

import functools
import math
import numbers
from dataclasses import dataclass, replace

import numpy as np
from numba import njit

from ...checks import LARGEST, angles_rad, parameter, real_array
from ..slider_crank import _newton as kernel
from ..slider_crank.geometry import CsspInputs, LoopConstants, initial_estimate
from .data import GscInputs

DFP_ITERATIONS = 400
#: how a position's answer was reached: Newton from the last answer (or the printed first
#: estimate), after the DFP fallback, or from the closed form on the asked branch
NEWTON, DFP_THEN_NEWTON, RESTARTED = "newton", "dfp+newton", "newton from closed form"
#: what a Newton that stopped found, when it is not a closed loop on the asked branch
LOOP_OPEN, OTHER_BRANCH = "loop open", "other branch"
NOT_CONVERGED, CANNOT_ASSEMBLE = "not converged", "cannot assemble"
#: statuses of a position, in the compiled sweep's code order
STATUSES = (NEWTON, DFP_THEN_NEWTON, RESTARTED, f"{NEWTON}: {LOOP_OPEN}", f"{NEWTON}: {OTHER_BRANCH}",
            f"{DFP_THEN_NEWTON}: {LOOP_OPEN}", f"{DFP_THEN_NEWTON}: {OTHER_BRANCH}", NOT_CONVERGED, CANNOT_ASSEMBLE)
#: the loop closed on the asked branch
CONVERGED = STATUSES[:3]
#: the Newton stopped (every |Delta| <= tol): q holds its answer (the thesis's "converged")
STOPPED = STATUSES[:7]
_NEWTON, _DFP_THEN_NEWTON, _RESTARTED, _NOT_CONVERGED, _CANNOT_ASSEMBLE = 0, 1, 2, 7, 8
#: a position closes when ||B - I|| <= CLOSURE_RTOL (a1 + a2 + |a4| + |S1|)
CLOSURE_RTOL = 1e-6
#: the branch of the thesis's example (S4 = -b + sqrt(b^2 - c)), asked by default
EXAMPLE_BRANCH = 1


@dataclass
class PositionRun:
    """Per crank angle: q (n, 5) = theta2, eta2, theta3, eta3 (rad, as the Newton left them:
    not wrapped), S4 (in), NaN where the Newton did not stop; status (n,) of ``STATUSES``;
    closure (n,) = ||B - I|| (real and dual parts together, dimensionless and in) at the
    answer; iterations (n,) steps of the Newton that gave it; branch (n,) the answer's
    assembly, sign(S4 + b) (+1, -1, 0 where both meet; NaN where the Newton did not stop)."""
    q: np.ndarray
    status: np.ndarray
    closure: np.ndarray
    iterations: np.ndarray
    branch: np.ndarray

    @property
    def converged(self) -> np.ndarray:
        """The loop closes (to CLOSURE_RTOL of its size) on the asked branch."""
        return np.isin(self.status, CONVERGED)

    @property
    def stopped(self) -> np.ndarray:
        """The Newton stopped (every |Delta| <= tol): q holds its answer, closed or not."""
        return np.isin(self.status, STOPPED)

    @property
    def dfp(self) -> np.ndarray:
        """The DFP fallback ran before the Newton that stopped."""
        return np.char.startswith(self.status.astype(str), DFP_THEN_NEWTON)


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


def constants(inputs: GscInputs, s1: float, real4: bool = False) -> LoopConstants:
    """The loop's constants for this geometry (REAL*4 as the 1996 build holds them, or double)."""
    geometry = _geometry_constants(inputs.a1, inputs.a2, inputs.a4, inputs.alpha4_deg, inputs.rpm, real4)
    return replace(geometry, s1=float(np.float32(s1)) if real4 else float(s1))


@functools.lru_cache(maxsize=256)
def _geometry_constants(a1: float, a2: float, a4: float, alpha4_deg: float, rpm: float, real4: bool) -> LoopConstants:
    return LoopConstants.of(CsspInputs(a1=a1, a2=a2, a4=a4, alpha4_deg=alpha4_deg, s1=1.0, rpm=rpm), real4)


def assembles(inputs: GscInputs, theta1, s1) -> np.ndarray:
    """True where a rod of length a2 reaches the slider line: the discriminant of
    |Q - P| = a2 in S4 is >= 0 (P the crank pin, Q on the slider axis)."""
    th = np.asarray(theta1, dtype=float)
    sa, ca = math.sin(inputs.alpha4), math.cos(inputs.alpha4)
    b = inputs.a1 * sa * np.sin(th) + s1 * ca
    c = (inputs.a1 * np.cos(th) + inputs.a4) ** 2 + (inputs.a1 * np.sin(th)) ** 2 + s1 ** 2 - inputs.a2 ** 2
    return b * b - c >= 0.0


def newton(theta1: float, q: np.ndarray, c: LoopConstants, setup: NewtonSetup = THESIS_1991) -> tuple[np.ndarray, bool, int]:
    """The printed iteration from q (5,) at one crank angle (rad): (answer, converged, steps).
    Every |Delta| <= tol (c.newton_tol, 1e-7, unless the setup says) stops it, 150 steps
    (setup.max_iterations) fail it; a singular A'A or a non-finite step fails at once.
    TypeError/ValueError for arguments that are not a finite angle, a finite 5-vector, a
    ``LoopConstants`` and a ``NewtonSetup``."""
    if not isinstance(c, LoopConstants) or not isinstance(setup, NewtonSetup):
        raise TypeError(f"c must be LoopConstants and setup a NewtonSetup, got {type(c).__name__}, "
                        f"{type(setup).__name__}")
    theta1 = parameter("theta1", theta1, largest=math.radians(LARGEST))
    q = real_array("q", q)
    if q.shape != (5,) or not np.all(np.isfinite(q)):
        raise ValueError(f"q must be 5 finite joint variables (theta2, eta2, theta3, eta3 rad, s4 in), got {q!r}")
    tol = c.newton_tol if setup.tol is None else setup.tol
    q, status, steps = kernel.newton(theta1, q, c.a1, c.a2, c.a4, c.alpha4,
                                     c.s1, tol, setup.max_iterations, setup.printed_inverse)
    return q, status == kernel.OK, int(steps)


@njit(cache=True)
def _dot(x, y):
    total = 0.0
    for k in range(x.shape[0]):
        total = total + x[k] * y[k]
    return total


@njit(cache=True)
def _matvec(m, v):
    out = np.zeros(m.shape[0])
    for i in range(m.shape[0]):
        out[i] = _dot(m[i], v)
    return out


@njit(cache=True)
def _residual(theta1, q, a1, a2, a4, alp4, s1):
    """Loop-closure error r = (B - I real, B dual) (18,) and its Jacobian (18, 5), dB/dq_j =
    H_j B, at crank angle theta1 (rad) and q (5,); B, H_j as the listing forms them."""
    h, (br, bd) = kernel.loop_product(theta1, q, a1, a2, a4, alp4, s1)
    r, jac = np.empty(18), np.empty((18, 5))
    for i in range(3):
        for j in range(3):
            r[3 * i + j] = br[i, j] - (1.0 if i == j else 0.0)
            r[9 + 3 * i + j] = bd[i, j]
    pr, pd = np.empty((3, 3)), np.empty((3, 3))
    for k, (hr, hd) in enumerate(h):
        kernel.productdual(hr, hd, br, bd, pr, pd)
        for i in range(3):
            for j in range(3):
                jac[3 * i + j, k], jac[9 + 3 * i + j, k] = pr[i, j], pd[i, j]
    return r, jac


@njit(cache=True)
def _identity(h):
    for i in range(5):
        for j in range(5):
            h[i, j] = 1.0 if i == j else 0.0


@njit(cache=True)
def _dfp(theta1, q, a1, a2, a4, alp4, s1, iterations):
    """Davidon-Fletcher-Powell descent on f = ||r||^2 from q with a backtracking (Armijo)
    line search: at most ``iterations`` steps; stops where no step decreases f.  Written
    out element by element (each as numpy's vector expression of it would round)."""
    r, jac = _residual(theta1, q, a1, a2, a4, alp4, s1)
    q, f, grad, hinv = q.copy(), _dot(r, r), _matvec(jac.T, r), np.empty((5, 5))
    trial, s, y = np.empty(5), np.empty(5), np.empty(5)
    for k in range(5):
        grad[k] = 2.0 * grad[k]
    _identity(hinv)
    for _ in range(iterations):
        direction = _matvec(hinv, grad)
        for k in range(5):
            direction[k] = -direction[k]
        if _dot(grad, direction) >= 0.0:                 # not a descent direction: restart
            _identity(hinv)
            for k in range(5):
                direction[k] = -grad[k]
        step, slope = 1.0, _dot(grad, direction)
        while True:
            for k in range(5):
                trial[k] = q[k] + step * direction[k]
            r, jac = _residual(theta1, trial, a1, a2, a4, alp4, s1)
            if _dot(r, r) <= f + 1e-4 * step * slope:      # (a NaN f is no decrease)
                break
            step *= 0.5
            if step <= 1e-12:                            # no step decreases f
                return q
        tiny = True                                      # max |s| < 1e-13 (False for a NaN)
        for k in range(5):
            s[k] = step * direction[k]
            q[k] = q[k] + s[k]
            tiny = tiny and abs(s[k]) < 1e-13
        f, grad_new = _dot(r, r), _matvec(jac.T, r)
        for k in range(5):
            grad_new[k] = 2.0 * grad_new[k]
            y[k] = grad_new[k] - grad[k]
        grad = grad_new
        if math.sqrt(_dot(grad, grad)) < 1e-13 or tiny:
            return q
        sy, hy = _dot(s, y), _matvec(hinv, y)
        yhy = _dot(y, hy)
        if sy > 0.0 and yhy > 0.0:
            for i in range(5):
                for j in range(5):
                    hinv[i, j] = hinv[i, j] + s[i] * s[j] / sy - hy[i] * hy[j] / yhy
    return q


@njit(cache=True)
def _reach(theta1, a1, a2, a4, alp4, s1):
    """b and the discriminant b^2 - c of |Q - P|^2 = a2^2, S4^2 + 2 b S4 + c = 0 (``assembles``)."""
    st, ct = math.sin(theta1), math.cos(theta1)
    b = a1 * math.sin(alp4) * st + s1 * math.cos(alp4)
    c = (a1 * ct + a4) ** 2 + (a1 * st) ** 2 + s1 ** 2 - a2 ** 2
    return b, b * b - c


@njit(cache=True)
def _closed_form(theta1, a1, a2, a4, alp4, s1, branch):
    """q (5,) of the closed loop on the branch (+1, -1) at crank angle theta1 (rad): S4 = -b
    + branch sqrt(b^2 - c); theta2, eta2 (cos eta2 >= 0) of the rod u = (Q - P)/a2 in the
    crank frame; theta3, eta3 from the rotation L3 must be, Rz(theta3) Ry(eta3) = M Rx(-pi/2)
    with M = R' Rx(-alpha4) (R = Rz(theta1 + theta2) Ry(eta2), the rod's frame; M4 = Rx(alpha4)):
    theta3 from M's second column, eta3 from its third row (exact where the five-variable loop
    closes, k3 . k4 = 0, D085).  NaN where the rod cannot reach the slider axis."""
    b, disc = _reach(theta1, a1, a2, a4, alp4, s1)
    q = np.full(5, math.nan)
    if not disc >= 0.0:
        return q
    s4 = -b + branch * math.sqrt(disc)
    st, ct, sa, ca = math.sin(theta1), math.cos(theta1), math.sin(alp4), math.cos(alp4)
    ux, uy, uz = (-a4 - a1 * ct) / a2, (-s4 * sa - a1 * st) / a2, (-s4 * ca - s1) / a2
    vx, vy = ct * ux + st * uy, ct * uy - st * ux
    q[0], q[1], q[4] = math.atan2(vy, vx), math.atan2(-uz, math.hypot(vx, vy)), s4
    sp, cp, se, ce = math.sin(theta1 + q[0]), math.cos(theta1 + q[0]), math.sin(q[1]), math.cos(q[1])
    sb, cb = math.sin(alp4 + 0.5 * math.pi), math.cos(alp4 + 0.5 * math.pi)
    q[2] = math.atan2(-(ce * sp * cb + se * sb), cp * cb)
    q[3] = math.atan2(-se * cp, se * sp * sb + ce * cb)
    return q


@njit(cache=True)
def _closure(theta1, q, a1, a2, a4, alp4, s1):
    r, _ = _residual(theta1, q, a1, a2, a4, alp4, s1)
    return math.sqrt(_dot(r, r))


@njit(cache=True)
def _on_branch(theta1, q, closure, tol, a1, a2, a4, alp4, s1, branch):
    """A closed loop on the branch."""
    side = q[4] + _reach(theta1, a1, a2, a4, alp4, s1)[0]
    return closure <= tol and (abs(side) <= tol or side * branch > 0.0)


@njit(cache=True)
def _closed_form_angles(q):
    """The same loop in the closed form's angles (cos eta2 >= 0): (theta2 + pi, pi - eta2,
    pi - theta3, pi + eta3, S4) gives the same L2 (Rz(theta2 + pi) Ry(pi - eta2) = Rz(theta2)
    Ry(eta2) Rx(pi): the rod's frame turned half a turn about the rod) and L3 M4."""
    if not math.cos(q[1]) < 0.0:
        return q
    return np.array([q[0] + math.pi, math.pi - q[1], math.pi - q[2], math.pi + q[3], q[4]])


@njit(cache=True)
def _restart(theta1, a1, a2, a4, alp4, s1, tol, branch, newton_tol, max_iterations, printed):
    """Newton from the closed form on the branch, where the five-variable loop closes there
    (the closed form's closure <= tol): (q, closure, steps), q NaN where it does not."""
    start = _closed_form(theta1, a1, a2, a4, alp4, s1, branch)
    if not math.isfinite(start[4]) or not _closure(theta1, start, a1, a2, a4, alp4, s1) <= tol:
        return np.full(5, math.nan), math.nan, 0
    q, status, steps = kernel.newton(theta1, start, a1, a2, a4, alp4, s1, newton_tol, max_iterations, printed)
    r = _closure(theta1, q, a1, a2, a4, alp4, s1)
    if status != kernel.OK or not _on_branch(theta1, q, r, tol, a1, a2, a4, alp4, s1, branch):
        return np.full(5, math.nan), math.nan, 0
    return q, r, steps


@njit(cache=True)
def _sweep(theta1, s1, ok, q0, a1, a2, a4, alp4, tol, max_iterations, printed, use_dfp, stop_at_failure,
           closure_tol, branch):
    """The compiled loop of ``positions``: codes (``STATUSES`` index), q, closure, steps, and
    S4 + b (the branch's sign).  ``branch`` 0: no check, no restart."""
    n = theta1.shape[0]
    q_out, closure, side = np.empty((n, 5)), np.empty(n), np.empty(n)
    code, steps = np.empty(n, dtype=np.int64), np.zeros(n, dtype=np.int64)
    for i in range(n):
        code[i], closure[i], side[i] = _NOT_CONVERGED if ok[i] else _CANNOT_ASSEMBLE, math.nan, math.nan
        for k in range(5):
            q_out[i, k] = math.nan
    guess = q0.copy()
    for i in range(n):
        if not ok[i]:
            continue
        finite = True
        for k in range(5):
            finite = finite and math.isfinite(guess[k])
        if finite:
            q, status, steps[i] = kernel.newton(theta1[i], guess, a1, a2, a4, alp4, s1[i], tol, max_iterations,
                                                printed)
            done, how = status == kernel.OK, _NEWTON
            if not done and use_dfp and (i == 0 or code[i - 1] != _NOT_CONVERGED):  # DFP only after a converged position
                start = _dfp(theta1[i], guess, a1, a2, a4, alp4, s1[i], DFP_ITERATIONS)
                q, status, steps[i] = kernel.newton(theta1[i], start, a1, a2, a4, alp4, s1[i], tol, max_iterations,
                                                    printed)
                done, how = status == kernel.OK, _DFP_THEN_NEWTON
        else:
            done, how, q = False, _NEWTON, guess
        r = _closure(theta1[i], q, a1, a2, a4, alp4, s1[i]) if done else math.nan
        if branch != 0 and not (done and _on_branch(theta1[i], q, r, closure_tol[i], a1, a2, a4, alp4, s1[i], branch)):
            again, r_again, n_again = _restart(theta1[i], a1, a2, a4, alp4, s1[i], closure_tol[i], branch, tol,
                                               max_iterations, printed)
            if math.isfinite(r_again):
                q, r, steps[i], done, how = again, r_again, n_again, True, _RESTARTED
        if not done:
            if stop_at_failure:
                break
            continue
        code[i] = how
        side[i] = q[4] + _reach(theta1[i], a1, a2, a4, alp4, s1[i])[0]
        if not r <= closure_tol[i]:
            code[i] = 3 + 2 * how                                   # loop open
        elif branch != 0 and abs(side[i]) > closure_tol[i] and side[i] * branch < 0.0:
            code[i] = 4 + 2 * how                                   # other branch
        answer = _closed_form_angles(q) if branch != 0 and code[i] == how else q
        for k in range(5):
            q_out[i, k] = answer[k]
        closure[i] = r
        guess = q                                   # the sweep goes on from the Newton's own answer
    return code, q_out, closure, steps, side


def closure_tolerance(inputs: GscInputs, s1) -> np.ndarray:
    """The largest ||B - I|| of a closed loop (``CLOSURE_RTOL`` of the loop's size, in) at the
    crank's axial offsets s1 (in)."""
    return CLOSURE_RTOL * (inputs.a1 + inputs.a2 + abs(inputs.a4) + np.abs(np.asarray(s1, dtype=float)))


def positions(inputs: GscInputs, theta1, use_dfp: bool = True, stop_at_failure: bool = False,
              setup: NewtonSetup = THESIS_1991, branch: int | None = EXAMPLE_BRANCH) -> PositionRun:
    """Solve every crank angle theta1 (rad, in sweep order) by the printed method.

    A failed angle leaves the next one to start from the last answer, or
    (``stop_at_failure``) ends the sweep, as the thesis's program stops.  ``branch``: the
    assembly asked for, +1 (the example's, default) or -1; a stopped Newton that is not a
    closed loop on it is tried again from the closed form (status "newton from closed form")
    where the five-variable loop closes there; None: the printed method unchecked.
    TypeError unless ``inputs`` is GscInputs and ``setup`` a NewtonSetup; the angles as
    ``checks.angles_rad``; ValueError for another branch."""
    if not isinstance(inputs, GscInputs) or not isinstance(setup, NewtonSetup):
        raise TypeError(f"inputs must be GscInputs and setup a NewtonSetup, got {type(inputs).__name__}, "
                        f"{type(setup).__name__}")
    asked = branch_asked(branch)
    th = angles_rad("theta1", theta1)
    s1 = inputs.axial(th)[0]
    ok = assembles(inputs, th, s1) if setup.check_assembly else np.ones(th.size, dtype=bool)
    c = constants(inputs, s1[0], setup.real4)
    s1 = s1.astype(np.float32).astype(float) if setup.real4 else s1.astype(float)
    guess = initial_estimate(c, real4=setup.real4)
    tol = c.newton_tol if setup.tol is None else setup.tol
    limit = closure_tolerance(inputs, s1)
    with np.errstate(all="ignore"):
        code, q, closure, steps, side = _sweep(th, s1, ok, guess, c.a1, c.a2, c.a4, c.alpha4, tol,
                                               setup.max_iterations, setup.printed_inverse, use_dfp,
                                               stop_at_failure, limit, asked)
        sign = np.where(np.abs(side) <= limit, 0.0, np.sign(side))
    return PositionRun(q, np.array(STATUSES, dtype=object)[code], closure, steps, sign)


def branch_asked(branch) -> int:
    """+1 or -1 as the compiled sweep's int, None as 0 (no check); TypeError, ValueError else."""
    if branch is None:
        return 0
    if isinstance(branch, (bool, np.bool_)) or not isinstance(branch, numbers.Integral):
        raise TypeError(f"branch must be +1, -1 or None, got {type(branch).__name__} {branch!r}")
    if branch not in (1, -1):
        raise ValueError(f"branch must be +1 (the example's assembly), -1 or None, got {branch!r}")
    return int(branch)


def positions_batch(inputs: list[GscInputs], theta1, use_dfp: bool = True, stop_at_failure: bool = False,
                    branch: int | None = EXAMPLE_BRANCH) -> list[PositionRun]:
    """``positions`` for several configurations."""
    return [positions(x, theta1, use_dfp, stop_at_failure, branch=branch) for x in inputs]
