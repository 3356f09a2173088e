"""Ali (1977): the thesis's own structure run dynamically, no Exudyn (for ``elastodynamics``
and the docs' generated block).

The path point's 2x2 stiffness from the corrected port's flexibility (beta^T F beta, eq. 6;
the links massless, so the point carries all the inertia), m u'' + c u' + K(theta) u = -m
a(theta) at constant crank speed, its periodic solution found directly (the one-revolution map's
fixed point): the 1977 structure with the inertia of its deflection kept, small-deflection
theory; and the quasi-static answer it is held against (``source_case1``/``cognate_case1``,
corrected).  Damping: stiffness-proportional, a modal damping ratio zeta at DAMPING_HZ.

Units: inch, pound-force, second; masses lbf s^2/in; crank angles in degrees; frequencies in Hz.
"""
from __future__ import annotations

import math

import numpy as np
import pandas as pd

from ....errors import ConvergenceError
from ....port.ali1977.case1 import cognate_case1, source_case1, source_mechanics
from ....port.ali1977.cognate import cognate_mechanics
from ....port.ali1977.data import EXAMPLE
from ....port.ali1977.quirks import CORRECTED
from ....port.ali1977.structure import GRAVITY_IN, flexibility

#: the source four-bar and its crossed cognate (the same path point, other links)
SIDES, CASE = ("source", "cognate"), 1
#: the design speed, rev/min
RPM = 300.0
#: the path point's mass, lbf s^2/in
MASS = EXAMPLE.mass_lbf / GRAVITY_IN
#: modal damping ratio at DAMPING_HZ (stiffness-proportional), and the lower ones of the study
ZETA, ZETA_LOW, ZETA_LOWEST = 0.05, 0.02, 0.005
DAMPING_HZ = 10.0
#: the thesis's structure's speed sweep, rev/min (its limit speeds refined by ``speed_limit``), and
#: its time steps per revolution
LINEAR_RPM = np.arange(20.0, 401.0, 10.0)
LINEAR_STEPS = 720
#: the quasi-static answer's error, as a fraction of its peak deflection, that sets the speed limit
ERROR_LEVEL = 0.10
#: ``speed_limit``: the error's assumed growth with the speed for the first step (the measured local
#: growth near the limits: as the speed to the 1.9-10.7 in the example's searches; 3 puts the
#: second run of three of its four searches within the tolerance), the ratio's tolerance about the
#: level (relative: a run this close ends the search; the limit then from the secant through the
#: nearest runs, far closer: the bench's limit-speed knob measures it against the converged
#: reference), the most speeds run
LIMIT_GROWTH = 3.0
LIMIT_RATIO_TOLERANCE = 0.02
LIMIT_RUNS = 8
#: ``linear_limit``: the speeds searched, from 1 - LIMIT_BELOW to 1 + LIMIT_ABOVE times the sweep's
#: crossing, every LINEAR_LIMIT_STEP_RPM
LIMIT_BELOW, LIMIT_ABOVE = 0.2, 0.05


def damping_beta(zeta: float) -> float:
    """The stiffness-proportional damping coefficient (s): zeta at DAMPING_HZ."""
    return 2.0 * zeta / (2.0 * math.pi * DAMPING_HZ)


def _mechanics(deg, side: str, rpm: float = RPM):
    """The corrected port's Mechanics of ``side`` over ``deg`` (its own frame) and the rotation
    (2x2) that turns its own frame into the source's (D025's turn; the identity for the source)."""
    deg = np.asarray(deg, dtype=float)
    if side == "source":
        return source_mechanics(deg, rpm=rpm, quirks=CORRECTED), np.eye(2)
    if side != "cognate":
        raise ValueError(f"side must be one of {SIDES}, got {side!r}")
    mech = cognate_mechanics(deg, rpm=rpm, quirks=CORRECTED)
    c, s = math.cos(mech.frame_angle), math.sin(mech.frame_angle)
    return mech, np.array([[c, -s], [s, c]])


def port_stiffness(deg, side: str = "source") -> np.ndarray:
    """The path point's 2x2 stiffness (lbf/in, source frame) over ``deg``: the inverse of the x, y
    block of the port's compliance beta^T F beta (eq. 6, corrected; no load on the rotation, as
    Case I)."""
    mech, turn = _mechanics(deg, side)
    flex = flexibility(*mech.flex_lengths, EXAMPLE.section, CORRECTED)
    compliance = np.swapaxes(mech.beta, -1, -2) @ flex @ mech.beta
    return turn @ np.linalg.inv(compliance[:, :2, :2]) @ turn.T


def frequencies_of(stiffness: np.ndarray) -> np.ndarray:
    """The two natural frequencies (Hz) of the path-point mass on the stiffness (.., 2, 2)."""
    return np.sqrt(np.linalg.eigvalsh(stiffness / MASS)) / (2.0 * math.pi)


def _case1(deg, rpm: float, side: str) -> dict:
    call = source_case1 if side == "source" else cognate_case1
    return call(np.asarray(deg, dtype=float), rpm=rpm, quirks=CORRECTED)


def quasi_static(deg, rpm: float, side: str = "source") -> np.ndarray:
    """The corrected port's Case I deflection (dx, dy) (N, 2), in, source frame, at ``rpm``."""
    out = _case1(deg, rpm, side)
    return np.column_stack([out["dx"], out["dy"]])


def rigid_path_point(deg, rpm: float = RPM, side: str = "source") -> np.ndarray:
    """The rigid path point (x, y) (N, 2), in, source frame, from the corrected port."""
    out = _case1(deg, rpm, side)
    return np.column_stack([out["xp"], out["yp"]] if side == "source" else [out["cxp"], out["cyp"]])


def linear_periodic(rpms, zeta: float, steps: int = LINEAR_STEPS, side: str = "source") -> tuple[np.ndarray, np.ndarray]:
    """The thesis's structure run dynamically: m u'' + beta K u' + K u = -m a over a revolution at
    each of ``rpms`` (S,), K = ``port_stiffness``, a the port's rigid acceleration, beta =
    ``damping_beta(zeta)``; the trapezoidal rule (Newmark's average acceleration) in ``steps``
    steps per revolution, and its periodic solution: the fixed point of the revolution's affine
    map.  The load at each speed is RPM's times (rpm / RPM)^2 (at constant crank speed every
    rigid acceleration scales so; equal to the port's at that speed to rounding).  Returns (the deflections (S, steps, 2) at deg = 360 k / steps, the map's spectral
    radius (S,): how fast a start-up transient dies per revolution)."""
    rpms = np.atleast_1d(np.asarray(rpms, dtype=float))
    deg = np.arange(steps) * 360.0 / steps
    stiffness = port_stiffness(deg, side)
    mech, turn = _mechanics(deg, side)
    load = -MASS * (mech.acc @ turn.T) * ((rpms / RPM) ** 2)[:, None, None]         # (S, N, 2)
    beta = damping_beta(zeta)
    h = (60.0 / rpms / steps)[:, None, None, None]                                # (S, 1, 1, 1)
    k0 = np.broadcast_to(stiffness / MASS, (len(rpms), steps, 2, 2))              # step i's start
    k1 = np.roll(k0, -1, axis=1)                                                  # and end
    eye = np.broadcast_to(np.eye(2), k0.shape)
    # a step: u1 - h/2 v1 = u0 + h/2 v0;  v1 + h/2 (beta K1 v1 + K1 u1) = v0 - h/2 (beta K0 v0 + K0 u0) + h/2 (P0 + P1)/m;
    # u1 eliminated: (I + (h/2 beta + h^2/4) K1) v1 = that right side - h/2 K1 (u0 + h/2 v0), a 2x2 solve
    b = eye + (h / 2 * beta + h ** 2 / 4) * k1
    inv = np.stack([np.stack([b[..., 1, 1], -b[..., 0, 1]], -1), np.stack([-b[..., 1, 0], b[..., 0, 0]], -1)], -2)
    inv /= (b[..., 0, 0] * b[..., 1, 1] - b[..., 0, 1] * b[..., 1, 0])[..., None, None]
    from_u = inv @ (-h / 2 * k0 - h / 2 * k1)                                     # v1's dependence on u0
    from_v = inv @ (eye - h / 2 * beta * k0 - h ** 2 / 4 * k1)                    # and on v0
    maps = np.concatenate([np.concatenate([eye + h / 2 * from_u, h / 2 * (eye + from_v)], -1),
                           np.concatenate([from_u, from_v], -1)], -2)             # (S, N, 4, 4)
    dv = (inv @ (h[..., 0] / 2 * (load + np.roll(load, -1, axis=1)) / MASS)[..., None])[..., 0]
    out, phi = _periodic_orbit(maps, np.concatenate([h[..., 0] / 2 * dv, dv], -1))
    return out[..., :2], np.abs(np.linalg.eigvals(phi)).max(axis=1)


def _periodic_orbit(maps: np.ndarray, shifts: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The periodic orbit of the affine steps x -> maps[:, i] x + shifts[:, i] (S, N, n, n), (S,
    N, n): the state before each step (S, N, n), and the revolution's map (S, n, n).  The steps in
    about sqrt(N) blocks, composed side by side (the loops' lengths about 4 sqrt(N), not 2 N)."""
    count, n, size = maps.shape[0], maps.shape[1], maps.shape[-1]
    length = math.ceil(math.sqrt(n))
    blocks = math.ceil(n / length)
    pad = blocks * length - n
    maps = np.concatenate([maps, np.broadcast_to(np.eye(size), (count, pad, size, size))], 1)
    shifts = np.concatenate([shifts, np.zeros((count, pad, size))], 1)
    maps, shifts = maps.reshape(count, blocks, length, size, size), shifts.reshape(count, blocks, length, size)

    def step(m, g, x):
        return np.einsum("...ij,...j->...i", m, x) + g
    block_map, block_shift = np.broadcast_to(np.eye(size), (count, blocks, size, size)), np.zeros((count, blocks, size))
    for j in range(length):
        block_map, block_shift = maps[:, :, j] @ block_map, step(maps[:, :, j], shifts[:, :, j], block_shift)
    phi, g = np.broadcast_to(np.eye(size), (count, size, size)), np.zeros((count, size))
    for k in range(blocks):
        phi, g = block_map[:, k] @ phi, step(block_map[:, k], block_shift[:, k], g)
    x = np.linalg.solve(np.eye(size) - phi, g[..., None])[..., 0]
    starts = np.empty((count, blocks, size))
    for k in range(blocks):
        starts[:, k], x = x, step(block_map[:, k], block_shift[:, k], x)
    out = np.empty((count, blocks, length, size))
    for j in range(length):
        out[:, :, j], starts = starts, step(maps[:, :, j], shifts[:, :, j], starts)
    return out.reshape(count, blocks * length, size)[:, :n], phi


def error_of(deflection: np.ndarray, reference: np.ndarray) -> tuple[float, float, float]:
    """(peak |reference|, peak |deflection|, largest |deflection - reference|) over a revolution, in."""
    return (float(np.hypot(*reference.T).max()), float(np.hypot(*deflection.T).max()),
            float(np.hypot(*(deflection - reference).T).max()))


def crossing(rpm, ratio, level: float = ERROR_LEVEL) -> float:
    """The speed where ``ratio`` first passes ``level``, interpolated linearly; NaN if never."""
    rpm, ratio = np.asarray(rpm, dtype=float), np.asarray(ratio, dtype=float)
    above = np.flatnonzero(ratio > level)
    if not len(above):
        return math.nan
    k = above[0]
    if k == 0:
        return float(rpm[0])
    return float(rpm[k - 1] + (level - ratio[k - 1]) * (rpm[k] - rpm[k - 1]) / (ratio[k] - ratio[k - 1]))


def speed_limit(ratio, guess: float, level: float = ERROR_LEVEL) -> float:
    """The speed (rpm) where ``ratio(rpm)`` (the quasi-static answer's error over its peak) passes
    ``level``, near ``guess``: the ratio at ``guess``, then a speed extrapolated as if it grew as
    the speed to the LIMIT_GROWTH, then the secant in log ratio against log speed through the
    nearest speeds either side of the level (the last two while none brackets it), until a speed's
    ratio is within LIMIT_RATIO_TOLERANCE of ``level`` (at most LIMIT_RUNS speeds); the limit then
    from the secant through the bracket.  The ratio must rise through ``level`` once near ``guess``
    (the linear model's sweep shows where); a NaN ratio (a failed run), a falling ratio or no
    convergence raises ConvergenceError."""
    points: list[tuple[float, float]] = []          # (log rpm, log ratio)
    target = math.log(level)

    def at(rpm):
        value = float(ratio(rpm))
        if not value > 0.0:
            raise ConvergenceError(f"speed_limit: the error ratio at {rpm:g} rpm is {value} (NaN or not positive: the run failed)")
        points.append((math.log(rpm), math.log(value)))
        return value

    def secant():
        below, above = [p for p in points if p[1] < target], [p for p in points if p[1] >= target]
        a, b = (max(below), min(above)) if below and above else points[-2:]
        slope = (b[1] - a[1]) / (b[0] - a[0])
        if not slope > 0.0:
            raise ConvergenceError(f"speed_limit: the error ratio falls with the speed near {math.exp(a[0]):g} rpm")
        return math.exp(a[0] + (target - a[1]) / slope)
    r = at(guess)
    x = guess * (level / r) ** (1.0 / LIMIT_GROWTH)
    for _ in range(LIMIT_RUNS - 1):
        if abs(at(x) / level - 1.0) < LIMIT_RATIO_TOLERANCE:
            return secant()
        x = secant()
    raise ConvergenceError(f"speed_limit: no speed within {LIMIT_RATIO_TOLERANCE:g} of {level:g} in {LIMIT_RUNS} runs "
                           f"from {guess:g} rpm")


def _scaled_quasi_static(rpms, side: str) -> list[np.ndarray]:
    """The quasi-static deflection (LINEAR_STEPS, 2), in, at each of ``rpms`` over
    ``linear_periodic``'s angles: RPM's times (rpm / RPM)^2 (the load, and so the linear
    deflection, scales so; the port's at that speed to rounding), one port call for every speed."""
    qs = quasi_static(np.arange(LINEAR_STEPS) * 360.0 / LINEAR_STEPS, RPM, side)
    return [qs * (rpm / RPM) ** 2 for rpm in rpms]


LINEAR_LIMIT_STEP_RPM = 0.25


def linear_limit(sweep: pd.DataFrame, side: str, zeta: float) -> float:
    """The thesis's structure's limit speed (rpm), ``side`` at ``zeta``: ``crossing`` on the speeds
    every LINEAR_LIMIT_STEP_RPM from LIMIT_BELOW below to LIMIT_ABOVE above the crossing of ``sweep``
    (``linear_sweep``'s; one batched ``linear_periodic``, cheaper than a bisection's calls)."""
    rows = sweep[(sweep["side"] == side) & (sweep["zeta"] == zeta)]
    guess = crossing(rows["rpm"], rows["error_over_peak"])
    rpms = np.arange(guess * (1.0 - LIMIT_BELOW), guess * (1.0 + LIMIT_ABOVE), LINEAR_LIMIT_STEP_RPM)
    out, _ = linear_periodic(rpms, zeta, side=side)
    ratio = [(lambda peak_qs, _, error: error / peak_qs)(*error_of(orbit, qs))
             for orbit, qs in zip(out, _scaled_quasi_static(rpms, side))]
    return crossing(rpms, ratio)


def linear_sweep() -> pd.DataFrame:
    """The linear dynamics of the thesis's structure at every LINEAR_RPM, per side, for ZETA,
    ZETA_LOW and ZETA_LOWEST: the peak quasi-static deflection, the dynamic peak, the quasi-static answer's error
    over its peak, and how much of a start-up transient is left after a revolution."""
    frames = []
    for side in SIDES:
        for zeta in (ZETA, ZETA_LOW, ZETA_LOWEST):
            out, decay = linear_periodic(LINEAR_RPM, zeta, side=side)
            rows = []
            for k, (rpm, qs) in enumerate(zip(LINEAR_RPM, _scaled_quasi_static(LINEAR_RPM, side))):
                peak_qs, peak, error = error_of(out[k], qs)
                rows.append({"side": side, "zeta": zeta, "rpm": rpm, "quasi_static_peak": peak_qs, "dynamic_peak": peak,
                             "error_over_peak": error / peak_qs, "transient_left_per_rev": decay[k]})
            frames.append(pd.DataFrame(rows))
    return pd.concat(frames, ignore_index=True)
