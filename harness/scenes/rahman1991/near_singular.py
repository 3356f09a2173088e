"""Rahman (1991) near theta2 = 0: digits lost by the printed rates, and by the corrected ones.

Section 3.2 reports "abnormally high" accelerations near 100 and 300 deg, where theta2 -> 0,
and blames round-off.  For each configuration below we find the crank angle theta1* where the
printed Newton's theta2 crosses zero (bisection to 1e-15 rad), step off it by delta, and
evaluate the joint rates four ways:

- printed: eqs. (39)-(43), (38a)-(42a) in float64 at the printed Newton's position;
- printed_mp: the same formulas, same float inputs, in 40-digit mpmath: their round-off;
- printed_exact: the printed formulas at the exact loop's position (float64): the formula's
  own conditioning, without the Newton's tolerance (on the planar points only the
  five-variable loop and the exact one are the same mechanism);
- corrected: the CORRECTED path's float64 jets of the exact closed loop;
- truth: the exact closed loop in 40-digit mpmath, rates by mpmath.diff.

Digits are counted against a scale (omega, a1 omega, omega^2, a1 omega^2 for angle rates,
S4', angle accelerations, S4''), so that a rate whose true value is 0 is judged by what it
adds to the motion: digits = -log10(|x - ref| / max(|ref|, scale)), capped at 16.
A value keeps "half its digits" when digits >= 8; ``flag`` marks those that do not.
"""
from __future__ import annotations

import mpmath
import numpy as np
import pandas as pd

from ....port.rahman1991 import analysis as gsc, position as gsc_position, printed_rates
from ....port.rahman1991.analysis import ball_angles
from ....port.slider_crank.kinematics import kinematics
from ....port.rahman1991.data import GscInputs

CONFIGS = [GscInputs(a4=10.0), GscInputs(a4=30.0, s1=3.5), GscInputs(a4=20.0, alpha4_deg=232.0)]
OFFSETS_DEG = (1.0, 1e-2, 1e-4, 1e-6, 1e-8)
QUANTITIES = ["theta2_d", "eta2_d", "s4_d", "theta2_dd", "eta2_dd", "s4_dd"]
DIGITS = 40


def _printed_q(inputs: GscInputs, theta1: float, q0: np.ndarray) -> np.ndarray:
    q, done, _ = gsc_position.newton(theta1, q0, gsc_position.constants(inputs, inputs.s1))
    if not done:
        raise ArithmeticError(f"printed Newton did not converge at {np.degrees(theta1)} deg")
    return q


def crossings(inputs: GscInputs) -> list[tuple[float, np.ndarray]]:
    """(theta1*, q*) where the printed theta2 crosses 0 (mod 2 pi), by bisection."""
    th = np.radians(gsc.CRANK_DEG)
    run = gsc_position.positions(inputs, th)
    s = np.sin(run.q[:, 0])
    found = []
    for k in np.flatnonzero((s[:-1] * s[1:] < 0) & (np.cos(run.q[:-1, 0]) > 0)):
        lo, hi, q_lo = th[k], th[k + 1], run.q[k]
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            q_mid = _printed_q(inputs, mid, q_lo)
            if np.sin(q_mid[0]) * s[k] > 0:
                lo, q_lo = mid, q_mid
            else:
                hi = mid
        found.append((lo, q_lo))
    return found


def _printed_rates(q, inputs: GscInputs, m):
    t2, e2, t3, e3, _ = (m.mpf(float(v)) if m is mpmath else v for v in q)
    w = m.mpf(inputs.omega) if m is mpmath else inputs.omega
    v = printed_rates.velocities(t2, e2, t3, e3, w, 0.0, inputs.a1, inputs.a2, m=m)
    a = printed_rates.accelerations(t2, e2, t3, e3, v, w, 0.0, 0.0, 0.0, inputs.a1, inputs.a2, m=m)
    return [v[0], v[2], v[4], a[0], a[2], a[4]]


def _truth(inputs: GscInputs, theta1: float) -> list:
    """theta2, eta2, S4 of the closed loop and their time derivatives, 40 digits."""
    mp = mpmath.mp
    a1, a2, a4, s1 = (mp.mpf(v) for v in (inputs.a1, inputs.a2, inputs.a4, inputs.s1))
    al, w = mp.radians(mp.mpf(inputs.alpha4_deg)), mp.mpf(inputs.omega)

    def loop(t):
        b = a1 * mp.sin(al) * mp.sin(t) + s1 * mp.cos(al)
        c = (a1 * mp.cos(t) + a4) ** 2 + (a1 * mp.sin(t)) ** 2 + s1 ** 2 - a2 ** 2
        s4 = -b + mp.sqrt(b * b - c)
        u = [(-a4 - a1 * mp.cos(t)) / a2, (-s4 * mp.sin(al) - a1 * mp.sin(t)) / a2, (-s4 * mp.cos(al) - s1) / a2]
        vx, vy = mp.cos(t) * u[0] + mp.sin(t) * u[1], mp.cos(t) * u[1] - mp.sin(t) * u[0]
        return [mp.atan2(vy, vx), mp.atan2(-u[2], mp.sqrt(vx * vx + vy * vy)), s4]

    t0 = mp.mpf(theta1)
    rates = [mp.diff(lambda t, k=k: loop(t)[k], t0, 1) * w for k in range(3)]
    accel = [mp.diff(lambda t, k=k: loop(t)[k], t0, 2) * w * w for k in range(3)]
    return rates + accel


def _digits(x: float, ref: float, scale: float) -> float:
    err = abs(float(x) - float(ref))
    return 16.0 if err == 0.0 else float(min(16.0, -np.log10(err / max(abs(float(ref)), scale))))


def table() -> pd.DataFrame:
    mpmath.mp.dps = DIGITS
    rows = []
    for inputs in CONFIGS:
        w, a1 = inputs.omega, inputs.a1
        scales = [w, w, a1 * w, w * w, w * w, a1 * w * w]
        for star, q_star in crossings(inputs):
            for delta in OFFSETS_DEG:
                theta1 = star + np.radians(delta)
                q = _printed_q(inputs, theta1, q_star)
                with np.errstate(all="ignore"):
                    printed = _printed_rates(q, inputs, np)
                printed_mp = _printed_rates(q, inputs, mpmath)
                kin = kinematics(inputs, np.array([theta1]))
                exact = [kin.theta2[0], kin.eta2[0], *(v[0] for v in ball_angles(kin)), kin.s4[0]]
                with np.errstate(all="ignore"):
                    printed_exact = _printed_rates(exact, inputs, np)
                corrected = [kin.theta2d[0], kin.eta2d[0], kin.s4d[0], kin.theta2dd[0], kin.eta2dd[0], kin.s4dd[0]]
                truth = _truth(inputs, theta1)
                for k, name in enumerate(QUANTITIES):
                    rows.append(dict(
                        a4=inputs.a4, alpha4_deg=inputs.alpha4_deg, s1=inputs.s1,
                        crank_deg=np.degrees(star), offset_deg=delta, theta2_deg=np.degrees(np.mod(q[0] + np.pi, 2 * np.pi) - np.pi),
                        quantity=name, printed=float(printed[k]), printed_mp=float(printed_mp[k]),
                        printed_exact=float(printed_exact[k]), corrected=float(corrected[k]), truth=float(truth[k]),
                        digits_printed_roundoff=_digits(printed[k], printed_mp[k], scales[k]),
                        digits_printed_vs_truth=_digits(printed[k], truth[k], scales[k]),
                        digits_printed_exact_vs_truth=_digits(printed_exact[k], truth[k], scales[k]),
                        digits_corrected_vs_truth=_digits(corrected[k], truth[k], scales[k])))
    frame = pd.DataFrame(rows)
    frame["flag"] = np.where(frame.digits_printed_vs_truth < 8.0, "printed loses > half its digits", "")
    return frame
